"""Time ``bearingcalc select`` as a cold process on a large catalogue: 10^4 rows, every one
of them at the spec's shaft (the worst case: none is set aside by the bore), against a
10-bin duty cycle.

The catalogue is made here: the designations of the shipped ISO table with a 40 mm bore
(deep groove, angular contact, cylindrical, tapered, spherical and thrust), each from
many makers with ratings spread about a plausible size. Run from the repository root:

    python benchmarks/bench_select.py [--rows 10000] [--runs 5]
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bearingcalc.catalogue.iso import iso_table

TARGET_SECONDS = 1.0
SPEC = """kind: rolling-bearing
name: gearbox shaft, 10 load cases
catalogue: catalogue.csv
bore_diameter: 40 mm
radial_load: 6 kN
axial_load: 1 kN
speed: 1500 rpm
lubrication: {viscosity: 68 mm^2/s}
contamination_factor: 0.5
limits: {min_rating_life: 20000 h, min_static_safety: 2}
duty_cycle:
""" + "".join(f"  - {{time: 10 %, radial_load: {4 + 0.5 * k} kN, speed: {900 + 100 * k} rpm}}\n"
              for k in range(10))


def make_catalogue(rows: int, path: Path) -> None:
    """``rows`` rows, all with a 40 mm bore: ISO's dimensions, made-up ratings."""
    sizes = [dims for dims in iso_table().values() if abs(dims.bore_diameter - 0.040) < 1e-9]
    rng = np.random.default_rng(1)
    lines = ["designation,maker,type,bore_diameter [mm],outside_diameter [mm],width [mm],"
             "dynamic_load_rating [kN],static_load_rating [kN],e,y2,y0,mass [kg],source"]
    for i in range(rows):
        dims = sizes[i % len(sizes)]
        maker = f"M{i // len(sizes):05d}"
        big, wide = dims.outside_diameter * 1e3, dims.width * 1e3
        rating = 0.03 * big * wide * rng.uniform(0.7, 1.3)
        factors = ("0.37,1.6,0.9" if dims.type == "tapered-roller" else
                   "0.28,3.6,2.5" if dims.type == "spherical-roller" else ",,")
        lines.append(f"{dims.designation},{maker},{dims.type},40,{big:g},{wide:g},"
                     f"{rating:.3g},{0.8 * rating:.3g},{factors},{0.002 * big * wide / 10:.3g},"
                     "made up for the benchmark")
    path.write_text("\n".join(lines) + "\n")


def cold_run(folder: Path) -> float:
    start = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "bearingcalc", "select", "spec.yaml",
                          "--format", "json"], cwd=folder, capture_output=True, text=True,
                         check=False)
    elapsed = time.perf_counter() - start
    if run.returncode not in (0, 1):
        raise SystemExit(run.stderr)
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10_000)
    parser.add_argument("--runs", type=int, default=5)
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        make_catalogue(options.rows, folder / "catalogue.csv")
        (folder / "spec.yaml").write_text(SPEC)
        cold_run(folder)  # the first run writes the bytecode caches
        times = [cold_run(folder) for _ in range(options.runs)]
    median = statistics.median(times)
    print(f"select, {options.rows} rows at the shaft x 10 bins, cold: median {median:.3f} s "
          f"(min {min(times):.3f}, max {max(times):.3f}, {options.runs} runs); target "
          f"<= {TARGET_SECONDS:.1f} s: {'met' if median <= TARGET_SECONDS else 'MISSED'}")


if __name__ == "__main__":
    main()
