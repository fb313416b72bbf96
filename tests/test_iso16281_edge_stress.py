"""ISO/TS 16281's edge-stress factor of roller laminae (8.3, eq. 60) in the reference
life, and ``edge_stress_factor`` through the commands.

The factor's values are checked against a second implementation of the standard's
equation, minzhun/ISO16281's ``RollerBearing.__concentration_edge_stress`` (commit
ade7076), and its effect on the life against a closed form: where every lamina of a
roller carries the same load, each lamina's term of the life sum scales by f_k^(9/2),
so L10r falls by (Σ f_k^(9/2)/n_s)^(−8/9)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from bearingcalc.core.iso16281_life import edge_stress_factors, roller_reference_life
from bearingcalc.core.iso16281_rollers import roller_geometry, solve_roller_equilibrium
from tests.mounted_specs import refused_lines


def _minzhun_factors(laminae: int) -> list[float]:
    """The factor as minzhun/ISO16281 writes it, lamina by lamina (k from 1)."""
    out = []
    for k in range(1, laminae + 1):
        share = abs((2 * k - laminae - 1) / (2 * laminae - 2))
        out.append(1.0 if share == 0 else 1.0 - 0.01 / math.log(1.985 * share))
    return out


@pytest.mark.parametrize("laminae", [10, 11, 30, 31, 200])
def test_the_factors_are_the_second_implementations(laminae):
    np.testing.assert_allclose(edge_stress_factors(laminae)[0], _minzhun_factors(laminae),
                               rtol=1e-14)


def test_the_factor_is_symmetric_one_at_the_middle_and_largest_at_the_ends():
    factors = edge_stress_factors([30, 31], 31)
    thirty, thirty_one = factors[0, :30], factors[1]
    np.testing.assert_array_equal(thirty, thirty[::-1])
    assert thirty_one[15] == 1.0
    assert factors[0, 30] == 1.0  # past the design's own laminae
    end = 1.0 - 0.01 / math.log(1.985 / 2)
    assert thirty[0] == pytest.approx(end, rel=1e-14) and end == pytest.approx(2.3283, 1e-4)
    assert np.all(np.diff(thirty[:15]) < 0)


@pytest.mark.parametrize("laminae", [12, 30, 51])
def test_evenly_loaded_laminae_lose_life_by_the_closed_form(laminae):
    """A straight, untilted roller at zero clearance loads its laminae alike."""
    z, dwe, lwe, dpw, c = 14, 11e-3, 12e-3, 70e-3, 7.35e4
    geometry = roller_geometry(z, dwe, lwe, 0.0, laminae=laminae, profile="none")
    solved = solve_roller_equilibrium(geometry, np.array([[0.0, 1e4, 0, 0, 0]]))
    plain, edged = (roller_reference_life(solved.lamina_load, [z], [dwe], [dpw], [0.0], [c],
                                          edge_stress=edge) for edge in (False, True))
    f = np.array(_minzhun_factors(laminae))
    expected = (np.sum(f ** 4.5) / laminae) ** (-8 / 9)
    assert edged.revolutions[0] / plain.revolutions[0] == pytest.approx(expected, rel=1e-9)


def test_designs_of_different_lamina_counts_each_take_their_own_factors():
    z, dwe, lwe, dpw, c = 14, 11e-3, 12e-3, 70e-3, 7.35e4
    counts = [12, 31]
    geometry = roller_geometry([z, z], dwe, lwe, 0.0, laminae=counts, profile="none")
    loads = np.array([[0.0, 1e4, 0, 0, 4.0]] * 2)
    together = solve_roller_equilibrium(geometry, loads)
    both = roller_reference_life(together.lamina_load, [z, z], [dwe] * 2, [dpw] * 2,
                                 [0.0] * 2, [c] * 2, laminae=counts, edge_stress=[True, True])
    for i, count in enumerate(counts):
        alone = solve_roller_equilibrium(
            roller_geometry(z, dwe, lwe, 0.0, laminae=count, profile="none"), loads[i:i + 1])
        one = roller_reference_life(alone.lamina_load, [z], [dwe], [dpw], [0.0], [c],
                                    edge_stress=True)
        assert both.revolutions[i] == pytest.approx(one.revolutions[0], rel=1e-9)


SPEC = """\
kind: rolling-bearing
name: NU 210 as mounted
type: {type}
method: {method}
dynamic_load_rating: 73.5 kN
static_load_rating: 69.5 kN
roller_count: 14
roller_diameter: 11 mm
roller_length: 12 mm
pitch_diameter: 70 mm
operating_clearance: 20 µm
roller_profile: none
misalignment: 1 mrad
{edge}radial_load: 10 kN
speed: 1500 rpm
"""


def test_the_field_lowers_an_edge_loaded_bearings_life_and_false_is_the_default(cli,
                                                                                 spec_file):
    lives = {}
    for edge in ("", "edge_stress_factor: false\n", "edge_stress_factor: true\n"):
        run = cli("solve", spec_file(SPEC.format(edge=edge, method="iso-16281",
                                                 type="cylindrical-roller")),
                  "--format", "json")
        assert run.code == 0, run.err
        lives[edge] = json.loads(run.out)["results"]["reference_rating_life"]
    assert lives[""] == lives["edge_stress_factor: false\n"]
    assert lives["edge_stress_factor: true\n"] < 0.5 * lives[""]


CATALOGUE_ONLY = """\
kind: rolling-bearing
name: plain
type: {type}
method: {method}
dynamic_load_rating: 14.8 kN
static_load_rating: 7.8 kN
{geometry}edge_stress_factor: {value}
radial_load: 2 kN
speed: 3000 rpm
"""
BALLS = ("ball_count: 9\nball_diameter: 7.938 mm\npitch_diameter: 38.5 mm\n"
         "inner_groove_conformity: 0.52\nouter_groove_conformity: 0.53\n"
         "operating_clearance: 10 µm\n")


@pytest.mark.parametrize(("kind", "method", "geometry", "value"), [
    ("cylindrical-roller", "iso-281", "", "true"),
    ("deep-groove", "iso-16281", BALLS, "true"),
    ("deep-groove", "iso-16281", BALLS, "false"),
    ("cylindrical-roller", "iso-281", "", "maybe"),
], ids=["catalogue-method", "balls", "balls-false", "not-a-boolean"])
def test_the_field_is_refused_where_it_means_nothing(cli, spec_file, kind, method, geometry,
                                                     value):
    lines = refused_lines(cli, spec_file, CATALOGUE_ONLY.format(
        type=kind, method=method, geometry=geometry, value=value))
    assert len(lines) == 1 and "edge_stress_factor:" in lines[0], lines
