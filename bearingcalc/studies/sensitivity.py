"""Sobol sensitivity indices: how much of each result's variance each input explains,
alone (first order) and with its interactions (total order)."""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.models.quantities import Tolerance
from bearingcalc.studies.study import Study, StudyError


def sobol_indices(study: Study, samples: int, seed: int = 0,
                  keys: Sequence[str] | None = None
                  ) -> dict[str, dict[str, dict[str, float]] | str]:
    """First- and total-order Sobol indices of each result (scipy.stats.sobol_indices).

    Uses n = the largest power of 2 <= ``samples`` (at least 2^10, at most
    2^16), which costs n·(d + 2) solver evaluations in one call. A result
    without indices gets the reason instead: it does not vary, or the design
    is impossible somewhere in the sample (scipy needs finite values and would
    otherwise return meaningless numbers).
    """
    from scipy import stats

    if len(study.inputs) < 2:
        raise StudyError("needs at least two toleranced inputs", "--sobol")
    n = 1 << max(10, min(16, int(math.log2(max(samples, 2)))))
    dists = [_frozen(item.tolerance, stats) for item in study.inputs]
    keys = list(keys or study.keys)
    impossible = np.zeros(len(keys), dtype=bool)
    constant = np.ones(len(keys), dtype=bool)

    def func(x: NDArray) -> NDArray:
        results, _ = study.evaluate(x.T, keys)
        outputs = np.vstack([results[key] for key in keys])
        finite = np.isfinite(outputs)
        impossible[:] |= ~finite.all(axis=1)
        outputs = np.where(finite, outputs, 0.0)
        constant[:] &= np.ptp(outputs, axis=1) == 0
        return outputs

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # rows without indices are reported below
        result = stats.sobol_indices(func=func, n=n, dists=dists, rng=seed)
    # scipy drops the results' axis when there is one result: a row per result always
    first = np.asarray(result.first_order).reshape(len(keys), len(study.inputs))
    total = np.asarray(result.total_order).reshape(len(keys), len(study.inputs))
    out: dict[str, dict[str, dict[str, float]] | str] = {}
    for row, key in enumerate(keys):
        if impossible[row]:
            out[key] = "impossible designs in the sample"
        elif constant[row] or not (np.isfinite(first[row]).all()
                                   and np.isfinite(total[row]).all()):
            out[key] = "does not vary with the tolerances"
        else:
            out[key] = {
                "first_order": {item.name: float(first[row, i])
                                for i, item in enumerate(study.inputs)},
                "total_order": {item.name: float(total[row, i])
                                for i, item in enumerate(study.inputs)},
            }
    return out


def _frozen(tolerance: Tolerance, stats: Any) -> Any:
    """The tolerance's distribution as a frozen scipy.stats distribution."""
    low, width = tolerance.low, tolerance.high - tolerance.low
    if tolerance.distribution == "uniform":
        return stats.uniform(loc=low, scale=width)
    if tolerance.distribution == "triangular":
        return stats.triang(c=0.5, loc=low, scale=width)
    return stats.norm(loc=tolerance.center, scale=tolerance.std)
