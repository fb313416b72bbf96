"""Pictures with matplotlib (Agg: no display needed), in engineering units."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.units import to_display
from bearingcalc.wording import plural, printable

if TYPE_CHECKING:
    from bearingcalc.kinds import Kind
    from bearingcalc.studies import StudyReport
    from bearingcalc.sweeps import Sweep


def _pyplot():  # type: ignore[no-untyped-def]
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def tolerance_histogram(report: StudyReport, key: str, path: str | Path | IO[bytes], *,
                        fmt: str | None = None, bins: int = 80) -> None:
    """Histogram of ``key``'s Monte Carlo samples, with its limit(s), the worst-case
    bounds and the mean ± 3σ band marked; PNG or SVG by the file's suffix."""
    plt = _pyplot()
    record = report.record
    si_unit = record["units"][key]
    from bearingcalc.studies import coarse_histogram

    lows, highs, totals = coarse_histogram(*report.histograms[key], bins)
    scale, unit = to_display(1.0, si_unit)
    figure, axes = plt.subplots(figsize=(8, 4.5), dpi=120)
    if totals.size:
        axes.bar(lows * scale, totals, width=(highs - lows) * scale, align="edge",
                 color="#4c72b0", edgecolor="none",
                 label=f"Monte Carlo, {record['samples']} samples")
    else:
        axes.text(0.5, 0.5, "every sample is an impossible design", ha="center",
                  transform=axes.transAxes)
    entry = record["results"][key]
    mc = entry.get("monte_carlo") or {}
    if mc.get("std") is not None:
        mean, std = mc["mean"], mc["std"]
        axes.axvspan((mean - 3 * std) * scale, (mean + 3 * std) * scale, color="#4c72b0",
                     alpha=0.12, label="mean ± 3σ")
    worst = entry.get("worst_case") or {}
    for side in ("min", "max"):
        if worst.get(side) is not None:
            axes.axvline(worst[side] * scale, color="#dd8452", linestyle="--",
                         label="worst case" if side == "min" else None)
    levels = _study_limits(report, key)
    limits = [level for level, _ in levels]
    for i, (limit, named) in enumerate(levels):
        axes.axvline(limit * scale, color="#c44e52", linewidth=2,
                     label=named if i == 0 else None)
    # The axis spans the 0.135 %–99.865 % quantiles, the worst case and the limits: a
    # few tail samples would otherwise stretch it and squeeze the histogram.
    spots = [value for value in (mc.get("p00135"), mc.get("p99865"), worst.get("min"),
                                 worst.get("max"), *limits) if value is not None]
    if len(spots) >= 2 and max(spots) > min(spots):
        pad = 0.05 * (max(spots) - min(spots))
        left, right = (min(spots) - pad) * scale, (max(spots) + pad) * scale
        axes.set_xlim(left, right)
        outside = int(totals[(highs * scale < left) | (lows * scale > right)].sum()) if (
            totals.size) else 0
        if outside:
            axes.text(0.99, 0.97, f"{plural(outside, 'sample')} beyond the axis", ha="right",
                      va="top", transform=axes.transAxes, fontsize="small", color="#555555")
    axes.set_xlabel(f"{words(key)} [{unit}]" if unit else words(key))
    axes.set_ylabel("samples")
    axes.set_title(printable(f"{record['name'] or record['spec']}: {words(key)}"))
    _legend_below(axes)
    figure.tight_layout()
    figure.savefig(path, format=fmt)
    plt.close(figure)


def sweep_plot(sweep: Sweep, keys: Sequence[str], path: str | Path | IO[bytes], *,
               fmt: str | None = None, chosen: bool = False) -> None:
    """A line sweep: the chosen results against the input, one panel per unit, limits
    drawn and the range within limits shaded. A grid sweep: filled contours of the first
    chosen result, the limit contour bold, impossible designs left blank. Unless the
    results were ``chosen`` by the user, a margin gives way to the quantity it judges
    (a life rather than its margin), which says the same with the limit drawn."""
    plt = _pyplot()
    figure, axes = plt.subplots(figsize=(8, 5), dpi=120)
    if len(sweep.axes) == 1:
        axes = _line(sweep, keys, figure, axes)
    else:
        key = keys[0]
        quantity = _judged_quantity(sweep, key)
        if not chosen and quantity in sweep.results:
            key = quantity  # type: ignore[assignment]
        _contour(sweep, key, figure, axes)
    axes.set_title(printable(f"{sweep.name} ({sweep.kind.name})"))
    figure.tight_layout()
    figure.savefig(path, format=fmt)
    plt.close(figure)


def _legend_below(axes: Any, handles: list[Any] | None = None) -> None:
    """The legend under the plot, where it cannot cover a line or a bar."""
    kwargs = {"handles": handles} if handles is not None else {}
    axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=3, fontsize="small",
                frameon=False, **kwargs)


def words(name: str) -> str:
    """A result key or a dotted field name in words: ``modified_rating_life`` is
    "modified rating life", ``pinion_bearings.2.position`` "position of pinion bearing 2",
    ``lubrication.viscosity`` "viscosity of the lubrication"."""
    parts = name.split(".")
    field = parts[-1].replace("_", " ")
    owners = []
    rest = parts[:-1]
    while rest:
        if len(rest) >= 2 and rest[1].isdigit():
            owners.append(f"{rest[0].replace('_', ' ').removesuffix('s')} {rest[1]}")
            rest = rest[2:]
        else:
            owners.append(f"the {rest[0].replace('_', ' ')}")
            rest = rest[1:]
    return " of ".join([field, *reversed(owners)])


def _axis_label(name: str, si_unit: str) -> tuple[float, str]:
    scale, unit = to_display(1.0, si_unit)
    return scale, f"{words(name)} [{unit}]" if unit else words(name)


def _limit_levels(sweep: Sweep, key: str) -> list[tuple[float, str]]:
    """The limits of a result in a sweep, each with its words (see :func:`_levels`),
    read at the first point where the result and the margin are known."""
    def at_a_point(margin: str) -> Mapping[str, float] | None:
        if margin not in sweep.results:
            return None
        good = np.flatnonzero(np.isfinite(sweep.results[key])
                              & np.isfinite(sweep.results[margin]))
        if not good.size:
            return None
        return {name: float(values[good[0]]) for name, values in sweep.results.items()}

    return _levels(sweep.kind, sweep.limits, sweep.kind.margins, key, at_a_point)


def _study_limits(report: StudyReport, key: str) -> list[tuple[float, str]]:
    """The limits of a result in a tolerance study (see :func:`_levels`), read at the
    nominal design."""
    from bearingcalc.kinds import KINDS

    results = report.record["results"]

    def nominal(margin: str) -> Mapping[str, float] | None:
        if margin not in report.margins or results[key]["nominal"] is None:
            return None
        return {name: entry["nominal"] for name, entry in results.items()
                if entry["nominal"] is not None}

    return _levels(KINDS[report.record["kind"]], report.limits, report.margins, key, nominal)


#: A value no result has exactly, to ask a margin whether it judges a result.
_PROBE = 1.2345678


def _levels(kind: Kind, limits: Mapping[str, float], margins: Iterable[str], key: str,
            known: Callable[[str], Mapping[str, float] | None]) -> list[tuple[float, str]]:
    """The limits of a result, each with its words: its own symmetric limit, 0 of a
    margin, or the limit of a result a margin judges (a life's required life; the min
    bending safety of either gear), from the results ``known`` gives at one design."""
    if key in limits:
        return [(-limits[key], "limit"), (limits[key], "limit")]
    if key in margins:
        return [(0.0, "limit")]
    for margin, judged in kind.judged.items():
        if judged.value({key: _PROBE}) != _PROBE:  # it judges other results
            continue
        point = known(margin)
        value = None if point is None else judged.value(point)
        if point is None or value is None:
            continue
        limit = judged.limit(value, point[margin])
        if np.isfinite(limit):
            named = judged.named({}).removeprefix("smallest ")  # "min static safety s0"
            return [(limit, f"{judged.limit_word} {named}")]
    return []


def _judged_quantity(sweep: Sweep, margin: str) -> str | None:
    judged = sweep.kind.judged.get(margin)
    return judged.quantity if judged is not None and isinstance(judged.quantity, str) else None


def _spans_decades(values: NDArray) -> bool:
    """Positive values over more than two decades: a log axis shows them."""
    finite = values[np.isfinite(values)]
    return finite.size > 1 and bool(np.all(finite > 0)) and finite.max() > 100 * finite.min()


def _power_law(x: NDArray, y: NDArray) -> bool:
    """y a power of x (a life against a load): a straight line on log-log axes."""
    good = np.isfinite(x) & np.isfinite(y) & (x > 0) & (y > 0)
    if good.sum() < 4 or not x[good].max() > 1.5 * x[good].min():
        return False
    lx, ly = np.log(x[good]), np.log(y[good])
    slope, intercept = np.polyfit(lx, ly, 1)
    residual = ly - (slope * lx + intercept)
    return abs(slope) > 0.5 and float(np.std(residual)) < 1e-3 * max(float(np.std(ly)), 1e-300)


def _line(sweep: Sweep, keys: Sequence[str], figure: Any, axes: Any) -> Any:
    """Draw a line sweep; returns the top panel. Results of one unit share a panel, and
    panels of different units are stacked over the one input axis, so no limit line of
    one result seems to cross the curve of another."""
    axis = sweep.axes[0]
    x_scale, x_label = _axis_label(axis.name, axis.unit)
    x = sweep.inputs[axis.name] * x_scale
    units = sweep.units
    # A margin is an affine image of the quantity it judges: drawn beside it, it would
    # lie exactly over it; the quantity with its limit line says the same.
    keys = [key for key in keys if _judged_quantity(sweep, key) not in keys] or list(keys)
    by_unit: dict[str, list[str]] = {}
    for key in keys:
        by_unit.setdefault(units[key], []).append(key)
    if len(by_unit) > 1:
        figure.delaxes(axes)
        figure.set_figheight(2.4 + 2.2 * len(by_unit))
        panels = list(figure.subplots(len(by_unit), 1, sharex=True))
    else:
        panels = [axes]
    log_x = any(_power_law(x, sweep.results[key]) for key in keys) and bool(np.all(x > 0))
    colours = iter(["#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860"])
    handles = []
    log_y: dict[str, bool] = {}
    for panel, (si_unit, members) in zip(panels, by_unit.items(), strict=True):
        scale, unit = to_display(1.0, si_unit)
        for key in members:
            colour = next(colours, "#333333")
            # A whole-number input has no values between its points: mark the points.
            (line,) = panel.plot(x, sweep.results[key] * scale, color=colour,
                                 label=words(key), marker="o" if axis.integer else None,
                                 markersize=4)
            handles.append(line)
            for i, (level, named) in enumerate(_limit_levels(sweep, key)):
                label = f"{named} of {words(key)}" if named == "limit" else named
                limit = panel.axhline(level * scale, color=colour, linestyle=":",
                                      linewidth=1.4, label=label)
                if i == 0:
                    handles.append(limit)
        logarithmic = all(_spans_decades(sweep.results[key]) for key in members)
        log_y.update(dict.fromkeys(members, logarithmic))
        if logarithmic:
            panel.set_yscale("log")
        panel.set_ylabel(", ".join(words(key) for key in members)
                         + (f" [{unit}]" if unit else ""))
        panel.grid(alpha=0.3)
        if logarithmic or log_x:
            panel.grid(alpha=0.1, which="minor")
    if sweep.kind.margins and sweep.within_limits.any():
        for i, (start, stop) in enumerate(_within_limit_spans(sweep, x, log_x, log_y)):
            for panel in panels:
                panel.axvspan(start, stop, color="#55a868", alpha=0.15,
                              label="within limits" if i == 0 else None)
        handles.append(panels[0].get_legend_handles_labels()[0][-1])
    bottom = panels[-1]
    impossible = sweep.status != 0
    if impossible.any():
        # in the legend, where no curve runs under it
        (note,) = bottom.plot([], [], linestyle="none", label=(
            f"{int(impossible.sum())} of {len(impossible)} points are impossible (gaps)"))
        handles.append(note)
    bottom.set_xlabel(x_label)
    if log_x:
        bottom.set_xscale("log")
        _plain_log_ticks(bottom.xaxis, float(np.nanmin(x)), float(np.nanmax(x)))
    elif axis.integer:
        bottom.xaxis.get_major_locator().set_params(integer=True)
    _legend_below(bottom, handles)
    return panels[0]


def _plain_log_ticks(axis: Any, low: float, high: float) -> None:
    """Ticks at 1, 2 and 5 of each decade, written plainly (2, 5, 10 kN, not 10⁰, 10¹)."""
    from matplotlib.ticker import NullFormatter, ScalarFormatter

    decades = range(int(np.floor(np.log10(low))), int(np.ceil(np.log10(high))) + 1)
    ticks = [m * 10.0 ** d for d in decades for m in (1, 2, 5) if low <= m * 10.0 ** d <= high]
    if len(ticks) >= 2:
        axis.set_ticks(ticks)
        axis.set_major_formatter(ScalarFormatter())
        axis.set_minor_formatter(NullFormatter())


def _within_limit_spans(sweep: Sweep, x: NDArray, log_x: bool,
                        log_y: dict[str, bool]) -> list[tuple[float, float]]:
    """The runs of the input within limits, each ending where a judged curve crosses
    its limit as drawn: straight between points on the plot's own axes (log where they
    are log), so the shade ends exactly where the drawn curve meets its limit line.
    Where no judged result changes side (an impossible point), the run ends midway."""
    at = np.log(x) if log_x else x
    sides = _sides_of_limits(sweep, log_y)
    ok = sweep.within_limits

    def edge(i: int, leaving: bool) -> float:
        crossings = []
        for side in sides:
            a, b = side[i], side[i + 1]
            if np.isfinite(a) and np.isfinite(b) and (a >= 0) == leaving and (b >= 0) != leaving:
                crossings.append(at[i] + a / (a - b) * (at[i + 1] - at[i]))
        if not crossings:
            where = (at[i] + at[i + 1]) / 2
        else:
            where = min(crossings) if leaving else max(crossings)
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
    for margin in sweep.kind.margins:
        if margin not in sweep.results:
            continue
        judged = sweep.kind.judged.get(margin)
        quantity = _judged_quantity(sweep, margin)
        levels = _limit_levels(sweep, quantity) if quantity in log_y else []
        if judged is not None and quantity in sweep.results and levels:
            value, limit = np.abs(sweep.results[quantity]), abs(levels[0][0])
            with np.errstate(divide="ignore", invalid="ignore"):
                room = (np.log(value) - np.log(limit) if log_y[quantity]
                        else value - limit)
            sides.append(room if judged.at_least else -room)
        else:
            sides.append(sweep.results[margin])
    for key, limit in sweep.limits.items():
        if key in sweep.results:
            sides.append(limit - np.abs(sweep.results[key]))
    return sides


def _contour(sweep: Sweep, key: str, figure: Any, axes: Any) -> None:
    first, second = sweep.axes
    x_scale, x_label = _axis_label(second.name, second.unit)
    y_scale, y_label = _axis_label(first.name, first.unit)
    z_scale, z_label = _axis_label(key, sweep.units[key])
    shape = sweep.shape
    x = second.values * x_scale
    y = first.values * y_scale
    z = np.ma.masked_invalid(sweep.results[key].reshape(shape) * z_scale)
    # A whole-number axis (ball count, teeth) has nothing between its values: draw cells,
    # not contours that would invent diagonal boundaries between them.
    stepped = first.integer or second.integer
    handles = []
    if z.count() == 0:
        axes.text(0.5, 0.5, "no possible design in this range", ha="center",
                  transform=axes.transAxes)
    else:
        # Colour by the central 96 % of the values: a few very negative margins far from
        # the limit would otherwise squeeze the interesting band into one colour.
        low, high = np.percentile(z.compressed(), [2.0, 98.0])
        if not high > low:
            low, high = float(z.min()), float(z.max()) + 1e-300
        logarithmic = low > 0 and high > 100 * low  # decades: a log scale, round ticks
        if logarithmic:
            from matplotlib.colors import LogNorm
            from matplotlib.ticker import LogLocator

            norm = LogNorm(vmin=low, vmax=high)
            levels = np.geomspace(low, high, 25)
        else:  # round levels, so the colour bar's ticks read as numbers one would write
            from matplotlib.ticker import MaxNLocator

            norm, levels = None, MaxNLocator(nbins=20).tick_values(low, high)
        if stepped:
            filled = axes.pcolormesh(x, y, z, shading="nearest", cmap="viridis",
                                     norm=norm, vmin=None if norm else low,
                                     vmax=None if norm else high)
        else:
            filled = axes.contourf(x, y, np.ma.clip(z, low, high), levels=levels,
                                   cmap="viridis", extend="both", norm=norm)
        bar = figure.colorbar(filled, ax=axes, label=z_label, extend="both")
        if logarithmic:
            bar.locator = LogLocator()
            bar.update_ticks()
        ok = sweep.within_limits.reshape(shape)
        if sweep.kind.margins and ok.any():
            handles.append(_within_limits_overlay(axes, x, y, ok, stepped))
    axes.set_facecolor("#dddddd")  # masked (impossible) points show as the background
    impossible = sweep.status != 0
    if impossible.any():
        axes.text(0.01, 0.01, "grey: impossible designs", transform=axes.transAxes,
                  fontsize="small", color="#333333")
    axes.set_xlabel(x_label)
    axes.set_ylabel(y_label)
    for target, axis in ((axes.xaxis, second), (axes.yaxis, first)):
        if axis.integer:
            target.get_major_locator().set_params(integer=True)
    if handles:
        _legend_below(axes, handles)


def _within_limits_overlay(axes: Any, x: NDArray, y: NDArray, ok: NDArray,
                           stepped: bool) -> Any:
    """Hatch the designs within every limit and outline them; the legend handle."""
    from matplotlib.patches import Patch

    if stepped:
        rows, cols = np.nonzero(ok)
        axes.scatter(x[cols], y[rows], marker="+", color="white", s=18, linewidths=0.8)
    else:
        axes.contourf(x, y, ok.astype(float), levels=[0.5, 1.5], colors="none",
                      hatches=["//"])
        axes.contour(x, y, ok.astype(float), levels=[0.5], colors="white", linewidths=2.0)
    return Patch(facecolor="none", edgecolor="black", hatch="" if stepped else "//",
                 label="within limits" + (" (+)" if stepped else ""))
