"""A report of a spec with tolerances: its inputs read back at their nominal values."""

from __future__ import annotations

import re

from tests.conftest import ROOT


def test_a_toleranced_spec_is_reported_at_its_nominal_values(cli, tmp_path):
    spec = ROOT / "specs" / "tolerances" / "thrust-bearing.yaml"
    page = tmp_path / "report.html"
    run = cli("report", spec, "--output", page)
    assert run.code == 0, run.err
    text = page.read_text()
    # the spec writes contact_angle: 30 deg ± 0.25 deg; in SI 30° = π/6 = 0.5235987756 rad
    written = re.search(r"contact_angle.{0,400}?0\.5235987756", text, re.S)
    assert written is not None


def test_a_bearing_with_a_toleranced_load_gets_its_life_plot(cli, tmp_path):
    spec = tmp_path / "bearing.yaml"
    text = (ROOT / "specs" / "rolling-bearing.yaml").read_text()
    spec.write_text(re.sub(r"(?m)^radial_load: (.*?)(\s*#.*)?$", r"radial_load: \1 ± 0.5 kN", text,
                           count=1))
    assert "9 kN ± 0.5 kN" in spec.read_text()
    page = tmp_path / "report.html"
    run = cli("report", spec, "--output", page)
    assert run.code == 0, run.err
    assert "The modified rating life against the radial load" in page.read_text()
