"""Spiral bevel pairs: the tooth forces against the normal tooth force built here as a 3-D
vector from the hand, the rotation and the pressure and spiral angles, resolved along
both gears' axes, for both hands and both rotations; and in a drive, the thrust on the
bearing that force says."""

from __future__ import annotations

import itertools
import math
import re

import numpy as np
import pytest

from tests.conftest import ROOT, solve_json

PAIR = ("kind: bevel-gears\ngear_a: {{teeth: 20}}\ngear_b: {{teeth: 40}}\nmodule: 3 mm\n"
        "shaft_angle: {sigma} deg\ngear_a_speed: 1500 rpm\nface_width: 15 mm\n"
        "pressure_angle: 20 deg\ntorque: 10 N*m\nspiral_angle: 35 deg\n"
        "hand: {hand}\nrotation: {rotation}\n")
CASES = list(itertools.product((90.0, 70.0), ("left", "right"),
                               ("clockwise", "counterclockwise")))


def forces_3d(results: dict, sigma: float, hand: str, rotation: str) -> dict[str, float]:
    """The force of the gear on the driving pinion, built as a vector and resolved.

    The pinion's axis is x̂, pointing from the apex toward its back; the mean pitch point
    P = R_m(cos δ1, sin δ1, 0); gear B's axis is (cos Σ, sin Σ, 0). At P, g is the
    pitch cone's element (away from the apex), t = x̂ × u the direction of a
    counterclockwise turn seen from the back (the turn is clockwise where ω points along
    −x̂, the way the viewer looks), n the pitch cone's outward normal. A right-hand
    tooth runs along cos β·g + sin β·t from toe to heel (it turns clockwise seen from the
    apex side), a left-hand one along cos β·g − sin β·t. The force is normal to the
    tooth: in the pitch plane square to the tooth, against the pinion's motion, and
    −sin φn along n (it separates the gears); its component along the motion is W_t.
    """
    d1, beta = results["gear_a_pitch_angle"], math.radians(35.0)
    phi, sig = math.radians(20.0), math.radians(sigma)
    axis1, u1 = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    g = math.cos(d1) * axis1 + math.sin(d1) * u1
    n = -math.sin(d1) * axis1 + math.cos(d1) * u1
    t = np.cross(axis1, u1)
    q = (-math.sin(beta) * g + math.cos(beta) * t if hand == "right"
         else math.sin(beta) * g + math.cos(beta) * t)   # square to the tooth, q·t > 0
    moving = 1.0 if rotation == "counterclockwise" else -1.0   # along ±t
    w_n = results["tangential_force"] / (math.cos(phi) * math.cos(beta))
    force = w_n * (-moving * math.cos(phi) * q - math.sin(phi) * n)
    assert abs(force @ t) == pytest.approx(results["tangential_force"], rel=1e-12)
    axis2 = np.array([math.cos(sig), math.sin(sig), 0.0])
    point = g  # P's direction from the apex
    u2 = point - (point @ axis2) * axis2
    u2 /= np.linalg.norm(u2)
    on_gear = -force
    return {"gear_a_axial_force": float(force @ axis1),
            "gear_a_radial_force": float(-force @ u1),
            "gear_b_axial_force": float(on_gear @ axis2),
            "gear_b_radial_force": float(-on_gear @ u2)}


@pytest.mark.parametrize(("sigma", "hand", "rotation"), CASES)
def test_spiral_forces_are_the_3d_normal_force_resolved(cli, spec_file, sigma, hand,
                                                        rotation):
    (record,) = solve_json(cli, spec_file(PAIR.format(sigma=sigma, hand=hand,
                                                      rotation=rotation)))
    results = record["results"]
    expected = forces_3d(results, sigma, hand, rotation)
    for key, value in expected.items():
        assert results[key] == pytest.approx(value, rel=1e-9, abs=1e-9), key


def test_the_apex_rule_of_a_driving_pinion(cli, spec_file):
    """A driving pinion's thrust points away from the apex for left hand turning
    clockwise or right hand counterclockwise; the other two pull it toward the apex here
    (sin β·cos δ1 > tan φn·sin δ1)."""
    signs = {}
    for hand, rotation in itertools.product(("left", "right"),
                                            ("clockwise", "counterclockwise")):
        (record,) = solve_json(cli, spec_file(
            PAIR.format(sigma=90, hand=hand, rotation=rotation), f"{hand}-{rotation}.yaml"))
        signs[hand, rotation] = record["results"]["gear_a_axial_force"] > 0
    assert signs == {("left", "clockwise"): True, ("right", "counterclockwise"): True,
                     ("left", "counterclockwise"): False, ("right", "clockwise"): False}


def test_zerol_is_the_straight_pair(cli, spec_file):
    text = PAIR.format(sigma=90, hand="right", rotation="clockwise")
    (zerol,) = solve_json(cli, spec_file(text.replace("35 deg", "0 deg"), "zerol.yaml"))
    straight_text = text.replace("spiral_angle: 35 deg\nhand: right\nrotation: clockwise\n", "")
    (straight,) = solve_json(cli, spec_file(straight_text, "straight.yaml"))
    for key in ("gear_a_axial_force", "gear_a_radial_force", "gear_b_axial_force",
                "gear_b_radial_force"):
        assert zerol["results"][key] == pytest.approx(straight["results"][key], rel=1e-12)


DRIVE = (ROOT / "specs" / "bevel-drive-tapered.yaml").read_text()


@pytest.mark.parametrize(("hand", "rotation"), list(itertools.product(
    ("left", "right"), ("clockwise", "counterclockwise"))))
def test_the_drive_puts_the_thrust_on_the_bearing_the_3d_force_says(cli, spec_file, hand,
                                                                    rotation):
    """Back-to-back tapered bearings at 85 mm and 150 mm: the one nearer the apex carries
    shaft forces away from the apex (+x). A thrust away from the apex (the 3-D force's
    sign) loads bearing 1 by Ka beyond bearing 2's: FaA − FaB = Ka; toward the apex,
    bearing 2: FaB − FaA = |Ka|."""
    rating = DRIVE[DRIVE.index("rating:"):DRIVE.index("pinion_arrangement")]
    text = DRIVE.replace(rating, "") + (f"spiral_angle: 35 deg\nhand: {hand}\n"
                                        f"rotation: {rotation}\n")
    (record,) = solve_json(cli, spec_file(text))
    results = record["results"]
    pair = {"gear_a_pitch_angle": results["gear_a_pitch_angle"],
            "tangential_force": results["tangential_force"]}
    thrust = forces_3d(pair, 90.0, hand, rotation)["gear_a_axial_force"]
    first, second = (results[f"pinion_bearing_{i}_axial_load"] for i in (1, 2))
    if thrust > 0:
        assert first - second == pytest.approx(thrust, rel=1e-9)
    else:
        assert second - first == pytest.approx(-thrust, rel=1e-9)


@pytest.mark.parametrize(("hand", "rotation"), list(itertools.product(
    ("left", "right"), ("clockwise", "counterclockwise"))))
def test_a_one_way_locating_bearing_is_told_which_way_the_thrust_points(cli, spec_file,
                                                                        hand, rotation):
    """A single-row angular-contact bearing locating the pinion shaft carries thrust one
    way only: the drive warns, naming the way the 3-D force says the thrust points. A
    deep-groove bearing, which carries both, draws no such warning."""
    plain = re.sub(r"^rating:.*$", f"spiral_angle: 35 deg\nhand: {hand}\n"
                   f"rotation: {rotation}\nrating:\n  cutter_radius: 3 in",
                   (ROOT / "specs" / "bevel-drive.yaml").read_text(), count=1,
                   flags=re.MULTILINE)
    one_way = plain.replace("{position: 90 mm, locating: true, type: deep-groove,",
                            "{position: 90 mm, locating: true, type: angular-contact, "
                            "contact_angle: 40 deg,")
    assert one_way != plain
    (record,) = solve_json(cli, spec_file(one_way, "one-way.yaml"))
    pair = {"gear_a_pitch_angle": record["results"]["gear_a_pitch_angle"],
            "tangential_force": record["results"]["tangential_force"]}
    thrust = forces_3d(pair, 90.0, hand, rotation)["gear_a_axial_force"]
    way = "away from the apex" if thrust > 0 else "toward the apex"
    told = [w for w in record["warnings"] if w.startswith("pinion_bearing_1 locates")]
    assert len(told) == 1 and way in told[0], told
    (deep,) = solve_json(cli, spec_file(plain, "deep.yaml"))
    assert not any("locates" in w for w in deep["warnings"]), deep["warnings"]


@pytest.mark.parametrize(("extra", "field"), [
    ("spiral_angle: 35 deg\nhand: right\n", "rotation"),
    ("hand: right\n", "hand"),
    ("spiral_angle: 60 deg\nhand: right\nrotation: clockwise\n", "spiral_angle"),
])
def test_bad_spiral_input_is_one_line(cli, spec_file, extra, field):
    text = PAIR.format(sigma=90, hand="x", rotation="x").split("spiral_angle")[0] + extra
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1 and f": {field}: " in run.err, run.err


def test_a_spiral_rating_needs_the_cutter_radius(cli, spec_file):
    text = (ROOT / "specs" / "bevel-gears-sizing.yaml").read_text() + (
        "spiral_angle: 35 deg\nhand: right\nrotation: clockwise\n")
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1, run.err
    assert ": rating.cutter_radius: " in run.err, run.err


@pytest.mark.parametrize("sigma", [90.0, 70.0])
def test_the_normal_section_is_the_virtual_helical_gears(cli, spec_file, sigma):
    """The normal-section spur gear whose flank has the curvature of the virtual helical
    gear's involute helicoid at the pitch point, reached through the transverse section:
    α_t = atan(tan φn/cos β), tan β_b = tan β·cos α_t, the transverse flank radius
    ρ_t = r_v·sin α_t, the normal one ρ_n = ρ_t/cos β_b, and z_vn = 2ρ_n/(m_mn·sin φn)."""
    (record,) = solve_json(cli, spec_file(PAIR.format(sigma=sigma, hand="left",
                                                      rotation="clockwise")))
    results = record["results"]
    beta, phi_n = math.radians(35.0), math.radians(20.0)
    normal_module = results["mean_module"] * math.cos(beta)
    assert results["mean_normal_module"] == pytest.approx(normal_module, rel=1e-12)
    alpha_t = math.atan(math.tan(phi_n) / math.cos(beta))
    base_helix = math.atan(math.tan(beta) * math.cos(alpha_t))
    for gear in ("gear_a", "gear_b"):
        virtual_radius = results[f"{gear}_virtual_teeth"] * results["mean_module"] / 2
        normal_flank = virtual_radius * math.sin(alpha_t) / math.cos(base_helix)
        expected = 2 * normal_flank / (normal_module * math.sin(phi_n))
        assert results[f"{gear}_normal_virtual_teeth"] == pytest.approx(expected, rel=1e-12)


def test_a_straight_pair_has_no_normal_section(cli, spec_file):
    straight = PAIR.format(sigma=90, hand="right", rotation="clockwise").replace(
        "spiral_angle: 35 deg\nhand: right\nrotation: clockwise\n", "")
    (record,) = solve_json(cli, spec_file(straight))
    assert "mean_normal_module" not in record["results"]
    assert "gear_a_normal_virtual_teeth" not in record["results"]


def test_a_spiral_angle_without_sizing_is_refused(cli, spec_file):
    """The kinematics do not depend on the spiral: a spiral_angle on a pair that is not
    sized would be silently ignored, so it is refused naming face_width."""
    text = PAIR.format(sigma=90, hand="left", rotation="clockwise").replace(
        "face_width: 15 mm\n", "").replace("torque: 10 N*m\n", "")
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1 and ": face_width: " in run.err, run.err


def test_a_spiral_pair_without_a_rating_takes_no_duty_cycle(cli, spec_file):
    text = PAIR.format(sigma=90, hand="left", rotation="clockwise") + (
        "duty_cycle:\n  - {time: 100 %}\n")
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1, run.err
    assert ": duty_cycle: " in run.err and "rating too" in run.err, run.err
