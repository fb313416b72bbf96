"""The typer app of the command line, and what its commands share: the options several
take, the check of a whole-number option, the number of worker processes.

The commands register on :data:`app` from the modules that define them
(:mod:`bearingcalc.cli` and its submodules), each importing the app from here.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import Annotated

import typer

from bearingcalc.cli_output import (
    EXIT_OK,
    OneLineUsageErrors,
    errors_as_exit,
    write_stdout,
)
from bearingcalc.errors import OptionError

app = typer.Typer(cls=OneLineUsageErrors, add_completion=False, pretty_exceptions_enable=False,
                  no_args_is_help=True,
                  context_settings={"help_option_names": ["-h", "--help"]},
                  help="Rolling-contact machine design: thrust bearings, bevel gears and more.")

MAX_JOBS_PER_CORE = 4


DebugOption = Annotated[bool, typer.Option("--debug", help="Show tracebacks of internal errors.")]
# Folders are refused by check_targets, in one line like every other unwritable target.
OutputOption = Annotated[Path | None, typer.Option(
    "--output", "-o", metavar="FILE",
    help="Write to this file instead of stdout (atomically: a failed run leaves "
    "an existing file as it was; never a file the run reads, a spec or a catalogue).")]
PlotOption = Annotated[Path | None, typer.Option(
    "--plot", metavar="FILE", help="Draw a chart to this .png or .svg file.")]


def whole_number(low: int, high: int | None = None) -> Callable[[int | None], int | None]:
    """An option's check that its whole number is at least ``low`` (and at most
    ``high``): said in one line, and in the help's own words rather than a range token."""
    def check(value: int | None) -> int | None:
        if value is not None and (value < low or (high is not None and value > high)):
            span = f"from {low} to {high}" if high is not None else f"of at least {low}"
            raise typer.BadParameter(f"{value}: give a whole number {span}")
        return value

    return check


def _use_catalogue(path: Path | None) -> Path | None:
    from bearingcalc.catalogue.places import set_default_catalogue

    set_default_catalogue(None if path is None else str(path))
    return path


CatalogueOption = Annotated[Path | None, typer.Option(
    "--catalogue", callback=_use_catalogue, show_default=False, metavar="FILE",
    help="The bearing catalogue (CSV) of specs that name a designation but no catalogue "
    "(default: the file the environment variable BEARINGCALC_CATALOGUE names).")]


def _print_version(value: bool) -> None:
    if value:
        from bearingcalc import __version__

        with errors_as_exit(debug=False):
            write_stdout(lambda stream: stream.write(f"bearingcalc {__version__}\n"))
        raise typer.Exit(EXIT_OK)


@app.callback()
def main(
    version: Annotated[bool, typer.Option(
        "--version", "-V", callback=_print_version, is_eager=True,
        help="Print the version and exit.")] = False,
) -> None:
    """Rolling-contact machine design from YAML specs."""


def worker_count(jobs: int | None) -> int:
    """The number of workers: ``--jobs``, or the cores; at most ``MAX_JOBS_PER_CORE`` per
    core, since more only fight over the same cores (and hundreds of processes can
    exhaust a shared machine)."""
    cores = os.cpu_count() or 1
    most = MAX_JOBS_PER_CORE * cores
    if jobs is not None and jobs > most:
        raise OptionError("--jobs", f"{jobs} is more than {most} ({MAX_JOBS_PER_CORE} per "
                          f"core on this machine's {cores}); leave it out to use every core")
    return jobs or cores
