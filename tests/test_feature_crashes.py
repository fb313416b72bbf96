"""Crashes on combinations of features: a drive's one-way locating bearing over a duty
cycle, tolerance --sobol with one result, --debug on every command, induced_axial_factor
on a located shaft."""

from __future__ import annotations

import json
import math
from dataclasses import replace

import numpy as np
import pytest

from bearingcalc.core import rolling_bearing
from bearingcalc.studies.sensitivity import sobol_indices
from tests.conftest import ROOT, solve_json
from tests.test_tolerance import R_DISK, R_RING, linear_disk

CYCLE = (ROOT / "specs" / "bevel-drive-duty-cycle.yaml").read_text()
DEEP_GROOVE = ("type: deep-groove, dynamic_load_rating: 20.3 kN,\n     static_load_rating: "
               "11.2 kN, static_factor: 14,")
TAPERED = ("type: tapered-roller, dynamic_load_rating: 20.3 kN,\n     static_load_rating: "
           "11.2 kN, contact_angle: 14 deg, load_factors: {e: 0.37, y: 1.6, y0: 0.9},")
ANGULAR = ("type: angular-contact, dynamic_load_rating: 20.3 kN,\n     static_load_rating: "
           "11.2 kN, contact_angle: 25 deg,")
assert DEEP_GROOVE in CYCLE


@pytest.mark.parametrize("locating", [TAPERED, ANGULAR], ids=["tapered", "angular-contact"])
def test_a_one_way_locating_bearing_over_a_duty_cycle_solves_checks_and_reports(
        locating, cli, spec_file, tmp_path):
    path = spec_file(CYCLE.replace(DEEP_GROOVE, locating), "drive.yaml")
    (record,) = solve_json(cli, path)
    assert all(math.isfinite(v) for v in record["results"].values() if v is not None)
    # the gear's thrust points one way in every bin: the one-way warning, once
    assert sum("gear_bearing_2 locates its shaft" in note for note in record["warnings"]) == 1
    check = cli("check", path, "--format", "json")
    assert check.code in (0, 1) and json.loads(check.out)["status"] in ("pass", "fail")
    report = cli("report", path, "--output", tmp_path / "drive.html")
    assert report.code in (0, 1), report.err
    assert "locates its shaft" in (tmp_path / "drive.html").read_text()


def test_a_drive_cycle_with_a_one_way_locating_bearing_sweeps(cli, spec_file):
    """A sweep stacks the designs after the bins: every number an array of both."""
    path = spec_file(CYCLE.replace(DEEP_GROOVE, TAPERED), "drive.yaml")
    run = cli("sweep", path, "--vary", "torque=50N*m:70N*m:3", "--format", "json")
    assert run.code in (0, 1), run.err


def test_sobol_indices_of_one_result_are_those_of_an_additive_function(spec_file):
    """center_speed = R_ring·ω_ring + R_disk·ω_disk (linear): first = total order =
    aᵢ²σᵢ²/Σ aⱼ²σⱼ², with one result asked for."""
    study = linear_disk(spec_file)
    indices = sobol_indices(study, 1 << 16, keys=["center_speed"])
    assert list(indices) == ["center_speed"]
    variance = (R_RING * 1.0) ** 2 + (R_DISK * 2.0) ** 2
    expected = {"surface_speed": (R_RING * 1.0) ** 2 / variance,
                "disk_speed": (R_DISK * 2.0) ** 2 / variance}
    for name, value in expected.items():
        assert abs(indices["center_speed"]["first_order"][name] - value) < 0.01
        assert abs(indices["center_speed"]["total_order"][name] - value) < 0.01


def test_tolerance_sobol_with_one_result_runs_and_shows_the_indices(cli):
    spec = ROOT / "specs" / "tolerances" / "thrust-bearing.yaml"
    run = cli("tolerance", spec, "--sobol", "-r", "slip_margin", "-n", "4096")
    assert run.code in (0, 1), run.err
    table = run.out[run.out.index("Sobol' indices"):]
    rows = [line for line in table.splitlines() if "contact_angle" in line]
    assert rows and "slip_margin" in rows[0]
    record = json.loads(cli("tolerance", spec, "--sobol", "-r", "slip_margin", "-n", "4096",
                            "--format", "json").out)
    first = record["results"]["slip_margin"]["sobol"]["first_order"]["contact_angle"]
    assert f"{first:.3f}" in rows[0]


def test_the_tolerance_table_shows_sobol_indices_of_every_result(cli):
    spec = ROOT / "specs" / "tolerances" / "thrust-bearing.yaml"
    run = cli("tolerance", spec, "--sobol", "-n", "4096")
    assert run.code in (0, 1), run.err
    table = run.out[run.out.index("Sobol' indices"):]
    for key in ("slip_margin", "spin_to_roll", "ball_speed"):
        assert key in table
    assert "-0.000" not in table


@pytest.fixture
def exploding_solver(monkeypatch):
    """rolling-bearing's solver, raising an error no spec could cause."""
    def explode(inputs, wanted=None):
        raise ZeroDivisionError("induced for the test")

    monkeypatch.setattr(rolling_bearing, "SOLVER", replace(rolling_bearing.SOLVER,
                                                           evaluate=explode))


COMMANDS = {
    "solve": ("solve", "{spec}"),
    "check": ("check", "{spec}"),
    "check in two processes": ("check", "{spec}", "{other}", "--jobs", "2"),
    "tolerance": ("tolerance", "{toleranced}", "-n", "1024"),
    "sweep": ("sweep", "{spec}", "--vary", "radial_load=8kN:10kN:3"),
    "select": ("select", "{shaft}", "--catalogue", str(ROOT / "specs" / "catalogues" /
                                                      "example.csv")),
    "report": ("report", "{spec}", "--output", "{html}"),
}


@pytest.mark.parametrize("command", list(COMMANDS))
def test_debug_prints_the_traceback_of_an_internal_error(command, exploding_solver, cli,
                                                         tmp_path):
    spec = tmp_path / "bearing.yaml"
    spec.write_text((ROOT / "specs" / "rolling-bearing.yaml").read_text())
    toleranced = tmp_path / "toleranced.yaml"
    toleranced.write_text(spec.read_text().replace("radial_load: 9 kN",
                                                   "radial_load: 9 kN ± 0.5 kN"))
    assert "9 kN ± 0.5 kN" in toleranced.read_text()
    other = tmp_path / "other.yaml"
    other.write_text(spec.read_text())
    shaft = tmp_path / "shaft.yaml"  # select's: the shaft, not the bearing's dm
    shaft.write_text(spec.read_text().replace("pitch_diameter: 46 mm", "bore_diameter: 30 mm"))
    args = [arg.format(spec=spec, toleranced=toleranced, other=other, shaft=shaft,
                       html=tmp_path / "r.html") for arg in COMMANDS[command]]
    quiet = cli(*args)
    said = quiet.err + quiet.out  # check reports the spec's line in its report
    assert quiet.code == 2 and "internal error" in said and "ZeroDivisionError" in said
    assert "Traceback" not in said
    loud = cli(*args, "--debug")
    assert loud.code == 2
    assert "Traceback (most recent call last)" in loud.err
    assert "induced for the test" in loud.err and "in explode" in loud.err
    # the switch is the run's own: the next run without --debug is quiet again
    assert "Traceback" not in cli(*args).err


def test_induced_axial_factor_on_a_located_shaft_is_refused_in_one_line(cli, spec_file):
    text = (ROOT / "specs" / "bevel-drive.yaml").read_text()
    located = text.replace("static_factor: 12, bore_diameter: 25 mm",
                           "static_factor: 12, induced_axial_factor: 0.3, bore_diameter: "
                           "25 mm", 1)
    assert located != text
    path = spec_file(located, "drive.yaml")
    run = cli("solve", path)
    assert run.code == 2
    (line,) = run.err.strip().splitlines()
    assert line.startswith(f"{path}:") and "pinion_bearings.1.induced_axial_factor" in line
    assert "locating-floating" in line and "back-to-back" in line


def test_induced_axial_factor_still_sets_r_on_an_adjusted_shaft(cli, spec_file):
    """The same field on an adjusted pair is R itself: the induced load is R·Fr."""
    text = (ROOT / "specs" / "bevel-drive-tapered.yaml").read_text()
    given = text.replace("load_factors: {e: 0.37, y: 1.6, y0: 0.9},\n     bore_diameter: 25 mm",
                         "load_factors: {e: 0.37, y: 1.6, y0: 0.9}, induced_axial_factor: "
                         "0.25,\n     bore_diameter: 25 mm", 1)
    assert given != text
    (record,) = solve_json(cli, spec_file(given, "drive.yaml"))
    results = record["results"]
    assert np.isclose(results["pinion_bearing_1_induced_axial_load"],
                      0.25 * results["pinion_bearing_1_radial_load"], rtol=1e-12)


def test_a_drive_sweeps_its_static_safety_limit(cli):
    """The limit is one of the numbers a sweep makes an array: the margin follows it."""
    run = cli("sweep", ROOT / "specs" / "bevel-drive.yaml", "--vary",
              "limits.min_static_safety=1:2:3", "--format", "json")
    assert run.code in (0, 1), run.err
    points = [json.loads(line) for line in run.out.splitlines()]
    margins = [point["results"]["static_safety_margin"] for point in points]
    assert len(margins) == 3
    assert np.allclose(np.diff(margins), -0.5, rtol=1e-12)
