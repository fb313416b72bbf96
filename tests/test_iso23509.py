"""The ISO 23509 blank and ISO 10300-1's virtual cylindrical gears of a spiral bevel pair
without offset against the published sample behind both standards: z 14/39, d_e2
176.893 mm, b 25.4 mm, β_m 35°, α_n 20°, r_c0 114.3 mm, face-milled, completing.

Sources, each value at the digits it is printed to:

- ISO 23509:2016 Annex F.2 (sample 1, data type II: k_d = 2, c_ham = 0.24737, the
  dedendum angles θ_a2 2.1342°, θ_f2 6.4934° given), its printed values as transcribed
  in the public repository afuentesaz/AGMAStandards, ``ISO23509Calc/Calc/SelfTest.cs``;
- ISO/TR 10300-30:2024 Annex A (sample 1, the same pair rated), Tables A.1 to A.6, as
  transcribed there in ``ISO10300Calc/Calc/SelfTest.cs``.

At the mean point the wheel's addendum is c_ham of the working depth, so data type I's
profile shift is x_hm1 = 1 − 2·c_ham. The TR's depths (h_am1 4.837, h_fm1 2.393,
h_am2 1.590, h_fm2 5.640 mm) follow from it; the standard's sample prints depths
1.2 µm apart (h_am2 1.591 mm: its c_ham splits the depth at the outer section), so its
depth-borne values are held to 3 µm here (twice that, across a diameter), the rest to
their printed digits.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingcalc.core.iso10300_virtual import MeanSection, virtual_gears
from bearingcalc.core.iso23509 import BlankInputs, blank, pitch_cones

C_HAM = 0.24737
SAMPLE = BlankInputs(14, 39, math.radians(90.0), 176.893, 25.4, math.radians(35.0),
                     math.radians(20.0), 114.3, 1.0 - 2.0 * C_HAM, 0.037, -0.055,
                     taper="constant-slot-width")
#: ISO 23509 Annex F.2, to its printed digits [mm, °].
PRINTED = {
    "outer_cone_distance": 93.973, "mean_cone_distance": 81.273,
    "pitch_angle_pinion": 19.747, "pitch_angle_gear": 70.253,
    "mean_pitch_diameter_pinion": 54.918, "mean_pitch_diameter_gear": 152.987,
    "mean_normal_module": 3.213, "outer_pitch_diameter_pinion": 63.500,
    "outer_pitch_diameter_gear": 176.893,
    "addendum_angle_pinion": 6.493, "dedendum_angle_pinion": 2.134,
    "face_angle_pinion": 26.240, "root_angle_pinion": 17.613,
    "face_angle_gear": 72.387, "root_angle_gear": 63.760,
    "crown_to_crossing_point_pinion": 86.324, "crown_to_crossing_point_gear": 29.808,
}
#: ISO 23509 Annex F.2's values that carry its depths (within 3 µm) [mm].
DEPTH_BORNE = {
    "outer_addendum_pinion": 6.281, "outer_addendum_gear": 2.064,
    "outer_dedendum_pinion": 2.867, "outer_dedendum_gear": 7.085,
    "outer_tip_diameter_pinion": 75.324, "outer_tip_diameter_gear": 178.288,
    "outer_root_diameter_pinion": 58.102, "outer_root_diameter_gear": 172.106,
}
#: ISO/TR 10300-30 sample 1's depths [mm].
TR_DEPTHS = {"mean_addendum_pinion": 4.837, "mean_dedendum_pinion": 2.393,
             "mean_addendum_gear": 1.590, "mean_dedendum_gear": 5.640}
#: ISO/TR 10300-30 sample 1, Table A.5: the virtual cylindrical gears [mm, °, 1].
TR_VIRTUAL = {
    "dv1": 58.350, "dv2": 452.804, "alpha_vet": 23.957, "mvt": 3.923, "zv1": 14.875,
    "zv2": 115.431, "beta_vb": 32.615, "dva1": 68.023, "dva2": 455.984, "dvb1": 53.323,
    "dvb2": 413.796, "pvet": 11.262, "gv_alpha": 13.120, "eps_v_alpha": 1.165,
    "bv_eff": 21.590, "bv": 25.400, "eps_v_beta": 1.227, "eps_v_gamma": 2.392,
    "rho_t": 13.173, "beta_B": 13.468, "rho_rel": 12.459, "zvn1": 25.594,
    "zvn2": 198.613, "dvn1": 82.241, "dvan1": 91.915, "dvbn1": 77.281, "lbm": 22.442,
}
ANGLES = ("alpha_vet", "beta_vb", "beta_B")


def in_print_units(key: str, value) -> float:
    value = float(value)
    return math.degrees(value) if "angle" in key or key in ANGLES else value


@pytest.fixture(scope="module")
def sample() -> dict:
    return blank(SAMPLE)


@pytest.mark.parametrize("key", list(PRINTED))
def test_the_blank_is_the_standards_sample_to_its_digits(sample, key):
    assert round(in_print_units(key, sample[key]), 3) == PRINTED[key]


@pytest.mark.parametrize("key", list(DEPTH_BORNE))
def test_the_outer_section_is_the_standards_within_its_depth_convention(sample, key):
    assert in_print_units(key, sample[key]) == pytest.approx(DEPTH_BORNE[key], abs=3e-3)


@pytest.mark.parametrize("key", list(TR_DEPTHS))
def test_the_mean_depths_are_the_reports(sample, key):
    assert round(float(sample[key]), 3) == TR_DEPTHS[key]


def test_the_constant_slot_width_sums_the_dedendum_angles_the_sample_gives(sample):
    """The sample gives θ_f2 6.4934° and θ_a2 (= θ_f1) 2.1342° to four places, from a
    c_ham of five: within 0.00015°."""
    assert math.degrees(sample["dedendum_angle_gear"]) == pytest.approx(6.4934, abs=1.5e-4)
    assert math.degrees(sample["dedendum_angle_pinion"]) == pytest.approx(2.1342, abs=1.5e-4)


def test_the_normal_thickness_within_its_modifications_printed_digits(sample):
    """x_sm is printed to 0.001: s_mn = m_mn·(π/2 + 2(x_sm + x_hm·tan α_n)) holds to
    2·m_mn·0.0005 of the printed 6.465 and 3.511 mm."""
    slack = 2.0 * 3.2133 * 0.0005 + 0.0005
    assert sample["mean_normal_circular_thickness_pinion"] == pytest.approx(6.465, abs=slack)
    assert sample["mean_normal_circular_thickness_gear"] == pytest.approx(3.511, abs=slack)


def test_the_other_tapers():
    """Standard depth: the root lines meet at the pitch apex (θ_f = atan(h_fm/R_m));
    uniform depth: no taper; either way the face angle is the mate's root angle's
    complement across the clearance (θ_a1 = θ_f2)."""
    standard = blank(SAMPLE._replace(taper="standard-depth"))
    for member in ("pinion", "gear"):
        assert standard[f"dedendum_angle_{member}"] == pytest.approx(math.atan(
            standard[f"mean_dedendum_{member}"] / standard["mean_cone_distance"]), rel=1e-15)
    assert standard["addendum_angle_pinion"] == standard["dedendum_angle_gear"]
    uniform = blank(SAMPLE._replace(taper="uniform-depth"))
    assert uniform["face_angle_pinion"] == uniform["pitch_angle_pinion"]
    assert uniform["outer_addendum_gear"] == uniform["mean_addendum_gear"]


def test_pitch_cones_at_any_shaft_angle():
    """The two pitch cones touch along a common element: z1/sin δ1 = z2/sin δ2."""
    sigma = np.radians([30.0, 60.0, 90.0, 120.0, 150.0])
    delta1, delta2 = pitch_cones(13, 41, sigma)
    assert np.allclose(delta1 + delta2, sigma, rtol=1e-15)
    assert np.allclose(13 / np.sin(delta1), 41 / np.sin(delta2), rtol=1e-13)


@pytest.fixture(scope="module")
def virtual(sample) -> dict:
    return virtual_gears(MeanSection(
        14, 39, (sample["mean_pitch_diameter_pinion"], sample["mean_pitch_diameter_gear"]),
        (sample["pitch_angle_pinion"], sample["pitch_angle_gear"]),
        (sample["mean_addendum_pinion"], sample["mean_addendum_gear"]),
        (sample["mean_dedendum_pinion"], sample["mean_dedendum_gear"]),
        sample["mean_normal_module"], math.radians(35.0), math.radians(20.0), 25.4))


@pytest.mark.parametrize("key", list(TR_VIRTUAL))
def test_the_virtual_gears_are_the_reports_to_its_digits(virtual, key):
    assert round(in_print_units(key, virtual[key]), 3) == TR_VIRTUAL[key]


def test_a_straight_pair_has_no_face_contact():
    """β_m = 0: the virtual gears are spur gears, ε_vβ = 0, β_B = 0, and the middle
    contact line spans the effective face."""
    flat = virtual_gears(MeanSection(20, 40, (50.0, 100.0), tuple(pitch_cones(
        20, 40, math.pi / 2)), (3.0, 2.0), (3.5, 4.5), 2.5, 0.0, math.radians(20.0), 20.0))
    assert flat["eps_v_beta"] == 0.0 and flat["beta_B"] == 0.0
    assert flat["lbm"] == pytest.approx(17.0 * math.sqrt(0.85), rel=1e-15)
