"""Cold start of `bearingcalc solve` against a cold `python -c "import numpy"`.

Each command runs as a fresh process, several times, alternating, and the
medians are compared. Run from the repository root with the project installed:

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
    numpy_cmd = [sys.executable, "-c", "import numpy"]
    solve_cmd = [sys.executable, "-m", "bearingcalc", "solve", "specs/thrust-bearing.yaml"]
    timed(numpy_cmd), timed(solve_cmd)  # warm the file cache, not the interpreter
    numpy_times, solve_times = [], []
    for _ in range(args.runs):
        numpy_times.append(timed(numpy_cmd))
        solve_times.append(timed(solve_cmd))
    numpy_median = statistics.median(numpy_times)
    solve_median = statistics.median(solve_times)
    print(f"python -c 'import numpy'                         median {numpy_median * 1e3:7.1f} ms")
    print(f"bearingcalc solve specs/thrust-bearing.yaml      median {solve_median * 1e3:7.1f} ms")
    print(f"ratio {solve_median / numpy_median:.2f}x (target <= 5x, stretch <= 3x), "
          f"{args.runs} runs each")


if __name__ == "__main__":
    main()
