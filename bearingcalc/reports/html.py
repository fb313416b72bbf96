"""The calculation report: one self-contained HTML file per spec file (CSS and every plot
inlined as SVG, no external resource), to print and file with the drawing.

It holds a header (name, kind, verdict in words, date, bearingcalc's version, the
spec's path and SHA-256), the inputs as written and in SI, every result by its group
with its unit and meaning (and its SI value, as the JSON gives it), the verdict lines,
the warnings, the standards the kind applies, the plots that fit the kind, and the spec
verbatim.
"""

from __future__ import annotations

import datetime
import hashlib
from collections.abc import Iterator, Mapping, Sequence
from html import escape
from typing import TYPE_CHECKING

from bearingcalc.reports.formatting import format_number
from bearingcalc.units import to_display
from bearingcalc.verdicts import verdict_line

if TYPE_CHECKING:
    from bearingcalc.evaluation import Evaluation
    from bearingcalc.kinds import Kind

_CSS = """
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; font-size: 10pt;
       margin: 1.5em; color: #111; }
h1 { font-size: 16pt; margin-bottom: 0.2em; } h2 { font-size: 12pt; margin-top: 1.4em;
  border-bottom: 1px solid #999; } h3 { font-size: 10.5pt; margin: 0.8em 0 0.3em; }
table { border-collapse: collapse; margin: 0.3em 0 0.8em; }
th, td { border: 1px solid #bbb; padding: 2px 6px; vertical-align: top; }
th { background: #eee; text-align: left; } td.number { text-align: right;
  font-variant-numeric: tabular-nums; white-space: nowrap; }
.pass { color: #1a7f37; font-weight: bold; } .fail { color: #b42318; font-weight: bold; }
pre { background: #f6f6f6; border: 1px solid #ddd; padding: 0.6em; font-size: 8.5pt;
      white-space: pre-wrap; }
.meta td { border: none; padding: 0 1em 0 0; } figure { margin: 0.5em 0; }
figure svg { max-width: 100%; height: auto; }
td.si { color: #555; font-size: 8.5pt; }
@page { margin: 15mm; }
@media print { body { margin: 0; } h2 { break-after: avoid; }
  section { break-before: page; } section.first { break-before: avoid; }
  table, figure { break-inside: avoid; } }
"""


def report_html(evaluations: Sequence[Evaluation], kinds: Mapping[str, Kind],
                spec_text: str, spec_path: str, version: str,
                inputs: Sequence[list[tuple[str, str, str]]],
                plots: Sequence[list[tuple[str, str]]]) -> str:
    """The whole report of a spec file: one section per document. ``inputs[i]`` is the
    i-th document's (field, as written, in SI) rows, ``plots[i]`` its (caption, SVG)."""
    digest = hashlib.sha256(spec_text.encode("utf-8")).hexdigest()
    today = datetime.datetime.now(datetime.timezone.utc).date().isoformat()
    title = escape(evaluations[0].name if len(evaluations) == 1 else spec_path)
    parts = [f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
             f"<title>{title}: calculation report</title><style>{_CSS}</style></head><body>"]
    for i, evaluation in enumerate(evaluations):
        parts.append(_section(evaluation, kinds[evaluation.kind], i == 0, today, version,
                              spec_path, digest, inputs[i], plots[i]))
    parts.append(f"<section><h2>The spec, verbatim</h2><p>{escape(spec_path)}, SHA-256 "
                 f"<code>{digest}</code></p><pre>{escape(spec_text)}</pre></section>")
    parts.append("</body></html>\n")
    return "".join(parts)


def _section(evaluation: Evaluation, kind: Kind, first: bool, today: str, version: str,
             spec_path: str, digest: str, inputs: list[tuple[str, str, str]],
             plots: list[tuple[str, str]]) -> str:
    verdict = ("<span class=\"pass\">PASS</span>: every limit is met" if
               evaluation.within_limits else "<span class=\"fail\">FAIL</span>: a limit is "
               "broken")
    if not evaluation.margins:
        verdict = "<span class=\"pass\">PASS</span>: no limit judged"
    out = [f"<section class=\"{'first' if first else ''}\">",
           f"<h1>{escape(evaluation.name)}</h1>",
           "<table class=\"meta\">",
           *(f"<tr><td>{label}</td><td>{value}</td></tr>" for label, value in (
               ("kind", escape(evaluation.kind)), ("verdict", verdict), ("date", today),
               ("bearingcalc", escape(version)), ("spec", escape(spec_path)),
               ("SHA-256", f"<code>{digest}</code>"),
               *((escape(key), escape(value)) for key, value in evaluation.sources.items()))),
           "</table>"]
    out.append("<h2>Inputs</h2><table><tr><th>input</th><th>as written</th><th>SI</th></tr>")
    out += [f"<tr><td>{escape(name)}</td><td>{escape(written)}</td>"
            f"<td class=\"number\">{escape(si)}</td></tr>" for name, written, si in inputs]
    out.append("</table>")
    out.append("<h2>Results</h2>")
    out += list(_result_tables(evaluation, kind))
    out.append("<h2>Verdict</h2><ul>")
    if evaluation.within_limits:
        lines = [verdict_line(v) for v in evaluation.verdicts] or ["no limit judged"]
        out += [f"<li class=\"pass\">PASS: {escape(line)}</li>" for line in lines]
    else:
        out += [f"<li class=\"fail\">FAIL: {escape(line)}</li>"
                for line in evaluation.violations]
    out.append("</ul>")
    if evaluation.warnings:
        out.append("<h2>Warnings</h2><ul>")
        out += [f"<li>{escape(warning)}</li>" for warning in evaluation.warnings]
        out.append("</ul>")
    out.append("<h2>Standards and methods</h2><ul>")
    out += [f"<li>{escape(line)}</li>" for line in kind.standards]
    out.append(f"</ul><p>docs/physics.md is the derivation and check of each method, in "
               f"bearingcalc {escape(version)}'s source and documentation.</p>")
    for caption, svg in plots:
        out.append(f"<figure>{svg}<figcaption>{escape(caption)}</figcaption></figure>")
    out.append("</section>")
    return "".join(out)


def _result_tables(evaluation: Evaluation, kind: Kind) -> Iterator[str]:
    grouped: set[str] = set()
    # a matrix's members (each bearing of a shaft, each bin of a cycle) under its heading
    members = [(table.heading, table.keys) for table in evaluation.tables]
    groups = [*kind.groups.items(), *members, ("other", tuple(evaluation.results))]
    for heading, keys in groups:
        present = [key for key in keys if key in evaluation.results and key not in grouped]
        if not present:
            continue
        grouped.update(present)
        yield (f"<h3>{escape(heading)}</h3><table><tr><th>result</th><th>value</th>"
               "<th>unit</th><th>meaning</th><th>SI</th></tr>")
        for key in present:
            value = evaluation.results[key]
            unit, factor = kind.display.get(key) or to_display(1.0, evaluation.units[key])[::-1]
            shown = "unbounded" if value is None else format_number(value * factor)
            # the JSON's number whole in data-si; ten digits on the page, which the
            # float's last bits (2.1500000000000004) would only clutter
            si = "null" if value is None else repr(value)
            short = "null" if value is None else f"{value:.10g}"
            yield (f"<tr><td>{escape(key)}</td><td class=\"number\">{escape(shown)}</td>"
                   f"<td>{escape(unit)}</td><td>{escape(evaluation.meanings[key])}</td>"
                   f"<td class=\"number si\" data-key=\"{escape(key)}\" "
                   f"data-si=\"{escape(si)}\">{escape(short)}</td></tr>")
        yield "</table>"
