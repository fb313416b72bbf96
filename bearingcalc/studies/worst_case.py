"""The worst case: the exact min and max of every result over the tolerance box, and
the designs where they occur (method: docs/physics.md §10)."""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.studies.study import Study

#: Step of the central differences that tell whether a result is monotonic along an
#: input, as a fraction of the input's tolerance band.
PROBE_STEP = 1e-7
#: Most non-monotonic inputs of one extreme that the grid zoom refines (beyond: L-BFGS-B),
#: and its grid points per input for 1, 2 and 3 of them.
GRID_MAX_FREE = 3
GRID_POINTS = {1: 65, 2: 17, 3: 9}
#: The zoom stops when its grid step is below this fraction of the band, or after
#: ZOOM_PATIENCE passes without a better value.
ZOOM_RESOLUTION = 1e-13
ZOOM_PATIENCE = 8


@dataclass
class _ExtremeSearch:
    """One extreme (min or max of one result) being searched for, in unit coordinates
    of the tolerance box; ``value`` is sign·f at ``point``, so smaller is better."""

    key: str
    sense: str
    sign: float
    point: NDArray
    value: float
    free: NDArray = field(default_factory=lambda: np.empty(0, dtype=np.intp))
    center: NDArray = field(default_factory=lambda: np.empty(0))
    radius: float = 0.5
    stale: int = 0


def worst_case(study: Study) -> dict[str, dict[str, Any]]:
    """Exact min and max of each result over the tolerance box, and where they occur.

    1. All 2^d corners, ``INTERIOR_POINTS`` scrambled Sobol points and the centre
       of the box are evaluated in one solver call, and the central difference
       along every input at each of them in one more.
    2. An input along which a result rises (or falls) at every one of those
       points is monotonic over the box: its extreme is at that input's bound,
       and nothing is searched along it. A result monotonic along every input
       has its extremes at two corners, already evaluated.
    3. The other extremes are refined together, from the best point: at most
       ``GRID_MAX_FREE`` non-monotonic inputs by a grid over them, zoomed onto
       its best point pass after pass, every pending extreme's grid in one
       solver call per pass (:func:`_zoom`); more by L-BFGS-B (scipy.optimize),
       with gradients from one vectorised central-difference call per step.

    Infeasible designs (NaN) are skipped. Method: docs/physics.md §10.
    """
    low, width = study.box()
    unit = study.search_points()
    results, _ = study.scan_box(unit)
    rises = _differences(study, unit, low, width)
    searches: list[_ExtremeSearch] = []
    starts: list[NDArray] = []
    out: dict[str, dict[str, Any]] = {}
    for key in study.keys:
        values = results[key]
        if np.all(np.isnan(values)):
            out[key] = {"min": None, "max": None}
            continue
        out[key] = {}
        for sense, sign in (("min", 1.0), ("max", -1.0)):
            best = int(np.nanargmin(sign * values))
            search = _ExtremeSearch(key, sense, sign, unit[best].copy(),
                                    float(sign * values[best]))
            # Minimising sign·f: a rising input goes to its lower bound, a
            # falling one to its upper; one that never changes f stays put.
            slope = sign * rises[key]
            never_falls, never_rises = (slope >= 0).all(axis=1), (slope <= 0).all(axis=1)
            moved = search.point.copy()
            moved[never_falls & ~never_rises] = 0.0
            moved[never_rises & ~never_falls] = 1.0
            search.free = np.flatnonzero(~(never_falls | never_rises))
            searches.append(search)
            starts.append(moved)
    _move_to(study, searches, starts, low, width)
    _zoom(study, [s for s in searches if 0 < s.free.size <= GRID_MAX_FREE], low, width)
    for search in searches:
        if search.free.size > GRID_MAX_FREE:
            search.point, search.value = refine_with_lbfgsb(study, search.key, search.sign,
                                                            search.point, low, width)
        out[search.key][search.sense] = search.sign * search.value
        out[search.key][f"{search.sense}_inputs"] = {
            item.name: float(low[i] + search.point[i] * width[i])
            for i, item in enumerate(study.inputs)}
    return out


def _differences(study: Study, unit: NDArray, low: NDArray, width: NDArray
                 ) -> dict[str, NDArray]:
    """Result key -> f(u + h·eᵢ) − f(u − h·eᵢ), shape (d, points), at every point u of
    ``unit`` and along every input i (h = PROBE_STEP of the box, kept inside it)."""
    d, n = unit.shape[1], unit.shape[0]
    probes = np.repeat(unit[None, None, :, :], 2, axis=0).repeat(d, axis=1)  # (2, d, n, d)
    for i in range(d):
        probes[0, i, :, i] = np.minimum(unit[:, i] + PROBE_STEP, 1.0)
        probes[1, i, :, i] = np.maximum(unit[:, i] - PROBE_STEP, 0.0)
    results, _ = study.evaluate(low + probes.reshape(-1, d) * width)
    with np.errstate(invalid="ignore"):  # inf − inf: an unbounded result, not monotonic
        return {key: (values[: d * n] - values[d * n:]).reshape(d, n)
                for key, values in ((k, np.asarray(results[k])) for k in study.keys)}


def _move_to(study: Study, searches: list[_ExtremeSearch], starts: list[NDArray],
             low: NDArray, width: NDArray) -> None:
    """Move each search to its start (its monotonic inputs at their bounds) unless
    the design there is impossible or worse (one solver call for all)."""
    if not searches:
        return
    results, _ = study.evaluate(low + np.array(starts) * width)
    for row, (search, start) in enumerate(zip(searches, starts, strict=True)):
        value = search.sign * float(results[search.key][row])
        if value <= search.value:   # False for NaN
            search.point, search.value = start, value


def _zoom(study: Study, searches: list[_ExtremeSearch], low: NDArray, width: NDArray
          ) -> None:
    """Refine ``searches`` over their free inputs by grids zoomed onto their best
    point: GRID_POINTS[k] points a side over the whole range first, then over ±1
    grid step around the best point so far, until that step is below
    ZOOM_RESOLUTION of the box or ZOOM_PATIENCE passes bring no better value.
    Every pass solves the grids of all pending searches in one call."""
    for search in searches:
        search.center = np.full(search.free.size, 0.5)
        search.radius = 0.5
    active = list(searches)
    while active:
        blocks = []
        for search in active:
            k = search.free.size
            axes = [np.linspace(max(c - search.radius, 0.0), min(c + search.radius, 1.0),
                                GRID_POINTS[k]) for c in search.center]
            grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, k)
            block = np.repeat(search.point[None, :], len(grid), axis=0)
            block[:, search.free] = grid
            blocks.append(block)
        results = _evaluate_once(study, low + np.vstack(blocks) * width)
        offset, still = 0, []
        for search, block in zip(active, blocks, strict=True):
            values = search.sign * np.asarray(results[search.key][offset:offset + len(block)])
            offset += len(block)
            if np.all(np.isnan(values)):
                continue
            best = int(np.nanargmin(values))
            search.center = block[best, search.free]
            search.radius = 2.0 * search.radius / (GRID_POINTS[search.free.size] - 1)
            if values[best] < search.value:
                search.point, search.value, search.stale = block[best].copy(), float(
                    values[best]), 0
            else:
                search.stale += 1
            if search.radius > ZOOM_RESOLUTION and search.stale < ZOOM_PATIENCE:
                still.append(search)
        active = still


def _evaluate_once(study: Study, points: NDArray) -> dict[str, NDArray]:
    """The results at ``points`` (n, d), each distinct design solved once: the grids of
    searches zoomed onto the same point (extremes at one design, many results with
    their extremes on one face of an impossible region) repeat whole."""
    unique, inverse = np.unique(points, axis=0, return_inverse=True)
    results, _ = study.evaluate(unique)
    index = np.reshape(inverse, -1)
    return {key: np.asarray(values)[index] for key, values in results.items()}


def refine_with_lbfgsb(study: Study, key: str, sign: float, start: NDArray, low: NDArray,
                       width: NDArray) -> tuple[NDArray, float]:
    """L-BFGS-B from ``start`` (the box in unit coordinates): the point and sign·f there."""
    from scipy.optimize import minimize

    d = len(start)
    step = 1e-7
    fixed = width == 0

    def value_and_gradient(u: NDArray) -> tuple[float, NDArray]:
        points = np.repeat(u[None, :], 2 * d + 1, axis=0)
        for i in range(d):
            up, down = min(u[i] + step, 1.0), max(u[i] - step, 0.0)
            points[1 + 2 * i, i], points[2 + 2 * i, i] = up, down
        values = sign * study.evaluate(low + points * width)[0][key]
        if np.isnan(values[0]):
            return 1e300, np.zeros(d)
        grad = np.zeros(d)
        for i in range(d):
            up, down = values[1 + 2 * i], values[2 + 2 * i]
            span = points[1 + 2 * i, i] - points[2 + 2 * i, i]
            if not fixed[i] and span > 0 and np.isfinite(up) and np.isfinite(down):
                grad[i] = (up - down) / span
        return float(values[0]), grad

    start_value = value_and_gradient(start)[0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        found = minimize(value_and_gradient, start, jac=True, method="L-BFGS-B",
                         bounds=[(0.0, 1.0)] * d, options={"ftol": 1e-15, "gtol": 1e-14,
                                                           "maxiter": 200})
    best_u, best = (found.x, found.fun) if found.fun < start_value else (start, start_value)
    return np.asarray(best_u), float(best)
