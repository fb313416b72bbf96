"""Every hostile case of the generated corpus, through the evaluation API and (a sample)
through every command.

solve, check, tolerance and sweep must each refuse each case with lines that name
the file (and the line, where the document could be read), exit status 2, no
traceback or internal error, and never touch an existing output file.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import zlib

import pytest

from bearingcalc import sweeps
from bearingcalc.errors import SpecError
from bearingcalc.evaluation import evaluate_document, evaluate_file, load_one_spec
from bearingcalc.kinds import KINDS, OUT_OF_RANGE_REASON
from tests.conftest import ROOT, WARNINGS_AS_ERRORS
from tests.hostile import KINDS as CORPUS_KINDS
from tests.hostile import (
    PHYSICS_PREFIX,
    SPECS,
    STRUCTURAL,
    derived_choice,
    hostile_corpus,
    sweep_option,
)

CORPUS = hostile_corpus()
GOOD = sorted((ROOT / "specs").glob("*.yaml"))

# A warning from numpy or Python is a failure here: none may reach a user's terminal.
pytestmark = pytest.mark.filterwarnings("error")


def test_the_corpus_covers_every_kind():
    assert set(CORPUS_KINDS) == set(KINDS)


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_a_new_kind_gets_its_cases_and_sweep_from_its_example(kind):
    example, fields, vary = derived_choice(kind)
    _, spec, document = load_one_spec(SPECS / example)
    assert fields
    sweeps.check_axes(document, [sweeps.parse_axis(vary, spec)])


def test_no_case_ends_at_the_generic_overflow_status(corpus_dir):
    """Every impossible design has a status of its own naming its field; the generic
    'out of the range of double precision' is only a last guard."""
    generic = OUT_OF_RANGE_REASON[1]
    reached = []
    for name in CORPUS:
        for outcome in evaluate_file(corpus_dir / name):
            lines = outcome.lines() if hasattr(outcome, "lines") else []
            reached += [line for line in lines if generic in line]
            assert lines, f"{name} was accepted"
    assert not reached, reached


def test_a_sample_run_with_warnings_as_errors_prints_only_its_error_lines(corpus_dir):
    names = [name for name in CORPUS if name.startswith(PHYSICS_PREFIX)][::3]
    run = subprocess.run([sys.executable, *WARNINGS_AS_ERRORS, "-m", "bearingcalc", "solve",
                          *(str(corpus_dir / name) for name in names)],
                         capture_output=True, text=True, timeout=120, check=False)
    assert run.returncode == 2
    assert run.stdout == ""
    for line in run.stderr.splitlines():
        assert line.startswith(str(corpus_dir)), line


def test_the_corpus_is_large_and_every_class_is_in_it():
    assert len(CORPUS) >= 300
    for fragment in ("mm)", "rpm**0", "12,7", "alias-bomb", "deep", "merge-key", "latin1"):
        assert any(fragment in name or fragment.encode() in data
                   for name, data in CORPUS.items()), fragment


@pytest.fixture(scope="module")
def corpus_dir(tmp_path_factory):
    folder = tmp_path_factory.mktemp("hostile")
    for name, data in CORPUS.items():
        (folder / name).write_bytes(data)
    return folder


def _clean(run, path) -> list[str]:
    """Problems with a run that must refuse ``path``: empty list when it did right."""
    problems = []
    if run.code != 2:
        problems.append(f"exit {run.code}")
    if run.exception is not None and not isinstance(run.exception, SystemExit):
        problems.append(f"exception {run.exception!r}")
    if run.out:
        problems.append(f"stdout {run.out[:80]!r}")
    lines = run.err.splitlines()
    if not lines:
        problems.append("no message")
    for line in lines:
        if not line.startswith(f"{path}:") and not line.startswith(f"{path}#"):
            problems.append(f"line without the file: {line[:120]!r}")
        if "Traceback" in line or "internal error" in line:
            problems.append(f"internal: {line[:160]!r}")
        if any(ord(c) < 32 for c in line):
            problems.append(f"control character: {line[:80]!r}")
    return problems


def _refused_in_process(path, name) -> list[str]:
    """Problems with the evaluation API's handling of a case that must be refused, on
    the paths solve, tolerance and sweep take: empty when every one refused it with
    lines naming the file and no internal error."""
    problems = []
    outcomes = evaluate_file(path)
    errors = [outcome for outcome in outcomes if isinstance(outcome, SpecError)]
    if len(errors) != len(outcomes) or not errors:
        problems.append("solve accepted a document")
    for error in errors:
        for line in error.lines():
            if not line.startswith((f"{path}:", f"{path}#")):
                problems.append(f"line without the file: {line[:120]!r}")
            if "internal error" in line:
                problems.append(f"internal: {line[:160]!r}")
    try:
        _, spec, document = load_one_spec(path)
    except SpecError:
        return problems  # tolerance and sweep refuse it as they load it
    try:
        evaluate_document(document)
        problems.append("tolerance accepted the nominal design")
    except SpecError:
        pass
    if not name.startswith(PHYSICS_PREFIX):  # a sweep may start from an impossible design
        try:
            axes = [sweeps.parse_axis(sweep_option(name), spec)]
            sweeps.check_axes(document, axes)
            problems.append("sweep accepted it")
        except sweeps.SweepError:
            pass
    return problems


def test_every_case_is_refused_by_the_evaluation_api(corpus_dir):
    failures = {name: problems for name in CORPUS
                if (problems := _refused_in_process(corpus_dir / name, name))}
    assert not failures, failures


#: About one case in this many goes through the command line as well.
CLI_SAMPLE_STEP = 8
CLI_SAMPLE = [name for name in CORPUS if zlib.crc32(name.encode()) % CLI_SAMPLE_STEP == 0]


def test_the_sample_is_spread_over_every_kind_of_case():
    assert len(CLI_SAMPLE) >= 30
    assert any(name.startswith(PHYSICS_PREFIX) for name in CLI_SAMPLE)
    assert any(name in STRUCTURAL for name in CLI_SAMPLE)


def test_solve_refuses_the_sample_with_clear_lines(cli, corpus_dir):
    failures = {}
    for name in CLI_SAMPLE:
        path = corpus_dir / name
        problems = _clean(cli("solve", path), path)
        if problems:
            failures[name] = problems
    assert not failures, failures


def test_tolerance_and_sweep_refuse_the_sample_and_write_nothing(cli, corpus_dir, tmp_path):
    out = tmp_path / "report.txt"
    failures = {}
    for name in CLI_SAMPLE:
        path = corpus_dir / name
        commands = [("tolerance", path, "-n", "64")]
        if not name.startswith(PHYSICS_PREFIX):  # a sweep may start from an impossible design
            commands.append(("sweep", path, "--vary", sweep_option(name)))
        for command in commands:
            out.write_text("keep")
            run = cli(*command, "-o", out)
            problems = _clean(run, path)
            if out.read_text() != "keep":
                problems.append("the output file was touched")
            if problems:
                failures[f"{command[0]} {name}"] = problems
    assert not failures, failures


def test_check_reports_every_good_file_in_a_folder_full_of_hostile_ones(cli, corpus_dir,
                                                                       tmp_path):
    folder = tmp_path / "mixed"
    shutil.copytree(corpus_dir, folder)
    for good in GOOD:
        shutil.copy(good, folder / f"good-{good.name}")
    shutil.copytree(ROOT / "specs" / "catalogues", folder / "catalogues")  # the good ones'
    run = cli("check", folder, "--format", "json")
    assert run.code == 2, run.err

    def no_constants(word):
        raise AssertionError(f"non-finite number {word} in the report")

    records = [json.loads(line, parse_constant=no_constants) for line in run.out.splitlines()]
    by_file = {}
    for record in records:
        by_file.setdefault(record["spec"].split("#")[0], []).append(record)
    for good in GOOD:
        (record,) = by_file[str(folder / f"good-{good.name}")]
        assert record["status"] in ("pass", "fail"), record
    for name in CORPUS:
        statuses = [r["status"] for r in by_file[str(folder / name)]]
        assert "invalid" in statuses, (name, statuses)
    for record in records:
        for message in record["messages"]:
            assert "internal error" not in message and "Traceback" not in message, message
