"""Life of roller bearings (L10, Cu, aISO, pairs) against values that do not share the
solver's formulas: points read off a printed diagram, printed constants used as
properties (continuity, slopes measured by finite differences), and the Weibull
survival product of two bearings solved by root-finding.

Sources:
(G) GOST 18855-2013 (identical to ISO 281:2007), public PDF in the repository
    ArtemFilin1990/Mar, path "03_ГОСТ_подшипники_и_нормативка/ГОСТ по подшипникам/
    14_18855-2013.pdf": Figure 4 (printed page 28, PDF page 34), aISO of radial roller
    bearings against eC·Cu/P, one curve per κ; Annex Б.3.3.3, the note "C0/Cu = 8.2"
    and the exponent 0.3 of the size bracket above Dpw = 100 mm (eq. Б.21).
(S) SKF, "Basic rating life" (skf.com, roller bearings, principles, using life
    equations): L10 = (C/P)^p with p = 10/3 for roller bearings; C is the load a
    bearing carries for an L10 of 10^6 revolutions (also the Timken Engineering Manual,
    "Dynamic load rating", TIMKEN_ENGINEERING_MANUAL.md in ArtemFilin1990/Mar).
(W) Lundberg & Palmgren: a bearing's survival is S = exp(ln 0.9·(L/L10)^e), the
    survival of several is the product of theirs; line contact rates lives ∝ (C/P)^4
    with e = 9/8 (point contact ∝ (C/P)^3 with e = 10/9), from which ISO 281 derives
    its i^(7/9) (i^0.7) rule for i similar bearings sharing a load.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from bearingcalc.core import arrangements, iso281
from bearingcalc.core.bearing_life import ROLLER_WEIBULL_SLOPE, WEIBULL_SLOPE, system_life
from tests.conftest import solve_json
from tests.test_roller_bearing import a_iso as transcribed_a_iso

# --- aISO: Figure 4 of (G) read at printed points --------------------------------------------

#: (G) Figure 4 rendered at 300 dpi and read by pixel: the gridlines (0.005 … 5 across,
#: 0.1 … 50 up) fix a log–log scale (364 px a decade across, 510 up), and each curve's
#: centre is read where it crosses the column of eC·Cu/P. At 4.5 and 3 the labelled curves
#: (κ = 0.6 … 0.15, labels at the right edge) are apart and off the gridlines; κ = 0.5 at
#: 3 lies on the line aISO = 2 and is left out. {eC·Cu/P: {κ: aISO}}.
FIGURE_4_READINGS = {4.5: {0.6: 13.65, 0.5: 3.72, 0.4: 0.893, 0.3: 0.549, 0.2: 0.285,
                           0.15: 0.183},
                     3.0: {0.6: 6.06, 0.4: 0.644, 0.3: 0.429, 0.2: 0.246, 0.15: 0.168}}
#: The reading's tolerance, in pixels of the 300 dpi rendering, each way: the printed
#: line is about 5 px wide and the printed gridlines sit up to 3 px off a true log scale.
READING_PX = 10.0
PX_PER_DECADE_ACROSS, PX_PER_DECADE_UP = 364.0, 510.0


def roller_a_iso(kappa, load_ratio, thrust=False):
    return float(iso281.life_modification_factor(kappa, 1.0, load_ratio, 1.0, thrust,
                                                 family="roller"))


#: The solver's aISO and the transcription other tests compare the options with.
A_ISO_UNDER_TEST = {"solver": roller_a_iso,
                    "transcription": lambda kappa, ratio: transcribed_a_iso(kappa, 1.0,
                                                                            ratio, 1.0)}


@pytest.mark.parametrize("which", sorted(A_ISO_UNDER_TEST))
@pytest.mark.parametrize(("load_ratio", "kappa", "printed"),
                         [(x, k, a) for x, row in FIGURE_4_READINGS.items()
                          for k, a in row.items()])
def test_a_iso_passes_through_the_printed_diagram(load_ratio, kappa, printed, which):
    """The curve must cross the box of ±READING_PX around each point read off (G)
    Figure 4; aISO rises with eC·Cu/P, so the box's left and right edges bound it."""
    curve = A_ISO_UNDER_TEST[which]
    dx = 10 ** (READING_PX / PX_PER_DECADE_ACROSS)
    dy = 10 ** (READING_PX / PX_PER_DECADE_UP)
    assert curve(kappa, load_ratio / dx) <= printed * dy
    assert curve(kappa, load_ratio * dx) >= printed / dy


def test_the_diagram_tells_a_wrong_branch():
    """The box is narrow enough to matter: the ball bearings' aISO (another exponent and
    constants) lies more than three boxes' height from the reading at κ = 0.3."""
    ball = float(iso281.life_modification_factor(0.3, 1.0, 4.5, 1.0, family="ball"))
    box_height = READING_PX / PX_PER_DECADE_UP * math.log(10)
    assert abs(math.log(ball / FIGURE_4_READINGS[4.5][0.3])) > 3 * box_height


@pytest.mark.parametrize("edge", [0.4, 1.0])
@pytest.mark.parametrize("load_ratio", [0.05, 0.3, 1.0, 3.0])
def test_a_iso_is_continuous_where_its_formula_changes(edge, load_ratio):
    """(G) draws each κ as one smooth curve: the three κ ranges of the printed formulas
    must meet at κ = 0.4 and 1, so a misread constant of any one range shows as a step.
    The step allowed, 1e-4 relative, is what the constants' five printed figures leave;
    a last digit misread in any exponent or factor makes a larger one."""
    below = roller_a_iso(edge * (1 - 1e-9), load_ratio)
    at = roller_a_iso(edge, load_ratio)
    assert at == pytest.approx(below, rel=1e-4)


def test_a_iso_of_thrust_roller_bearings_is_the_radial_curve_at_a_2_5_times_load():
    """(G) eq. (40)–(42) (Figure 6): thrust roller bearings read the radial curve at
    eC·Cu/(2.5·P)."""
    for kappa in (0.2, 0.7, 2.0):
        assert roller_a_iso(kappa, 2.5, thrust=True) == pytest.approx(
            roller_a_iso(kappa, 1.0), rel=1e-12)


def test_a_iso_cap_and_floor():
    """(G) 9.3: aISO is at most 50 (the top of Figure 4); with eC = 0 it is 0.1 (the
    bottom line every curve starts from)."""
    got = iso281.life_modification_factor(np.array([4.0, 1.0]), np.array([1.0, 0.0]),
                                          np.array([1e6, 1e3]), np.array([1.0, 1e4]),
                                          family="roller")
    assert got.tolist() == pytest.approx([50.0, 0.1], rel=1e-12)


# --- L10 and Cu: the printed constants as properties -----------------------------------------

def log_slope(function, x, step=1e-4):
    """d ln f / d ln x by central differences."""
    up, down = function(x * math.exp(step)), function(x * math.exp(-step))
    return (math.log(up) - math.log(down)) / (2 * step)


def test_basic_rating_life_at_the_rating_is_a_million_revolutions():
    """(S): C is the load for an L10 of 10^6 revolutions, whatever its size."""
    for c in (1e3, 40.2e3, 2.5e6):
        assert float(iso281.basic_rating_life(c, c, family="roller")) == pytest.approx(
            1e6, rel=1e-12)


@pytest.mark.parametrize("ratio", [0.5, 1.0, 3.7, 20.0])
def test_basic_rating_life_falls_as_the_load_to_the_printed_exponent(ratio):
    """(S): p = 10/3 for roller bearings, measured as the slope of ln L10 against ln P
    (and against ln C) by finite differences; the truncation error of the difference is
    far below 1e-6."""
    c = 40.2e3
    p = c / ratio
    by_load = log_slope(lambda load: float(iso281.basic_rating_life(c, load,
                                                                    family="roller")), p)
    by_rating = log_slope(lambda rating: float(iso281.basic_rating_life(rating, p,
                                                                        family="roller")), c)
    assert by_load == pytest.approx(-10 / 3, rel=1e-6)
    assert by_rating == pytest.approx(10 / 3, rel=1e-6)


def test_fatigue_load_limit_is_c0_over_8_2_up_to_100_mm():
    """(G) Б.3.3.3, note: C0/Cu = 8.2 for roller bearings, at every size up to
    Dpw = 100 mm."""
    for dm_mm in (10.0, 46.0, 99.999, 100.0):
        cu = float(iso281.fatigue_load_limit(37267.0, dm_mm / 1e3, family="roller"))
        assert 37267.0 / cu == pytest.approx(8.2, rel=1e-12)


@pytest.mark.parametrize("dm_mm", [120.0, 200.0, 450.0, 1500.0])
def test_fatigue_load_limit_above_100_mm_falls_as_the_size_to_the_printed_0_3(dm_mm):
    """(G) eq. (Б.21): above 100 mm Cu falls as Dpw^(−0.3) (the slope of ln Cu against
    ln Dpw by finite differences), and it meets the C0/8.2 plateau at 100 mm without a
    step."""
    slope = log_slope(lambda dm: float(iso281.fatigue_load_limit(37267.0, dm / 1e3,
                                                                 family="roller")), dm_mm)
    assert slope == pytest.approx(-0.3, rel=1e-6)
    just_above = float(iso281.fatigue_load_limit(37267.0, 0.1 * (1 + 1e-9), family="roller"))
    assert just_above == pytest.approx(37267.0 / 8.2, rel=1e-8)


# --- pairs: the Weibull survival product -----------------------------------------------------

def life_by_survival_product(lives, slope):
    """(W): the life L at which S_1(L)·S_2(L)·… = 0.9, with S_k(L) = exp(ln 0.9·(L/L_k)^e),
    found by brentq on ln S(L) − ln 0.9 (not the closed form)."""
    def residual(life):
        return sum(math.log(0.9) * (life / each) ** slope for each in lives) - math.log(0.9)
    return brentq(residual, 1e-9 * min(lives), min(lives), xtol=1e-14 * min(lives),
                  rtol=1e-15)


@pytest.mark.parametrize(("family", "life_exponent", "slope"),
                         [("roller", 4.0, 9 / 8), ("ball", 3.0, 10 / 9)])
def test_pair_rating_is_two_bearings_at_half_load_surviving_together(family, life_exponent,
                                                                     slope):
    """(W): two similar bearings each carry P/2 and live (C/(P/2))^k; the pair lives L
    when both survive; its rating is the load at which that L is one million revolutions,
    C_pair = P·L^(1/k). ISO 76: the static rating of the pair is the sum."""
    c, load = 40.2e3, 10e3
    each = (c / (load / 2)) ** life_exponent
    pair_life = life_by_survival_product([each, each], slope)
    expected = load * pair_life ** (1 / life_exponent)
    got_c, got_c0 = arrangements.pair_ratings(c, 44e3, family)
    assert float(got_c) == pytest.approx(expected, rel=1e-9)
    assert float(got_c0) == pytest.approx(88e3, rel=1e-12)


@pytest.mark.parametrize("lives", [[2.0e8, 7.5e8], [1e6, 1e6], [3e7, 9e9], [4e8, 1e8, 2e8]])
@pytest.mark.parametrize("slope", [ROLLER_WEIBULL_SLOPE, WEIBULL_SLOPE])
def test_system_life_is_the_life_all_survive_at_90_percent(lives, slope):
    """(W): the system's L10 is where the product of the survivals is 0.9."""
    got = float(system_life([np.asarray(life) for life in lives], slope))
    assert got == pytest.approx(life_by_survival_product(lives, slope), rel=1e-9)


def test_the_slopes_are_lundberg_palmgrens():
    assert ROLLER_WEIBULL_SLOPE == 9 / 8 and WEIBULL_SLOPE == 10 / 9


def test_whole_tapered_pair_life(cli, spec_file):
    """A 30206-size pair, back-to-back, from catalogue ratings, through the CLI: the pair's
    C from (W) (two bearings at half load), C0 and Cu the sums (ISO 76; SKF, Rolling
    bearings, 2018, p. 400: Pu of a pair = 2·Pu), P = Fr + Y1·Fa with the catalogue's Y1
    (Fa/Fr = 0.28 ≤ e = 0.37). The basic life is the L10 for which the rating equation of
    (S) holds at the pair's C, P·(L10/10^6)^(3/10) = C (solved by brentq), at 1500 r/min
    in seconds; the modified life is the basic life times aISO, and aISO at this κ and
    eC·Cu/P must be the solver's function's (checked above against Figure 4)."""
    text = ("kind: rolling-bearing\ntype: tapered-roller\narrangement: back-to-back\n"
            "dynamic_load_rating: 40.2 kN\nstatic_load_rating: 44 kN\n"
            "fatigue_load_limit: 4.8 kN\ncontact_angle: 14 deg\n"
            "load_factors: {e: 0.37, y1: 1.8, y2: 2.7, y0: 1.8}\npitch_diameter: 46 mm\n"
            "radial_load: 9 kN\naxial_load: 2.5 kN\nspeed: 1500 rpm\n"
            "lubrication: {viscosity: 68 mm^2/s}\ncontamination_factor: 0.5\n")
    (record,) = solve_json(cli, spec_file(text))
    results = record["results"]
    p = 9e3 + 1.8 * 2.5e3
    each = (40.2e3 / (p / 2)) ** 4
    c_pair = p * life_by_survival_product([each, each], 9 / 8) ** 0.25
    l10 = brentq(lambda life: p * (life / 1e6) ** 0.3 - c_pair, 1e3, 1e15, rtol=1e-15)
    kappa = results["operating_viscosity"] / results["reference_viscosity"]
    a_iso = float(iso281.life_modification_factor(kappa, 0.5, 9600.0, p, family="roller"))
    seconds_per_rev = 60 / 1500
    expected = {"pair_dynamic_load_rating": c_pair, "pair_static_load_rating": 88e3,
                "fatigue_load_limit": 9600.0, "equivalent_dynamic_load": p,
                "static_equivalent_load": 9e3 + 1.8 * 2.5e3, "viscosity_ratio": kappa,
                "basic_rating_life": l10 * seconds_per_rev,
                "modified_rating_life": a_iso * l10 * seconds_per_rev}
    assert {key: results[key] for key in expected} == pytest.approx(expected, rel=1e-9)
