"""Designs whose ring runs off (no equilibrium) stop iterating, and no design that holds
is taken for one of them: a tapered bearing's axial load just above the least that
holds its rollers, Fa > Fr·tanα (one roller at ψ = 0 carrying Q: Fr = Q·cosα,
Fa = Q·sinα; Harris & Kotzalas, Part 1, ch. 7), with short and long rollers."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import yaml

from bearingcalc.core.iso16281_rollers import roller_geometry, solve_roller_equilibrium
from tests.mounted_specs import refused_lines


@pytest.mark.parametrize("length", [2e-3, 6e-3, 14e-3])
def test_every_tapered_design_above_the_limit_holds_and_none_below(length):
    alpha, radial = math.radians(14), 6000.0
    limit = radial * math.tan(alpha)
    axial = limit * np.concatenate([np.linspace(0.9, 0.999, 50),
                                    np.linspace(1.001, 1.2, 200)])
    loads = np.zeros((axial.size, 5))
    loads[:, 0], loads[:, 1] = axial, radial
    geometry = roller_geometry([17] * axial.size, 7.5e-3, length, alpha, laminae=30)
    solved = solve_roller_equilibrium(geometry, loads)
    assert not solved.converged[axial < limit].any()
    assert solved.converged[axial > limit].all()


CYLINDRICAL = {
    "kind": "rolling-bearing", "type": "cylindrical-roller", "method": "iso-16281",
    "dynamic_load_rating": "44 kN", "static_load_rating": "36.5 kN", "roller_count": 13,
    "roller_diameter": "7.5 mm", "roller_length": "10 mm", "pitch_diameter": "46 mm",
    "operating_clearance": "15 µm", "radial_load": "8 kN", "speed": "3000 rpm",
    "tilting_moment": "1e6 N*m"}


def _yaml(spec: dict) -> str:
    return yaml.safe_dump(spec, allow_unicode=True, sort_keys=False)


def test_a_cylindrical_ring_pushed_off_names_the_load_that_crushes_it(cli, spec_file):
    """Rollers all round carry any load: the design has an equilibrium, beyond the model."""
    lines = refused_lines(cli, spec_file, _yaml(CYLINDRICAL))
    assert len(lines) == 1 and ": tilting_moment: " in lines[0], lines
    assert "crushed" in lines[0]


ANGULAR = {
    "kind": "rolling-bearing", "type": "angular-contact", "method": "iso-16281",
    "contact_angle": "25 deg", "dynamic_load_rating": "14.8 kN", "static_load_rating": "7.8 kN",
    "ball_count": 9, "ball_diameter": "7.938 mm", "pitch_diameter": "38.5 mm",
    "inner_groove_conformity": 0.52, "outer_groove_conformity": 0.53,
    "radial_load": "2 kN", "speed": "3000 rpm"}


DEEP_GROOVE = {
    **{key: value for key, value in ANGULAR.items() if key != "contact_angle"},
    "type": "deep-groove", "operating_clearance": "150 µm", "axial_load": "0 N"}


@pytest.mark.parametrize(("moment", "warned"), [("20 N*m", True), ("1 N*m", False)])
def test_a_single_bearing_tilted_past_the_model_says_so(cli, spec_file, moment, warned):
    """Free to tilt with nothing holding its shaft, a deep-groove bearing with a large
    clearance tilts past 10 mrad under a tilting moment: solved, with a warning."""
    spec = {**DEEP_GROOVE, "tilting_moment": moment}
    run = cli("solve", spec_file(_yaml(spec)), "--format", "json")
    assert run.code in (0, 1), run.err  # 1: its contact pressure fails its limit
    record = json.loads(run.out)
    tilted = abs(record["results"]["ring_tilt"]) > 0.01
    assert tilted == warned
    assert any("tilts more than 10 mrad" in w for w in record["warnings"]) == warned
