"""The reports of ``solve``: a table per evaluation (engineering units), JSON Lines and
CSV (SI)."""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping, Sequence
from typing import IO, TYPE_CHECKING, Any

from bearingcalc.reports.csv_cells import write_csv_rows
from bearingcalc.reports.formatting import console, format_number, print_whole, safe_text
from bearingcalc.units import to_display
from bearingcalc.verdicts import Verdict, verdict_line

if TYPE_CHECKING:  # the report types only; their modules load with their commands
    from bearingcalc.evaluation import Evaluation
    from bearingcalc.kinds import Kind
    from bearingcalc.result_keys import ResultTable


def evaluation_record(evaluation: Evaluation) -> dict[str, Any]:
    """The JSON object of one evaluation (SI values)."""
    return {
        "spec": evaluation.source,
        "kind": evaluation.kind,
        "name": evaluation.name,
        **evaluation.sources,
        "results": evaluation.results,
        "units": evaluation.units,
        "within_limits": evaluation.within_limits,
        "verdicts": [verdict_record(verdict) for verdict in evaluation.verdicts],
        "warnings": evaluation.warnings,
    }


def verdict_record(verdict: Verdict) -> dict[str, Any]:
    """A verdict as JSON data (SI): the margin as a fraction of the limit."""
    return {"key": verdict.key, "name": verdict.name, "value": verdict.value,
            "limit": verdict.limit, "unit": verdict.unit, "margin": verdict.margin,
            "at_least": verdict.at_least, "passed": verdict.passed}


def write_json_lines(evaluations: Iterable[Evaluation], stream: IO[str]) -> None:
    """One JSON object per evaluation per line; non-finite numbers are refused."""
    for evaluation in evaluations:
        stream.write(json.dumps(evaluation_record(evaluation), allow_nan=False,
                                ensure_ascii=False) + "\n")


def write_csv(evaluations: Sequence[Evaluation], stream: IO[str]) -> None:
    """One row per evaluation, SI units in the header; columns are the union of keys.
    Nothing at all without an evaluation: there are no columns to name."""
    if not evaluations:
        return
    columns: dict[str, str] = {}
    sources: dict[str, None] = {}
    for evaluation in evaluations:
        for key, unit in evaluation.units.items():
            columns.setdefault(key, unit)
        sources.update(dict.fromkeys(evaluation.sources))
    header = ["spec", "kind", "name", *sources, "within_limits",
              *(f"{key} [{unit}]" for key, unit in columns.items())]
    write_csv_rows(stream, [header, *(
        [evaluation.source, evaluation.kind, evaluation.name,
         *(evaluation.sources.get(key, "") for key in sources), evaluation.within_limits,
         *(evaluation.results.get(key) for key in columns)]
        for evaluation in evaluations)])


def print_tables(evaluations: Iterable[Evaluation], kinds: Mapping[str, Any],
                 stream: IO[str] | None = None) -> None:
    """A table per evaluation in engineering units, with a PASS/FAIL verdict.

    ``kinds`` maps a kind's name to its registry entry, which gives each result's
    meaning, the headings that group a long table and any table units of its own.
    The verdict is written in words, so the table reads the same without colour.
    """
    from rich.table import Table

    out = console(stream)
    for evaluation in evaluations:
        kind = kinds[evaluation.kind]
        # The heading names the spec's file: above the table, whole (not its title,
        # which wraps to the table's width); the catalogue rows cited wrap as prose.
        print_whole(out, safe_text(f"{evaluation.name}  ({evaluation.kind}, "
                                   f"{evaluation.source})"))
        for key, value in evaluation.sources.items():
            out.print(f"{key}: {safe_text(value)}")
        table = Table()
        # Narrow terminals take their room from the meaning, which wraps; a key, a
        # number and a unit are read whole.
        table.add_column("result", no_wrap=True)
        table.add_column("value", justify="right", no_wrap=True)
        table.add_column("unit", no_wrap=True)
        table.add_column("meaning", style="dim", overflow="fold")
        in_matrices = {key for matrix in evaluation.tables for key in matrix.keys}
        shown = {key: value for key, value in evaluation.results.items()
                 if key not in in_matrices}
        for heading, keys in _grouped(shown, kind.groups):
            if heading:
                table.add_row(f"[bold]{heading}[/]", end_section=False)
            for key in keys:
                value = evaluation.results[key]
                unit, factor = kind.display.get(key) or to_display(1.0, evaluation.units[key])[::-1]
                shown = "unbounded" if value is None else format_number(value * factor)
                if value is not None and key in kind.labels:
                    shown = kind.labels[key].get(value, shown)
                style = "bold" if key in evaluation.margins else None
                table.add_row(key, shown, unit, evaluation.meanings[key], style=style)
            if heading:
                table.add_section()
        out.print(table)
        for matrix in evaluation.tables:
            _print_matrix(out, evaluation, matrix, kind.labels)
        _print_verdict(out, evaluation, kind)
        for warning in evaluation.warnings:
            out.print(f"[yellow]warning[/]: {safe_text(warning)}")
        out.print()


def _print_verdict(out: Any, evaluation: Evaluation, kind: Kind) -> None:
    """PASS with the limit nearest to failing, or FAIL with each limit broken."""
    if not evaluation.margins:
        out.print(f"[bold green]PASS[/]: {safe_text(_no_margins(kind))}")
    elif evaluation.within_limits:
        count = len(evaluation.verdicts)
        closest = (": within limits" if not count else
                   f": {verdict_line(evaluation.verdicts[0])}, the only limit judged"
                   if count == 1 else
                   f": {verdict_line(evaluation.verdicts[0])}, the closest of {count} "
                   "limits")
        out.print(f"[bold green]PASS[/]{safe_text(closest)}")
    else:
        for line in evaluation.violations:
            out.print(f"[bold red]FAIL[/]: {safe_text(line)}")


def _no_margins(kind: Kind) -> str:
    """Why a design with no margins passes: its kind has no limits, or none were given."""
    fields = kind.limit_fields
    if not fields:
        return "this kind has no limits"
    named = ", ".join(f"limits.{name}" for name in fields[:-1]) + f" or limits.{fields[-1]}"
    return f"no limits judged: none given that applies to this design; the spec can set {named}"


def _print_matrix(out: Any, evaluation: Evaluation, matrix: ResultTable,
                  labels: Mapping[str, Mapping[float, str]]) -> None:
    """Results along an axis as a table with a row per member (a bearing, a bin) and a
    column per quantity any member has; nothing when the evaluation has none of them.
    Where that table is wider than the terminal, it is turned: a row per quantity, a
    column per member, so that every number stays whole."""
    from rich.table import Table

    heading = matrix.heading
    rows = [(row, cells) for row, cells in zip(matrix.rows, matrix.cells, strict=True)
            if any(key in evaluation.results for key in cells if key is not None)]
    if not rows:
        return
    shown = [k for k in range(len(matrix.columns))
             if any(cells[k] in evaluation.results for _, cells in rows)]
    headings = []
    for k in shown:
        first = next(cells[k] for _, cells in rows if cells[k] is not None)
        unit = to_display(1.0, evaluation.units.get(first, "1"))[1]
        name = matrix.columns[k].replace("_", " ")
        headings.append(safe_text(f"{name} [{unit}]" if unit else name))
    names = [safe_text(evaluation.row_names.get(row, row)) for row, _ in rows]
    cells = [[_matrix_cell(evaluation, cells[k], labels.get(matrix.columns[k]))
              for k in shown] for _, cells in rows]
    # each column as wide as its widest number and its longest heading word, plus borders
    wide = max(map(len, names)) + 4 + sum(
        max(*(len(cell[k]) for cell in cells), *map(len, headings[k].split())) + 3
        for k in range(len(headings)))
    table = Table(title=heading, title_justify="left")
    if wide <= out.width:
        table.add_column("", no_wrap=True)  # the member's name, whole
        for name in headings:  # in words: a long heading wraps, the numbers stay whole
            table.add_column(name, justify="right")
        for name, row in zip(names, cells, strict=True):
            table.add_row(name, *row)
    else:
        table.add_column("", overflow="fold")
        for name in names:
            table.add_column(name, justify="right", no_wrap=True)
        for k, name in enumerate(headings):
            table.add_row(name, *(row[k] for row in cells))
    out.print(table)


def _matrix_cell(evaluation: Evaluation, key: str | None,
                 labels: Mapping[float, str] | None) -> str:
    value = None if key is None else evaluation.results.get(key)
    if value is None:
        return ""
    if labels is not None:
        return labels.get(value, format_number(value))
    return format_number(to_display(value, evaluation.units[key])[0])  # type: ignore[index]


def _grouped(results: Mapping[str, Any], groups: Mapping[str, Sequence[str]]
             ) -> list[tuple[str, list[str]]]:
    """(heading, keys) in table order: each group's results that are present, then the
    rest under no heading; one unnamed group when the kind has no headings."""
    if not groups:
        return [("", list(results))]
    placed = [(heading, [key for key in keys if key in results])
              for heading, keys in groups.items()]
    grouped = {key for _, keys in placed for key in keys}
    rest = [key for key in results if key not in grouped]
    return [(heading, keys) for heading, keys in placed if keys] + ([("", rest)] if rest else [])
