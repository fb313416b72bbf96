"""Batch checking speed: `bearingcalc check` on N generated specs, beside check-jsonschema.

Generates N spec files (a mix of all kinds, about 80 % passing, 10 % failing a
limit and 10 % invalid), then times, each as a cold process, median of a few runs:

- ``bearingcalc check DIR --format json`` (schema, units and physics), and
- ``check-jsonschema --schemafile schema.json FILE...`` against ``bearingcalc schema``
  (the schema only), when check-jsonschema is installed.

    python benchmarks/bench_check.py [--files 5000] [--runs 3] [--jobs N]
"""

from __future__ import annotations

import argparse
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PASSING = [
    """kind: thrust-bearing
name: tb-{i}
ball_diameter: {d:.3f} mm
contact_angle: {theta:.2f} deg
shaft_speed: {speed} rpm
ball_count: 6
""",
    """kind: thrust-bearing
name: tb-check-{i}
ball_radius: 5 mm
contact_angle: 30 deg
pitch_radius: {b:.4f} mm
shaft_speed: {speed} rpm
limits:
  max_spin_to_roll: 0.02
""",
    """kind: disk-on-circle
name: planet-{i}
disk_radius: {d:.3f} mm
surface_radius: 90 mm
contact: internal
disk_speed: {speed} rpm
surface_speed: -50 rpm
""",
    """kind: cone-on-plane
name: cone-{i}
half_angle: {theta:.2f} deg
spin_speed: {speed} rpm
axis_point_height: 12 mm
""",
    """kind: bevel-gears
name: bevel-{i}
gear_a: {{teeth: {za}}}
gear_b: {{teeth: {zb}}}
module: 2 mm
shaft_angle: 90 deg
arm_speed: {speed} rpm
""",
]
FAILING = """kind: thrust-bearing
name: tb-fail-{i}
ball_radius: 5 mm
contact_angle: 30 deg
pitch_radius: {b_bad:.3f} mm
shaft_speed: {speed} rpm
"""
INVALID = [
    "kind: thrust-bearing\nname: bad-{i}\nball_diameter: 12.7\ncontact_angle: 20 deg\n"
    "shaft_speed: 1500 rpm\n",
    "kind: thrust-bearing\nname: bad-{i}\nball_diameter: 12.7 mm\ncontact_angle: 50 deg\n"
    "shaft_speed: 1500 rpm\n",
    "kind: bevel-gears\nname: bad-{i}\ngear_a: {{teeth: 12}}\ngear_b: {{tooth: 24}}\n"
    "module: 2 mm\nshaft_angle: 90 deg\narm_speed: 100 rpm\n",
]


def generate(folder: Path, count: int, seed: int = 0) -> list[Path]:
    rng = random.Random(seed)
    paths = []
    for i in range(count):
        values = {"i": i, "d": rng.uniform(5, 20), "theta": rng.uniform(10, 40),
                  "speed": rng.randint(100, 3000), "b": rng.uniform(20.3, 21.7),
                  "b_bad": rng.uniform(15, 18), "za": rng.randint(10, 20),
                  "zb": rng.randint(20, 40)}
        roll = rng.random()
        if roll < 0.8:
            text = PASSING[i % len(PASSING)].format(**values)
        elif roll < 0.9:
            text = FAILING.format(**values)
        else:
            text = INVALID[i % len(INVALID)].format(**values)
        path = folder / f"group-{i % 20:02d}" / f"spec-{i:05d}.yaml"
        path.parent.mkdir(exist_ok=True)
        path.write_text(text)
        paths.append(path)
    return paths


def median_time(command: list[str], runs: int) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                              check=False)
        times.append(time.perf_counter() - start)
        if done.returncode not in (0, 1, 2):
            raise SystemExit(f"{command[0]} failed: {done.stderr.decode()[-500:]}")
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--files", type=int, default=5000)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=None)
    args = parser.parse_args()
    bin_dir = Path(sys.executable).parent
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp) / "specs"
        folder.mkdir()
        files = generate(folder, args.files)
        check = [str(bin_dir / "bearingcalc"), "check", str(folder), "--format", "json",
                 "--output", str(Path(tmp) / "report.jsonl")]
        if args.jobs:
            check += ["--jobs", str(args.jobs)]
        ours = median_time(check, args.runs)
        print(f"bearingcalc check     {args.files} files: median {ours:6.2f} s = "
              f"{args.files / ours:7.0f} specs/s (target >= 2000 specs/s)")
        checker = shutil.which("check-jsonschema", path=str(bin_dir)) or shutil.which(
            "check-jsonschema")
        if checker is None:
            print("check-jsonschema not installed: pip install check-jsonschema to compare")
            return
        schema = Path(tmp) / "schema.json"
        schema.write_text(subprocess.run([str(bin_dir / "bearingcalc"), "schema"],
                                         capture_output=True, text=True, check=True).stdout)
        theirs = median_time([checker, "--schemafile", str(schema), *map(str, files)],
                             args.runs)
        print(f"check-jsonschema      {args.files} files: median {theirs:6.2f} s = "
              f"{args.files / theirs:7.0f} specs/s (schema only)")
        print(f"bearingcalc is {theirs / ours:.1f}x faster")


if __name__ == "__main__":
    main()
