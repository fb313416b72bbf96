"""Solving a spec with some of its inputs replaced by arrays of values.

Tolerance studies and sweeps vary spec fields (``contact_angle``,
``gear_a.pitch_radius``) as the engineer wrote them; this module puts arrays in
place of those fields and lets the spec model derive the solver's inputs as it
does for single values, so one vectorised solver call covers every point.
"""

from __future__ import annotations

import copy
import dataclasses
from collections.abc import Collection, Iterator, Mapping
from typing import Any

from numpy.typing import ArrayLike, NDArray
from pydantic import BaseModel

from bearingcalc.errors import SpecError
from bearingcalc.kinds import Kind
from bearingcalc.models.base import Spec
from bearingcalc.models.field_path import FieldPath, replaced, resolve_field
from bearingcalc.models.quantities import Measured, Tolerance
from bearingcalc.models.yaml_loader import Document
from bearingcalc.result_keys import FlatResults


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
    return replaced(spec, [(FieldPath.parse(path), value) for path, value in values.items()])


def evaluate_with(kind: Kind, spec: Spec, values: Mapping[str, ArrayLike],
                  wanted: Collection[str] | None = None) -> tuple[FlatResults, NDArray]:
    """Results and status codes of ``spec`` with ``values`` in place of its fields."""
    varied = with_values(spec, values) if values else spec
    return kind.evaluate(varied.solver_inputs(), wanted)


def invalid_at(document: Document, written: Mapping[str, Any]) -> SpecError | None:
    """What the spec model says of ``document`` with the dotted fields in ``written``
    replaced by those values as a spec would write them (``'-0.0087 rad'``, ``2``);
    None where it takes them.

    Studies put arrays in place of fields and skip the spec model's checks; each
    field's checks are ranges (signs, bounds, rules between fields), so a study checks
    the ends of what it varies here, as ``solve`` would check one design.
    """
    from bearingcalc.evaluation import parse_document

    data = copy.deepcopy(document.data)
    for name, value in written.items():
        FieldPath.parse(name).set_in(data, value)
    try:
        parse_document(dataclasses.replace(document, data=data))
    except SpecError as error:
        return error
    return None


def _fields(spec: BaseModel) -> Iterator[tuple[str, Any]]:
    for name in type(spec).model_fields:
        yield name, getattr(spec, name)

