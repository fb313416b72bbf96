"""ISO 281:2007's tables of fc for roller bearings, entered here from the standard's
print, checked against a second source and for smoothness.

Sources:
(G) GOST 18855-2013 (identical to ISO 281:2007), Table 7 (pp. 14-15) and Table 10
    (pp. 17-18), read from its public PDF (the repository ArtemFilin1990/Mar, file
    03_ГОСТ_подшипники_и_нормативка/ГОСТ по подшипникам/14_18855-2013.pdf), text layer
    and page pictures;
(A) for Table 7, the transcription F04.m in tests/test_roller_bearing.py;
(F) the Lundberg–Palmgren expressions ISO/TR 1281-1 gives as the basis of the tables,
    computed here: every printed value is such an expression rounded to 0.1.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingcalc.core import roller_ratings as rr
from tests.test_roller_bearing import TABLE_7_SOURCE_A, fc_closed_form

GAMMA = [i / 100 for i in range(1, 31)]

# --- (G) Table 7, radial roller bearings, fc against Dwe·cosα/Dpw --------------------------
GOST_TABLE_7 = [52.1, 60.8, 66.5, 70.7, 74.1, 76.9, 79.2, 81.2, 82.8, 84.2,
                85.4, 86.4, 87.1, 87.7, 88.2, 88.5, 88.7, 88.8, 88.8, 88.7,
                88.5, 88.2, 87.9, 87.5, 87.0, 86.4, 85.8, 85.2, 84.5, 83.8]

# --- (G) Table 10, thrust roller bearings -------------------------------------------------
#: α = 90°, against Dwe/Dpw, 0.01 to 0.30.
GOST_TABLE_10_RIGHT = [105.4, 122.9, 134.5, 143.4, 150.7, 156.9, 162.4, 167.2, 171.7, 175.7,
                       179.5, 183.0, 186.3, 189.4, 192.3, 195.1, 197.7, 200.3, 202.7, 205.0,
                       207.2, 209.4, 211.5, 213.5, 215.4, 217.3, 219.1, 220.9, 222.7, 224.3]
#: The columns headed α = 50°, 65° and 80° (footnotes: for 45° < α < 60°, 60° <= α < 75°,
#: 75° <= α < 90°), against Dwe·cosα/Dpw from 0.01; each ends where the print has "-".
GOST_TABLE_10_ANGLED = {
    50: [109.7, 127.8, 139.5, 148.3, 155.2, 160.9, 165.6, 169.5, 172.8, 175.5, 177.8, 179.7,
         181.1, 182.3, 183.1, 183.7, 184.0, 184.1, 184.0, 183.7, 183.2, 182.6, 181.8, 180.9,
         179.8, 178.7],
    65: [107.1, 124.7, 136.2, 144.7, 151.5, 157.0, 161.6, 165.5, 168.7, 171.4, 173.6, 175.4,
         176.8, 177.9, 178.8, 179.3, 179.6, 179.7, 179.6, 179.3],
    80: [105.6, 123.0, 134.3, 142.8, 149.4, 154.9, 159.4, 163.2, 166.4, 169.0, 171.2, 173.0,
         174.4, 175.5, 176.3],
}
#: The one constant of (F) for thrust bearings: every printed digit of the four columns
#: admits 402.3247 to 402.3293 (the intersection of each entry's ±0.05 band).
THRUST_CONSTANT = 402.327


def thrust_fc_closed_form(gamma: float, alpha_deg: float) -> float:
    """fc of a thrust roller bearing (F): the line-contact expression of ISO/TR 1281-1
    with the load shared evenly by the rollers (so no 1.04 between the two washers'
    ratings), the reduction η = 1 − 0.15·sinα, and at α = 90° both washers flat:
    fc = A·η·γ^(2/9)·(1−γ)^(29/27)·(1+γ)^(−1/4)·[1 + ((1−γ)/(1+γ))^(143/24)]^(−2/9),
    at 90° A·0.85·γ^(2/9)·2^(−2/9) = 293.157·γ^(2/9)."""
    eta = 1 - 0.15 * math.sin(math.radians(alpha_deg))
    if alpha_deg == 90:
        return THRUST_CONSTANT * eta * gamma ** (2 / 9) * 2 ** (-2 / 9)
    ratio = ((1 - gamma) / (1 + gamma)) ** (143 / 24)
    return (THRUST_CONSTANT * eta * gamma ** (2 / 9) * (1 - gamma) ** (29 / 27)
            / (1 + gamma) ** 0.25 * (1 + ratio) ** (-2 / 9))


def columns() -> dict[int, list[float]]:
    return {90: GOST_TABLE_10_RIGHT, **GOST_TABLE_10_ANGLED}


# --- Table 7 -------------------------------------------------------------------------------

def test_table_7_at_every_hundredth_is_the_standards_print_and_the_transcription():
    assert [TABLE_7_SOURCE_A[g] for g in GAMMA] == GOST_TABLE_7
    np.testing.assert_allclose(rr.RADIAL_FC_GAMMA, GAMMA, rtol=0, atol=1e-15)
    assert rr.RADIAL_FC.tolist() == GOST_TABLE_7


@pytest.mark.parametrize("gamma", GAMMA)
def test_table_7_rows_are_the_closed_form_rounded(gamma):
    assert abs(GOST_TABLE_7[GAMMA.index(gamma)] - fc_closed_form(gamma)) <= 0.05 + 1e-9


@pytest.mark.parametrize("gamma", [0.105, 0.115, 0.155, 0.185, 0.215, 0.255, 0.295])
def test_between_rows_the_lookup_is_linear_in_the_hundredths(gamma):
    """Halfway between odd and even rows, where the former table of every other row was
    up to 0.12 % low: the mean of the two printed neighbours."""
    low = math.floor(gamma * 100 + 1e-9)
    expected = (GOST_TABLE_7[low - 1] + GOST_TABLE_7[low]) / 2
    _, fc = rr.roller_dynamic_load_rating(14, gamma * 0.1, 0.01, 0.1, 0.0,
                                          bearing_type="cylindrical-roller")
    assert float(fc) == pytest.approx(expected, rel=1e-12)


# --- Table 10 ------------------------------------------------------------------------------

@pytest.mark.parametrize("alpha", [90, 50, 65, 80])
def test_table_10_rows_are_the_closed_form_rounded(alpha):
    column = columns()[alpha]
    for gamma, printed in zip(GAMMA, column, strict=False):
        assert abs(printed - thrust_fc_closed_form(gamma, alpha)) <= 0.05 + 1e-9, gamma


def test_the_right_angle_column_is_a_power_of_two_ninths():
    """293.1·γ^(2/9) is within 0.07 % of every row; 293.157·γ^(2/9) rounds to each."""
    g = np.asarray(GAMMA)
    printed = np.asarray(GOST_TABLE_10_RIGHT)
    assert np.max(np.abs(293.1 * g ** (2 / 9) / printed - 1)) < 7e-4
    assert np.all(np.abs(293.157 * g ** (2 / 9) - printed) <= 0.05 + 1e-9)


@pytest.mark.parametrize("alpha", [90, 50, 65, 80])
def test_table_10_is_smooth(alpha):
    """Concave in γ (every second difference at most 0), within 0.2 of the closed
    form's second differences; the angled columns rise to one maximum."""
    ys = np.asarray(columns()[alpha])
    xs = np.asarray(GAMMA[:ys.size])
    assert np.all(np.diff(ys, 2) <= 1e-9)
    exact = np.array([thrust_fc_closed_form(x, alpha) for x in xs])
    assert np.max(np.abs(np.diff(ys, 2) - np.diff(exact, 2))) <= 0.2 + 1e-9
    rising = np.diff(ys) > 0
    assert np.count_nonzero(np.diff(rising.astype(int))) <= 1


def test_the_module_holds_table_10():
    np.testing.assert_allclose(rr.THRUST_FC_GAMMA, GAMMA, rtol=0, atol=1e-15)
    assert rr.THRUST_FC.tolist() == GOST_TABLE_10_RIGHT
    held = {round(math.degrees(lowest)): column.tolist()
            for lowest, column in rr.THRUST_FC_ANGLED}
    assert held == {45: GOST_TABLE_10_ANGLED[50], 60: GOST_TABLE_10_ANGLED[65],
                    75: GOST_TABLE_10_ANGLED[80]}


@pytest.mark.parametrize(("alpha", "column"), [
    (45.001, 50), (50.0, 50), (59.999, 50), (60.0, 65), (70.0, 65), (74.999, 65),
    (75.0, 80), (85.0, 80), (89.999, 80), (90.0, 90)])
def test_each_angle_reads_its_column(alpha, column):
    gamma = 0.013
    printed = columns()[column]
    expected = printed[0] + (printed[1] - printed[0]) * 0.3
    fc = rr.thrust_rating_factor(gamma, math.radians(alpha))
    assert float(fc) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(("alpha", "gamma"), [(50.0, 0.27), (65.0, 0.21), (80.0, 0.16),
                                              (90.0, 0.31), (90.0, 0.009)])
def test_beyond_a_column_fc_is_nan(alpha, gamma):
    assert np.isnan(rr.thrust_rating_factor(gamma, math.radians(alpha)))
