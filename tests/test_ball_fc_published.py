"""fc of ball bearings (ISO 281:2007 Tables 2 and 4) typed from the standard's print,
checked against a second source and for smoothness, and the solver's C against them.

Sources:
(G) GOST 18855-2013 (identical to ISO 281:2007), Table 2 (pp. 5-6, first column: single-row
    radial and angular contact ball bearings) and Table 4 (pp. 10-11, the α = 90° column),
    read from its public PDF (the repository ArtemFilin1990/Mar, file
    03_ГОСТ_подшипники_и_нормативка/ГОСТ по подшипникам/14_18855-2013.pdf), text layer;
    the footnote of both tables: values between the rows by linear interpolation.
(H) for Table 2, the public Python code hyswt/cadtest, tool/dgbb_caculate.py (a deep
    groove ball bearing design program), whose fc_list holds the same column at
    γ = 0.01 to 0.40 by 0.01;
(S) for Table 4, the transcription SECOND_TRANSCRIPTION in tests/test_ball_bearing.py.
No expected value here is read from the code under test.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingcalc.core import iso281
from tests.test_ball_bearing import SECOND_TRANSCRIPTION

GAMMA_2 = [i / 100 for i in range(1, 41)]
GAMMA_4 = [i / 100 for i in range(1, 36)]

# --- (G) Table 2, radial ball bearings, fc against γ = Dw·cosα/Dpw, 0.01 to 0.40 -------------
GOST_TABLE_2 = [29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
                56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,
                59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,
                55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4]
# --- (H) the same column as the second source holds it -------------------------------------
CADTEST_FC_LIST = [29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
                   56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60, 59.9,
                   59.8, 59.6, 59.3, 59, 58.6, 58.2, 57.7, 57.1, 56.6, 56,
                   55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50, 49.2, 48.4]
# --- (G) Table 4, thrust ball bearings, α = 90°, fc against γ = Dw/Dpw, 0.01 to 0.35 --------
GOST_TABLE_4_RIGHT = [36.7, 45.2, 51.1, 55.7, 59.5, 62.9, 65.8, 68.5, 71.0, 73.3,
                      75.4, 77.4, 79.3, 81.1, 82.7, 84.4, 85.9, 87.4, 88.8, 90.2,
                      91.5, 92.8, 94.1, 95.3, 96.4, 97.6, 98.7, 99.8, 100.8, 101.9,
                      102.9, 103.9, 104.8, 105.8, 106.7]


def table_2(gamma: float) -> float:
    """fc from (G) Table 2 by the linear interpolation its footnote states."""
    return float(np.interp(gamma, GAMMA_2, GOST_TABLE_2))


def table_4(gamma: float) -> float:
    return float(np.interp(gamma, GAMMA_4, GOST_TABLE_4_RIGHT))


# --- the tables: two sources and smoothness ---------------------------------------------------

def test_table_2_from_the_standards_print_is_the_second_sources():
    assert [float(v) for v in CADTEST_FC_LIST] == GOST_TABLE_2


def test_table_4_from_the_standards_print_is_the_second_transcription():
    assert [float(v) for v in SECOND_TRANSCRIPTION["thrust_fc"].split()] == GOST_TABLE_4_RIGHT


def test_table_2_is_smooth_with_one_maximum():
    """Rounded to 0.1, a smooth concave curve has second differences of at most
    +0.2 (four half-units of rounding) and the first differences fall from 6.7 to -0.9
    with one change of sign: the maximum, 60.0, at γ = 0.19. A typo, a swapped pair
    or a row out of place breaks one of these."""
    ys = np.asarray(GOST_TABLE_2)
    assert np.max(np.diff(ys, 2)) <= 0.2 + 1e-9
    signs = np.sign(np.diff(ys))
    assert np.count_nonzero(np.diff(signs[signs != 0])) == 1
    assert GAMMA_2[int(np.argmax(ys))] == 0.19


def test_table_4_is_smooth_and_rising():
    ys = np.asarray(GOST_TABLE_4_RIGHT)
    assert np.all(np.diff(ys) > 0)
    assert np.max(np.diff(ys, 2)) <= 0.2 + 1e-9


def test_the_module_holds_table_4_and_table_2_at_every_row():
    """The module's Tables 2 and 4 are the print's at every hundredth."""
    np.testing.assert_allclose(iso281.THRUST_FC_GAMMA, GAMMA_4, rtol=0, atol=1e-15)
    assert iso281.THRUST_FC.tolist() == GOST_TABLE_4_RIGHT
    np.testing.assert_allclose(iso281.RADIAL_FC_GAMMA, GAMMA_2, rtol=0, atol=1e-15)
    assert iso281.RADIAL_FC.tolist() == GOST_TABLE_2


# --- the solver's fc and C against the print ------------------------------------------------

#: (Z, Dw, Dpw [mm], α [deg]): small and large balls, on a row and between rows, with and
#: without a contact angle.
ON_BOTH_GRIDS = [
    (9, 12.7, 82.0, 0.0),       # γ = 0.15488, between 0.15 and 0.16
    (11, 15.875, 93.0, 15.0),   # γ = 0.16488
    (8, 17.462, 72.5, 0.0),     # γ = 0.24086, between 0.24 and 0.25
    (10, 30.0, 400.0, 0.0),     # γ = 0.075, Dw > 25.4 mm
    (12, 7.5, 150.0, 0.0),      # γ = 0.05, on a row
    (15, 12.0, 160.0, 25.0),    # γ = 0.06797
    (10, 11.0, 48.0, 0.0),      # γ = 0.22917, between 0.22 and 0.23
    (18, 9.0, 80.0, 40.0),      # γ = 0.08618
]


def c_of(z, dw, fc, alpha_deg):
    """ISO 281:2007, eq. (1) and (2): C = bm·fc·(cosα)^0.7·Z^(2/3)·Dw^1.8, for Dw > 25.4 mm
    3.647·bm·fc·(cosα)^0.7·Z^(2/3)·Dw^1.4; bm = 1.3 (Table 1); N and mm."""
    power = 1.8 if dw <= 25.4 else 1.4
    scale = 1.0 if dw <= 25.4 else 3.647
    return scale * 1.3 * fc * math.cos(math.radians(alpha_deg)) ** 0.7 * z ** (2 / 3) * dw ** power


@pytest.mark.parametrize(("z", "dw", "dpw", "alpha"), ON_BOTH_GRIDS)
def test_fc_and_c_of_radial_ball_bearings_from_the_print(z, dw, dpw, alpha):
    """fc to the last bit of the interpolation (1e-12: the arithmetic's, not the print's,
    since the expected value is the print's digits interpolated exactly)."""
    gamma = dw * math.cos(math.radians(alpha)) / dpw
    c, fc = iso281.dynamic_load_rating(z, dw / 1e3, dpw / 1e3, math.radians(alpha))
    assert float(fc) == pytest.approx(table_2(gamma), rel=1e-12)
    assert float(c) == pytest.approx(c_of(z, dw, table_2(gamma), alpha), rel=1e-12)


@pytest.mark.parametrize(("z", "dw", "dpw"), [(19, 9.525, 62.5), (15, 12.7, 60.0),
                                              (22, 6.35, 190.0), (12, 28.575, 85.0)])
def test_fc_and_c_of_thrust_ball_bearings_from_the_print(z, dw, dpw):
    """Table 4 (α = 90°) and eq. (4): C = bm·fc·Z^(2/3)·Dw^1.8, 3.647·… ·Dw^1.4 above
    25.4 mm."""
    gamma = dw / dpw
    c, fc = iso281.dynamic_load_rating(z, dw / 1e3, dpw / 1e3, 0.0, thrust=True)
    assert float(fc) == pytest.approx(table_4(gamma), rel=1e-12)
    assert float(c) == pytest.approx(c_of(z, dw, table_4(gamma), 0.0), rel=1e-12)


@pytest.mark.parametrize("gamma", [0.11, 0.15, 0.17, 0.19, 0.21, 0.33, 0.395])
def test_fc_between_the_rows_above_0_10_is_the_print(gamma):
    _, fc = iso281.dynamic_load_rating(10, gamma * 0.1, 0.1, 0.0)
    assert float(fc) == pytest.approx(table_2(gamma), rel=1e-12)
