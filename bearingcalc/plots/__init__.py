"""Pictures with matplotlib (Agg: no display needed), in engineering units: a tolerance
study's histogram (:mod:`.histogram`) and a sweep's lines (:mod:`.line`) or grid
(:mod:`.grid`), their axes named in words and their limits drawn (:mod:`.limits`)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import IO, TYPE_CHECKING

from bearingcalc.plots.common import pyplot, words
from bearingcalc.plots.grid import grid_sweep
from bearingcalc.plots.histogram import tolerance_histogram
from bearingcalc.plots.limits import judged_quantity
from bearingcalc.plots.line import line_sweep
from bearingcalc.wording import printable

if TYPE_CHECKING:
    from bearingcalc.sweeps import Sweep

__all__ = ["sweep_plot", "tolerance_histogram", "words"]


def sweep_plot(sweep: Sweep, keys: Sequence[str], path: str | Path | IO[bytes], *,
               fmt: str | None = None, chosen: bool = False) -> None:
    """A line sweep: the chosen results against the input, one panel per unit, limits
    drawn and the range within limits shaded. A grid sweep: filled contours of the first
    chosen result, the limit contour bold, impossible designs left blank. Unless the
    results were ``chosen`` by the user, a margin gives way to the quantity it judges
    (a life rather than its margin), which says the same with the limit drawn."""
    plt = pyplot()
    figure, axes = plt.subplots(figsize=(8, 5), dpi=120)
    if len(sweep.axes) == 1:
        axes = line_sweep(sweep, keys, figure, axes)
    else:
        key = keys[0]
        quantity = judged_quantity(sweep, key)
        if not chosen and quantity in sweep.results:
            key = quantity  # type: ignore[assignment]
        grid_sweep(sweep, key, figure, axes)
    axes.set_title(printable(f"{sweep.name} ({sweep.kind.name})"))
    figure.tight_layout()
    figure.savefig(path, format=fmt)
    plt.close(figure)
