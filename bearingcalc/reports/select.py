"""The reports of ``select``: per bearing position, the smallest bearings that meet every
limit and the nearest that do not, as a table (engineering units), JSON Lines or CSV
(SI)."""

from __future__ import annotations

import json
from typing import IO, TYPE_CHECKING, Any

from bearingcalc.core.common import MM
from bearingcalc.reports.csv_cells import Cell, write_csv_rows
from bearingcalc.reports.formatting import console, format_number, print_whole, safe_text
from bearingcalc.reports.solve import verdict_record
from bearingcalc.verdicts import verdict_line
from bearingcalc.wording import plural, printable

if TYPE_CHECKING:
    from bearingcalc.selection import Candidate, PositionChoice, Selection



def _verdict(candidate: Candidate) -> str:
    """The governing limit of a qualifying row, or what a failing one misses."""
    if candidate.problem:
        return candidate.problem
    if not candidate.verdicts:
        return "no limits judged"
    if candidate.qualifies:
        return verdict_line(candidate.verdicts[0])
    return "; ".join(verdict_line(v) for v in candidate.verdicts if not v.passed)


def candidate_record(candidate: Candidate) -> dict[str, Any]:
    """A listed row as JSON (SI)."""
    row = candidate.row
    return {"designation": row.designation, "maker": row.maker, "type": row.type,
            "bore_diameter": row.values["bore_diameter"],
            "outside_diameter": row.values["outside_diameter"],
            "width": row.values["width"], "mass": row.values.get("mass"),
            "catalogue_source": row.cited, "qualifies": candidate.qualifies,
            "governing": (verdict_record(candidate.verdicts[0]) if candidate.verdicts
                          else None),
            "problem": candidate.problem}


def _records(selection: Selection) -> list[dict[str, Any]]:
    return [{"spec": selection.source, "kind": selection.kind, "name": selection.name,
             "catalogue": selection.catalogue, "position": choice.position,
             "considered": choice.considered, "qualifying_count": choice.qualifying_count,
             "notes": choice.notes,
             "qualifying": [candidate_record(c) for c in choice.qualifying],
             "failing": [candidate_record(c) for c in choice.failing]}
            for choice in selection.choices]


def write_select_json_lines(selection: Selection, stream: IO[str]) -> None:
    """One JSON object per bearing position."""
    for record in _records(selection):
        stream.write(json.dumps(record, allow_nan=False, ensure_ascii=False) + "\n")


def write_select_csv(selection: Selection, stream: IO[str]) -> None:
    """One row per listed bearing, the qualifying first (ranked), SI units."""
    rows: list[list[Cell]] = [[
        "spec", "position", "rank", "qualifies", "designation", "maker", "type",
        "bore_diameter [m]", "outside_diameter [m]", "width [m]", "mass [kg]",
        "governing", "governing_margin", "verdict", "catalogue_source"]]
    for choice in selection.choices:
        listed = [*choice.qualifying, *choice.failing]
        for rank, candidate in enumerate(listed, 1):
            row = candidate.row
            governing = candidate.verdicts[0] if candidate.verdicts else None
            rows.append([
                selection.source, choice.position, rank if candidate.qualifies else None,
                candidate.qualifies, row.designation, row.maker, row.type,
                row.values["bore_diameter"], row.values["outside_diameter"],
                row.values["width"], row.values.get("mass"),
                governing.key if governing else None,
                None if governing is None else governing.margin,
                _verdict(candidate), row.cited])
    write_csv_rows(stream, rows)


def print_select_table(selection: Selection, stream: IO[str] | None = None) -> None:
    """Per position, the qualifying bearings smallest first, then the nearest misses."""
    out = console(stream)
    for choice in selection.choices:
        _print_choice(out, selection, choice)


def _print_choice(out: Any, selection: Selection, choice: PositionChoice) -> None:
    from rich.table import Table

    where = f", {choice.position}" if choice.position else ""
    print_whole(out, safe_text(f"{selection.name}  (select, {selection.source}{where})"))
    print_whole(out, safe_text(f"catalogue {selection.catalogue}: "
                               f"{plural(choice.considered, 'bearing')} fit the shaft and the "
                               f"envelope, {choice.qualifying_count} meet every limit"))
    for note in choice.notes:
        out.print(f"[yellow]note[/]: {safe_text(note)}")
    if choice.qualifying:
        table = Table(title="meet every limit, smallest first", title_justify="left")
        for name in ("#", "designation", "maker", "type", "d [mm]", "D [mm]", "B [mm]",
                     "mass [kg]", "governing limit"):
            table.add_column(safe_text(name),
                             justify="right" if "[" in name or name == "#" else "left")
        for rank, candidate in enumerate(choice.qualifying, 1):
            row = candidate.row
            mass = row.values.get("mass")
            table.add_row(str(rank), safe_text(row.designation), safe_text(row.maker),
                          row.type, format_number(row.values["bore_diameter"] * MM),
                          format_number(row.values["outside_diameter"] * MM),
                          format_number(row.values["width"] * MM),
                          "" if mass is None else format_number(mass),
                          safe_text(_verdict(candidate)))
        out.print(table)
    if choice.failing:
        table = Table(title="the nearest that fail", title_justify="left")
        for name in ("designation", "maker", "type", "D [mm]", "B [mm]", "misses"):
            table.add_column(safe_text(name), justify="right" if "[" in name else "left")
        for candidate in choice.failing:
            row = candidate.row
            table.add_row(safe_text(row.designation), safe_text(row.maker), row.type,
                          format_number(row.values["outside_diameter"] * MM),
                          format_number(row.values["width"] * MM),
                          safe_text(_verdict(candidate)))
        out.print(table)
    if choice.qualifying:
        best = choice.qualifying[0].row
        out.print(f"[bold green]SELECTED[/] {safe_text(best.designation)} "
                  f"({safe_text(best.maker)}) as {safe_text(choice.label)}; its row is from "
                  f"{safe_text(printable(best.source))}")
    else:
        out.print(f"[bold red]NONE[/] of the catalogue's bearings meets every limit for "
                  f"{safe_text(choice.label)}")
    out.print()
