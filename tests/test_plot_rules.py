"""The rules the plots follow: words with units on the axes, a limit drawn in the
quantity's own unit, log axes for decades and power laws, a margin not drawn over the
quantity it judges, and a study's default plot its weakest margin."""

from __future__ import annotations

import numpy as np
import pytest

from bearingcalc import plots
from bearingcalc.evaluation import load_one_spec
from bearingcalc.sweeps import parse_axis, run_sweep
from tests.conftest import ROOT


@pytest.mark.parametrize(("name", "said"), [
    ("modified_rating_life", "modified rating life"),
    ("pinion_bearings.2.position", "position of pinion bearing 2"),
    ("lubrication.viscosity", "viscosity of the lubrication"),
    ("duty_cycle.3.radial_load", "radial load of duty cycle 3"),
])
def test_names_read_as_words(name, said):
    assert plots.words(name) == said


def test_decades_and_power_laws():
    x = np.linspace(1.0, 20.0, 40)
    assert plots._power_law(x, 3.0 * x ** (-10 / 3))  # a life against a load
    assert not plots._power_law(x, 3.0 + x)
    assert plots._spans_decades(np.array([1.0, 50.0, 300.0]))
    assert not plots._spans_decades(np.array([1.0, 50.0]))
    assert not plots._spans_decades(np.array([-1.0, 500.0]))


def _sweep(path, text):
    kind, spec, _ = load_one_spec(path)
    return run_sweep(kind, spec, str(path), [parse_axis(text, spec)])


def test_a_life_sweep_draws_the_required_life_in_hours():
    """The life's limit comes from its margin: the spec's 6000 h, whatever the point."""
    solved = _sweep(ROOT / "specs" / "rolling-bearing.yaml", "radial_load=1kN:20kN:12")
    ((level, named),) = plots._limit_levels(solved, "modified_rating_life")
    assert level == pytest.approx(6000 * 3600.0, rel=1e-12)
    assert named == "required modified rating life"
    assert plots._judged_quantity(solved, "life_margin") == "modified_rating_life"


def test_the_line_plot_leaves_a_margin_out_beside_its_quantity(tmp_path, monkeypatch):
    solved = _sweep(ROOT / "specs" / "rolling-bearing.yaml", "radial_load=1kN:20kN:12")
    drawn = []
    real = plots._line

    def spy(sweep, keys, figure, axes):
        real(sweep, keys, figure, axes)
        drawn.extend(line.get_label() for ax in figure.axes for line in ax.get_lines())

    monkeypatch.setattr(plots, "_line", spy)
    plots.sweep_plot(solved, ["modified_rating_life", "life_margin"], tmp_path / "a.png")
    assert "modified rating life" in drawn and "life margin" not in drawn
    assert "required modified rating life" in drawn
