"""The ``select`` command: the smallest bearings of a catalogue that meet a spec's
limits (:mod:`bearingcalc.selection`)."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from bearingcalc.cli.app import CatalogueOption, DebugOption, OutputOption, app, whole_number
from bearingcalc.cli_output import (
    EXIT_LIMIT,
    WordedHelp,
    Writer,
    emit,
    errors_as_exit,
    output_target,
    refuse_unwritable,
)
from bearingcalc.output import StagedFiles

MAX_TOP = 100


class SelectFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


@app.command("select", cls=WordedHelp)
def select_command(
    spec_path: Annotated[Path, typer.Argument(
        help="A rolling-bearing spec (loads, speed, lubrication, limits; bore_diameter the "
        "shaft, outside_diameter and width the envelope) or a bevel-drive spec.",
        show_default=False, metavar="SPEC")],
    catalogue: CatalogueOption = None,
    bearing_type: Annotated[list[str] | None, typer.Option(
        "--type", "-t", metavar="TYPE",
        help="Allow this bearing type (repeatable; default: the spec's type, "
        "else every type).", show_default=False)] = None,
    series: Annotated[list[str] | None, typer.Option(
        "--series", "-s", metavar="SERIES",
        help="Allow this series, as designations begin: 62, 73, NU22, 302 "
        "(repeatable; default: every series).", show_default=False)] = None,
    max_outside_diameter: Annotated[str | None, typer.Option(
        "--max-outside-diameter", metavar="LENGTH",
        help="The largest outside diameter D, like '62 mm'.",
        show_default=False)] = None,
    max_width: Annotated[str | None, typer.Option(
        "--max-width", metavar="LENGTH",
        help="The largest width B (T of a tapered bearing), like '17 mm'.",
        show_default=False)] = None,
    top: Annotated[int, typer.Option(
        "--top", "-n", callback=whole_number(1, MAX_TOP), metavar="N",
        help=f"List this many of each, 1 to {MAX_TOP}.")] = 5,
    output_format: Annotated[SelectFormat, typer.Option(
        "--format", "-f", metavar="FORMAT",
        help="table (engineering units), json (JSON Lines, SI) or csv (SI).")
    ] = SelectFormat.table,
    output: OutputOption = None,
    debug: DebugOption = False,
) -> None:
    """Choose the smallest bearings of a catalogue that meet every limit of the spec.

    They are ranked by outside diameter, width and mass; the nearest that fail follow.

    Exit status: 0 a bearing qualifies (in every position a drive selects); 1 none
    does; 2 the spec, the catalogue or the options are invalid, or no bearing fits.
    """
    with errors_as_exit(debug):
        from bearingcalc import batch
        from bearingcalc.envelope import envelope_from_options
        from bearingcalc.reports.select import (
            print_select_table,
            write_select_csv,
            write_select_json_lines,
        )
        from bearingcalc.selection import select_spec

        target = output_target(output, "selection", {
            SelectFormat.table: ".txt", SelectFormat.json: ".jsonl",
            SelectFormat.csv: ".csv"}[output_format])
        refuse_unwritable("select", [batch.spec_file(spec_path)], target)
        envelope = envelope_from_options(bearing_type or [], series or [],
                                         max_outside_diameter, max_width)
        selection = select_spec(spec_path, envelope, top)
        writers: dict[SelectFormat, Writer] = {
            SelectFormat.table: lambda stream: print_select_table(selection, stream),
            SelectFormat.json: lambda stream: write_select_json_lines(selection, stream),
            SelectFormat.csv: lambda stream: write_select_csv(selection, stream),
        }
        with StagedFiles("select") as files:
            emit(writers[output_format], target, files)
        if not selection.found:
            raise typer.Exit(EXIT_LIMIT)
