"""Presenting evaluations: rich tables (engineering units), JSON Lines and CSV (SI).

This is the only module that imports rich.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable, Mapping, Sequence
from typing import IO, TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.units import to_display
from bearingcalc.wording import plural, printable

if TYPE_CHECKING:  # the report types only; their modules load with their commands
    from bearingcalc.batch import CheckRecord
    from bearingcalc.evaluation import Evaluation
    from bearingcalc.kinds import Kind
    from bearingcalc.sweep import Sweep
    from bearingcalc.tolerance import StudyReport


#: Width of tables when the output is not a terminal (a pipe, a CI log, a file): wide
#: enough that a row stays one line, instead of rich's 80 columns.
PIPE_WIDTH = 200


def console(stream: IO[str] | None = None) -> Any:
    """A rich console on ``stream`` (default stdout): the terminal's width on a terminal,
    ``PIPE_WIDTH`` columns elsewhere."""
    import sys

    from rich.console import Console

    class _Console(Console):
        def on_broken_pipe(self) -> None:
            # rich would exit with status 1 here; the CLI keeps the run's own status.
            raise BrokenPipeError

    target = stream if stream is not None else sys.stdout
    is_terminal = getattr(target, "isatty", lambda: False)()
    return _Console(file=stream, highlight=False, width=None if is_terminal else PIPE_WIDTH)


def _text(text: str) -> str:
    """Spec-supplied text made safe for a rich table: no control characters, no markup."""
    from rich.markup import escape

    return escape(printable(text))


def evaluation_record(evaluation: Evaluation) -> dict[str, Any]:
    """The JSON object of one evaluation (SI values)."""
    return {
        "spec": evaluation.source,
        "kind": evaluation.kind,
        "name": evaluation.name,
        "results": evaluation.results,
        "units": evaluation.units,
        "within_limits": evaluation.within_limits,
        "warnings": evaluation.warnings,
    }


def write_json_lines(evaluations: Iterable[Evaluation], stream: IO[str]) -> None:
    """One JSON object per evaluation per line; non-finite numbers are refused."""
    for evaluation in evaluations:
        stream.write(json.dumps(evaluation_record(evaluation), allow_nan=False,
                                ensure_ascii=False) + "\n")


def write_csv(evaluations: Sequence[Evaluation], stream: IO[str]) -> None:
    """One row per evaluation, SI units in the header; columns are the union of keys."""
    columns: dict[str, str] = {}
    for evaluation in evaluations:
        for key, unit in evaluation.units.items():
            columns.setdefault(key, unit)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["spec", "kind", "name", "within_limits",
                     *(f"{key} [{unit}]" for key, unit in columns.items())])
    for evaluation in evaluations:
        values = [evaluation.results.get(key) for key in columns]
        writer.writerow([printable(evaluation.source), evaluation.kind,
                         printable(evaluation.name),
                         str(evaluation.within_limits).lower(),
                         *("" if value is None else repr(value) for value in values)])
    stream.write(buffer.getvalue())


def print_tables(evaluations: Iterable[Evaluation], kinds: Mapping[str, Any],
                 stream: IO[str] | None = None) -> None:
    """A table per evaluation in engineering units, with a PASS/FAIL verdict.

    ``kinds`` maps a kind's name to its registry entry, which gives each result's
    meaning, the headings that group a long table and any table units of its own.
    The verdict is written in words, so the table reads the same without colour.
    """
    from rich.table import Table

    out = console(stream)
    for evaluation in evaluations:
        kind = kinds[evaluation.kind]
        table = Table(title=_text(f"{evaluation.name}  ({evaluation.kind}, {evaluation.source})"),
                      title_justify="left")
        table.add_column("result")
        table.add_column("value", justify="right")
        table.add_column("unit")
        table.add_column("meaning", style="dim")
        in_matrices = {f"{row}_{column}" for rows, columns in kind.matrices.values()
                       for row in rows for column in columns}
        shown = {key: value for key, value in evaluation.results.items()
                 if key not in in_matrices}
        for heading, keys in _grouped(shown, kind.groups):
            if heading:
                table.add_row(f"[bold]{heading}[/]", end_section=False)
            for key in keys:
                value = evaluation.results[key]
                unit, factor = kind.display.get(key) or to_display(1.0, evaluation.units[key])[::-1]
                shown = "unbounded" if value is None else format_number(value * factor)
                style = "bold" if key in evaluation.margins else None
                table.add_row(key, shown, unit, kind.results[key][1], style=style)
            if heading:
                table.add_section()
        out.print(table)
        for heading, (rows, columns) in kind.matrices.items():
            _print_matrix(out, evaluation, heading, rows, columns)
        if not evaluation.margins:
            out.print(f"[bold green]PASS[/]: {_text(_no_margins(kind))}")
        elif evaluation.within_limits:
            out.print("[bold green]PASS[/]: within limits")
        else:
            out.print(f"[bold red]FAIL[/]: {_text('; '.join(evaluation.violations))}")
        for warning in evaluation.warnings:
            out.print(f"[yellow]warning[/]: {_text(warning)}")
        out.print()


def _no_margins(kind: Kind) -> str:
    """Why a design with no margins passes: its kind has no limits, or none were given."""
    fields = kind.limit_fields
    if not fields:
        return "this kind has no limits"
    named = ", ".join(f"limits.{name}" for name in fields[:-1]) + f" or limits.{fields[-1]}"
    return f"no limits judged: none given that applies to this design; the spec can set {named}"


def _print_matrix(out: Any, evaluation: Evaluation, heading: str, rows: Sequence[str],
                  columns: Sequence[str]) -> None:
    """Results named ``{row}_{column}`` as a table with a row per member; nothing when the
    evaluation has none of them."""
    from rich.table import Table

    present = [row for row in rows if any(f"{row}_{c}" in evaluation.results for c in columns)]
    if not present:
        return
    table = Table(title=heading, title_justify="left")
    table.add_column("")
    for column in columns:
        unit = to_display(1.0, evaluation.units.get(f"{present[0]}_{column}", "1"))[1]
        table.add_column(_text(f"{column} [{unit}]" if unit else column), justify="right")
    for row in present:
        cells = []
        for column in columns:
            value = evaluation.results.get(f"{row}_{column}")
            key = f"{row}_{column}"
            cells.append("" if value is None else format_number(
                to_display(value, evaluation.units[key])[0]))
        table.add_row(row, *cells)
    out.print(table)


def _grouped(results: Mapping[str, Any], groups: Mapping[str, Sequence[str]]
             ) -> list[tuple[str, list[str]]]:
    """(heading, keys) in table order: each group's results that are present, then the
    rest under no heading; one unnamed group when the kind has no headings."""
    if not groups:
        return [("", list(results))]
    placed = [(heading, [key for key in keys if key in results])
              for heading, keys in groups.items()]
    grouped = {key for _, keys in placed for key in keys}
    rest = [key for key in results if key not in grouped]
    return [(heading, keys) for heading, keys in placed if keys] + ([("", rest)] if rest else [])


def format_number(value: float) -> str:
    """Seven significant digits; exact zero stays 0."""
    if value == 0:
        return "0"
    return f"{value:.7g}"


def check_record_json(record: CheckRecord) -> dict[str, Any]:
    """The JSON object of one check verdict."""
    return {"spec": record.spec, "kind": record.kind, "name": record.name,
            "status": record.status, "messages": record.messages, "margins": record.margins}


def write_check_json_lines(records: Iterable[CheckRecord], stream: IO[str]) -> None:
    for record in records:
        stream.write(json.dumps(check_record_json(record), allow_nan=False,
                                ensure_ascii=False) + "\n")


def write_junit(records: Sequence[CheckRecord], stream: IO[str]) -> None:
    """JUnit XML: one testcase per spec; ``fail`` as failure, ``invalid`` as error."""
    from xml.etree import ElementTree

    failures = sum(r.status == "fail" for r in records)
    errors = sum(r.status == "invalid" for r in records)
    suites = ElementTree.Element("testsuites", name="bearingcalc check", tests=str(len(records)),
                                 failures=str(failures), errors=str(errors))
    suite = ElementTree.SubElement(suites, "testsuite", name="bearingcalc check",
                                   tests=str(len(records)), failures=str(failures),
                                   errors=str(errors), skipped="0")
    for record in records:
        case = ElementTree.SubElement(suite, "testcase", classname=record.kind or "spec",
                                      name=printable(record.spec),
                                      file=printable(record.spec.split("#")[0]))
        text = "\n".join(printable(message) for message in record.messages)
        if record.status == "fail":
            ElementTree.SubElement(case, "failure", message=printable(_first(record.messages)),
                                   type="limit").text = text
        elif record.status == "invalid":
            ElementTree.SubElement(case, "error", message=printable(_first(record.messages)),
                                   type="invalid").text = text
    ElementTree.indent(suites)
    stream.write('<?xml version="1.0" encoding="UTF-8"?>\n')
    stream.write(ElementTree.tostring(suites, encoding="unicode") + "\n")


def print_check_table(records: Sequence[CheckRecord], *, show_all: bool,
                      stream: IO[str] | None = None, many: int = 50) -> None:
    """One row per spec (only fail/invalid rows past ``many`` specs unless ``show_all``),
    then a summary line with the counts."""
    from rich.table import Table

    out = console(stream)
    shown = records if show_all or len(records) <= many else [
        r for r in records if r.status != "pass"]
    if shown:
        table = Table(show_edge=False)
        for column in ("status", "file", "name", "kind", "governing margin / problem"):
            table.add_column(column, overflow="fold")
        colours = {"pass": "green", "fail": "red", "invalid": "magenta"}
        for record in shown:
            governing = record.governing_margin
            if record.status == "invalid":
                detail = _first(record.messages)
            elif governing is None:
                detail = "no limits judged"
            else:
                detail = f"{governing[0]} = {format_number(governing[1])}"
            table.add_row(f"[{colours[record.status]}]{record.status.upper()}[/]",
                          _text(record.spec), _text(record.name or ""), record.kind or "",
                          _text(_without_source(detail, record.spec)))
        out.print(table)
    counts = {status: sum(r.status == status for r in records)
              for status in ("pass", "fail", "invalid")}
    hidden = len(records) - len(shown)
    note = f" ({hidden} passing not shown; --all shows them)" if hidden else ""
    out.print(f"{plural(len(records), 'spec')}: [green]{counts['pass']} pass[/], "
                  f"[red]{counts['fail']} fail[/], "
                  f"[magenta]{counts['invalid']} invalid[/]{note}")


def _without_source(message: str, source: str) -> str:
    """A problem without its leading 'file:' (the file column says it), keeping ':line:'."""
    return message[len(source):].lstrip(":") if message.startswith(source + ":") else message


def _first(messages: Sequence[str]) -> str:
    return messages[0] if messages else ""


def print_tolerance_table(report: StudyReport, stream: IO[str] | None = None) -> None:
    """Worst case, RSS and Monte Carlo side by side (engineering units), the contribution
    table of the governing result, the yield and verdict, and a terminal histogram."""
    from rich import box
    from rich.markup import escape
    from rich.table import Table

    record = report.record
    out = console(stream)
    units = record["units"]
    out.print(f"[bold]{_text(record['name'] or record['spec'])}[/] ({record['kind']}, "
              f"{_text(record['spec'])})")

    inputs = Table(title="toleranced inputs", title_justify="left")
    for column in ("input", "nominal", "low", "high", "unit", "distribution", "σ"):
        inputs.add_column(column, no_wrap=True, justify="left" if column in (
            "input", "unit", "distribution") else "right")
    for name, entry in record["inputs"].items():
        shown = [to_display(entry[k], units[name]) for k in ("nominal", "low", "high", "std")]
        inputs.add_row(name, *(format_number(v) for v, _ in shown[:3]), shown[0][1],
                       entry["distribution"], format_number(shown[3][0]))
    out.print(inputs)

    table = Table(title="results: worst case, RSS and Monte Carlo side by side",
                  title_justify="left", box=box.SIMPLE_HEAD, pad_edge=False)
    for column in ("result", "nominal", "worst case\nmin\nmax", "RSS\nmean\nσ",
                   "Monte\nCarlo\nmean\nσ", "MC\nquantile\n0.135 %\n99.865 %"):
        table.add_column(column, justify="left" if column == "result" else "right",
                         no_wrap=True)
    results = record["results"]
    for key in report.governing:
        entry = results[key]
        unit = to_display(0.0, units[key])[1]

        def cell(*values: float | None, key: str = key) -> str:
            if any(v is None for v in values):
                return ""
            # Four digits keep six columns in 80; the JSON carries every digit.
            return "\n".join(f"{to_display(v, units[key])[0]:.4g}" for v in values)

        wc, rss, mc = (entry.get(m) or {} for m in ("worst_case", "rss", "monte_carlo"))
        table.add_row(escape(f"{key}\n[{unit}]") if unit else key, cell(entry["nominal"]),
                      cell(wc.get("min"), wc.get("max")), cell(rss.get("mean"), rss.get("std")),
                      cell(mc.get("mean"), mc.get("std")),
                      cell(mc.get("p00135"), mc.get("p99865")))
    out.print(table)

    others = [key for key in results if key not in report.governing]
    if others and _ran(results, "worst_case"):
        rest = Table(title="other results at worst case (all methods: --format json)",
                     title_justify="left")
        for column in ("result", "unit", "nominal", "min", "max"):
            rest.add_column(column, justify="left" if column in ("result", "unit") else "right",
                            no_wrap=True)
        for key in others:
            wc = results[key].get("worst_case") or {}
            shown = [to_display(v, units[key]) if v is not None else (None, "")
                     for v in (results[key]["nominal"], wc.get("min"), wc.get("max"))]
            rest.add_row(key, to_display(0.0, units[key])[1],
                         *("" if v is None else format_number(v) for v, _ in shown))
        out.print(rest)

    lead = report.governing[0] if report.governing else None
    rss_lead = (results.get(lead) or {}).get("rss") if lead else None
    if rss_lead and rss_lead.get("contributions"):
        shares = Table(title=f"which tolerance dominates {lead} (RSS)", title_justify="left")
        for column in ("input", "share", "∂f/∂x · σ"):
            shares.add_column(column, justify="left" if column == "input" else "right")
        ranked = sorted(rss_lead["contributions"].items(), key=lambda kv: -kv[1])
        for name, share in ranked:
            effect = rss_lead["sensitivities"][name] * record["inputs"][name]["std"]
            shares.add_row(name, f"{100 * share:.2f} %", format_number(
                to_display(effect, units[lead])[0]))
        out.print(shares)

    if "yield" in record:
        cpk = "n/a" if record["cpk"] is None else f"{record['cpk']:.3f}"
        out.print(f"Monte Carlo: {record['samples']} samples ({record['sampler']}, seed "
                      f"{record['seed']}): yield {100 * record['yield']:.4f} %, "
                      f"{record['ppm_out']:.1f} ppm out of spec, Cpk {cpk}, "
                      f"{record['infeasible_samples']} impossible designs")
    verdict = report.within_limits
    if verdict is True:
        out.print("[bold green]PASS[/]: every margin stays within its limit"
                      + (" at worst case" if _ran(results, "worst_case") else ""))
    elif verdict is False:
        reached = [f"{m} reaches {format_number(results[m]['worst_case']['min'])}"
                   for m in report.margins if (results[m].get("worst_case") or {}).get("min")
                   is not None and results[m]["worst_case"]["min"] < 0]
        out.print("[bold red]FAIL[/]: the tolerances can take a margin past its limit"
                      + (f" ({'; '.join(reached)} at worst case)" if reached else ""))
    for warning in record["warnings"]:
        out.print(f"[yellow]warning[/]: {_text(warning)}")
    if lead and lead in report.histograms:
        _terminal_histogram(out, lead, report, units[lead])


def _ran(results: dict[str, Any], method: str) -> bool:
    return any(method in entry for entry in results.values())


def _spread(std: float | None, si_unit: str) -> str:
    return "" if std is None else format_number(to_display(std, si_unit)[0])


def _terminal_histogram(console: Any, key: str, report: StudyReport, si_unit: str,
                        rows: int = 12, width: int = 40) -> None:
    """A small sideways histogram of ``key``'s Monte Carlo samples."""
    from bearingcalc.tolerance import coarse_histogram

    lows, highs, totals = coarse_histogram(*report.histograms[key], rows)
    if totals.size == 0:
        return
    unit = to_display(0.0, si_unit)[1]
    console.print()
    console.print(_text(f"{key}{f' [{unit}]' if unit else ''}, Monte Carlo histogram:"))
    peak = int(totals.max()) or 1
    for low, high, total in zip(lows, highs, totals.tolist(), strict=True):
        bar = "█" * round(width * total / peak)
        console.print(f"{format_number(to_display(low, si_unit)[0]):>12} … "
                      f"{format_number(to_display(high, si_unit)[0]):<12} {bar} {total}")


SWEEP_CSV_ROWS = 50_000


def sweep_columns(sweep: Sweep) -> list[tuple[str, NDArray]]:
    """(header, values) of the CSV's numeric columns: the varied inputs, then every result."""
    # "input." keeps a varied input apart from the result of the same name.
    columns = [(f"input.{axis.name} [{axis.unit}]", sweep.inputs[axis.name])
               for axis in sweep.axes]
    units = sweep.units
    columns += [(f"{key} [{units[key]}]", values) for key, values in sweep.results.items()]
    return columns


def write_sweep_csv(sweep: Sweep, stream: IO[str]) -> None:
    """One row per point: the varied inputs, every result (SI, units in the header) and the
    reason a point is impossible (empty results then).

    Numbers are written in their shortest round-trip form by orjson, 50,000 rows at
    a time: formatting a million rows is the cost of a large sweep, and Python's
    float formatting would take several times as long. Each block is turned into
    CSV as bytes, with no work per line (see :func:`_csv_block`).
    """
    columns = sweep_columns(sweep)
    stream.write(",".join([*(name for name, _ in columns), "reason"]) + "\n")
    integer_axes = [axis.integer for axis in sweep.axes]
    reasons = {code: ("," + _csv_text(sweep.reason(code))).encode() for code in
               np.unique(sweep.status).tolist() if code}
    for start in range(0, len(sweep.status), SWEEP_CSV_ROWS):
        stop = min(start + SWEEP_CSV_ROWS, len(sweep.status))
        block = np.column_stack([values[start:stop].astype(float) for _, values in columns])
        pieces = _csv_block(block, sweep.status[start:stop], len(sweep.axes), reasons)
        if any(integer_axes):
            lines = [_integer_fields(line, integer_axes)
                     for line in b"".join(pieces).split(b"\n")[:-1]]
            pieces = [b"\n".join(lines) + b"\n"]
        for piece in pieces:
            _write_bytes(stream, piece)


#: Row by row, orjson's "[[a,b],[c,d]]" with "]" deleted and "[" made a line end: each
#: row then ends in "," and a line end, a possible design's row end exactly.
_ROWS = bytes.maketrans(b"[", b"\n")


def _csv_block(block: NDArray, codes: NDArray, inputs: int, reasons: dict[int, bytes]
               ) -> list[bytes | memoryview]:
    """CSV lines of a block of rows (the varied inputs, then the results) with their
    status codes, in passes over the whole block's text and none per line; in pieces,
    to be written one after the other without joining them.

    One translate makes every row a possible design's line. An impossible design's
    results are all NaN: its first result is set to its code before formatting, so
    that its row end (``,5.0,null,…,null,`` and the line end) is found, one pass per
    code present, and replaced by empty fields and the reason. A last pass, only in
    a block with a number that is not finite elsewhere, empties the ``null`` orjson
    writes for it. A block where a possible design's row end could read as an
    impossible one's is written by :func:`_csv_block_marked` instead.
    """
    import orjson

    results = block.shape[1] - inputs
    impossible = codes != 0
    present = np.unique(codes[impossible]).tolist()
    finite = np.isfinite(block)
    if present and (results == 0 or finite[impossible, inputs:].any()
                    or _could_read_as_impossible(block[:, inputs:], finite[:, inputs:],
                                                 impossible, present)):
        return _csv_block_marked(block, codes, reasons)
    block[impossible, inputs] = codes[impossible]
    text = orjson.dumps(block, option=orjson.OPT_SERIALIZE_NUMPY).translate(_ROWS, b"]")
    # "[[" became two line ends, and the last row ends in "]]": it has no row end yet.
    # code -> (its row's results as written, the same as CSV: empty fields and the reason)
    blanks = {code: (b"," + repr(float(code)).encode() + b",null" * (results - 1),
                     b"," * results + reasons[code]) for code in present}
    for written, line in blanks.values():
        text = text.replace(written + b",\n", line + b"\n")
    last, ending = len(text), b",\n"
    if codes[-1]:
        written, line = blanks[int(codes[-1])]
        last, ending = last - len(written), line + b"\n"
    if not finite[~impossible].all():
        # Only now, so that the impossible rows' nulls above were still there to find.
        return [bytes(memoryview(text)[2:last]).replace(b"null", b""), ending]
    return [memoryview(text)[2:last], ending]


def _could_read_as_impossible(results: NDArray, finite: NDArray, impossible: NDArray,
                              codes: list[int]) -> bool:
    """Whether a possible design's results could end its row as an impossible one's:
    a code as its first result and nothing finite after it."""
    return bool((~impossible & np.isin(results[:, 0], codes)
                 & ~finite[:, 1:].any(axis=1)).any())


def _csv_block_marked(block: NDArray, codes: NDArray, reasons: dict[int, bytes]
                      ) -> list[bytes | memoryview]:
    """:func:`_csv_block` for any block: the status code rides along as a last column,
    so that ``,<code>],[`` ends every row and one pass per code present replaces it."""
    import orjson

    marker = np.where(codes == 0, np.nan, codes.astype(float))
    text = orjson.dumps(np.column_stack([block, marker]), option=orjson.OPT_SERIALIZE_NUMPY)
    body = text[2:-2].replace(b"],[", b"\n").replace(b"null", b"") + b"\n"
    for code in np.unique(codes).tolist():
        if code:
            body = body.replace(b"," + repr(float(code)).encode() + b"\n",
                                reasons[code] + b"\n")
    # A possible design's marker was a null: the line ends in the reason's empty field.
    return [body]


def _write_bytes(stream: IO[str], data: bytes | memoryview) -> None:
    """UTF-8 bytes onto a text stream: straight to its buffer where it has one."""
    buffer = getattr(stream, "buffer", None)
    if buffer is None:
        stream.write(bytes(data).decode())
        return
    stream.flush()
    buffer.write(data)


def write_sweep_parquet(sweep: Sweep, path: Any) -> None:
    """The CSV's columns as a Parquet table (pyarrow, the optional extra
    ``bearingcalc[parquet]``): float64 columns named as the CSV's headers, integer axes
    as int64, and ``reason`` (null for possible designs)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    arrays, names = [], []
    integer = {f"input.{axis.name} [{axis.unit}]": axis.integer for axis in sweep.axes}
    for name, values in sweep_columns(sweep):
        # from_pandas: NaN (an impossible design's result) becomes null, as in the CSV.
        arrays.append(pa.array(values.astype(np.int64) if integer.get(name)
                               else values.astype(float), from_pandas=True))
        names.append(name)
    reasons = {code: sweep.reason(code) for code in np.unique(sweep.status).tolist() if code}
    arrays.append(pa.array([reasons.get(code) for code in sweep.status.tolist()],
                           type=pa.string()))
    names.append("reason")
    pq.write_table(pa.Table.from_arrays(arrays, names=names), path)


def _integer_fields(line: bytes, integer_axes: list[bool]) -> bytes:
    fields = line.split(b",", len(integer_axes))
    for i, integer in enumerate(integer_axes):
        if integer and fields[i].endswith(b".0"):
            fields[i] = fields[i][:-2]
    return b",".join(fields)


def _csv_text(text: str) -> str:
    return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n') else text


def write_sweep_json_lines(sweep: Sweep, stream: IO[str]) -> None:
    """JSON Lines, one object per point: {"inputs", "results", "reason"} (SI units, as
    in the CSV header and the README)."""
    import orjson

    names = [axis.name for axis in sweep.axes]
    integer = {axis.name: axis.integer for axis in sweep.axes}
    keys = list(sweep.results)
    for start in range(0, len(sweep.status), SWEEP_CSV_ROWS):
        stop = min(start + SWEEP_CSV_ROWS, len(sweep.status))
        inputs = {name: sweep.inputs[name][start:stop].tolist() for name in names}
        results = {key: sweep.results[key][start:stop].tolist() for key in keys}
        lines = []
        for row, code in enumerate(sweep.status[start:stop].tolist()):
            point = {name: (int(inputs[name][row]) if integer[name] else inputs[name][row])
                     for name in names}
            solved = {} if code else {key: results[key][row] for key in keys}
            lines.append(orjson.dumps({"inputs": point, "results": solved,
                                       "reason": sweep.reason(code) if code else None}))
        stream.write(b"\n".join(lines).decode() + "\n")


def print_sweep_table(sweep: Sweep, keys: Sequence[str], stream: IO[str] | None = None,
                      grid_rows: int = 12, grid_columns: int = 8) -> None:
    """All points of a line with the chosen results; for a grid, the first chosen result
    on a compact grid (every n-th value of each axis)."""
    from rich.markup import escape
    from rich.table import Table

    out = console(stream)
    units = sweep.units

    def shown(value: float, si_unit: str, digits: int = 7) -> str:
        if not np.isfinite(value):
            return "—"
        return f"{to_display(value, si_unit)[0]:.{digits}g}"

    def label(name: str, si_unit: str) -> str:
        unit = to_display(0.0, si_unit)[1]
        return escape(f"{name} [{unit}]") if unit else name

    title = printable(f"{sweep.name} ({sweep.kind.name}, {sweep.source})")
    if len(sweep.axes) == 1:
        axis = sweep.axes[0]
        table = Table(title=escape(title), title_justify="left")
        for header in (label(axis.name, axis.unit), *(label(k, units[k]) for k in keys)):
            table.add_column(header, justify="right")
        table.add_column("impossible because")
        for i, value in enumerate(sweep.inputs[axis.name].tolist()):
            code = int(sweep.status[i])
            table.add_row(shown(value, axis.unit),
                          *(shown(sweep.results[k][i], units[k]) for k in keys),
                          sweep.reason(code) if code else "")
        out.print(table)
        return
    first, second = sweep.axes
    key = keys[0]
    values = sweep.results[key].reshape(sweep.shape)
    rows = np.unique(np.linspace(0, len(first.values) - 1, grid_rows).round().astype(int))
    cols = np.unique(np.linspace(0, len(second.values) - 1, grid_columns).round().astype(int))
    table = Table(title=f"{escape(title)}\n{label(key, units[key])} by "
                  f"{label(first.name, first.unit)} (rows) and {label(second.name, second.unit)}"
                  " (columns); —: impossible design", title_justify="left")
    table.add_column("")
    for j in cols:
        table.add_column(shown(second.values[j], second.unit, 4), justify="right")
    for i in rows:
        table.add_row(shown(first.values[i], first.unit, 4),
                      *(shown(values[i, j], units[key], 4) for j in cols))
    out.print(table)
    if len(rows) < len(first.values) or len(cols) < len(second.values):
        out.print(f"(every point of the {len(first.values)} × {len(second.values)} grid is "
                      "in --format csv or json)")
