"""Solving a spec with some of its inputs replaced by arrays of values.

Tolerance studies and sweeps vary spec fields (``contact_angle``,
``gear_a.pitch_radius``) as the engineer wrote them; this module puts arrays in
place of those fields and lets the spec model derive the solver's inputs as it
does for single values, so one vectorised solver call covers every point.
"""

from __future__ import annotations

from collections.abc import Collection, Iterator, Mapping
from typing import Any

from numpy.typing import ArrayLike, NDArray
from pydantic import BaseModel

from bearingcalc.kinds import Kind
from bearingcalc.spec.fields import Measured, SpecModel, Tolerance


def toleranced_fields(spec: BaseModel, prefix: str = "") -> dict[str, Tolerance]:
    """Dotted field name -> tolerance, for every field of ``spec`` that carries one."""
    found: dict[str, Tolerance] = {}
    for name, value in _fields(spec):
        path = f"{prefix}{name}"
        if isinstance(value, Measured) and value.tolerance is not None:
            found[path] = value.tolerance
        elif isinstance(value, BaseModel):
            found.update(toleranced_fields(value, f"{path}."))
    return found


def field_value(spec: BaseModel, path: str) -> Any:
    """The value of the dotted field ``path`` of ``spec``."""
    value: Any = spec
    for part in path.split("."):
        value = getattr(value, part)
    return value


def with_values(spec: SpecModel, values: Mapping[str, ArrayLike]) -> SpecModel:
    """A copy of ``spec`` with the dotted fields in ``values`` replaced (unvalidated)."""
    nested: dict[str, dict[str, ArrayLike]] = {}
    direct: dict[str, ArrayLike] = {}
    for path, value in values.items():
        head, _, rest = path.partition(".")
        if rest:
            nested.setdefault(head, {})[rest] = value
        else:
            direct[head] = value
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

