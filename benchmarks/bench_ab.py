"""Two trees of bearingcalc, one command, as cold processes run alternately: the median,
min and max of each, so that a change's cost is measured in one sitting on a noisy
machine.

    git worktree add /tmp/before <commit>
    env -u PYTHONDONTWRITEBYTECODE python benchmarks/bench_ab.py /tmp/before . -- \
        solve specs/thrust-bearing.yaml

Paths in the command are relative to each tree, which runs from its own root.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path


def cold_run(tree: Path, command: list[str]) -> float:
    """Seconds of one ``python -m bearingcalc ...`` in ``tree``, that tree on the path.
    Exit status 1 (a design or study outside its limits) is a run like any other; 2 and
    above stop the benchmark."""
    env = dict(os.environ, PYTHONPATH=str(tree))
    start = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "bearingcalc", *command], cwd=tree, env=env,
                         capture_output=True, check=False)
    elapsed = time.perf_counter() - start
    if run.returncode not in (0, 1):
        raise SystemExit(f"{tree}: exit {run.returncode}: {run.stderr.decode()[-500:]}")
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before", type=Path)
    parser.add_argument("after", type=Path)
    parser.add_argument("--runs", type=int, default=15)
    argv = sys.argv[1:]
    if "--" not in argv:
        parser.error("give the bearingcalc command after --")
    cut = argv.index("--")
    args, command = parser.parse_args(argv[:cut]), argv[cut + 1:]
    trees = (args.before.resolve(), args.after.resolve())
    for tree in trees:  # bytecode caches written, files in the page cache
        cold_run(tree, command)
    times: dict[Path, list[float]] = {tree: [] for tree in trees}
    for _ in range(args.runs):
        for tree in trees:
            times[tree].append(cold_run(tree, command))
    for name, tree in zip(("before", "after"), trees, strict=True):
        runs = times[tree]
        print(f"{name:6} {1e3 * statistics.median(runs):7.0f} ms "
              f"({1e3 * min(runs):.0f}–{1e3 * max(runs):.0f})  {tree}")


if __name__ == "__main__":
    main()
