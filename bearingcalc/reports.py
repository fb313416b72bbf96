"""Presenting evaluations: rich tables (engineering units), JSON Lines and CSV (SI).

This is the only module that imports rich.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable, Sequence
from typing import IO, Any

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
