"""A bearing's ``mounting`` through the command line: the operating clearance from its
chain against the chain written here again from its parts (Lamé's two bodies solved as
a linear system, ``tests/test_mounting_fits.py``; the parts' warming summed one by
one); the bearing as mounted at that clearance equal to the same bearing given it as
``operating_clearance``; the extremes over the bands at the corners an engineer would
pick by hand; a Monte Carlo study of the interference against the exact distribution of
a difference of two uniform bands; and each bad input one line."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
from scipy import integrate, stats

from tests.conftest import ROOT, solve_json
from tests.mounted_specs import refused_lines
from tests.test_mounting_fits import _lame_system

BEARING = """kind: rolling-bearing
name: 6208 as mounted
type: deep-groove
method: iso-16281
dynamic_load_rating: 32.5 kN
static_load_rating: 19 kN
bore_diameter: 40 mm
outside_diameter: 80 mm
width: 18 mm
ball_count: 9
ball_diameter: 12.7 mm
pitch_diameter: 60 mm
inner_groove_conformity: 0.515
outer_groove_conformity: 0.525
radial_load: 3 kN
speed: 3000 rpm
"""
#: Every band typed, so the expectation below needs no table: a C3-like clearance, a
#: normal-class ring, a k5 shaft and an H7 housing of an aluminium body.
TYPED = BEARING + """mounting:
  initial_clearance: 24 µm ± 9 µm
  bore_deviation: -6 µm ± 6 µm
  outside_deviation: -6.5 µm ± 6.5 µm
  shaft: 40.0075 mm ± 0.0055 mm
  housing: 79.985 mm ± 0.015 mm
  shaft_bore: 10 mm
  housing_outside_diameter: 110 mm
  housing_material: aluminium
  roughness: {shaft: 2.5 µm, housing: 4 µm}
  inner_ring_temperature: 70 degC
  outer_ring_temperature: 60 degC
  shaft_temperature: 75 degC
  housing_temperature: 50 degC
"""
STEEL, RING = (210e9, 0.3), (207.5e9, 0.3)
ALUMINIUM = (70e9, 0.33)
ALPHA_STEEL, ALPHA_ALUMINIUM = 11.5e-6, 23e-6


def _expected(initial, bore, shaft, outside, housing):
    """The operating clearance [m] written from the parts: each fit's interference at
    the operating temperatures less 0.4·Rz, its pressure from the two bodies solved
    together, the raceway's move from the ring's own solution, and the rings' unequal
    warming across one line through a ball."""
    dpw, dw = 60e-3, 12.7e-3
    inner_race, outer_race = dpw - dw, dpw + dw
    rise_inner, rise_outer, rise_shaft, rise_housing = 50.0, 40.0, 55.0, 30.0
    inner_fit = (shaft - bore - 0.4 * 2.5e-6
                 + bore * (ALPHA_STEEL * rise_shaft - ALPHA_STEEL * rise_inner))
    outer_fit = (outside - housing - 0.4 * 4e-6
                 + outside * (ALPHA_STEEL * rise_outer - ALPHA_ALUMINIUM * rise_housing))
    reduction = 0.0
    if inner_fit > 0:
        _, _, grows = _lame_system(inner_fit, 10e-3, bore, inner_race, STEEL, RING)
        reduction += 2 * grows
    if outer_fit > 0:
        _, shrinks, _ = _lame_system(outer_fit, outer_race, outside, 110e-3, RING, ALUMINIUM)
        reduction -= 2 * shrinks
    warming = ALPHA_STEEL * ((outer_race * rise_outer) - inner_race * rise_inner
                             - 2 * dw * (rise_inner + rise_outer) / 2)
    return initial - reduction + warming


def test_the_operating_clearance_is_its_chain_written_again(cli, spec_file):
    [record] = solve_json(cli, spec_file(TYPED))
    results = record["results"]
    middle = _expected(24e-6, 40e-3 - 6e-6, 40.0075e-3, 80e-3 - 6.5e-6, 79.985e-3)
    assert results["operating_clearance"] == pytest.approx(middle, rel=1e-9)
    # the least: the smallest group clearance, the tightest fits; the largest: the opposite
    least = _expected(15e-6, 40e-3 - 12e-6, 40.013e-3, 80e-3, 79.97e-3)
    most = _expected(33e-6, 40e-3, 40.002e-3, 80e-3 - 13e-6, 80e-3)
    assert results["operating_clearance_min"] == pytest.approx(least, rel=1e-9)
    assert results["operating_clearance_max"] == pytest.approx(most, rel=1e-9)


def test_the_bearing_as_mounted_is_the_one_given_that_clearance(cli, spec_file):
    [mounted] = solve_json(cli, spec_file(TYPED))
    clearance = mounted["results"]["operating_clearance"]
    [typed] = solve_json(cli, spec_file(BEARING + f"operating_clearance: {clearance!r} m\n"))
    for key in ("max_element_load", "reference_rating_life", "stiffness_radial",
                "ring_displacement_radial", "load_zone_angle"):
        assert mounted["results"][key] == pytest.approx(typed["results"][key], rel=1e-12)


CLASSED = BEARING + """mounting:
  clearance_group: C3
  shaft: k5
  housing: H7
"""


def test_classes_and_groups_read_from_their_tables(cli, spec_file):
    """A 40 mm bore: ISO 5753-1's C3 is 15 to 33 µm, ISO 492's normal Δdmp 0 to −12 µm
    and ΔDmp (80 mm) 0 to −13 µm, ISO 286's k5 at 40 mm +2 to +13 µm and H7 at 80 mm 0
    to +30 µm (SKF's and NSK's tables alike)."""
    [record] = solve_json(cli, spec_file(CLASSED))
    results = record["results"]
    assert results["initial_clearance_min"] == pytest.approx(15e-6, rel=1e-9)
    assert results["initial_clearance_max"] == pytest.approx(33e-6, rel=1e-9)
    assert results["fit_interference_inner_min"] == pytest.approx(2e-6, abs=1e-12)
    assert results["fit_interference_inner_max"] == pytest.approx(25e-6, abs=1e-12)
    assert results["fit_interference_outer_min"] == pytest.approx(-43e-6, abs=1e-12)
    assert results["fit_interference_outer_max"] == pytest.approx(0.0, abs=1e-12)


def test_a_study_of_the_interference_is_the_exact_difference_of_two_bands(cli, spec_file):
    """The shaft's k5 band (11 µm) less the ring's bore band (12 µm), both uniform: their
    difference has a trapezoidal density, its quantiles in closed form (the convolution
    of two uniform densities)."""
    path = spec_file(CLASSED)
    run = cli("tolerance", path, "--format", "json", "-n", "100000", "-m", "monte-carlo")
    assert run.code in (0, 1), run.err
    found = json.loads(run.out)["results"]["fit_interference_inner"]["monte_carlo"]
    shaft, bore = (2e-6, 13e-6), (-12e-6, 0.0)
    low, high = shaft[0] - bore[1], shaft[1] - bore[0]
    a, b = shaft[1] - shaft[0], bore[1] - bore[0]

    def cdf(x: float) -> float:
        """P(S − B ≤ x) of two uniforms of widths a ≤ b, by the trapezoid's areas."""
        t = x - low
        small, large = min(a, b), max(a, b)
        if t <= small:
            return t * t / (2 * a * b)
        if t <= large:
            return (small / 2 + (t - small)) * small / (a * b)
        u = high - x
        return 1 - u * u / (2 * a * b)

    quantile = {p: _solve_cdf(cdf, p, low, high) for p in (0.00135, 0.5, 0.99865)}
    assert found["p00135"] == pytest.approx(quantile[0.00135], abs=2e-8)
    assert found["p99865"] == pytest.approx(quantile[0.99865], abs=2e-8)
    assert found["mean"] == pytest.approx((low + high) / 2, abs=2e-9)
    assert found["std"] == pytest.approx(math.sqrt((a * a + b * b) / 12), rel=2e-3)
    # the closed form against the convolution integrated numerically, a second way:
    # P(S − B ≤ x) = ∫ F_S(x − y) f_−B(y) dy with −B uniform on [0, 12 µm]
    minus_bore = stats.uniform(-bore[1], b)
    for p, x in quantile.items():
        numeric = integrate.quad(lambda y, x=x: stats.uniform(shaft[0], a).cdf(x - y)
                                 * minus_bore.pdf(y), -bore[1], -bore[0])[0]
        assert numeric == pytest.approx(p, rel=1e-6)


def _solve_cdf(cdf, p, low, high):
    from scipy import optimize

    return optimize.brentq(lambda x: cdf(x) - p, low, high, xtol=1e-15)


@pytest.mark.parametrize(("mounting", "field"), [
    ("  clearance_group: C3\n  shaft: k5\n  housing: H7\noperating_clearance: 10 µm",
     "operating_clearance"),
    ("  clearance_group: C3\n  initial_clearance: 20 µm\n  shaft: k5\n  housing: H7",
     "initial_clearance"),
    ("  shaft: k5\n  housing: H7", "clearance_group"),
    ("  clearance_group: C9\n  shaft: k5\n  housing: H7", "clearance_group"),
    ("  clearance_group: C3\n  shaft: z5\n  housing: H7", "shaft"),
    ("  clearance_group: C3\n  shaft: k12\n  housing: H7", "shaft"),
    ("  clearance_group: C3\n  shaft: H7\n  housing: H7", "shaft"),
    ("  clearance_group: C3\n  shaft: 45 k5\n  housing: H7", "shaft"),
    ("  clearance_group: C3\n  shaft: k5\n  housing: k5", "housing"),
    ("  clearance_group: C3\n  shaft: k5\n  housing: H7\n  housing_outside_diameter: 80 mm",
     "housing_outside_diameter"),
    ("  clearance_group: C3\n  shaft: k5\n  housing: H7\n  shaft_bore: 40 mm", "shaft_bore"),
    ("  clearance_group: C3\n  shaft: k5\n  housing: H7\n  shaft_material: brass",
     "shaft_material"),
    ("  clearance_group: C3\n  shaft: k5\n  housing: H7\n  tolerance_class: 4",
     "tolerance_class"),
])
def test_bad_input_of_a_mounting_is_one_line(cli, spec_file, mounting, field):
    lines = refused_lines(cli, spec_file, BEARING + "mounting:\n" + mounting + "\n")
    assert len(lines) == 1, lines
    assert f": {field}:" in lines[0] or f".{field}:" in lines[0], lines


@pytest.mark.parametrize(("changes", "field"), [
    ([("bore_diameter: 40 mm", "bore_diameter: 2 mm")], "clearance_group"),
    ([("clearance_group: C3", "initial_clearance: 20 µm"),
      ("bore_diameter: 40 mm", "bore_diameter: 520 mm"),
      ("outside_diameter: 80 mm", "outside_diameter: 600 mm"),
      ("pitch_diameter: 60 mm", "pitch_diameter: 560 mm")], "shaft"),
    ([("method: iso-16281", "method: iso-281")], "mounting"),
    ([("type: deep-groove", "type: angular-contact\ncontact_angle: 25 deg")], "mounting"),
])
def test_a_mounting_the_bearing_cannot_take_is_one_line(cli, spec_file, changes, field):
    text = CLASSED
    for change in changes:
        text = text.replace(*change)
    lines = refused_lines(cli, spec_file, text)
    # one line per cause: a bore outside the tables refuses each band it takes
    assert lines and field in lines[0], lines
    assert all(": mounting" in line for line in lines), lines


def test_the_clearance_limit_needs_a_mounting(cli, spec_file):
    text = BEARING + "operating_clearance: 10 µm\nlimits:\n  min_operating_clearance: 0 µm\n"
    lines = refused_lines(cli, spec_file, text)
    assert len(lines) == 1 and "min_operating_clearance" in lines[0], lines


def test_the_interference_against_creep_is_nsks():
    """NSK, Rolling Bearings, CAT. No. E1102e, 9.1.2 (2): Δd_F = 0.08·√(d/B·Fr)·10⁻³ mm
    (Fr in N), the same as its {kgf} form 0.25·√(d/B·Fr) to the rounding of 0.25/√g;
    above 0.2·C0r at least Δd ≥ 0.02·Fr/B·10⁻³ mm (eq. 9.2; 0.2·Fr/B in kgf) as well."""
    from bearingcalc.core.mounted_clearance import required_interference

    d, b, fr, c0 = 40.0, 18.0, 3000.0, 19000.0
    light = required_interference(np.array(d * 1e-3), np.array(b * 1e-3), np.array(fr), c0)
    assert light == pytest.approx(0.08 * math.sqrt(d / b * fr) * 1e-6, rel=1e-12)
    kgf = 0.25 * math.sqrt(d / b * fr / 9.80665) * 1e-6
    assert light == pytest.approx(kgf, rel=3e-3)
    heavy = required_interference(np.array(d * 1e-3), np.array(b * 1e-3), np.array(8000.0),
                                  c0)
    assert heavy == pytest.approx(max(0.02 * 8000.0 / b, 0.08 * math.sqrt(d / b * 8000.0))
                                  * 1e-6, rel=1e-12)
    # NSK rounds 0.2/g = 0.0204 to 0.02
    assert 0.02 * 8000.0 / b == pytest.approx(0.2 * 8000.0 / 9.80665 / b, rel=2.5e-2)


@pytest.mark.parametrize(("shaft", "creeps", "too_tight"), [
    ("k5", True, False),    # least interference 2 µm < 0.08·√(40/18·3000) = 6.5 µm
    ("m6", False, False),   # +9..+25 on a 0..−12 bore: least 9 µm, middle 23 µm < 28 µm
    ("p6", False, True),    # +26..+42: the middle, 40 µm, past 7/10 000 of 40 mm = 28 µm
])
def test_a_creeping_or_too_tight_shaft_fit_warns(cli, spec_file, shaft, creeps, too_tight):
    text = CLASSED.replace("shaft: k5", f"shaft: {shaft}")
    [record] = solve_json(cli, spec_file(text))
    warned = " ".join(record["warnings"])
    assert ("against creep" in warned) == creeps
    assert ("7/10 000 of d" in warned) == too_tight


def test_a_drives_bearing_takes_its_clearance_from_its_mounting(cli, spec_file):
    """The mounted drive's deep-groove gear bearing given a mounting solves as the same
    drive given that bearing the operating clearance its chain reports."""
    drive = (ROOT / "specs" / "bevel-drive-mounted.yaml").read_text("utf-8")
    typed = "     operating_clearance: 10 µm}"
    assert typed in drive
    mounting = ("     mounting: {clearance_group: CN, shaft: k5, housing: H7, "
                "inner_ring_temperature: 70 degC, outer_ring_temperature: 60 degC}}")
    [mounted] = solve_json(cli, spec_file(drive.replace(typed, mounting)))
    clearance = mounted["results"]["gear_bearing_2_operating_clearance"]
    low = mounted["results"]["gear_bearing_2_operating_clearance_min"]
    high = mounted["results"]["gear_bearing_2_operating_clearance_max"]
    assert low < clearance < high
    [given] = solve_json(cli, spec_file(drive.replace(
        typed, f"     operating_clearance: {clearance!r} m}}")))
    for key in ("gear_bearing_2_radial_load", "gear_bearing_2_max_element_load",
                "gear_bearing_1_reference_rating_life", "pinion_axial_shift"):
        assert mounted["results"][key] == pytest.approx(given["results"][key], rel=1e-9)


SIZED = CLASSED.replace("pitch_diameter: 60 mm", "pitch_diameter: 70 mm").replace(
    "bore_diameter: 40 mm", "bore_diameter: 45 mm").replace(
    "outside_diameter: 80 mm", "outside_diameter: 90 mm")
CHAIN_KEYS = ("fit_interference_inner", "fit_interference_inner_min",
              "fit_interference_inner_max", "fit_interference_outer_min",
              "initial_clearance_min", "initial_clearance_max", "operating_clearance",
              "operating_clearance_min", "operating_clearance_max")


def test_a_sweep_of_the_bearings_size_reads_each_sizes_classes(cli, spec_file, tmp_path):
    """From a 45 mm bore to 55 mm the shaft's k5 (+2..+13 µm to +2..+15), the bore's
    Δdmp (0..−12 to 0..−15) and C3 (18..36 to 23..43 µm) change ranges (the housing's H7
    at 90 and 100 mm is 0..+35 in one): the sweep's far corner is that size's own
    solve, not the first size's bands carried over."""
    path = spec_file(SIZED)
    out = tmp_path / "sweep.csv"
    run = cli("sweep", path, "--vary", "bore_diameter=45mm:55mm:2", "--vary",
              "outside_diameter=90mm:100mm:2", "-o", out)
    assert run.code == 0, run.err
    rows = list(csv.DictReader(out.open(encoding="utf-8")))
    [far] = [row for row in rows if float(row["input.bore_diameter [m]"]) == 0.055
             and float(row["input.outside_diameter [m]"]) == 0.1]
    [alone] = solve_json(cli, spec_file(SIZED.replace("bore_diameter: 45 mm",
                                                      "bore_diameter: 55 mm").replace(
        "outside_diameter: 90 mm", "outside_diameter: 100 mm")))
    for key in CHAIN_KEYS:
        assert float(far[f"{key} [m]"]) == pytest.approx(alone["results"][key], rel=1e-12,
                                                          abs=1e-15)
    assert alone["results"]["initial_clearance_min"] == pytest.approx(23e-6, rel=1e-9)
    assert alone["results"]["fit_interference_inner_max"] == pytest.approx(30e-6, rel=1e-9)


def test_a_link_swept_past_its_band_widens_the_extremes(cli, spec_file, tmp_path):
    out = tmp_path / "sweep.csv"
    run = cli("sweep", spec_file(CLASSED), "--vary", "mounting.bore_deviation=-40um:0um:3",
              "-o", out)
    assert run.code == 0, run.err
    for row in csv.DictReader(out.open(encoding="utf-8")):
        value = float(row["operating_clearance [m]"])
        assert float(row["operating_clearance_min [m]"]) <= value
        assert value <= float(row["operating_clearance_max [m]"])


def test_solve_warns_of_assemblies_below_the_clearance_limit(cli, spec_file):
    """solve judges the bands' middles (5.8 µm ≥ 0) and says that the bands reach below
    the limit (−12.9 µm); tolerance gives their share."""
    [record] = solve_json(cli, spec_file(CLASSED + "limits:\n  min_operating_clearance: 0 µm\n"))
    assert record["within_limits"]
    assert record["results"]["operating_clearance_min"] < 0
    assert any("fall below min_operating_clearance" in w for w in record["warnings"])


def test_a_drawn_cup_takes_no_mounting(cli, spec_file):
    text = ("kind: rolling-bearing\ntype: needle-roller\nmethod: iso-16281\ndrawn_cup: true\n"
            "dynamic_load_rating: 12 kN\nstatic_load_rating: 15 kN\nbore_diameter: 20 mm\n"
            "outside_diameter: 26 mm\nroller_count: 18\nroller_diameter: 2.5 mm\n"
            "roller_length: 12 mm\npitch_diameter: 23 mm\nradial_load: 2 kN\n"
            "speed: 3000 rpm\nmounting: {clearance_group: CN, shaft: h6, housing: N7}\n")
    lines = refused_lines(cli, spec_file, text)
    assert len(lines) == 1 and "drawn-cup" in lines[0] and ": mounting:" in lines[0], lines


def test_a_drives_bearing_warns_of_creep_as_a_bearing_alone(cli, spec_file):
    drive = (ROOT / "specs" / "bevel-drive-mounted.yaml").read_text("utf-8")
    mounting = ("     mounting: {clearance_group: CN, shaft: k5, housing: H7, "
                "inner_ring_temperature: 70 degC, outer_ring_temperature: 60 degC}}")
    [record] = solve_json(cli, spec_file(drive.replace("     operating_clearance: 10 µm}",
                                                       mounting)))
    assert any(w.startswith("gear_bearing_2: ") and "against creep" in w
               for w in record["warnings"]), record["warnings"]
