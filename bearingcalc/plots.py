"""Pictures with matplotlib (Agg: no display needed), in engineering units."""

from __future__ import annotations

from pathlib import Path
from typing import IO

import numpy as np

from bearingcalc.tolerance import StudyReport
from bearingcalc.units import to_display


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
    edges, counts = report.histograms[key]
    occupied = np.nonzero(counts)[0]
    first, last = occupied[0], occupied[-1] + 1
    groups = np.array_split(np.arange(first, last), min(bins, last - first))
    low_edges = np.array([edges[g[0]] for g in groups])
    widths = np.array([edges[g[-1] + 1] - edges[g[0]] for g in groups])
    totals = np.array([counts[g].sum() for g in groups])
    scale, unit = to_display(1.0, si_unit)
    figure, axes = plt.subplots(figsize=(8, 4.5), dpi=120)
    axes.bar(low_edges * scale, totals, width=widths * scale, align="edge",
             color="#4c72b0", edgecolor="none", label=f"Monte Carlo, {record['samples']} samples")
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
    axes.set_title(f"{record['name'] or record['spec']}: {key}")
    axes.legend(loc="best", fontsize="small", framealpha=0.9)
    figure.tight_layout()
    figure.savefig(path, format=fmt)
    plt.close(figure)
