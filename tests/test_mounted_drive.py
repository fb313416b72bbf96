"""A bevel drive as mounted (``method: iso-16281``): its shafts rigid on their bearings'
contacts. Checked against what does not share its code: the drive's statics
(``method: iso-281``), which the shafts tend to as the bearings' span grows large
against their size, the difference falling as 1/span (a bearing's tilt stiffness grows
with its radial stiffness, so stiff bearings alone would not do it); each shaft's
stiffness at the mesh against central differences of its solved displacement; the
mesh displacements against two lines moved in three dimensions by exact rotations,
their offset by the common normal and their angle by the arccosine; and every bad
input of the method one line."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bearingcalc.core.mounted_drive import mesh_displacements, shaft_results
from bearingcalc.core.mounted_shaft import MountedShaft, solve_mounted_shaft
from bearingcalc.evaluation import load_one_spec
from tests.conftest import solve_json
from tests.mounted_specs import refused_lines, solved_with_limits

#: The straight bevel pair of DRIVE and ADJUSTED: the start of a spec for ``str.format``
#: (``{method}``; literal braces doubled).
GEARS = """kind: bevel-drive
method: {method}
gear_a: {{teeth: 20}}
gear_b: {{teeth: 43}}
module: 3 mm
shaft_angle: 90 deg
face_width: 20 mm
pressure_angle: 20 deg
input_speed: 1500 rpm
torque: 60 N*m
rating: {{quality_number: 8, hardness: 300 HB, mounting: one-straddle,
         geometry_factor_bending: 0.23, geometry_factor_pitting: 0.08}}
"""
DRIVE = GEARS + """\
pinion_bearings:
  - {{position: {first} mm, locating: true, type: deep-groove, ball_count: 9,
     ball_diameter: 7.938 mm, pitch_diameter: 38.5 mm, inner_groove_conformity: 0.52,
     outer_groove_conformity: 0.53, dynamic_load_rating: 14.8 kN,
     static_load_rating: 7.8 kN{clearance}}}
  - {{position: {second} mm, type: cylindrical-roller, roller_count: 13,
     roller_diameter: 7.5 mm, roller_length: 10 mm, pitch_diameter: 46 mm,
     dynamic_load_rating: 44 kN, static_load_rating: 36.5 kN{clearance}}}
{extra}
"""


def _radial_loads(cli, spec_file, method, scale, extra=""):
    """The pinion bearings' radial loads with the bearings 30 and 70 mm past the mean
    pitch point, times ``scale``."""
    mesh = 56.3
    text = DRIVE.format(method=method, first=mesh + 30 * scale, second=mesh + 70 * scale,
                        clearance=", operating_clearance: 0 µm" if method == "iso-16281"
                        else "", extra=extra)
    [record] = solve_json(cli, spec_file(text))
    results = record["results"]
    return np.array([results["pinion_bearing_1_radial_load"],
                     results["pinion_bearing_2_radial_load"]])


def test_the_shafts_tend_to_the_statics_as_one_over_the_span(cli, spec_file):
    differences = []
    for scale in (1, 2, 4, 8, 16):
        statics = _radial_loads(cli, spec_file, "iso-281", scale)
        mounted = _radial_loads(cli, spec_file, "iso-16281", scale)
        differences.append(np.max(np.abs(mounted / statics - 1.0)))
    ratios = np.array(differences[:-1]) / np.array(differences[1:])
    assert np.all((ratios > 1.8) & (ratios < 2.4)), ratios
    assert differences[-1] < 6e-3


def _pinion_shaft(spec_file, text):
    """The example drive's pinion shaft as the solver takes it, and its pair."""
    from bearingcalc.core import bevel_gears

    _, spec, _ = load_one_spec(spec_file(text))
    inputs = spec.solver_inputs()
    pair = bevel_gears.evaluate(inputs)
    speed = float(inputs["input_speed"])
    bearings = [{**bearing, "inner_speed": speed, "outer_speed": 0.0, "speed": speed}
                for bearing in inputs["shafts"]["pinion"]]
    return inputs, pair, bearings


def test_a_shafts_stiffness_at_the_mesh_is_its_displacements_slope(spec_file):
    """k = F/δ of a small force added at the mean pitch point along the axis and along
    the radial force, by central differences of the solved displacement of that
    point."""
    text = DRIVE.format(method="iso-16281", first=86.3, second=126.3,
                        clearance=", operating_clearance: 0 µm", extra="")
    _, pair, bearings = _pinion_shaft(spec_file, text)
    from bearingcalc.core.mounted_shaft import gear_load
    from bearingcalc.core.shaft_statics import mean_pitch_point

    def flat(value):
        return np.broadcast_to(np.asarray(value, dtype=float), (1,)).reshape(-1)

    mesh = mean_pitch_point(pair.results["mean_cone_distance"],
                            pair.results["gear_a_pitch_angle"])
    x_p, r_p = (float(np.asarray(v)) for v in mesh)
    load = gear_load(pair.results, "a", mesh)
    solved = solve_mounted_shaft(bearings, "locating-floating", {}, load, flat)
    stiffness = shaft_results("pinion", solved, mesh, ())
    for name, direction in (("axial", np.array([1.0, 0.0, 0.0])),
                            ("radial", np.array([0.0, -1.0, 0.0]))):
        step = 2.0
        # a unit force d at P = (x_p, r_p, 0) and its moment r × d about the apex:
        # (My, −Mz) = (−x_p·d_z, r_p·d_x − x_p·d_y)
        extra = np.array([direction[0], direction[1], direction[2],
                          -x_p * direction[2], r_p * direction[0] - x_p * direction[1]])
        moved = []
        for sign in (1.0, -1.0):
            q = solve_mounted_shaft(bearings, "locating-floating", {},
                                    load + sign * step * extra, flat).loaded.displacement[0]
            point = np.array([q[0] + q[4] * r_p, q[1] - q[4] * x_p, q[2] - q[3] * x_p])
            moved.append(point @ direction)
        slope = 2 * step / (moved[0] - moved[1])
        assert float(stiffness[f"pinion_stiffness_{name}"]) == pytest.approx(slope, rel=1e-4)


def _moved_lines(a, p, b, g):
    """Two lines (point p, direction a) and (g, b): the offset along n = a×b/|a×b| from
    the first to the second between their closest points, their angle by the arccosine,
    and how far each line's own point lies from its closest point along its direction
    (the shifts P, G, positive away from where they cross)."""
    normal = np.cross(a, b)
    normal /= np.linalg.norm(normal)
    # g − p = s·a − t·b + E·n, with s, t the closest points' places along each line
    s, t, offset = np.linalg.solve(np.stack([a, -b, normal], axis=1), g - p)
    angle = math.acos(np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b)))
    return offset, angle, -s * np.linalg.norm(a), -t * np.linalg.norm(b)


@pytest.mark.parametrize("sigma", [math.radians(90), math.radians(70)])
def test_the_mesh_displacements_are_two_lines_moved(sigma):
    """Each shaft moved by a small translation at the apex and a small rotation
    (θy about its y, −θz about its z, 10⁻⁷ of the sizes): E, P, G and Σ against the
    moved lines, their closest points and each shaft's apex from where they cross, to
    the second-order terms the first-order definitions leave out."""
    delta = math.radians(25)
    rng = np.random.default_rng(3)
    change = {shaft: rng.uniform(-1, 1, 5) * np.array([1e-7, 1e-7, 1e-7, 1e-6, 1e-6])
              for shaft in ("pinion", "gear")}

    class Moved:
        def __init__(self, q):
            self.loaded = type("E", (), {"displacement": q[None, :]})()
            self.rest = np.zeros((1, 5))

    shafts = {shaft: Moved(q) for shaft, q in change.items()}
    pair = {"shaft_angle": np.array(sigma), "gear_a_pitch_angle": np.array(delta)}
    mine = mesh_displacements(pair, shafts, ())
    b = np.array([math.cos(sigma), math.sin(sigma), 0.0])
    point = np.array([math.cos(delta), math.sin(delta), 0.0])
    radial = point - point.dot(b) * b
    radial /= np.linalg.norm(radial)
    frames = {"pinion": np.eye(3), "gear": np.stack([b, radial, np.cross(b, radial)], 1)}
    lines = {}
    for shaft, frame in frames.items():
        q = change[shaft]
        spin = Rotation.from_rotvec(frame @ np.array([0.0, q[3], -q[4]]))
        lines[shaft] = (spin.apply(frame[:, 0]), frame @ q[:3])
    offset, angle, pinion, gear = _moved_lines(*lines["pinion"], *lines["gear"])
    assert float(mine["mesh_offset_change"]) == pytest.approx(offset, rel=1e-4, abs=1e-13)
    assert float(mine["shaft_angle_change"]) == pytest.approx(angle - sigma, rel=1e-4,
                                                              abs=1e-12)
    assert float(mine["pinion_axial_shift"]) == pytest.approx(pinion, rel=1e-4, abs=1e-13)
    assert float(mine["gear_axial_shift"]) == pytest.approx(gear, rel=1e-4, abs=1e-13)


ADJUSTED = GEARS + """\
pinion_arrangement: {arrangement}
{setting}
pinion_bearings:
  - {{position: 85 mm, type: tapered-roller, dynamic_load_rating: 32.5 kN{locating},
     static_load_rating: 32.5 kN, contact_angle: 14 deg, load_factors: {{e: 0.37, y: 1.6,
     y0: 0.9}}, bore_diameter: 25 mm, outside_diameter: 52 mm, width: 16.25 mm}}
  - {{position: 150 mm, type: {second}, dynamic_load_rating: 32.5 kN,
     static_load_rating: 32.5 kN, contact_angle: 14 deg, load_factors: {{e: 0.37, y: 1.6,
     y0: 0.9}}, bore_diameter: 25 mm, outside_diameter: 52 mm, width: 16.25 mm}}
{extra}
"""


def _adjusted(method="iso-16281", arrangement="back-to-back",
              setting="pinion_setting: {preload: 800 N}", locating="",
              second="tapered-roller", extra=""):
    return ADJUSTED.format(method=method, arrangement=arrangement, setting=setting,
                           locating=locating, second=second, extra=extra)


def test_an_adjusted_pinion_carries_its_preload_at_rest(cli, spec_file):
    [record] = solve_json(cli, spec_file(_adjusted()))
    results = record["results"]
    assert results["pinion_preload_force"] == pytest.approx(800.0, rel=1e-6)
    axial = results["pinion_bearing_1_axial_load"] - results["pinion_bearing_2_axial_load"]
    assert abs(axial) == pytest.approx(abs(results["gear_a_axial_force"]), rel=1e-6)


@pytest.mark.parametrize(("text", "field"), [
    (_adjusted(method="iso-281"), "pinion_setting"),
    (_adjusted(setting=""), "pinion_setting"),
    (_adjusted(arrangement="locating-floating", locating=", locating: true"),
     "pinion_setting"),
    (_adjusted(setting="pinion_setting: {preload: -1 kN}"), "pinion_setting.preload"),
    (_adjusted(setting="pinion_setting: {end_play: 10 µm, preload: 1 kN}"),
     "pinion_setting.preload"),
    (_adjusted(extra="gear_setting: {preload: 1 kN}"), "gear_setting"),
])
def test_bad_input_of_a_drive_as_mounted_is_one_line(cli, spec_file, text, field):
    run = cli("solve", spec_file(text))
    assert run.code == 2, run.out
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in run.err, run.err
    assert f": {field}: " in lines[0], lines[0]


def test_a_cylindrical_bearing_cannot_locate_a_shaft_as_mounted(cli, spec_file):
    text = DRIVE.format(method="iso-16281", first=86.3, second=126.3,
                        clearance=", operating_clearance: 0 µm", extra="")
    text = text.replace("locating: true, type: deep-groove", "type: deep-groove").replace(
        "type: cylindrical-roller", "locating: true, type: cylindrical-roller")
    run = cli("solve", spec_file(text))
    assert run.code == 2
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and ".locating: " in lines[0], run.err


def test_the_drive_example_runs_every_command(cli, tmp_path):
    """specs/bevel-drive-mounted.yaml through solve, a sweep of the pinion's preload
    and the report."""
    example = "specs/bevel-drive-mounted.yaml"
    run = cli("sweep", example, "--vary", "pinion_setting.preload=0.5kN:2kN:3",
              "--format", "json")
    assert run.code == 0, run.err
    rows = [json.loads(line) for line in run.out.splitlines() if line.strip()]
    stiffness = [row["results"]["pinion_stiffness_axial"] for row in rows]
    assert stiffness == sorted(stiffness)
    report = tmp_path / "drive.html"
    assert cli("report", example, "--output", report).code == 0
    assert "mesh_offset_change" in report.read_text(encoding="utf-8")


def test_the_unset_shaft_rests_at_its_datum(spec_file):
    """A shaft with play rests where its displacements count from: Q = 0."""
    shaft = MountedShaft(None, np.zeros((1, 5)), [], [], np.zeros(1))
    assert not shaft.rest.any()


@pytest.mark.parametrize("vary", ["torque=100N*m:200N*m:3",
                                  "gear_bearings.2.outside_diameter=70mm:74mm:3"])
def test_a_drive_as_mounted_sweeps_its_loads_and_its_estimated_bearings(cli, vary):
    """A sweep of the pair's load alone, or of an estimated bearing's catalogue data (the
    estimate is made once, from the nominal data), solves every point."""
    run = cli("sweep", "specs/bevel-drive-mounted.yaml", "--vary", vary, "--format", "json")
    assert run.code == 0, run.err
    rows = [json.loads(line) for line in run.out.splitlines() if line.strip()]
    assert len(rows) == 3 and all(np.isfinite(row["results"]["pinion_axial_shift"])
                                  for row in rows)


LOCATED_BY_ONE_TAPERED = """kind: bevel-drive
name: spiral bevel drive, as mounted
method: iso-16281
gear_a: {teeth: 14}
gear_b: {teeth: 39}
module: 4.5 mm
shaft_angle: 90 deg
face_width: 25 mm
pressure_angle: 20 deg
spiral_angle: 0 deg
rotation: counterclockwise
input_speed: 1750 rpm
torque: 160 N*m
rating:
  quality_number: 11
  material: carburized
  grade: 1
  mounting: one-straddle
  crowned: true
  cutter_radius: 4.5 in
  geometry_factor_bending: 0.222
  geometry_factor_bending_gear: 0.217
  geometry_factor_pitting: 0.109
pinion_bearings:
  - {position: 80 mm, locating: true, type: tapered-roller, dynamic_load_rating: 54 kN,
     static_load_rating: 63 kN, contact_angle: 14 deg, load_factors: {e: 0.37, y: 1.6, y0: 0.9},
     bore_diameter: 30 mm, outside_diameter: 62 mm, width: 17.25 mm}
  - {position: 150 mm, type: deep-groove, dynamic_load_rating: 20.3 kN,
     static_load_rating: 11.2 kN, bore_diameter: 30 mm, outside_diameter: 62 mm,
     width: 16 mm, operating_clearance: 10 µm}
gear_bearings:
  - {position: 20 mm, type: cylindrical-roller, dynamic_load_rating: 62 kN,
     static_load_rating: 56 kN, bore_diameter: 35 mm, outside_diameter: 72 mm, width: 17 mm,
     operating_clearance: 15 µm}
  - {position: 140 mm, locating: true, type: deep-groove, dynamic_load_rating: 27 kN,
     static_load_rating: 15.3 kN, bore_diameter: 35 mm, outside_diameter: 72 mm, width: 17 mm,
     operating_clearance: 10 µm}
reliability: 90 %
lubrication: {viscosity: 68 mm^2/s}
contamination_factor: 0.5
limits:
  min_rating_life: 5000 h
  min_static_safety: 1.0
  min_bending_safety: 1.0
  min_contact_safety: 1.0
"""


def test_a_shaft_beyond_small_displacements_is_refused(cli, spec_file):
    """A spiral drive's pinion located by one tapered bearing (its thrust one way) and
    floating on a deep-groove one: the shaft tilts far beyond the rings' small
    displacements, and is refused in one line, not reported as millimetres at the
    mesh."""
    run = cli("solve", spec_file(LOCATED_BY_ONE_TAPERED))
    assert run.code == 2, run.out
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and ": pinion_bearings: " in lines[0], run.err


def test_the_mesh_limits_judge_the_drive_as_mounted(cli, spec_file):
    """limits.max_pinion_axial_shift and friends: margins 1 − |x|/limit in the verdict;
    refused in one line under the catalogue method."""
    limited, record = solved_with_limits(
        cli, spec_file, "bevel-drive-mounted.yaml", "  min_static_safety: 1.0",
        ("max_pinion_axial_shift: 40 µm", "max_shaft_angle_change: 0.01 deg"))
    results = record["results"]
    assert results["pinion_axial_shift_margin"] == pytest.approx(
        1.0 - abs(results["pinion_axial_shift"]) / 40e-6, rel=1e-12)
    assert results["shaft_angle_change_margin"] == pytest.approx(
        1.0 - abs(results["shaft_angle_change"]) / math.radians(0.01), rel=1e-12)
    assert [v["key"] for v in record["verdicts"] if not v["passed"]] == [
        "pinion_axial_shift_margin"]
    catalogue = limited.replace("method: iso-16281\n", "").replace(
        "pinion_setting: {preload: 1 kN}    # each bearing's axial load at rest\n", "")
    lines = refused_lines(cli, spec_file, catalogue)
    assert any(": limits.max_pinion_axial_shift: " in line for line in lines), lines
