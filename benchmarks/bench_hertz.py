"""Hertz point-contact solves per second, in one process (target >= 2 M contacts/s).

Solves 4,000,000 ball-in-groove contacts (random loads and race curvatures of
deep-groove bearings) in one call of `hertz_point_contact`, several times, and
prints the best and median rates. Run from the repository root:

    python benchmarks/bench_hertz.py [--contacts 4000000] [--runs 5]
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from bearingcalc.core.hertz import hertz_point_contact


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--contacts", type=int, default=4_000_000)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    n = args.contacts
    dw = rng.uniform(5e-3, 25e-3, n)
    gamma = rng.uniform(0.1, 0.3, n)
    conformity = rng.uniform(0.505, 0.54, n)
    inputs = (rng.uniform(10.0, 5000.0, n), 2 / dw, 2 / dw, 2 * gamma / (dw * (1 - gamma)),
              -1 / (conformity * dw), 207.5e9, 0.3, 207.5e9, 0.3)
    hertz_point_contact(*(x[:1000] if isinstance(x, np.ndarray) else x for x in inputs))
    rates = []
    for _ in range(args.runs):
        start = time.perf_counter()
        out = hertz_point_contact(*inputs)
        rates.append(n / (time.perf_counter() - start))
    assert np.isfinite(out["max_pressure"]).all()
    print(f"{n} contacts, {args.runs} runs: median {statistics.median(rates) / 1e6:.2f} M/s, "
          f"best {max(rates) / 1e6:.2f} M/s (target >= 2 M contacts/s)")


if __name__ == "__main__":
    main()
