"""The ``bearingcalc`` command line: parses options, calls the library and a report
writer per format, and sets the exit status. How a report reaches stdout or a file,
and how an error becomes one line, is :mod:`bearingcalc.cli_output`.

Exit status: 0 every spec within its limits; 1 some spec violates a limit;
2 some spec could not be read or is invalid (2 wins over 1).
"""

from __future__ import annotations

import os
import sys
from enum import Enum
from pathlib import Path
from typing import Annotated

# pydantic scans installed packages for plugins on its first model; bearingcalc uses
# none, and the scan costs about 20 ms of every command's start.
os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")

import typer

from bearingcalc.cli.app import (
    CatalogueOption,
    DebugOption,
    OutputOption,
    app,
    whole_number,
    worker_count,
)
from bearingcalc.cli_output import (
    EXIT_INVALID,
    EXIT_LIMIT,
    HelpListsKinds,
    WordedHelp,
    Writer,
    bad_option,
    emit,
    errors_as_exit,
    output_target,
    print_error,
    refuse_unwritable,
    with_progress,
    write_stdout,
)
from bearingcalc.errors import SpecError
from bearingcalc.output import StagedFiles

__all__ = ["app"]


class SolveFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


@app.command(cls=HelpListsKinds)
def solve(
    specs: Annotated[list[Path], typer.Argument(
        help="YAML spec files.", show_default=False, metavar="SPEC...")],
    output_format: Annotated[SolveFormat, typer.Option(
        "--format", "-f", metavar="FORMAT",
        help="table (engineering units), json (JSON Lines, SI) or csv (SI).")
    ] = SolveFormat.table,
    catalogue: CatalogueOption = None,
    debug: DebugOption = False,
) -> None:
    """Solve each spec and report every result of its kind and the verdict on its limits.

    Exit status: 0 every spec within its limits; 1 a limit violated; 2 a spec invalid.
    """
    with errors_as_exit(debug):
        from bearingcalc import reports
        from bearingcalc.evaluation import Evaluation, evaluate_file
        from bearingcalc.kinds import KINDS

        evaluations: list[Evaluation] = []
        invalid = False
        for path in specs:
            for outcome in evaluate_file(path):
                if isinstance(outcome, SpecError):
                    invalid = True
                    print_error(outcome)
                else:
                    evaluations.append(outcome)

        writers: dict[SolveFormat, Writer] = {
            SolveFormat.table: lambda stream: reports.print_tables(evaluations, KINDS, stream),
            SolveFormat.json: lambda stream: reports.write_json_lines(evaluations, stream),
            SolveFormat.csv: lambda stream: reports.write_csv(evaluations, stream),
        }
        write_stdout(writers[output_format])
        if invalid:
            raise typer.Exit(EXIT_INVALID)
        if not all(evaluation.within_limits for evaluation in evaluations):
            raise typer.Exit(EXIT_LIMIT)


class CheckFormat(str, Enum):
    table = "table"
    json = "json"
    junit = "junit"


@app.command(cls=WordedHelp)
def check(
    paths: Annotated[list[str], typer.Argument(
        help="Spec files, folders (searched recursively for *.yaml and *.yml) or globs.",
        show_default=False, metavar="PATH...")],
    output_format: Annotated[CheckFormat, typer.Option(
        "--format", "-f", metavar="FORMAT",
        help="table, json (JSON Lines) or junit (JUnit XML).")
    ] = CheckFormat.table,
    output: OutputOption = None,
    jobs: Annotated[int | None, typer.Option(
        "--jobs", "-j", callback=whole_number(1), metavar="N",
        help="Worker processes, 1 or more (default: the number of cores).",
        show_default=False)] = None,
    show_all: Annotated[bool, typer.Option(
        "--all", help="Table: list passing specs too when there are many.")] = False,
    catalogue: CatalogueOption = None,
    debug: DebugOption = False,
) -> None:
    """Check every spec: pass (within limits), fail (a limit violated) or invalid.

    Exit status: 0 all pass; 1 some fail and none invalid; 2 any invalid.
    """
    with errors_as_exit(debug):
        from bearingcalc import batch, reports

        workers = worker_count(jobs)
        entries = batch.discover(paths)
        report = output_target(output, "report", _CHECK_SUFFIXES[output_format])
        refuse_unwritable("check", batch.files_read(entries), report)
        records = with_progress(lambda tick: batch.check_entries(entries, workers, tick))

        writers: dict[CheckFormat, Writer] = {
            CheckFormat.table: lambda stream: reports.print_check_table(
                records, show_all=show_all, stream=stream),
            CheckFormat.json: lambda stream: reports.write_check_json_lines(records, stream),
            CheckFormat.junit: lambda stream: reports.write_junit(records, stream),
        }
        with StagedFiles("check") as files:
            emit(writers[output_format], report, files)
        raise typer.Exit(batch.exit_status(records))


@app.command(cls=WordedHelp)
def schema(
    kind: Annotated[str | None, typer.Option(
        "--kind", "-k", metavar="KIND",
        help="Only this kind's schema (see 'bearingcalc new --list').")] = None,
) -> None:
    """Print the JSON Schema (draft 2020-12) of the spec format, for editors and CI.

    Exit status: 0; 2 for an unknown kind.
    """
    import json

    from bearingcalc.kinds import KINDS, unknown_kind
    from bearingcalc.schema import spec_schema

    if kind is not None and kind not in KINDS:
        raise bad_option("--kind", unknown_kind(kind))
    text = json.dumps(spec_schema(kind), indent=2, ensure_ascii=False) + "\n"
    with errors_as_exit(debug=False):
        write_stdout(lambda stream: stream.write(text))


@app.command(cls=WordedHelp)
def new(
    kind_name: Annotated[str | None, typer.Argument(
        help="The kind of spec.", show_default=False, metavar="KIND")
                    ] = None,
    bearing_type: Annotated[str | None, typer.Option(
        "--type", metavar="TYPE", help="A template of this type, where the kind has several.",
        show_default=False)] = None,
    method: Annotated[str | None, typer.Option(
        "--method", metavar="METHOD", help="A template solved by this method, where the "
        "kind has several (rolling-bearing: iso-16281).", show_default=False)] = None,
    list_kinds: Annotated[bool, typer.Option("--list", help="List the kinds.")] = False,
) -> None:
    """Print a commented template spec of KIND, ready for 'bearingcalc check'.

    Exit status: 0; 2 for an unknown kind or type, or no KIND (the kinds are listed).
    """
    from bearingcalc.kinds import KINDS, unknown_kind
    from bearingcalc.templates import method_template_text, template_text

    if list_kinds or kind_name is None:
        text = "".join(f"{name:16} {entry.summary}\n" for name, entry in KINDS.items())
    elif kind_name not in KINDS:
        raise bad_option("KIND", unknown_kind(kind_name))
    elif method is not None and bearing_type is not None:
        raise bad_option("--method", "give --type or --method, not both: a method's "
                         "template has its own type")
    else:
        try:
            text = (template_text(kind_name, bearing_type) if method is None
                    else method_template_text(kind_name, method))
        except LookupError as error:
            raise bad_option("--type" if method is None else "--method", str(error)) from None
    with errors_as_exit(debug=False):
        write_stdout(lambda stream: stream.write(text))
    if kind_name is None and not list_kinds:
        print("bearingcalc new: give a KIND, one of those above (see 'bearingcalc new -h')",
              file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)


_CHECK_SUFFIXES = {CheckFormat.table: ".txt", CheckFormat.json: ".jsonl",
                   CheckFormat.junit: ".xml"}


# The commands of their own modules, registered on ``app`` as they load.
from bearingcalc.cli import report_command, select_command, studies  # noqa: E402,F401
