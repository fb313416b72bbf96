"""The report of ``tolerance``: worst case, RSS and Monte Carlo side by side in a table
(engineering units), or the study's record as JSON (SI)."""

from __future__ import annotations

import json
import math
import re
from typing import IO, TYPE_CHECKING, Any

from bearingcalc.reports.formatting import console, format_number, print_whole, safe_text
from bearingcalc.units import DIMENSIONS, TEMPERATURE_UNITS, UnitError, unit_scale
from bearingcalc.units import to_display as si_display
from bearingcalc.verdicts import Verdict, verdict_line

if TYPE_CHECKING:  # the report type only; its module loads with the command
    from bearingcalc.studies import StudyReport


def write_tolerance_json(report: StudyReport, stream: IO[str]) -> None:
    """The study's record as one line of JSON; non-finite numbers are refused."""
    stream.write(json.dumps(report.record, allow_nan=False, ensure_ascii=False) + "\n")


def print_tolerance_table(report: StudyReport, stream: IO[str] | None = None) -> None:
    """Worst case, RSS and Monte Carlo side by side (engineering units), the contribution
    table of the governing result, the yield and verdict, and a terminal histogram."""
    record = report.record
    out = console(stream)
    print_whole(out, f"[bold]{safe_text(record['name'] or record['spec'])}[/] "
                     f"({record['kind']}, {safe_text(record['spec'])})")
    for key, value in report.catalogue_sources.items():
        out.print(f"{key}: {safe_text(value)}")
    _print_inputs(out, report)
    _print_side_by_side(out, report)
    _print_other_results(out, report)
    lead = report.governing[0] if report.governing else None
    if lead:
        _print_contributions(out, report, lead)
    _print_sobol_indices(out, record, report.governing)
    _print_yield_and_verdict(out, report)
    if lead and lead in report.histograms:
        _terminal_histogram(out, lead, report, record["units"][lead])


def _print_inputs(out: Any, report: StudyReport) -> None:
    """The toleranced inputs: nominal, band and σ in the unit the spec wrote them in."""
    from rich.table import Table

    record = report.record
    units = record["units"]
    inputs = Table(title="toleranced inputs", title_justify="left")
    for column in ("input", "nominal", "low", "high", "unit", "distribution", "σ"):
        # the name folds in a narrow terminal; numbers and units are read whole
        inputs.add_column(column, no_wrap=column != "input", overflow="fold",
                          justify="left" if column in ("input", "unit", "distribution")
                          else "right")
    for name, entry in record["inputs"].items():
        shown = _as_written(entry, units[name]) or [
            _as_solve_shows(report, entry[k], units[name])
            for k in ("nominal", "low", "high", "std")]
        inputs.add_row(name, *(format_number(v) for v, _ in shown[:3]), shown[0][1],
                       entry["distribution"], format_number(shown[3][0]))
    out.print(inputs)


def _print_side_by_side(out: Any, report: StudyReport) -> None:
    """The studied results: nominal, worst case, RSS and Monte Carlo in one row each."""
    from rich import box
    from rich.markup import escape
    from rich.table import Table

    units = report.record["units"]
    table = Table(title="results: worst case, RSS and Monte Carlo side by side",
                  title_justify="left", box=box.SIMPLE_HEAD, pad_edge=False)
    for column in ("result", "nominal", "worst case\nmin\nmax", "RSS\nmean\nσ",
                   "Monte\nCarlo\nmean\nσ", "MC\nquantile\n0.135 %\n99.865 %"):
        table.add_column(column, justify="left" if column == "result" else "right",
                         no_wrap=True)
    results = report.record["results"]
    for key in report.governing:
        entry = results[key]
        unit = _as_solve_shows(report, 0.0, units[key], key)[1]

        def cell(*values: float | None, key: str = key) -> str:
            if any(v is None for v in values):
                return ""
            # Four digits keep six columns in 80; the JSON carries every digit.
            return "\n".join(f"{_as_solve_shows(report, v, units[key], key)[0]:.4g}"
                             for v in values)

        wc, rss, mc = (entry.get(m) or {} for m in ("worst_case", "rss", "monte_carlo"))
        table.add_row(escape(f"{key}\n[{unit}]") if unit else key, cell(entry["nominal"]),
                      cell(wc.get("min"), wc.get("max")), cell(rss.get("mean"), rss.get("std")),
                      cell(mc.get("mean"), mc.get("std")),
                      cell(mc.get("p00135"), mc.get("p99865")))
    out.print(table)


def _print_other_results(out: Any, report: StudyReport) -> None:
    """The results not studied, at worst case only (the JSON has every method)."""
    from rich.table import Table

    units = report.record["units"]
    results = report.record["results"]
    others = [key for key in results if key not in report.governing]
    if not (others and _ran(results, "worst_case")):
        return
    rest = Table(title="other results at worst case (all methods: --format json)",
                 title_justify="left")
    for column in ("result", "unit", "nominal", "min", "max"):
        rest.add_column(column, justify="left" if column in ("result", "unit") else "right",
                        no_wrap=True)
    for key in others:
        wc = results[key].get("worst_case") or {}
        shown = [_as_solve_shows(report, v, units[key], key) if v is not None else (None, "")
                 for v in (results[key]["nominal"], wc.get("min"), wc.get("max"))]
        rest.add_row(key, _as_solve_shows(report, 0.0, units[key], key)[1],
                     *("" if v is None else format_number(v) for v, _ in shown))
    out.print(rest)


def _print_contributions(out: Any, report: StudyReport, lead: str) -> None:
    """Which tolerance dominates the governing result: each input's share of its RSS
    variance and its effect ∂f/∂x · σ, largest first."""
    from rich.markup import escape
    from rich.table import Table

    record = report.record
    units = record["units"]
    rss_lead = (record["results"].get(lead) or {}).get("rss")
    if not (rss_lead and rss_lead.get("contributions")):
        return
    shares = Table(title=f"which tolerance dominates {lead} (RSS)", title_justify="left")
    unit = _as_solve_shows(report, 0.0, units[lead], lead)[1]
    for column in ("input", "share", f"∂f/∂x · σ [{unit}]" if unit else "∂f/∂x · σ"):
        shares.add_column(escape(column), justify="left" if column == "input" else "right")
    ranked = sorted(rss_lead["contributions"].items(), key=lambda kv: -kv[1])
    for name, share in ranked:
        effect = rss_lead["sensitivities"][name] * record["inputs"][name]["std"]
        shares.add_row(name, f"{100 * share:.2f} %", format_number(
            _as_solve_shows(report, effect, units[lead], lead)[0]))
    out.print(shares)


def _print_yield_and_verdict(out: Any, report: StudyReport) -> None:
    """The Monte Carlo yield line, PASS or FAIL at worst case, and the warnings."""
    record = report.record
    results = record["results"]
    if "yield" in record:
        out.print(f"Monte Carlo: {record['samples']} samples ({record['sampler']}, seed "
                  f"{record['seed']}): yield {_yield(record['yield'])}, "
                  f"{_out_of_spec(1.0 - record['yield'])} out of spec, "
                  f"{_capability(record)}, {record['infeasible_samples']} impossible designs")
        beyond = _beyond_the_band(record["inputs"])
        if beyond:
            out.print(f"[dim]Monte Carlo draws a normal input beyond its band ({beyond}), so "
                      "the samples' extremes can pass the worst case.[/]")
    worst = [Verdict(**entry) for entry in record.get("worst_case_verdicts", [])]
    verdict = report.within_limits
    if verdict is True:
        out.print("[bold green]PASS[/]: every margin stays within its limit"
                  + (f" at worst case; the closest: {verdict_line(worst[0])}" if worst
                     else " at worst case" if _ran(results, "worst_case") else ""))
    elif verdict is False:
        reached = [verdict_line(v) for v in worst if not v.passed]
        out.print("[bold red]FAIL[/]: the tolerances can take a margin past its limit"
                  + (f": at worst case, {'; '.join(reached)}" if reached else ""))
    for warning in record["warnings"]:
        out.print(f"[yellow]warning[/]: {safe_text(warning)}")


def _print_sobol_indices(out: Any, record: dict[str, Any], governing: list[str]) -> None:
    """The Sobol' indices of every result that has them (the studied results first): a
    row per input, the results under their names, the inputs by total index."""
    from rich.table import Table

    results = record["results"]
    keys = [*governing, *(key for key in results if key not in governing)]
    indexed = [key for key in keys if "sobol" in results[key]]
    if not indexed:
        return
    table = Table(title="Sobol' indices: each input's share of a result's variance, alone "
                  "(first order) and with its interactions (total order)",
                  title_justify="left")
    for column in ("result", "input", "first order", "total order"):
        table.add_column(column, justify="left" if column in ("result", "input") else "right",
                         no_wrap=column != "result", overflow="fold")
    for key in indexed:
        first, total = (results[key]["sobol"][order] for order in ("first_order",
                                                                    "total_order"))
        for row, name in enumerate(sorted(total, key=lambda name: -total[name])):
            # an estimate a hair below 0 reads 0.000, not -0.000
            table.add_row(key if row == 0 else "", name, f"{round(first[name], 3) + 0.0:.3f}",
                          f"{round(total[name], 3) + 0.0:.3f}",
                          end_section=row == len(total) - 1)
    out.print(table)


def _as_solve_shows(report: StudyReport, value: float, si_unit: str,
                    key: str | None = None) -> tuple[float, str]:
    """A value as solve shows it: the kind's own unit for its results (10⁶ rev), else
    the engineering unit of the SI one."""
    if key is not None and key in report.display:
        unit, factor = report.display[key]
        return value * factor, unit
    return si_display(value, si_unit)


def _as_written(entry: dict[str, Any], si_unit: str) -> list[tuple[float, str]] | None:
    """A toleranced input's nominal, band ends and σ in the unit the spec wrote it in
    (80 degC stays degC, 0.3 in stays in); None where it was written without a unit
    or in one that is not this quantity's."""
    written = entry.get("written_unit", "")
    keys = ("nominal", "low", "high")
    if written in TEMPERATURE_UNITS:
        scale, offset = TEMPERATURE_UNITS[written]
        return [((entry[k] - offset) / scale, written) for k in keys] + [
            (entry["std"] / scale, written)]
    dimension = next((d for d in DIMENSIONS.values() if d.si_unit == si_unit), None)
    if not written or dimension is None:
        return None
    try:
        factor, divides = unit_scale(written, dimension)
    except UnitError:
        return None
    powers = re.sub(r"\s*(\*\*|\^)\s*", "^", written)
    unit = re.sub(r"\s*\*\s*", "·", powers.replace("^2", "²").replace("^3", "³"))
    return [(entry[k] * factor if divides else entry[k] / factor, unit)
            for k in (*keys, "std")]


def _ran(results: dict[str, Any], method: str) -> bool:
    return any(method in entry for entry in results.values())


def _terminal_histogram(out: Any, key: str, report: StudyReport, si_unit: str,
                        rows: int = 12, width: int = 40) -> None:
    """A small sideways histogram of ``key``'s Monte Carlo samples."""
    from bearingcalc.studies import coarse_histogram

    lows, highs, totals = coarse_histogram(*report.histograms[key], rows)
    if totals.size == 0:
        return
    scale, unit = _as_solve_shows(report, 1.0, si_unit, key)
    out.print()
    out.print(safe_text(f"{key}{f' [{unit}]' if unit else ''}, Monte Carlo histogram:"))
    peak = int(totals.max()) or 1
    # Four digits tell the bins apart; the edges are the histogram's, not results.
    for low, high, total in zip(lows, highs, totals.tolist(), strict=True):
        bar = "█" * round(width * total / peak)
        out.print(f"{_four_digits(low * scale):>10} … {_four_digits(high * scale):<10} "
                  f"{bar} {total}")


def _beyond_the_band(inputs: dict[str, Any]) -> str:
    """Each normal input's band in σ and the share of samples beyond it, P(|z| > k) =
    erfc(k/√2): "radial_load, speed ±3σ: 0.27 %"; empty without normal inputs."""
    by_k: dict[float, list[str]] = {}
    for name, entry in inputs.items():
        if entry["distribution"] == "normal" and entry["std"]:
            k = round((entry["high"] - entry["low"]) / 2 / entry["std"], 6)
            by_k.setdefault(k, []).append(name)
    return "; ".join(f"{', '.join(names)} ±{k:g}σ: {_out_of_spec(math.erfc(k / math.sqrt(2)))}"
                     for k, names in by_k.items())


def _yield(fraction: float) -> str:
    """The yield to as many decimals as its complement, out of spec, shows: 74.8 %,
    99.99730 %."""
    # rounded so that 1 − 0.9 is 0.1, not 0.0999…, whose decade is one lower
    out = round(1.0 - fraction, 12)
    if out <= 0:
        return "100 %"
    decimals = max(1, 2 - math.floor(math.log10(100 * out)))
    return f"{100 * fraction:.{decimals}f} %"


def _four_digits(value: float) -> str:
    """Four significant digits without an exponent where the value allows: 20780, 0.1595."""
    if value == 0 or 1e-4 <= abs(value) < 1e7:
        digits = max(0, 3 - math.floor(math.log10(abs(value)))) if value else 0
        return f"{value:.{digits}f}"
    return f"{value:.4g}"


def _out_of_spec(fraction: float) -> str:
    """A fraction out of spec in % from 0.1 % up, in ppm below."""
    return f"{100 * fraction:.3g} %" if fraction >= 1e-3 else f"{1e6 * fraction:.3g} ppm"


def _capability(record: dict[str, Any]) -> str:
    """The smallest capability index: Cpl or Cpu of a one-sided limit (a margin), Cpk of
    a two-sided one; n/a without a spread or a limit."""
    found = [(entry["value"], f"{entry['index']} {entry['value']:.3g} ({entry['of']})")
             for entry in record.get("capability", {}).values()]
    if record.get("cpk") is not None:
        found.append((record["cpk"], f"Cpk {record['cpk']:.3g}"))
    return min(found)[1] if found else "Cpk n/a"

