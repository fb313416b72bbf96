"""A 1000 × 1000 grid sweep of a thrust bearing to CSV: time and peak memory.

Runs `bearingcalc sweep specs/thrust-bearing.yaml --vary contact_angle=5deg:44deg:1000
--vary pitch_radius=10mm:40mm:1000 --output grid.csv` as a cold process (median of
a few runs; peak resident memory from the operating system), then times the
stages in-process to show where the time goes.

    python benchmarks/bench_sweep.py [--points 1000] [--runs 3]
"""

from __future__ import annotations

import argparse
import io
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SPEC = ROOT / "specs" / "thrust-bearing.yaml"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    n = args.points
    vary = [f"contact_angle=5deg:44deg:{n}", f"pitch_radius=10mm:40mm:{n}"]
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "grid.csv"
        command = [str(Path(sys.executable).parent / "bearingcalc"), "sweep", str(SPEC),
                   "--vary", vary[0], "--vary", vary[1], "--output", str(out)]
        times = []
        for _ in range(args.runs):
            start = time.perf_counter()
            subprocess.run(command, check=True)
            times.append(time.perf_counter() - start)
        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        size = out.stat().st_size / 1e6
    print(f"{n} x {n} grid to CSV ({size:.0f} MB): median {statistics.median(times):.2f} s "
          f"end to end (target <= 3 s), peak RSS {peak:.0f} MB (target < 1024)")

    from bearingcalc import reports
    from bearingcalc.evaluation import load_one_spec
    from bearingcalc.sweeps import parse_axis, run_sweep

    kind, spec, document = load_one_spec(SPEC)
    start = time.perf_counter()
    axes = [parse_axis(text, spec) for text in vary]
    solved = run_sweep(kind, spec, document.source, axes)
    solve_time = time.perf_counter() - start
    start = time.perf_counter()
    reports.write_sweep_csv(solved, io.StringIO())
    csv_time = time.perf_counter() - start
    print(f"in-process: solving {n * n} points {solve_time:.2f} s, formatting the CSV "
          f"{csv_time:.2f} s")


if __name__ == "__main__":
    main()
