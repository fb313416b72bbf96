"""Monte Carlo speed and memory of `bearingcalc tolerance`, beside a plain numpy loop.

The spec is benchmarks/tolerance-bench.yaml: a thrust bearing with three
toleranced inputs. Measured, in one run, and printed as ratios to the reference:

1. the reference: a plain single-threaded numpy loop over chunks of 10^6 samples
   (draw three normals, evaluate the spin-to-roll ratio, count the yield),
   timed inside the process, at 10^7 samples and at the large size (10^8);
2. `bearingcalc tolerance --method monte-carlo`, end to end (a cold process, CLI
   included): every result at 10^7 samples ÷ the reference at 10^7 (target <= 2.0);
   `--result spin_to_roll` at 10^7 with both cores and with `--jobs 1` (how well the
   two threads share the machine), and at the large size ÷ the reference at that
   size (target <= 0.67);
3. peak resident memory of the large run (target < 400 MB).

    python benchmarks/bench_tolerance.py [--samples 10000000] [--large-samples 100000000]

``--large-samples 0`` leaves the large run (its reference loop and its CLI run) out.
"""

from __future__ import annotations

import argparse
import math
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
SPEC = ROOT / "benchmarks" / "tolerance-bench.yaml"


def reference_loop(samples: int, chunk: int = 1_000_000) -> float:
    """Samples per second of the plain reference loop (point 1 above)."""
    rng = np.random.default_rng(0)
    limit = 0.004
    start = time.perf_counter()
    passed = 0
    for first in range(0, samples, chunk):
        n = min(chunk, samples - first)
        r = 0.00635 + rng.standard_normal(n) * (0.0025e-3 / 3)
        theta = math.radians(30) + rng.standard_normal(n) * (math.radians(0.25) / 3)
        b = 0.026 + rng.standard_normal(n) * (0.03e-3 / 3)
        sin, cos = np.sin(theta), np.cos(theta)
        k = r * (1 + sin + cos) / (b - r * cos)
        rho = (k * sin + sin - cos) / (k * cos + sin + cos)
        passed += int(np.count_nonzero(np.abs(rho) <= limit))
    return samples / (time.perf_counter() - start)


def cli_run(samples: int, *extra: str) -> float:
    command = [str(Path(sys.executable).parent / "bearingcalc"), "tolerance", str(SPEC),
               "--method", "monte-carlo", "--samples", str(samples), "--format", "json",
               *extra]
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          check=False)
    elapsed = time.perf_counter() - start
    if done.returncode not in (0, 1):
        raise SystemExit(done.stderr.decode())
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=10_000_000)
    parser.add_argument("--large-samples", type=int, default=100_000_000)
    args = parser.parse_args()
    n, large = args.samples, args.large_samples
    reference = n / reference_loop(n)
    print(f"reference numpy loop, {n:.0e} samples (1 thread, in-process): {reference:.2f} s")
    runs = {
        "every result, both cores": (),
        "spin_to_roll, both cores": ("--result", "spin_to_roll"),
        "spin_to_roll, --jobs 1": ("--result", "spin_to_roll", "--jobs", "1"),
        "spin_to_roll, --sampler random": ("--result", "spin_to_roll", "--sampler", "random"),
    }
    for label, extra in runs.items():
        elapsed = min(cli_run(n, *extra) for _ in range(2))
        target = " (target <= 2.0)" if not extra else ""
        print(f"bearingcalc {label:34} {elapsed:5.2f} s for {n:.0e} = "
              f"{elapsed / reference:.2f}x the reference{target}")
    if large:
        reference_large = large / reference_loop(large)
        elapsed = cli_run(large, "--result", "spin_to_roll")
        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        print(f"reference numpy loop, {large:.0e} samples: {reference_large:.2f} s; bearingcalc "
              f"spin_to_roll, both cores: {elapsed:.2f} s = {elapsed / reference_large:.2f}x "
              "(target <= 0.67)")
        print(f"peak resident memory of any of these runs: {peak:.0f} MB (target < 400 MB)")


if __name__ == "__main__":
    main()
