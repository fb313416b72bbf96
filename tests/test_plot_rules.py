"""The rules the plots follow: words with units on the axes, a limit drawn in the
quantity's own unit, log axes for decades and power laws, a margin not drawn over the
quantity it judges, and a study's default plot its weakest margin."""

from __future__ import annotations

import numpy as np
import pytest

from bearingcalc import plots
from bearingcalc.evaluation import load_one_spec
from bearingcalc.plots import common, limits, line
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
    assert common.power_law(x, 3.0 * x ** (-10 / 3))  # a life against a load
    assert not common.power_law(x, 3.0 + x)
    assert common.spans_decades(np.array([1.0, 50.0, 300.0]))
    assert not common.spans_decades(np.array([1.0, 50.0]))
    assert not common.spans_decades(np.array([-1.0, 500.0]))


def _sweep(path, text):
    kind, spec, _ = load_one_spec(path)
    return run_sweep(kind, spec, str(path), [parse_axis(text, spec)])


def test_a_life_sweep_draws_the_required_life_in_hours():
    """The life's limit comes from its margin: the spec's 6000 h, whatever the point."""
    solved = _sweep(ROOT / "specs" / "rolling-bearing.yaml", "radial_load=1kN:20kN:12")
    ((level, named),) = limits.sweep_limits(solved, "modified_rating_life")
    assert level == pytest.approx(6000 * 3600.0, rel=1e-12)
    assert named == "required modified rating life"
    assert limits.judged_quantity(solved, "life_margin") == "modified_rating_life"


def test_the_line_plot_leaves_a_margin_out_beside_its_quantity(tmp_path, monkeypatch):
    solved = _sweep(ROOT / "specs" / "rolling-bearing.yaml", "radial_load=1kN:20kN:12")
    drawn = []
    real = plots.line_sweep

    def spy(sweep, keys, figure, axes):
        top = real(sweep, keys, figure, axes)
        drawn.extend(line.get_label() for ax in figure.axes for line in ax.get_lines())
        return top

    monkeypatch.setattr(plots, "line_sweep", spy)
    plots.sweep_plot(solved, ["modified_rating_life", "life_margin"], tmp_path / "a.png")
    assert "modified rating life" in drawn and "life margin" not in drawn
    assert "required modified rating life" in drawn


def test_the_shade_ends_where_the_drawn_life_crosses_its_drawn_requirement():
    """The life is drawn straight between points on a log axis: the shade within limits
    ends where that line meets the required life's line, not midway between points."""
    solved = _sweep(ROOT / "specs" / "rolling-bearing.yaml", "radial_load=2kN:20kN:10")
    x = solved.inputs["radial_load"]
    life = solved.results["modified_rating_life"]
    required = 6000 * 3600.0
    ((start, stop),) = line.within_limit_spans(
        solved, x, log_x=False, log_y={"modified_rating_life": True})
    # the life falls with the load: interpolate the load against log life
    drawn = np.interp(np.log(required), np.log(life[::-1]), x[::-1])
    assert start == x[0]
    assert stop == pytest.approx(drawn, rel=1e-12)
    # and it lies near where the bearing's life truly reaches 6000 h
    fine = _sweep(ROOT / "specs" / "rolling-bearing.yaml", "radial_load=8kN:11kN:3001")
    true = fine.inputs["radial_load"][np.argmin(abs(fine.results["modified_rating_life"]
                                                     - required))]
    assert stop == pytest.approx(true, rel=0.01)
    assert abs(stop - true) < abs((x[3] + x[4]) / 2 - true)  # nearer than the midpoint


def test_results_of_different_units_are_stacked_not_twinned(tmp_path, monkeypatch):
    """A limit line on a second y axis would seem to cross the other result's curve."""
    solved = _sweep(ROOT / "specs" / "rolling-bearing.yaml", "radial_load=2kN:20kN:10")
    figures = []
    real = plots.line_sweep

    def spy(sweep, keys, figure, axes):
        figures.append(figure)
        return real(sweep, keys, figure, axes)

    monkeypatch.setattr(plots, "line_sweep", spy)
    plots.sweep_plot(solved, ["modified_rating_life", "static_safety_factor"],
                     tmp_path / "a.png")
    (figure,) = figures
    panels = figure.axes
    assert len(panels) == 2
    tops = sorted(panel.get_position().y0 for panel in panels)
    assert tops[0] < tops[1]  # one above the other, not twins on one frame
    assert panels[0].get_shared_x_axes().joined(panels[0], panels[1])


def _study(name, samples=4096):
    from bearingcalc.studies import run_study

    kind, spec, _ = load_one_spec(ROOT / "specs" / "tolerances" / name)
    return run_study(kind, spec, name, methods=["worst-case", "monte-carlo"],
                     samples=samples)


def test_a_study_plots_the_life_its_weakest_margin_judges_with_the_required_life():
    report = _study("ball-bearing.yaml")
    assert report.plotted == "modified_rating_life"
    ((level, named),) = limits.study_limits(report, "modified_rating_life")
    assert level == pytest.approx(2000 * 3600.0, rel=1e-12)
    assert named == "required modified rating life"


def test_a_study_plots_the_margin_that_fails():
    """The drive fails on the bending safety (a margin of the weaker gear, no one
    result), not on its lives: that margin is the plot."""
    report = _study("bevel-drive.yaml")
    results = report.record["results"]
    assert results["bending_safety_margin"]["worst_case"]["min"] < 0
    assert results["life_margin"]["worst_case"]["min"] > 0
    assert report.plotted == "bending_safety_margin"
    assert limits.study_limits(report, "bending_safety_margin") == [(0.0, "limit")]


def test_a_chosen_result_is_the_plot(cli, tmp_path, monkeypatch):
    drawn = []
    monkeypatch.setattr(plots, "tolerance_histogram",
                        lambda report, key, path, fmt=None: drawn.append(key))
    run = cli("tolerance", ROOT / "specs" / "tolerances" / "ball-bearing.yaml", "-n", "1024",
              "-r", "static_safety_factor", "--plot", tmp_path / "h.png")
    assert run.code in (0, 1), run.err
    assert drawn == ["static_safety_factor"]


def test_a_safety_judged_through_the_weaker_member_still_draws_its_limit():
    """A drive's bending margin judges the weaker gear and its s0 margin the weakest
    bearing (no one result): each such result is drawn with that same limit."""
    solved = _sweep(ROOT / "specs" / "bevel-drive.yaml",
                    "pinion_bearings.2.position=110mm:250mm:8")
    spec = load_one_spec(ROOT / "specs" / "bevel-drive.yaml")[1]
    ((bending, named),) = limits.sweep_limits(solved, "bending_safety")
    assert bending == pytest.approx(spec.limits.min_bending_safety, rel=1e-12)
    assert named == "min bending safety S_F"
    ((static, named),) = limits.sweep_limits(solved, "pinion_bearing_1_static_safety_factor")
    assert static == pytest.approx(spec.limits.min_static_safety, rel=1e-12)
    assert named == "min static safety s0"
    assert limits.sweep_limits(solved, "gear_speed") == []


def test_the_shade_is_the_same_on_a_falling_input():
    """Swept from high load to low, the run within limits ends at the same crossing."""
    path = ROOT / "specs" / "rolling-bearing.yaml"
    rising = _sweep(path, "radial_load=2kN:20kN:10")
    falling = _sweep(path, "radial_load=20kN:2kN:10")
    log_y = {"modified_rating_life": True}
    ((start, stop),) = line.within_limit_spans(rising, rising.inputs["radial_load"], False,
                                               log_y)
    ((start_falling, stop_falling),) = line.within_limit_spans(
        falling, falling.inputs["radial_load"], False, log_y)
    assert (start_falling, stop_falling) == (pytest.approx(stop, rel=1e-12), 2000.0)
    assert start == 2000.0


def test_of_two_limits_crossed_between_points_the_last_to_pass_starts_the_run(monkeypatch):
    """From 16 kN down to 4 kN both margins recover: the life at 10 kN, the safety only
    at 6.4 kN; the run within limits starts at 6.4 kN, whichever way the input runs."""
    from types import SimpleNamespace

    sides = [np.array([-1.0, 1.0]), np.array([-0.8, 0.2])]
    monkeypatch.setattr(line, "_sides_of_limits", lambda sweep, log_y: sides)
    falling = SimpleNamespace(within_limits=np.array([False, True]))
    ((start, stop),) = line.within_limit_spans(falling, np.array([16.0, 4.0]), False, {})
    assert (start, stop) == (pytest.approx(6.4, rel=1e-12), 4.0)
    sides = [side[::-1] for side in sides]
    rising = SimpleNamespace(within_limits=np.array([True, False]))
    ((start, stop),) = line.within_limit_spans(rising, np.array([4.0, 16.0]), False, {})
    assert (start, stop) == (4.0, pytest.approx(6.4, rel=1e-12))


def test_every_limit_the_sweep_crosses_is_shown():
    """Over torque the drive's lives hold past where its gear's bending safety fails:
    the bending margin is shown, so the shade's edge is a drawn curve."""
    from bearingcalc.sweeps import shown_results

    solved = _sweep(ROOT / "specs" / "bevel-drive.yaml", "torque=40N*m:80N*m:9")
    keys = shown_results(solved, None)
    assert keys[:len(solved.kind.governing)] == [
        key for key in solved.kind.governing if key in solved.results]
    assert "bending_safety_margin" in keys
    assert shown_results(solved, ["gear_speed"]) == ["gear_speed"]


def test_a_study_leads_with_the_margin_that_fails():
    report = _study("bevel-drive.yaml")
    assert report.governing[0] == "bending_safety_margin"
    assert "life_margin" in report.governing
