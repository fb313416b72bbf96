"""The shaft load diagram of a drive's report: the bending moment along each shaft,
checked by the statics it must obey, not by its own formula: it vanishes beyond the
shaft's last force, and its slope jumps at each bearing by the radial load the drive
reports for that bearing."""

from __future__ import annotations

import numpy as np
import pytest

from bearingcalc.core.bevel_drive import shaft_bending_moments
from bearingcalc.evaluation import evaluate_document, load_one_spec
from tests.conftest import ROOT

STEP = 1e-7  # [m], for the slopes on either side of a bearing


@pytest.mark.parametrize("name", ["bevel-drive.yaml", "bevel-drive-tapered.yaml"])
def test_the_moment_obeys_the_statics_of_the_drive(name):
    _, spec, document = load_one_spec(ROOT / "specs" / name)
    evaluation = evaluate_document(document)
    results = evaluation.results
    shafts = spec.solver_inputs()["shafts"]
    for shaft, gear in (("pinion", "a"), ("gear", "b")):
        positions = tuple(float(b["position"]) for b in shafts[shaft])
        angle = results[f"gear_{gear}_pitch_angle"]
        mesh = results["mean_cone_distance"] * np.cos(angle)
        radius = results["mean_cone_distance"] * np.sin(angle)
        forces = (results["tangential_force"], results[f"gear_{gear}_radial_force"],
                  results[f"gear_{gear}_axial_force"])

        def moments(x, positions=positions, mesh=mesh, radius=radius, forces=forces):
            return np.stack(shaft_bending_moments(np.asarray(x, dtype=float), positions,
                                                  mesh, radius, *forces))

        scale = float(np.abs(moments(np.linspace(0.0, 0.2, 2001))).max())
        # nothing acts outside the forces: no moment there
        first, last = min(*positions, mesh), max(*positions, mesh)
        outside = moments([first - 0.01, first - 1e-6, last + 1e-6, last + 0.05])
        assert np.abs(outside).max() <= 1e-12 * scale
        for i, at in enumerate(positions, 1):
            slope = [(moments([at + s + STEP]) - moments([at + s]))[:, 0] / STEP
                     for s in (STEP, -2 * STEP)]
            reaction = np.hypot(*(slope[0] - slope[1]))
            assert reaction == pytest.approx(results[f"{shaft}_bearing_{i}_radial_load"],
                                             rel=1e-6), (shaft, i)


def test_the_report_of_a_drive_draws_its_shafts(cli, tmp_path):
    target = tmp_path / "drive.html"
    run = cli("report", ROOT / "specs" / "bevel-drive.yaml", "-o", target)
    assert run.code == 0, run.err
    page = target.read_text(encoding="utf-8")
    assert "bending moment" in page and page.count("<svg") >= 2


def test_a_drive_with_bearings_on_one_shaft_draws_that_shaft(cli, tmp_path, monkeypatch):
    import yaml

    from bearingcalc.plots import report

    panels = []
    real = report.svg_of

    def counted(draw, **kwargs):
        panels.append(kwargs.get("panels"))
        return real(draw, **kwargs)

    monkeypatch.setattr(report, "svg_of", counted)

    data = yaml.safe_load((ROOT / "specs" / "bevel-drive.yaml").read_text())
    del data["gear_bearings"]
    spec = tmp_path / "pinion-only.yaml"
    spec.write_text(yaml.safe_dump(data, allow_unicode=True))
    target = tmp_path / "drive.html"
    run = cli("report", spec, "-o", target)
    assert run.code == 0, run.err
    assert target.read_text(encoding="utf-8").count("<svg") == 2  # lives, the one shaft
    assert panels == [None, 1]
