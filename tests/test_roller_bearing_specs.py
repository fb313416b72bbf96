"""Whole roller-bearing specs (kind: rolling-bearing) through the command line: the
contact of ISO 76's static rating against a Hertz line contact written here, the inputs
the kind refuses, and ball-bearing as its other name."""

from __future__ import annotations

import json
import math

import pytest

from bearingcalc.core import roller_bearing_contacts as rbc
from tests.conftest import ROOT, solve_json
from tests.test_roller_bearing import DEG, REL, results_of

# --- 4. the ISO 76 basis: 4000 MPa at C0 -------------------------------------------------------

def hertz_line(load, length, radius, modulus, poisson):
    """Hertz line contact of two bodies of one material (Johnson, Contact Mechanics, 1985,
    §4.2): E* = E/(2(1 − ν²)), p0 = sqrt(Q·E*/(π·L·R)), b = sqrt(4·Q·R/(π·L·E*))."""
    e_star = 1.0 / (2 * (1 - poisson ** 2) / modulus)
    return (math.sqrt(load * e_star / (math.pi * length * radius)),
            math.sqrt(4 * load * radius / (math.pi * length * e_star)))


@pytest.mark.parametrize(("kind", "z", "dwe", "lwe", "dpw", "alpha"),
                         [("cylindrical-roller", 13, 9.0, 9.0, 46.0, 0.0),
                          ("cylindrical-roller", 16, 16.0, 16.0, 130.0, 0.0),
                          ("tapered-roller", 17, 7.5, 12.0, 46.0, 14.0),
                          ("tapered-roller", 21, 11.0, 18.0, 90.0, 25.0)])
def test_c0_loads_the_inner_race_to_4000_mpa(cli, spec_file, kind, z, dwe, lwe, dpw, alpha):
    """ISO 76:2006: C0 of a radial roller bearing is the load giving 4000 MPa at the
    centre of the most heavily loaded contact. Stribeck's Q = 5·P0/(i·Z·cosα) on the
    inner race, R = Dwe(1 − γ)/2, E = 208 GPa, ν = 0.3: the solver, loaded with Fr = C0
    (C0 by the formula written here), must give that pressure within 1 % and Hertz's line
    contact as written here to 1e-9."""
    cos_a = math.cos(alpha * DEG)
    gamma = dwe * cos_a / dpw
    c0 = 44 * (1 - gamma) * z * lwe * dwe * cos_a
    text = (f"kind: rolling-bearing\ntype: {kind}\nroller_count: {z}\n"
            f"roller_diameter: {dwe} mm\nroller_length: {lwe} mm\npitch_diameter: {dpw} mm\n"
            f"contact_angle: {alpha} deg\nradial_load: {c0!r} N\nspeed: 1000 rpm\n"
            "material: {elastic_modulus: 208 GPa, poisson_ratio: 0.3}\n")
    results = results_of(cli, spec_file, text)
    q = 5 * c0 / (z * cos_a)
    inner = hertz_line(q, lwe * 1e-3, dwe * 1e-3 * (1 - gamma) / 2, 208e9, 0.3)
    direct = rbc.line_contact(q, lwe * 1e-3, dwe * 1e-3 * (1 - gamma) / 2, 208e9, 0.3)
    assert tuple(map(float, direct)) == pytest.approx(inner, rel=REL)
    outer = hertz_line(q, lwe * 1e-3, dwe * 1e-3 * (1 + gamma) / 2, 208e9, 0.3)
    assert results["inner_contact_pressure"] == pytest.approx(4000e6, rel=0.01)
    expected = {"static_safety_factor": 1.0, "max_roller_load": q,
                "inner_contact_pressure": inner[0], "inner_contact_half_width": inner[1],
                "outer_contact_pressure": outer[0], "outer_contact_half_width": outer[1]}
    assert {key: results[key] for key in expected} == pytest.approx(expected, rel=1e-9)


# --- 10. refused inputs ------------------------------------------------------------------------

SPEC = "kind: rolling-bearing\nspeed: 600 rpm\n"
CYLINDRICAL = (SPEC + "type: cylindrical-roller\nroller_count: 13\nroller_diameter: 9 mm\n"
               "roller_length: 9 mm\npitch_diameter: 46 mm\nradial_load: 6 kN\n")
CATALOGUE = SPEC + "dynamic_load_rating: 430 kN\nstatic_load_rating: 1340 kN\n"
THRUST = CATALOGUE + "radial_load: 10 kN\naxial_load: {fa} kN\ncontact_angle: {alpha} deg\n"
REFUSED = {  # the spec, and the field the one line of stderr must name
    "no roller_length, no C": (CYLINDRICAL.replace("roller_length: 9 mm\n", ""),
                               "roller_length"),
    "ball_count on rollers": (CYLINDRICAL + "ball_count: 13\n", "roller_count"),
    "deep-groove pair": (CATALOGUE + "type: deep-groove\narrangement: back-to-back\n"
                         "radial_load: 6 kN\n", "arrangement"),
    "thrust 50 deg, Fa/Fr below e": (THRUST.format(fa=15, alpha=50)
                                     + "type: thrust-spherical-roller\n", "axial_load"),
    "radial load on 90 deg thrust": (THRUST.format(fa=60, alpha=90)
                                     + "type: thrust-cylindrical-roller\n", "radial_load"),
    "tapered at 50 deg": (CYLINDRICAL.replace("cylindrical-roller", "tapered-roller")
                          + "contact_angle: 50 deg\n", "contact_angle"),
}


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_bad_roller_input_is_one_line_naming_the_field(cli, spec_file, case):
    text, field = REFUSED[case]
    run = cli("solve", spec_file(text), "--format", "json")
    assert run.code == 2, run.out
    assert run.err.count("\n") == 1, run.err
    assert field in run.err, run.err
    assert run.out == ""


# --- 11. the ball-bearing alias ----------------------------------------------------------------

def test_ball_bearing_kind_is_an_alias_of_rolling_bearing(cli, spec_file):
    text = ("kind: rolling-bearing\ntype: tapered-roller\narrangement: face-to-face\n"
            "roller_count: 17\nroller_diameter: 7.5 mm\nroller_length: 12 mm\n"
            "pitch_diameter: 46 mm\ncontact_angle: 14 deg\nradial_load: 9 kN\n"
            "axial_load: 2.5 kN\nspeed: 1500 rpm\nlubrication: {viscosity: 68 mm^2/s}\n"
            "contamination_factor: 0.5\n")
    (rolling,) = solve_json(cli, spec_file(text, "rolling.yaml"))
    (ball,) = solve_json(cli, spec_file(text.replace("kind: rolling-bearing",
                                                     "kind: ball-bearing"), "ball.yaml"))
    assert json.dumps(rolling["results"]) == json.dumps(ball["results"])
    assert rolling["units"] == ball["units"] and rolling["warnings"] == ball["warnings"]
    assert "pair_dynamic_load_rating" in rolling["results"]


def test_a_sweep_over_the_rows_is_each_row_count_solved_alone(cli, spec_file):
    """rows, a choice of 1 or 2, sweeps like a count: a tapered roller bearing's C grows
    by 2^(7/9) from one row to two, and each point is the spec solved alone."""
    text = (ROOT / "specs" / "rolling-bearing-tapered-geometry.yaml").read_text().replace(
        "type: tapered-roller\n", "type: tapered-roller\nrows: 1\n")
    run = cli("sweep", spec_file(text, "one-row.yaml"), "--vary", "rows=1:2:2", "-f", "json")
    assert run.code == 0, run.err
    points = {json.loads(line)["inputs"]["rows"]: json.loads(line)["results"]
              for line in run.out.splitlines()}
    assert points[2]["dynamic_load_rating"] == pytest.approx(
        points[1]["dynamic_load_rating"] * 2 ** (7 / 9), rel=1e-12)
    (alone,) = solve_json(cli, spec_file(text.replace("rows: 1", "rows: 2"), "two.yaml"))
    for key in ("dynamic_load_rating", "modified_rating_life"):
        assert points[2][key] == pytest.approx(alone["results"][key], rel=1e-12)
