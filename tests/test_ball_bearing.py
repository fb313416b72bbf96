"""kind: ball-bearing against published numbers, a second transcription of the tables,
an independent Hertz computation of the ISO 76 basis, and properties of the formulas."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from bearingcalc.core import ball_bearing as bb
from bearingcalc.core import iso76, iso281
from tests.conftest import ROOT, csv_column, solve_json, study_status

HOURS = 3600.0
SPECS = sorted((ROOT / "specs").glob("ball-bearing*.yaml"))

BASE = """kind: ball-bearing
type: deep-groove
dynamic_load_rating: 55.3 kN
static_load_rating: 31.5 kN
static_factor: 13
radial_load: 10 kN
speed: 3000 rpm
"""


def results_of(cli, spec_file, text):
    (record,) = solve_json(cli, spec_file(text))
    return record["results"], record


# --- published worked examples -----------------------------------------------------------

def test_skf_catalogue_example_6309(cli, spec_file):
    """SKF Rolling bearings catalogue (PUB BU/P1 17000/1 EN), 'Selecting bearing size',
    example 1: a 6309, C = 55.3 kN, Fr = 10 kN at 3000 r/min: L10 = 169 million
    revolutions, L10h = 940 h."""
    results, _ = results_of(cli, spec_file, BASE)
    assert round(results["basic_rating_life_revolutions"] / 1e6) == 169
    assert round(results["basic_rating_life"] / HOURS) == 940
    assert results["basic_rating_life_revolutions"] == pytest.approx(5.53 ** 3 * 1e6, rel=1e-12)


def test_skf_calculator_report_6309_with_axial_load(cli, spec_file):
    """SKF Bearing Calculator report for a 6309 (C = 55.3 kN, C0 = 31.5 kN, f0 = 13),
    Fr = 4 kN, Fa = 0.5 kN at 1800 r/min: P = 4 kN (Fa/Fr below e) and L10h ≈ 24 500 h."""
    text = BASE.replace("10 kN", "4 kN").replace("3000 rpm", "1800 rpm") + "axial_load: 0.5 kN\n"
    results, _ = results_of(cli, spec_file, text)
    assert results["equivalent_dynamic_load"] == pytest.approx(4000.0, rel=1e-12)
    assert results["basic_rating_life"] / HOURS == pytest.approx(24_500, rel=0.002)
    # e at f0·Fa/C0 = 0.2063, interpolated in ISO 281 Table 3 between 0.172 and 0.345
    ratio = 13 * 0.5 / 31.5
    assert results["axial_ratio_limit"] == pytest.approx(
        0.19 + (ratio - 0.172) / (0.345 - 0.172) * 0.03, rel=1e-12)


#: ISO 281:2007 Table 12, reliability -> a1 as printed (two or three significant digits).
ISO_281_TABLE_12 = {90: 1.0, 95: 0.64, 96: 0.55, 97: 0.47, 98: 0.37, 99: 0.25, 99.2: 0.22,
                    99.4: 0.19, 99.6: 0.16, 99.8: 0.12, 99.9: 0.093, 99.92: 0.087,
                    99.94: 0.080, 99.95: 0.077}


@pytest.mark.parametrize(("percent", "printed"), ISO_281_TABLE_12.items())
def test_reliability_factor_reproduces_iso_281_table_12(percent, printed):
    a1 = float(iso281.reliability_factor(percent / 100.0))
    assert float(f"{a1:.1e}") == pytest.approx(printed, abs=1e-12)  # two significant digits


# --- the ISO 76 basis, computed independently ----------------------------------------------

def _complete_elliptic(m: float) -> tuple[float, float]:
    """K(m) and E(m) by quadrature (not scipy.special), for an independent check."""
    k = quad(lambda t: 1.0 / math.sqrt(1.0 - m * math.sin(t) ** 2), 0, math.pi / 2,
             epsabs=1e-12)[0]
    e = quad(lambda t: math.sqrt(1.0 - m * math.sin(t) ** 2), 0, math.pi / 2, epsabs=1e-12)[0]
    return k, e


def _hertz_peak_pressure(load, curvatures, modulus=207.5e9, poisson=0.3):
    """Peak pressure of two bodies in point contact (Harris & Kotzalas, Essential Concepts
    of Bearing Technology, 5th ed., ch. 6), written here from the textbook."""
    r11, r12, r21, r22 = curvatures
    total = r11 + r12 + r21 + r22
    difference = abs((r11 - r12) + (r21 - r22)) / total

    def mismatch(k):
        big_k, big_e = _complete_elliptic(1.0 - 1.0 / k ** 2)
        return ((k * k + 1) * big_e - 2 * big_k) / ((k * k - 1) * big_e) - difference

    k = brentq(mismatch, 1.0 + 1e-9, 100.0, xtol=1e-14)
    _, big_e = _complete_elliptic(1.0 - 1.0 / k ** 2)
    s = 3 * load / (2 * total) * 2 * (1 - poisson ** 2) / modulus
    a = (2 * k * k * big_e / math.pi) ** (1 / 3) * s ** (1 / 3)
    b = (2 * big_e / (math.pi * k)) ** (1 / 3) * s ** (1 / 3)
    return 3 * load / (2 * math.pi * a * b)


def test_iso_76_f0_is_the_load_giving_4200_mpa_at_the_inner_contact_of_a_6205():
    """ISO 76:2006, 6.1.1: C0 of a radial ball bearing is the load that gives 4200 MPa at
    the centre of the most heavily loaded contact; with Stribeck's Q = 5·C0/(Z·cosα), f0 =
    Q/(5·Dw²). A 6205 (Dw = 7.938 mm, Dpw = 38.5 mm, inner conformity 0.52) must reproduce
    Table 1's f0 within 1 %."""
    dw, dpw, fi = 7.938e-3, 38.5e-3, 0.52
    gamma = dw / dpw
    curvatures = (2 / dw, 2 / dw, 2 * gamma / (dw * (1 - gamma)), -1 / (fi * dw))
    unit_pressure = _hertz_peak_pressure(1.0, curvatures)
    load = (4200e6 / unit_pressure) ** 3   # p ∝ Q^(1/3)
    f0_hertz = load / (5 * (dw * 1e3) ** 2)
    _, f0_table = iso76.static_load_rating(9, dw, dpw, 0.0)
    assert float(f0_table) == pytest.approx(f0_hertz, rel=0.01)


# --- the tables: a second transcription and smoothness --------------------------------------

SECOND_TRANSCRIPTION = {
    # Typed again from ISO 281:2007 Table 2 and Table 4 and ISO 76:2006 Table 1, row by row.
    "radial_fc": "29.1 35.8 40.3 43.8 46.7 49.1 51.1 52.8 54.3 55.5 56.6 57.5 58.2 58.8 59.3 "
                 "59.6 59.8 59.9 60.0 59.9 59.8 59.6 59.3 59.0 58.6 58.2 57.7 57.1 56.6 56.0 "
                 "55.3 54.6 53.9 53.2 52.4 51.7 50.9 50.0 49.2 48.4",
    "thrust_fc": "36.7 45.2 51.1 55.7 59.5 62.9 65.8 68.5 71.0 73.3 75.4 77.4 79.3 81.1 82.7 "
                 "84.4 85.9 87.4 88.8 90.2 91.5 92.8 94.1 95.3 96.4 97.6 98.7 99.8 100.8 101.9 "
                 "102.9 103.9 104.8 105.8 106.7",
    "static_f0": "14.7 14.9 15.1 15.3 15.5 15.7 15.9 16.1 16.3 16.5 16.4 16.1 15.9 15.6 15.4 "
                 "15.2 14.9 14.7 14.4 14.2 14.0 13.7 13.5 13.2 13.0 12.8 12.5 12.3 12.1 11.8 "
                 "11.6 11.4 11.2 10.9 10.7 10.5 10.3 10.0 9.8 9.6 9.4",
}


@pytest.mark.parametrize(("name", "table"), [("radial_fc", iso281.RADIAL_FC),
                                             ("thrust_fc", iso281.THRUST_FC),
                                             ("static_f0", iso76.STATIC_F0)])
def test_tables_match_a_second_transcription(name, table):
    assert np.array_equal(table, np.array(SECOND_TRANSCRIPTION[name].split(), dtype=float))


@pytest.mark.parametrize(("xs", "ys", "slope_jump"), [
    (iso281.RADIAL_FC_GAMMA, iso281.RADIAL_FC, 700.0),
    (iso281.THRUST_FC_GAMMA, iso281.THRUST_FC, 300.0),
    (iso76.STATIC_F0_GAMMA, iso76.STATIC_F0, 50.0),
])
def test_tables_are_smooth(xs, ys, slope_jump):
    """No entry breaks the trend: the slope changes by no more than a bound set by each
    curve's own bend (a typo such as 165.2 for 106.7 or a repeated value would)."""
    assert np.all(np.diff(xs) > 0)
    slopes = np.diff(ys) / np.diff(xs)
    assert np.max(np.abs(np.diff(slopes))) < slope_jump


def test_factor_tables_are_monotonic_as_the_standard_has_them():
    assert np.all(np.diff(iso281.DEEP_GROOVE_E) > 0) and np.all(np.diff(iso281.DEEP_GROOVE_Y) < 0)
    assert np.all(np.diff(iso281.ANGULAR_X) < 0) and np.all(np.diff(iso281.ANGULAR_Y) < 0)
    assert np.all(np.diff(iso281.ANGULAR_E) > 0) and np.all(np.diff(iso76.ANGULAR_Y0) < 0)
    assert np.all(np.diff(iso281.THRUST_FC) > 0)


# --- aISO, viscosity and properties ----------------------------------------------------------

@pytest.mark.parametrize("edge", [0.4, 1.0])
def test_aiso_is_continuous_at_the_band_edges(edge):
    below = iso281.life_modification_factor(edge * (1 - 1e-12), 0.5, 1340.0, 10_000.0)
    at = iso281.life_modification_factor(edge, 0.5, 1340.0, 10_000.0)
    # The standard's rounded coefficients leave a step of about 1e-4 at κ = 0.4.
    assert float(at) == pytest.approx(float(below), rel=5e-4)


def test_aiso_floor_is_0_1_and_cap_is_50():
    clean_nothing = iso281.life_modification_factor(np.array([0.1, 1.0, 4.0]), 0.0, 1000.0, 1e4)
    assert np.allclose(clean_nothing, 0.1, rtol=1e-15)
    assert float(iso281.life_modification_factor(4.0, 1.0, 1e6, 1.0)) == 50.0


def test_walther_viscosity_returns_its_reference_points():
    nu = iso281.walther_viscosity(68e-6, 8.7e-6, np.array([313.15, 373.15, 343.15]))
    assert nu[0] == pytest.approx(68e-6, rel=1e-12) and nu[1] == pytest.approx(8.7e-6,
                                                                                   rel=1e-12)
    assert 8.7e-6 < nu[2] < 68e-6


def test_reference_viscosity_is_continuous_enough_at_1000_rpm_and_falls_with_speed():
    n = np.array([500.0, 999.999, 1000.0, 3000.0]) * 2 * np.pi / 60
    nu1 = iso281.reference_viscosity(n, 0.05)
    assert np.all(np.diff(nu1) < 0)
    assert nu1[1] == pytest.approx(nu1[2], rel=0.03)  # the standard's two fits meet


def _evaluate(**changes):
    inputs = {"bearing_type": "deep-groove", "dynamic_load_rating": 55300.0,
              "static_load_rating": 31500.0, "static_factor": 13.0, "contact_angle": 0.0,
              "radial_load": 10_000.0, "axial_load": 0.0, "speed": 314.159,
              "reliability": 0.9, "min_static_safety": 1.0}
    inputs.update(changes)
    solution = bb.evaluate(inputs)
    return solution.results, solution.status


def test_life_falls_as_the_cube_of_the_load():
    loads = np.array([1e3, 2e3, 5e3, 1e4])
    results, status = _evaluate(radial_load=loads)
    assert np.all(status == 0)
    assert np.allclose(results["basic_rating_life"] * loads ** 3,
                       results["basic_rating_life"][0] * loads[0] ** 3, rtol=1e-13)


def test_static_safety_scales_with_c0():
    ratings = np.array([10e3, 20e3, 40e3])
    results, _ = _evaluate(static_load_rating=ratings)
    assert np.allclose(results["static_safety_factor"] / ratings, 1 / 10e3, rtol=1e-15)


def test_vectorised_results_equal_one_at_a_time():
    loads = np.linspace(1e3, 2e4, 7)
    together, _ = _evaluate(radial_load=loads, axial_load=loads / 3)
    for i, load in enumerate(loads):
        alone, _ = _evaluate(radial_load=load, axial_load=load / 3)
        for key, values in together.items():
            assert values[i] == pytest.approx(float(alone[key]), rel=1e-15), key


# --- through the CLI -------------------------------------------------------------------

@pytest.mark.parametrize("spec", SPECS, ids=lambda p: p.name)
@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_every_example_solves_in_every_format(cli, spec, fmt):
    run = cli("solve", spec, "--format", fmt)
    assert run.code == 0, run.err  # every example is within its limits
    if fmt == "table":
        for heading in ("ratings", "loads", "life", "static"):
            assert heading in run.out
        assert "10⁶ rev" in run.out and " h " in run.out


def test_json_is_flat_and_si(cli):
    (record,) = solve_json(cli, ROOT / "specs" / "ball-bearing.yaml")
    assert record["units"]["basic_rating_life"] == "s"
    assert record["units"]["dynamic_load_rating"] == "N"
    assert record["units"]["operating_viscosity"] == "m²/s"
    assert all(isinstance(v, float) for v in record["results"].values())


def test_geometry_ratings_and_catalogue_ratings_are_both_reported(cli, spec_file):
    text = BASE + "ball_count: 8\nball_diameter: 17.462 mm\npitch_diameter: 72.5 mm\n"
    results, record = results_of(cli, spec_file, text)
    assert results["dynamic_load_rating"] == 55300.0
    c_iso, fc = iso281.dynamic_load_rating(8, 17.462e-3, 72.5e-3, 0.0)
    assert results["dynamic_load_rating_iso"] == pytest.approx(float(c_iso), rel=1e-15)
    # Table 2 at γ = 0.24086 by hand: 59.0 + (0.24086 − 0.24)/0.02 · (58.2 − 59.0)
    assert float(fc) == pytest.approx(59.0 - 0.8 * (17.462 / 72.5 - 0.24) / 0.02, rel=1e-12)
    assert any("catalogue" in w for w in record["warnings"])


def test_c_from_geometry_by_hand_for_a_large_ball():
    """Dw > 25.4 mm takes the 3.647·Dw^1.4 form (ISO 281 eq. 2). γ = 30/120 = 0.25:
    fc = 58.6, Table 2's row 0.25 as GOST 18855-2013 prints it
    (tests/test_ball_fc_published.py checks the table against a second source); the
    module's rows 0.24 and 0.26 (59.0, 58.2) put the same value there."""
    c, fc = iso281.dynamic_load_rating(10, 30e-3, 120e-3, 0.0)
    assert float(fc) == pytest.approx(58.6, rel=1e-12)
    expected = 3.647 * 1.3 * 58.6 * 10 ** (2 / 3) * 30 ** 1.4
    assert float(c) == pytest.approx(expected, rel=1e-12)


def test_check_passes_and_fails_by_the_margins(cli, spec_file):
    passing = spec_file(BASE + "limits: {min_rating_life: 900 h}\n", "pass.yaml")
    failing = spec_file(BASE + "limits: {min_rating_life: 1000 h}\n", "fail.yaml")
    static = spec_file(BASE + "limits: {min_static_safety: 4}\n", "static.yaml")
    run = cli("check", passing, failing, static, "--format", "json")
    statuses = {json.loads(line)["spec"]: json.loads(line) for line in run.out.splitlines()}
    assert run.code == 1
    assert statuses[str(passing)]["status"] == "pass"
    assert statuses[str(failing)]["status"] == "fail"
    assert statuses[str(failing)]["margins"]["life_margin"] == pytest.approx(
        939.5132 / 1000 - 1, rel=1e-6)
    assert statuses[str(static)]["status"] == "fail"


def test_tolerance_reports_the_life_band_and_the_yield(cli):
    run = cli("tolerance", ROOT / "specs" / "tolerances" / "ball-bearing.yaml", "-n", "20000",
              "--format", "json")
    record = json.loads(run.out)
    assert run.code == study_status(record) == 1, run.err  # the life can fall short
    life = record["results"]["modified_rating_life"]
    assert life["worst_case"]["min"] < life["nominal"] < life["worst_case"]["max"]
    assert life["rss"]["std"] > 0 and life["monte_carlo"]["std"] > 0
    assert 0 < record["yield"] < 1
    # The worst case of life is at the highest loads and speed, the lowest viscosity.
    low = life["worst_case"]["min_inputs"]
    assert low["radial_load"] == pytest.approx(11_500, rel=1e-9)
    assert low["speed"] == pytest.approx(3150 * 2 * math.pi / 60, rel=1e-9)


def test_sweep_of_life_against_load_plots(cli, tmp_path):
    plot = tmp_path / "life.png"
    run = cli("sweep", ROOT / "specs" / "ball-bearing.yaml", "--vary",
              "radial_load=2kN:20kN:10", "-r", "modified_rating_life", "-r", "life_margin",
              "--plot", plot, "-f", "csv")
    assert run.code == 0, run.err
    load = np.array(csv_column(run.out, "input.radial_load [N]"))
    life = np.array(csv_column(run.out, "basic_rating_life [s]"))
    assert len(load) == 10 and np.allclose(life * load ** 3, life[0] * load[0] ** 3, rtol=1e-13)
    assert plot.read_bytes().startswith(b"\x89PNG")


BAD = [
    # (change, field blamed, fragment)
    ("radial_load: -1 kN\n", "radial_load", "must not be negative"),
    ("type: thrust\n", "radial_load", "carries no radial load"),
    ("radial_load: 0 kN\n", "radial_load", "both loads are zero"),
    ("speed: 0 rpm\n", "speed", "speed: must be positive"),
    ("reliability: 80 %\n", "reliability", "from 90 % to 99.95 %"),
    ("reliability: 99\n", "reliability", "a bare number is a fraction"),
    ("contamination_factor: 1.5\n", "contamination_factor", "from 0 to 1"),
    # A missing key is blamed at the line of the key that needs it.
    ("pitch_diameter: 72.5 mm\nlubrication: {viscosity: 20 mm^2/s}\n", "contamination_factor",
     "needs the contamination factor", "lubrication"),
    ("contact_angle: 95 deg\n", "contact_angle", "from 0 deg to below 90 deg"),
    ("type: angular-contact\ncontact_angle: 15 deg\n", "load_factors", "give load_factors",
     "contact_angle"),
    ("ball_count: 8\nball_diameter: 80 mm\npitch_diameter: 72.5 mm\n", "ball_diameter",
     "must be smaller than pitch_diameter"),
    ("ball_count: 40\nball_diameter: 17.462 mm\npitch_diameter: 72.5 mm\n", "ball_count",
     "the balls do not fit"),
    ("ball_count: 3\nball_diameter: 1 mm\npitch_diameter: 172.5 mm\n", "ball_diameter",
     "outside ISO 281's fc table"),
    ("pitch_diameter: 72.5 mm\nlubrication: {viscosity: 0.5 mm^2/s}\n"
     "contamination_factor: 0.5\n", "lubrication", "κ = ν/ν1 is below 0.1"),
    ("pitch_diameter: 72.5 mm\nlubrication: {viscosity: 20 mm^2/s, temperature: 80 degC}\n"
     "contamination_factor: 0.5\n", "lubrication", "not both"),
    ("bore_diameter: 45 mm\n", "outside_diameter", "give both bore_diameter and outside",
     "bore_diameter"),
    ("radial_load: 10 N*m\n", "radial_load", "is not a unit of force"),
]


@pytest.mark.parametrize(("change", "field", "fragment", "line_key"),
                         [(*case, case[1]) if len(case) == 3 else case for case in BAD],
                         ids=[f"bad{i}" for i in range(len(BAD))])
def test_bad_input_is_one_clear_line(cli, spec_file, change, field, fragment, line_key):
    rows = BASE.splitlines()
    for new_row in change.splitlines():
        key = new_row.split(":")[0]
        at = [i for i, row in enumerate(rows) if row.startswith(f"{key}:")]
        if at:
            rows[at[0]] = new_row
        else:
            rows.append(new_row)
    path = spec_file("\n".join(rows) + "\n")
    blamed = [i for i, row in enumerate(rows) if row.startswith(f"{line_key}:")]
    line = blamed[0] + 1 if blamed else 1
    run = cli("solve", path)
    assert run.code == 2, run.out
    assert run.err.count("\n") == 1, run.err
    assert run.err.startswith(f"{path}:{line}: "), run.err
    assert fragment in run.err, run.err


def test_deep_groove_with_axial_load_needs_f0_and_c0(cli, spec_file):
    text = "kind: ball-bearing\ndynamic_load_rating: 55.3 kN\nradial_load: 1 kN\n" \
           "axial_load: 1 kN\nspeed: 100 rpm\n"
    run = cli("solve", spec_file(text))
    assert run.code == 2 and "needs f0 and C0" in run.err


def test_thrust_without_c0_leaves_static_results_out_with_a_warning(cli, spec_file):
    text = ("kind: ball-bearing\ntype: thrust\nball_count: 19\nball_diameter: 9.525 mm\n"
            "pitch_diameter: 62.5 mm\naxial_load: 8 kN\nspeed: 400 rpm\n")
    results, record = results_of(cli, spec_file, text)
    assert "static_safety_factor" not in results
    assert any("static results are left out" in w for w in record["warnings"])
    # Table 4 at γ = 0.1524 by hand, C = 1.3·fc·Z^(2/3)·Dw^1.8.
    gamma = 9.525 / 62.5
    fc = 79.3 + (81.1 - 79.3) * (gamma - 0.13) / 0.01 if gamma < 0.14 else \
        81.1 + (82.7 - 81.1) * (gamma - 0.14) / 0.01 if gamma < 0.15 else \
        82.7 + (84.4 - 82.7) * (gamma - 0.15) / 0.01
    assert results["dynamic_load_rating"] == pytest.approx(
        1.3 * fc * 19 ** (2 / 3) * 9.525 ** 1.8, rel=1e-12)


def test_axial_ratio_outside_table_3_warns(cli, spec_file):
    _, record = results_of(cli, spec_file, BASE.replace("10 kN", "1 kN") +
                                 "axial_load: 0.1 kN\n")
    assert any("below 0.172" in w for w in record["warnings"])


# --- the rolling-element family --------------------------------------------------------------

FAMILY_FORMULAS = {
    "C": lambda family: iso281.dynamic_load_rating(9, 8e-3, 40e-3, 0.0, family=family),
    "P": lambda family: iso281.equivalent_dynamic_load(1e3, 5e2, "angular-contact", 0.5,
                                                       family=family),
    "L10": lambda family: iso281.basic_rating_life(5e4, 1e4, family=family),
    "Cu": lambda family: iso281.fatigue_load_limit(3e4, 0.07, family=family),
    "aISO": lambda family: iso281.life_modification_factor(1.0, 0.5, 1e3, 1e4,
                                                           family=family),
    "C0": lambda family: iso76.static_load_rating(9, 8e-3, 40e-3, 0.0, family=family),
    "P0": lambda family: iso76.static_equivalent_load(1e3, 5e2, "deep-groove", 0.0,
                                                      family=family),
}


#: Formulas whose roller form needs inputs of its own (Lwe, i) and so a function of its own
#: (bearingcalc.core.roller_ratings); the rest take either family.
BALL_SIGNATURES = ("C", "P", "C0", "P0")


@pytest.mark.parametrize("formula", sorted(FAMILY_FORMULAS))
def test_every_family_dependent_formula_computes_for_balls_and_refuses_unknown(formula):
    value = FAMILY_FORMULAS[formula]("ball")
    value = value[0] if isinstance(value, tuple) else value   # (C, fc), (P, X, ...): C, P
    assert np.isfinite(value) and value > 0
    if formula in BALL_SIGNATURES:
        with pytest.raises(NotImplementedError, match="ball bearings only"):
            FAMILY_FORMULAS[formula]("roller")
    else:
        rolled = FAMILY_FORMULAS[formula]("roller")
        assert np.isfinite(rolled) and rolled > 0 and rolled != value
    with pytest.raises(ValueError, match="unknown rolling-element family 'needle'"):
        FAMILY_FORMULAS[formula]("needle")


def test_the_solver_states_its_family_and_the_standards_default_to_it():
    assert bb.FAMILY == "ball"
    c_default, _ = iso281.dynamic_load_rating(9, 8e-3, 40e-3, 0.0)
    c_ball, _ = iso281.dynamic_load_rating(9, 8e-3, 40e-3, 0.0, family="ball")
    assert float(c_default) == float(c_ball)
