"""Designs whose ring runs off (no equilibrium) stop iterating, and no design that holds
is taken for one of them: a tapered bearing's axial load just above the least that
holds its rollers, Fa > Fr·tanα (one roller at ψ = 0 carrying Q: Fr = Q·cosα,
Fa = Q·sinα; Harris & Kotzalas, Part 1, ch. 7), with short and long rollers."""

from __future__ import annotations

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
