"""``method: iso-16281`` of ``kind: rolling-bearing`` through the command line: every
result against the independent scalar reference (``tests/iso16281_reference.py``:
scipy's root on its own residual, its own Hertz and life), and each bad input one line
with exit status 2."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests import iso16281_reference as reference
from tests.conftest import csv_column, solve_json

#: The material a spec that names none takes: steel, E = 207.5 GPa, ν = 0.3.
STEEL = 207.5e9

DEEP_GROOVE = """kind: rolling-bearing
type: deep-groove
method: iso-16281
dynamic_load_rating: 14.8 kN
static_load_rating: 7.8 kN
ball_count: 9
ball_diameter: 7.938 mm
pitch_diameter: 38.5 mm
inner_groove_conformity: 0.52
outer_groove_conformity: 0.53
operating_clearance: {clearance}
radial_load: 2 kN
axial_load: {axial}
speed: 3000 rpm
{extra}
"""
ANGULAR = """kind: rolling-bearing
type: angular-contact
method: iso-16281
contact_angle: 40 deg
dynamic_load_rating: 31 kN
static_load_rating: 20 kN
ball_count: 12
ball_diameter: 11.112 mm
pitch_diameter: 52.5 mm
inner_groove_conformity: 0.515
outer_groove_conformity: 0.525
radial_load: 3 kN
axial_load: {axial}
speed: 3000 rpm
{extra}
"""


def _solved(cli, spec_file, text):
    [record] = solve_json(cli, spec_file(text))
    return record["results"]


def _reference(bearing, forces, c, imposed=None):
    solved = reference.solve_equilibrium(bearing, forces,
                                         imposed={"z": 0, "tilt_y": 0, **(imposed or {})})
    life = reference.ball_reference_life(bearing, solved["load"], c)
    inner, outer = reference.ball_pressures(bearing, solved["load"], solved["angle"])
    return solved, life, max(inner.max(), outer.max())


@pytest.mark.parametrize(("clearance", "axial", "moment"), [
    (10e-6, 300.0, 2.0), (0.0, 0.0, 0.0), (-4e-6, 800.0, -1.5), (30e-6, 0.0, 0.0)])
def test_a_deep_groove_bearing_is_the_references(cli, spec_file, clearance, axial, moment):
    extra = f"tilting_moment: {moment} N*m" if moment else ""
    results = _solved(cli, spec_file, DEEP_GROOVE.format(
        clearance=f"{clearance * 1e6} µm", axial=f"{axial} N", extra=extra))
    bearing = reference.BallBearing(9, 7.938e-3, 38.5e-3, 0.52, 0.53,
                                    diametral_clearance=clearance, elastic_modulus=STEEL)
    solved, life, pressure = _reference(bearing, (axial, 2000.0, 0, 0, moment), 14800.0)
    q = solved["q"]
    assert results["ring_displacement_radial"] == pytest.approx(q[1], rel=1e-8)
    assert results["ring_displacement_axial"] == pytest.approx(q[0], rel=1e-8, abs=1e-15)
    assert results["ring_tilt"] == pytest.approx(q[4], rel=1e-8, abs=1e-15)
    assert results["max_element_load"] == pytest.approx(solved["load"].max(), rel=1e-8)
    assert results["loaded_elements"] == np.count_nonzero(solved["load"] > 0)
    revolutions = 3000 / 60
    assert results["reference_rating_life"] == pytest.approx(
        life["life_million"] * 1e6 / revolutions, rel=1e-8)
    assert results["reference_rating_life_revolutions"] == pytest.approx(
        life["life_million"] * 1e6, rel=1e-8)
    assert results["dynamic_equivalent_reference_load"] == pytest.approx(
        life["reference_load"], rel=1e-8)
    assert results["life_ratio_to_iso281"] == pytest.approx(
        results["reference_rating_life"] / results["basic_rating_life"], rel=1e-12)
    assert results["max_contact_pressure"] == pytest.approx(pressure, rel=1e-7)
    assert results["stiffness_radial"] == pytest.approx(solved["stiffness"][1, 1], rel=1e-5)
    assert results["equilibrium_residual"] < 1e-9
    loads = [results[f"element_{k}_load"] for k in range(1, 10)]
    np.testing.assert_allclose(loads, solved["load"], rtol=1e-8, atol=1e-8 * max(loads))


def test_an_angular_contact_bearing_is_the_references(cli, spec_file):
    results = _solved(cli, spec_file, ANGULAR.format(axial="4 kN", extra=""))
    bearing = reference.BallBearing(12, 11.112e-3, 52.5e-3, 0.515, 0.525,
                                    free_contact_angle=math.radians(40),
                                    elastic_modulus=STEEL)
    solved, life, _ = _reference(bearing, (4000.0, 3000.0, 0, 0, 0), 31000.0)
    assert results["ring_displacement_axial"] == pytest.approx(solved["q"][0], rel=1e-8)
    angles = np.abs(solved["angle"][solved["load"] > 0])
    assert results["operating_contact_angle_max"] == pytest.approx(angles.max(), rel=1e-8)
    assert results["operating_contact_angle_min"] == pytest.approx(angles.min(), rel=1e-8)
    assert results["reference_rating_life_revolutions"] == pytest.approx(
        life["life_million"] * 1e6, rel=1e-8)


def test_an_imposed_misalignment_reports_the_moment_it_takes(cli, spec_file):
    results = _solved(cli, spec_file, DEEP_GROOVE.format(
        clearance="5 µm", axial="500 N", extra="misalignment: 2 mrad"))
    bearing = reference.BallBearing(9, 7.938e-3, 38.5e-3, 0.52, 0.53,
                                    diametral_clearance=5e-6, elastic_modulus=STEEL)
    solved, _, _ = _reference(bearing, (500.0, 2000.0, 0, 0, 0), 14800.0,
                              imposed={"tilt_z": 2e-3})
    assert results["ring_tilt"] == pytest.approx(2e-3, rel=1e-12)
    assert results["tilting_moment_reaction"] == pytest.approx(solved["reaction"][4],
                                                               rel=1e-7)


@pytest.mark.parametrize(("text", "field"), [
    (DEEP_GROOVE.format(clearance="10 µm", axial="0 N", extra="").replace(
        "type: deep-groove", "type: spherical-roller"), "type"),
    (DEEP_GROOVE.format(clearance="10 µm", axial="0 N", extra="").replace(
        "method: iso-16281", "method: iso-281"), "operating_clearance"),
    (DEEP_GROOVE.format(clearance="10 µm", axial="0 N",
                        extra="tilting_moment: 1 N*m\nmisalignment: 1 mrad"), "misalignment"),
    (DEEP_GROOVE.format(clearance="10 µm", axial="0 N", extra="").replace(
        "operating_clearance: 10 µm\n", ""), "operating_clearance"),
    (ANGULAR.format(axial="4 kN", extra="operating_clearance: 10 µm"), "operating_clearance"),
    (DEEP_GROOVE.format(clearance="10 µm", axial="0 N", extra="").replace(
        "inner_groove_conformity: 0.52\n", ""), "inner_groove_conformity"),
    (DEEP_GROOVE.format(clearance="2 mm", axial="0 N", extra=""), "operating_clearance"),
    (ANGULAR.format(axial="4 kN", extra="arrangement: back-to-back\nwidth: 16 mm"),
     "setting"),
    (DEEP_GROOVE.format(clearance="10 µm", axial="0 N", extra="").replace(
        "radial_load: 2 kN\naxial_load: 0 N\nspeed: 3000 rpm\n",
        "duty_cycle:\n  - {time: 0.5, radial_load: 2 kN, speed: 3000 rpm}\n"
        "  - {time: 0.5, radial_load: 1 kN, speed: 1000 rpm}\n"), "duty_cycle"),
    (DEEP_GROOVE.format(clearance="10 µm", axial="0 N", extra="").replace(
        "method: iso-16281", "method: iso-999"), "method"),
])
def test_bad_input_is_one_line(cli, spec_file, text, field):
    path = spec_file(text)
    run = cli("solve", path)
    assert run.code == 2, run.out
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in run.err, run.err
    assert f" {field}" in lines[0] or f".{field}" in lines[0] or f"{field}:" in lines[0], lines


def test_an_angular_contact_bearing_without_axial_load_finds_no_equilibrium(cli, spec_file):
    run = cli("solve", spec_file(ANGULAR.format(axial="0 N", extra="")))
    assert run.code == 2
    assert "no equilibrium" in run.err and len(run.err.strip().splitlines()) == 1, run.err


def test_a_sweep_of_the_clearance_is_each_point_solved_alone(cli, spec_file, tmp_path):
    path = spec_file(DEEP_GROOVE.format(clearance="10 µm", axial="300 N", extra=""))
    out = tmp_path / "sweep.csv"
    run = cli("sweep", path, "--vary", "operating_clearance=-5um:40um:6", "--output", out)
    assert run.code in (0, 1), run.err
    text = out.read_text()
    clearances = csv_column(text, "input.operating_clearance [m]")
    radial = csv_column(text, "ring_displacement_radial [m]")
    assert len(clearances) == 6
    for clearance, found in zip(clearances, radial, strict=True):
        bearing = reference.BallBearing(9, 7.938e-3, 38.5e-3, 0.52, 0.53,
                                        diametral_clearance=clearance, elastic_modulus=STEEL)
        solved, _, _ = _reference(bearing, (300.0, 2000.0, 0, 0, 0), 14800.0)
        assert found == pytest.approx(solved["q"][1], rel=1e-8)


def test_a_light_load_with_much_clearance_warns(cli, spec_file):
    """40 µm of clearance under 100 N: one ball carries the load, the zone is below 90°,
    and P is below 1 % of C."""
    [record] = solve_json(cli, spec_file(DEEP_GROOVE.format(
        clearance="40 µm", axial="0 N", extra="").replace("radial_load: 2 kN",
                                                         "radial_load: 100 N")))
    results = record["results"]
    assert results["loaded_elements"] == 1
    assert results["load_zone_angle"] < math.pi / 2
    warned = " ".join(record["warnings"])
    assert "one rolling element carries the whole load" in warned
    assert "load zone is below 90°" in warned
    assert "minimum load" in warned


def test_new_prints_the_methods_template_and_it_checks(cli, spec_file):
    run = cli("new", "rolling-bearing", "--method", "iso-16281")
    assert run.code == 0 and "method: iso-16281" in run.out
    [record] = solve_json(cli, spec_file(run.out))
    assert record["results"]["equilibrium_residual"] < 1e-9


@pytest.mark.parametrize("args", [("--method", "iso-1628"),
                                  ("--method", "iso-16281", "--type", "deep-groove")])
def test_new_refuses_an_unknown_method_or_both_options(cli, args):
    run = cli("new", "rolling-bearing", *args)
    assert run.code == 2 and "--method" in run.err
