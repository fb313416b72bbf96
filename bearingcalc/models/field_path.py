"""Dotted field names: ``pinion_bearings.2.position`` names the field ``position`` of the
second item of the list ``pinion_bearings``. One way to parse them, to find what they
name in a spec's data or model, and to write a value there, for errors, sweeps,
tolerances and variations alike.

List items are numbered from 1 where people read them (messages, ``--vary``, JSON keys
of tolerance inputs) and from 0 in key paths, as Python indexes lists.
"""

from __future__ import annotations

import re
import typing
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel
from pydantic.fields import FieldInfo

from bearingcalc.models.base import nested_model
from bearingcalc.wording import plural

#: Fields of a spec that are not inputs: what it is and what it is called.
NOT_INPUTS = ("kind", "name")


def list_index(part: str) -> int | None:
    """The 0-based list index that a part of a dotted field name names (``"2"`` -> 1),
    or None when the part is not a whole number in ASCII digits. Items count from 1,
    so ``"0"`` gives -1, which is no item."""
    return int(part) - 1 if part.isascii() and part.isdigit() else None


@dataclass(frozen=True)
class FieldPath:
    """A field of a spec by its key path: names of fields and 0-based list indices."""

    parts: tuple[str | int, ...]

    @classmethod
    def parse(cls, dotted: str) -> FieldPath:
        """``"pinion_bearings.2.position"`` -> ("pinion_bearings", 1, "position")."""
        return cls(tuple(part if (index := list_index(part)) is None else index
                         for part in dotted.split(".")))

    def __str__(self) -> str:
        return ".".join(str(part + 1) if isinstance(part, int) else part
                        for part in self.parts)

    def get(self, data: Any) -> Any:
        """The value at this path in document data (mappings and lists) or in a model;
        None where any part of it is missing."""
        for part in self.parts:
            if isinstance(part, int):
                if not isinstance(data, (list, tuple)) or not 0 <= part < len(data):
                    return None
                data = data[part]
            elif isinstance(data, dict):
                data = data.get(part)
            elif isinstance(data, BaseModel) and part in type(data).model_fields:
                data = getattr(data, part)
            else:
                return None
        return data

    def set_in(self, data: Any, value: Any) -> None:
        """Write ``value`` at this path of document data, making the mappings on the way
        (the lists must be there: an item is never made up)."""
        *parents, last = self.parts
        for key in parents:
            data = data[key] if isinstance(key, int) else data.setdefault(key, {})
        data[last] = value


def replaced(spec: Any, values: Iterable[tuple[FieldPath, Any]]) -> Any:
    """A copy of a model (or list of models) with the values at the given paths replaced,
    unvalidated: the model derives its solver inputs from arrays as from numbers."""
    nested: dict[str | int, list[tuple[FieldPath, Any]]] = {}
    direct: dict[str | int, Any] = {}
    for path, value in values:
        head, *rest = path.parts
        if rest:
            nested.setdefault(head, []).append((FieldPath(tuple(rest)), value))
        else:
            direct[head] = value
    if isinstance(spec, (list, tuple)):
        items = list(spec)
        for index, inner in nested.items():
            items[index] = replaced(items[index], inner)  # type: ignore[index]
        for index, value in direct.items():
            items[index] = value  # type: ignore[index]
        return type(spec)(items)
    for name, inner in nested.items():
        direct[name] = replaced(getattr(spec, name), inner)  # type: ignore[arg-type]
    return spec.model_copy(update=direct)


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
        if value is not None and not isinstance(value, BaseModel):
            # a union's plain form (a material by name) holds no fields to follow
            raise FieldPathError(f"{here} is {value!r} in the spec, not a group of fields: "
                                 f"write it as a mapping ({', '.join(inputs)}) to name "
                                 f"{here}.{part}")
        info = group.model_fields[part]
        value = None if value is None else getattr(value, part)
        names.append(part)
        if value is None and left_out is None:
            left_out = ".".join(names)
        group, is_list, in_list = nested_model(info), is_list_field(info), False
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


def is_list_field(info: FieldInfo) -> bool:
    """Whether a model field holds a list (of nested models)."""
    annotation = info.annotation
    return typing.get_origin(annotation) in (list, tuple) or any(
        typing.get_origin(arg) in (list, tuple) for arg in typing.get_args(annotation))


