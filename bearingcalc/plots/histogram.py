"""A tolerance study's Monte Carlo histogram with its limits, worst case and ±3σ band."""

from __future__ import annotations

from pathlib import Path
from typing import IO, TYPE_CHECKING

from bearingcalc.plots.common import legend_below, pyplot, words
from bearingcalc.plots.limits import study_limits
from bearingcalc.units import to_display
from bearingcalc.wording import plural, printable

if TYPE_CHECKING:
    from bearingcalc.studies import StudyReport


def tolerance_histogram(report: StudyReport, key: str, path: str | Path | IO[bytes], *,
                        fmt: str | None = None, bins: int = 80) -> None:
    """Histogram of ``key``'s Monte Carlo samples, with its limit(s), the worst-case
    bounds and the mean ± 3σ band marked; PNG or SVG by the file's suffix."""
    plt = pyplot()
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
    levels = study_limits(report, key)
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
    legend_below(axes)
    figure.tight_layout()
    figure.savefig(path, format=fmt)
    plt.close(figure)
