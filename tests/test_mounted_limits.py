"""Bearings as mounted in their classic limits, each against a computation that shares
nothing with the solver: Sjövall's load integrals by ``scipy.integrate.quad``, Harris's
closed form of a ball bearing's axial law (``tests/iso16281_shaft_reference.py``), and
ISO 281's load-case table of an adjusted pair.

- A straight-roller bearing with many rollers at zero clearance: the reference life
  L10r·(Fr/C)⁴ tends to the value the continuous load distribution gives (ISO/TS
  16281's roller life scales with (C/Fr)⁴ at a fixed load zone, where ISO 281 rounds
  the exponent to 10/3).
- An adjusted tapered pair at zero end play under a radial load: each bearing's load
  zone is 180° and its axial load Fa/(Fr·tanα) tends to J_a/J_r(ε = ½) = 1.2580 of line
  contact; ISO 281's table takes 0.5/Y = 1.25 (Y = 0.4·cot α). With ISO's logarithmic
  profile the rollers' laminae come into contact one by one, which stiffens the
  roller's load law toward point contact's (1.2158), so the ratio falls to about 1.213.
- A preloaded ball pair: the external thrust at which the second bearing lifts off is
  Harris's axial load at twice the preload deflection.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from bearingcalc.core.iso16281_life import roller_reference_life
from bearingcalc.core.iso16281_rollers import roller_geometry, solve_roller_equilibrium
from tests import iso16281_reference as reference
from tests import iso16281_shaft_reference as shaft
from tests.conftest import solve_json
from tests.mounted_specs import refused_lines, solved_with_limits


def _mean(power: float) -> float:
    """(1/2π)∫ cos^p ψ dψ over the half-filled load zone |ψ| < π/2."""
    value, _ = integrate.quad(lambda psi: math.cos(psi) ** power, -math.pi / 2, math.pi / 2,
                              epsabs=1e-14, epsrel=1e-13)
    return value / (2.0 * math.pi)


def _continuous_roller_life_constant(gamma: float) -> float:
    """L10r·(Fr/C)⁴ [10⁶ rev] of a radial roller bearing with a continuous ring of
    straight rollers at zero clearance, inner ring turning: Q(ψ) = Q_max·cos^(10/9)ψ,
    Fr = Z·Q_max·J_r, the equivalent loads the 4th (rotating) and 4.5th (stationary)
    power means, the raceway ratings of ISO/TS 16281 8.3 with λν = 0.83."""
    j_r = _mean(19 / 9)
    x = 1.038 * ((1 - gamma) / (1 + gamma)) ** (143 / 108)
    inner = 0.83 * 0.378 * _mean(40 / 9) ** 0.25 / j_r * (1 + x ** 4.5) ** (-2 / 9)
    outer = 0.83 * 0.364 * _mean(5.0) ** (1 / 4.5) / j_r * (1 + x ** -4.5) ** (-2 / 9)
    return (inner ** 4.5 + outer ** 4.5) ** (-8 / 9)


@pytest.mark.parametrize(("count", "tolerance"), [(100, 2e-3), (400, 2e-4)])
def test_many_straight_rollers_tend_to_the_continuous_life(count, tolerance):
    dwe, dpw, fr, c = 2e-3, 0.4, 5e4, 3e5
    geometry = roller_geometry(count, dwe, 3e-3, 0.0, laminae=20, profile="none")
    solved = solve_roller_equilibrium(geometry, np.array([[0.0, fr, 0.0, 0.0, 0.0]]))
    life = roller_reference_life(solved.lamina_load, np.array([count]), dwe, dpw, 0.0,
                                 np.array([c]))
    measured = life.revolutions[0] / 1e6 * (fr / c) ** 4
    expected = _continuous_roller_life_constant(dwe / dpw)
    assert measured == pytest.approx(expected, rel=tolerance)


TAPERED_PAIR = """kind: rolling-bearing
type: tapered-roller
arrangement: back-to-back
method: iso-16281
dynamic_load_rating: 54 kN
roller_count: {count}
roller_diameter: 7.5 mm
roller_length: 14 mm
pitch_diameter: {pitch}
contact_angle: 14 deg
roller_profile: {profile}
pair_spacing: 100 mm
setting: {{end_play: 0 µm}}
radial_load: 12 kN
speed: 1000 rpm
"""


def _ratio(cli, spec_file, count, pitch, profile):
    [record] = solve_json(cli, spec_file(TAPERED_PAIR.format(count=count, pitch=pitch,
                                                              profile=profile)))
    results = record["results"]
    assert results["load_zone_angle"] == pytest.approx(math.pi, rel=1e-9)
    return results["bearing_1_axial_load"] / (results["bearing_1_radial_load"]
                                             * math.tan(math.radians(14)))


def test_zero_end_play_gives_half_load_zones_and_the_tables_axial_load(cli, spec_file):
    """J_a/J_r at ε = ½ of line contact by quad; 40 rollers within 0.15 % of it, 160
    within 0.01 %; ISO 281's 0.5/Y = 1.25 within 0.7 %."""
    continuous = _mean(10 / 9) / _mean(19 / 9)
    assert continuous == pytest.approx(1.2580, abs=1e-4)
    assert _ratio(cli, spec_file, 40, "100 mm", "none") == pytest.approx(continuous,
                                                                         rel=1.5e-3)
    assert _ratio(cli, spec_file, 160, "400 mm", "none") == pytest.approx(continuous,
                                                                          rel=1e-4)
    assert continuous == pytest.approx(1.25, rel=7e-3)


def test_the_iso_profile_stiffens_the_rollers_load_law(cli, spec_file):
    """Profiled, a roller's contact lengthens as it is loaded, so its load grows faster
    than δ^(10/9): the ratio falls below line contact's J_a/J_r, to about point
    contact's (exponent 3/2), 3 % below ISO 281's table."""
    point, line = _mean(1.5) / _mean(2.5), _mean(10 / 9) / _mean(19 / 9)
    profiled = _ratio(cli, spec_file, 160, "400 mm", "iso")
    assert profiled < 0.98 * line
    assert profiled == pytest.approx(point, rel=1e-2)


BALL_PAIR = """kind: rolling-bearing
type: angular-contact
arrangement: back-to-back
method: iso-16281
contact_angle: 40 deg
dynamic_load_rating: 24 kN
ball_count: 12
ball_diameter: 11.112 mm
pitch_diameter: 52.5 mm
inner_groove_conformity: 0.52
outer_groove_conformity: 0.53
pair_spacing: 80 mm
setting: {{end_play: -20 µm}}
radial_load: 0 N
axial_load: {axial} N
speed: 1000 rpm
"""


def test_the_second_bearing_lifts_off_at_harris_axial_load(cli, spec_file):
    """End play −20 µm: each bearing 10 µm past first contact at rest. The shaft moves
    10 µm under the thrust that unloads bearing 2, so bearing 1 is then 20 µm past
    first contact: the lift-off thrust is Harris's F_a(δa = 20 µm)."""
    bearing = reference.BallBearing(12, 11.112e-3, 52.5e-3, 0.52, 0.53,
                                    free_contact_angle=math.radians(40),
                                    elastic_modulus=207.5e9)
    lift_off = shaft.lift_off_thrust(bearing, -20e-6)
    assert lift_off == pytest.approx(shaft.ball_axial_load(bearing, 20e-6), rel=1e-12)
    below, above = (solve_json(cli, spec_file(BALL_PAIR.format(axial=lift_off * factor)))[0]
                    ["results"] for factor in (0.999, 1.001))
    assert below["bearing_2_axial_load"] > 0.0
    assert below["bearing_2_axial_load"] < 2e-3 * lift_off
    assert above["bearing_2_axial_load"] == 0.0
    assert above["bearing_1_axial_load"] == pytest.approx(lift_off * 1.001, rel=1e-9)


ORDER = ("x", "y", "z", "tilt_y", "tilt_z")


def _matrix(results):
    """The 5 × 5 tangent stiffness from its entries on and above the diagonal."""
    matrix = np.empty((5, 5))
    for i, a in enumerate(ORDER):
        for j, b in enumerate(ORDER[i:], start=i):
            matrix[i, j] = matrix[j, i] = results[f"stiffness_matrix_{a}_{b}"]
    return matrix


def test_the_stiffness_matrix_is_central_differences_of_the_references_forces(cli):
    """specs/rolling-bearing-mounted.yaml: every entry against the independent reference's
    central differences at its own equilibrium (scipy's root), to 1e-6 of the largest
    entry of its kind (translation, coupling, tilt)."""
    [record] = solve_json(cli, "specs/rolling-bearing-mounted.yaml")
    bearing = reference.BallBearing(9, 7.938e-3, 38.5e-3, 0.52, 0.53,
                                    diametral_clearance=10e-6, elastic_modulus=207.5e9)
    solved = reference.solve_equilibrium(bearing, (300.0, 2000.0, 0.0, 0.0, 2.0))
    mine, theirs = _matrix(record["results"]), solved["stiffness"]
    for rows, columns in ((slice(0, 3), slice(0, 3)), (slice(0, 3), slice(3, 5)),
                          (slice(3, 5), slice(3, 5))):
        block = theirs[rows, columns]
        np.testing.assert_allclose(mine[rows, columns], block, rtol=1e-6,
                                   atol=1e-6 * np.abs(block).max())


def test_a_pairs_stiffness_matrix_is_its_shafts(cli):
    """specs/rolling-bearing-mounted-pair.yaml: the matrix of the shaft midway between the
    pressure centres, against the independent shaft reference's central differences."""
    [record] = solve_json(cli, "specs/rolling-bearing-mounted-pair.yaml")
    bearing = reference.BallBearing(12, 9.525e-3, 46e-3, 0.52, 0.53,
                                    free_contact_angle=math.radians(40),
                                    elastic_modulus=207.5e9)
    spacing = record["results"]["pair_spacing_used"]
    end_play = shaft.end_play_for_preload(bearing, 300.0)
    pair = shaft.matched_pair(bearing, (-spacing / 2, spacing / 2), "back-to-back", end_play)
    theirs = shaft.solve_shaft(pair, (1500.0, 3000.0, 0.0, 0.0, 0.0))["stiffness"]
    mine = _matrix(record["results"])
    np.testing.assert_allclose(mine, theirs, rtol=1e-5, atol=1e-6 * np.abs(theirs).max())


ANGULAR = """kind: rolling-bearing
type: angular-contact
method: iso-16281
contact_angle: 40 deg
ball_count: 120
ball_diameter: 5 mm
pitch_diameter: 200 mm
inner_groove_conformity: 0.52
outer_groove_conformity: 0.53
radial_load: 100 N
axial_load: {axial} N
misalignment: 0 rad
speed: 1000 rpm
"""


def test_an_angular_contact_bearing_meets_iso_281s_x_and_y_at_a_half_load_zone(
        cli, spec_file):
    """ISO 281 rates a radial bearing at a load zone of 180°, its ring held square (a
    misalignment of 0; a single bearing left free to tilt narrows its load zone). A 40°
    bearing of many balls under Fa/Fr = J_a/J_r·tan α (point contact, ε = ½: 1.02), its
    load zone 180°, has P_ref = Fr = ISO 281's P (Fa/Fr below e = 1.14) within 1 %.
    Above e, ISO 281's X = 0.35 and Y = 0.57 are one straight line fitted to
    Lundberg and Palmgren's curve of P against Fa/Fr and rounded to two digits, and take
    the contact angle as it was before loading: P_ref lies below it, by 6 to 25 %, the
    conservative side."""
    point = _mean(1.5) / _mean(2.5) * math.tan(math.radians(40))
    assert point == pytest.approx(1.02, abs=5e-3)
    [half] = solve_json(cli, spec_file(ANGULAR.format(axial=100 * point)))
    results = half["results"]
    assert results["load_zone_angle"] == pytest.approx(math.pi, rel=0.03)
    assert results["dynamic_equivalent_reference_load"] == pytest.approx(
        results["equivalent_dynamic_load"], rel=0.01)
    for ratio in (1.2, 2.0, 5.0, 20.0):
        [record] = solve_json(cli, spec_file(ANGULAR.format(axial=100 * ratio)))
        results = record["results"]
        share = results["dynamic_equivalent_reference_load"] / results[
            "equivalent_dynamic_load"]
        assert 0.75 < share < 0.94, ratio


def test_the_stiffness_limits_judge_the_bearing_as_mounted(cli, spec_file):
    """limits.min_stiffness_radial and min_stiffness_axial: margins k/k_min − 1, a FAIL
    below; refused in one line under the catalogue method, whose bearing has none."""
    text, record = solved_with_limits(
        cli, spec_file, "rolling-bearing-mounted.yaml", "  min_rating_life: 1500 h",
        ("min_stiffness_radial: 100 N/µm", "min_stiffness_axial: 50 N/µm"))
    results = record["results"]
    assert results["stiffness_radial_margin"] == pytest.approx(
        results["stiffness_radial"] / 1e8 - 1.0, rel=1e-12)
    assert results["stiffness_axial_margin"] == pytest.approx(
        results["stiffness_axial"] / 5e7 - 1.0, rel=1e-12)
    failed = [v["key"] for v in record["verdicts"] if not v["passed"]]
    assert failed == ["stiffness_axial_margin"]
    catalogue = text.replace("method: iso-16281\n", "").replace(
        "operating_clearance: 10 µm\n", "").replace("tilting_moment: 2 N*m\n", "")
    lines = refused_lines(cli, spec_file, catalogue)
    assert len(lines) == 1 and ": limits.min_stiffness_radial: " in lines[0], lines
