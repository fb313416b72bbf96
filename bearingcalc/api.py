"""bearingcalc from Python: the commands' own code path, returning objects.

``solve`` takes a spec file's path, a spec's YAML text or a mapping, and returns one
:class:`Result` per document; ``tolerance`` and ``sweep`` return what their commands
print, as objects. Bad input raises :class:`~bearingcalc.errors.SpecError`, whose text
is the lines the command line prints (``.problems`` gives them as data); an argument of
the wrong type or value raises its subclass :class:`~bearingcalc.errors.ArgumentError`
(a ValueError too), which names the argument. Units are SI throughout, as in JSON.
"""

from __future__ import annotations

import io
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from html import escape
from typing import Any

from bearingcalc import api_arguments as arguments
from bearingcalc.errors import ArgumentError, Problem, SpecError
from bearingcalc.evaluation import Evaluation, evaluate_document, evaluate_documents, parse_document
from bearingcalc.models.yaml_loader import Document

SpecInput = str | os.PathLike[str] | Mapping[str, Any]
__all__ = ["ArgumentError", "Problem", "Result", "SpecError", "Study", "Sweep", "solve",
           "sweep", "tolerance"]


@dataclass(frozen=True)
class Result:
    """One solved spec: SI results, their units, the verdicts and the warnings, as
    ``bearingcalc solve --format json`` gives them."""

    evaluation: Evaluation

    @property
    def kind(self) -> str:
        return self.evaluation.kind

    @property
    def name(self) -> str:
        return self.evaluation.name

    @property
    def results(self) -> dict[str, float | None]:
        return self.evaluation.results

    @property
    def units(self) -> dict[str, str]:
        return self.evaluation.units

    @property
    def within_limits(self) -> bool:
        return self.evaluation.within_limits

    @property
    def verdicts(self) -> list[Any]:
        return self.evaluation.verdicts

    @property
    def warnings(self) -> list[str]:
        return self.evaluation.warnings

    @property
    def catalogue_sources(self) -> dict[str, str]:
        return self.evaluation.sources

    def quantity(self, key: str) -> Any:
        """The result ``key`` as a pint quantity in its SI unit (an unbounded result is
        infinite)."""
        if not isinstance(key, str) or key not in self.results:
            raise arguments.unknown_result("Result.quantity", "key", key, self.kind, self.results)
        value = self.results[key]
        unit = self.units[key]
        return _registry().Quantity(float("inf") if value is None else value,
                                    _PINT_NAMES.get(unit, unit))

    def to_frame(self) -> Any:
        """The results as a pandas DataFrame (key, value in SI, unit, meaning); pandas is
        an optional extra (``pip install pandas``)."""
        meanings = self.evaluation.meanings
        return _pandas().DataFrame(
            [(key, value, self.units[key], meanings[key])
             for key, value in self.results.items()],
            columns=["result", "value", "unit", "meaning"]).set_index("result")

    def _repr_html_(self) -> str:
        from bearingcalc.units import to_display

        rows = []
        for key, value in self.results.items():
            shown, unit = ("unbounded", "") if value is None else to_display(
                value, self.units[key])
            number = shown if isinstance(shown, str) else f"{shown:.7g}"
            rows.append(f"<tr><td>{escape(key)}</td><td style='text-align:right'>{number}"
                        f"</td><td>{escape(unit)}</td><td>{escape(self.evaluation.meanings[key])}"
                        "</td></tr>")
        verdict = "PASS" if self.within_limits else "FAIL"
        return (f"<p><b>{escape(self.name)}</b> ({escape(self.kind)}): {verdict}</p>"
                "<table><tr><th>result</th><th>value</th><th>unit</th><th>meaning</th>"
                f"</tr>{''.join(rows)}</table>")

    def __repr__(self) -> str:
        verdict = "within limits" if self.within_limits else "outside limits"
        return f"<Result {self.name!r} ({self.kind}): {len(self.results)} results, {verdict}>"


def _pandas() -> Any:
    try:
        import pandas as pd
    except ImportError:
        raise ImportError("to_frame needs pandas: pip install pandas") from None
    return pd


#: The SI units results name that pint spells otherwise.
_PINT_NAMES = {"1": "dimensionless", "N·m": "N*m", "m²/s": "m**2/s", "kg/m³": "kg/m**3",
               "rad/s²": "rad/s**2", "m/s²": "m/s**2"}


def _registry() -> Any:
    from bearingcalc.units import unit_registry

    return unit_registry()


def solve(spec: SpecInput) -> list[Result]:
    """Every document of ``spec`` solved: a path, a YAML text or a mapping.

    >>> (result,) = solve("kind: thrust-bearing\\nball_diameter: 12.7 mm\\n"
    ...                   "contact_angle: 30 deg\\nshaft_speed: 1500 rpm\\n")
    >>> round(result.results["pitch_radius"] * 1e3, 3)  # mm
    26.023
    >>> result.units["pitch_radius"]
    'm'
    """
    outcomes = evaluate_documents(arguments.spec_documents(spec, "solve"))
    errors = [outcome for outcome in outcomes if isinstance(outcome, SpecError)]
    if errors:  # every document's problems, in the file's order
        errors[0].more = [*errors[0].more, *errors[1:]]
        raise errors[0]
    return [Result(outcome) for outcome in outcomes]  # type: ignore[arg-type]


@dataclass(frozen=True)
class Study:
    """A tolerance study: the record ``bearingcalc tolerance --format json`` prints."""

    report: Any

    @property
    def record(self) -> dict[str, Any]:
        return self.report.record

    @property
    def within_limits(self) -> bool | None:
        return self.report.within_limits

    def to_frame(self) -> Any:
        """Each result's nominal value and what each method found, a row per result, in
        SI (pandas, an optional extra)."""
        columns = {"nominal": ("nominal",), "worst_case_min": ("worst_case", "min"),
                   "worst_case_max": ("worst_case", "max"), "rss_mean": ("rss", "mean"),
                   "rss_std": ("rss", "std"), "monte_carlo_mean": ("monte_carlo", "mean"),
                   "monte_carlo_std": ("monte_carlo", "std"),
                   "p00135": ("monte_carlo", "p00135"), "p99865": ("monte_carlo", "p99865")}

        def cell(entry: dict[str, Any], path: tuple[str, ...]) -> Any:
            found: Any = entry
            for step in path:
                found = found.get(step) if isinstance(found, dict) else None
            return found

        results = self.record["results"]
        frame = _pandas().DataFrame(
            [[key, self.record["units"][key], *(cell(entry, path) for path in columns.values())]
             for key, entry in results.items()], columns=["result", "unit", *columns])
        return frame.set_index("result").dropna(axis="columns", how="all")

    def __repr__(self) -> str:
        record = self.record
        methods = [name for name, key in (("worst case", "worst_case"), ("RSS", "rss"))
                   if any(key in entry for entry in record["results"].values())]
        if "samples" in record:
            methods.append(f"Monte Carlo {record['samples']:g}")
        verdict = {True: "within limits", False: "limits exceeded", None: "no limits"}[
            self.within_limits]
        return (f"<Study {record['name'] or record['spec']!r} ({record['kind']}): "
                f"{len(record['results'])} results by {', '.join(methods)}, {verdict}>")

    def plot(self, path: str | os.PathLike[str] | None = None, key: str | None = None
             ) -> Any:
        """The Monte Carlo histogram of ``key`` (default: the margin nearest its limit), written
        to ``path`` (.png or .svg), or returned as SVG for a notebook."""
        from bearingcalc.plots import tolerance_histogram

        sampled = self.report.histograms
        if not sampled:
            raise ArgumentError("Study.plot", "key", "the study ran no Monte Carlo, whose "
                                "samples a histogram shows: add 'monte-carlo' to methods")
        if key is not None and (not isinstance(key, str) or key not in sampled):
            raise arguments.unknown_result("Study.plot", "key", key, self.record["kind"], sampled)
        chosen = key or self.report.plotted
        return _drawn(lambda target, fmt: tolerance_histogram(self.report, chosen, target,
                                                              fmt=fmt), path, "Study.plot")


def tolerance(spec: SpecInput, *, methods: str | Sequence[str] = ("worst-case", "rss",
                                                                    "monte-carlo"),
              samples: int = 100_000, seed: int = 0, sampler: str = "sobol",
              results: str | Sequence[str] = ()) -> Study:
    """``bearingcalc tolerance`` of the one spec in ``spec``: ``methods`` (a list, or
    names separated by commas) of worst-case, rss and monte-carlo; Monte Carlo's
    ``samples`` (2 to 1e10; 2^30 with the sobol sampler), ``seed`` (0 or more) and
    ``sampler`` (sobol or random); ``results`` narrows Monte Carlo to those results."""
    from bearingcalc.studies import METHODS, StudyError, check_band_ends, run_study
    from bearingcalc.studies.sampling import MAX_SAMPLES, SAMPLERS, SOBOL_MAX_SAMPLES

    chosen = arguments.names(methods, "tolerance", "methods", "methods",
                             "['worst-case', 'rss']")
    if not chosen:
        raise ArgumentError("tolerance", "methods", f"names no method; give one or more of "
                            f"{', '.join(METHODS)}")
    for method in chosen:
        arguments.choice(method, "tolerance", "methods", METHODS)
    sampler = arguments.choice(sampler, "tolerance", "sampler", SAMPLERS)
    sobol = sampler == "sobol" and "monte-carlo" in chosen
    samples = arguments.whole_number(
        samples, "tolerance", "samples", 2, SOBOL_MAX_SAMPLES if sobol else MAX_SAMPLES,
        "100_000", " (the distinct Sobol' points of 30 bits; sampler='random' takes more)"
        if sobol else "")
    seed = arguments.whole_number(seed, "tolerance", "seed", 0)
    asked = arguments.names(results, "tolerance", "results", "result keys",
                            "['slip_margin']")
    document = _one(spec, "tolerance")
    kind, parsed = parse_document(document)
    nominal = evaluate_document(document)
    for key in asked:
        if key not in nominal.results:
            raise arguments.unknown_result("tolerance", "results", key, kind.name, nominal.results)
    check_band_ends(document, parsed)
    try:
        return Study(run_study(kind, parsed, document.source, methods=chosen,
                               samples=samples, seed=seed, sampler=sampler,
                               results=asked, threads=os.cpu_count() or 1))
    except StudyError as error:
        raise SpecError(str(error), source=document.source) from None


@dataclass(frozen=True)
class Sweep:
    """A sweep: the points ``bearingcalc sweep`` prints (``.inputs``, ``.results`` in
    SI, NaN where a design is impossible, ``.status``)."""

    solved: Any

    @property
    def inputs(self) -> dict[str, Any]:
        return self.solved.inputs

    @property
    def results(self) -> dict[str, Any]:
        return self.solved.results

    @property
    def status(self) -> Any:
        return self.solved.status

    def to_frame(self) -> Any:
        """A row per point: the varied inputs, then every result, as the CSV's columns
        (SI, NaN where a design is impossible), and the reason a point is impossible
        (pandas, an optional extra)."""
        from bearingcalc.reports.sweep_csv import sweep_columns

        frame = _pandas().DataFrame(dict(sweep_columns(self.solved)))
        frame["reason"] = [self.solved.reason(int(code)) if code else ""
                           for code in self.solved.status]
        return frame

    def __repr__(self) -> str:
        solved = self.solved
        axes = (" × ".join(str(axis.values.size) for axis in solved.axes) + " points of "
                + " × ".join(axis.name for axis in solved.axes))
        impossible = int((solved.status != 0).sum())
        return (f"<Sweep {solved.name!r} ({solved.kind.name}): {axes}, "
                f"{len(solved.results)} results, {impossible} impossible>")

    def plot(self, path: str | os.PathLike[str] | None = None,
             results: str | Sequence[str] = ()) -> Any:
        """The results against the swept input (contours over a grid), written to
        ``path`` (.png or .svg), or returned as SVG for a notebook."""
        from bearingcalc.plots import sweep_plot
        from bearingcalc.sweeps import shown_results

        asked = arguments.names(results, "Sweep.plot", "results", "result keys",
                                "['slip_margin']")
        for key in asked:
            if key not in self.results:
                raise arguments.unknown_result("Sweep.plot", "results", key, self.solved.kind.name,
                                      self.results)
        keys = shown_results(self.solved, asked or None)
        return _drawn(lambda target, fmt: sweep_plot(self.solved, keys, target, fmt=fmt,
                                                     chosen=bool(asked)), path, "Sweep.plot")


def sweep(spec: SpecInput, vary: Mapping[str, str]) -> Sweep:
    """``bearingcalc sweep`` of the one spec in ``spec``: ``vary`` maps a field to its
    ``START:STOP:N`` (``{"contact_angle": "5deg:40deg:36"}``); one for a line, two for a
    grid."""
    from bearingcalc.sweeps import SweepError, sweep_axes

    example = '{"contact_angle": "5deg:40deg:36"}'
    if not isinstance(vary, Mapping):
        written = vary.partition("=") if isinstance(vary, str) else None
        like = (f'{{"{written[0].strip()}": "{written[2].strip()}"}}'
                if written is not None and written[1] else example)
        raise ArgumentError("sweep", "vary", f"a mapping of a field to its START:STOP:N, like "
                            f"{like}, got {arguments.describe(vary)}")
    if not 1 <= len(vary) <= 2:
        raise ArgumentError("sweep", "vary", f"one field for a line or two for a grid, like "
                            f"{example}, got {len(vary)}")
    for name, span in vary.items():
        if not isinstance(name, str) or not isinstance(span, str):
            raise ArgumentError("sweep", "vary", f"each field's name and its START:STOP:N are "
                                f"texts, like {example}, got {name!r}: {span!r}")
        if span.count(":") != 2:
            raise ArgumentError("sweep", "vary", f"{name}: {span!r}: write START:STOP:N, like "
                                "'5deg:40deg:36'")
    document = _one(spec, "sweep")
    kind, parsed = parse_document(document)
    try:
        return Sweep(sweep_axes(kind, parsed, document,
                                [f"{name}={span}" for name, span in vary.items()]))
    except SweepError as error:  # worded for --vary: the argument here is vary
        raise ArgumentError("sweep", "vary", str(error).removeprefix("--vary").lstrip(": ")
                            ) from None


def _one(spec: SpecInput, function: str) -> Document:
    documents = arguments.spec_documents(spec, function)
    if len(documents) > 1:
        raise SpecError(f"{len(documents)} specs: a study takes one", source=documents[0].source)
    return documents[0]


class _Svg:
    """A drawing a notebook shows."""

    def __init__(self, text: str) -> None:
        self.text = text

    def _repr_svg_(self) -> str:
        return self.text


def _drawn(draw: Any, path: str | os.PathLike[str] | None, function: str) -> Any:
    if path is not None:
        target = arguments.chart_path(path, function)
        with target.open("wb") as stream:
            draw(stream, target.suffix[1:].lower())
        return target
    buffer = io.BytesIO()
    draw(buffer, "svg")
    return _Svg(buffer.getvalue().decode("utf-8"))
