"""A double-row cylindrical or needle roller bearing as mounted (``rows: 2``) through
every command, and what is refused of it. Its physics is checked against an
independent reference in ``tests/test_iso16281_double_row.py``."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from tests.mounted_specs import refused_lines

NN = """\
kind: rolling-bearing
name: NN 3010 as mounted
type: cylindrical-roller
method: iso-16281
rows: 2
dynamic_load_rating: 53 kN
static_load_rating: 80 kN
roller_count: 23
roller_diameter: 6.5 mm
roller_length: 7 mm
pitch_diameter: 65 mm
width: 26 mm
operating_clearance: 5 µm
radial_load: 10 kN
speed: 1500 rpm
{extra}"""


def _run(cli, spec_file, text: str, *args: str):
    """``bearingcalc COMMAND SPEC OPTIONS…`` on ``text`` written as the spec."""
    return cli(args[0], spec_file(text, "nn.yaml"), *args[1:])


def _results(cli, spec_file, extra: str = "") -> dict:
    run = _run(cli, spec_file, NN.format(extra=extra), "solve", "--format", "json")
    assert run.code == 0, run.err
    return json.loads(run.out)["results"]


def _row_loads(results: dict, row: int) -> list[float]:
    return [results[f"row_{row}_element_{j}_load"] for j in range(1, 24)]


def test_every_roller_of_both_rows_is_listed_and_the_largest_is_one_rollers(cli, spec_file):
    results = _results(cli, spec_file, "misalignment: 0.5 mrad\n")
    first, second = _row_loads(results, 1), _row_loads(results, 2)
    assert "element_1_load" not in results and "row_3_element_1_load" not in results
    assert results["max_element_load"] == max(first + second)
    assert results["loaded_elements"] == sum(load > 0 for load in first + second)
    # the tilt loads one row more than the other, roller by roller under the load
    assert first[0] != pytest.approx(second[0], rel=1e-3)
    assert results["row_2_element_1_azimuth"] == results["row_1_element_1_azimuth"] == 0.0


def test_an_untilted_double_row_loads_both_rows_alike(cli, spec_file):
    results = _results(cli, spec_file)
    np_first, np_second = _row_loads(results, 1), _row_loads(results, 2)
    assert np_second == pytest.approx(np_first, rel=1e-12, abs=1e-9)
    assert math.isclose(results["ring_tilt"], 0.0, abs_tol=1e-15)


def test_the_table_shows_each_row_under_its_heading(cli, spec_file):
    run = _run(cli, spec_file, NN.format(extra="misalignment: 0.5 mrad\n"), "solve")
    assert run.code == 0, run.err
    assert "row 1: rolling elements as mounted" in run.out
    assert "row 2: rolling elements as mounted" in run.out


def test_the_edge_stress_factor_takes_each_rows_ends(cli, spec_file):
    """Straight, untilted rollers load every lamina of both rows alike, so the life falls
    by (Σ f_k^(9/2)/n_s)^(−8/9) only if each row takes its own factors (ISO/TS 16281
    8.3, eq. 60; f_k as minzhun/ISO16281 writes it, in tests/test_iso16281_edge_stress)."""
    from tests.test_iso16281_edge_stress import _minzhun_factors

    plain = _results(cli, spec_file, "roller_profile: none\n")
    edged = _results(cli, spec_file, "roller_profile: none\nedge_stress_factor: true\n")
    factors = _minzhun_factors(30)
    expected = (sum(f ** 4.5 for f in factors) / 30) ** (-8 / 9)
    assert edged["reference_rating_life"] / plain["reference_rating_life"] == pytest.approx(
        expected, rel=1e-9)


@pytest.mark.parametrize("command", [
    ("tolerance", "--samples", "512", "--format", "json"),
    ("tolerance", "--method", "worst-case", "--format", "json"),
    ("sweep", "--vary", "misalignment=0mrad:1mrad:5", "--format", "json"),
])
def test_the_studies_run_on_a_double_row(cli, spec_file, command):
    text = NN.format(extra="misalignment: 0.5 mrad ± 0.2 mrad\n")
    if command[0] == "sweep":
        text = NN.format(extra="misalignment: 0.5 mrad\n")
    run = _run(cli, spec_file, text, *command)
    assert run.code == 0, run.err
    assert "nan" not in run.out.lower().replace("nano", "")


def test_the_report_draws_a_double_row(cli, spec_file, tmp_path):
    out = tmp_path / "nn.html"
    run = _run(cli, spec_file, NN.format(extra="misalignment: 0.5 mrad\n"), "report", "--output",
               str(out))
    assert run.code == 0, run.err
    assert "row_2_element_23" in out.read_text(encoding="utf-8")


TAPERED = """\
kind: rolling-bearing
name: double-row tapered
type: tapered-roller
method: iso-16281
rows: 2
dynamic_load_rating: 90 kN
static_load_rating: 120 kN
contact_angle: 14 deg
roller_count: 17
roller_diameter: 7.5 mm
roller_length: 14 mm
pitch_diameter: 45 mm
radial_load: 6 kN
axial_load: 3 kN
speed: 3000 rpm
"""
CATALOGUE_ONLY = """\
kind: rolling-bearing
name: NN 3010 from its catalogue data
type: cylindrical-roller
method: iso-16281
rows: 2
dynamic_load_rating: 53 kN
static_load_rating: 80 kN
bore_diameter: 50 mm
outside_diameter: 80 mm
width: 26 mm
operating_clearance: 5 µm
radial_load: 10 kN
speed: 1500 rpm
"""


@pytest.mark.parametrize(("text", "field", "says"), [
    (TAPERED, "rows", "back-to-back"),
    (CATALOGUE_ONLY, "roller_count", "roller_diameter"),
], ids=["tapered-double-row", "geometry-not-given"])
def test_what_a_double_row_cannot_be_is_one_line(cli, spec_file, text, field, says):
    lines = refused_lines(cli, spec_file, text)
    assert len(lines) == 1 and f" {field}: " in lines[0] and says in lines[0], lines


def test_a_drive_shaft_rests_on_a_double_row(cli, spec_file):
    """The example drive with its gear's floating bearing a double row: its largest
    load is one roller's, not the two rollers' at an azimuth."""
    example = (Path(__file__).parents[1] / "specs" / "bevel-drive-mounted.yaml").read_text(
        encoding="utf-8")
    text = example.replace(
        "dynamic_load_rating: 62 kN,  # NU 207-size",
        "dynamic_load_rating: 62 kN, rows: 2, roller_count: 16, roller_diameter: 7 mm, "
        "roller_length: 7 mm, pitch_diameter: 53 mm,")
    assert text != example
    run = _run(cli, spec_file, text, "solve", "--format", "json")
    assert run.code == 0, run.err
    results = json.loads(run.out)["results"]
    largest, radial = (results[f"gear_bearing_1_{key}"] for key in ("max_element_load",
                                                                     "radial_load"))
    # the two rollers at an azimuth together carry about 0.29·Fr here, one about 0.15·Fr
    assert 0.0 < largest < 0.2 * radial
    assert math.isfinite(results["gear_bearing_1_reference_rating_life"])


def test_a_sweep_over_the_rows_keeps_the_single_rows_design(cli, spec_file):
    """The single row has no second row's rollers: they are null, not out of range."""
    run = _run(cli, spec_file, NN.format(extra="misalignment: 0.5 mrad\n"), "sweep", "--vary",
               "rows=1:2:2", "--format", "json")
    assert run.code == 0, run.err
    single, double = (json.loads(line)["results"] for line in run.out.splitlines())
    assert single["row_2_element_1_load"] is None and single["row_2_element_1_azimuth"] is None
    assert single["row_1_element_1_load"] > 0 and double["row_2_element_1_load"] > 0


def test_a_sweep_over_the_roller_count_leaves_the_fewer_rollers_missing(cli, spec_file):
    run = _run(cli, spec_file, NN.format(extra=""), "sweep", "--vary", "roller_count=20:23:2",
               "--format", "json")
    assert run.code == 0, run.err
    fewer, more = (json.loads(line)["results"] for line in run.out.splitlines())
    assert fewer["row_1_element_23_load"] is None and fewer["row_1_element_20_load"] > 0
    assert more["row_1_element_23_azimuth"] == pytest.approx(2 * math.pi * 22 / 23)
