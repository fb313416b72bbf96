"""A line sweep: the results against one input, a panel per unit, limits drawn and the
range within limits shaded out to where each drawn curve meets its drawn limit."""

from __future__ import annotations

import itertools
import textwrap
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.plots.common import axis_label, legend_below, power_law, spans_decades, words
from bearingcalc.plots.limits import judged_quantity, sweep_limits
from bearingcalc.units import to_display

if TYPE_CHECKING:
    from bearingcalc.sweeps import Sweep


def line_sweep(sweep: Sweep, keys: Sequence[str], figure: Any, axes: Any) -> Any:
    """Draw a line sweep; returns the top panel. Results of one unit share a panel, and
    panels of different units are stacked over the one input axis, so no limit line of
    one result seems to cross the curve of another."""
    axis = sweep.axes[0]
    x_scale, x_label = axis_label(axis.name, axis.unit)
    x = sweep.inputs[axis.name] * x_scale
    # A margin is an affine image of the quantity it judges: drawn beside it, it would
    # lie exactly over it; the quantity with its limit line says the same.
    keys = [key for key in keys if judged_quantity(sweep, key) not in keys] or list(keys)
    by_unit: dict[str, list[str]] = {}
    for key in keys:
        by_unit.setdefault(sweep.units[key], []).append(key)
    if len(by_unit) > 1:
        figure.delaxes(axes)
        figure.set_figheight(2.4 + 2.2 * len(by_unit))
        panels = list(figure.subplots(len(by_unit), 1, sharex=True))
    else:
        panels = [axes]
    log_x = any(power_law(x, sweep.results[key]) for key in keys) and bool(np.all(x > 0))
    drawn = [key for members in by_unit.values() for key in members]
    colours = dict(zip(drawn, itertools.chain(PALETTE, itertools.repeat("#333333")),
                       strict=False))
    handles = []
    log_y: dict[str, bool] = {}
    for panel, (si_unit, members) in zip(panels, by_unit.items(), strict=True):
        drawn_handles, logarithmic = _draw_panel(panel, sweep, x, members, si_unit,
                                                 colours, log_x)
        handles += drawn_handles
        log_y.update(dict.fromkeys(members, logarithmic))
    if sweep.kind.margins and sweep.within_limits.any():
        for i, (start, stop) in enumerate(within_limit_spans(sweep, x, log_x, log_y)):
            for panel in panels:
                panel.axvspan(start, stop, color="#55a868", alpha=0.15,
                              label="within limits" if i == 0 else None)
        handles.append(panels[0].get_legend_handles_labels()[0][-1])
    bottom = panels[-1]
    handles += _draw_input_axis(bottom, sweep, x, x_label, log_x)
    legend_below(bottom, handles)
    return panels[0]


#: The curves' colours in the order they are drawn; grey after the sixth.
PALETTE = ("#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860")


def _draw_panel(panel: Any, sweep: Sweep, x: NDArray, members: list[str], si_unit: str,
                colours: dict[str, str], log_x: bool) -> tuple[list[Any], bool]:
    """The curves of one unit's results with their limit lines; their legend handles,
    and whether the panel's axis is logarithmic."""
    integer = sweep.axes[0].integer
    handles = []
    scale, unit = to_display(1.0, si_unit)
    for key in members:
        colour = colours[key]
        # A whole-number input has no values between its points: mark the points.
        (line,) = panel.plot(x, sweep.results[key] * scale, color=colour,
                             label=words(key), marker="o" if integer else None,
                             markersize=4)
        handles.append(line)
        # a swept limit is no one line: only a margin's 0 is
        levels = ([] if limits_swept(sweep) and key not in sweep.kind.margins
                  else sweep_limits(sweep, key))
        for i, (level, named) in enumerate(levels):
            label = f"{named} of {words(key)}" if named == "limit" else named
            limit = panel.axhline(level * scale, color=colour, linestyle=":",
                                  linewidth=1.4, label=label)
            if i == 0:
                handles.append(limit)
    # decades, or a power of a log input (a life against a load): log-log is straight
    logarithmic = all(spans_decades(sweep.results[key])
                      or (log_x and power_law(x, sweep.results[key])) for key in members)
    if logarithmic:
        panel.set_yscale("log")
        low, high = panel.get_ylim()
        if low > 0 and high < 1000 * low:  # a few decades: 1, 2, 5, 10, not 10⁰, 10¹
            plain_log_ticks(panel.yaxis, low, high)
    # wrapped to the panel's height, so a long name stays beside its own panel
    panel.set_ylabel(textwrap.fill(", ".join(words(key) for key in members)
                                   + (f" [{unit}]" if unit else ""), 34))
    panel.grid(alpha=0.3)
    if logarithmic or log_x:
        panel.grid(alpha=0.1, which="minor")
    return handles, logarithmic


def _draw_input_axis(bottom: Any, sweep: Sweep, x: NDArray, x_label: str, log_x: bool
                     ) -> list[Any]:
    """The swept input's axis under the bottom panel, its range, scale and ticks; the
    legend's note of the impossible points, if any."""
    handles = []
    impossible = sweep.status != 0
    if impossible.any():
        # in the legend, where no curve runs under it
        (note,) = bottom.plot([], [], linestyle="none", label=(
            f"{int(impossible.sum())} of {len(impossible)} points are impossible (gaps)"))
        handles.append(note)
    bottom.set_xlabel(x_label)
    if x.size > 1 and np.isfinite(x).all() and x.min() < x.max():
        bottom.set_xlim(x.min(), x.max())  # the input's range, drawn or not
    if log_x:
        bottom.set_xscale("log")
        plain_log_ticks(bottom.xaxis, float(np.nanmin(x)), float(np.nanmax(x)))
    elif sweep.axes[0].integer:
        bottom.xaxis.get_major_locator().set_params(integer=True)
    return handles


def plain_log_ticks(axis: Any, low: float, high: float) -> None:
    """Ticks at 1, 2 and 5 of each decade, written plainly (2, 5, 10 kN, not 10⁰, 10¹)."""
    from matplotlib.ticker import NullFormatter, ScalarFormatter

    decades = range(int(np.floor(np.log10(low))), int(np.ceil(np.log10(high))) + 1)
    ticks = [m * 10.0 ** d for d in decades for m in (1, 2, 5) if low <= m * 10.0 ** d <= high]
    if len(ticks) >= 2:
        axis.set_ticks(ticks)
        axis.set_minor_formatter(NullFormatter())
    else:  # within one 1-2-5 step: matplotlib's minor ticks, written plainly too
        axis.set_minor_formatter(ScalarFormatter())
    axis.set_major_formatter(ScalarFormatter())


def within_limit_spans(sweep: Sweep, x: NDArray, log_x: bool,
                        log_y: dict[str, bool]) -> list[tuple[float, float]]:
    """The runs of the input within limits, each ending where a judged curve crosses
    its limit as drawn: straight between points on the plot's own axes (log where they
    are log), so the shade ends exactly where the drawn curve meets its limit line.
    Where no judged result changes side (an impossible point), the run ends midway."""
    at = np.log(x) if log_x else x
    sides = _sides_of_limits(sweep, log_y)
    ok = sweep.within_limits

    def edge(i: int, leaving: bool) -> float:
        # fractions of the way from point i to i + 1 (the input may fall or rise)
        crossings = []
        for side in sides:
            a, b = side[i], side[i + 1]
            if np.isfinite(a) and np.isfinite(b) and (a >= 0) == leaving and (b >= 0) != leaving:
                crossings.append(a / (a - b))
        # leaving, the first limit to be crossed ends the run; entering, the last
        fraction = 0.5 if not crossings else min(crossings) if leaving else max(crossings)
        where = at[i] + fraction * (at[i + 1] - at[i])
        return float(np.exp(where) if log_x else where)

    edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(int), [0]])))
    return [(float(x[0]) if start == 0 else edge(start - 1, leaving=False),
             float(x[-1]) if stop == len(x) else edge(stop - 1, leaving=True))
            for start, stop in zip(edges[::2], edges[1::2], strict=True)]


def _sides_of_limits(sweep: Sweep, log_y: dict[str, bool]) -> list[NDArray]:
    """For each limit the sweep judges, a number per point that is ≥ 0 within it: the
    drawn quantity's distance from its drawn limit line (in logs on a log axis), else
    the margin itself or the room left under a symmetric limit."""
    sides = []
    swept = limits_swept(sweep)
    for margin in sweep.kind.margins:
        if margin not in sweep.results:
            continue
        judged = sweep.kind.judged.get(margin)
        quantity = judged_quantity(sweep, margin)
        levels = sweep_limits(sweep, quantity) if quantity in log_y and not swept else []
        if judged is not None and quantity in sweep.results and levels:
            value, limit = np.abs(sweep.results[quantity]), abs(levels[0][0])
            with np.errstate(divide="ignore", invalid="ignore"):
                room = (np.log(value) - np.log(limit) if log_y[quantity]
                        else value - limit)
            sides.append(room if judged.at_least else -room)
        else:
            sides.append(sweep.results[margin])
    for key, limit in sweep.limits.items():
        if key in sweep.results and not swept:
            sides.append(limit - np.abs(sweep.results[key]))
    return sides


def limits_swept(sweep: Sweep) -> bool:
    """Whether the sweep varies a limit itself, so that no limit is one value."""
    return any(axis.name.startswith("limits.") for axis in sweep.axes)
