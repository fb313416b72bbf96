"""Ball-bearing kinematics: published defect frequencies, identities, and a numerical
3-D solve of the race-control conditions that shares none of the closed forms."""

from __future__ import annotations

import json

import numpy as np
import pytest

from bearingcalc.core.ball_bearing_kinematics import ball_kinematics
from tests.conftest import ROOT

TAU = 2 * np.pi


def test_case_western_reserve_6205_drive_end_bearing():
    """Case Western Reserve University Bearing Data Center, 'Bearing information':
    6205-2RS JEM SKF deep-groove bearing, Z = 9, Dw = 0.3126 in, Dpw = 1.537 in,
    α = 0; defect frequencies as multiples of the shaft speed: BPFI 5.4152, BPFO
    3.5848, FTF 0.39828, rolling element (2·BSF) 4.7135. (Their FTF is rounded in the
    fourth digit, and their 2·BSF in the fifth: 0.39831 and 4.71344 follow from their own
    dimensions.)"""
    k = ball_kinematics(9, 0.3126, 1.537, 0.0, TAU, 0.0)
    assert round(float(k["ball_pass_frequency_inner"]), 4) == 5.4152
    assert round(float(k["ball_pass_frequency_outer"]), 4) == 3.5848
    assert float(k["cage_frequency"]) == pytest.approx(0.39828, abs=5e-5)
    assert 2 * float(k["ball_spin_frequency"]) == pytest.approx(4.7135, abs=1e-4)


def _random_geometries(n, seed):
    rng = np.random.default_rng(seed)
    dw = rng.uniform(2e-3, 30e-3, n)
    dpw = dw / rng.uniform(0.05, 0.45, n)
    alpha = rng.uniform(0.0, np.radians(60), n)
    w_i = rng.uniform(-2000, 2000, n)
    w_o = rng.uniform(-2000, 2000, n)
    return dw, dpw, alpha, w_i, w_o


def test_identities_of_the_defect_frequencies():
    dw, dpw, alpha, w_i, w_o = _random_geometries(5000, 1)
    k = ball_kinematics(11, dw, dpw, alpha, w_i, w_o)
    relative = np.abs(w_i - w_o) / TAU
    assert np.allclose(k["ball_pass_frequency_outer"] + k["ball_pass_frequency_inner"],
                       11 * relative, rtol=1e-12)
    assert np.allclose(k["ball_pass_frequency_outer"],
                       11 * np.abs(k["cage_frequency"] - w_o / TAU), rtol=1e-12)


def _three_d_solve(dw, dpw, alpha, w_i, w_o, control):
    """Unknowns: the cage speed Ω and the ball's absolute angular velocity ω (3 numbers).
    Conditions, written as vectors in the fixed frame: no slip at both contact centres
    (velocity of the ball's material point = velocity of the ring's), the ball's
    angular velocity relative to the cage in the meridian plane, no spin at the
    controlling race. Solved by least squares; nothing here uses the closed forms."""
    ex, er, et = np.eye(3)                       # axis, radial (to the ball), tangential
    big_r, r = dpw / 2, dw / 2
    centre = big_r * er
    normal = np.cos(alpha) * er + np.sin(alpha) * ex
    contacts = {"inner": (centre - r * normal, w_i), "outer": (centre + r * normal, w_o)}

    def cross_matrix(v):
        return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])

    rows, rhs = [], []
    for point, ring in contacts.values():
        # ball: Ω ex × G + ω × (P − G); ring: ring·ex × P
        a = np.zeros((3, 4))
        a[:, 0] = np.cross(ex, centre)
        a[:, 1:] = -cross_matrix(point - centre)      # ω × d = −d × ω
        rows.extend(a)
        rhs.extend(ring * np.cross(ex, point))
    rows.append(np.concatenate([[0.0], et]))           # (ω − Ω ex)·et = 0
    rhs.append(0.0)
    point, ring = contacts[control]
    rows.append(np.concatenate([[0.0], normal]))       # (ring ex − ω)·n = 0
    rhs.append(ring * normal @ ex)
    solution, *_ = np.linalg.lstsq(np.array(rows), np.array(rhs), rcond=None)
    cage, omega = solution[0], solution[1:]
    relative = omega - cage * ex

    def ratio(name, side):
        _, ring = contacts[name]
        rel = (ring - cage) * ex - relative
        tangent = np.cos(alpha) * ex - np.sin(alpha) * er
        return (side * rel @ normal) / (rel @ tangent)

    return cage, relative, ratio("inner", -1.0), ratio("outer", 1.0)


@pytest.mark.parametrize("control", ["outer", "inner"])
def test_race_control_matches_a_numerical_3d_solve(control):
    dw, dpw, alpha, w_i, w_o = _random_geometries(2000, 2 if control == "outer" else 3)
    k = ball_kinematics(9, dw, dpw, alpha, w_i, w_o, control)
    for i in range(len(dw)):
        cage, relative, inner, outer = _three_d_solve(dw[i], dpw[i], alpha[i], w_i[i],
                                                      w_o[i], control)
        scale = abs(w_i[i]) + abs(w_o[i])
        assert k["cage_speed"][i] == pytest.approx(cage, rel=1e-9, abs=1e-12 * scale)
        assert k["ball_speed_relative_to_cage"][i] == pytest.approx(
            np.linalg.norm(relative), rel=1e-9, abs=1e-9 * scale)
        axis_angle = np.arctan2(-relative[1], relative[0])
        line = (axis_angle + np.pi / 2) % np.pi - np.pi / 2
        assert k["ball_attitude_angle"][i] == pytest.approx(line, abs=1e-9)
        assert k["inner_spin_to_roll"][i] == pytest.approx(inner, rel=1e-9, abs=1e-12)
        assert k["outer_spin_to_roll"][i] == pytest.approx(outer, rel=1e-9, abs=1e-12)


def test_harris_attitude_angles():
    """Harris & Kotzalas ch. 8: tanβ = sinα/(cosα + Dw/Dpw) with outer-race control,
    sinα/(cosα − Dw/Dpw) with inner-race control."""
    alpha, dw, dpw = np.radians(40), 10e-3, 50e-3
    outer = ball_kinematics(10, dw, dpw, alpha, 100.0, 0.0, "outer")["ball_attitude_angle"]
    inner = ball_kinematics(10, dw, dpw, alpha, 100.0, 0.0, "inner")["ball_attitude_angle"]
    assert float(outer) == pytest.approx(np.arctan(np.sin(alpha) / (np.cos(alpha) + 0.2)),
                                         rel=1e-13)
    assert float(inner) == pytest.approx(np.arctan(np.sin(alpha) / (np.cos(alpha) - 0.2)),
                                         rel=1e-13)


def test_no_spin_at_zero_contact_angle_and_none_at_the_controlling_race():
    k = ball_kinematics(9, 8e-3, 40e-3, 0.0, 300.0, 0.0)
    assert abs(float(k["inner_spin_to_roll"])) < 1e-15
    assert float(k["outer_spin_to_roll"]) == 0.0
    k = ball_kinematics(9, 8e-3, 40e-3, np.radians(25), 300.0, 0.0, "inner")
    assert float(k["inner_spin_to_roll"]) == 0.0 and float(k["outer_spin_to_roll"]) != 0.0


def test_an_outer_ring_turning_with_the_inner_fixed():
    """The cage follows the turning outer ring at (1 + γ)/2 of its speed; the ball-pass
    frequencies swap their roles."""
    gamma = 8 / 40
    k = ball_kinematics(9, 8e-3, 40e-3, 0.0, 0.0, TAU * 10)
    assert float(k["cage_frequency"]) == pytest.approx(10 * (1 + gamma) / 2, rel=1e-14)
    assert float(k["ball_pass_frequency_inner"]) == pytest.approx(9 * 10 * (1 + gamma) / 2,
                                                                  rel=1e-14)
    assert float(k["ball_pass_frequency_outer"]) == pytest.approx(9 * 10 * (1 - gamma) / 2,
                                                                  rel=1e-14)


SPEC = """kind: ball-bearing
type: angular-contact
contact_angle: 40 deg
ball_count: 12
ball_diameter: 11.112 mm
pitch_diameter: 60 mm
radial_load: 1 kN
axial_load: 2 kN
inner_speed: 10000 rpm
outer_speed: 0 rpm
limits: {max_spin_to_roll: 0.25}
"""


def test_kinematics_in_every_format_and_the_spin_margin(cli, spec_file):
    path = spec_file(SPEC)
    for fmt in ("table", "json", "csv"):
        run = cli("solve", path, "-f", fmt)
        assert run.code == 0, run.err
        assert "ball_pass_frequency_outer" in run.out
    record = json.loads(cli("solve", path, "-f", "json").out)
    results = record["results"]
    assert results["outer_spin_to_roll"] == 0.0
    assert results["spin_to_roll_margin"] == pytest.approx(
        0.25 - abs(results["inner_spin_to_roll"]), rel=1e-15)
    run = cli("solve", spec_file(SPEC.replace("0.25", "0.1")))
    assert run.code == 1 and "spin_to_roll_margin" in run.out


def test_speed_alone_means_the_inner_ring_turning(cli, spec_file):
    both = json.loads(cli("solve", spec_file(SPEC), "-f", "json").out)["results"]
    alone = json.loads(cli("solve", spec_file(SPEC.replace(
        "inner_speed: 10000 rpm\nouter_speed: 0 rpm", "speed: 10000 rpm")), "-f", "json").out)
    assert alone["results"] == both


@pytest.mark.parametrize(("text", "fragment"), [
    (SPEC + "speed: 100 rpm\n", "not both"),
    (SPEC.replace("outer_speed: 0 rpm", "outer_speed: 10000 rpm"), "must turn relative"),
    (SPEC.replace("inner_speed: 10000 rpm\nouter_speed: 0 rpm\n", ""), "missing: give speed"),
    (SPEC + "race_control: middle\n", "must be one of outer, inner, got 'middle'"),
])
def test_bad_speeds_are_one_clear_line(cli, spec_file, text, fragment):
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1 and fragment in run.err, run.err


def test_tolerance_gives_the_band_of_each_defect_frequency(cli):
    run = cli("tolerance", ROOT / "specs" / "tolerances" / "ball-bearing-kinematics.yaml",
              "-n", "4096", "-f", "json")
    assert run.code == 0, run.err  # no margin: nothing to exceed
    results = json.loads(run.out)["results"]
    for key in ("ball_pass_frequency_outer", "ball_pass_frequency_inner", "cage_frequency",
                "ball_spin_frequency"):
        band = results[key]["worst_case"]
        assert band["min"] < results[key]["nominal"] < band["max"], key
