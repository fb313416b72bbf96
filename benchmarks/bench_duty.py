"""Speed of duty cycles: a drive with 10 bins against the same drive at one point, and a
Monte Carlo study of a bearing's 10-bin duty cycle.

1. Cold `bearingcalc solve` of specs/bevel-drive.yaml, and of the same drive with a
   10-bin duty cycle (written to a temporary file), alternating runs, medians
   (target: the cycle within 10 % of the single point).
2. `bearingcalc tolerance --method monte-carlo --jobs 1` of the 6309 of
   specs/rolling-bearing-duty-cycle.yaml with 10 bins and a tolerance on each bin's
   radial load, as a cold process: samples per second (target >= 10^5 on one core).

    python benchmarks/bench_duty.py [--runs 11] [--samples 1000000]
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BINS = 10


def drive_with_cycle() -> str:
    """specs/bevel-drive.yaml with 10 bins of torque and speed."""
    bins = "".join(
        f"  - {{name: bin {k}, time: {100 / BINS:g} %, torque: {45 + 3 * k} N*m, "
        f"input_speed: {900 + 100 * k} rpm}}\n" for k in range(1, BINS + 1))
    return (ROOT / "specs" / "bevel-drive.yaml").read_text() + "duty_cycle:\n" + bins


def bearing_with_cycle() -> str:
    """The 6309 of specs/rolling-bearing-duty-cycle.yaml over 10 bins, each radial load
    toleranced (±10 %, normal)."""
    text = (ROOT / "specs" / "rolling-bearing-duty-cycle.yaml").read_text()
    head = text.partition("duty_cycle:\n")[0]
    limits = "limits:\n" + text.partition("limits:\n")[2]
    bins = "".join(
        f"  - {{time: {100 / BINS:g} %, radial_load: {4 + 0.5 * k:g} kN ± "
        f"{0.4 + 0.05 * k:g} kN, axial_load: 1 kN, speed: {600 + 150 * k} rpm}}\n"
        for k in range(1, BINS + 1))
    return head + "duty_cycle:\n" + bins + limits


def cold(*args: str) -> float:
    """Seconds of one cold `bearingcalc` process."""
    command = [sys.executable, "-m", "bearingcalc", *args]
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True, check=False)
    elapsed = time.perf_counter() - start
    if done.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(command)} failed: {done.stderr}")
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=11)
    parser.add_argument("--samples", type=int, default=1_000_000)
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        drive = Path(folder) / "drive-cycle.yaml"
        drive.write_text(drive_with_cycle())
        bearing = Path(folder) / "bearing-cycle.yaml"
        bearing.write_text(bearing_with_cycle())
        single, cycle = [], []
        for _ in range(options.runs):
            single.append(cold("solve", str(ROOT / "specs" / "bevel-drive.yaml")))
            cycle.append(cold("solve", str(drive)))
        one, ten = statistics.median(single), statistics.median(cycle)
        print(f"cold solve, the drive at one point       median {1e3 * one:7.1f} ms")
        print(f"cold solve, the drive over {BINS} bins        median {1e3 * ten:7.1f} ms "
              f"{ten / one:5.2f}x (target <= 1.10x)")
        seconds = cold("tolerance", str(bearing), "--method", "monte-carlo", "--samples",
                       str(options.samples), "--jobs", "1", "--format", "json")
        rate = options.samples / seconds
        print(f"Monte Carlo, {BINS}-bin bearing cycle, {options.samples:.0e} samples, one core: "
              f"{seconds:.2f} s, {rate:.3g} samples/s (target >= 1e5), cold process")


if __name__ == "__main__":
    main()
