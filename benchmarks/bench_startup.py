"""Cold start of `bearingcalc solve`, and of the default `bearingcalc tolerance` (every
method, 10^5 samples), against a cold `python -c "import numpy"`.

Each command runs as a fresh process, several times, alternating, and the
medians are compared. Whether Python may write bytecode caches is printed: with
PYTHONDONTWRITEBYTECODE set, every run compiles the package again and the ratio
rises by about 0.3–0.5. Run from the repository root with the project installed:

    python benchmarks/bench_startup.py [--runs 15]
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def timed(command: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, cwd=ROOT)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    args = parser.parse_args()
    import os

    numpy_cmd = [sys.executable, "-c", "import numpy"]
    solve_cmd = [sys.executable, "-m", "bearingcalc", "solve", "specs/thrust-bearing.yaml"]
    study_cmd = [sys.executable, "-m", "bearingcalc", "tolerance",
                 "specs/tolerances/thrust-bearing.yaml", "-f", "json"]
    timed(numpy_cmd), timed(solve_cmd), timed(study_cmd)  # warm the file cache
    numpy_times, solve_times, study_times = [], [], []
    for _ in range(args.runs):
        numpy_times.append(timed(numpy_cmd))
        solve_times.append(timed(solve_cmd))
        study_times.append(timed(study_cmd))
    numpy_median = statistics.median(numpy_times)
    solve_median = statistics.median(solve_times)
    study_median = statistics.median(study_times)
    if os.environ.get("PYTHONDONTWRITEBYTECODE"):
        print("bytecode caches: off (PYTHONDONTWRITEBYTECODE is set: every run compiles)")
    else:
        print("bytecode caches: on (PYTHONDONTWRITEBYTECODE is not set)")
    print(f"python -c 'import numpy'                         median {numpy_median * 1e3:7.1f} ms")
    print(f"bearingcalc solve specs/thrust-bearing.yaml      median {solve_median * 1e3:7.1f} ms")
    print(f"bearingcalc tolerance (default, 1e5 samples)     median {study_median * 1e3:7.1f} ms")
    print(f"solve ratio {solve_median / numpy_median:.2f}x (target <= 2.5x); default tolerance "
          f"ratio {study_median / numpy_median:.2f}x (target <= 6x); {args.runs} runs each")


if __name__ == "__main__":
    main()
