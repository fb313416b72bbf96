"""Tolerance studies on the vectorised solvers: worst case, RSS, Monte Carlo, Sobol indices.

Every method evaluates whole arrays of designs per solver call, never a Python
loop per sample. Inputs are the spec fields that carry a tolerance (see
:class:`bearingcalc.models.fields.Tolerance` for the distributions).

Monte Carlo streams: samples are drawn and solved in chunks, and only running
statistics are kept, so memory does not grow with the number of samples. The
sample stream is one sequence, whatever the chunk size or the number of
threads: chunk k starts the Sobol stream at its first sample, or advances the
PCG64 generator, to its first sample. Sums are taken per fixed block of
``BLOCK`` samples and added exactly (``math.fsum``), and histogram counts are
integers, so the statistics do not depend on chunking or threads either.
"""

from __future__ import annotations

import copy
import itertools
import math
import threading
import warnings
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.errors import BearingcalcError
from bearingcalc.kinds import Kind
from bearingcalc.models.fields import SpecModel, Tolerance
from bearingcalc.units import to_display
from bearingcalc.variation import evaluate_with, field_value, toleranced_fields

METHODS = ("worst-case", "rss", "monte-carlo")
SAMPLERS = ("sobol", "random")
#: Samples per block: the unit of exact summation and the pilot for histogram ranges.
BLOCK = 1 << 16
#: Histogram bins per result for the Monte Carlo quantiles.
HISTOGRAM_BINS = 1 << 16
QUANTILES = {"p00135": 0.00135, "p50": 0.5, "p99865": 0.99865}
#: Designs in the interior of the box, besides its corners, that seed the worst-case search.
INTERIOR_POINTS = 1 << 10
MAX_CORNER_INPUTS = 14
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
#: Distinct points of a 30-bit Sobol' sequence (scipy's default, and ours).
SOBOL_MAX_SAMPLES = 1 << 30


class StudyError(BearingcalcError):
    """A tolerance study that cannot be run as asked (no tolerances, bad options)."""


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


@dataclass
class StudyInput:
    """One toleranced spec field."""

    name: str
    tolerance: Tolerance

    @property
    def low(self) -> float:
        return self.tolerance.low

    @property
    def high(self) -> float:
        return self.tolerance.high


@dataclass
class MonteCarloResult:
    """Monte Carlo statistics of every result, the yield and the process capability."""

    samples: int
    seed: int
    sampler: str
    stats: dict[str, dict[str, float | None]]
    histograms: dict[str, tuple[NDArray, NDArray]]   # key -> (bin edges, counts)
    passed: int
    infeasible: int

    @property
    def yield_fraction(self) -> float:
        return self.passed / self.samples

    @property
    def ppm_out(self) -> float:
        return 1e6 * (self.samples - self.passed) / self.samples


@dataclass
class Study:
    """A tolerance study of one spec."""

    kind: Kind
    spec: SpecModel
    inputs: list[StudyInput] = field(init=False)
    nominal: dict[str, float] = field(init=False)
    #: impossible designs met by the worst-case search of the box (see worst_case)
    box_impossible: dict[str, Any] | None = field(init=False, default=None)

    def __post_init__(self) -> None:
        self.inputs = [StudyInput(name, tol) for name, tol in toleranced_fields(self.spec).items()]
        if not self.inputs:
            raise StudyError("the spec has no tolerances: give one on any input with a unit, "
                             "like 'contact_angle: 20 deg ± 0.25 deg'")
        results, _ = evaluate_with(self.kind, self.spec, {})
        self.nominal = {key: float(value) for key, value in results.items()}

    @property
    def keys(self) -> list[str]:
        """Every numeric result of the kind that this spec has."""
        return list(self.nominal)

    @property
    def limit_values(self) -> dict[str, float]:
        """Result key -> its symmetric limit value from the spec."""
        return self.kind.limit_values(self.spec.solver_inputs())  # type: ignore[attr-defined]

    def evaluate(self, columns: NDArray, keys: Sequence[str] | None = None
                 ) -> tuple[dict[str, NDArray], NDArray]:
        """Results ``keys`` (default all; NaN where infeasible) and status codes at the
        designs in the rows of ``columns`` (n, d)."""
        keys = self.keys if keys is None else keys
        values = {item.name: columns[:, i] for i, item in enumerate(self.inputs)}
        wanted = {*keys, *self.margins}
        results, status = evaluate_with(self.kind, self.spec, values, wanted)
        bad = status != 0
        if not bad.any():  # the usual chunk: nothing to blank, no copies
            shape = np.broadcast_shapes(status.shape, *(np.shape(results[k]) for k in wanted))
            return {key: np.broadcast_to(results[key], shape) for key in wanted}, status
        return {key: np.where(bad, np.nan, results[key]) for key in wanted}, status

    @property
    def margins(self) -> list[str]:
        """The kind's margins that this spec has (a margin needs its limit)."""
        return [key for key in self.kind.margins if key in self.nominal]

    # --- worst case -------------------------------------------------------------------

    def worst_case(self) -> dict[str, dict[str, Any]]:
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
           solver call per pass (:meth:`_zoom`); more by L-BFGS-B (scipy.optimize),
           with gradients from one vectorised central-difference call per step.

        Infeasible designs (NaN) are skipped. Method: docs/physics.md §10.
        """
        low, width = self.box()
        unit = self.search_points()
        results, _ = self.scan_box(unit)
        rises = self._differences(unit, low, width)
        searches: list[_ExtremeSearch] = []
        starts: list[NDArray] = []
        out: dict[str, dict[str, Any]] = {}
        for key in self.keys:
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
        self._move_to(searches, starts, low, width)
        self._zoom([s for s in searches if 0 < s.free.size <= GRID_MAX_FREE], low, width)
        for search in searches:
            if search.free.size > GRID_MAX_FREE:
                search.point, search.value = self._refine(search.key, search.sign, search.point,
                                                          low, width)
            out[search.key][search.sense] = search.sign * search.value
            out[search.key][f"{search.sense}_inputs"] = {
                item.name: float(low[i] + search.point[i] * width[i])
                for i, item in enumerate(self.inputs)}
        return out

    def scan_box(self, unit: NDArray | None = None) -> tuple[dict[str, NDArray], NDArray]:
        """Results and status at the box's ``search_points`` (or ``unit``); records in
        ``box_impossible`` how much of the box is impossible designs."""
        low, width = self.box()
        unit = self.search_points() if unit is None else unit
        results, status = self.evaluate(low + unit * width)
        self.box_impossible = self._impossible_part(unit, status, low, width)
        return results, status

    def box(self) -> tuple[NDArray, NDArray]:
        """(low, width) of the tolerance box, input by input. [SI]"""
        return (np.array([item.low for item in self.inputs]),
                np.array([item.high - item.low for item in self.inputs]))

    def search_points(self) -> NDArray:
        """Where the worst case starts, in unit coordinates of the box: all 2^d corners
        (d <= MAX_CORNER_INPUTS), INTERIOR_POINTS scrambled Sobol' points, the centre."""
        from bearingcalc.tolerance.sobol import SobolStream

        d = len(self.inputs)
        if d <= MAX_CORNER_INPUTS:
            corners = np.array(list(itertools.product((0.0, 1.0), repeat=d)))
        else:
            corners = np.empty((0, d))
        interior = SobolStream(d, 0).next(INTERIOR_POINTS)
        return np.vstack([corners, interior, np.full((1, d), 0.5)])

    def _differences(self, unit: NDArray, low: NDArray, width: NDArray) -> dict[str, NDArray]:
        """Result key -> f(u + h·eᵢ) − f(u − h·eᵢ), shape (d, points), at every point u of
        ``unit`` and along every input i (h = PROBE_STEP of the box, kept inside it)."""
        d, n = unit.shape[1], unit.shape[0]
        probes = np.repeat(unit[None, None, :, :], 2, axis=0).repeat(d, axis=1)  # (2, d, n, d)
        for i in range(d):
            probes[0, i, :, i] = np.minimum(unit[:, i] + PROBE_STEP, 1.0)
            probes[1, i, :, i] = np.maximum(unit[:, i] - PROBE_STEP, 0.0)
        results, _ = self.evaluate(low + probes.reshape(-1, d) * width)
        with np.errstate(invalid="ignore"):  # inf − inf: an unbounded result, not monotonic
            return {key: (values[: d * n] - values[d * n:]).reshape(d, n)
                    for key, values in ((k, np.asarray(results[k])) for k in self.keys)}

    def _move_to(self, searches: list[_ExtremeSearch], starts: list[NDArray], low: NDArray,
                 width: NDArray) -> None:
        """Move each search to its start (its monotonic inputs at their bounds) unless
        the design there is impossible or worse (one solver call for all)."""
        if not searches:
            return
        results, _ = self.evaluate(low + np.array(starts) * width)
        for row, (search, start) in enumerate(zip(searches, starts, strict=True)):
            value = search.sign * float(results[search.key][row])
            if value <= search.value:   # False for NaN
                search.point, search.value = start, value

    def _zoom(self, searches: list[_ExtremeSearch], low: NDArray, width: NDArray) -> None:
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
            results, _ = self.evaluate(low + np.vstack(blocks) * width)
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

    def _impossible_part(self, unit: NDArray, status: NDArray, low: NDArray,
                         width: NDArray) -> dict[str, Any] | None:
        """How much of the worst-case search of the box hit impossible designs, and one
        of them (the first corner or point found) with the reason; None when none did."""
        bad = np.flatnonzero(status != 0)
        if bad.size == 0:
            return None
        first = int(bad[0])
        field, why = self.kind.status_reasons[int(status[first])]
        return {"fraction": bad.size / status.size,
                "inputs": {item.name: float(low[i] + unit[first, i] * width[i])
                           for i, item in enumerate(self.inputs)},
                "reason": f"{field}: {why}" if field else why}

    def _refine(self, key: str, sign: float, start: NDArray, low: NDArray, width: NDArray
                ) -> tuple[NDArray, float]:
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
            values = sign * self.evaluate(low + points * width)[0][key]
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

    # --- RSS ---------------------------------------------------------------------------

    def rss(self) -> dict[str, dict[str, Any]]:
        """First-order propagation: std = sqrt(Σ(∂f/∂xᵢ·σᵢ)²) at the distribution means.

        Derivatives are central differences with one Richardson step (error of
        order h⁴), all 4d + 1 designs in one solver call; h = σᵢ/100.
        """
        d = len(self.inputs)
        center = np.array([i.tolerance.center for i in self.inputs])
        sigma = np.array([i.tolerance.std for i in self.inputs])
        step = np.where(sigma > 0, sigma * 1e-2, 0.0)
        points = np.repeat(center[None, :], 4 * d + 1, axis=0)
        for i in range(d):
            for j, offset in enumerate((step[i], -step[i], step[i] / 2, -step[i] / 2)):
                points[1 + 4 * i + j, i] += offset
        results, _ = self.evaluate(points)
        out: dict[str, dict[str, Any]] = {}
        for key in self.keys:
            values = np.asarray(results[key])
            if not np.isfinite(values).all():
                # A result unbounded or impossible near the centre has no first-order spread.
                out[key] = {"mean": None, "std": None, "contributions": {}}
                continue
            derivatives = np.zeros(d)
            for i in range(d):
                if step[i] == 0:
                    continue
                f_up, f_down, f_up2, f_down2 = values[1 + 4 * i: 5 + 4 * i]
                coarse = (f_up - f_down) / (2 * step[i])
                fine = (f_up2 - f_down2) / step[i]
                derivatives[i] = (4 * fine - coarse) / 3
            terms = (derivatives * sigma) ** 2
            total = float(terms.sum())
            mean = float(values[0])
            if not (np.isfinite(mean) and np.isfinite(total)):
                out[key] = {"mean": None, "std": None, "contributions": {}}
                continue
            shares = terms / total if total > 0 else np.zeros(d)
            out[key] = {
                "mean": mean,
                "std": math.sqrt(total),
                "contributions": {item.name: float(shares[i])
                                  for i, item in enumerate(self.inputs)},
                "sensitivities": {item.name: float(derivatives[i])
                                  for i, item in enumerate(self.inputs)},
            }
        return out

    # --- Monte Carlo --------------------------------------------------------------------

    def draw(self, start: int, count: int, seed: int, sampler: str) -> NDArray:
        """Samples ``start`` to ``start + count`` of the study's sample stream, shape (count, d).

        The stream is the same however it is cut into pieces.
        """
        return self._shape(SampleStream(len(self.inputs), seed, sampler, start).next(count))

    def _shape(self, uniform: NDArray, normal_quantile: Callable[..., NDArray] | None = None
               ) -> NDArray:
        """The designs at uniform points (n, d): an (n, d) view of a (d, n) array, so
        that each input's values, which the solver reads whole, are contiguous."""
        quantile = normal_quantile or normal_quantile_function(len(uniform))
        out = np.empty((len(self.inputs), len(uniform)))
        for i, item in enumerate(self.inputs):
            inverse_cdf(item.tolerance, uniform[:, i], out[i], quantile)
        return out.T

    def monte_carlo(self, samples: int, seed: int = 0, sampler: str = "sobol", *,
                    chunk: int = 2 * BLOCK, threads: int = 2, keys: Sequence[str] | None = None,
                    progress: Callable[[int], None] | None = None) -> MonteCarloResult:
        """Statistics of every result (or of ``keys``) over ``samples`` drawn designs.

        The blocks of the sample stream are shared among ``threads`` workers in
        contiguous runs; each worker walks its run chunk by chunk with its own
        sample engine and statistics, and the statistics are merged at the end.
        numpy and scipy.special release the GIL, so the workers run in parallel.
        """
        if samples < 2:
            raise StudyError("--samples must be at least 2")
        if chunk % BLOCK:
            raise StudyError(f"the chunk size must be a multiple of {BLOCK}")
        keys = list(keys or self.keys)
        limits = self.limit_values
        normal_draws = samples * sum(item.tolerance.distribution == "normal"
                                     for item in self.inputs)
        quantile = normal_quantile_function(normal_draws)
        # The pilot is the stream's first block: it sets the histogram ranges, and its
        # results are then counted as that block instead of being solved again.
        pilot_count = min(samples, BLOCK)
        pilot_uniform = SampleStream(len(self.inputs), seed, sampler, 0).next(pilot_count)
        pilot, pilot_status = self.evaluate(self._shape(pilot_uniform, quantile), keys)
        template = {key: _Accumulator(self.nominal[key], pilot[key]) for key in keys}
        blocks = -(-samples // BLOCK)
        workers = max(1, min(threads, blocks))
        bounds = [blocks * w // workers for w in range(workers + 1)]

        stop_now = threading.Event()

        def work(first_block: int, end_block: int) -> tuple[dict[str, _Accumulator], int, int]:
            accumulators = {key: acc.empty_like() for key, acc in template.items()}
            scratch = _Scratch()
            passed = infeasible = 0
            start, stop = first_block * BLOCK, min(end_block * BLOCK, samples)

            def count(results: dict[str, NDArray], status: NDArray, size: int) -> None:
                nonlocal passed, infeasible
                ok = self.kind.within_limits(results, status)
                for key in keys:
                    accumulators[key].add(results[key], scratch)
                passed += int(np.count_nonzero(ok))
                infeasible += int(np.count_nonzero(status))
                if progress:
                    progress(size)

            if start == 0 and start < stop:
                count(pilot, pilot_status, pilot_count)
                start = pilot_count
            stream = SampleStream(len(self.inputs), seed, sampler, start)
            while start < stop and not stop_now.is_set():
                size = min(chunk, stop - start)
                results, status = self.evaluate(self._shape(stream.next(size), quantile), keys)
                count(results, status, size)
                start += size
            return accumulators, passed, infeasible

        pool = ThreadPoolExecutor(max_workers=workers)
        try:
            futures = [pool.submit(work, bounds[w], bounds[w + 1]) for w in range(workers)]
            outcomes = [future.result() for future in futures]
        except BaseException:
            # Ctrl-C: the workers stop at their next chunk (a fraction of a second)
            # instead of running the study to its end.
            stop_now.set()
            raise
        finally:
            pool.shutdown(wait=False, cancel_futures=True)
        merged = template
        passed = sum(outcome[1] for outcome in outcomes)
        infeasible = sum(outcome[2] for outcome in outcomes)
        for accumulators, _, _ in outcomes:
            for key in keys:
                merged[key].merge(accumulators[key])
        stats = {key: merged[key].summary() for key in keys}
        for key, limit in limits.items():
            if key in stats:
                stats[key]["cpk"] = _cpk(stats[key], limit)
        histograms = {key: merged[key].histogram() for key in keys}
        return MonteCarloResult(samples, seed, sampler, stats, histograms, passed, infeasible)

    def cpk(self, mc: MonteCarloResult) -> float | None:
        """The smallest Cpk over the kind's limits, or None without limits."""
        values = [mc.stats[key].get("cpk") for key in self.kind.limits if key in mc.stats]
        finite = [v for v in values if v is not None]
        return min(finite) if finite else None

    # --- Sobol indices -------------------------------------------------------------------

    def sobol(self, samples: int, seed: int = 0, keys: Sequence[str] | None = None
              ) -> dict[str, dict[str, dict[str, float]] | str]:
        """First- and total-order Sobol indices of each result (scipy.stats.sobol_indices).

        Uses n = the largest power of 2 <= ``samples`` (at least 2^10, at most
        2^16), which costs n·(d + 2) solver evaluations in one call. A result
        without indices gets the reason instead: it does not vary, or the design
        is impossible somewhere in the sample (scipy needs finite values and would
        otherwise return meaningless numbers).
        """
        from scipy import stats

        if len(self.inputs) < 2:
            raise StudyError("--sobol needs at least two toleranced inputs")
        n = 1 << max(10, min(16, int(math.log2(max(samples, 2)))))
        dists = [_frozen(item.tolerance, stats) for item in self.inputs]
        keys = list(keys or self.keys)
        impossible = np.zeros(len(keys), dtype=bool)
        constant = np.ones(len(keys), dtype=bool)

        def func(x: NDArray) -> NDArray:
            results, _ = self.evaluate(x.T, keys)
            outputs = np.vstack([results[key] for key in keys])
            finite = np.isfinite(outputs)
            impossible[:] |= ~finite.all(axis=1)
            outputs = np.where(finite, outputs, 0.0)
            constant[:] &= np.ptp(outputs, axis=1) == 0
            return outputs

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # rows without indices are reported below
            result = stats.sobol_indices(func=func, n=n, dists=dists, rng=seed)
        first = np.asarray(result.first_order)
        total = np.asarray(result.total_order)
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
                                    for i, item in enumerate(self.inputs)},
                    "total_order": {item.name: float(total[row, i])
                                    for i, item in enumerate(self.inputs)},
                }
        return out

    def input_summary(self) -> dict[str, dict[str, Any]]:
        """The JSON ``inputs`` object: nominal, band, distribution and std of each input."""
        return {item.name: {"nominal": float(field_value(self.spec, item.name)),
                            "low": item.low, "high": item.high,
                            "distribution": item.tolerance.distribution,
                            "std": item.tolerance.std}
                for item in self.inputs}


class SampleStream:
    """A uniform sample stream on (0, 1)^d from ``start`` on, drawn in pieces.

    ``sobol``: scrambled Sobol points, those of scipy.stats.qmc.Sobol bit for bit
    (:mod:`bearingcalc.tolerance.sobol`), from ``start`` on; ``random``: numpy's PCG64 advanced
    to ``start``. Either way the points are those of one sequence, however it is cut.
    """

    def __init__(self, d: int, seed: int, sampler: str, start: int = 0) -> None:
        self.d = d
        if sampler == "sobol":
            from bearingcalc.tolerance.sobol import SobolStream

            # scipy.stats.qmc.Sobol's points bit for bit, without importing scipy.stats.
            self.engine = SobolStream(d, seed, start)
            self.generator = None
        elif sampler == "random":
            bits = np.random.PCG64(seed)
            bits.advance(start * d)  # one 64-bit draw per double
            self.generator = np.random.Generator(bits)
        else:
            raise StudyError(f"unknown sampler {sampler!r}; use sobol or random")

    def next(self, count: int) -> NDArray:
        if self.generator is not None:
            # Drawn row by row as ever, then laid out column by column like the Sobol'
            # points, so that each input's values are contiguous.
            points = np.asfortranarray(self.generator.random((count, self.d)))
        else:
            points = self.engine.next(count)
        # Keep the inverse CDFs finite: a point exactly at 0 would map to −inf. (Neither
        # sampler reaches 1: Sobol' points are at most 1 − 2⁻³⁰, PCG64's 1 − 2⁻⁵³.)
        return np.maximum(points, 1e-300, out=points)


#: Normal draws in a study above which scipy.special.ndtri is worth its import (about
#: 0.3 s); below it, bearingcalc.tolerance.normal.ndtri, whose tails run per element in Python.
#: Both give the same bits, so the choice never shows in a result.
SCIPY_NDTRI_ABOVE = 1 << 21


def normal_quantile_function(draws: int) -> Callable[..., NDArray]:
    """The inverse normal CDF to use for ``draws`` normal values: scipy.special.ndtri
    or its bit-for-bit twin that needs no scipy import (see SCIPY_NDTRI_ABOVE)."""
    if draws > SCIPY_NDTRI_ABOVE:
        from scipy.special import ndtri

        return ndtri  # type: ignore[no-any-return]
    from bearingcalc.tolerance.normal import ndtri as light_ndtri

    return light_ndtri


def inverse_cdf(tolerance: Tolerance, u: NDArray, out: NDArray,
                normal_quantile: Callable[..., NDArray]) -> NDArray:
    """Map uniform points ``u`` to the tolerance's distribution, into ``out``;
    ``normal_quantile`` is the inverse normal CDF to use (normal_quantile_function)."""
    low, width = tolerance.low, tolerance.high - tolerance.low
    if tolerance.distribution == "uniform":
        np.multiply(u, width, out=out)
        return np.add(out, low, out=out)   # low + u·width
    if tolerance.distribution == "triangular":
        lower = low + width * np.sqrt(u / 2.0)
        upper = tolerance.high - width * np.sqrt((1.0 - u) / 2.0)
        out[...] = np.where(u < 0.5, lower, upper)
        return out
    normal_quantile(u, out=out)
    np.multiply(out, tolerance.std, out=out)
    return np.add(out, tolerance.center, out=out)   # center + std·Φ⁻¹(u)


def _frozen(tolerance: Tolerance, stats: Any) -> Any:
    low, width = tolerance.low, tolerance.high - tolerance.low
    if tolerance.distribution == "uniform":
        return stats.uniform(loc=low, scale=width)
    if tolerance.distribution == "triangular":
        return stats.triang(c=0.5, loc=low, scale=width)
    return stats.norm(loc=tolerance.center, scale=tolerance.std)


def _cpk(stats: dict[str, float | None], limit: float) -> float | None:
    mean, std = stats.get("mean"), stats.get("std")
    if mean is None or std is None or std <= 0:
        return None
    return min(limit - mean, mean + limit) / (3.0 * std)


class _Scratch:
    """One worker's temporary arrays, grown as needed and reused for every result and
    chunk, so that counting a chunk allocates nothing."""

    def __init__(self) -> None:
        self._floats = np.empty(0)
        self._ints = np.empty(0, dtype=np.int64)

    def floats(self, size: int) -> NDArray:
        if self._floats.size < size:
            self._floats = np.empty(size)
        return self._floats[:size]

    def ints(self, size: int) -> NDArray:
        if self._ints.size < size:
            self._ints = np.empty(size, dtype=np.int64)
        return self._ints[:size]


class _Accumulator:
    """Running statistics of one result, exact however the samples are chunked.

    Values are shifted by the nominal result before summing, which keeps the
    variance free of cancellation. Quantiles come from a histogram of
    ``HISTOGRAM_BINS`` bins spanning three times the range of the first
    ``BLOCK`` samples (the pilot), centred on it, plus one bin each side for
    values outside. A quantile interpolates between the two order statistics
    around it, each placed within its bin, so it is off by at most one bin
    width, 1/21845 of the pilot's range.
    """

    def __init__(self, shift: float, pilot: NDArray) -> None:
        self.shift = shift if math.isfinite(shift) else 0.0
        finite = pilot[np.isfinite(pilot)]
        low, high = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
        span = high - low
        if span <= 0:
            span = max(abs(low) * 1e-9, 1e-300)
        self.edge = low - span
        self.width = 3.0 * span / HISTOGRAM_BINS
        self.sums: list[float] = []
        self.squares: list[float] = []
        self.count = 0
        self.low, self.high = math.inf, -math.inf
        self.counts = np.zeros(HISTOGRAM_BINS + 2, dtype=np.int64)

    def empty_like(self) -> _Accumulator:
        """An accumulator with the same shift and bins and nothing counted."""
        twin = copy.copy(self)
        twin.sums, twin.squares = [], []
        twin.counts = np.zeros_like(self.counts)
        return twin

    def add(self, values: NDArray, scratch: _Scratch | None = None) -> None:
        """Count a chunk of values that starts on a block boundary; NaN is skipped.

        ``scratch`` holds the worker's temporary arrays, reused from chunk to chunk.
        """
        scratch = scratch or _Scratch()
        size = len(values)
        blocks = -(-size // BLOCK)
        padded = scratch.floats(blocks * BLOCK)
        shifted = padded[:size]
        np.subtract(values, self.shift, out=shifted)
        padded[size:] = 0.0
        per_block = padded.reshape(blocks, BLOCK)
        sums = per_block.sum(axis=1)
        kept = values
        if not np.isfinite(sums).all():
            # A NaN or an infinity somewhere in the chunk (a finite chunk's block sums
            # are finite unless they overflow): what is not finite counts as 0 here and
            # is left out of the count, the extremes and the histogram.
            finite = np.isfinite(values)
            shifted[~finite] = 0.0
            sums = per_block.sum(axis=1)
            kept = values[finite]
        self.sums.extend(sums.tolist())
        # np.sum's pairwise order depends only on the block, not on where the chunk
        # sits in memory (einsum's does), which keeps the result chunk-invariant.
        np.square(per_block, out=per_block)
        self.squares.extend(per_block.sum(axis=1).tolist())
        self.count += kept.size
        if kept.size == 0:
            return
        # + 0.0 makes a zero positive: which signed zero np.min meets first depends on
        # the chunking, and the result must not.
        low, high = float(kept.min()) + 0.0, float(kept.max()) + 0.0
        self.low, self.high = min(self.low, low), max(self.high, high)
        self._count(kept, low, high, scratch)

    def _count(self, values: NDArray, low: float, high: float, scratch: _Scratch) -> None:
        """Add finite ``values`` whose min and max are ``low`` and ``high`` to the
        histogram, in place (no 65,538-bin array to allocate, zero and add a chunk).

        A value's bin is floor((x − edge)·(1/width)) + 1, clipped to [0,
        HISTOGRAM_BINS + 1] (the two overflow bins), in that order of operations.
        """
        scale = 1.0 / self.width
        if low == high:
            # A result that does not vary (a speed the spec fixes): one bin takes all.
            index = math.floor((low - self.edge) * scale)
            self.counts[min(max(index, -1), HISTOGRAM_BINS) + 1] += len(values)
            return
        index = scratch.floats(len(values))
        np.subtract(values, self.edge, out=index)
        np.multiply(index, scale, out=index)
        bins = scratch.ints(len(values))
        # (x − edge)·scale rounds monotonically, so the chunk's extremes bound every
        # index: when all lie in [0, HISTOGRAM_BINS + 1), truncation is the floor and
        # nothing is clipped, and the same bins take three passes fewer.
        if (low - self.edge) * scale >= 0.0 and (high - self.edge) * scale < HISTOGRAM_BINS + 1:
            np.copyto(bins, index, casting="unsafe")
            np.add.at(self.counts[1:], bins, 1)   # bin floor(index) + 1
            return
        np.floor(index, out=index)
        np.clip(index, -1, HISTOGRAM_BINS, out=index)
        np.add(index, 1.0, out=index)
        np.copyto(bins, index, casting="unsafe")
        np.add.at(self.counts, bins, 1)

    def merge(self, other: _Accumulator) -> None:
        """Add another accumulator's counts (sums are exact, so order does not matter)."""
        self.sums.extend(other.sums)
        self.squares.extend(other.squares)
        self.count += other.count
        self.low = min(self.low, other.low)
        self.high = max(self.high, other.high)
        self.counts += other.counts

    def summary(self) -> dict[str, float | None]:
        n = self.count
        if n == 0:
            return {name: None for name in ("mean", "std", "min", "max", *QUANTILES)}
        total, squares = math.fsum(self.sums), math.fsum(self.squares)
        mean_shifted = total / n
        variance = max(squares - total * mean_shifted, 0.0) / (n - 1) if n > 1 else 0.0
        out: dict[str, float | None] = {
            "mean": self.shift + mean_shifted,
            "std": math.sqrt(variance),
            "min": self.low,
            "max": self.high,
        }
        for name, q in QUANTILES.items():
            out[name] = self.quantile(q)
        return out

    def quantile(self, q: float) -> float:
        """The q-quantile as numpy's default (linear) method defines it, placing the two
        order statistics around it each within its bin: off by at most one bin width."""
        if self.low == self.high:
            return self.low
        rank = q * (self.count - 1)
        below = math.floor(rank)
        cumulative = np.cumsum(self.counts)
        lower = self._order_statistic(cumulative, below)
        upper = self._order_statistic(cumulative, min(below + 1, self.count - 1))
        value = lower + (rank - below) * (upper - lower)
        return float(min(max(value, self.low), self.high))

    def _order_statistic(self, cumulative: NDArray, rank: int) -> float:
        index = int(np.searchsorted(cumulative, rank, side="right"))
        before = int(cumulative[index - 1]) if index > 0 else 0
        if index == 0:
            return self.low  # below the histogram: only the minimum is known
        if index == len(self.counts) - 1:
            return self.high
        fraction = (rank - before + 0.5) / int(self.counts[index])
        return self.edge + (index - 1 + fraction) * self.width

    def histogram(self) -> tuple[NDArray, NDArray]:
        """(edges, counts) of the in-range bins."""
        edges = self.edge + self.width * np.arange(HISTOGRAM_BINS + 1)
        return edges, self.counts[1:-1].copy()


def coarse_histogram(edges: NDArray, counts: NDArray, bins: int
                     ) -> tuple[NDArray, NDArray, NDArray]:
    """(low edges, high edges, counts) of at most ``bins`` bars merging the fine bins
    between the first and last occupied one; empty when nothing was counted."""
    occupied = np.flatnonzero(counts)
    if occupied.size == 0:
        return np.empty(0), np.empty(0), np.empty(0, dtype=np.int64)
    first, last = occupied[0], occupied[-1] + 1
    groups = np.array_split(np.arange(first, last), min(bins, last - first))
    lows = np.array([edges[g[0]] for g in groups])
    highs = np.array([edges[g[-1] + 1] for g in groups])
    totals = np.array([counts[g].sum() for g in groups], dtype=np.int64)
    return lows, highs, totals


@dataclass
class StudyReport:
    """Everything a tolerance run found: the contract's JSON object and the histograms."""

    record: dict[str, Any]
    histograms: dict[str, tuple[NDArray, NDArray]]
    governing: list[str]
    limits: dict[str, float]
    margins: tuple[str, ...]

    @property
    def within_limits(self) -> bool | None:
        """Whether every margin stays >= 0: at worst case if run, else in every sample."""
        results = self.record["results"]
        if self.record.get("impossible_in_box") or self.record.get("infeasible_samples"):
            return False  # a box holding impossible designs never passes
        if not self.margins:
            return None
        worst = [results[m].get("worst_case", {}).get("min") for m in self.margins]
        if all(w is not None for w in worst):
            return all(w >= 0 for w in worst)  # type: ignore[operator]
        if "yield" in self.record:
            return bool(self.record["yield"] == 1.0)  # Monte Carlo alone: every sample
        return None


def run_study(kind: Kind, spec: SpecModel, source: str, *, methods: Sequence[str],
              samples: int = 100_000, seed: int = 0, sampler: str = "sobol",
              sobol: bool = False, results: Sequence[str] = (), threads: int = 2,
              progress: Callable[[int], None] | None = None) -> StudyReport:
    """Run the chosen methods and assemble the report (SI units throughout).

    ``results`` narrows Monte Carlo and Sobol to those result keys (and names the
    governing results); worst case and RSS always cover every result.
    """
    if not methods:
        raise StudyError(f"--method names no method; use one or more of {', '.join(METHODS)}")
    unknown = [m for m in methods if m not in METHODS]
    if unknown:
        raise StudyError(f"unknown method {unknown[0]!r}; use {', '.join(METHODS)}")
    if sampler not in SAMPLERS:
        raise StudyError(f"unknown sampler {sampler!r}; use {' or '.join(SAMPLERS)}")
    if sampler == "sobol" and "monte-carlo" in methods and samples > SOBOL_MAX_SAMPLES:
        raise StudyError(f"--samples {samples} is more than the {SOBOL_MAX_SAMPLES} distinct "
                         "Sobol' points of 30 bits; use --sampler random for more")
    study = Study(kind, spec)
    missing = [key for key in results if key not in study.keys]
    if missing:
        raise StudyError(f"--result {missing[0]!r} is not a result of this {kind.name} spec; "
                         f"choose from {', '.join(study.keys)}")
    governing = list(results) or [key for key in kind.governing if key in study.keys]
    focus = list(results) or study.keys
    record: dict[str, Any] = {
        "spec": source, "kind": kind.name, "name": getattr(spec, "name", None),
        "inputs": study.input_summary(),
        "results": {key: {"nominal": value} for key, value in study.nominal.items()},
        "units": {**{key: kind.results[key][0] for key in study.keys},
                  **{item.name: item.tolerance.unit for item in study.inputs}},
        "warnings": [],
    }
    if "worst-case" in methods:
        for key, entry in study.worst_case().items():
            record["results"][key]["worst_case"] = entry
    else:
        # Every method must know when the box crosses a validity edge, not only the
        # worst case: RSS at the centre and a lucky sample would otherwise pass it.
        study.scan_box()
    if study.box_impossible is not None:
        box = study.box_impossible
        record["impossible_in_box"] = box
        at = ", ".join("{} = {:.6g} {}".format(name, *to_display(value, record["units"][name]))
                       for name, value in box["inputs"].items())
        covers = ("worst case covers only the possible part, and " if "worst-case" in methods
                  else "")
        record["warnings"].append(
            f"{100 * box['fraction']:.3g} % of the worst-case search of the tolerance box "
            f"are impossible designs, e.g. at {at} ({box['reason']}); {covers}the study "
            "fails")
    if "rss" in methods:
        for key, entry in study.rss().items():
            record["results"][key]["rss"] = entry
    histograms: dict[str, tuple[NDArray, NDArray]] = {}
    if "monte-carlo" in methods:
        mc = study.monte_carlo(samples, seed, sampler, threads=threads,
                               keys=list(dict.fromkeys([*focus, *study.margins])),
                               progress=progress)
        for key, stats in mc.stats.items():
            record["results"][key]["monte_carlo"] = stats
        record.update({"samples": samples, "seed": seed, "sampler": sampler,
                       "yield": mc.yield_fraction, "ppm_out": mc.ppm_out,
                       "cpk": study.cpk(mc), "infeasible_samples": mc.infeasible})
        if mc.infeasible:
            record["warnings"].append(f"{mc.infeasible} of {samples} samples are impossible "
                                      "designs; they count as out of spec")
        histograms = mc.histograms
    if sobol:
        for key, entry in study.sobol(samples, seed, focus).items():
            if isinstance(entry, str):
                record["warnings"].append(f"{key}: no Sobol indices, {entry}")
            else:
                record["results"][key]["sobol"] = entry
    return StudyReport(_finite(record), histograms, governing, study.limit_values,
                       tuple(study.margins))


def _finite(value: Any) -> Any:
    """The record with every non-finite float replaced by None (JSON has no NaN)."""
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, list):
        return [_finite(item) for item in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value
