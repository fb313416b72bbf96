"""The ``bearingcalc`` command line: parses options, calls the library, prints.

Exit status: 0 every spec within its limits; 1 some spec violates a limit;
2 some spec could not be read or is invalid (2 wins over 1).
"""

from __future__ import annotations

import sys
import traceback
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from bearingcalc.errors import SpecError

app = typer.Typer(add_completion=False, pretty_exceptions_enable=False, no_args_is_help=True,
                  help="Rolling-contact machine design: thrust bearings, bevel gears and more.")

EXIT_OK, EXIT_LIMIT, EXIT_INVALID = 0, 1, 2


class SolveFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


DebugOption = Annotated[bool, typer.Option("--debug", help="Show tracebacks of internal errors.")]


@app.callback()
def main() -> None:
    """Rolling-contact machine design from YAML specs."""


@app.command()
def solve(
    specs: Annotated[list[Path], typer.Argument(
        help="YAML spec files.", show_default=False, metavar="SPEC...")],
    output_format: Annotated[SolveFormat, typer.Option(
        "--format", "-f", help="table (engineering units), json (JSON Lines, SI) or csv (SI).")
    ] = SolveFormat.table,
    debug: DebugOption = False,
) -> None:
    """Solve each spec and report every speed, the spin-to-roll ratio and the slip margin."""
    with _errors_as_exit(debug):
        from bearingcalc import reports
        from bearingcalc.evaluation import Evaluation, evaluate_file
        from bearingcalc.kinds import KINDS

        evaluations: list[Evaluation] = []
        invalid = False
        for path in specs:
            for outcome in evaluate_file(path):
                if isinstance(outcome, SpecError):
                    invalid = True
                    _print_error(outcome)
                else:
                    evaluations.append(outcome)
        if output_format is SolveFormat.json:
            reports.write_json_lines(evaluations, sys.stdout)
        elif output_format is SolveFormat.csv:
            if evaluations:
                reports.write_csv(evaluations, sys.stdout)
        else:
            descriptions = {name: {key: meaning for key, (_, meaning) in kind.results.items()}
                            for name, kind in KINDS.items()}
            reports.print_tables(evaluations, descriptions)
        if invalid:
            raise typer.Exit(EXIT_INVALID)
        if not all(evaluation.within_limits for evaluation in evaluations):
            raise typer.Exit(EXIT_LIMIT)


def _print_error(error: Exception) -> None:
    print(f"error: {error}" if not isinstance(error, SpecError) else str(error), file=sys.stderr)


class _errors_as_exit:
    """Turns any unexpected exception into one line on stderr and exit status 2."""

    def __init__(self, debug: bool) -> None:
        self.debug = debug

    def __enter__(self) -> None:
        return None

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: object) -> bool:
        if exc is None or isinstance(exc, (typer.Exit, typer.Abort, SystemExit)):
            return False
        if isinstance(exc, KeyboardInterrupt):
            print("interrupted", file=sys.stderr)
            raise typer.Exit(130)
        if isinstance(exc, BrokenPipeError):
            raise typer.Exit(EXIT_OK)
        if self.debug:
            traceback.print_exception(exc)
        if isinstance(exc, SpecError):
            _print_error(exc)
        else:
            print(f"internal error: {type(exc).__name__}: {exc} "
                  "(run again with --debug for the traceback, and please report it)",
                  file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)
