"""What every plot shares: matplotlib without a display, legends below the data, names
in words with units, and the tests for log axes."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.units import to_display


def pyplot():  # type: ignore[no-untyped-def]
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def legend_below(axes: Any, handles: list[Any] | None = None) -> None:
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


def axis_label(name: str, si_unit: str) -> tuple[float, str]:
    scale, unit = to_display(1.0, si_unit)
    return scale, f"{words(name)} [{unit}]" if unit else words(name)


def spans_decades(values: NDArray) -> bool:
    """Positive values over more than two decades: a log axis shows them."""
    finite = values[np.isfinite(values)]
    return finite.size > 1 and bool(np.all(finite > 0)) and finite.max() > 100 * finite.min()


def power_law(x: NDArray, y: NDArray) -> bool:
    """y a power of x (a life against a load): a straight line on log-log axes."""
    good = np.isfinite(x) & np.isfinite(y) & (x > 0) & (y > 0)
    if good.sum() < 4 or not x[good].max() > 1.5 * x[good].min():
        return False
    lx, ly = np.log(x[good]), np.log(y[good])
    slope, intercept = np.polyfit(lx, ly, 1)
    residual = ly - (slope * lx + intercept)
    return abs(slope) > 0.5 and float(np.std(residual)) < 1e-3 * max(float(np.std(ly)), 1e-300)
