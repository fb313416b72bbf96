"""The example bevel drive (specs/bevel-drive.yaml) from the torque to each bearing's
life, computed here without the solver's code: the gear forces of a straight bevel pair,
each shaft's statics by hand and by a 3-D equilibrium solved by numpy, and the bearings'
loads and lives from ISO 281's and ISO 76's published numbers.

Sources:
(B) straight bevel gear forces at the mean pitch point: Wt = T/r_m, Wr = Wt·tanφ·cosγ,
    Wa = Wt·tanφ·sinγ on the pinion (pitch angle γ, pressure angle φ), the gear's radial
    the pinion's axial and its axial the pinion's radial (Budynas & Nisbett, Shigley's
    Mechanical Engineering Design, 13-15); r_m = r·(A − F/2)/A, A = r/sinγ the cone
    distance;
(G) GOST 18855-2013 (identical to ISO 281:2007), Table 3, single-row radial ball
    bearings: X = 0.56 and, against f0·Fa/C0 = 0.172, 0.345, 0.689, 1.03, 1.38, 2.07,
    3.45, 5.17, 6.89, e = 0.19 … 0.44 and Y = 2.30 … 1.00 (linear between rows); L10 =
    (C/P)^3 million revolutions; the system life with the Weibull slope 10/9 of ball
    bearings; GOST 18854-2013 (ISO 76:2006) Table 1: P0 = max(Fr, 0.6·Fr + 0.5·Fa).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import ROOT, solve_json
from tests.test_bevel_drive import _three_d_balance

TABLE_3_RATIO = [0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89]
TABLE_3_E = [0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44]
TABLE_3_Y = [2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00]

# The example spec's numbers, read from specs/bevel-drive.yaml.
TEETH = (20, 43)
MODULE, FACE, PHI = 3.0e-3, 20.0e-3, math.radians(20.0)
TORQUE, SPEED_RPM = 60.0, 1500.0
BEARINGS = {  # shaft: (positions [m], locating index, C, C0 [N], f0)
    "pinion": ((0.090, 0.150), 0, 23.4e3, 11.6e3, 12.0),
    "gear": ((0.020, 0.120), 1, 20.3e3, 11.2e3, 14.0),
}


def gear_forces():
    """(B): per shaft, (axial position of the mean pitch point from the apex, r_m, Wt, Wr,
    Wa) [m, N]."""
    pitch_angle = math.atan2(TEETH[0], TEETH[1])
    radius = MODULE * TEETH[0] / 2
    cone = radius / math.sin(pitch_angle)
    mean = cone - FACE / 2
    r_mean = radius * mean / cone
    wt = TORQUE / r_mean
    wr = wt * math.tan(PHI) * math.cos(pitch_angle)
    wa = wt * math.tan(PHI) * math.sin(pitch_angle)
    gear_angle = math.pi / 2 - pitch_angle
    return {"pinion": (mean * math.cos(pitch_angle), r_mean, wt, wr, wa),
            "gear": (mean * math.cos(gear_angle), mean * math.sin(gear_angle), wt, wa, wr)}


def equivalent_load(fr, fa, c0, f0):
    """(G) Table 3 and ISO 281 7.2: P = Fr where Fa/Fr ≤ e, else 0.56·Fr + Y·Fa."""
    ratio = f0 * fa / c0
    e = float(np.interp(ratio, TABLE_3_RATIO, TABLE_3_E))
    if fa == 0 or fa / fr <= e:
        return fr
    return 0.56 * fr + float(np.interp(ratio, TABLE_3_RATIO, TABLE_3_Y)) * fa


@pytest.fixture
def drive(cli):
    (record,) = solve_json(cli, ROOT / "specs" / "bevel-drive.yaml")
    return record["results"]


def test_gear_forces(drive):
    _, _, wt, wr, wa = gear_forces()["pinion"]
    assert drive["tangential_force"] == pytest.approx(wt, rel=1e-12)
    assert drive["gear_a_radial_force"] == pytest.approx(wr, rel=1e-12)
    assert drive["gear_a_axial_force"] == pytest.approx(wa, rel=1e-12)
    assert (drive["gear_b_radial_force"], drive["gear_b_axial_force"]) == pytest.approx(
        (wa, wr), rel=1e-12)


def test_the_tangential_reactions_by_hand():
    """In the plane of Wt alone the shaft is a beam on two supports: moments about each
    support give R1 = Wt·|x2 − xp|/(x2 − x1) and R2 = Wt·|x1 − xp|/(x2 − x1), the overhung
    pinion's near bearing taking more than Wt. The 3-D solve must reproduce it with no
    radial or axial force."""
    for shaft, ((x1, x2), locating, *_) in BEARINGS.items():
        xp, rp, wt, _, _ = gear_forces()[shaft]
        radial, axial, torque = _three_d_balance(x1, x2, locating, xp, rp, wt, 0.0, 0.0)
        by_hand = (wt * abs(x2 - xp) / (x2 - x1), wt * abs(x1 - xp) / (x2 - x1))
        assert radial == pytest.approx(by_hand, rel=1e-12)
        assert axial == pytest.approx(0.0, abs=1e-9) and torque == pytest.approx(wt * rp)
    assert by_hand[0] < wt  # the gear, straddled
    xp, _, wt, _, _ = gear_forces()["pinion"]
    assert wt * abs(0.150 - xp) / 0.060 > wt  # the pinion, overhung


def bearing_numbers():
    """Each bearing's (name, Fr, Fa, P, L10 [s], s0) by (B), the 3-D solve and (G)."""
    rows = []
    for shaft, ((x1, x2), locating, c, c0, f0) in BEARINGS.items():
        xp, rp, wt, wr, wa = gear_forces()[shaft]
        radial, axial, _ = _three_d_balance(x1, x2, locating, xp, rp, wt, wr, wa)
        rev_per_s = SPEED_RPM / 60 * (1.0 if shaft == "pinion" else TEETH[0] / TEETH[1])
        for index, fr in enumerate(radial):
            fa = axial if index == locating else 0.0
            p = equivalent_load(fr, fa, c0, f0)
            p0 = max(fr, 0.6 * fr + 0.5 * fa)
            rows.append((f"{shaft}_bearing_{index + 1}", fr, fa, p,
                         (c / p) ** 3 * 1e6 / rev_per_s, c0 / p0))
    return rows


@pytest.mark.parametrize("row", bearing_numbers(), ids=lambda row: row[0])
def test_each_bearings_loads_and_lives(drive, row):
    """1e-9: the 3-D solve and the solver's closed form differ by rounding only."""
    name, fr, fa, p, life, s0 = row
    got = [drive[f"{name}_{key}"] for key in ("radial_load", "axial_load",
                                              "equivalent_dynamic_load", "basic_rating_life",
                                              "static_safety_factor")]
    assert got == pytest.approx([fr, fa, p, life, s0], rel=1e-9, abs=1e-9)


def test_one_bearing_takes_the_table_3_branch():
    """The gear's locating bearing carries Fa/Fr above e (f0·Fa/C0 about 0.96, between
    the rows 0.689 and 1.03), so the test above reaches Y as well as Fr."""
    loaded = [row for row in bearing_numbers() if row[3] != row[1]]
    assert [row[0] for row in loaded] == ["gear_bearing_2"]
    _, fr, fa, _, _, _ = loaded[0]
    assert 0.689 < 14.0 * fa / 11.2e3 < 1.03 and fa / fr > 0.28


def test_system_basic_life(drive):
    """(G): the bearings fail independently, Weibull slope e = 10/9:
    L = (Σ L_i^(−e))^(−1/e)."""
    lives = np.array([row[4] for row in bearing_numbers()])
    expected = float(np.sum(lives ** (-10 / 9)) ** (-9 / 10))
    assert drive["system_basic_rating_life"] == pytest.approx(expected, rel=1e-9)
