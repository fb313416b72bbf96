"""The base of every spec model, and what the commands ask of a model's fields."""

from __future__ import annotations

import functools
import math
import typing
from collections.abc import Collection, Mapping, Sequence
from typing import Any, ClassVar

from pydantic import (
    BaseModel,
    ConfigDict,
    PrivateAttr,
    Tag,
    ValidationError,
    ValidationInfo,
    model_validator,
)
from pydantic.fields import FieldInfo

from bearingcalc.models.plain_numbers import _Count, _Percentage, _plain_number, _RangedNumber
from bearingcalc.models.quantities import _Quantity
from bearingcalc.models.rules import problems_of
from bearingcalc.models.yaml_schema import plain_scalar
from bearingcalc.units import Dimension, parse_quantity

if typing.TYPE_CHECKING:  # the results' layout only: made above the models
    from bearingcalc.result_keys import ResultTable


class SpecModel(BaseModel):
    """Base of spec models and of the groups of fields they hold: unknown keys and
    non-finite numbers are refused."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=True,
                              validate_default=False)


class Spec(SpecModel):
    """A whole spec of one kind: what every command asks of it.

    Once its fields are valid, a spec checks its cross-field rules and those of every
    model it holds (:mod:`bearingcalc.models.rules`); it raises the first problem with
    the others in its ``more``. Validating with ``context={"rules": False}`` skips them.
    Each kind's model declares the fields ``kind`` and ``name`` itself, where they read
    best in its schema.
    """

    if typing.TYPE_CHECKING:
        kind: str
        name: str | None

    #: Where the spec's bearings may take a catalogue's row by designation: '' for the
    #: spec itself, a list field's name for each of its items.
    CATALOGUE_PLACES: ClassVar[tuple[str, ...]] = ()
    #: Result-style keys naming each catalogue row the spec took (``catalogue_source``),
    #: and what the reader should know of them; set as the spec is read.
    _catalogue_sources: dict[str, str] = PrivateAttr(default_factory=dict)
    _catalogue_notes: list[str] = PrivateAttr(default_factory=list)

    def catalogue_sources(self) -> dict[str, str]:
        return dict(self._catalogue_sources)

    def catalogue_notes(self) -> list[str]:
        """What the reader should know of the catalogue rows taken (a value of the spec's
        that overrides the catalogue's, bearings ISO's table does not hold)."""
        return list(self._catalogue_notes)

    @model_validator(mode="after")
    def _cross_field_rules(self, info: ValidationInfo) -> Spec:
        if (info.context or {}).get("rules") is False:
            return self
        problems = problems_of(self)
        if problems:
            problems[0].more = problems[1:]
            raise problems[0]
        return self

    def solver_inputs(self) -> Mapping[str, Any]:
        """The SI inputs of the kind's solver (arrays where a study varies a field): the
        typed mapping its ``Solver.inputs`` declares."""
        raise NotImplementedError(f"{type(self).__name__} gives no solver inputs")

    def field_as_written(self, field: str) -> str:
        """The spec's own name for a solver field a status names (a spec that gives the
        ball's radius is told about ``ball_radius``, not ``ball_diameter``)."""
        return field

    def warnings(self) -> list[str]:
        """What the reader should know about how the results were found."""
        return []

    def row_names(self) -> dict[str, str]:
        """Names for the rows of the kind's tables of results (a duty cycle's bins)."""
        return {}

    def result_notes(self, results: Mapping[str, float | None],
                     tables: Sequence[ResultTable] = ()) -> list[str]:
        """What the reader should know that only the results tell (``tables``: the
        results along axes, a duty cycle's bins)."""
        return []

    def study_notes(self, varied: Collection[str]) -> list[str]:
        """What the reader of a sweep or study that varies the dotted fields ``varied``
        should know (inputs typed for one design that the others keep)."""
        return []


#: What marks a tagged union's branch (``roller_profile``'s named or crowned form) in
#: pydantic's error locations: a branch is not a key of the spec, so errors leave it out.
BRANCH_MARK = "~"


def branch(name: str) -> Tag:
    """The tag of a union's branch ``name``, which error locations leave out."""
    return Tag(BRANCH_MARK + name)


def spec_errors(exc: ValidationError) -> list[Any]:
    """pydantic's errors of a spec, each located by the spec's keys alone (no branch of
    a tagged union)."""
    return [{**error, "loc": tuple(part for part in error["loc"]
                                   if not (isinstance(part, str)
                                           and part.startswith(BRANCH_MARK)))}
            for error in exc.errors(include_url=False)]


def nested_model(info: FieldInfo) -> type[BaseModel] | None:
    """The spec model a field holds (``gear_a`` -> Gear), or None for a plain value."""
    return _model_in(info.annotation)


def _model_in(annotation: Any) -> type[BaseModel] | None:
    """The first pydantic model in a type annotation (``Gear``, ``list[Bearing] | None``)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in typing.get_args(annotation):
        found = _model_in(arg)
        if found is not None:
            return found
    return None


def field_parser(info: FieldInfo) -> tuple[str, Any, str] | None:
    """How to read a value of a spec field from text, for sweeps.

    Returns ("quantity", text -> SI float, SI unit), ("integer", text -> int, "1") (a
    count, or a choice of whole numbers), ("number", text -> float, "1"), or None for
    fields that are not numbers.
    """
    metadata = list(info.metadata)
    for arg in typing.get_args(info.annotation):
        metadata.extend(typing.get_args(arg)[1:])
    for item in metadata:
        func = getattr(item, "func", None)
        if isinstance(func, _Quantity):
            return ("quantity", functools.partial(_parse_as, dimension=func.dimension),
                    func.dimension.si_unit)
        if isinstance(func, _Count):
            return "integer", _whole_number, "1"
        if func is _plain_number or isinstance(func, (_Percentage, _RangedNumber)):
            # Read as the spec reads it: '90 %' is a reliability of 0.9, '250HB' a
            # hardness (a reader of its own, where a bound may leave its word out).
            return "number", getattr(func, "read", None) or functools.partial(
                _validated, validator=func), "1"
    if _whole_choices(info.annotation):  # a grade, a number of rows: validated per point
        return "integer", _whole_number, "1"
    return None


def _validated(text: str, validator: Any) -> float:
    """A bound of a sweep read as the spec reads the field's value: the text as YAML
    reads a plain value, a number as it is (the spec's rules judge it at each end of the
    range), a text such as '90 %' by the field's own validator."""

    value = plain_scalar(text)
    if not isinstance(value, (int, float, str)) or isinstance(value, bool):
        raise ValueError(f"'{text}' is not a number")
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"'{text}' is not a finite number")
    if not isinstance(value, str):
        return float(value)
    number = validator(value)
    if not math.isfinite(number):
        raise ValueError(f"'{text}' is not a finite number")
    return float(number)


def _whole_choices(annotation: Any) -> bool:
    """Whether the annotation is a choice of whole numbers (``Literal[1, 2, 3]``, maybe
    optional)."""
    for arg in (annotation, *typing.get_args(annotation)):
        if typing.get_origin(arg) is typing.Literal:
            choices = typing.get_args(arg)
            return all(isinstance(c, int) and not isinstance(c, bool) for c in choices)
    return False


def _parse_as(text: str, dimension: Dimension) -> float:
    return parse_quantity(text, dimension)


def _whole_number(text: str) -> int:
    """A count or a choice of whole numbers as YAML reads it (``12``, or ``12.0``, which a
    spec's count takes too)."""

    value = plain_scalar(text)
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError(f"'{text}' is not a whole number")
    return value


