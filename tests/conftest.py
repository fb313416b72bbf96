from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import settings
from typer.testing import CliRunner

from bearingcalc.cli import app

ROOT = Path(__file__).resolve().parent.parent

# The same examples on every run, so CI cannot fail on a draw a developer never saw.
settings.register_profile("deterministic", derandomize=True, print_blob=True)
settings.load_profile("deterministic")


#: Python options that make every warning an error, except the deprecation notices of
#: libraries (an older typer's about click), which Python hides from users anyway.
WARNINGS_AS_ERRORS = ("-W", "error", "-W", "ignore::DeprecationWarning",
                      "-W", "ignore::PendingDeprecationWarning")


class Run:
    """A finished CLI run: exit code, stdout and stderr."""

    def __init__(self, result) -> None:
        self.code = result.exit_code
        self.out = result.stdout
        self.err = result.stderr
        self.exception = result.exception


def csv_column(text: str, header: str) -> list[float]:
    """The values of one column of a sweep's CSV output, by its header."""
    import csv
    import io

    return [float(row[header]) for row in csv.DictReader(io.StringIO(text))]


def solve_json(cli, path) -> list[dict]:
    """The JSON records of `bearingcalc solve PATH --format json`, whose exit status
    must be 1 exactly when a record is outside its limits."""
    run = cli("solve", path, "--format", "json")
    records = [json.loads(line) for line in run.out.splitlines()]
    assert records, run.err
    assert run.code == (0 if all(r["within_limits"] for r in records) else 1), run.err
    return records


def study_status(record: dict) -> int:
    """The exit status a tolerance study's JSON record calls for: 1 when the box holds
    impossible designs or a margin (a ``*_margin`` result) can go below zero, at worst
    case when it ran, else in some Monte Carlo sample; 0 otherwise."""
    if record.get("impossible_in_box") or record.get("infeasible_samples"):
        return 1
    margins = [entry for key, entry in record["results"].items() if key.endswith("_margin")]
    if margins and all("worst_case" in entry for entry in margins):
        return int(any(entry["worst_case"]["min"] < 0 for entry in margins))
    return int("yield" in record and record["yield"] < 1.0)


@pytest.fixture
def cli():
    runner = CliRunner()

    def run(*args: str) -> Run:
        return Run(runner.invoke(app, [str(a) for a in args]))

    return run


@pytest.fixture
def spec_file(tmp_path):
    def write(text: str | bytes, name: str = "spec.yaml") -> Path:
        path = tmp_path / name
        path.write_bytes(text if isinstance(text, bytes) else text.encode())
        return path

    return write


@pytest.fixture(scope="session", autouse=True)
def _example_specs_stay_untouched():
    """No test may change an input: the example specs are byte for byte the same after
    the whole run as before it."""
    def snapshot() -> dict[str, bytes]:
        return {str(path): path.read_bytes()
                for path in sorted((ROOT / "specs").rglob("*")) if path.is_file()}

    before = snapshot()
    yield
    after = snapshot()
    changed = sorted(set(before) ^ set(after) | {p for p in before if before[p] != after.get(p)})
    assert not changed, f"tests changed these example specs: {changed}"


def refused_in_one_sentence(call, words) -> None:
    """``call()`` raises a ValueError of one sentence holding every one of ``words``."""
    with pytest.raises(ValueError) as refusal:
        call()
    message = str(refusal.value)
    assert message.endswith(".") and message.count(". ") == 0, message
    for word in words:
        assert word in message, message
