"""What the ISO/TS 16281 equilibrium benchmarks share: their options, solving a batch
of designs in calls of a given size against the clock, and the lines they print.

The solver is an argument (``solve(geometry, loads)``, returning ``converged`` and
``residual`` per design), and a batch's geometry a named tuple of per-design arrays,
so one loop times the ball and the roller solvers alike. The scripts set the BLAS
thread counts before numpy is first imported; import this module after that.
"""

from __future__ import annotations

import argparse
import resource
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np

#: Designs solved once before the clock starts, so that imports and first-call caches
#: stay out of the first run.
WARM_UP = 100


def parser(doc: str, designs: int) -> argparse.ArgumentParser:
    """The options both benchmarks take; a large run's calls default to one batch."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--designs", type=int, default=designs)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--large", type=int, default=100_000, help="0 skips the large run")
    parser.add_argument("--chunk", type=int, default=designs,
                        help="designs per call in the large run")
    parser.add_argument("--seed", type=int, default=0)
    return parser


def head(geometry: Any, count: int) -> Any:
    """The first ``count`` designs of a batch's geometry."""
    return type(geometry)(*(a[:count] for a in geometry))


def timed(solve: Callable, geometry: Any, loads: np.ndarray, chunk: int) -> tuple[float, bool]:
    """Seconds to solve every design, ``chunk`` designs a call; whether all converged."""
    start = time.perf_counter()
    ok = True
    for first in range(0, loads.shape[0], chunk):
        part = type(geometry)(*(a[first:first + chunk] for a in geometry))
        solved = solve(part, loads[first:first + chunk])
        ok = ok and bool(solved.converged.all() and np.max(solved.residual) < 1e-9)
    return time.perf_counter() - start, ok


def one_call(solve: Callable, geometry: Any, loads: np.ndarray, runs: int, target: int,
             batch: str) -> None:
    """Time the whole batch in one call ``runs`` times and print the median rate beside
    ``target``; ``batch`` names it ("30000 designs")."""
    solve(head(geometry, WARM_UP), loads[:WARM_UP])
    designs = loads.shape[0]
    times = []
    for _ in range(runs):
        seconds, ok = timed(solve, geometry, loads, designs)
        assert ok, "a design did not converge"
        times.append(seconds)
    rate = designs / statistics.median(times)
    print(f"{batch} in one call, {runs} runs: median {statistics.median(times):.3f} s = "
          f"{rate:,.0f} designs/s, best {designs / min(times):,.0f}/s "
          f"(target >= {target:,}/s)")


def in_chunks(solve: Callable, geometry: Any, loads: np.ndarray, chunk: int) -> None:
    """Time and print one run of the batch in calls of ``chunk`` designs."""
    seconds, ok = timed(solve, geometry, loads, chunk)
    assert ok, "a design did not converge"
    designs = loads.shape[0]
    print(f"{designs} designs in chunks of {chunk}: {seconds:.2f} s = "
          f"{designs / seconds:,.0f} designs/s")


def peak_memory() -> None:
    """Print the process's peak resident memory against the benchmarks' target."""
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"peak resident memory: {peak:.0f} MB (target < 400 MB)")
