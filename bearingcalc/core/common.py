"""Helpers shared by the solver modules."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray


def first_failure(checks: Sequence[tuple[int, ArrayLike]], shape: tuple[int, ...]) -> NDArray:
    """Status code per element: the code of the first failed check, 0 where all pass.

    ``checks`` holds (code, failed) pairs in the order they should be reported;
    ``failed`` arrays broadcast to ``shape``.
    """
    status = np.zeros(shape, dtype=np.int8)
    for code, failed in reversed(checks):
        if np.any(failed):   # usually none fails: no selection pass then
            status = np.where(failed, np.int8(code), status)
    return status


def broadcast_all(results: dict[str, ArrayLike]) -> dict[str, NDArray]:
    """Every result broadcast to the common shape of all of them."""
    shape = np.broadcast_shapes(*(np.shape(value) for value in results.values()))
    return {key: np.broadcast_to(np.asarray(value, dtype=float), shape)
            for key, value in results.items()}


def nan_where(bad: NDArray, value: ArrayLike) -> NDArray:
    """``value`` with NaN where ``bad`` holds, so impossible points carry no number."""
    return np.where(bad, np.nan, value)
