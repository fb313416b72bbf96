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

from bearingcalc.cli_output import (
    EXIT_INVALID,
    EXIT_LIMIT,
    EXIT_OK,
    HelpListsKinds,
    Writer,
    check_parquet_output,
    check_plot_name,
    emit,
    errors_as_exit,
    output_target,
    plot_target,
    print_error,
    refuse_unwritable,
    stage_plot,
    with_progress,
    write_stdout,
)
from bearingcalc.errors import SpecError
from bearingcalc.output import StagedFiles

app = typer.Typer(add_completion=False, pretty_exceptions_enable=False, no_args_is_help=True,
                  context_settings={"help_option_names": ["-h", "--help"]},
                  help="Rolling-contact machine design: thrust bearings, bevel gears and more.")

MAX_JOBS_PER_CORE = 4
#: Most Monte Carlo samples: 1e10 takes about half an hour on two cores.
MAX_SAMPLES = 10**10


class SolveFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


DebugOption = Annotated[bool, typer.Option("--debug", help="Show tracebacks of internal errors.")]
# Folders are refused by check_targets, in one line like every other unwritable target.
OutputOption = Annotated[Path | None, typer.Option(
    "--output", "-o", help="Write to this file instead of stdout (atomically: a failed run "
    "leaves an existing file as it was; never one of the specs the run reads).")]
PlotOption = Annotated[Path | None, typer.Option(
    "--plot", help="Draw a chart to this .png or .svg file.")]


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


def _sample_count(text: str | int) -> int:
    """``--samples`` as engineers write it: 100000, 1e5 or 100_000."""
    try:
        number = float(str(text).replace("_", ""))
    except ValueError:
        raise typer.BadParameter(f"{text!r} is not a number of samples, like 1e5") from None
    if not (number.is_integer() and 2 <= number <= MAX_SAMPLES):
        raise typer.BadParameter(f"{text!r}: give a whole number from 2 to {MAX_SAMPLES:.0e}")
    return int(number)


@app.command(cls=HelpListsKinds)
def solve(
    specs: Annotated[list[Path], typer.Argument(
        help="YAML spec files.", show_default=False, metavar="SPEC...")],
    output_format: Annotated[SolveFormat, typer.Option(
        "--format", "-f", help="table (engineering units), json (JSON Lines, SI) or csv (SI).")
    ] = SolveFormat.table,
    debug: DebugOption = False,
) -> None:
    """Solve each spec and report every result of its kind and the verdict on its limits."""
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


@app.command()
def check(
    paths: Annotated[list[str], typer.Argument(
        help="Spec files, folders (searched recursively for *.yaml and *.yml) or globs.",
        show_default=False, metavar="PATH...")],
    output_format: Annotated[CheckFormat, typer.Option(
        "--format", "-f", help="table, json (JSON Lines) or junit (JUnit XML).")
    ] = CheckFormat.table,
    output: OutputOption = None,
    jobs: Annotated[int | None, typer.Option(
        "--jobs", "-j", min=1, help="Worker processes (default: the number of cores).",
        show_default=False)] = None,
    show_all: Annotated[bool, typer.Option(
        "--all", help="Table: list passing specs too when there are many.")] = False,
    debug: DebugOption = False,
) -> None:
    """Check every spec: pass (within limits), fail (a limit violated) or invalid.

    Exit status: 0 all pass; 1 some fail and none invalid; 2 any invalid.
    """
    with errors_as_exit(debug):
        from bearingcalc import batch, reports

        workers = _workers(jobs)
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
        with StagedFiles() as files:
            emit(writers[output_format], report, files)
        raise typer.Exit(batch.exit_status(records))


@app.command()
def schema(
    kind: Annotated[str | None, typer.Option(
        "--kind", "-k", help="Only this kind's schema (see 'bearingcalc new --list').")] = None,
) -> None:
    """Print the JSON Schema (draft 2020-12) of the spec format, for editors and CI."""
    import json

    from bearingcalc.kinds import KINDS, unknown_kind
    from bearingcalc.schema import spec_schema

    if kind is not None and kind not in KINDS:
        print(f"error: --kind: {unknown_kind(kind)}", file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)
    text = json.dumps(spec_schema(kind), indent=2, ensure_ascii=False) + "\n"
    with errors_as_exit(debug=False):
        write_stdout(lambda stream: stream.write(text))


@app.command()
def new(
    kind: Annotated[str | None, typer.Argument(help="The kind of spec.", show_default=False)
                    ] = None,
    bearing_type: Annotated[str | None, typer.Option(
        "--type", help="A template of this type, where the kind has several.",
        show_default=False)] = None,
    list_kinds: Annotated[bool, typer.Option("--list", help="List the kinds.")] = False,
) -> None:
    """Print a commented template spec of KIND, ready for 'bearingcalc check'."""
    from bearingcalc.kinds import KINDS, unknown_kind
    from bearingcalc.templates import template_text

    if list_kinds or kind is None:
        text = "".join(f"{name:16} {entry.summary}\n" for name, entry in KINDS.items())
    elif kind not in KINDS:
        print(f"error: {unknown_kind(kind)}", file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)
    else:
        try:
            text = template_text(kind, bearing_type)
        except LookupError as error:
            print(f"error: --type: {error}", file=sys.stderr)
            raise typer.Exit(EXIT_INVALID) from None
    with errors_as_exit(debug=False):
        write_stdout(lambda stream: stream.write(text))
    if kind is None and not list_kinds:
        raise typer.Exit(EXIT_INVALID)


class StudyFormat(str, Enum):
    table = "table"
    json = "json"


@app.command()
def tolerance(
    spec_path: Annotated[Path, typer.Argument(
        help="A YAML spec with tolerances on some inputs ('20 deg ± 0.25 deg').",
        show_default=False, metavar="SPEC")],
    method: Annotated[str, typer.Option(
        "--method", "-m", help="Comma-separated: worst-case, rss, monte-carlo.")
    ] = "worst-case,rss,monte-carlo",
    samples: Annotated[int, typer.Option("--samples", "-n", parser=_sample_count,
                                         help="Monte Carlo samples (1e5, 100000).")] = 100_000,
    seed: Annotated[int, typer.Option("--seed", min=0, help="Seed of the sampler.")] = 0,
    sampler: Annotated[str, typer.Option("--sampler", help="sobol or random.")] = "sobol",
    sobol: Annotated[bool, typer.Option("--sobol", help="Add Sobol sensitivity indices.")
                     ] = False,
    result: Annotated[list[str] | None, typer.Option(
        "--result", "-r", help="Study this result (repeatable): it leads the table and plot, "
        "and Monte Carlo and Sobol cover only the chosen results.")] = None,
    output_format: Annotated[StudyFormat, typer.Option(
        "--format", "-f", help="table (engineering units) or json (SI).")] = StudyFormat.table,
    plot: PlotOption = None,
    output: OutputOption = None,
    jobs: Annotated[int | None, typer.Option(
        "--jobs", "-j", min=1, help="Threads for Monte Carlo (default: the number of cores).",
        show_default=False)] = None,
    debug: DebugOption = False,
) -> None:
    """Worst case, RSS and Monte Carlo of every result under the spec's tolerances.

    Exit status: 0 the margins stay within their limits (at worst case when it is
    run); 1 they can be exceeded; 2 the spec or the options are invalid.
    """
    with errors_as_exit(debug):
        from bearingcalc import batch, reports
        from bearingcalc.evaluation import evaluate_document, load_one_spec
        from bearingcalc.tolerance import StudyError, check_band_ends, run_study

        methods = [m.strip() for m in method.split(",") if m.strip()]
        check_plot_name(plot)
        if plot is not None and "monte-carlo" not in methods:
            raise SpecError("--plot draws the Monte Carlo histogram: add monte-carlo to "
                            "--method", source=str(plot))
        table_or_json = output_target(
            output, "report", ".json" if output_format is StudyFormat.json else ".txt")
        histogram = plot_target(plot)
        refuse_unwritable("tolerance", [batch.spec_file(spec_path)], table_or_json, histogram)
        kind, spec, document = load_one_spec(spec_path)
        evaluate_document(document)  # a nominal design that solve refuses is refused here too
        threads = _workers(jobs)
        try:
            check_band_ends(document, spec)
            report = with_progress(lambda tick: run_study(
                kind, spec, document.source, methods=methods, samples=samples, seed=seed,
                sampler=sampler, sobol=sobol, results=result or (), threads=threads,
                progress=tick), total=samples if "monte-carlo" in methods else None,
                label="Monte Carlo")
        except StudyError as error:
            raise SpecError(str(error), source=document.source) from None

        writers: dict[StudyFormat, Writer] = {
            StudyFormat.table: lambda stream: reports.print_tolerance_table(report, stream),
            StudyFormat.json: lambda stream: reports.write_tolerance_json(report, stream),
        }
        with StagedFiles() as files:
            if histogram is not None and report.governing:
                from bearingcalc.plots import tolerance_histogram

                stage_plot(files, histogram, lambda f, fmt: tolerance_histogram(
                    report, report.governing[0], f, fmt=fmt))
            emit(writers[output_format], table_or_json, files)
        raise typer.Exit(EXIT_LIMIT if report.within_limits is False else EXIT_OK)


class SweepFormat(str, Enum):
    table = "table"
    csv = "csv"
    json = "json"
    parquet = "parquet"


@app.command()
def sweep(
    spec_path: Annotated[Path, typer.Argument(
        help="A YAML spec; the varied inputs replace its values.", show_default=False,
        metavar="SPEC")],
    vary: Annotated[list[str], typer.Option(
        "--vary", "-v", help="NAME=START:STOP:N with units, e.g. contact_angle=5deg:40deg:36; "
        "once for a line, twice for a grid.", show_default=False)],
    result: Annotated[list[str] | None, typer.Option(
        "--result", "-r", help="Results for the table and plot (repeatable) "
        "(default: the kind's governing results).")] = None,
    output_format: Annotated[SweepFormat | None, typer.Option(
        "--format", "-f", help="table, csv, json (JSON Lines) or parquet (default: csv for "
        "--output *.csv, json for *.json or *.jsonl, parquet for *.parquet, else table).",
        show_default=False)
    ] = None,
    output: OutputOption = None,
    plot: PlotOption = None,
    debug: DebugOption = False,
) -> None:
    """Solve the spec over a line or grid of one or two inputs; impossible points are gaps."""
    with errors_as_exit(debug):
        from bearingcalc import batch, reports
        from bearingcalc import sweep as sweeps
        from bearingcalc.evaluation import load_one_spec

        check_plot_name(plot)
        chosen = output_format or _format_for(output)
        if chosen is SweepFormat.parquet:
            check_parquet_output(spec_path, output)
        # Without --format, the suggested file is CSV, which holds every result.
        suffix = _SWEEP_SUFFIXES.get(chosen, ".txt" if output_format else ".csv")
        results_file = output_target(output, "results", suffix)
        chart = plot_target(plot)
        refuse_unwritable("sweep", [batch.spec_file(spec_path)], results_file, chart)
        kind, spec, document = load_one_spec(spec_path)
        solved = sweeps.sweep_spec(kind, spec, document, vary)
        for note in solved.warnings:  # on stderr: the results may be a CSV or JSON stream
            print(f"warning: {note}", file=sys.stderr)
        keys = sweeps.shown_results(solved, result)

        writers: dict[SweepFormat, Writer] = {
            SweepFormat.table: lambda stream: reports.print_sweep_table(solved, keys, stream),
            SweepFormat.csv: lambda stream: reports.write_sweep_csv(solved, stream),
            SweepFormat.json: lambda stream: reports.write_sweep_json_lines(solved, stream),
            SweepFormat.parquet: lambda stream: reports.write_sweep_parquet(solved, stream),
        }
        with StagedFiles() as files:
            if chart is not None:
                from bearingcalc.plots import sweep_plot

                stage_plot(files, chart, lambda f, fmt: sweep_plot(solved, keys, f, fmt=fmt))
            # Parquet is refused without --output (check_parquet_output): never stdout.
            emit(writers[chosen], results_file, files, binary=chosen is SweepFormat.parquet)


def _workers(jobs: int | None) -> int:
    """The number of workers: ``--jobs``, or the cores; at most ``MAX_JOBS_PER_CORE`` per
    core, since more only fight over the same cores (and hundreds of processes can
    exhaust a shared machine)."""
    cores = os.cpu_count() or 1
    most = MAX_JOBS_PER_CORE * cores
    if jobs is not None and jobs > most:
        raise SpecError(f"--jobs {jobs} is more than {most} ({MAX_JOBS_PER_CORE} per core on "
                        f"this machine's {cores}); leave it out to use every core",
                        source="--jobs")
    return jobs or cores


def _format_for(output: Path | None) -> SweepFormat:
    suffix = output.suffix.lower() if output is not None else ""
    return {".csv": SweepFormat.csv, ".json": SweepFormat.json, ".jsonl": SweepFormat.json,
            ".parquet": SweepFormat.parquet}.get(suffix, SweepFormat.table)


_CHECK_SUFFIXES = {CheckFormat.table: ".txt", CheckFormat.json: ".jsonl",
                   CheckFormat.junit: ".xml"}
_SWEEP_SUFFIXES = {SweepFormat.csv: ".csv", SweepFormat.json: ".jsonl",
                   SweepFormat.parquet: ".parquet"}
