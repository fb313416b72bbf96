"""The calculation report of a spec file: each document solved as ``solve`` solves it,
its inputs read back as written and in SI, the drawings its kind names
(:mod:`bearingcalc.plots.report`), all written by
:func:`bearingcalc.reports.html.report_html`."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

from bearingcalc import __version__
from bearingcalc.evaluation import evaluate_document, load_selected, parse_document
from bearingcalc.kinds import KINDS
from bearingcalc.models.base import field_parser
from bearingcalc.models.field_path import FieldPathError, resolve_field
from bearingcalc.models.quantities import Measured
from bearingcalc.models.yaml_loader import read_spec_text
from bearingcalc.plots.report import report_plots
from bearingcalc.reports.html import report_html


def report_of(path: str | Path) -> str:
    """The HTML report of every document of the spec file at ``path``; SpecError where
    a document cannot be read or solved (as ``solve`` would refuse it)."""
    documents = load_selected(path)
    text = read_spec_text(str(path).rpartition("#")[0] if not Path(path).exists()
                          else path)
    evaluations, inputs, plots = [], [], []
    for document in documents:
        evaluation = evaluate_document(document)
        kind, spec = parse_document(document)
        evaluations.append(evaluation)
        inputs.append(list(_inputs(document.data, spec)))
        plots.append(report_plots(kind, spec, evaluation))
    return report_html(evaluations, KINDS, text, str(path), __version__, inputs, plots)


def _leaves(data: Any, prefix: str = "") -> Iterator[tuple[str, Any]]:
    if isinstance(data, dict):
        if {"nominal"} <= set(data):  # a toleranced value, as one input
            yield prefix, data
            return
        for key, value in data.items():
            yield from _leaves(value, f"{prefix}.{key}" if prefix else str(key))
    elif isinstance(data, list):
        for i, value in enumerate(data, 1):
            yield from _leaves(value, f"{prefix}.{i}")
    else:
        yield prefix, data


def _inputs(data: Any, spec: Any) -> Iterator[tuple[str, str, str]]:
    """(field, as written, in SI) of every input the spec gives."""
    for name, written in _leaves(data):
        if name in ("kind", "name"):
            continue
        shown = written if isinstance(written, str) else (
            "{" + ", ".join(f"{k}: {v}" for k, v in written.items()) + "}"
            if isinstance(written, dict) else str(written))
        try:
            found = resolve_field(spec, name)
        except FieldPathError:
            yield name, shown, ""
            continue
        value = found.value
        if isinstance(value, Measured):  # a toleranced input: its nominal value
            value = float(value)
        parsed = field_parser(found.info) if found.info is not None else None
        unit = "" if parsed is None or parsed[2] == "1" else f" {parsed[2]}"
        if isinstance(value, bool):
            si = "true" if value else "false"
        elif isinstance(value, float):
            si = f"{value:.10g}{unit}"  # ten digits: the float's own, not its last bits
        else:
            si = str(value)
        yield name, shown, si
