"""From a YAML document to checked results: the one path every command takes.

``load_spec_file`` reads a file into documents; ``parse_document``
(:mod:`bearingcalc.parsing`) validates one against its kind's model;
``evaluate_document`` solves it and judges it against its limits. Errors come out as
:class:`SpecError` with file, line and field.
"""

from __future__ import annotations

import math
import re
import sys
import traceback
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from bearingcalc.core.common import DerivedTest
from bearingcalc.errors import SpecError
from bearingcalc.kinds import KINDS, Kind
from bearingcalc.models.base import Spec
from bearingcalc.models.field_path import FieldPath
from bearingcalc.models.yaml_loader import (
    Document,
    load_documents,
)
from bearingcalc.parsing import parse_document
from bearingcalc.result_keys import FlatResults, ResultTable
from bearingcalc.verdicts import Verdict, judge, verdict_line
from bearingcalc.wording import plural


@dataclass
class Evaluation:
    """The solved results of one valid spec, in SI units."""

    source: str
    kind: str
    name: str
    results: dict[str, float | None]      # None: unbounded (see warnings)
    units: dict[str, str]
    margins: dict[str, float]
    warnings: list[str] = field(default_factory=list)
    #: names of the rows of the kind's tables of results (a duty cycle's bins)
    row_names: dict[str, str] = field(default_factory=dict)
    #: every limit judged, the worst first
    verdicts: list[Verdict] = field(default_factory=list)
    #: the catalogue row of each bearing taken from one: ``catalogue_source`` (or
    #: ``pinion_bearing_1_catalogue_source``) -> designation, maker and source
    sources: dict[str, str] = field(default_factory=dict)
    #: each result's meaning
    meanings: dict[str, str] = field(default_factory=dict)
    #: the results along axes, each axis's table (a row per bearing, per bin)
    tables: tuple[ResultTable, ...] = ()

    @property
    def within_limits(self) -> bool:
        return all(margin >= 0 for margin in self.margins.values())

    @property
    def violations(self) -> list[str]:
        """A line per limit broken, the worst first, in engineering terms."""
        named = {verdict.key for verdict in self.verdicts}
        return [verdict_line(verdict) for verdict in self.verdicts if not verdict.passed] + [
            f"{key} is {value:.4g} (below 0)" for key, value in self.margins.items()
            if value < 0 and key not in named]


def evaluate_documents(documents: Sequence[Document]) -> list[Evaluation | SpecError]:
    """Evaluate many documents: each valid one solved, each bad one refused with its error.

    Specs of the same kind that give the same inputs are stacked into arrays and
    solved in one vectorised call, so a batch costs little more than its parsing.
    """
    outcomes: list[Evaluation | SpecError | None] = [None] * len(documents)
    groups: dict[tuple[str, tuple[Any, ...]], list[tuple[int, Spec, dict[str, Any]]]] = {}
    for index, document in enumerate(documents):
        try:
            kind, spec = parse_document(document)
            inputs = spec.solver_inputs()
        except SpecError as error:
            outcomes[index] = error
            continue
        except Exception as exc:  # one spec's surprise never costs the others their report
            outcomes[index] = _internal_error(document, exc)
            continue
        # Specs solved together must give the same inputs and the same words (a bearing
        # type): which results exist depends on both.
        groups.setdefault((kind.name, _layout(inputs)), []).append((index, spec, inputs))
    for (kind_name, _), members in groups.items():
        kind = KINDS[kind_name]
        try:
            _solve_group(documents, kind, members, outcomes)
        except Exception:
            # Solve them one by one, so only the spec at fault is refused.
            for member in members:
                try:
                    _solve_group(documents, kind, [member], outcomes)
                except Exception as exc:
                    outcomes[member[0]] = _internal_error(documents[member[0]], exc)
    return outcomes  # type: ignore[return-value]


def _solve_group(documents: Sequence[Document], kind: Kind,
                 members: list[tuple[int, Spec, dict[str, Any]]],
                 outcomes: list[Evaluation | SpecError | None]) -> None:
    """Solve specs of one kind with the same inputs given in one vectorised call."""
    stacked = _stacked([member[2] for member in members])
    raw, status, flags = kind.evaluate_with_warnings(stacked)
    layout = raw.with_values({})  # the solve's names, tables and reasons
    columns = {key: values.tolist() for key, values in raw.items()}
    flagged = {key: np.asarray(values, dtype=bool).tolist() for key, values in flags.items()}
    codes = status.tolist()
    for row, (index, spec, _) in enumerate(members):
        values = {key: column[row] for key, column in columns.items()}
        raised = [kind.warnings[key] for key, column in flagged.items() if column[row]]
        try:
            outcomes[index] = _judge(documents[index], kind, spec, values, codes[row], layout,
                                     raised)
        except SpecError as error:
            outcomes[index] = error


def _layout(inputs: Any) -> Any:
    """What must agree for specs to be solved together: the structure of their solver
    inputs, which inputs are given, and their words (a bearing type); not the numbers."""
    if isinstance(inputs, dict):
        return tuple((key, _layout(value)) for key, value in inputs.items())
    if isinstance(inputs, list):
        return tuple(_layout(item) for item in inputs)
    if isinstance(inputs, np.ndarray):  # a duty cycle's bins: their number must agree
        return np.shape(inputs)
    return inputs if inputs is None or isinstance(inputs, str) else float


def _stacked(inputs: list[Any]) -> Any:
    """Solver inputs of specs with one layout, each number replaced by an array of them."""
    first = inputs[0]
    if isinstance(first, dict):
        return {key: _stacked([each[key] for each in inputs]) for key in first}
    if isinstance(first, list):
        return [_stacked([each[i] for each in inputs]) for i in range(len(first))]
    if isinstance(first, np.ndarray):  # the bins stay on the first axis, the specs follow
        return np.stack(inputs, axis=-1)
    return first if first is None or isinstance(first, str) else np.array(inputs)


#: Whether an internal error's traceback goes to stderr where it is caught (the command
#: line's --debug); without, it is only the spec's one line, as the run goes on.
_TRACEBACKS: dict[str, bool] = {"shown": False}


def _listed(keys: Sequence[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    return keys[0] if len(keys) == 1 else f"{', '.join(keys[:-1])} and {keys[-1]}"


def show_tracebacks(shown: bool) -> None:
    """Print (or not) the traceback of every internal error as it is caught."""
    _TRACEBACKS["shown"] = shown


def note_internal_error(exc: BaseException) -> None:
    """An exception caught so that one spec's failure does not stop the others: its
    traceback on stderr when :func:`show_tracebacks` asked for it."""
    if _TRACEBACKS["shown"]:
        traceback.print_exception(exc, file=sys.stderr)


def _internal_error(document: Document, exc: Exception) -> SpecError:
    note_internal_error(exc)
    return document.error(f"internal error ({type(exc).__name__}: {str(exc)[:200]}); "
                          "please report it with this spec")


def evaluate_document(document: Document) -> Evaluation:
    """Solve one document and judge it against its limits; raises SpecError."""
    (outcome,) = evaluate_documents([document])
    if isinstance(outcome, SpecError):
        raise outcome
    return outcome


def evaluate_file(path: str | Path) -> list[Evaluation | SpecError]:
    """Every document of a file (or the one ``file.yaml#N`` names), each evaluated or
    refused with its error."""
    try:
        documents = load_selected(path)
    except SpecError as error:
        return [error]
    return evaluate_documents(documents)


def load_selected(path: str | Path) -> list[Document]:
    """The documents of a spec file, or only the N-th for ``file.yaml#N`` (as reports
    name the documents of a multi-document file); raises SpecError."""
    text_path, _, index = str(path).rpartition("#")
    if not text_path or Path(str(path)).exists() or not Path(text_path).is_file():
        return load_documents(path)
    documents = load_documents(text_path)
    if not re.fullmatch(r"[0-9]{1,9}", index) or not 1 <= int(index) <= len(documents):
        raise SpecError(f"'#{index}' does not pick a document: write {text_path}#N with N "
                        f"from 1 to {len(documents)} (the file has "
                        f"{plural(len(documents), 'document')})", source=text_path)
    return [documents[int(index) - 1]]


def load_one_spec(path: str | Path) -> tuple[Kind, Spec, Document]:
    """The one spec of a file (``file.yaml#N`` picks a document of several); raises SpecError."""
    documents = load_selected(path)
    if len(documents) > 1:
        raise SpecError(f"the file holds {len(documents)} specs; pick one as "
                        f"{path}#1 .. #{len(documents)}", source=str(path))
    kind, spec = parse_document(documents[0])
    return kind, spec, documents[0]


def _judge(document: Document, kind: Kind, spec: Spec, raw: dict[str, float],
           code: int, layout: FlatResults, raised: Sequence[str] = ()) -> Evaluation:
    """One spec's results from its solved values and status code."""
    if code:
        name, reason = layout.reasons[code]
        name = spec.field_as_written(name)
        written = FieldPath.parse(name).get(document.data)
        # A test of a quantity found from several fields: the field's value is not it.
        quoted = isinstance(written, (str, int, float)) and not isinstance(reason, DerivedTest)
        got = f", got {written}" if quoted else ""
        raise document.error(f"{reason}{got}", field=name)
    results: dict[str, float | None] = {}
    warnings: list[str] = [*spec.catalogue_notes(), *spec.warnings(), *raised]
    of_bins = {key for table in layout.tables if table.axis == "bin" for key in table.keys}
    # on a sparse axis a row of NaN is an element the design lacks (specs of 8 and 9
    # balls solved together pad the smaller one's); a NaN in a row it has is an error
    absent = {key for table in layout.tables if kind.along[table.axis].sparse
              for cells in table.cells
              if all(key is None or math.isnan(raw.get(key, math.nan)) for key in cells)
              for key in cells if key is not None}
    unbounded: dict[str, list[str]] = {}
    for key, value in raw.items():
        if math.isnan(value) and key in absent:
            results[key] = None
            continue
        if math.isnan(value):
            raise document.error(f"{key} cannot be computed for this design; please report it")
        if math.isinf(value):
            reason = "the bin is at rest" if key in of_bins else kind.unbounded_reason
            unbounded.setdefault(reason, []).append(key)
            results[key] = None
        else:
            results[key] = value
    warnings += [f"{_listed(keys)} {'is' if len(keys) == 1 else 'are'} unbounded (null in "
                 f"JSON): {reason}" for reason, keys in unbounded.items()]
    units = {key: layout.names[key][0] for key in results}
    margins = {key: value for key in kind.margins
               if (value := results.get(key)) is not None}
    name = spec.name or _default_name(document)
    warnings += spec.result_notes(results, layout.tables)
    judged = judge(kind.judged, kind.results, layout.with_values(results), margins)
    return Evaluation(document.source, kind.name, name, results, units, margins, warnings,
                      spec.row_names(), judged, spec.catalogue_sources(),
                      {key: layout.names[key][1] for key in results},
                      _present(layout.tables, absent, results))


def _present(tables: Sequence[ResultTable], absent: set[str],
             results: Mapping[str, float | None]) -> tuple[ResultTable, ...]:
    """The tables without the rows of elements this design lacks (every cell absent)."""
    def lacks(cells: tuple[str | None, ...]) -> bool:
        keys = [key for key in cells if key is not None]
        return bool(keys) and all(key in absent and results.get(key) is None for key in keys)

    kept = []
    for table in tables:
        rows = [i for i, cells in enumerate(table.cells) if not lacks(cells)]
        kept.append(table if len(rows) == len(table.cells) else table._replace(
            rows=tuple(table.rows[i] for i in rows),
            positions=tuple(table.positions[i] for i in rows),
            cells=tuple(table.cells[i] for i in rows)))
    return tuple(kept)


def _default_name(document: Document) -> str:
    stem = Path(document.path).stem
    return stem if document.source == document.path else f"{stem}#{document.index}"
