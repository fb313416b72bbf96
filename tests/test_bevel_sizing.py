"""Bevel-pair sizing against Shigley's Example 15-1, a gear maker's blank table,
identities of the geometry, and a 3-D decomposition of the tooth force."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from bearingcalc.core import bevel_rating
from bearingcalc.core import bevel_sizing as bs
from tests.conftest import ROOT, csv_column, solve_json

LBF, HP, INCH = 4.4482216152605, 745.69987158227022, 0.0254

MITER = (ROOT / "specs" / "bevel-gears-sizing.yaml").read_text()


def _shigley_15_1(cycles=1e7, reliability=0.99, torque=1.0):
    """Example 15-1's pair in SI: Pd = 5/in, 25/25 teeth, F = 1.1 in, 20°, Qv 7, 180 HB,
    600 rev/min, uncrowned, outboard (neither member straddle), J = 0.216, I = 0.065."""
    module = INCH / 5
    return bevel_rating.agma_rating(torque, 600 * 2 * math.pi / 60, module, 25 * module,
                                    1.1 * INCH, 7, 180, 1.25, 0, 0.216, 0.065, 1.0, cycles,
                                    reliability)


def test_shigley_example_15_1_bending_and_wear_ratings():
    """Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., Example 15-1:
    (a) bending: Wt = 552.6 lbf, H = 13.2 hp; (b) wear: Wt = 458.1 lbf, H = 10.9 hp (US
    units). The SI form rounds its constants: within 2 % of the book."""
    out = _shigley_15_1()
    # At T = 1 N·m the power ratings are the power at S = 1.
    bending_hp = float(out["bending_power_rating"]) / HP
    contact_hp = float(out["contact_power_rating"]) / HP
    speed = 600 * 2 * math.pi / 60
    pitch_line = 0.5 * 25 * INCH / 5 * speed
    assert bending_hp == pytest.approx(13.2, rel=0.02)
    assert contact_hp == pytest.approx(10.9, rel=0.02)
    assert float(out["bending_power_rating"]) / pitch_line / LBF == pytest.approx(552.6, rel=0.02)
    assert float(out["contact_power_rating"]) / pitch_line / LBF == pytest.approx(458.1, rel=0.02)


def test_the_si_formulas_factor_by_factor():
    """Each factor of the SI form, computed here from Budynas & Nisbett eqs. (15-1)-(15-23)
    for Example 15-1 at T = 100 N·m, against the solver to rounding."""
    module, b, de, torque = 5.08, 27.94, 127.0, 100.0          # mm, mm, mm, N·m
    speed = 600 * 2 * math.pi / 60
    v = de / 2000 * speed
    b_exp = 0.25 * (12 - 7) ** (2 / 3)
    a_coeff = 50 + 56 * (1 - b_exp)
    kv = ((a_coeff + math.sqrt(200 * v)) / a_coeff) ** b_exp
    ks = 0.4867 + 0.008339 * module
    km = 1.25 + 5.6e-6 * b ** 2
    wt = 2 * torque * 1000 / de
    s_f = wt / b * ks * km / 0.216 * kv / module
    s_h = 190 * math.sqrt(wt * kv * km * (0.00492 * b + 0.4375) * 2 / (b * de * 0.065))
    k_l = 1.683 * 1e7 ** -0.0323
    c_l = 3.4822 * 1e7 ** -0.0602
    out = _shigley_15_1(torque=torque)
    assert float(out["bending_stress"]) == pytest.approx(s_f * 1e6, rel=1e-13)
    assert float(out["contact_stress"]) == pytest.approx(s_h * 1e6, rel=1e-13)
    assert float(out["bending_safety"]) == pytest.approx((0.30 * 180 + 14.48) * k_l / s_f,
                                                         rel=1e-13)
    assert float(out["contact_safety"]) == pytest.approx((2.35 * 180 + 162.89) * c_l / s_h,
                                                         rel=1e-13)


def test_shigley_example_15_1_part_c_scales_by_the_life_and_reliability_factors():
    """Example 15-1 (c): R = 0.995 and 10^9 cycles. Against (a) and (b), the bending
    rating scales by K_L/K_R and the wear rating by (C_L/C_R)² (s_F ∝ Wt, s_H ∝ √Wt)."""
    base, part_c = _shigley_15_1(), _shigley_15_1(cycles=1e9, reliability=0.995)
    k_l = (1e9 / 1e7) ** -0.0323
    c_l = (1e9 / 1e7) ** -0.0602
    k_r = (0.50 - 0.25 * math.log10(0.005)) / (0.50 - 0.25 * math.log10(0.01))
    assert float(part_c["bending_power_rating"] / base["bending_power_rating"]) == \
        pytest.approx(k_l / k_r, rel=1e-13)
    assert float(part_c["contact_power_rating"] / base["contact_power_rating"]) == \
        pytest.approx(c_l ** 2 / k_r, rel=1e-13)
    assert 0.50 - 0.25 * math.log10(0.005) == pytest.approx(1.075, abs=5e-4)  # book's K_R


def test_reliability_factor_branches():
    low = _shigley_15_1(reliability=0.95)
    assert float(low["bending_safety"] / _shigley_15_1()["bending_safety"]) == pytest.approx(
        1.0 / (0.70 - 0.15 * math.log10(0.05)), rel=1e-13)


def test_khk_gleason_straight_bevel_table():
    """KHK Gear Technical Reference, 'Bevel gear calculations', Gleason straight bevel gear
    table: m = 3, z = 20/40, Σ = 90°, α = 20°: δ 26.56505°/63.43495°, Re 67.08204,
    ha 4.035/1.965, hf 2.580/4.650, da 67.2180/121.7575, X 58.1955/28.2425 (mm)."""
    d1, d2 = math.atan(20 / 40), math.atan(40 / 20)
    g = {k: float(v) for k, v in bs.blank_geometry(20, 40, 3e-3, d1, d2, 20e-3,
                                                    math.radians(20)).items()}
    mm = 1e3
    assert math.degrees(d1) == pytest.approx(26.56505, abs=5e-6)
    assert g["outer_cone_distance"] * mm == pytest.approx(67.08204, abs=5e-6)
    assert g["gear_a_addendum"] * mm == pytest.approx(4.035, abs=5e-4)
    assert g["gear_b_addendum"] * mm == pytest.approx(1.965, abs=5e-4)
    assert g["gear_a_dedendum"] * mm == pytest.approx(2.580, abs=5e-4)
    assert g["gear_b_dedendum"] * mm == pytest.approx(4.650, abs=5e-4)
    assert g["gear_a_dedendum_angle"] == pytest.approx(math.atan(2.580 / 67.08204), rel=1e-6)
    assert g["gear_a_outside_diameter"] * mm == pytest.approx(67.2180, abs=5e-5)
    assert g["gear_b_outside_diameter"] * mm == pytest.approx(121.7575, abs=5e-5)
    assert g["gear_a_crown_to_apex"] * mm == pytest.approx(58.1955, abs=5e-5)
    assert g["gear_b_crown_to_apex"] * mm == pytest.approx(28.2425, abs=5e-5)


def test_geometry_identities(cli, spec_file):
    text = MITER.replace("gear_a: {teeth: 25}", "gear_a: {teeth: 17}").replace(
        "gear_b: {teeth: 25}", "gear_b: {teeth: 52}")
    assert "{teeth: 52}" in text
    for angle in ("90 deg", "70 deg", "115 deg"):
        (record,) = solve_json(cli, spec_file(text.replace("90 deg", angle)))
        r = record["results"]
        assert r["gear_a_pitch_angle"] + r["gear_b_pitch_angle"] == pytest.approx(
            math.radians(float(angle.split()[0])), rel=1e-14)
        # Re from either gear
        re_b = r["gear_b_outer_pitch_diameter"] / (2 * math.sin(r["gear_b_pitch_angle"]))
        assert r["outer_cone_distance"] == pytest.approx(re_b, rel=1e-13)
        assert r["gear_a_mean_pitch_diameter"] / r["gear_a_outer_pitch_diameter"] == \
            pytest.approx(r["mean_cone_distance"] / r["outer_cone_distance"], rel=1e-14)
        # the three components make the normal tooth force at φ
        wt, wr, wa = (r[k] for k in ("tangential_force", "gear_a_radial_force",
                                     "gear_a_axial_force"))
        assert math.hypot(wt, wr, wa) == pytest.approx(wt / math.cos(math.radians(20)),
                                                       rel=1e-14)


@pytest.mark.parametrize("shaft_angle", [60.0, 90.0, 125.0])
def test_tooth_force_in_three_dimensions(shaft_angle):
    """Gear A (axis n3) and gear B (axis k) share their pitch apex at the origin. The
    tooth force on A at the mean pitch point is built as a vector (tangential plus the
    separating part square to the common cone element); its moment about A's axis must
    be the torque, and its parts along and across each gear's own axis the solver's."""
    z1, z2, torque = 17, 43, 60.0
    sigma = math.radians(shaft_angle)
    d1 = math.atan(math.sin(sigma) / (z2 / z1 + math.cos(sigma)))
    d2 = sigma - d1
    geometry = bs.blank_geometry(z1, z2, 3e-3, d1, d2, 18e-3, math.radians(20))
    forces = {k: float(v) for k, v in bs.tooth_forces(
        torque, geometry["gear_a_mean_pitch_diameter"], math.radians(20), d1, d2).items()}
    rm = float(geometry["mean_cone_distance"])
    n3 = np.array([0.0, 0.0, 1.0])
    k = np.array([math.sin(sigma), 0.0, math.cos(sigma)])       # B's axis, at Σ from A's
    element = np.array([math.sin(d1), 0.0, math.cos(d1)])      # apex → pitch point, plane y=0
    point = rm * element
    assert np.dot(element, k) == pytest.approx(math.cos(d2), abs=1e-14)
    tangential = np.array([0.0, 1.0, 0.0])                      # square to the plane of axes
    normal_in_plane = np.cross(tangential, element)             # square to the element
    outward_a = normal_in_plane if np.dot(normal_in_plane, point - n3 * (point @ n3)) > 0 \
        else -normal_in_plane
    wt = forces["tangential_force"]
    force_on_a = wt * tangential - wt * math.tan(math.radians(20)) * outward_a
    assert abs(np.cross(point, force_on_a) @ n3) == pytest.approx(torque, rel=1e-13)
    radial_a = point - n3 * (point @ n3)
    assert force_on_a @ n3 == pytest.approx(forces["gear_a_axial_force"], rel=1e-13)
    assert -force_on_a @ (radial_a / np.linalg.norm(radial_a)) == pytest.approx(
        forces["gear_a_radial_force"], rel=1e-13)
    force_on_b = -force_on_a
    radial_b = point - k * (point @ k)
    assert force_on_b @ k == pytest.approx(forces["gear_b_axial_force"], rel=1e-13)
    assert -force_on_b @ (radial_b / np.linalg.norm(radial_b)) == pytest.approx(
        forces["gear_b_radial_force"], rel=1e-13)
    if shaft_angle == 90.0:
        assert forces["gear_b_radial_force"] == pytest.approx(forces["gear_a_axial_force"],
                                                              rel=1e-13)
        assert forces["gear_b_axial_force"] == pytest.approx(forces["gear_a_radial_force"],
                                                             rel=1e-13)


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_sizing_in_every_format(cli, fmt):
    run = cli("solve", ROOT / "specs" / "bevel-gears-sizing.yaml", "-f", fmt)
    assert run.code == 0, run.err
    for key in ("outer_cone_distance", "gear_b_crown_to_apex", "tangential_force",
                "contact_power_rating"):
        assert key in run.out
    if fmt == "table":
        for heading in ("geometry", "forces", "rating"):
            assert heading in run.out


def test_power_and_torque_agree(cli, spec_file):
    (by_power,) = solve_json(cli, ROOT / "specs" / "bevel-gears-sizing.yaml")
    torque = 7500 / (600 * 2 * math.pi / 60)
    (by_torque,) = solve_json(cli, spec_file(MITER.replace("power: 7.5 kW",
                                                           f"torque: {torque!r} N*m")))
    for key in ("tangential_force", "bending_safety", "contact_safety"):
        assert by_torque["results"][key] == pytest.approx(by_power["results"][key], rel=1e-13)


def test_check_fails_a_pair_by_its_safety_margins(cli, spec_file):
    run = cli("check", spec_file(MITER.replace("7.5 kW", "12 kW")), "-f", "json")
    record = json.loads(run.out)
    assert run.code == 1 and record["status"] == "fail"
    assert record["margins"]["contact_safety_margin"] < 0


def test_tolerance_gives_the_band_of_each_safety_factor(cli):
    run = cli("tolerance", ROOT / "specs" / "tolerances" / "bevel-gears-sizing.yaml", "-n",
              "4096", "-f", "json")
    assert run.code == 0, run.err
    results = json.loads(run.out)["results"]
    for key in ("bending_safety", "contact_safety"):
        band = results[key]["worst_case"]
        assert band["min"] < results[key]["nominal"] < band["max"]
        # the weakest corner has the most torque and the narrowest face
        assert band["min_inputs"]["torque"] == pytest.approx(125.0, rel=1e-9)


def test_sweep_of_face_width_plots_both_safety_factors(cli, tmp_path):
    plot = tmp_path / "safety.png"
    run = cli("sweep", ROOT / "specs" / "bevel-gears-sizing.yaml", "--vary",
              "face_width=15mm:30mm:16", "-r", "bending_safety", "-r", "contact_safety",
              "--plot", plot, "-f", "csv")
    assert run.code == 0, run.err
    bending = csv_column(run.out, "bending_safety [1]")
    assert len(bending) == 16 and bending[-1] > bending[0]
    assert plot.read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize(("change", "fragment"), [
    (("face_width: 27.94 mm", "face_width: 50 mm"), "less than half the outer cone"),
    (("power: 7.5 kW", "power: 7.5 kW\ntorque: 100 N*m"), "not both"),
    (("power: 7.5 kW", ""), "the strength rating needs a load"),
    (("quality_number: 7", "quality_number: 12"), "from 5 to 11"),
    (("quality_number: 7", "quality_number: 7.5"), "whole number"),
    (("180 HB", "450 HB"), "from 180 to 400 HB"),
    (("180 HB", "180 HRC"), "like '180 HB'"),
    (("geometry_factor_bending: 0.216", "geometry_factor_bending: 0"), "from 1e-06"),
    (("cycles: 1e7", "cycles: 1e11"), "from 1000 to 1e+10"),
    (("reliability: 0.99", "reliability: 0.5"), "from 90 % to 99.99 %"),
    (("gear_a: {teeth: 25}", "gear_a: {pitch_radius: 63.5 mm}"), "sizing needs the teeth"),
    (("pressure_angle: 20 deg", "pressure_angle: 50 deg"), "between 0 deg and 45 deg"),
    (("gear_a_speed: 600 rpm", "arm_speed: 100 rpm\ngear_b_speed: 100 rpm\n#"),
     "power gives no torque"),
])
def test_bad_sizing_input_is_one_clear_line(cli, spec_file, change, fragment):
    text = MITER.replace(*change)
    assert text != MITER
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1 and fragment in run.err, run.err


def test_a_small_pinion_warns_of_undercut(cli, spec_file):
    text = MITER.replace("gear_a: {teeth: 25}", "gear_a: {teeth: 11}").replace(
        "gear_b: {teeth: 25}", "gear_b: {teeth: 40}")
    (record,) = solve_json(cli, spec_file(text.replace("27.94 mm", "20 mm")))
    assert any("undercut" in w for w in record["warnings"])


def test_a_pair_faster_than_its_dynamic_factor_covers_is_refused(cli, spec_file):
    """A module written in m, not mm, makes a 60 m pinion at 4,700 m/s: far above the
    v_t,max the AGMA dynamic factor covers at Q_v 8 (about 28.7 m/s), so the spec is
    refused at the quality number, not rated."""
    text = (ROOT / "specs" / "bevel-drive.yaml").read_text()
    run = cli("solve", spec_file(text.replace("module: 3 mm", "module: 3 m")))
    assert run.code == 2 and "rating.quality_number" in run.err and "v_t,max" in run.err
    # (50 + 56·(1 − B) + Q_v − 3)²/200 with B = 0.25·(12 − Q_v)^(2/3), written out at Q_v 8
    b_exp = 0.25 * 4.0 ** (2.0 / 3.0)
    assert bevel_rating.max_pitch_line_speed(8) == pytest.approx(
        (50.0 + 56.0 * (1.0 - b_exp) + 5.0) ** 2 / 200.0, rel=1e-12)
    assert 28.6 < bevel_rating.max_pitch_line_speed(8) < 28.7
    # the example pair at 1500 rpm runs at 4.7 m/s: rated as before
    assert cli("solve", spec_file(text)).code == 0
