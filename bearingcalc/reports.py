"""Presenting evaluations: rich tables (engineering units), JSON Lines and CSV (SI).

This is the only module that imports rich.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable, Sequence
from typing import IO, Any

from bearingcalc.batch import CheckRecord
from bearingcalc.evaluation import Evaluation
from bearingcalc.units import to_display


def evaluation_record(evaluation: Evaluation) -> dict[str, Any]:
    """The JSON object of one evaluation (SI values)."""
    return {
        "spec": evaluation.source,
        "kind": evaluation.kind,
        "name": evaluation.name,
        "results": evaluation.results,
        "units": evaluation.units,
        "within_limits": evaluation.within_limits,
        "warnings": evaluation.warnings,
    }


def write_json_lines(evaluations: Iterable[Evaluation], stream: IO[str]) -> None:
    """One JSON object per evaluation per line; non-finite numbers are refused."""
    for evaluation in evaluations:
        stream.write(json.dumps(evaluation_record(evaluation), allow_nan=False,
                                ensure_ascii=False) + "\n")


def write_csv(evaluations: Sequence[Evaluation], stream: IO[str]) -> None:
    """One row per evaluation, SI units in the header; columns are the union of keys."""
    columns: dict[str, str] = {}
    for evaluation in evaluations:
        for key, unit in evaluation.units.items():
            columns.setdefault(key, unit)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["spec", "kind", "name", "within_limits",
                     *(f"{key} [{unit}]" for key, unit in columns.items())])
    for evaluation in evaluations:
        values = [evaluation.results.get(key) for key in columns]
        writer.writerow([evaluation.source, evaluation.kind, evaluation.name,
                         str(evaluation.within_limits).lower(),
                         *("" if value is None else repr(value) for value in values)])
    stream.write(buffer.getvalue())


def print_tables(evaluations: Iterable[Evaluation], descriptions: dict[str, dict[str, str]],
                 stream: IO[str] | None = None) -> None:
    """A table per evaluation in engineering units, with a PASS/FAIL verdict.

    ``descriptions`` maps kind -> result key -> meaning. The verdict is written
    in words, so the table reads the same without colour.
    """
    from rich.console import Console
    from rich.table import Table

    console = Console(file=stream, highlight=False)
    for evaluation in evaluations:
        table = Table(title=f"{evaluation.name}  ({evaluation.kind}, {evaluation.source})",
                      title_justify="left")
        table.add_column("result")
        table.add_column("value", justify="right")
        table.add_column("unit")
        table.add_column("meaning", style="dim")
        meanings = descriptions.get(evaluation.kind, {})
        for key, value in evaluation.results.items():
            if value is None:
                shown, unit = "unbounded", to_display(0.0, evaluation.units[key])[1]
            else:
                number, unit = to_display(value, evaluation.units[key])
                shown = format_number(number)
            style = "bold" if key in evaluation.margins else None
            table.add_row(key, shown, unit, meanings.get(key, ""), style=style)
        console.print(table)
        if not evaluation.margins:
            console.print("[bold green]PASS[/]: no limits apply to this kind")
        elif evaluation.within_limits:
            console.print("[bold green]PASS[/]: within limits")
        else:
            console.print(f"[bold red]FAIL[/]: {'; '.join(evaluation.violations)}")
        for warning in evaluation.warnings:
            console.print(f"[yellow]warning[/]: {warning}")
        console.print()


def format_number(value: float) -> str:
    """Seven significant digits; exact zero stays 0."""
    if value == 0:
        return "0"
    return f"{value:.7g}"


def check_record_json(record: CheckRecord) -> dict[str, Any]:
    """The JSON object of one check verdict."""
    return {"spec": record.spec, "kind": record.kind, "name": record.name,
            "status": record.status, "messages": record.messages, "margins": record.margins}


def write_check_json_lines(records: Iterable[CheckRecord], stream: IO[str]) -> None:
    for record in records:
        stream.write(json.dumps(check_record_json(record), allow_nan=False,
                                ensure_ascii=False) + "\n")


def write_junit(records: Sequence[CheckRecord], stream: IO[str]) -> None:
    """JUnit XML: one testcase per spec; ``fail`` as failure, ``invalid`` as error."""
    from xml.etree import ElementTree

    failures = sum(r.status == "fail" for r in records)
    errors = sum(r.status == "invalid" for r in records)
    suites = ElementTree.Element("testsuites", name="bearingcalc check", tests=str(len(records)),
                                 failures=str(failures), errors=str(errors))
    suite = ElementTree.SubElement(suites, "testsuite", name="bearingcalc check",
                                   tests=str(len(records)), failures=str(failures),
                                   errors=str(errors), skipped="0")
    for record in records:
        case = ElementTree.SubElement(suite, "testcase", classname=record.kind or "spec",
                                      name=record.spec, file=record.spec.split("#")[0])
        text = "\n".join(record.messages)
        if record.status == "fail":
            ElementTree.SubElement(case, "failure", message=_first(record.messages),
                                   type="limit").text = text
        elif record.status == "invalid":
            ElementTree.SubElement(case, "error", message=_first(record.messages),
                                   type="invalid").text = text
    ElementTree.indent(suites)
    stream.write('<?xml version="1.0" encoding="UTF-8"?>\n')
    stream.write(ElementTree.tostring(suites, encoding="unicode") + "\n")


def print_check_table(records: Sequence[CheckRecord], *, show_all: bool,
                      stream: IO[str] | None = None, many: int = 50) -> None:
    """One row per spec (only fail/invalid rows past ``many`` specs unless ``show_all``),
    then a summary line with the counts."""
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    console = Console(file=stream, highlight=False)
    shown = records if show_all or len(records) <= many else [
        r for r in records if r.status != "pass"]
    if shown:
        table = Table(show_edge=False)
        for column in ("status", "name", "kind", "governing margin / problem"):
            table.add_column(column, overflow="fold")
        colours = {"pass": "green", "fail": "red", "invalid": "magenta"}
        for record in shown:
            governing = record.governing_margin
            if record.status == "invalid":
                detail = _first(record.messages)
            elif governing is None:
                detail = "no limits apply"
            else:
                detail = f"{governing[0]} = {format_number(governing[1])}"
            table.add_row(f"[{colours[record.status]}]{record.status.upper()}[/]",
                          escape(record.name or record.spec), record.kind or "",
                          escape(detail))
        console.print(table)
    counts = {status: sum(r.status == status for r in records)
              for status in ("pass", "fail", "invalid")}
    hidden = len(records) - len(shown)
    note = f" ({hidden} passing not shown; --all shows them)" if hidden else ""
    console.print(f"{len(records)} specs: [green]{counts['pass']} pass[/], "
                  f"[red]{counts['fail']} fail[/], "
                  f"[magenta]{counts['invalid']} invalid[/]{note}")


def _first(messages: Sequence[str]) -> str:
    return messages[0] if messages else ""
