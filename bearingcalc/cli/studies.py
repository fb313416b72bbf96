"""The study commands, ``tolerance`` and ``sweep``: a spec varied over its tolerances or
over a line or grid of its inputs."""

from __future__ import annotations

import sys
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from bearingcalc.cli.app import (
    CatalogueOption,
    DebugOption,
    OutputOption,
    PlotOption,
    app,
    whole_number,
    worker_count,
)
from bearingcalc.cli_output import (
    EXIT_LIMIT,
    EXIT_OK,
    WordedHelp,
    Writer,
    check_parquet_output,
    check_plot_name,
    emit,
    errors_as_exit,
    output_target,
    plot_target,
    refuse_unwritable,
    stage_plot,
    with_progress,
)
from bearingcalc.errors import OptionError, SpecError
from bearingcalc.output import StagedFiles


def _sample_count(text: str | int) -> int:
    """``--samples`` as engineers write it: 100000, 1e5 or 100_000."""
    from bearingcalc.studies.sampling import MAX_SAMPLES

    try:
        number = float(str(text).replace("_", ""))
    except ValueError:
        raise typer.BadParameter(f"{text!r} is not a number of samples, like 1e5") from None
    if not (number.is_integer() and 2 <= number <= MAX_SAMPLES):
        raise typer.BadParameter(f"{text!r}: give a whole number from 2 to {MAX_SAMPLES:.0e}")
    return int(number)



class StudyFormat(str, Enum):
    table = "table"
    json = "json"


@app.command(cls=WordedHelp)
def tolerance(  # noqa: PLR0913  one typer option per flag of the command
    spec_path: Annotated[Path, typer.Argument(
        help="A YAML spec with tolerances on some inputs ('20 deg ± 0.25 deg').",
        show_default=False, metavar="SPEC")],
    method: Annotated[str, typer.Option(
        "--method", "-m", metavar="METHODS", help="Comma-separated: worst-case, rss, monte-carlo.")
    ] = "worst-case,rss,monte-carlo",
    samples: Annotated[int, typer.Option("--samples", "-n", parser=_sample_count, metavar="N",
                                         help="Monte Carlo samples, as 1e5 or 100000.")] = 100_000,
    seed: Annotated[int, typer.Option(
        "--seed", callback=whole_number(0), metavar="N",
        help="Seed of the sampler, 0 or more.")] = 0,
    sampler: Annotated[str, typer.Option(
        "--sampler", metavar="SAMPLER",
        help="How Monte Carlo draws: sobol (Sobol' points) or random.")] = "sobol",
    sobol: Annotated[bool, typer.Option(
        "--sobol", help="Add Sobol' sensitivity indices: which input drives each result's "
        "variance.")] = False,
    result: Annotated[list[str] | None, typer.Option(
        "--result", "-r", metavar="KEY",
        help="Study this result (repeatable): it leads the table and plot, "
        "and Monte Carlo and Sobol cover only the chosen results.")] = None,
    output_format: Annotated[StudyFormat, typer.Option(
        "--format", "-f", metavar="FORMAT", help="table (engineering units) or json (SI).")
    ] = StudyFormat.table,
    plot: PlotOption = None,
    output: OutputOption = None,
    jobs: Annotated[int | None, typer.Option(
        "--jobs", "-j", callback=whole_number(1), metavar="N",
        help="Threads for Monte Carlo, 1 or more (default: the number of cores).",
        show_default=False)] = None,
    catalogue: CatalogueOption = None,
    debug: DebugOption = False,
) -> None:
    """Study every result under the spec's tolerances: worst case, RSS and Monte Carlo.

    Exit status: 0 the margins stay within their limits (at worst case when it is
    run); 1 they can be exceeded, or the box holds impossible designs; 2 the spec or
    the options are invalid.
    """
    with errors_as_exit(debug):
        from bearingcalc import batch, reports
        from bearingcalc.evaluation import evaluate_document, load_one_spec
        from bearingcalc.studies import StudyError, check_band_ends, run_study

        methods = [m.strip() for m in method.split(",") if m.strip()]
        check_plot_name(plot)
        if plot is not None and "monte-carlo" not in methods:
            raise OptionError("--plot", "draws the Monte Carlo histogram: add monte-carlo to "
                              "--method", source=str(plot))
        table_or_json = output_target(
            output, "report", ".json" if output_format is StudyFormat.json else ".txt")
        histogram = plot_target(plot)
        refuse_unwritable("tolerance", [batch.spec_file(spec_path)], table_or_json, histogram)
        kind, spec, document = load_one_spec(spec_path)
        evaluate_document(document)  # a nominal design that solve refuses is refused here too
        threads = worker_count(jobs)
        try:
            check_band_ends(document, spec)
            report = with_progress(lambda tick: run_study(
                kind, spec, document.source, methods=methods, samples=samples, seed=seed,
                sampler=sampler, sobol=sobol, results=result or (), threads=threads,
                progress=tick), total=samples if "monte-carlo" in methods else None,
                label="Monte Carlo")
        except StudyError as error:
            if error.option is not None:
                raise OptionError(error.option, error.message, source=document.source) from None
            raise SpecError(str(error), source=document.source) from None

        writers: dict[StudyFormat, Writer] = {
            StudyFormat.table: lambda stream: reports.print_tolerance_table(report, stream),
            StudyFormat.json: lambda stream: reports.write_tolerance_json(report, stream),
        }
        with StagedFiles("tolerance") as files:
            plotted = result[0] if result else report.plotted
            if histogram is not None and plotted is not None:
                from bearingcalc.plots import tolerance_histogram

                stage_plot(files, histogram, lambda f, fmt: tolerance_histogram(
                    report, plotted, f, fmt=fmt))
            emit(writers[output_format], table_or_json, files)
        raise typer.Exit(EXIT_LIMIT if report.within_limits is False else EXIT_OK)


class SweepFormat(str, Enum):
    table = "table"
    csv = "csv"
    json = "json"
    parquet = "parquet"


@app.command(cls=WordedHelp)
def sweep(
    spec_path: Annotated[Path, typer.Argument(
        help="A YAML spec; the varied inputs replace its values.", show_default=False,
        metavar="SPEC")],
    vary: Annotated[list[str], typer.Option(
        "--vary", "-v", metavar="NAME=START:STOP:N",
        help="NAME=START:STOP:N with units, e.g. contact_angle=5deg:40deg:36; "
        "once for a line, twice for a grid.", show_default=False)],
    result: Annotated[list[str] | None, typer.Option(
        "--result", "-r", metavar="KEY", help="Results for the table and plot (repeatable) "
        "(default: the kind's governing results and any other limit the sweep crosses).")
    ] = None,
    output_format: Annotated[SweepFormat | None, typer.Option(
        "--format", "-f", metavar="FORMAT",
        help="table, csv, json (JSON Lines) or parquet (default: csv for "
        "--output *.csv, json for *.json or *.jsonl, parquet for *.parquet, else table).",
        show_default=False)
    ] = None,
    output: OutputOption = None,
    plot: PlotOption = None,
    catalogue: CatalogueOption = None,
    debug: DebugOption = False,
) -> None:
    """Solve the spec over a line or grid of one or two inputs; impossible points are gaps.

    The spec's own checks must hold at the range's corners; a point the solver finds
    impossible (no equilibrium, θ >= 45°) is a gap, its reason given.

    Exit status: 0 the sweep is written; 2 a bad spec, --vary or --result, or an output
    that cannot be written.
    """
    with errors_as_exit(debug):
        from bearingcalc import batch, reports, sweeps
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
        keys = sweeps.shown_results(solved, result)

        writers: dict[SweepFormat, Writer] = {
            SweepFormat.table: lambda stream: reports.print_sweep_table(solved, keys, stream),
            SweepFormat.csv: lambda stream: reports.write_sweep_csv(solved, stream),
            SweepFormat.json: lambda stream: reports.write_sweep_json_lines(solved, stream),
            SweepFormat.parquet: lambda stream: reports.write_sweep_parquet(solved, stream),
        }
        with StagedFiles("sweep") as files:
            if chart is not None:
                from bearingcalc.plots import sweep_plot

                stage_plot(files, chart, lambda f, fmt: sweep_plot(solved, keys, f, fmt=fmt,
                                                                   chosen=bool(result)))
            # Parquet is refused without --output (check_parquet_output): never stdout.
            emit(writers[chosen], results_file, files, binary=chosen is SweepFormat.parquet)
        # On stderr, the results may be a CSV or JSON stream; once they are written, so
        # that a refused output is the run's one line.
        for note in solved.warnings:
            print(f"warning: {note}", file=sys.stderr)
        for cited in solved.sources:
            print(cited, file=sys.stderr)



def _format_for(output: Path | None) -> SweepFormat:
    suffix = output.suffix.lower() if output is not None else ""
    return {".csv": SweepFormat.csv, ".json": SweepFormat.json, ".jsonl": SweepFormat.json,
            ".parquet": SweepFormat.parquet}.get(suffix, SweepFormat.table)



_SWEEP_SUFFIXES = {SweepFormat.csv: ".csv", SweepFormat.json: ".jsonl",
                   SweepFormat.parquet: ".parquet"}
