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
from typer.testing import CliRunner

from bearingcalc.cli import app
from bearingcalc.core.iso16281_rollers import roller_geometry, solve_roller_equilibrium


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


def test_a_cylindrical_ring_pushed_off_names_the_load_that_crushes_it(tmp_path):
    """Rollers all round carry any load: the design has an equilibrium, beyond the model."""
    path = tmp_path / "nu.yaml"
    path.write_text(yaml.safe_dump(CYLINDRICAL, allow_unicode=True, sort_keys=False),
                    encoding="utf-8")
    run = CliRunner().invoke(app, ["solve", str(path)])
    assert run.exit_code == 2
    lines = [line for line in run.output.splitlines() if line.strip()]
    assert len(lines) == 1 and ": tilting_moment: " in lines[0], run.output
    assert "crushed" in lines[0]


ANGULAR = {
    "kind": "rolling-bearing", "type": "angular-contact", "method": "iso-16281",
    "contact_angle": "25 deg", "dynamic_load_rating": "14.8 kN", "static_load_rating": "7.8 kN",
    "ball_count": 9, "ball_diameter": "7.938 mm", "pitch_diameter": "38.5 mm",
    "inner_groove_conformity": 0.52, "outer_groove_conformity": 0.53,
    "radial_load": "2 kN", "speed": "3000 rpm"}


@pytest.mark.parametrize(("axial", "warned"), [("20 N", True), ("1 kN", False)])
def test_a_single_bearing_tilted_past_the_model_says_so(tmp_path, axial, warned):
    """Free to tilt with nothing holding its shaft, an angular-contact bearing's ring
    tilts past 10 mrad under a small axial load: solved, with a warning."""
    path = tmp_path / "ac.yaml"
    path.write_text(yaml.safe_dump({**ANGULAR, "axial_load": axial}, allow_unicode=True,
                                   sort_keys=False), encoding="utf-8")
    run = CliRunner().invoke(app, ["solve", str(path), "--format", "json"])
    assert run.exit_code in (0, 1), run.output  # 1: its contact pressure fails its limit
    record = json.loads(run.output)
    tilted = abs(record["results"]["ring_tilt"]) > 0.01
    assert tilted == warned
    assert any("tilts more than 10 mrad" in w for w in record["warnings"]) == warned
