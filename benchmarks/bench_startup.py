"""Cold start of `bearingcalc solve` on every example spec, and of the default
`bearingcalc tolerance` (every method, 10^5 samples), against a cold
`python -c "import numpy"`.

Each command runs as a fresh process, several times, alternating, and the
medians are compared: `solve specs/thrust-bearing.yaml` (target <= 2.5x) and the
default tolerance study of `specs/tolerances/thrust-bearing.yaml` (target <= 6x) as
before, and `solve` of every example, `specs/*.yaml` and `specs/tolerances/*.yaml`,
of which the slowest is reported (target <= 3x). Whether Python may write bytecode
caches is printed: with PYTHONDONTWRITEBYTECODE set, every run compiles the package
again and the ratio rises by about 0.3–0.5. Run from the repository root with the
project installed:

    python benchmarks/bench_startup.py [--runs 15]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
#: The example whose cold solve has its own target, as before every example was timed.
REFERENCE_EXAMPLE = "specs/thrust-bearing.yaml"


def timed(command: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, cwd=ROOT)
    return time.perf_counter() - start


def examples() -> list[str]:
    """Every example spec, relative to the repository root."""
    paths = sorted(ROOT.glob("specs/*.yaml")) + sorted(ROOT.glob("specs/tolerances/*.yaml"))
    return [path.relative_to(ROOT).as_posix() for path in paths]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    args = parser.parse_args()

    numpy_cmd = [sys.executable, "-c", "import numpy"]
    solve_cmds = {spec: [sys.executable, "-m", "bearingcalc", "solve", spec]
                  for spec in examples()}
    study_cmd = [sys.executable, "-m", "bearingcalc", "tolerance",
                 "specs/tolerances/thrust-bearing.yaml", "-f", "json"]
    commands = {"numpy": numpy_cmd, "study": study_cmd, **solve_cmds}
    for command in commands.values():  # warm the file cache
        timed(command)
    times: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(args.runs):
        for name, command in commands.items():
            times[name].append(timed(command))
    median = {name: statistics.median(values) for name, values in times.items()}
    numpy_median = median["numpy"]
    solve_median = median[REFERENCE_EXAMPLE]
    study_median = median["study"]

    if os.environ.get("PYTHONDONTWRITEBYTECODE"):
        print("bytecode caches: off (PYTHONDONTWRITEBYTECODE is set: every run compiles)")
    else:
        print("bytecode caches: on (PYTHONDONTWRITEBYTECODE is not set)")
    print(f"python -c 'import numpy'                         median {numpy_median * 1e3:7.1f} ms")
    print("bearingcalc solve, every example:")
    for spec in solve_cmds:
        print(f"  {spec:<47s} median {median[spec] * 1e3:7.1f} ms  "
              f"{median[spec] / numpy_median:4.2f}x")
    print(f"bearingcalc solve {REFERENCE_EXAMPLE}      median {solve_median * 1e3:7.1f} ms")
    print(f"bearingcalc tolerance (default, 1e5 samples)     median {study_median * 1e3:7.1f} ms")
    print(f"solve ratio {solve_median / numpy_median:.2f}x (target <= 2.5x); default tolerance "
          f"ratio {study_median / numpy_median:.2f}x (target <= 6x); {args.runs} runs each")
    worst = max(solve_cmds, key=lambda spec: median[spec])
    print(f"slowest example: solve {worst}, median {median[worst] * 1e3:.1f} ms, ratio "
          f"{median[worst] / numpy_median:.2f}x (target <= 3x for every example)")


if __name__ == "__main__":
    main()
