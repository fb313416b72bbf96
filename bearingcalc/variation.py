"""Solving a spec with some of its inputs replaced by arrays of values.

Tolerance studies and sweeps vary spec fields (``contact_angle``,
``gear_a.pitch_radius``) as the engineer wrote them; this module puts arrays in
place of those fields and lets the spec model derive the solver's inputs as it
does for single values, so one vectorised solver call covers every point.
"""

from __future__ import annotations

import re
import typing
from collections.abc import Collection, Iterator, Mapping
from dataclasses import dataclass
from typing import Any

from numpy.typing import ArrayLike, NDArray
from pydantic import BaseModel
from pydantic.fields import FieldInfo

from bearingcalc.kinds import Kind
from bearingcalc.models.base import SpecModel, nested_model
from bearingcalc.models.quantities import Measured, Tolerance
from bearingcalc.models.yaml_loader import list_index
from bearingcalc.wording import plural

#: Fields of a spec that are not inputs: what it is and what it is called.
NOT_INPUTS = ("kind", "name")


class FieldPathError(ValueError):
    """A dotted field name that leads to no input of the spec; the message says what is
    there instead."""


@dataclass(frozen=True)
class FieldAt:
    """What a dotted field name names in a spec, as :func:`resolve_field` found it."""

    name: str                       # written as the spec's messages write it: list items
                                    # 1-based, without leading zeros
    info: FieldInfo | None          # the model field holding the value (for a list item,
                                    # the list's); None for the spec itself
    value: Any                      # the value in the spec; None where the spec leaves it out
    group: type[BaseModel] | None   # the model of a group of fields or of a list's items
    is_list: bool                   # the name ends at a list
    in_list: bool                   # the name ends at an item of a list
    left_out: str | None            # the shortest part of the name the spec leaves out

    @property
    def parent(self) -> str:
        """The name of what holds this field ("pinion_bearings" for an item of it)."""
        return self.name.rpartition(".")[0]


def resolve_field(spec: BaseModel, path: str) -> FieldAt:
    """Follow the dotted field name ``path`` through ``spec`` (list items 1-based).

    Each part is checked against the spec's models, and each item number against
    the list the spec has, so a name that leads nowhere is refused, saying what is
    there. A name through a group or list the spec leaves out is followed through the
    models and resolves with value None and ``left_out`` set.

    Raises
    ------
    FieldPathError : an unknown field, an item number that is not one of the list's,
        a list named without an item number, or a name that goes into a single value.
    """
    value: Any = spec
    info: FieldInfo | None = None
    group: type[BaseModel] | None = type(spec)
    is_list = in_list = False
    left_out: str | None = None
    names: list[str] = []
    parts = path.split(".")
    for i, part in enumerate(parts):
        here = ".".join(names) or "the spec"
        rest = parts[i + 1:]
        if is_list:
            index = _item_index(part, value, here, group, rest)
            value = None if value is None else value[index]
            names.append(str(index + 1))
            is_list, in_list = False, True
            continue
        if group is None:
            raise FieldPathError(f"{here} is a single value, with no fields inside; name "
                                 f"{here} itself")
        inputs = [field for field in group.model_fields if field not in NOT_INPUTS]
        if part == "":
            where = f"after {here}; its inputs" if names else "before the first dot; inputs"
            raise FieldPathError(f"a name is missing {where}: {', '.join(inputs)}")
        if part not in inputs:
            raise FieldPathError(f"{here} has no input '{part}'; inputs: {', '.join(inputs)}")
        info = group.model_fields[part]
        value = None if value is None else getattr(value, part)
        names.append(part)
        if value is None and left_out is None:
            left_out = ".".join(names)
        group, is_list, in_list = nested_model(info), _is_list(info), False
    return FieldAt(".".join(names), info, value, group, is_list, in_list, left_out)


def _item_index(part: str, items: Any, here: str, item_model: type[BaseModel] | None,
                rest: list[str]) -> int:
    """The 0-based index of the item ``part`` of the list ``here`` (None when the spec
    leaves the list out), or a FieldPathError that says how items are numbered."""
    count = None if items is None else len(items)
    index = list_index(part)
    if index is not None and index >= 0 and (count is None or index < count):
        return index
    if count == 0:
        raise FieldPathError(f"{here} is an empty list: it has no item {part}")
    numbered = "from 1" if count is None else f"from 1 to {count}" if count > 1 else "1"
    a_list = "a list" if count is None else f"a list of {plural(count, 'item')}"
    if index is not None or re.fullmatch(r"[-+][0-9]+", part, re.ASCII):
        raise FieldPathError(f"{here} is {a_list}, numbered {numbered}: there is no item "
                             f"{part}; name one like {here}.1{''.join('.' + p for p in rest)}")
    # "pinion_bearings.position": the item number left out before one of its fields
    fields = item_model.model_fields if item_model is not None else {}
    example = ".".join([here, "1", *([part] if part in fields else []), *rest]).rstrip(".")
    raise FieldPathError(f"{here} is {a_list}; name an item by its number, {numbered}, like "
                         f"{example}")


def _is_list(info: FieldInfo) -> bool:
    """Whether a model field holds a list (of nested models)."""
    annotation = info.annotation
    return typing.get_origin(annotation) in (list, tuple) or any(
        typing.get_origin(arg) in (list, tuple) for arg in typing.get_args(annotation))


def toleranced_fields(spec: BaseModel, prefix: str = "") -> dict[str, Tolerance]:
    """Dotted field name -> tolerance, for every field of ``spec`` that carries one
    (items of list fields are named by their 1-based index: ``bearings.1.position``)."""
    found: dict[str, Tolerance] = {}
    for name, value in _fields(spec):
        path = f"{prefix}{name}"
        items = enumerate(value, 1) if isinstance(value, (list, tuple)) else [(None, value)]
        for index, item in items:
            where = path if index is None else f"{path}.{index}"
            if isinstance(item, Measured) and item.tolerance is not None:
                found[where] = item.tolerance
            elif isinstance(item, BaseModel):
                found.update(toleranced_fields(item, f"{where}."))
    return found


def field_value(spec: BaseModel, path: str) -> Any:
    """The value of the dotted field ``path`` of ``spec`` (list items 1-based), None
    where the spec leaves it out. Raises FieldPathError for a name that leads nowhere."""
    return resolve_field(spec, path).value


def with_values(spec: Any, values: Mapping[str, ArrayLike]) -> Any:
    """A copy of ``spec`` with the dotted fields in ``values`` replaced (unvalidated)."""
    nested: dict[str, dict[str, ArrayLike]] = {}
    direct: dict[str, ArrayLike] = {}
    for path, value in values.items():
        head, _, rest = path.partition(".")
        if rest:
            nested.setdefault(head, {})[rest] = value
        else:
            direct[head] = value
    if isinstance(spec, (list, tuple)):
        items = list(spec)
        for head, inner in nested.items():
            items[int(head) - 1] = with_values(items[int(head) - 1], inner)
        for head, value in direct.items():
            items[int(head) - 1] = value
        return type(spec)(items)
    for head, inner in nested.items():
        direct[head] = with_values(getattr(spec, head), inner)
    return spec.model_copy(update=direct)


def evaluate_with(kind: Kind, spec: SpecModel, values: Mapping[str, ArrayLike],
                  wanted: Collection[str] | None = None) -> tuple[dict[str, NDArray], NDArray]:
    """Results and status codes of ``spec`` with ``values`` in place of its fields."""
    varied = with_values(spec, values) if values else spec
    return kind.evaluate(varied.solver_inputs(), wanted)  # type: ignore[attr-defined]


def _fields(spec: BaseModel) -> Iterator[tuple[str, Any]]:
    for name in type(spec).model_fields:
        yield name, getattr(spec, name)

