"""A grid sweep: filled contours (or cells of a whole-number input) of one result, the
designs within limits hatched and outlined, impossible ones grey."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.plots.common import axis_label, legend_below

if TYPE_CHECKING:
    from bearingcalc.sweeps import Sweep


def grid_sweep(sweep: Sweep, key: str, figure: Any, axes: Any) -> None:
    first, second = sweep.axes
    x_scale, x_label = axis_label(second.name, second.unit)
    y_scale, y_label = axis_label(first.name, first.unit)
    z_scale, z_label = axis_label(key, sweep.units[key])
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
        _filled_result(figure, axes, x, y, z, stepped, z_label)
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
        legend_below(axes, handles)


def _filled_result(figure: Any, axes: Any, x: NDArray, y: NDArray, z: Any, stepped: bool,
                   z_label: str) -> None:
    """The result in colour: cells (``stepped``) or filled contours, on a log scale where
    it spans decades, with its colour bar."""
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
