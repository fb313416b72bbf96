"""ISO/TS 16281 roller-bearing equilibria solved per second, in one process,
single-threaded numpy (target >= 5,000 designs/s with 30 laminae, peak memory < 400 MB).

Random cylindrical bearings (diametral clearance −5 to 40 µm) and tapered bearings at
the cup's angle (8° to 28°), half each, in one batch: Z 10 to 25, Dwe 5 to 25 mm,
Lwe 0.7 to 3.5·Dwe, ISO's logarithmic profile on 30 laminae, radial load 500 N to
40 kN, a tapered bearing's axial load 1.3 to 3 times Fr·tan α and a tilting moment of
±2 % of Fr·Lwe. Times `solve_roller_equilibrium` on the batch (median of the runs),
then one run of `--large` designs in calls of `--chunk`, and the peak resident memory.
Run from the repository root:

    python benchmarks/bench_iso16281_rollers.py [--designs 10000] [--runs 3]
        [--large 100000] [--chunk 10000] [--laminae 30] [--seed 0]
"""

from __future__ import annotations

import os

for _variable in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")

import argparse  # noqa: E402
import resource  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from bearingcalc.core.iso16281_rollers import (  # noqa: E402
    RollerGeometry,
    roller_geometry,
    solve_roller_equilibrium,
)

TARGET = 5_000


def designs(n: int, laminae: int, seed: int) -> tuple[RollerGeometry, np.ndarray]:
    """n random bearings (the first half cylindrical, the rest tapered) and their loads
    (Fx, Fy, Fz, My, Mz) [N, N·m]."""
    rng = np.random.default_rng(seed)
    tapered = np.arange(n) >= n // 2
    z = rng.integers(10, 26, n).astype(float)
    dwe = rng.uniform(5e-3, 25e-3, n)
    lwe = dwe * rng.uniform(0.7, 3.5, n)
    alpha = np.where(tapered, rng.uniform(np.radians(8), np.radians(28), n), 0.0)
    clearance = np.where(tapered, 0.0, rng.uniform(-5e-6, 40e-6, n))
    geometry = roller_geometry(z, dwe, lwe, alpha, diametral_clearance=clearance,
                               laminae=laminae)
    fr = rng.uniform(500.0, 4e4, n)
    fa = np.where(tapered, fr * np.tan(alpha) * rng.uniform(1.3, 3.0, n), 0.0)
    moment = rng.uniform(-1, 1, n) * fr * lwe * 0.02
    zero = np.zeros(n)
    return geometry, np.stack([fa, fr, zero, zero, moment], axis=1)


def timed(geometry: RollerGeometry, loads: np.ndarray, chunk: int) -> tuple[float, bool]:
    """Seconds to solve every design, ``chunk`` designs a call; whether all converged."""
    start = time.perf_counter()
    ok = True
    for first in range(0, loads.shape[0], chunk):
        part = RollerGeometry(*(a[first:first + chunk] for a in geometry))
        solved = solve_roller_equilibrium(part, loads[first:first + chunk])
        ok = ok and bool(solved.converged.all() and np.max(solved.residual) < 1e-9)
    return time.perf_counter() - start, ok


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--designs", type=int, default=10_000)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--large", type=int, default=100_000, help="0 skips the large run")
    parser.add_argument("--chunk", type=int, default=10_000,
                        help="designs per call in the large run")
    parser.add_argument("--laminae", type=int, default=30)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    geometry, loads = designs(args.designs, args.laminae, args.seed)
    solve_roller_equilibrium(RollerGeometry(*(a[:100] for a in geometry)), loads[:100])
    times = []
    for _ in range(args.runs):
        seconds, ok = timed(geometry, loads, args.designs)
        assert ok, "a design did not converge"
        times.append(seconds)
    rate = args.designs / statistics.median(times)
    print(f"{args.designs} designs of {args.laminae} laminae in one call, {args.runs} runs: "
          f"median {statistics.median(times):.3f} s = {rate:,.0f} designs/s, best "
          f"{args.designs / min(times):,.0f}/s (target >= {TARGET:,}/s)")
    if args.large:
        geometry, loads = designs(args.large, args.laminae, args.seed + 1)
        seconds, ok = timed(geometry, loads, args.chunk)
        assert ok, "a design did not converge"
        print(f"{args.large} designs in chunks of {args.chunk}: {seconds:.2f} s = "
              f"{args.large / seconds:,.0f} designs/s")
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"peak resident memory: {peak:.0f} MB (target < 400 MB)")


if __name__ == "__main__":
    main()
