"""The golden set: what the tool printed for every example, recorded once and compared
on every run, so that moving code around can never change a number or a message.

Each case is a command line run from the repository root; its record is the exit
status, stdout and stderr. ``python -m tests.golden.cases`` records them anew (only
for a deliberate change of output, said so in the commit message).
"""

from __future__ import annotations

import sys
import zlib
from pathlib import Path

from typer.testing import CliRunner

from bearingcalc.cli import app
from tests.hostile import KINDS as HOSTILE_KINDS
from tests.hostile import hostile_corpus

ROOT = Path(__file__).resolve().parents[2]
RECORDS = Path(__file__).resolve().parent / "records"
#: About one case in this many of the hostile corpus, for the error lines (chosen by a
#: hash of the name, so that new cases do not move the sample).
HOSTILE_SAMPLE_STEP = 7
HOSTILE_FOLDER = Path("tests/golden/hostile")


def cases() -> dict[str, list[str]]:
    """Record name -> command line (relative to the repository root)."""
    out: dict[str, list[str]] = {}
    for spec in sorted((ROOT / "specs").glob("*.yaml")):
        out[f"solve-{spec.stem}"] = ["solve", f"specs/{spec.name}", "--format", "json"]
    for template in sorted((ROOT / "bearingcalc" / "templates").glob("*.yaml")):
        out[f"solve-template-{template.stem}"] = [
            "solve", f"bearingcalc/templates/{template.name}", "--format", "json"]
    out["check-specs"] = ["check", "specs", "--format", "json", "--jobs", "1"]
    for spec in sorted((ROOT / "specs" / "tolerances").glob("*.yaml")):
        out[f"tolerance-{spec.stem}"] = ["tolerance", f"specs/tolerances/{spec.name}",
                                         "--format", "json", "--seed", "7", "-n", "20000",
                                         "--jobs", "1"]
        out[f"sweep-tolerances-{spec.stem}"] = _sweep(f"specs/tolerances/{spec.name}",
                                                      spec.stem)
    for kind, (example, _, vary) in HOSTILE_KINDS.items():
        out[f"sweep-{kind}"] = ["sweep", f"specs/{example}", "--vary", vary, "--format", "csv"]
    for name in _hostile_sample():
        out[f"hostile-{Path(name).stem}"] = ["solve", str(HOSTILE_FOLDER / name)]
    return out


def _hostile_sample() -> dict[str, bytes]:
    # The catalogue cases name their catalogues by absolute paths, which a record of
    # their lines would pin to one machine.
    return {name: data for name, data in sorted(hostile_corpus().items())
            if zlib.crc32(name.encode()) % HOSTILE_SAMPLE_STEP == 0
            and not name.startswith("physics-catalogue-")}


def _sweep(path: str, stem: str) -> list[str]:
    for kind in sorted(HOSTILE_KINDS, key=len, reverse=True):
        if stem.startswith(kind):
            return ["sweep", path, "--vary", HOSTILE_KINDS[kind][2], "--format", "csv"]
    raise KeyError(stem)


def stage(root: Path) -> None:
    """A copy of what the cases read, under ``root``: the example specs, the templates and
    the sampled hostile files (so that runs never write into the repository)."""
    import shutil

    shutil.copytree(ROOT / "specs", root / "specs")
    shutil.copytree(ROOT / "bearingcalc" / "templates", root / "bearingcalc" / "templates")
    folder = root / HOSTILE_FOLDER
    folder.mkdir(parents=True, exist_ok=True)
    for name, data in _hostile_sample().items():
        (folder / name).write_bytes(data)


def run(argv: list[str]) -> str:
    """The record of one command line: exit status, stdout and stderr."""
    result = CliRunner().invoke(app, argv)
    return f"exit {result.exit_code}\n--- stdout\n{result.stdout}--- stderr\n{result.stderr}"


def record() -> None:
    import os
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        stage(Path(folder))
        os.chdir(folder)
        RECORDS.mkdir(exist_ok=True)
        for old in RECORDS.glob("*.txt"):
            old.unlink()
        for name, argv in cases().items():
            (RECORDS / f"{name}.txt").write_text(run(argv), encoding="utf-8")


if __name__ == "__main__":
    record()
    sys.exit(0)
