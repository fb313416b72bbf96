"""`bearingcalc solve` on disk-on-circle, cone-on-plane and bevel-gears specs."""

from __future__ import annotations

import math

import pytest
from numpy.testing import assert_allclose

from bearingcalc.kinds import KINDS
from tests.conftest import ROOT, solve_json
from tests.independent import bevel_pair_3d

CONTRACT_KEYS = {
    "disk-on-circle": ["center_distance", "center_speed", "center_tangential_accel",
                       "center_normal_accel", "center_accel", "orbit_speed",
                       "contact_point_accel"],
    "cone-on-plane": ["precession_speed", "angular_accel", "axis_point_speed",
                      "axis_point_accel"],
    "bevel-gears": ["gear_a_pitch_radius", "gear_b_pitch_radius", "gear_a_pitch_angle",
                    "gear_b_pitch_angle", "shaft_angle", "gear_ratio", "cone_distance",
                    "gear_a_speed_relative_to_arm", "relative_speed", "gear_a_speed",
                    "contact_point_speed", "pitch_line_speed", "apex_mismatch", "slip_margin"],
}

DISK = """kind: disk-on-circle
disk_radius: 20 mm
surface_radius: 80 mm
contact: internal
disk_speed: 600 rpm
"""
CONE = """kind: cone-on-plane
half_angle: 15 deg
spin_speed: 300 rpm
"""
BEVEL = """kind: bevel-gears
gear_a:
  teeth: 12
gear_b:
  teeth: 24
module: 2.5 mm
shaft_angle: 90 deg
arm_speed: 120 rpm
"""


def solve_one(cli, path):
    (record,) = solve_json(cli, path)
    return record


def test_the_first_results_of_the_rolling_systems_keep_their_order():
    for name, keys in CONTRACT_KEYS.items():
        # the results every consumer relies on first, in order; others may follow
        assert list(KINDS[name].results)[:len(keys)] == keys


@pytest.mark.parametrize("kind", sorted(CONTRACT_KEYS))
def test_example_spec_json_has_exactly_the_contract_keys(cli, kind):
    record = solve_one(cli, ROOT / "specs" / f"{kind}.yaml")
    assert record["kind"] == kind
    assert list(record["results"]) == CONTRACT_KEYS[kind]
    assert set(record["units"]) == set(CONTRACT_KEYS[kind])
    assert record["within_limits"] is True


def test_cone_without_axis_point_leaves_out_its_results(cli, spec_file):
    record = solve_one(cli, spec_file(CONE))
    assert list(record["results"]) == ["precession_speed", "angular_accel"]
    assert_allclose(record["results"]["precession_speed"],
                    -300 * 2 * math.pi / 60 * math.tan(math.radians(15)), rtol=1e-14)


def test_disk_defaults_to_a_fixed_surface_and_external_contact(cli, spec_file):
    text = DISK.replace("contact: internal\n", "")
    res = solve_one(cli, spec_file(text))["results"]
    assert_allclose(res["center_distance"], 0.1, rtol=1e-15)
    assert_allclose(res["center_speed"], 0.02 * 600 * 2 * math.pi / 60, rtol=1e-14)


def test_bevel_from_teeth_matches_the_3d_solve(cli, spec_file):
    res = solve_one(cli, spec_file(BEVEL + "gear_b_speed: -30 rpm\n"))["results"]
    ref = bevel_pair_3d(0.015, 0.03, math.pi / 2, 4 * math.pi, -math.pi)
    assert_allclose(math.degrees(res["gear_a_pitch_angle"]), 26.565, atol=5e-4)
    for key in ("gear_a_pitch_angle", "gear_b_pitch_angle", "cone_distance",
                "gear_a_speed_relative_to_arm", "gear_a_speed", "relative_speed",
                "contact_point_speed", "pitch_line_speed"):
        assert_allclose(res[key], ref[key], rtol=1e-9, err_msg=key)


@pytest.mark.parametrize("variant", [
    "gear_a: {pitch_radius: 15 mm}\ngear_b: {pitch_radius: 30 mm}\nshaft_angle: 90 deg\n",
    "gear_a: {teeth: 12, pitch_radius: 15 mm}\ngear_b: {teeth: 24}\nmodule: 2.5 mm\n"
    "shaft_angle: 90 deg\n",
    "gear_a: {pitch_radius: 15 mm, pitch_angle: 26.56505117707799 deg}\n"
    "gear_b: {pitch_radius: 30 mm, pitch_angle: 63.43494882292201 deg}\n",
    "gear_a: {pitch_radius: 15 mm, pitch_angle: 26.56505117707799 deg}\n"
    "gear_b: {pitch_radius: 30 mm}\nshaft_angle: 90 deg\n",
])
def test_bevel_geometry_can_be_given_in_every_allowed_way(cli, spec_file, variant):
    text = "kind: bevel-gears\narm_speed: 120 rpm\n" + variant
    res = solve_one(cli, spec_file(text))["results"]
    assert_allclose(res["shaft_angle"], math.pi / 2, rtol=1e-12)
    assert_allclose(res["gear_a_pitch_angle"], math.atan(0.5), rtol=1e-12)
    assert abs(res["apex_mismatch"]) < 1e-12


def test_bevel_apex_mismatch_over_the_limit_fails(cli, spec_file):
    text = ("kind: bevel-gears\narm_speed: 120 rpm\n"
            "gear_a: {pitch_radius: 15 mm, pitch_angle: 30 deg}\n"
            "gear_b: {pitch_radius: 30 mm, pitch_angle: 60 deg}\n")
    run = cli("solve", spec_file(text))
    assert run.code == 1
    assert "FAIL" in run.out and "slip_margin" in run.out


BAD = [
    (DISK.replace("20 mm", "80 mm"), 2, "disk_radius: internal contact needs disk_radius < "
     "surface_radius, got 80 mm"),
    (DISK.replace("internal", "inside"), 4,
     "contact: must be one of external, internal, got 'inside'"),
    (DISK.replace("80 mm", "-80 mm"), 3, "must be greater than zero"),
    (DISK + "disk_accel: 5 rpm\n", 6, "'rpm' is not a unit of angular acceleration"),
    (CONE.replace("15 deg", "90 deg"), 2, "half_angle: the cone half-angle must be between "
     "0 deg and 90 deg, got 90 deg"),
    (CONE.replace("15 deg", "-5 deg"), 2, "between 0 deg and 90 deg"),
    (CONE + "axis_point_height: 0 mm\n", 4, "must be greater than zero"),
    (BEVEL.replace("teeth: 12", "{}").replace("gear_a:\n  {}", "gear_a: {}"), 2,
     "gear_a: give gear_a.pitch_radius, or gear_a.teeth with module"),
    (BEVEL.replace("module: 2.5 mm\n", ""), 2, "module: gear_a.teeth without a pitch radius "
     "needs the module"),
    (BEVEL.replace("teeth: 12", "teeth: 12.5"), 3, "gear_a.teeth: must be a whole number"),
    (BEVEL.replace("teeth: 24", "teeth: 4"), 5, "gear_b.teeth: must be at least 5"),
    (BEVEL.replace("90 deg", "180 deg"), 7, "shaft_angle: the shaft angle must be between "
     "0 deg and 180 deg, got 180 deg"),
    (BEVEL.replace("90 deg", "0 deg"), 7, "shaft angle must be between 0 deg and 180 deg"),
    (BEVEL.replace("teeth: 12", "teeth: 12\n  pitch_angle: 30 deg").replace(
        "teeth: 24", "teeth: 24\n  pitch_angle: 50 deg"), 9,
     "shaft_angle: the shaft angle must equal the sum of the two pitch angles, got 90 deg"),
    (BEVEL.replace("teeth: 12", "teeth: 12\n  pitch_angle: 95 deg"), 4,
     "gear_a.pitch_angle: the pitch angle of gear A must be between 0 deg and the shaft angle"),
    (BEVEL.replace("shaft_angle: 90 deg\n", ""), 1, "shaft_angle: missing: give shaft_angle"),
    (BEVEL.replace("teeth: 12", "teeth: 12\n  pitch_radius: 20 mm"), 4,
     "gear_a.pitch_radius: disagrees with module × teeth / 2 = 15 mm"),
    (BEVEL + "gear_c: {teeth: 5}\n", 9, "unknown key 'gear_c'"),
    (BEVEL.replace("teeth: 12", "tooth: 12"), 3, "unknown key 'tooth' (did you mean 'teeth'?)"),
    (BEVEL + "limits: {max_apex_mismatch: -1}\n", 9, "must be a finite number from 0"),
]


@pytest.mark.parametrize(("text", "line", "fragment"), BAD,
                         ids=[f"bad{i}" for i in range(len(BAD))])
def test_bad_input_of_each_kind_gets_one_clear_line_and_exit_2(cli, spec_file, text, line,
                                                               fragment):
    path = spec_file(text)
    run = cli("solve", path)
    assert run.code == 2, run.out
    assert run.out == ""
    assert run.err.count("\n") == 1, run.err
    assert run.err.startswith(f"{path}:{line}: "), run.err
    assert fragment in run.err, run.err


@pytest.mark.parametrize("kind", sorted(CONTRACT_KEYS))
@pytest.mark.parametrize("fmt", ["table", "csv"])
def test_each_kind_solves_in_table_and_csv(cli, kind, fmt):
    run = cli("solve", ROOT / "specs" / f"{kind}.yaml", "--format", fmt)
    assert run.code == 0 and run.err == ""
    assert KINDS[kind].name in run.out
