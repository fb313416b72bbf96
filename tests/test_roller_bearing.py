"""Roller bearings (kind: rolling-bearing): a table typed from two outside sources, the
equivalent loads from the printed factors, published numbers and an independent kinematic
and contact computation. No expected value is taken from the code under test."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingcalc.core import arrangements, iso281
from bearingcalc.core import roller_bearing_contacts as rbc
from bearingcalc.core import roller_ratings as rr
from bearingcalc.core.bearing_types import names_where
from tests.conftest import solve_json

DEG = math.pi / 180.0
REL = 1e-12


def results_of(cli, spec_file, text):
    (record,) = solve_json(cli, spec_file(text))
    return record["results"]


# --- 1. ISO 281:2007 Table 7 (fc of radial roller bearings) ---------------------------------

#: Table 7 entered from two outside sources, which agree at every point they share
#: (tests/test_iso281_tables.py adds the standard's own print, GOST 18855-2013):
#: (A) a MATLAB function F04.m (public code of a GOST/ISO 281 bearing program) tabulating
#:     fc at γ = 0.01 to 0.30 in steps of 0.01, as ISO 281:2007 prints it;
#: (B) the TypeScript "CRB-Designer: Cross-Roller Precision Tool" (public code), which
#:     holds every other row above 0.10 (0.01 to 0.10 by 0.01, 0.12 to 0.30 by 0.02).
TABLE_7_GAMMA = [i / 100 for i in range(1, 31)]
TABLE_7_GRID_B = [i / 100 for i in range(1, 11)] + [i / 100 for i in range(12, 31, 2)]
TABLE_7_SOURCE_A = dict(zip((i / 100 for i in range(1, 31)), [
    52.1, 60.8, 66.5, 70.7, 74.1, 76.9, 79.2, 81.2, 82.8, 84.2, 85.4, 86.4, 87.1, 87.7, 88.2,
    88.5, 88.7, 88.8, 88.8, 88.7, 88.5, 88.2, 87.9, 87.5, 87.0, 86.4, 85.8, 85.2, 84.5, 83.8],
    strict=True))
TABLE_7_SOURCE_B = [52.1, 60.8, 66.5, 70.7, 74.1, 76.9, 79.2, 81.2, 82.8, 84.2,
                    86.4, 87.7, 88.5, 88.8, 88.7, 88.2, 87.5, 86.4, 85.2, 83.8]


def fc_closed_form(gamma: float) -> float:
    """fc of a radial roller bearing, line contact (ISO/TR 1281-1:2008, the basis of
    ISO 281's Table 7, with λ·ν = 0.83)."""
    ratio = ((1 - gamma) / (1 + gamma)) ** (143 / 108)
    return (0.83 * 207.9 * gamma ** (2 / 9) * (1 - gamma) ** (29 / 27) / (1 + gamma) ** 0.25
            * (1 + (1.04 * ratio) ** 4.5) ** (-2 / 9))


def test_the_two_sources_agree_and_the_module_holds_the_same_table():
    assert [TABLE_7_SOURCE_A[round(g, 2)] for g in TABLE_7_GRID_B] == TABLE_7_SOURCE_B
    np.testing.assert_allclose(rr.RADIAL_FC_GAMMA, TABLE_7_GAMMA, rtol=0, atol=1e-15)
    assert rr.RADIAL_FC.tolist() == [TABLE_7_SOURCE_A[g] for g in TABLE_7_GAMMA]


@pytest.mark.parametrize("gamma", sorted(TABLE_7_SOURCE_A))
def test_every_printed_fc_is_the_closed_form_rounded_to_one_decimal(gamma):
    """The printed digit is the ISO/TR 1281-1 expression rounded to 0.1; the module's table
    (at its grid) and both outside sources (at every hundredth) must obey that."""
    exact = fc_closed_form(gamma)
    assert abs(TABLE_7_SOURCE_A[gamma] - exact) <= 0.05 + 1e-9
    on_grid = np.isclose(rr.RADIAL_FC_GAMMA, gamma, rtol=0, atol=1e-12)
    if on_grid.any():
        assert abs(float(rr.RADIAL_FC[on_grid][0]) - exact) <= 0.05 + 1e-9


def test_table_7_is_smooth_concave_with_one_maximum():
    """Every divided second difference is at most zero (a typo or a swapped pair of
    entries would break that; two equal neighbours at the top, 88.8 at 0.18 and 0.19,
    give one zero), so the slope changes sign once: the maximum is at γ = 0.18. The
    second differences are the closed form's within 4 × 0.05, what rounding to 0.1
    allows."""
    xs, ys = np.asarray(TABLE_7_GAMMA), np.asarray(rr.RADIAL_FC)
    slopes = np.diff(ys) / np.diff(xs)
    assert np.all(np.diff(slopes) <= 1e-9)
    assert np.count_nonzero(np.diff(np.sign(np.round(slopes, 9)[slopes != 0]))) == 1
    assert xs[np.argmax(ys)] == pytest.approx(0.18)
    exact = np.array([fc_closed_form(g) for g in TABLE_7_GAMMA])
    gap = np.diff(ys, 2) - np.diff(exact, 2)
    assert np.max(np.abs(gap)) <= 0.2 + 1e-9


# --- 2. and 3. C and C0 from the geometry ------------------------------------------------------
# tests/test_roller_bearing_published.py: C from the two raceways' Lundberg–Palmgren
# ratings, C0 from Hertz's line contact at 4000 MPa.

@pytest.mark.parametrize(("kind", "dwe", "alpha", "finite"), [
    *[("cylindrical-roller", dwe, 0.0, ok) for dwe, ok in ((0.5, False), (1.0, True),
                                                          (30.0, True), (31.0, False))],
    *[(kind, dwe, alpha, ok) for kind in names_where(family="roller", thrust=True)
      for dwe, alpha, ok in ((10.0, 50.0, True), (10.0, 90.0, True), (31.0, 90.0, False),
                             (0.5, 90.0, False), (45.0, 50.0, False))]])
def test_fc_is_nan_outside_tables_7_and_10(kind, dwe, alpha, finite):
    """Table 7 runs from γ = 0.01 to 0.30 (Dpw = 100 mm here); Table 10's 90° column
    too, its column for 45° < α < 60° to γ = Dwe·cosα/Dpw = 0.26."""
    c, fc = rr.roller_dynamic_load_rating(14, dwe / 1e3, 0.01, 0.1, alpha * DEG,
                                          bearing_type=kind)
    assert bool(np.isfinite(fc)) is finite and bool(np.isfinite(c)) is finite


# --- 5. equivalent loads P and P0 --------------------------------------------------------------

def p_iso(fr, fa, alpha_deg, kind, double, e=None, y=None, y1=None, y2=None, x=None):
    """ISO 281:2007, 7.2 (radial roller) and 8.2 (thrust roller), catalogue factors
    replacing the standard's where given. The factors are the printed ones, as typed from
    ISO 281:2007 and checked against GOST 18855-2013 (identical), Table 8: single row
    X = 0.40, Y = 0.40·cotα above e; double row Y = 0.45·cotα up to e, X = 0.67,
    Y = 0.67·cotα above; e = 1.5·tanα; Table 11: a single thrust bearing X = tanα,
    Y = 1."""
    a = alpha_deg * DEG
    if kind in ("cylindrical-roller", "needle-roller"):
        return fr
    if kind.startswith("thrust-"):
        return fa if alpha_deg == 90.0 else math.tan(a) * fr + fa
    cot = 1 / math.tan(a)
    if fa / fr <= (1.5 * math.tan(a) if e is None else e):
        return fr + (0.45 * cot if y1 is None else y1) * fa if double else fr
    if double:
        return (0.67 if x is None else x) * fr + (0.67 * cot if y2 is None else y2) * fa
    return (0.4 if x is None else x) * fr + (0.4 * cot if y is None else y) * fa


def p0_iso(fr, fa, alpha_deg, kind, double, x0=None, y0=None):
    """ISO 76:2006, static equivalent load of radial and thrust roller bearings, catalogue
    X0 and Y0 replacing the standard's where given. The printed factors, checked against
    GOST 18854-2013 (identical), 7.2 and 8.2: single row X0 = 0.5, Y0 = 0.22·cotα
    (P0 ≥ Fr), double row X0 = 1, Y0 = 0.44·cotα; thrust P0a = 2.3·Fr·tanα + Fa."""
    a = alpha_deg * DEG
    if kind.startswith("thrust-"):
        return fa if alpha_deg == 90.0 else 2.3 * fr * math.tan(a) + fa
    if alpha_deg == 0.0:
        return fr
    cot = 1 / math.tan(a)
    if x0 is not None or y0 is not None:
        return max(fr, x0 * fr + y0 * fa)
    return fr + 0.44 * cot * fa if double else max(fr, 0.5 * fr + 0.22 * cot * fa)


LOAD_CASES = [  # Fr, Fa [N], α [deg], type, double row, catalogue factors
    (5000.0, 2000.0, 0.0, "cylindrical-roller", False, {}),
    (5000.0, 900.0, 0.0, "needle-roller", True, {}),
    (9000.0, 2000.0, 14.0, "tapered-roller", False, {}),       # Fa/Fr 0.22 < e 0.374
    (9000.0, 6000.0, 14.0, "tapered-roller", False, {}),       # above e
    (9000.0, 2000.0, 14.0, "tapered-roller", True, {}),
    (9000.0, 6000.0, 14.0, "tapered-roller", True, {}),
    (12000.0, 2000.0, 11.0, "spherical-roller", True, {}),
    (12000.0, 9000.0, 11.0, "spherical-roller", True, {}),
    (9000.0, 2500.0, 14.0, "tapered-roller", False, {"e": 0.37, "y": 1.6}),
    (9000.0, 4500.0, 14.0, "tapered-roller", False, {"e": 0.37, "y": 1.6}),
    (9000.0, 4500.0, 14.0, "tapered-roller", False, {"e": 0.37, "y": 1.6, "x": 0.45}),
    (12000.0, 2000.0, 11.0, "spherical-roller", True, {"e": 0.28, "y1": 2.4, "y2": 3.6}),
    (12000.0, 6000.0, 11.0, "spherical-roller", True, {"e": 0.28, "y1": 2.4, "y2": 3.6}),
    (10000.0, 60000.0, 50.0, "thrust-spherical-roller", False, {}),
    (0.0, 60000.0, 90.0, "thrust-cylindrical-roller", False, {}),
    (4000.0, 30000.0, 55.0, "thrust-tapered-roller", False, {}),
]


@pytest.mark.parametrize(("fr", "fa", "alpha", "kind", "double", "factors"), LOAD_CASES)
def test_equivalent_dynamic_load(fr, fa, alpha, kind, double, factors):
    load = rr.roller_equivalent_dynamic_load(fr, fa, alpha * DEG, bearing_type=kind,
                                             double_row=double, **factors)
    assert float(load.load) == pytest.approx(p_iso(fr, fa, alpha, kind, double, **factors),
                                             rel=REL)
    if alpha not in (0.0, 90.0):
        assert float(load.e) == pytest.approx(factors.get("e", 1.5 * math.tan(alpha * DEG)),
                                              rel=REL)


STATIC_CASES = [(*case[:5], {}) for case in LOAD_CASES] + [
    (9000.0, 2500.0, 14.0, "tapered-roller", True, {"x0": 1.0, "y0": 1.8}),
    (9000.0, 900.0, 14.0, "tapered-roller", False, {"x0": 0.5, "y0": 0.9}),   # P0 = Fr
    (9000.0, 12000.0, 14.0, "tapered-roller", False, {"x0": 0.5, "y0": 0.9})]


@pytest.mark.parametrize(("fr", "fa", "alpha", "kind", "double", "factors"), STATIC_CASES)
def test_static_equivalent_load(fr, fa, alpha, kind, double, factors):
    p0 = rr.roller_static_equivalent_load(fr, fa, alpha * DEG, bearing_type=kind,
                                          double_row=double, **factors)
    assert float(p0) == pytest.approx(p0_iso(fr, fa, alpha, kind, double, **factors),
                                      rel=REL)


# --- 6. life: L10, Cu, aISO and a pair's whole life ------------------------------------------
# tests/test_roller_life_published.py: aISO against the points of GOST 18855-2013's
# Figure 4 and its continuity, L10's and Cu's printed exponents as measured slopes, pairs
# and system lives from the Weibull survival product.

def a_iso(kappa, ec, cu, p, thrust=False):
    """ISO 281:2007, 9.3 (life modification factor), roller bearings, as transcribed for
    the tests of the options (tests/test_iso281_options.py); thrust bearings take
    eC·Cu/(2.5·P). Capped at 50, and 50 where the bracket is not positive. The
    transcription is itself checked against the points of GOST 18855-2013's Figure 4
    (tests/test_roller_life_published.py), as the solver is."""
    x2, e1 = ((1.3993, 0.054381) if kappa < 0.4 else (1.2348, 0.19087) if kappa < 1
              else (1.2348, 0.071739))
    load = ec * cu / p / (2.5 if thrust else 1.0)
    bracket = 1 - (1.5859 - x2 / kappa ** e1) * load ** 0.4
    return 50.0 if bracket <= 0 else min(50.0, 0.1 * bracket ** -9.185)


# --- 7. pairs and induced axial forces ---------------------------------------------------------

@pytest.mark.parametrize(("alpha", "factor"), [(20, 0.50), (25, 0.57), (30, 0.66), (40, 0.88),
                                               (35, 0.77), (22.5, 0.535), (15, math.nan),
                                               (45, math.nan)])
def test_induced_axial_factor_of_angular_contact_ball_bearings(alpha, factor):
    """SKF, Rolling bearings (2018), p. 401, Table 11: R = 0.50, 0.57, 0.66, 0.88 at 20°,
    25°, 30°, 40°; linear between (35°: 0.77); none outside (NaN)."""
    assert float(arrangements.induced_axial_factor_ball(alpha * DEG)) == pytest.approx(
        factor, rel=1e-9, nan_ok=True)


def test_induced_axial_factor_of_tapered_roller_bearings():
    """R = 0.5/Y (SKF, Rolling bearings (2018), tapered roller bearings, axial load)."""
    got = arrangements.induced_axial_factor_tapered(np.array([1.5, 1.6, 2.7]))
    assert got.tolist() == pytest.approx([0.5 / 1.5, 0.5 / 1.6, 0.5 / 2.7], rel=REL)


# --- 8. kinematics: pure rolling solved independently -----------------------------------------

@pytest.mark.parametrize(("z", "dwe", "dpw", "alpha", "w_inner", "w_outer", "thrust"), [
    (13, 9e-3, 46e-3, 0.0, 314.159, 0.0, False),
    (17, 7.5e-3, 46e-3, 14.0, 157.08, -20.0, False),
    (15, 11e-3, 60e-3, 11.0, 0.0, 83.8, False),
    (18, 12e-3, 95e-3, 50.0, 62.8, 0.0, True),
    (15, 10e-3, 80e-3, 90.0, 62.8, 5.0, True),
])
def test_kinematics_from_zero_slip_at_both_contacts(z, dwe, dpw, alpha, w_inner, w_outer,
                                                    thrust):
    """The contact points lie at radii Dpw/2 ∓ Dwe·cosα/2 from the bearing axis and at Dwe/2
    from the roller's axis, on opposite sides of it. In the cage frame (cage speed ω_c,
    roller spin ω_R) zero slip reads (ω_i − ω_c)·r_i = −ω_R·Dwe/2 and
    (ω_o − ω_c)·r_o = +ω_R·Dwe/2. BPFO = Z·|f_c − f_o|, BPFI = Z·|f_i − f_c|: the rollers
    passing a point of each ring per second."""
    cos_a = 0.0 if alpha == 90.0 else math.cos(alpha * DEG)
    r_i, r_o = dpw / 2 - dwe * cos_a / 2, dpw / 2 + dwe * cos_a / 2
    matrix = np.array([[-r_i, dwe / 2], [-r_o, -dwe / 2]])
    w_cage, w_roller = np.linalg.solve(matrix, [-w_inner * r_i, -w_outer * r_o])
    got = rbc.roller_kinematics(z, dwe, dpw, alpha * DEG, w_inner, w_outer, thrust)
    hz = 1 / (2 * math.pi)
    expected = {"cage_speed": w_cage, "cage_frequency": w_cage * hz,
                "roller_spin_frequency": abs(w_roller) * hz,
                "ball_pass_frequency_outer": z * abs(w_cage - w_outer) * hz,
                "ball_pass_frequency_inner": z * abs(w_inner - w_cage) * hz}
    assert {key: float(got[key]) for key in expected} == pytest.approx(expected, rel=REL)


# --- 9. published worked examples ----------------------------------------------------------------

@pytest.mark.parametrize(("load", "life_mrev", "published_c"), [
    (10.279e3, 1440.0, 91.1e3),   # 8th ed.: FD = 1.4·1650 lbf, xD = 50 000 h·480 r/min
    (13.92e3, 1248.0, 118e3),     # 10th ed.: FD = 1.4·2235 lbf, xD = 40 000 h·520 r/min
])
def test_shigley_problem_11_3_straight_roller(load, life_mrev, published_c):
    """Budynas & Nisbett, Shigley's Mechanical Engineering Design, 8th and 10th ed., problem
    11-3 (straight cylindrical roller, 03 series): C10 = FD·xD^(3/10), printed rounded to
    three figures. The solver's L10 at the printed C's rounding interval must bracket the
    design life."""
    half_unit = 0.05e3 if published_c < 100e3 else 0.5e3
    low = float(iso281.basic_rating_life(published_c - half_unit, load, family="roller"))
    high = float(iso281.basic_rating_life(published_c + half_unit, load, family="roller"))
    assert low <= life_mrev * 1e6 <= high
    at_c = float(iso281.basic_rating_life(published_c, load, family="roller"))
    assert at_c / 1e6 == pytest.approx(life_mrev, rel=0.005)
