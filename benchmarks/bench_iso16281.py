"""ISO/TS 16281 ball-bearing equilibria solved per second, in one process, single-threaded
numpy (target >= 30,000 designs/s, peak memory < 400 MB).

Random deep-groove bearings (diametral clearance -5 to 30 µm) and angular-contact
bearings at their free contact angle (15° to 40°), half each, in one batch: Z 7 to 16,
Dw 5 to 15 mm, Dpw 3.5 to 6·Dw, conformities 0.505 to 0.55, radial load 100 to 5000 N,
an axial load (deep groove: up to half the radial; angular contact: 1.3 to 3 times
Fr·tan α0) and a tilting moment of ±5 % of Fr·Dpw in the load plane; each spring
constant by exact Hertz (`ball_spring_constant`). Times `solve_ball_equilibrium` on the
batch (median of the runs), prints the Newton iterations' distribution, then one run of
10^5 designs in chunks, and the peak resident memory. Run from the repository root:

    python benchmarks/bench_iso16281.py [--designs 30000] [--runs 3]
        [--large 100000] [--chunk 30000] [--seed 0]
"""

from __future__ import annotations

import os

for _variable in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")

import _chunked  # noqa: E402
import numpy as np  # noqa: E402

from bearingcalc.core import iso16281_balls  # noqa: E402
from bearingcalc.core.iso16281_ball_contacts import BallGeometry, ball_geometry  # noqa: E402
from bearingcalc.core.iso16281_life import ball_spring_constant  # noqa: E402

TARGET = 30_000


def designs(n: int, seed: int) -> tuple[BallGeometry, np.ndarray]:
    """n random bearings (the first half deep-groove, the rest angular-contact) and
    their loads (Fx, Fy, Fz, My, Mz) [N, N·m]."""
    rng = np.random.default_rng(seed)
    half = n // 2
    z = rng.integers(7, 17, n).astype(float)
    dw = rng.uniform(5e-3, 15e-3, n)
    dpw = dw * rng.uniform(3.5, 6.0, n)
    fi, fe = rng.uniform(0.505, 0.55, n), rng.uniform(0.505, 0.55, n)
    alpha = np.where(np.arange(n) < half, 0.0, rng.uniform(np.radians(15), np.radians(40), n))
    k = ball_spring_constant(dw, dpw, fi, fe, alpha, 2.1e11, 0.3)
    clearance = rng.uniform(-5e-6, 30e-6, n)
    deep, angular = slice(0, half), slice(half, n)
    families = (ball_geometry(z[deep], dw[deep], dpw[deep], fi[deep], fe[deep], k[deep],
                              diametral_clearance=clearance[deep]),
                ball_geometry(z[angular], dw[angular], dpw[angular], fi[angular],
                              fe[angular], k[angular], free_contact_angle=alpha[angular]))
    geometry = BallGeometry(*(np.concatenate(parts) for parts in zip(*families, strict=True)))
    fr = rng.uniform(100.0, 5000.0, n)
    fa = np.where(np.arange(n) < half, rng.uniform(0.0, 0.5, n) * fr,
                  fr * np.tan(alpha) * rng.uniform(1.3, 3.0, n))
    moment = rng.uniform(-0.05, 0.05, n) * fr * dpw
    zero = np.zeros(n)
    return geometry, np.stack([fa, fr, zero, zero, moment], axis=1)


def iterations(geometry: BallGeometry, loads: np.ndarray) -> list[int]:
    """How many Newton iterations each design took, counted by solving with every
    iteration budget from 1 up (cheap at a small sample)."""
    budget = iso16281_balls.MAX_ITERATIONS
    taken = np.full(loads.shape[0], budget + 1)
    try:
        for limit in range(1, budget + 1):
            iso16281_balls.MAX_ITERATIONS = limit
            done = iso16281_balls.solve_ball_equilibrium(geometry, loads).converged
            taken = np.where(done & (taken > budget), limit, taken)
            if (taken <= budget).all():
                break
    finally:
        iso16281_balls.MAX_ITERATIONS = budget
    return taken.tolist()


def main() -> None:
    args = _chunked.parser(__doc__, designs=30_000).parse_args()
    solve = iso16281_balls.solve_ball_equilibrium
    geometry, loads = designs(args.designs, args.seed)
    _chunked.one_call(solve, geometry, loads, args.runs, TARGET, f"{args.designs} designs")
    sample = 2000
    counts = iterations(_chunked.head(geometry, sample), loads[:sample])
    quartiles = np.percentile(counts, [50, 90, 99, 100])
    print(f"Newton iterations over the first {sample} designs: median {quartiles[0]:.0f}, "
          f"90 % {quartiles[1]:.0f}, 99 % {quartiles[2]:.0f}, max {quartiles[3]:.0f}")
    if args.large:
        geometry, loads = designs(args.large, args.seed + 1)
        _chunked.in_chunks(solve, geometry, loads, args.chunk)
    _chunked.peak_memory()


if __name__ == "__main__":
    main()
