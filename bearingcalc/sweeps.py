"""Design sweeps: a spec solved over a line or a grid of one or two of its inputs.

All points are solved in one vectorised call (see :mod:`bearingcalc.variation`).
A point where the design is impossible is not an error: its results are NaN
and it carries the reason (the solver's status code).
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray
from pydantic import BaseModel

from bearingcalc.errors import BearingcalcError, OptionError
from bearingcalc.kinds import Kind
from bearingcalc.models.base import Spec, field_parser
from bearingcalc.models.field_path import NOT_INPUTS, FieldPathError, resolve_field
from bearingcalc.models.yaml_loader import Document
from bearingcalc.result_keys import FlatResults
from bearingcalc.variation import evaluate_with, invalid_at
from bearingcalc.wording import plural

MAX_POINTS = 4_000_000


class SweepError(BearingcalcError):
    """A sweep that cannot be run as asked: a bad ``--vary`` (its message says what,
    after the option's name)."""


@dataclass
class Axis:
    """One varied input: its dotted field name, values (SI) and unit."""

    name: str
    values: NDArray
    unit: str
    integer: bool = False
    #: START and STOP as the user wrote them ('50deg'), for messages
    written: tuple[str, str] | None = None


@dataclass
class Sweep:
    """The solved points of a sweep, flattened in row-major order of the axes."""

    kind: Kind
    source: str
    name: str
    axes: list[Axis]
    inputs: dict[str, NDArray]        # axis name -> value at each point
    results: FlatResults              # key -> value at each point, NaN where infeasible
    status: NDArray                   # 0 feasible, else a key of results.reasons
    limits: dict[str, float]          # result key -> symmetric limit value
    warnings: list[str] = field(default_factory=list)
    #: 'catalogue_source: ...' of each bearing taken from a catalogue
    sources: list[str] = field(default_factory=list)

    @property
    def units(self) -> dict[str, str]:
        return {key: self.results.names[key][0] for key in self.results}

    def reason(self, code: int) -> str:
        """The words for a status code: 'field: why'."""
        field, why = self.results.reasons[code]
        return f"{field}: {why}" if field else why

    @property
    def within_limits(self) -> NDArray:
        """Feasible points whose margins are all >= 0."""
        return self.kind.within_limits(self.results, self.status)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(axis.values) for axis in self.axes)


#: The name is any text without spaces, so that a misspelt one is explained by
#: :func:`bearingcalc.models.field_path.resolve_field` rather than refused as a whole.
_VARY = re.compile(r"^\s*(?P<name>[^\s=:]+)\s*=\s*(?P<start>[^:]+):(?P<stop>[^:]+):"
                   r"(?P<count>\s*[0-9]{1,12}\s*)$")


def parse_axis(text: str, spec: Spec) -> Axis:
    """An axis from ``NAME=START:STOP:N`` (START and STOP with units where the field has one)."""
    match = _VARY.match(text)
    if match is None:
        raise SweepError(f"{text!r}: write NAME=START:STOP:N, like "
                         "contact_angle=5deg:40deg:36")
    name, count = match["name"], int(match["count"])
    if count < 2:
        raise SweepError(f"{name}: N must be at least 2, got {count}")
    if count > MAX_POINTS:  # before any array of that size is built
        raise SweepError(f"{name}: N = {count} is more than the {MAX_POINTS} points "
                         "a sweep may have; use fewer")
    name, (kind_of_field, converter, unit) = _number_field(spec, name)
    try:
        start, stop = converter(match["start"].strip()), converter(match["stop"].strip())
    except ValueError as exc:
        raise SweepError(f"{name}: {exc}") from None
    written = (match["start"].strip(), match["stop"].strip())
    if kind_of_field == "integer":
        values = np.unique(np.round(np.linspace(start, stop, count)).astype(np.int64))
        if len(values) < count:
            raise SweepError(f"{name}: {name} is a whole number; {start}..{stop} holds "
                             f"only {len(values)} distinct values, ask for at most that many")
        return Axis(name, values, unit, integer=True, written=written)
    return Axis(name, np.linspace(start, stop, count), unit, written=written)


def _number_field(spec: Spec, path: str) -> tuple[str, tuple[str, Any, str]]:
    """The name (as :func:`resolve_field` writes it) and parser (see ``field_parser``)
    of the field ``path`` names, if it is a number the spec gives; else a SweepError
    that says what it is and what to vary instead."""
    try:
        found = resolve_field(spec, path)
    except FieldPathError as error:
        raise SweepError(f"{path}: {error}") from None
    name = found.name
    if found.is_list:
        count = "" if found.value is None else f" of {plural(len(found.value), 'item')}"
        example = _example_field(found.group, None)
        raise SweepError(f"{name}: {name} is a list{count}, not a number: vary a field "
                         f"of one item, like {name}.1.{example}")
    if found.group is not None:
        what = (f"an item of {found.parent}" if found.in_list else "a group of fields")
        inputs = [f for f in found.group.model_fields if f not in NOT_INPUTS]
        example = _example_field(found.group, found.value)
        raise SweepError(f"{name}: {name} is {what}, not a number: vary one of its "
                         f"fields, like {name}.{example}; its fields are {', '.join(inputs)}")
    parser = field_parser(found.info) if found.info is not None else None
    if parser is None:
        raise SweepError(f"{name}: {name} is not a number that can be swept")
    if found.left_out is not None and found.left_out != name:
        raise SweepError(f"{name}: the spec leaves {found.left_out} out (it is "
                         f"optional and not given); give {found.left_out} in the spec to "
                         f"sweep {name}")
    if found.value is None:
        raise SweepError(f"{name}: the spec leaves {name} out (it is solved, or "
                         "optional and not given); give it a value in the spec to sweep it")
    return name, parser


def _example_field(model: type[BaseModel] | None, value: BaseModel | None) -> str:
    """A field of ``model`` to name in an example: the first number the spec gives (of
    ``value``), else the first number, else the first field."""
    if model is None:
        return "..."
    inputs = {f: info for f, info in model.model_fields.items() if f not in NOT_INPUTS}
    numbers = [f for f, info in inputs.items() if field_parser(info) is not None]
    given = [f for f in numbers if value is not None and getattr(value, f) is not None]
    return next(iter(given or numbers or list(inputs) or ["..."]))


def check_axes(document: Document, axes: list[Axis]) -> None:
    """Validate the spec at every corner of the swept range, as ``solve`` would (see
    :func:`bearingcalc.variation.invalid_at`). Raises SweepError naming the axis and the
    value."""
    for corner in itertools.product(*((0, len(axis.values) - 1) for axis in axes)):
        written = {axis.name: _as_written(axis, axis.values[i])
                   for axis, i in zip(axes, corner, strict=True)}
        error = invalid_at(document, written)
        if error is not None:
            at = ", ".join(f"{axis.name} = {_bound_as_written(axis, i)}"
                           for axis, i in zip(axes, corner, strict=True))
            what = f"{error.field}: {error.message}" if error.field else error.message
            raise SweepError(f"the spec is invalid at {at}: {what}")


def _bound_as_written(axis: Axis, index: int) -> str:
    """The sweep's START (``index`` 0) or STOP as the user wrote it."""
    if axis.written is not None:
        return axis.written[0 if index == 0 else 1]
    return str(_as_written(axis, axis.values[index]))


def _as_written(axis: Axis, value: Any) -> Any:
    if axis.integer:
        return int(value)
    return f"{float(value)!r} {axis.unit}" if axis.unit != "1" else float(value)


def run_sweep(kind: Kind, spec: Spec, source: str, axes: list[Axis]) -> Sweep:
    """Solve every point of the line or grid spanned by ``axes`` in one call."""
    if not 1 <= len(axes) <= 2:
        raise SweepError("give it once for a line or twice for a grid")
    if len(axes) == 2 and axes[0].name == axes[1].name:
        raise SweepError(f"{axes[0].name} is given twice")
    points = int(np.prod([len(axis.values) for axis in axes]))
    if points > MAX_POINTS:
        raise SweepError(f"{points} points is more than {MAX_POINTS}; use fewer")
    grids = np.meshgrid(*(axis.values for axis in axes), indexing="ij")
    inputs = {axis.name: grid.ravel() for axis, grid in zip(axes, grids, strict=True)}
    results, status = evaluate_with(kind, spec, inputs)
    feasible = status == 0
    shape = (points,)
    solved = results.with_values({key: np.where(feasible, np.broadcast_to(value, shape), np.nan)
                                  for key, value in results.items()})
    limits = kind.limit_values(spec.solver_inputs())
    name = spec.name or source
    cited = [f"{key}: {value}" for key, value in spec.catalogue_sources().items()]
    return Sweep(kind, source, name, axes, inputs, solved,
                 np.broadcast_to(status, shape).copy(), limits,
                 spec.study_notes([axis.name for axis in axes]), cited)


def sweep_axes(kind: Kind, spec: Spec, document: Document, vary: list[str]) -> Sweep:
    """The sweep of a loaded spec over the axes written as ``--vary`` gives them; raises
    SweepError for a bad axis."""
    axes = [parse_axis(text, spec) for text in vary]
    check_axes(document, axes)
    return run_sweep(kind, spec, document.source, axes)


def sweep_spec(kind: Kind, spec: Spec, document: Document, vary: list[str]) -> Sweep:
    """:func:`sweep_axes`, a bad axis an :class:`OptionError` of ``--vary``."""
    try:
        return sweep_axes(kind, spec, document, vary)
    except SweepError as error:
        raise OptionError("--vary", str(error), source=document.source) from None


def shown_results(solved: Sweep, asked: list[str] | None) -> list[str]:
    """The results a table or chart shows: those asked for, else the kind's governing
    ones and every other limit the sweep crosses (a drive's gear safety where its lives
    hold), so that each edge of the range within limits is a curve that is shown; one the
    sweep has not is an :class:`OptionError` of ``--result``."""
    keys = asked or solved.kind.governing_of(solved.results)
    if not asked:
        for margin in solved.kind.margins:
            values = solved.results.get(margin)
            judged = solved.kind.judged.get(margin)
            quantity = judged.key(solved.results) if judged is not None else None
            shown = quantity if quantity is not None and quantity in solved.results \
                else margin
            if values is not None and bool(np.any(values < 0)) and not {margin, shown} & {
                    *keys}:
                keys.append(shown)
    unknown = [key for key in keys if key not in solved.results]
    if unknown:
        raise OptionError("--result", f"{unknown[0]!r} is not a result of this "
                          f"{solved.kind.name} spec; choose from {', '.join(solved.results)}",
                          source=solved.source)
    return keys
