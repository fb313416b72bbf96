"""Helpers and constants shared by the solver modules."""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: SI -> the units the rolling-bearing standards write their formulas in: millimetres,
#: newtons and revolutions per minute (from rad/s).
MM = 1e3
NEWTON = 1.0
RPM = 60.0 / (2.0 * np.pi)

#: Status codes per design: a composite's members need codes past 127.
STATUS_DTYPE = np.int16

#: Relative slack of the balls-fit test, a few ulps of π.
FIT_SLACK = 8 * np.finfo(float).eps

#: The rolling elements of a bearing: ISO 281 and ISO 76 give each family formulas of
#: its own (roller bearings: C = bm·fc·(i·Lwe·cosα)^(7/9)·Z^(3/4)·Dwe^(29/27),
#: L10 = (C/P)^(10/3), C0 = 44·(1 − Dwe·cosα/Dpw)·i·Z·Lwe·Dwe·cosα).
Family = Literal["ball", "roller"]
FAMILIES: tuple[str, ...] = ("ball", "roller")


class DerivedTest(str):
    """A status reason whose test is on a quantity found from several inputs (the fill
    Z·asin(Dw/Dpw), γ, a contact ellipse), not on its field's value alone: a message
    quotes no value of the field as if that value were what failed."""

    __slots__ = ()


def first_failure(checks: Sequence[tuple[int, ArrayLike]], shape: tuple[int, ...]) -> NDArray:
    """Status code per element: the code of the first failed check, 0 where all pass.

    ``checks`` holds (code, failed) pairs in the order they should be reported;
    ``failed`` arrays broadcast to ``shape``.
    """
    status = np.zeros(shape, dtype=STATUS_DTYPE)
    for code, failed in reversed(checks):
        if np.any(failed):   # usually none fails: no selection pass then
            status = np.where(failed, STATUS_DTYPE(code), status)
    return status


def broadcast_all(results: dict[str, ArrayLike]) -> dict[str, NDArray]:
    """Every result broadcast to the common shape of all of them."""
    shape = np.broadcast_shapes(*(np.shape(value) for value in results.values()))
    return {key: np.broadcast_to(np.asarray(value, dtype=float), shape)
            for key, value in results.items()}


def packed(order: Iterable[str], results: Mapping[str, ArrayLike],
           flags: Mapping[str, ArrayLike], checks: Sequence[tuple[int, ArrayLike]]
           ) -> tuple[dict[str, NDArray], NDArray, dict[str, NDArray]]:
    """A solver's results (in ``order``, those it has), status codes (see
    :func:`first_failure`) and warning flags, all broadcast to one shape."""
    shape = np.broadcast_shapes(*(np.shape(v) for v in (*results.values(), *flags.values())))
    status = first_failure(checks, shape)
    ordered = {key: np.broadcast_to(np.asarray(results[key], dtype=float), shape)
               for key in order if key in results}
    warnings = {key: np.broadcast_to(np.asarray(flag, dtype=bool), shape)
                for key, flag in flags.items()}
    return ordered, status, warnings


@dataclass
class Found:
    """What one step of a solve found: results [SI], warning flags, and status checks
    (code, where it fails) in the order they are reported.

    Each step returns its own; the solve gathers them with :meth:`add` in the order the
    steps ran, so the first check that fails names the fault and no step writes into
    what another was handed.
    """

    results: dict[str, ArrayLike] = field(default_factory=dict)
    flags: dict[str, ArrayLike] = field(default_factory=dict)
    checks: list[tuple[int, ArrayLike]] = field(default_factory=list)

    def add(self, step: Found) -> Found:
        """This with a later step's findings (its results replace ones of the same key)."""
        self.results.update(step.results)
        self.flags.update(step.flags)
        self.checks.extend(step.checks)
        return self

    def packed(self, order: Iterable[str]
               ) -> tuple[dict[str, NDArray], NDArray, dict[str, NDArray]]:
        """The solve's results in ``order``, status codes and flags (see :func:`packed`)."""
        return packed(order, self.results, self.flags, self.checks)


def nan_where(bad: NDArray, value: ArrayLike) -> NDArray:
    """``value`` with NaN where ``bad`` holds, so impossible points carry no number."""
    return np.where(bad, np.nan, value)


def balls_fit(ball_count: ArrayLike, size_ratio: ArrayLike) -> NDArray:
    r"""Whether Z balls fit side by side on their pitch circle.

    .. math:: Z \arcsin\frac{D_w}{D_{pw}} \le \pi

    Parameters
    ----------
    ball_count : Z. [1]
    size_ratio : the ball's diameter over the pitch diameter, Dw/Dpw (or the ball's
        radius over the pitch radius, the same ratio); above 1 it counts as 1. [1]

    Returns
    -------
    True where they fit. A few ulps of slack keep balls that fit exactly (6 at a ratio
    of 1/2) from being refused because asin and the product round up.
    """
    ratio = np.minimum(np.asarray(size_ratio, dtype=float), 1.0)
    return np.asarray(ball_count, dtype=float) * np.arcsin(ratio) <= np.pi * (1.0 + FIT_SLACK)


def table_lookup(x: ArrayLike, xs: NDArray, ys: NDArray) -> NDArray:
    """Linear interpolation in a table; NaN outside its range (no extrapolation)."""
    x = np.asarray(x, dtype=float)
    inside = (x >= xs[0]) & (x <= xs[-1])
    return np.where(inside, np.interp(x, xs, ys), np.nan)


def known_family(family: str) -> None:
    """Refuse a rolling-element family that is neither "ball" nor "roller" (ValueError)."""
    if family not in FAMILIES:
        raise ValueError(f"unknown rolling-element family {family!r}: expected one of "
                         f"{', '.join(FAMILIES)}")


def ball_family_only(family: str, formula: str) -> None:
    """Refuse a rolling-element family whose form of ``formula`` is not implemented.

    Raises
    ------
    NotImplementedError : for "roller": the roller-bearing form of the formula, which
        needs the roller's length and the number of rows, has a function of its own.
    ValueError : for a family that is neither "ball" nor "roller".
    """
    known_family(family)
    if family == "roller":
        raise NotImplementedError(f"{formula} is implemented here for ball bearings only; "
                                  "the roller-bearing form is in "
                                  "bearingcalc.core.roller_ratings")
