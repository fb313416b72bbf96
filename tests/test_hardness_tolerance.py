"""A Brinell hardness carries a tolerance as every input with a unit does ('300 HB ±
10 HB'): the study's worst case of a margin is the margin that solve gives at each end of
the band, and a band that leaves AGMA 2003's 180 to 400 HB is refused at its end."""

from __future__ import annotations

import json
import math

from tests.conftest import solve_json

SPEC = """kind: bevel-gears
name: miter pair
gear_a: {{teeth: 25}}
gear_b: {{teeth: 25}}
module: 5.08 mm
shaft_angle: 90 deg
gear_a_speed: 600 rpm
face_width: 27.94 mm
pressure_angle: 20 deg
power: 7.5 kW
rating:
  quality_number: 7
  hardness: {hardness}
  mounting: neither-straddle
  crowned: false
  geometry_factor_bending: 0.216
  geometry_factor_pitting: 0.065
  cycles: 1e7
  reliability: 0.99
limits:
  min_bending_safety: 1.0
  min_contact_safety: 1.0
"""


def test_the_worst_case_of_a_toleranced_hardness_is_solve_at_the_band_ends(cli, spec_file):
    study = cli("tolerance", spec_file(SPEC.format(hardness="300 HB ± 10 HB")),
                "--method", "worst-case", "--format", "json")
    assert study.code in (0, 1), study.err
    results = json.loads(study.out)["results"]
    for end, hardness in (("min", "290 HB"), ("max", "310 HB")):
        solved = solve_json(cli, spec_file(SPEC.format(hardness=hardness),
                                           name=f"{end}.yaml"))[0]["results"]
        for margin in ("bending_safety_margin", "contact_safety_margin"):
            assert math.isclose(results[margin]["worst_case"][end], solved[margin],
                                rel_tol=1e-9), (margin, end)


def test_a_hardness_band_past_the_charts_is_refused_at_its_end(cli, spec_file):
    run = cli("solve", spec_file(SPEC.format(hardness="395 HB ± 10 HB")))
    assert run.code == 2
    assert run.err.count("\n") == 1, run.err
    assert "rating.hardness" in run.err and "405" in run.err, run.err
