"""Runs the hostile corpus of tests/hostile_features.py through the CLI and the API and
holds each case to the promises of the README ("Bad input and output files") and of
docs/python.md: success with finite numbers, or exit status 2 with one clean line per
problem naming the file, its line and the field; inputs untouched; no output on failure.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import pytest

from bearingcalc.errors import SpecError
from tests.hostile_features import Case, Run, cases, run_cli

CASES = cases()

FORBIDDEN = (
    "Traceback",
    "internal error",
    "out of the range of double precision",
    "Error:",
    "Exception",
    "Usage:",
)
NONFINITE = re.compile(r"(?<![\w.\-])-?(nan|NaN|inf|Inf|Infinity)(?![\w.\-])")


def write_files(folder: Path, case: Case) -> dict[Path, bytes]:
    for name, content in case.files.items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
    for name, target in case.links.items():
        os.symlink(target, folder / name)
    for name, target in case.hardlinks.items():
        os.link(folder / target, folder / name)
    return snapshot(folder)


def snapshot(folder: Path) -> dict[Path, bytes]:
    return {p: p.read_bytes() for p in folder.rglob("*") if p.is_file() and not p.is_symlink()}


def input_names(case: Case) -> set[str]:
    return {Path(name).name for name in case.files} | set(case.files)


def finite_json(text: str) -> list[str]:
    bad = []

    def reject(token):
        bad.append(token)
        return 0.0

    for line in text.splitlines():
        if line.strip():
            try:
                json.loads(line, parse_constant=reject)
            except json.JSONDecodeError:
                return []  # not JSON Lines: the text scan below decides
    return [f"non-finite JSON number {t}" for t in bad]


def outcome_problems(case: Case, run: Run) -> list[str]:
    problems = []
    for word in FORBIDDEN:
        if word in run.stderr:
            problems.append(f"stderr holds {word!r}")
    if case.expect == "ok" and run.code == 2:
        problems.append(f"exit 2, expected success: {run.stderr.strip()[:400]!r}")
    if case.expect == "error" and run.code != 2:
        problems.append(f"exit {run.code}, expected 2 (stderr {run.stderr.strip()[:300]!r})")
    if run.code not in (0, 1, 2):
        problems.append(f"exit status {run.code}")
    if run.code in (0, 1):
        problems += finite_json(run.stdout)
        if not problems and NONFINITE.search(run.stdout):
            problems.append(
                f"non-finite number in the output: {NONFINITE.search(run.stdout).group(0)!r}"
            )
        if not run.stdout.strip() and not case.outputs:
            problems.append("success with nothing on stdout")
    if run.code == 2:
        problems += error_line_problems(case, run)
    return problems


def error_line_problems(case: Case, run: Run) -> list[str]:
    lines = [line for line in run.stderr.splitlines() if line.strip()]
    if not lines:
        return ["exit 2 with nothing on stderr"]
    names = input_names(case)
    command = run.argv[0] if run.argv else ""
    problems = []
    for line in lines:
        if line.startswith("warning"):
            continue
        head = line.split(":", 1)[0].split("#", 1)[0]
        if line.startswith((f"bearingcalc {command}:", f"{command}:")):
            continue
        if head in run.argv:  # an output or option path the line is about
            continue
        if head not in names and Path(head).name not in names:
            problems.append(f"line does not name an input file: {line[:200]!r}")
            continue
        if (
            case.needs_line
            and head.endswith((".yaml", ".yml"))
            and not re.match(rf"^{re.escape(line.split(':', 1)[0])}:\d+: ", line)
        ):
            problems.append(f"spec error without its line: {line[:200]!r}")
        if len(line) > 600:
            problems.append(f"line of {len(line)} characters")
    for wanted in case.fields:
        if not re.search(rf"(^|[\s:(']){re.escape(wanted)}([.:'\s]|$)", run.stderr, re.M):
            problems.append(f"no line names {wanted!r}: {run.stderr.strip()[:300]!r}")
    return problems


@pytest.mark.parametrize("name", sorted(n for n, c in CASES.items() if c.api is None))
def test_cli_case(name: str, tmp_path: Path) -> None:
    case = CASES[name]
    before = write_files(tmp_path, case)
    run = run_cli(tmp_path, case.argv, case.env)
    problems = outcome_problems(case, run)
    after = snapshot(tmp_path)
    for path, content in before.items():
        if after.get(path) != content:
            problems.append(f"input {path.relative_to(tmp_path)} changed")
    created = sorted(str(p.relative_to(tmp_path)) for p in set(after) - set(before))
    if run.code == 2 and created:
        problems.append(f"a failed run wrote {created}")
    if run.code in (0, 1):
        for out in case.outputs:
            if not (tmp_path / out).is_file():
                problems.append(f"the run did not write {out}")
    if not problems and case.check is not None and run.code in (0, 1):
        problems += case.check(tmp_path, run)
    assert not problems, f"{name}: bearingcalc {' '.join(case.argv)}\n  " + "\n  ".join(problems)


@pytest.mark.parametrize("name", sorted(n for n, c in CASES.items() if c.api is not None))
def test_api_case(name: str, tmp_path: Path, monkeypatch) -> None:
    case = CASES[name]
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("BEARINGCALC_CATALOGUE", raising=False)
    try:
        value = case.api(tmp_path)
    except SpecError as exc:
        text = str(exc)
        assert case.expect != "ok", f"{name}: SpecError where success was expected: {text}"
        assert "Traceback" not in text and "internal error" not in text, f"{name}: {text}"
        missing = [n for n in case.api_names if n not in text]
        assert not missing, f"{name}: the SpecError does not name {missing}: {text!r}"
        return
    except ValueError as exc:  # documented for misused arguments; it must still name them
        text = str(exc)
        assert case.expect != "ok", f"{name}: ValueError where success was expected: {text}"
        missing = [n for n in case.api_names if n not in text]
        assert not missing, f"{name}: the ValueError does not name {missing}: {text!r}"
        return
    except Exception as exc:  # TypeError, AttributeError, KeyError, ... from inside
        pytest.fail(f"{name}: {type(exc).__name__} from inside: {exc!r}")
    assert case.expect != "error", f"{name}: no error, returned {value!r}"
