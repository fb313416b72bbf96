"""Monte Carlo speed and memory of `bearingcalc tolerance`, beside a plain numpy loop.

The spec is benchmarks/tolerance-bench.yaml: a thrust bearing with three
toleranced inputs. Measured, in one run:

1. the reference: a plain single-threaded numpy loop over chunks of 10^6 samples
   (draw three normals, evaluate the spin-to-roll ratio, count the yield),
   timed inside the process;
2. `bearingcalc tolerance --method monte-carlo --result spin_to_roll`, 10^7
   samples, end to end (a cold process, CLI included), with both cores and with
   `--jobs 1`; and the same for every result of the kind;
3. peak resident memory of a 10^8-sample run.

    python benchmarks/bench_tolerance.py [--samples 10000000] [--memory-samples 100000000]
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
    """Samples per second of the plain loop the issue describes."""
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


def engine_rate(samples: int) -> float:
    """Samples per second of the Monte Carlo engine alone (imports and set-up excluded)."""
    from bearingcalc.evaluation import load_one_spec
    from bearingcalc.tolerance import Study

    kind, spec, _ = load_one_spec(SPEC)
    study = Study(kind, spec)
    study.monte_carlo(1 << 16, keys=["spin_to_roll"])  # imports and first-call costs
    start = time.perf_counter()
    study.monte_carlo(samples, keys=["spin_to_roll"])
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
    parser.add_argument("--memory-samples", type=int, default=100_000_000)
    args = parser.parse_args()
    n = args.samples
    reference = reference_loop(n)
    print(f"reference numpy loop (1 thread, in-process)     {reference / 1e6:6.1f} M samples/s")
    engine = engine_rate(n)
    print(f"bearingcalc engine in-process, spin_to_roll, both cores {engine / 1e6:6.1f} "
          f"M samples/s ({engine / reference:.2f}x the reference)")
    runs = {
        "bearingcalc, spin_to_roll, both cores": ("--result", "spin_to_roll"),
        "bearingcalc, spin_to_roll, --sampler random": ("--result", "spin_to_roll",
                                                        "--sampler", "random"),
        "bearingcalc, spin_to_roll, --jobs 1": ("--result", "spin_to_roll", "--jobs", "1"),
        "bearingcalc, every result, both cores": (),
    }
    for label, extra in runs.items():
        elapsed = min(cli_run(n, *extra) for _ in range(2))
        print(f"{label:46} {n / elapsed / 1e6:6.1f} M samples/s end to end "
              f"({elapsed:.2f} s for {n:.0e}, {n / elapsed / reference:.2f}x the reference)")
    if args.memory_samples:
        start = time.perf_counter()
        cli_run(args.memory_samples, "--result", "spin_to_roll")
        elapsed = time.perf_counter() - start
        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        print(f"{args.memory_samples:.0e} samples: {elapsed:.1f} s, peak resident memory of "
              f"the largest run {peak:.0f} MB (target < 500 MB)")


if __name__ == "__main__":
    main()
