"""The feature matrix: every combination of bearing type, pair arrangement, shaft
arrangement, straight or spiral pair, one operating point or a duty cycle with a bin at
rest, and ratings, geometry or a catalogue row, on every kind that takes bearings,
through ``solve`` and ``check``; a sample of them (by the CRC-32 of the case's name)
through ``tolerance``, ``sweep``, ``report`` and ``select``.

Each run must end in a result (exit 0 or 1, every number finite) or in clear lines
(exit 2, each naming the spec file, no traceback, no internal error). The cases are
generated from the type tables and the registry (``tests/feature_matrix.py``).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from pydantic import BaseModel
from typer.testing import CliRunner

from bearingcalc.cli import app
from bearingcalc.errors import SpecError
from bearingcalc.evaluation import parse_document
from bearingcalc.models.yaml_loader import load_documents
from bearingcalc.variation import with_values
from tests.conftest import Run
from tests.feature_matrix import (
    ARRANGEMENTS,
    CATALOGUE,
    OPERATION,
    PAIRS,
    SHAFT_ARRANGEMENTS,
    SOURCES,
    TYPES,
    Case,
    bearing_kinds,
    cases,
)

CASES = cases()
#: One case in this many of those that solve, and of those refused, goes through the
#: slower commands.
SAMPLE_SOLVED, SAMPLE_REFUSED = 8, 80
BROKEN = re.compile(r"Traceback|internal error|\bnan\b|\binf\b", re.IGNORECASE)


@pytest.fixture(scope="module")
def matrix(tmp_path_factory) -> Path:
    """Every case as a spec file of its own, in one folder."""
    folder = tmp_path_factory.mktemp("matrix")
    for case in CASES:
        (folder / f"{case.name}.yaml").write_text(case.text(), encoding="utf-8")
    return folder


def _finite(value: object) -> bool:
    if isinstance(value, dict):
        return all(_finite(v) for v in value.values())
    if isinstance(value, list):
        return all(_finite(v) for v in value)
    return not isinstance(value, float) or math.isfinite(value)


@pytest.fixture(scope="module")
def checked(matrix) -> tuple[Run, list[dict]]:
    """``check`` of the whole folder, and its JSON records."""
    run = Run(CliRunner().invoke(app, ["check", str(matrix), "--format", "json",
                                       "--jobs", "1"]))
    return run, [json.loads(line) for line in run.out.splitlines()]


def _ends_cleanly(run: Run, what: str, said_on_stderr: bool = True) -> None:
    """A result (0 or 1) or clear lines (2, on stderr unless the report holds them);
    never a traceback or an internal error, whatever the exit status."""
    assert run.exception is None or isinstance(run.exception, SystemExit), (what, run.err)
    assert run.code in (0, 1, 2), (what, run.code, run.err)
    assert not BROKEN.search(run.err), (what, run.err)
    if run.code == 2 and said_on_stderr:
        assert run.err.strip(), what


def test_the_matrix_holds_every_type_arrangement_and_bearing_kind():
    """Generated, not listed: every type and arrangement of the tables appears on every
    kind that takes bearings, and every kind of the registry that does is here."""
    kinds = bearing_kinds()
    assert {"rolling-bearing", "bevel-drive"} <= set(kinds)
    seen = {(case.kind, case.spec.get("type") or case.spec["pinion_bearings"][0]["type"])
            for case in CASES}
    assert seen == {(kind, bearing_type) for kind in kinds for bearing_type in TYPES}
    names = {case.name for case in CASES}
    for parts in (ARRANGEMENTS, SHAFT_ARRANGEMENTS, PAIRS, SOURCES, OPERATION):
        for part in parts:
            assert any(f".{part}." in f"{name}." for name in names), part
    assert len(names) == len(CASES)
    assert all(any(bin_.get("speed") == "0 rpm" or bin_.get("input_speed") == "0 rpm"
                   for bin_ in case.spec["duty_cycle"])
               for case in CASES if "duty_cycle" in case.spec)


def test_check_of_every_combination_ends_in_a_result_or_clear_lines(checked):
    run, records = checked
    _ends_cleanly(run, "check", said_on_stderr=False)
    assert len(records) == len(CASES)
    statuses = {record["status"] for record in records}
    assert run.code == (2 if "invalid" in statuses else 1 if "fail" in statuses else 0)
    solved: dict[str, set[str]] = {}
    for record in records:
        assert _finite(record), record
        assert not any(BROKEN.search(message) for message in record["messages"]), record
        if record["status"] == "invalid":
            assert record["messages"], record
            assert all(message.startswith(record["spec"]) for message in record["messages"])
        else:
            name = Path(record["spec"]).stem
            solved.setdefault(name.split(".")[0], set()).add(name.split(".")[1])
    # The matrix solves something of every type on its own (not only refusals), and
    # every radial type in a drive.
    assert solved["rolling-bearing"] == set(TYPES)


def test_solve_of_every_combination_ends_in_a_result_or_clear_lines(matrix, cli):
    paths = sorted(matrix.glob("*.yaml"))
    run = cli("solve", *paths, "--format", "json")
    _ends_cleanly(run, "solve")
    records = [json.loads(line) for line in run.out.splitlines()]
    assert records and all(_finite(record) for record in records)
    refused = {line.split(":", 1)[0] for line in run.err.splitlines()}
    assert {record["spec"] for record in records} | refused == {str(p) for p in paths}
    assert not {record["spec"] for record in records} & refused


def test_solve_tables_of_every_combination_that_solves(checked, cli):
    """The table of each solved combination prints (its matrices, load cases, bins)."""
    paths = [record["spec"] for record in checked[1] if record["status"] != "invalid"]
    run = cli("solve", *paths)
    _ends_cleanly(run, "solve table")
    assert run.code in (0, 1) and not run.err
    assert len(re.findall(r"^(?:PASS|FAIL):", run.out, re.MULTILINE)) >= len(paths)


def _sampled_file(tmp_path: Path, case: Case, tolerance: bool = False,
                  suffix: str = "") -> Path:
    path = tmp_path / f"{case.name}{suffix}.yaml"
    path.write_text(case.text(tolerance), encoding="utf-8")
    return path


def _sample(records: list[dict]) -> list[Case]:
    """The cases the slower commands run: chosen by the CRC-32 of their names, more of
    those that solve than of those refused."""
    solved = {Path(record["spec"]).stem for record in records if record["status"] != "invalid"}
    return [case for case in CASES
            if case.sampled(SAMPLE_SOLVED if case.name in solved else SAMPLE_REFUSED)]


def test_a_sample_through_tolerance_sweep_report_and_select(checked, tmp_path, cli):
    sample = _sample(checked[1])
    assert {case.kind for case in sample} == set(bearing_kinds())
    assert {case.name.rsplit(".", 1)[1] for case in sample} == set(OPERATION)
    for case in sample:
        spec = _sampled_file(tmp_path, case)
        toleranced = _sampled_file(tmp_path, case, tolerance=True, suffix=".toleranced")
        runs = {
            "tolerance": cli("tolerance", toleranced, "--samples", "1024", "--format", "json"),
            "sweep": cli("sweep", spec, "--vary", case.swept, "--format", "json"),
            "report": cli("report", spec, "--output", tmp_path / "report.html"),
            "select": cli("select", spec, "--catalogue", CATALOGUE, "--format", "json"),
        }
        for command, run in runs.items():
            _ends_cleanly(run, f"{command} {case.name}")
            if run.code in (0, 1) and command != "report":
                for line in run.out.splitlines():
                    assert _finite(json.loads(line)), (command, case.name, line)


#: One case in this many has every number of its spec varied as an array.
SAMPLE_VARIED = 20


def _numbers(model: BaseModel, prefix: str = "") -> list[tuple[str, float]]:
    """Every number of a spec by its dotted path (list items from 1), as --vary names it."""
    found = []
    for name in type(model).model_fields:
        value = getattr(model, name)
        items = list(enumerate(value, 1)) if isinstance(value, list) else [(None, value)]
        for i, item in items:
            path = f"{prefix}{name}" + ("" if i is None else f".{i}")
            if isinstance(item, BaseModel):
                found += _numbers(item, f"{path}.")
            elif isinstance(item, (int, float)) and not isinstance(item, bool):
                found.append((path, float(item)))
    return found


def test_every_number_of_a_sample_varies_as_an_array(matrix):
    """Sweeps and tolerance studies put an array in place of a field and solve all its
    values at once: no number of any combination may meet a test that takes one value
    (the solvers' and the models' alike), whatever the result (status codes judge it)."""
    varied = 0
    for case in CASES:
        if not case.sampled(SAMPLE_VARIED):
            continue
        (document,) = load_documents(matrix / f"{case.name}.yaml")
        try:
            kind, spec = parse_document(document)
        except SpecError:
            continue
        for path, value in _numbers(spec):
            values = np.array([0.9, 1.0, 1.1]) * value if value else np.array([0.0, 0.1, 0.2])
            _, status = kind.evaluate(with_values(spec, {path: values}).solver_inputs())
            # one status per value, or one for all where the field feeds no solver (a width)
            assert np.size(status) in (1, 3), (case.name, path)
            varied += 1
    assert varied > 500
