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

import json
import math

import numpy as np
import pytest

from bearingcalc.core.iso10300_virtual import MeanSection, virtual_gears
from bearingcalc.core.iso23509 import BlankInputs, blank, gleason_profile_shift, pitch_cones
from tests.conftest import ROOT

C_HAM = 0.24737
SAMPLE = BlankInputs(14, 39, math.radians(90.0), 176.893, 25.4, math.radians(35.0),
                     math.radians(20.0), 114.3, 1.0 - 2.0 * C_HAM, 0.037, -0.055,
                     taper="duplex")
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


def test_gleasons_addendum_factor_is_the_samples():
    """The sample's c_ham 0.24737 is Gleason's 0.210 + 0.290/u_a at z 14/39 (u_a = u²
    at Σ = 90°)."""
    delta1, delta2 = pitch_cones(14, 39, math.pi / 2)
    assert round((1.0 - gleason_profile_shift(14, 39, delta1, delta2)) / 2.0, 5) == C_HAM


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


# --- through the command line: a spiral or Zerol pair's blank -------------------------

SPIRAL = (ROOT / "specs" / "bevel-gears-spiral.yaml").read_text(encoding="utf-8")
#: The same pair cut duplex, as the standard's sample is.
DUPLEX = SPIRAL.replace("rating:", "taper: duplex\nrating:")


def solved(cli, spec_file, text: str) -> dict:
    run = cli("solve", spec_file(text), "--format", "json")
    assert run.code in (0, 1), run.err
    return json.loads(run.out)["results"]


def test_the_annex_e_pair_is_the_iso_sample_through_solve(cli, spec_file):
    """specs/bevel-gears-spiral.yaml is the same pair (m 25.4/5.6 mm: d_e2 176.893 mm, a
    4.5 in cutter, Gleason's profile shift): cut duplex, its blank prints as the
    standard's sample does."""
    found = solved(cli, spec_file, DUPLEX)
    for key, printed in PRINTED.items():
        if key in found:
            assert round(in_print_units(key, found[key]) * (1e3 if "angle" not in key
                                                               else 1.0), 3) == printed, key
    for key, printed in TR_DEPTHS.items():
        assert round(found[key] * 1e3, 3) == printed, key
    assert round(found["profile_shift"], 5) == round(1 - 2 * C_HAM, 5)
    assert "gear_a_addendum" not in found  # the Gleason proportions are a straight pair's


def test_the_blanks_fields_reach_the_solver(cli, spec_file):
    text = SPIRAL.replace("rating:", "profile_shift: 0.3\nthickness_modification: "
                          "{pinion: 0.036, gear: -0.055}\ntaper: standard-depth\nrating:")
    found = solved(cli, spec_file, text)
    module = found["mean_normal_module"]
    assert found["mean_addendum_pinion"] == pytest.approx(1.3 * module, rel=1e-12)
    assert found["mean_dedendum_gear"] == pytest.approx(1.55 * module, rel=1e-12)
    assert found["dedendum_angle_gear"] == pytest.approx(math.atan(
        found["mean_dedendum_gear"] / (found["mean_pitch_diameter_gear"] / 2
                                       / math.sin(found["pitch_angle_gear"]))), rel=1e-12)
    assert found["mean_normal_circular_thickness_pinion"] == pytest.approx(module * (
        math.pi / 2 + 2 * (0.036 + 0.3 * math.tan(math.radians(20)))), rel=1e-12)


def test_a_zerol_pair_takes_the_blank_without_a_cutter(cli, spec_file):
    text = (SPIRAL.replace("spiral_angle: 35 deg", "spiral_angle: 0 deg")
            .replace("  cutter_radius: 4.5 in      # rc, for the lengthwise curvature "
                     "factor K_x\n", ""))
    found = solved(cli, spec_file, text)
    assert found["dedendum_angle_pinion"] == pytest.approx(math.atan(
        found["mean_dedendum_pinion"] * 2 * math.sin(found["pitch_angle_pinion"])
        / found["mean_pitch_diameter_pinion"]), rel=1e-12)


@pytest.mark.parametrize("shift,member", [
    ("-0.6", "pinion"), ("0.9\nthickness_modification: {pinion: -0.45, gear: 0.45}",
                         "pinion")])
def test_a_profile_shift_that_undercuts_or_points_a_tooth_is_one_line(cli, spec_file,
                                                                      shift, member):
    run = cli("solve", spec_file(SPIRAL.replace("rating:", f"profile_shift: {shift}\nrating:")))
    lines = run.err.strip().splitlines()
    assert run.code == 2 and len(lines) == 1, run.err
    assert ": profile_shift:" in lines[0] and member in lines[0]


@pytest.mark.parametrize("text,field", [
    (SPIRAL.replace("spiral_angle: 35 deg         # βm at the mean point (0 deg: Zerol)\n"
                    "hand: left                   # the pinion's hand (gear B's is the "
                    "other)\nrotation: counterclockwise   # the pinion's, seen from its "
                    "back toward the apex\n", "").replace(
        "  cutter_radius: 4.5 in      # rc, for the lengthwise curvature factor K_x\n", "")
     .replace("rating:", "profile_shift: 0.3\nrating:"), "profile_shift"),
    (SPIRAL.replace("rating:", "cutter_radius: 100 mm\nrating:"), "rating.cutter_radius"),
    (SPIRAL.replace("  cutter_radius: 4.5 in      # rc, for the lengthwise curvature "
                    "factor K_x\n", "").replace("rating:", "taper: duplex\nrating:")
     .replace("  quality_number: 11", "  quality_number: 11").split("rating:")[0]
     + "limits: {}\n", "cutter_radius"),
    (SPIRAL.replace("rating:", "profile_shift: 2\nrating:"), "profile_shift"),
    (SPIRAL.replace("rating:", "taper: tapered\nrating:"), "taper"),
    (SPIRAL.replace("rating:", "thickness_modification: {pinion: 0.1}\nrating:"),
     "thickness_modification"),
])
def test_the_blanks_fields_refused_in_one_line(cli, spec_file, text, field):
    run = cli("solve", spec_file(text))
    lines = run.err.strip().splitlines()
    assert run.code == 2 and len(lines) == 1, run.err
    assert f": {field}" in lines[0], lines


def test_a_spiral_pair_given_by_its_pitch_angles_takes_them(cli, spec_file):
    """Pitch angles in place of the shaft angle: the blank is built on them."""
    delta1 = math.degrees(math.atan(14 / 39))
    text = SPIRAL.replace("gear_a: {teeth: 14}", f"gear_a: {{teeth: 14, pitch_angle: "
                          f"{delta1!r} deg}}").replace("gear_b: {teeth: 39}", f"gear_b: "
                          f"{{teeth: 39, pitch_angle: {90 - delta1!r} deg}}").replace(
        "shaft_angle: 90 deg\n", "")
    found, given = solved(cli, spec_file, SPIRAL), solved(cli, spec_file, text)
    for key in ("face_angle_pinion", "outer_tip_diameter_gear", "contact_ratio"):
        assert given[key] == pytest.approx(found[key], rel=1e-12), key


def test_the_spiral_pairs_contact_ratio_is_the_reports(cli, spec_file):
    """ε_vα of the virtual cylindrical pair, ISO/TR 10300-30 sample 1: 1.165."""
    assert round(solved(cli, spec_file, SPIRAL)["contact_ratio"], 3) == 1.165


def test_a_duplex_taper_with_too_small_a_cutter_is_one_line(cli, spec_file):
    text = DUPLEX.replace("cutter_radius: 4.5 in", "cutter_radius: 40 mm")
    run = cli("solve", spec_file(text))
    lines = run.err.strip().splitlines()
    assert run.code == 2 and len(lines) == 1 and ": cutter_radius:" in lines[0], run.err


# --- ISO 10300's closed-form factors of the sample -------------------------------------

#: ISO/TR 10300-30 sample 1, Tables A.4 to A.7: T1 300 N·m at 1200 r/min, one member
#: cantilevered, the pattern checked under a light load, E 210 000 N/mm², ν 0.3,
#: σ_Hlim 1500 N/mm², ν40 150 mm²/s, flanks' Rz 8 µm [N, √(N/mm²), 1].
TR_FACTORS = {"Fmt1": 10925.3, "Fn": 14193.3, "ZM-B": 0.916, "ZE": 191.646, "ZL": 0.992,
              "Zv": 0.974, "ZR": 0.930, "KHbeta-C": 1.650, "KF0": 1.000}


def test_the_closed_form_factors_are_the_reports(sample, virtual):
    from bearingcalc.core import iso10300_factors as factors

    dm1 = sample["mean_pitch_diameter_pinion"] * 1e-3
    tangential, normal = factors.nominal_forces(300.0, dm1, math.radians(20.0),
                                                math.radians(35.0))
    speed = math.pi * dm1 * 1200.0 / 60.0
    film, speed_factor, roughness = factors.lubricant_film_factors(
        1500e6, 150e-6, speed, (8e-6, 8e-6), virtual["rho_rel"] * 1e-3)
    found = {
        "Fmt1": tangential, "Fn": normal, "ZM-B": factors.mid_zone_factor(virtual),
        "ZE": factors.elasticity_factor((210e9, 210e9), (0.3, 0.3)) / 1e3,
        "ZL": film, "Zv": speed_factor, "ZR": roughness,
        "KHbeta-C": factors.face_load_factor("one-straddle", "light-load"),
        "KF0": factors.lengthwise_curvature_factor(114.3, sample["mean_cone_distance"],
                                                   math.radians(35.0)),
    }
    for key, printed in TR_FACTORS.items():
        digits = 1 if key.startswith("F") and key != "KF0" else 3
        assert round(float(found[key]), digits) == printed, (key, float(found[key]))


def test_the_mid_zone_factors_branches_meet():
    """F1 and F2 are continuous in ε_vβ at 1 (the partial-overlap branch meets the
    full one), so Z_M-B is."""
    from bearingcalc.core import iso10300_factors as factors

    base = {"eps_v_alpha": np.array(1.4), "dva1": np.array(60.0), "dvb1": np.array(48.0),
            "zv1": np.array(16.0), "dva2": np.array(200.0), "dvb2": np.array(180.0),
            "zv2": np.array(60.0), "alpha_vet": np.array(math.radians(22.0))}
    below = factors.mid_zone_factor({**base, "eps_v_beta": np.array(1.0 - 1e-12)})
    at = factors.mid_zone_factor({**base, "eps_v_beta": np.array(1.0)})
    assert float(below) == pytest.approx(float(at), rel=1e-9)


def test_the_load_factors_by_method_b_are_the_reports(sample, virtual):
    """K_v 1.020 (subcritical, the masses of the virtual gears referred to their base
    circles) and K_Hα 1.161: ISO/TR 10300-30 sample 1, K_A 1.1, the wheel's f_pt 26 µm,
    ρ 7860 kg/m³."""
    from bearingcalc.core import iso10300_factors as factors

    si = {key: (value * 1e-3 if key in ("dv1", "dv2", "bv_eff", "bv") else value)
          for key, value in virtual.items()}
    force = 2.0 * 300.0 / (sample["mean_pitch_diameter_pinion"] * 1e-3)
    kv, ratio = factors.dynamic_factor(si, 14, 1200 * math.pi / 30, force, 1.1, 26e-6,
                                       7860.0)
    assert ratio < factors.SUBCRITICAL and round(float(kv), 3) == 1.020
    determinant = force * 1.1 * kv * 1.65
    k_h_alpha = factors.transverse_load_factor(si, determinant, force, 1.1, 26e-6)
    assert round(float(k_h_alpha), 3) == 1.161


def test_the_dynamic_factor_meets_itself_across_its_sectors(sample, virtual):
    """Between the main resonance and the supercritical sector K_v runs linearly, so it
    meets each at 1.25 and 1.5."""
    from bearingcalc.core import iso10300_factors as factors

    si = {key: (value * 1e-3 if key in ("dv1", "dv2", "bv_eff", "bv") else value)
          for key, value in virtual.items()}
    force = 2.0 * 300.0 / (sample["mean_pitch_diameter_pinion"] * 1e-3)
    _, ratio = factors.dynamic_factor(si, 14, 1.0, force, 1.1, 26e-6, 7860.0)
    per_rad_s = float(ratio)
    speeds = np.array([1.25, 1.25 + 1e-12, 1.5 - 1e-12, 1.5]) / per_rad_s
    kv, _ = factors.dynamic_factor(si, 14, speeds, force, 1.1, 26e-6, 7860.0)
    assert kv[0] == pytest.approx(kv[1], rel=1e-9)
    assert kv[2] == pytest.approx(kv[3], rel=1e-9)
