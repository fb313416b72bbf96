"""Monte Carlo: statistics of every result, the yield and the process capability over
drawn designs, streamed in chunks by parallel threads.

Samples are drawn and solved in chunks, and only running statistics are kept, so
memory does not grow with the number of samples. The sample stream is one
sequence, whatever the chunk size or the number of threads: chunk k starts the
Sobol stream at its first sample, or advances the PCG64 generator, to its first
sample. Sums are taken per fixed block of ``BLOCK`` samples and added exactly
(``math.fsum``), and histogram counts are integers, so the statistics do not
depend on chunking or threads either.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.studies.accumulator import BLOCK, _Accumulator, _Scratch
from bearingcalc.studies.sampling import SampleStream, designs_at, normal_quantile_function
from bearingcalc.studies.study import Study, StudyError


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


def monte_carlo(study: Study, samples: int, seed: int = 0, sampler: str = "sobol", *,
                chunk: int = 2 * BLOCK, threads: int = 2, keys: Sequence[str] | None = None,
                progress: Callable[[int], None] | None = None) -> MonteCarloResult:
    """Statistics of every result (or of ``keys``) over ``samples`` drawn designs.

    The blocks of the sample stream are shared among ``threads`` workers in
    contiguous runs; each worker walks its run chunk by chunk with its own
    sample engine and statistics, and the statistics are merged at the end.
    numpy and scipy.special release the GIL, so the workers run in parallel.
    """
    if samples < 2:
        raise StudyError("must be at least 2", "--samples")
    if chunk % BLOCK:
        raise StudyError(f"the chunk size must be a multiple of {BLOCK}")
    keys = list(keys or study.keys)
    d = len(study.inputs)
    quantile = normal_quantile_function(samples * sum(
        item.tolerance.distribution == "normal" for item in study.inputs))
    # The pilot is the stream's first block: it sets the histogram ranges, and its
    # results are then counted as that block instead of being solved again.
    pilot_count = min(samples, BLOCK)
    pilot_uniform = SampleStream(d, seed, sampler, 0).next(pilot_count)
    pilot, pilot_status = study.evaluate(designs_at(study.inputs, pilot_uniform, quantile),
                                         keys)
    template = {key: _Accumulator(study.nominal[key], pilot[key]) for key in keys}
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
            ok = study.kind.within_limits(results, status)
            for key in keys:
                accumulators[key].add(results[key], scratch)
            passed += int(np.count_nonzero(ok))
            infeasible += int(np.count_nonzero(status))
            if progress:
                progress(size)

        if start == 0 and start < stop:
            count(pilot, pilot_status, pilot_count)
            start = pilot_count
        stream = SampleStream(d, seed, sampler, start)
        while start < stop and not stop_now.is_set():
            size = min(chunk, stop - start)
            # The chunk's designs are a temporary, freed once solved: their memory then
            # takes the next chunk's draws instead of fresh pages.
            results, status = study.evaluate(
                designs_at(study.inputs, stream.next(size), quantile), keys)
            count(results, status, size)
            start += size
        return accumulators, passed, infeasible

    outcomes = _run_workers(work, bounds, stop_now)
    stats, histograms = _merged_statistics(template, [outcome[0] for outcome in outcomes],
                                           keys, study.limit_values)
    return MonteCarloResult(samples, seed, sampler, stats, histograms,
                            sum(outcome[1] for outcome in outcomes),
                            sum(outcome[2] for outcome in outcomes))


def _merged_statistics(template: dict[str, _Accumulator],
                       per_worker: list[dict[str, _Accumulator]], keys: Sequence[str],
                       limits: dict[str, float]
                       ) -> tuple[dict[str, dict[str, Any]], dict[str, Any]]:
    """The workers' statistics merged, on the pilot's shift and bins (``template``, which
    counts nothing): each result's summary, with its Cpk where it has a limit, and its
    histogram."""
    merged = {key: template[key].empty_like() for key in keys}
    for accumulators in per_worker:
        for key in keys:
            merged[key].merge(accumulators[key])
    stats = {key: merged[key].summary() for key in keys}
    for key, limit in limits.items():
        if key in stats:
            stats[key]["cpk"] = _cpk(stats[key], limit)
    histograms = {key: merged[key].histogram() for key in keys}
    return stats, histograms


def _run_workers(work: Callable[[int, int], Any], bounds: list[int],
                 stop_now: threading.Event) -> list[Any]:
    """``work(bounds[w], bounds[w + 1])`` for each worker w on a thread of its own; their
    outcomes in order.

    The threads are daemons and the wait for them wakes every tenth of a second: on
    Ctrl-C the workers are told to stop at their next chunk and the run ends at once,
    never held at exit by a worker still in its chunk (a pool's threads are joined then).
    """
    outcomes: list[Any] = [None] * (len(bounds) - 1)
    failures: list[BaseException] = []

    def run(w: int) -> None:
        try:
            outcomes[w] = work(bounds[w], bounds[w + 1])
        except BaseException as exc:  # handed to the main thread, which raises it
            failures.append(exc)
            stop_now.set()

    threads = [threading.Thread(target=run, args=(w,), daemon=True)
               for w in range(len(bounds) - 1)]
    try:
        for thread in threads:
            thread.start()
        for thread in threads:
            while thread.is_alive():
                thread.join(0.1)
    except BaseException:
        stop_now.set()
        raise
    if failures:
        raise failures[0]
    return outcomes


def smallest_cpk(study: Study, mc: MonteCarloResult) -> float | None:
    """The smallest Cpk over the kind's limits, or None without limits."""
    values = [mc.stats[key].get("cpk") for key in study.kind.limits if key in mc.stats]
    finite = [v for v in values if v is not None]
    return min(finite) if finite else None


def one_sided_capability(study: Study, mc: MonteCarloResult) -> dict[str, dict[str, Any]]:
    """Each margin's process capability against its one limit: Cpl of a quantity held
    above a lower limit (a life, a safety), Cpu of one held below an upper limit (a
    pressure), both the margin's mean over three of its standard deviations.

    A margin is its quantity's distance to the limit on a scale of its own (m = Q/L − 1,
    Q − L, or 1 − Q/L), an affine map with a positive or negative slope, so the
    margin's μ/3σ is the quantity's (μ − LSL)/3σ or (USL − μ)/3σ exactly.
    """
    out: dict[str, dict[str, Any]] = {}
    for key in study.margins:
        stats = mc.stats.get(key, {})
        mean, std = stats.get("mean"), stats.get("std")
        if mean is None or std is None or not std > 0:
            continue
        judged = study.kind.judged.get(key)
        at_least = True if judged is None else judged.at_least
        out[key] = {"index": "Cpl" if at_least else "Cpu", "value": mean / (3.0 * std),
                    "of": key if judged is None else judged.named(study.nominal)}
    return out


def _cpk(stats: dict[str, float | None], limit: float) -> float | None:
    """Cpk = min(L − μ, μ + L) / 3σ of a result held to |x| <= L; None without a spread."""
    mean, std = stats.get("mean"), stats.get("std")
    if mean is None or std is None or std <= 0:
        return None
    return min(limit - mean, mean + limit) / (3.0 * std)
