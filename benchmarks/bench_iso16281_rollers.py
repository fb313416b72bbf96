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

import _chunked  # noqa: E402
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


def main() -> None:
    parser = _chunked.parser(__doc__, designs=10_000)
    parser.add_argument("--laminae", type=int, default=30)
    args = parser.parse_args()
    geometry, loads = designs(args.designs, args.laminae, args.seed)
    _chunked.one_call(solve_roller_equilibrium, geometry, loads, args.runs, TARGET,
                      f"{args.designs} designs of {args.laminae} laminae")
    if args.large:
        geometry, loads = designs(args.large, args.laminae, args.seed + 1)
        _chunked.in_chunks(solve_roller_equilibrium, geometry, loads, args.chunk)
    _chunked.peak_memory()


if __name__ == "__main__":
    main()
