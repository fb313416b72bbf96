"""The ``bearingcalc`` command line: parses options, calls the library, prints.

Exit status: 0 every spec within its limits; 1 some spec violates a limit;
2 some spec could not be read or is invalid (2 wins over 1).
"""

from __future__ import annotations

import os
import sys
import traceback
from collections.abc import Callable
from enum import Enum
from pathlib import Path
from typing import Annotated, BinaryIO, TextIO, TypeVar

# pydantic scans installed packages for plugins on its first model; bearingcalc uses
# none, and the scan costs about 20 ms of every command's start.
os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")

import typer

from bearingcalc.errors import SpecError
from bearingcalc.wording import printable

T = TypeVar("T")

app = typer.Typer(add_completion=False, pretty_exceptions_enable=False, no_args_is_help=True,
                  context_settings={"help_option_names": ["-h", "--help"]},
                  help="Rolling-contact machine design: thrust bearings, bevel gears and more.")

EXIT_OK, EXIT_LIMIT, EXIT_INVALID = 0, 1, 2
#: A closed output pipe whose run's status is unknown: the shell's 128 + SIGPIPE.
EXIT_BROKEN_PIPE = 141
MAX_JOBS_PER_CORE = 4
#: Most Monte Carlo samples: 1e10 takes about half an hour on two cores.
MAX_SAMPLES = 10**10


class SolveFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


DebugOption = Annotated[bool, typer.Option("--debug", help="Show tracebacks of internal errors.")]
OutputOption = Annotated[Path | None, typer.Option(
    "--output", "-o", help="Write to this file instead of stdout (atomically: a failed run "
    "leaves an existing file as it was).", dir_okay=False)]
PlotOption = Annotated[Path | None, typer.Option(
    "--plot", help="Draw a chart to this .png or .svg file.", dir_okay=False)]


def _print_version(value: bool) -> None:
    if value:
        from bearingcalc import __version__

        print(f"bearingcalc {__version__}")
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

        def write(stream: TextIO) -> None:
            if output_format is SolveFormat.json:
                reports.write_json_lines(evaluations, stream)
            elif output_format is SolveFormat.csv:
                if evaluations:
                    reports.write_csv(evaluations, stream)
            else:
                reports.print_tables(evaluations, KINDS, stream)

        _emit(write, None)
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
    with _errors_as_exit(debug):
        from bearingcalc import batch, reports

        workers = _workers(jobs)
        records = _with_progress(lambda tick: batch.check_paths(paths, workers, tick))

        def write(stream: TextIO) -> None:
            if output_format is CheckFormat.json:
                reports.write_check_json_lines(records, stream)
            elif output_format is CheckFormat.junit:
                reports.write_junit(records, stream)
            else:
                reports.print_check_table(records, show_all=show_all, stream=stream)

        _emit(write, output)
        raise typer.Exit(batch.exit_status(records))


@app.command()
def schema(
    kind: Annotated[str | None, typer.Option(
        "--kind", "-k", help="Only this kind's schema (see 'bearingcalc new --list').")] = None,
) -> None:
    """Print the JSON Schema (draft 2020-12) of the spec format, for editors and CI."""
    import json

    from bearingcalc.kinds import KINDS
    from bearingcalc.schema import spec_schema

    if kind is not None and kind not in KINDS:
        print(f"error: --kind: unknown kind {kind!r}; known kinds: {', '.join(KINDS)}",
              file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)
    print(json.dumps(spec_schema(kind), indent=2, ensure_ascii=False))


@app.command()
def new(
    kind: Annotated[str | None, typer.Argument(help="The kind of spec.", show_default=False)
                    ] = None,
    list_kinds: Annotated[bool, typer.Option("--list", help="List the kinds.")] = False,
) -> None:
    """Print a commented template spec of KIND, ready for 'bearingcalc check'."""
    from importlib import resources

    from bearingcalc.kinds import KINDS

    if list_kinds or kind is None:
        for name, entry in KINDS.items():
            print(f"{name:16} {entry.summary}")
        if kind is None and not list_kinds:
            raise typer.Exit(EXIT_INVALID)
        return
    if kind not in KINDS:
        print(f"error: unknown kind {kind!r}; known kinds: {', '.join(KINDS)}", file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)
    print(resources.files("bearingcalc.templates").joinpath(f"{kind}.yaml").read_text("utf-8"),
          end="")


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
    with _errors_as_exit(debug):
        from bearingcalc import reports
        from bearingcalc.evaluation import evaluate_document, load_one_spec
        from bearingcalc.tolerance import StudyError, run_study

        methods = [m.strip() for m in method.split(",") if m.strip()]
        _check_plot_name(plot)
        if plot is not None and "monte-carlo" not in methods:
            raise SpecError("--plot draws the Monte Carlo histogram: add monte-carlo to "
                            "--method", source=str(plot))
        kind, spec, document = load_one_spec(spec_path)
        evaluate_document(document)  # a nominal design that solve refuses is refused here too
        threads = _workers(jobs)
        try:
            report = _with_progress(lambda tick: run_study(
                kind, spec, document.source, methods=methods, samples=samples, seed=seed,
                sampler=sampler, sobol=sobol, results=result or (), threads=threads,
                progress=tick), total=samples if "monte-carlo" in methods else None,
                label="Monte Carlo")
        except StudyError as error:
            raise SpecError(str(error), source=document.source) from None

        def write(stream: TextIO) -> None:
            if output_format is StudyFormat.json:
                import json

                stream.write(json.dumps(report.record, allow_nan=False,
                                        ensure_ascii=False) + "\n")
            else:
                reports.print_tolerance_table(report, stream)

        if plot is not None and report.governing:
            from bearingcalc.plots import tolerance_histogram

            _save_plot(plot, lambda f, fmt: tolerance_histogram(report, report.governing[0], f,
                                                                fmt=fmt))
        _emit(write, output)
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
    with _errors_as_exit(debug):
        from bearingcalc import reports
        from bearingcalc import sweep as sweeps
        from bearingcalc.evaluation import load_one_spec

        _check_plot_name(plot)
        kind, spec, document = load_one_spec(spec_path)
        try:
            axes = [sweeps.parse_axis(text, spec) for text in vary]
            sweeps.check_axes(document, axes)
            solved = sweeps.run_sweep(kind, spec, document.source, axes)
        except sweeps.SweepError as error:
            raise SpecError(str(error), source=document.source) from None
        keys = result or [k for k in kind.governing if k in solved.results]
        unknown = [k for k in keys if k not in solved.results]
        if unknown:
            raise SpecError(f"--result {unknown[0]!r} is not a result of this {kind.name} spec;"
                            f" choose from {', '.join(solved.results)}", source=document.source)
        chosen = output_format or _format_for(output)

        def write(stream: TextIO) -> None:
            if chosen is SweepFormat.csv:
                reports.write_sweep_csv(solved, stream)
            elif chosen is SweepFormat.json:
                reports.write_sweep_json_lines(solved, stream)
            else:
                reports.print_sweep_table(solved, keys, stream)

        if plot is not None:
            from bearingcalc.plots import sweep_plot

            _save_plot(plot, lambda f, fmt: sweep_plot(solved, keys, f, fmt=fmt))
        if chosen is SweepFormat.parquet:
            _write_parquet(solved, output, document.source)
            return
        _emit(write, output)


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


def _write_parquet(solved: object, output: Path | None, source: str) -> None:
    """The sweep as a Parquet file, atomically; pyarrow is the optional extra."""
    if output is None:
        raise SpecError("--format parquet writes a file: give --output grid.parquet",
                        source=source)
    try:
        import pyarrow  # noqa: F401
    except ImportError:
        raise SpecError("Parquet output needs pyarrow, the optional extra: pip install "
                        "'bearingcalc[parquet]'", source=str(output)) from None
    from bearingcalc import reports
    from bearingcalc.output import atomic_write

    try:
        atomic_write(output, lambda stream: reports.write_sweep_parquet(solved, stream),  # type: ignore[arg-type]
                     binary=True)
    except OSError as exc:
        raise SpecError(f"cannot write the report: {exc.strerror or exc}",
                        source=str(output)) from None


def _with_progress(work: Callable[[Callable[[int], None] | None], T], total: int | None = None,
                   label: str = "checking") -> T:
    """Run ``work`` with a progress callback drawing a bar on stderr, when it is a terminal.

    The bar is transient and shows after a second, so quick runs print nothing extra.
    """
    if not sys.stderr.isatty():
        return work(None)
    import time

    from rich.console import Console
    from rich.progress import Progress

    started = time.monotonic()
    with Progress(console=Console(stderr=True), transient=True, auto_refresh=False) as bar:
        task = bar.add_task(label, total=total)

        def tick(count: int) -> None:
            bar.advance(task, count)
            if time.monotonic() - started > 1.0:
                bar.refresh()

        return work(tick)


def _check_plot_name(plot: Path | None) -> None:
    if plot is not None and plot.suffix.lower() not in (".png", ".svg"):
        raise SpecError("--plot: give a .png or .svg file name", source=str(plot))


def _save_plot(plot: Path, draw: Callable[[BinaryIO, str], None]) -> None:
    """Draw a picture into ``plot`` atomically, in the format its suffix names."""
    from bearingcalc.output import atomic_write

    try:
        atomic_write(plot, lambda stream: draw(stream, plot.suffix[1:].lower()), binary=True)
    except OSError as exc:
        raise SpecError(f"cannot write the plot: {exc.strerror or exc}",
                        source=str(plot)) from None


def _emit(write: Callable[[TextIO], None], output: Path | None) -> None:
    """Write a report to ``output`` atomically, or to stdout."""
    if output is None:
        try:
            write(sys.stdout)
            sys.stdout.flush()
        except BrokenPipeError:
            # The reader left (| head): stop writing, but keep the run's exit status,
            # which says whether the specs passed.
            _silence_stdout()
        return
    from bearingcalc.output import atomic_write

    try:
        atomic_write(output, write)
    except OSError as exc:
        raise SpecError(f"cannot write the report: {exc.strerror or exc}",
                        source=str(output)) from None


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so the flush at exit does not fail a second time."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    os.close(devnull)


def _print_error(error: Exception) -> None:
    lines = error.lines() if isinstance(error, SpecError) else [f"error: {error}"]
    # Control characters from a spec are shown as escapes, never sent to the terminal.
    print("\n".join(printable(line) for line in lines), file=sys.stderr)


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
            _silence_stdout()
            raise typer.Exit(EXIT_BROKEN_PIPE)
        if self.debug:
            traceback.print_exception(exc)
        if isinstance(exc, SpecError):
            _print_error(exc)
        else:
            print(f"internal error: {type(exc).__name__}: {exc} "
                  "(run again with --debug for the traceback, and please report it)",
                  file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)
