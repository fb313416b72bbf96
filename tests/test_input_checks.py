"""Input that is valid field by field but contradictory, implausible or outside the
theory: refused with the field at fault, never solved into a silently wrong number."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from bearingcalc.core import ball_bearing, bevel_drive, iso281
from bearingcalc.evaluation import load_one_spec
from bearingcalc.kinds import KINDS, OUT_OF_RANGE
from tests.conftest import ROOT, WARNINGS_AS_ERRORS, solve_json

CATALOGUE = """kind: ball-bearing
dynamic_load_rating: 55.3 kN
static_load_rating: 31.5 kN
radial_load: 10 kN
speed: 3000 rpm
"""
GEOMETRY = """kind: ball-bearing
ball_count: 9
ball_diameter: 7.938 mm
inner_groove_conformity: 0.52
outer_groove_conformity: 0.53
radial_load: 1.5 kN
speed: 1450 rpm
"""


def _one_line(run):
    assert run.code == 2, run.out
    assert run.out == ""
    lines = run.err.splitlines()
    assert len(lines) == 1, run.err
    return lines[0]


# --- contradictory ring geometry ----------------------------------------------------------

@pytest.mark.parametrize("pitch", ["150 mm", "45 mm", "30 mm", "100 mm"])
def test_a_pitch_circle_outside_the_rings_names_both_ring_fields(cli, spec_file, pitch):
    path = spec_file(CATALOGUE + f"pitch_diameter: {pitch}\nbore_diameter: 45 mm\n"
                     "outside_diameter: 100 mm\n")
    line = _one_line(cli("solve", path))
    assert line.startswith(f"{path}:6: pitch_diameter: {pitch} is outside the rings")
    assert "bore_diameter (45 mm)" in line and "outside_diameter (100 mm)" in line


def test_a_pitch_circle_off_the_rings_mean_is_warned_within_five_percent_not(cli, spec_file):
    rings = "bore_diameter: 45 mm\noutside_diameter: 100 mm\n"   # mean 72.5 mm
    near = solve_json(cli, spec_file(CATALOGUE + rings + "pitch_diameter: 76 mm\n"))[0]
    far = solve_json(cli, spec_file(CATALOGUE + rings + "pitch_diameter: 76.2 mm\n"))[0]
    assert not any("rings' mean" in w for w in near["warnings"])
    assert any("76.2 mm is more than 5% from the rings' mean" in w for w in far["warnings"])


@pytest.mark.parametrize(("ball", "refused"), [("13.4 mm", False), ("13.5 mm", True),
                                               ("14 mm", True)])
def test_a_ball_must_be_smaller_than_the_ring_section(cli, spec_file, ball, refused):
    text = GEOMETRY.replace("7.938 mm", ball).replace("ball_count: 9", "ball_count: 5")
    run = cli("solve", spec_file(text + "bore_diameter: 25 mm\noutside_diameter: 52 mm\n"),
              "-f", "json")
    if refused:
        assert "ball_diameter" in _one_line(run) and "(outside_diameter − bore_diameter)/2 " \
            "= 13.5 mm" in run.err
    else:
        assert run.code == 0, run.err


def test_bore_and_outside_diameter_stand_in_for_the_pitch_diameter(cli, spec_file):
    """Geometry mode from d and D gives exactly the results of Dpw = (d + D)/2."""
    by_rings = solve_json(cli, spec_file(
        GEOMETRY + "bore_diameter: 25 mm\noutside_diameter: 52 mm\n", "rings.yaml"))[0]
    by_pitch = solve_json(cli, spec_file(
        GEOMETRY + "pitch_diameter: 38.5 mm\nbore_diameter: 25 mm\noutside_diameter: 52 mm\n",
        "pitch.yaml"))[0]
    assert by_rings["results"] == by_pitch["results"]
    assert by_rings["results"]["dynamic_load_rating_iso"] > 0
    assert any("(d + D)/2 = 38.5 mm" in w for w in by_rings["warnings"])


# --- implausible magnitudes and the limits of Hertz theory --------------------------------

@pytest.mark.parametrize(("written", "hint"), [("207.5 MPa", "did you mean 207.5 GPa?"),
                                               ("210000 kPa", "did you mean 210000 MPa?"),
                                               ("207500 GPa", "did you mean 207500 MPa?")])
def test_a_modulus_outside_1_to_1000_gpa_is_refused_with_a_hint(cli, spec_file, written, hint):
    path = spec_file(GEOMETRY + "pitch_diameter: 38.5 mm\n"
                     f"material: {{elastic_modulus: {written}}}\n")
    line = _one_line(cli("solve", path))
    assert line.startswith(f"{path}:9: material.elastic_modulus: {written} is outside")
    assert "1 GPa to 1000 GPa" in line
    assert line.endswith(hint)


@pytest.mark.parametrize(("field", "written", "fragment"), [
    ("radial_load", "2e9 N", "did you mean 2e9 N"),   # no unit of force brings it in
    ("radial_load", "2e9 kN", "1 µN to 10⁶ kN"),
    ("speed", "2e6 rpm", "up to 10⁶ rpm"),
    ("pitch_diameter", "500 m", "did you mean 500 mm?"),
    ("pitch_diameter", "0.5 um", "did you mean 0.5 mm?"),
])
def test_magnitudes_no_machine_element_has_are_refused(cli, spec_file, field, written, fragment):
    text = CATALOGUE.replace("radial_load: 10 kN", f"radial_load: {written}"
                             if field == "radial_load" else "radial_load: 10 kN")
    text = text.replace("speed: 3000 rpm", f"speed: {written}" if field == "speed"
                        else "speed: 3000 rpm")
    if field == "pitch_diameter":
        text += f"pitch_diameter: {written}\n"
    line = _one_line(cli("solve", spec_file(text)))
    assert f"{field}: {written} is outside the range of real machine elements" in line
    if fragment.startswith("did you mean 2e9 N"):
        assert "did you mean" not in line
    else:
        assert fragment in line


def test_the_edges_of_the_plausible_ranges_are_accepted(cli, spec_file):
    text = CATALOGUE.replace("radial_load: 10 kN", "radial_load: 1e6 kN").replace(
        "dynamic_load_rating: 55.3 kN", "dynamic_load_rating: 1e9 N")
    run = cli("solve", spec_file(text))
    # Accepted: it fails its static safety (1e6 kN on C0 = 31.5 kN), it is not refused.
    assert run.code == 1, run.err


def test_a_contact_ellipse_wider_than_the_ball_is_refused_naming_the_load(cli, spec_file):
    base = GEOMETRY + "pitch_diameter: 38.5 mm\n"
    accepted = solve_json(cli, spec_file(base, "ok.yaml"))[0]["results"]
    half_ball = 7.938e-3 / 2
    assert max(accepted["inner_contact_semi_major"],
               accepted["outer_contact_semi_major"]) < half_ball
    path = spec_file(base.replace("radial_load: 1.5 kN", "radial_load: 900 kN"))
    line = _one_line(cli("solve", path))
    assert line.startswith(f"{path}:6: radial_load: the most heavily loaded ball's contact "
                           "ellipse is not small against the ball")


def test_the_contact_status_is_where_hertz_gives_a_semi_major_axis_above_dw_over_2():
    """The solver's status flips where its own semi-major axis crosses Dw/2."""
    kind = KINDS["ball-bearing"]
    from bearingcalc.evaluation import load_one_spec

    _, spec, _ = load_one_spec(ROOT / "specs" / "ball-bearing-geometry.yaml")
    inputs = dict(spec.solver_inputs())
    inputs["radial_load"] = np.geomspace(1e3, 1e7, 400)
    inputs["axial_load"] = 0.0
    solution = kind.solver.evaluate(inputs, None)
    results, status = solution.results, solution.status
    widest = np.maximum(results["inner_contact_semi_major"],
                        results["outer_contact_semi_major"])
    too_wide = widest > 7.938e-3 / 2
    assert too_wide.any() and not too_wide.all()
    np.testing.assert_array_equal(status == 14, too_wide)


# --- each cause of a non-finite design has its own status ---------------------------------

def test_a_frozen_oil_has_its_own_status_in_the_solver():
    kind = KINDS["ball-bearing"]
    from bearingcalc.evaluation import load_one_spec

    _, spec, _ = load_one_spec(ROOT / "specs" / "ball-bearing.yaml")
    inputs = dict(spec.solver_inputs(), viscosity=None, viscosity_40=68e-6,
                  viscosity_100=8.7e-6, temperature=np.array([123.15, 313.15]))
    _, status = kind.evaluate(inputs)
    assert status.tolist() == [13, 0]
    assert kind.status_reasons[13][0] == "lubrication.temperature"


def test_walther_temperature_inverts_walther_viscosity():
    t = np.linspace(250.0, 420.0, 50)
    nu = iso281.walther_viscosity(68e-6, 8.7e-6, t)
    np.testing.assert_allclose(iso281.walther_temperature(68e-6, 8.7e-6, nu), t,
                               rtol=1e-12)


def test_zero_load_factors_have_their_own_status_in_the_solver():
    kind = KINDS["ball-bearing"]
    from bearingcalc.evaluation import load_one_spec

    _, spec, _ = load_one_spec(ROOT / "specs" / "ball-bearing.yaml")
    inputs = dict(spec.solver_inputs(), load_x=0.0, load_y=np.array([0.0, 1.2]), load_e=0.0,
                  axial_load=1e3)
    _, status = kind.evaluate(inputs)
    assert status.tolist() == [12, 0]


def test_a_sweep_through_coinciding_bearings_names_the_position(cli):
    run = cli("sweep", ROOT / "specs" / "bevel-drive.yaml", "--vary",
              "pinion_bearings.2.position=50mm:130mm:5", "-f", "json")
    assert run.code == 0, run.err
    rows = [json.loads(line) for line in run.out.splitlines()]
    gaps = [row for row in rows if row["reason"] is not None]
    assert len(gaps) == 1, rows
    assert "pinion_bearings.2.position: two bearings at the same position" in json.dumps(gaps)
    assert bevel_drive.STATUS_REASONS[bevel_drive.COINCIDING_BEARINGS["gear"]][0] == \
        "gear_bearings.2.position"


def test_drive_bearing_status_codes_never_overlap():
    """Every bearing's every failure has a code of its own in the solve's reasons, apart
    from the drive's own codes and the last guard, naming the bearing's field (or the
    drive's own field that sets it)."""
    drive = KINDS["bevel-drive"]
    spec = load_one_spec(ROOT / "specs" / "bevel-drive.yaml")[1]
    results, _ = drive.evaluate(spec.solver_inputs())
    reasons = results.reasons
    own = set(drive.status_reasons)
    assert own == set(bevel_drive.STATUS_REASONS) | {OUT_OF_RANGE}
    of_members = set(reasons) - own
    per_bearing = len(bevel_drive.BEARINGS.solver.status_reasons)
    assert len(of_members) == 4 * per_bearing  # two shafts of two bearings
    assert min(of_members) > max(own)
    assert ("gear_bearings.2.ball_diameter", ball_bearing.STATUS_REASONS[1][1]) in \
        reasons.values()
    fields = {field for field, _ in reasons.values()}
    assert {"input_speed", "lubrication.temperature", "gear_bearings.1.roller_diameter",
            "pinion_bearings.1.ball_diameter"} <= fields


def test_a_failing_bearing_is_named_by_its_own_reason():
    """A bearing the rolling-bearing solver refuses fails the drive with that bearing's
    reason: the code of the solve maps back to the bearing's field."""
    drive = KINDS["bevel-drive"]
    spec = load_one_spec(ROOT / "specs" / "bevel-drive.yaml")[1]
    inputs = spec.solver_inputs()
    bearing = inputs["shafts"]["gear"][1]
    bearing["viscosity"] = np.array([bearing["viscosity"], 1e-9])  # κ far below 0.1
    results, status = drive.evaluate(inputs)
    assert status[0] == 0
    field, why = results.reasons[int(status[1])]
    # the drive's lubrication sets the bearing's: the reason names it, and the bearing
    assert field == "lubrication"
    assert why == f"at gear_bearings.2, {ball_bearing.STATUS_REASONS[5][1]}"


# --- a tolerance box crossing a validity edge ---------------------------------------------

@pytest.mark.parametrize("method", ["worst-case", "rss", "monte-carlo", "rss,monte-carlo"])
def test_a_box_reaching_past_45_deg_never_passes(tmp_path, method):
    text = (ROOT / "specs" / "tolerances" / "thrust-bearing.yaml").read_text()
    text = text.replace("contact_angle: 30 deg ± 0.25 deg", "contact_angle: 44.2 deg ± 1 deg")
    text = text.replace("max_spin_to_roll: 0.01", "max_spin_to_roll: 0.5")
    spec = tmp_path / "tb.yaml"
    spec.write_text(text)
    run = subprocess.run([sys.executable, *WARNINGS_AS_ERRORS, "-m", "bearingcalc", "tolerance",
                          str(spec), "-m", method, "-n", "4096", "-f", "json"],
                         capture_output=True, text=True, timeout=120, check=False)
    assert run.returncode == 1, run.stderr
    assert run.stderr == ""
    record = json.loads(run.stdout)
    assert "contact_angle" in record["impossible_in_box"]["reason"]
    assert math.isclose(record["impossible_in_box"]["inputs"]["contact_angle"],
                        math.radians(45.2), rel_tol=1e-12) or \
        record["impossible_in_box"]["inputs"]["contact_angle"] > math.pi / 4


# --- every problem in one run -------------------------------------------------------------

def test_field_errors_and_rule_problems_come_together_in_line_order(cli, spec_file):
    text = ("kind: ball-bearing\n"                  # 1
            "dynamic_load_rating: 55.3 kN\n"       # 2
            "radial_load: 10 kNx\n"                # 3
            "axial_load: 2 kN\n"                   # 4: needs f0 and C0
            "speed: 3000 rpmm\n"                   # 5
            "reliability: 120 %\n"                 # 6
            "pitch_diameter: 72.5 mm\n"            # 7
            "lubrication:\n"                       # 8: needs contamination_factor
            "  viscosity: 20 mm^2/s\n")
    path = spec_file(text)
    run = cli("solve", path)
    assert run.code == 2
    assert [line.split(": ")[0:2] for line in run.err.splitlines()] == [
        [f"{path}:3", "radial_load"], [f"{path}:4", "static_load_rating"],
        [f"{path}:5", "speed"], [f"{path}:6", "reliability"],
        [f"{path}:8", "contamination_factor"], [f"{path}:8", "fatigue_load_limit"]]


def test_a_rule_reading_an_invalid_field_stays_silent(cli, spec_file):
    """With the loads unreadable, 'both loads are zero' would be a false alarm."""
    text = CATALOGUE.replace("radial_load: 10 kN", "radial_load: ten kN")
    run = cli("solve", spec_file(text))
    assert run.code == 2
    assert len(run.err.splitlines()) == 1 and "both loads are zero" not in run.err


# --- wording ------------------------------------------------------------------------------

def test_a_design_with_no_margins_names_the_limits_it_could_set(cli, spec_file):
    text = ("kind: ball-bearing\ntype: thrust\ndynamic_load_rating: 55.3 kN\n"
            "axial_load: 1 kN\nspeed: 3000 rpm\n")
    run = cli("solve", spec_file(text))
    assert run.code == 0
    assert "limits.min_rating_life" in run.out and "no limits apply" not in run.out
    assert "PASS: this kind has no limits" in cli("solve", ROOT / "specs" /
                                                  "cone-on-plane.yaml").out


@pytest.mark.parametrize("command", [("new", "ball-bearings"), ("schema", "--kind", "bevel-gear")])
def test_a_mistyped_kind_gets_a_suggestion(cli, command):
    run = cli(*command)
    assert run.code == 2
    assert "(did you mean '" in run.err and run.err.count("\n") == 1
