"""Pictures with matplotlib (Agg: no display needed), in engineering units."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.units import to_display
from bearingcalc.wording import printable

if TYPE_CHECKING:
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
    limits = []
    if key in report.limits:
        limits = [-report.limits[key], report.limits[key]]
    elif key in report.margins:
        limits = [0.0]
    for i, limit in enumerate(limits):
        axes.axvline(limit * scale, color="#c44e52", linewidth=2,
                     label="limit" if i == 0 else None)
    axes.set_xlabel(f"{key} [{unit}]" if unit else key)
    axes.set_ylabel("samples")
    axes.set_title(printable(f"{record['name'] or record['spec']}: {key}"))
    _legend_below(axes)
    figure.tight_layout()
    figure.savefig(path, format=fmt)
    plt.close(figure)


def sweep_plot(sweep: Sweep, keys: Sequence[str], path: str | Path | IO[bytes], *,
               fmt: str | None = None) -> None:
    """A line sweep: the chosen results against the input, one y axis per unit, limits
    drawn and the range within limits shaded. A grid sweep: filled contours of the first
    chosen result, the limit contour bold, impossible designs left blank."""
    plt = _pyplot()
    figure, axes = plt.subplots(figsize=(8, 5), dpi=120)
    if len(sweep.axes) == 1:
        _line(sweep, keys, figure, axes)
    else:
        _contour(sweep, keys[0], figure, axes)
    axes.set_title(printable(f"{sweep.name} ({sweep.kind.name})"))
    figure.tight_layout()
    figure.savefig(path, format=fmt)
    plt.close(figure)


def _legend_below(axes: Any, handles: list[Any] | None = None) -> None:
    """The legend under the plot, where it cannot cover a line or a bar."""
    kwargs = {"handles": handles} if handles is not None else {}
    axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=3, fontsize="small",
                frameon=False, **kwargs)


def _axis_label(name: str, si_unit: str) -> tuple[float, str]:
    scale, unit = to_display(1.0, si_unit)
    return scale, f"{name} [{unit}]" if unit else name


def _limit_levels(sweep: Sweep, key: str) -> list[float]:
    if key in sweep.limits:
        return [-sweep.limits[key], sweep.limits[key]]
    if key in sweep.kind.margins:
        return [0.0]
    return []


def _line(sweep: Sweep, keys: Sequence[str], figure: Any, axes: Any) -> None:
    axis = sweep.axes[0]
    x_scale, x_label = _axis_label(axis.name, axis.unit)
    x = sweep.inputs[axis.name] * x_scale
    units = sweep.units
    by_unit: dict[str, list[str]] = {}
    for key in keys:
        by_unit.setdefault(units[key], []).append(key)
    colours = iter(["#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860"])
    handles = []
    for n, (si_unit, members) in enumerate(by_unit.items()):
        target = axes if n == 0 else axes.twinx()
        if n > 1:
            target.spines["right"].set_position(("axes", 1 + 0.12 * (n - 1)))
        scale, unit = to_display(1.0, si_unit)
        for key in members:
            colour = next(colours, "#333333")
            # A whole-number input has no values between its points: mark the points.
            (line,) = target.plot(x, sweep.results[key] * scale, color=colour, label=key,
                                  marker="o" if axis.integer else None, markersize=4)
            handles.append(line)
            for i, level in enumerate(_limit_levels(sweep, key)):
                limit = target.axhline(level * scale, color=colour, linestyle=":",
                                       linewidth=1.2, label=f"limit of {key}")
                if i == 0:
                    handles.append(limit)
        target.set_ylabel(", ".join(members) + (f" [{unit}]" if unit else ""))
    ok = sweep.within_limits
    if sweep.kind.margins and ok.any():
        # Shade each run of points within limits out to the midpoints beside it.
        middles = np.concatenate([[x[0]], (x[1:] + x[:-1]) / 2, [x[-1]]])
        edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(int), [0]])))
        for i, (start, stop) in enumerate(zip(edges[::2], edges[1::2], strict=True)):
            axes.axvspan(middles[start], middles[stop], color="#55a868", alpha=0.15,
                         label="within limits" if i == 0 else None)
        handles.append(axes.get_legend_handles_labels()[0][-1])
    impossible = sweep.status != 0
    if impossible.any():
        axes.text(0.01, 0.01, f"{int(impossible.sum())} of {len(impossible)} points are "
                  "impossible designs (gaps)", transform=axes.transAxes, fontsize="small",
                  color="#555555")
    axes.set_xlabel(x_label)
    if axis.integer:
        axes.xaxis.get_major_locator().set_params(integer=True)
    _legend_below(axes, handles)
    axes.grid(alpha=0.3)


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
        if stepped:
            filled = axes.pcolormesh(x, y, z, shading="nearest", cmap="viridis",
                                     vmin=low, vmax=high)
        else:
            filled = axes.contourf(x, y, np.ma.clip(z, low, high),
                                   levels=np.linspace(low, high, 25), cmap="viridis",
                                   extend="both")
        figure.colorbar(filled, ax=axes, label=z_label, extend="both")
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
