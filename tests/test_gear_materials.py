"""Bevel gears of case-hardened and other steels (AGMA 2003's allowable stress numbers,
temperature and hardness-ratio factors), against Budynas & Nisbett's Example 15-2 as
printed and the factors' formulas written here."""

from __future__ import annotations

import json
import math

import pytest

from bearingcalc.core import gear_materials as gm
from tests.conftest import solve_json

PSI = 6894.757293168
INCH = 0.0254

#: Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, §15-5, Example 15-2: a
#: 20/60 straight bevel pair, Pd = 8 /in, F = 1.25 in, Qv = 6, 6.85 hp at 900 rev/min,
#: R = 0.995 at 10⁹ pinion revolutions, 300 °F, carburized and case-hardened grade 1,
#: neither member straddle-mounted, crowned, I = 0.0825, J_P = 0.248, J_G = 0.202.
EXAMPLE_15_2 = f"""kind: bevel-gears
name: Shigley Example 15-2
gear_a: {{teeth: 20}}
gear_b: {{teeth: 60}}
module: {25.4 / 8!r} mm
shaft_angle: 90 deg
gear_a_speed: 900 rpm
face_width: 1.25 in
pressure_angle: 20 deg
power: 6.85 hp
rating:
  quality_number: 6
  material: carburized
  grade: 1
  mounting: neither-straddle
  crowned: true
  geometry_factor_bending: 0.248
  geometry_factor_bending_gear: 0.202
  geometry_factor_pitting: 0.0825
  overload_factor: 1.0
  cycles: 1e9
  reliability: 0.995
  temperature: 300 degF
limits:
  max_face_width_ratio: 0.5
"""
#: The example's printed results (psi, and the safety factors as the book forms them).
PRINTED = {"gear_b_bending_stress": 10390 * PSI, "bending_stress": 8463 * PSI,
           "contact_stress": 107560 * PSI}
PRINTED_SAFETY = {"gear_b_bending_safety": 2.24, "bending_safety": 2.66,
                  "gear_b_contact_safety": math.sqrt(3.21),
                  "contact_safety": math.sqrt(2.81)}
#: The book works in US units: s_at = 30 000 psi and s_ac = 200 000 psi; its SI table
#: prints 205 MPa and 1380 MPa for the same steel, which the safety factors scale by.
US_TO_SI = {"bending": 205e6 / (30000 * PSI), "contact": 1380e6 / (200000 * PSI)}


def test_shigley_example_15_2_carburized_at_300_f(cli, spec_file):
    """Every printed stress (within 0.1 %: the SI form's K_s and C_p constants are the US
    ones rounded, and the book prints 4 digits) and safety factor (within the printing's
    3 digits, after scaling by the SI table's allowable over the US one)."""
    (record,) = solve_json(cli, spec_file(EXAMPLE_15_2))
    results = record["results"]
    for key, value in PRINTED.items():
        assert results[key] == pytest.approx(value, rel=1e-3), key
    for key, value in PRINTED_SAFETY.items():
        scale = US_TO_SI["bending" if "bending" in key else "contact"]
        assert results[key] == pytest.approx(value * scale, rel=6e-3), key
    # the weaker member governs: gear B in bending, as the book concludes
    assert results["bending_safety_margin"] == pytest.approx(
        results["gear_b_bending_safety"] - 1.0, rel=1e-12)


def test_temperature_factor():
    """K_T = (460 + t)/710 above 250 °F: 1.070 at 300 °F, as Example 15-2 prints."""
    assert float(gm.temperature_factor((300 - 32) / 1.8 + 273.15)) == pytest.approx(
        760 / 710, rel=1e-12)
    assert float(gm.temperature_factor((250 - 32) / 1.8 + 273.15)) == 1.0
    assert float(gm.temperature_factor(293.15)) == 1.0


@pytest.mark.parametrize(("hb_pinion", "hb_gear", "ratio", "expected"), [
    (300, 300, 3.0, 1.0),                                  # ratio 1: no factor
    (360, 200, 3.0, 1 + (0.00898 * 1.7 - 0.00829) * 2.0),  # 1.8 taken as 1.7
    (300, 200, 2.5, 1 + (0.00898 * 1.5 - 0.00829) * 1.5),
    (300, 200, 1 / 3, 1.0),   # the softer member has fewer teeth: no gain, and no loss
])
def test_hardness_ratio_factor(hb_pinion, hb_gear, ratio, expected):
    """C_H = 1 + B1(N/n − 1), B1 = 0.00898·H_BP/H_BG − 0.00829 on 1.2 ≤ H_BP/H_BG ≤ 1.7
    (Budynas & Nisbett eq. 15-16; AGMA's interpretation above 1.7)."""
    assert float(gm.hardness_ratio_factor(hb_pinion, hb_gear, ratio)) == pytest.approx(
        expected, rel=1e-12)


@pytest.mark.parametrize(("material", "grade", "s_at", "s_ac"), [
    ("carburized", 1, 205, 1380), ("carburized", 2, 240, 1550), ("carburized", 3, 275, 1720),
    ("nitrided", 2, 150, 1000), ("flame-or-induction-hardened", 1, 154, 1210),
])
def test_allowable_stress_numbers(material, grade, s_at, s_ac):
    """Budynas & Nisbett Tables 15-4 and 15-6 (SI), which an AGMA 2003-D19 calculator's
    SI table repeats."""
    assert tuple(float(v) for v in gm.allowable_stresses(material, grade)) == (
        s_at * 1e6, s_ac * 1e6)


def test_through_hardened_grade_2_follows_the_hardness(cli, spec_file):
    """Grade 2 through-hardened steel: s_at = 0.33·HB + 41.24, s_ac = 2.51·HB + 203.86 MPa
    against grade 1's 0.30·HB + 14.48 and 2.35·HB + 162.89: the safety factors scale by
    those ratios."""
    base = EXAMPLE_15_2.replace("material: carburized", "material: through-hardened\n"
                                "  hardness: 300 HB").replace("  temperature: 300 degF\n", "")
    (grade_1,) = solve_json(cli, spec_file(base, "g1.yaml"))
    (grade_2,) = solve_json(cli, spec_file(base.replace("grade: 1", "grade: 2"), "g2.yaml"))
    bending = (0.33 * 300 + 41.24) / (0.30 * 300 + 14.48)
    contact = (2.51 * 300 + 203.86) / (2.35 * 300 + 162.89)
    assert grade_2["results"]["bending_safety"] == pytest.approx(
        grade_1["results"]["bending_safety"] * bending, rel=1e-12)
    assert grade_2["results"]["contact_safety"] == pytest.approx(
        grade_1["results"]["contact_safety"] * contact, rel=1e-12)


@pytest.mark.parametrize(("change", "field"), [
    (("material: carburized", "material: nitrided"), "rating.grade"),
    (("material: carburized", "material: through-hardened"), "rating.hardness"),
    (("material: carburized", "material: carburized\n  hardness: 300 HB"), "rating.hardness"),
])
def test_bad_steel_is_one_line(cli, spec_file, change, field):
    run = cli("solve", spec_file(EXAMPLE_15_2.replace(*change)))
    assert run.code == 2 and run.err.count("\n") == 1 and f": {field}: " in run.err, run.err


def test_a_face_width_in_inches_is_read(cli, spec_file):
    (record,) = solve_json(cli, spec_file(EXAMPLE_15_2))
    assert record["results"]["face_width_ratio"] == pytest.approx(
        1.25 * INCH / record["results"]["outer_cone_distance"], rel=1e-12)


STRICT = EXAMPLE_15_2.replace("  max_face_width_ratio: 0.5\n",
                              "  max_face_width_ratio: 0.5\n  min_bending_safety: 2.5\n")


@pytest.mark.parametrize("cycle", ["", "duty_cycle:\n  - {time: 100 %}\n"])
def test_the_weaker_member_is_judged_at_a_point_and_over_a_cycle(cli, spec_file, cycle):
    """Gear B (S_F 2.24 in the book) is weaker than the pinion (2.66): with a minimum of
    2.5 the verdict names gear B's safety against 2.5, alone or as a one-bin cycle."""
    run = cli("solve", spec_file(STRICT + cycle))
    assert run.code == 1, run.err
    (record,) = solve_json(cli, spec_file(STRICT + cycle, "json.yaml"))
    (verdict,) = [v for v in record["verdicts"] if v["key"] == "bending_safety_margin"]
    assert verdict["value"] == record["results"]["gear_b_bending_safety"]
    assert verdict["limit"] == pytest.approx(2.5, rel=1e-12)
    assert "< min 2.5" in run.out
    assert "FAIL: gear B's bending safety S_F" in run.out
    assert verdict["name"] == "gear B's bending safety S_F"


def test_a_softer_gear_takes_its_own_allowables_and_c_h(cli, spec_file):
    """Through-hardened pinion 300 HB, gear B 200 HB, ratio 3: gear B's s_ac = 2.35·200 +
    162.89 and C_H = 1 + (0.00898·1.5 − 0.00829)·2, against a gear B of 300 HB."""
    base = EXAMPLE_15_2.replace("material: carburized", "material: through-hardened\n"
                                "  hardness: 300 HB")
    (same,) = solve_json(cli, spec_file(base, "same.yaml"))
    (soft,) = solve_json(cli, spec_file(base.replace("hardness: 300 HB", "hardness: 300 HB\n"
                                                     "  gear_hardness: 200 HB"), "soft.yaml"))
    c_h = 1 + (0.00898 * 1.5 - 0.00829) * 2
    contact = (2.35 * 200 + 162.89) / (2.35 * 300 + 162.89) * c_h
    bending = (0.30 * 200 + 14.48) / (0.30 * 300 + 14.48)
    assert soft["results"]["gear_b_contact_safety"] == pytest.approx(
        same["results"]["gear_b_contact_safety"] * contact, rel=1e-12)
    assert soft["results"]["gear_b_bending_safety"] == pytest.approx(
        same["results"]["gear_b_bending_safety"] * bending, rel=1e-12)
    assert soft["results"]["contact_safety"] == same["results"]["contact_safety"]


def test_a_gear_hardness_without_gear_bs_j_is_refused(cli, spec_file):
    text = EXAMPLE_15_2.replace("material: carburized", "material: through-hardened\n"
                                "  hardness: 300 HB\n  gear_hardness: 200 HB").replace(
        "  geometry_factor_bending_gear: 0.202\n", "")
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1
    assert ": rating.geometry_factor_bending_gear: " in run.err


def test_a_sweep_over_the_grade_is_each_grade_solved_alone(cli, spec_file, tmp_path):
    """A choice of whole numbers sweeps like a count: each point is the spec with that
    grade (carburized grades 1 to 3, Table 15-6's numbers), solved on its own."""
    spec = spec_file(EXAMPLE_15_2, "steel.yaml")
    run = cli("sweep", spec, "--vary", "rating.grade=1:3:3", "-f", "json")
    assert run.code == 0, run.err
    points = [json.loads(line) for line in run.out.splitlines()]
    assert [point["inputs"]["rating.grade"] for point in points] == [1, 2, 3]
    for point in points:
        grade = point["inputs"]["rating.grade"]
        (alone,) = solve_json(cli, spec_file(EXAMPLE_15_2.replace("grade: 1",
                                                                  f"grade: {grade}"),
                                             f"grade-{grade}.yaml"))
        for key in ("bending_safety", "contact_safety", "gear_b_bending_safety"):
            assert point["results"][key] == pytest.approx(alone["results"][key],
                                                          rel=1e-12), (grade, key)


def test_a_grade_the_steel_has_not_stops_the_sweep(cli, spec_file):
    spec = spec_file(EXAMPLE_15_2.replace("material: carburized", "material: nitrided")
                     .replace("grade: 1", "grade: 2"))
    run = cli("sweep", spec, "--vary", "rating.grade=1:2:2")
    assert run.code == 2 and run.err.count("\n") == 1 and "rating.grade" in run.err, run.err


def test_a_sweep_over_the_hardness_follows_the_allowables(cli, spec_file):
    """Through-hardened grade 1: S_F ∝ s_at = 0.30·HB + 14.48 and S_H ∝ s_ac = 2.35·HB +
    162.89 MPa (Budynas & Nisbett Figs 15-12, 15-13), the bounds written with HB."""
    base = EXAMPLE_15_2.replace("material: carburized", "material: through-hardened\n"
                                "  hardness: 300 HB").replace("  temperature: 300 degF\n", "")
    run = cli("sweep", spec_file(base), "--vary", "rating.hardness=200HB:400 HB:3", "-f",
              "json")
    assert run.code == 0, run.err
    points = {json.loads(line)["inputs"]["rating.hardness"]: json.loads(line)["results"]
              for line in run.out.splitlines()}
    assert sorted(points) == [200.0, 300.0, 400.0]
    for hardness, results in points.items():
        assert results["bending_safety"] == pytest.approx(
            points[200.0]["bending_safety"] * (0.30 * hardness + 14.48) / (0.30 * 200 + 14.48),
            rel=1e-12)
        assert results["contact_safety"] == pytest.approx(
            points[200.0]["contact_safety"] * (2.35 * hardness + 162.89)
            / (2.35 * 200 + 162.89), rel=1e-12)


@pytest.mark.parametrize(("written", "says"), [
    ("true", "got true"),                                  # YAML's true is not 1
    ('"2"', "got '2' (a number: write it without quotes)"),
])
def test_a_grade_must_be_a_plain_whole_number(cli, spec_file, written, says):
    run = cli("solve", spec_file(EXAMPLE_15_2.replace("grade: 1", f"grade: {written}")))
    assert run.code == 2 and run.err.count("\n") == 1, run.err
    assert f": rating.grade: must be one of 1, 2, 3, {says}" in run.err


@pytest.mark.parametrize(("temperature", "accepted"), [
    ("32 degF", True), ("392 degF", True), ("31 degF", False), ("393 degF", False),
    ("-40 degC", False), ("1e6 K", False)])
def test_the_temperature_is_within_what_k_t_covers(cli, spec_file, temperature, accepted):
    """K_T = 1 starts at 32 °F (0 °C); above about 200 °C a hardened steel tempers, which
    K_T does not model: outside 0–200 °C the temperature is refused in one line."""
    text = EXAMPLE_15_2.replace("temperature: 300 degF", f"temperature: {temperature}")
    run = cli("solve", spec_file(text))
    if accepted:
        assert run.code == 0, run.err
    else:
        assert run.code == 2 and run.err.count("\n") == 1, run.err
        assert ": rating.temperature: " in run.err and "0 °C to 200 °C" in run.err, run.err
