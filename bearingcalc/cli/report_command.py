"""The ``report`` command: a spec file's calculation report as one self-contained HTML
file (:mod:`bearingcalc.reports.calculation`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from bearingcalc.cli.app import CatalogueOption, DebugOption, OutputOption, app
from bearingcalc.cli_output import (
    WordedHelp,
    emit,
    errors_as_exit,
    output_target,
    refuse_unwritable,
)
from bearingcalc.output import StagedFiles


@app.command("report", cls=WordedHelp)
def report_command(
    spec_path: Annotated[Path, typer.Argument(
        help="A YAML spec file (every document of it goes in the report).",
        show_default=False, metavar="SPEC")],
    output: OutputOption = None,
    catalogue: CatalogueOption = None,
    debug: DebugOption = False,
) -> None:
    """Write a calculation report to print and file: one HTML file, nothing outside it.

    It holds the inputs, results, verdict, standards, plots and the spec itself.

    Exit status: 0 the report is written; 2 the spec cannot be read or solved.
    """
    with errors_as_exit(debug):
        from bearingcalc import batch
        from bearingcalc.reports.calculation import report_of

        target = output_target(output, "report", ".html")
        refuse_unwritable("report", [batch.spec_file(spec_path)], target)
        page = report_of(spec_path)
        with StagedFiles("report") as files:
            emit(lambda stream: stream.write(page), target, files)
