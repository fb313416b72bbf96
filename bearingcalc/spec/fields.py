"""Field types shared by every spec model: quantities with units, counts, limits.

A quantity field is written in YAML as a string with a unit (``"12.7 mm"``) and
arrives in the model as an SI float; the conversion happens here and nowhere
else.
"""

from __future__ import annotations

import math
from typing import Annotated, Any

from pydantic import BaseModel, BeforeValidator, ConfigDict, WithJsonSchema

from bearingcalc.units import ANGLE, ANGULAR_ACCEL, ANGULAR_SPEED, LENGTH, Dimension, parse_quantity

QUANTITY_PATTERN = r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*[^\s\d.+-].*$"


class SpecModel(BaseModel):
    """Base of spec models: unknown keys and non-finite numbers are refused."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=True,
                              validate_default=False)


class _Quantity:
    """Before-validator turning a quantity string into SI, with a sign check."""

    def __init__(self, dimension: Dimension, sign: str | None) -> None:
        self.dimension = dimension
        self.sign = sign

    def __call__(self, value: Any) -> float:
        si = parse_quantity(value, self.dimension)
        if self.sign == "positive" and not si > 0:
            raise ValueError(f"must be greater than zero, got '{value}'")
        if self.sign == "non-negative" and not si >= 0:
            raise ValueError(f"must not be negative, got '{value}'")
        return si


def quantity(dimension: Dimension, sign: str | None = None) -> Any:
    """Annotated float type of a quantity field of ``dimension``.

    ``sign`` is None (any finite value), "positive" or "non-negative".
    """
    words = {"positive": "positive ", "non-negative": "non-negative ", None: ""}[sign]
    schema = {
        "type": "string",
        "description": f"{words}{dimension.name} with a unit, e.g. '{dimension.example}'",
        "examples": [dimension.example],
        # A number, then a unit: refuses bare numbers and unit-less strings.
        "pattern": QUANTITY_PATTERN,
        "x-dimension": dimension.name,
        "x-si-unit": dimension.si_unit,
    }
    return Annotated[float, BeforeValidator(_Quantity(dimension, sign)), WithJsonSchema(schema)]


def _count(minimum: int, what: str) -> Any:
    def check(value: Any) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError(f"must be a whole number of {what}, got {value!r}")
        if value < minimum:
            raise ValueError(f"must be at least {minimum}, got {value}")
        return value

    schema = {"type": "integer", "minimum": minimum, "description": f"number of {what}"}
    return Annotated[int, BeforeValidator(check), WithJsonSchema(schema)]


def _plain_number(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"must be a plain number, like 0.01, got {value!r}")
    if not math.isfinite(value) or value < 0:
        raise ValueError(f"must be a finite number >= 0, got {value!r}")
    return float(value)


Length = quantity(LENGTH)
PositiveLength = quantity(LENGTH, "positive")
Angle = quantity(ANGLE)
AngularSpeed = quantity(ANGULAR_SPEED)
AngularAccel = quantity(ANGULAR_ACCEL)
BallCount = _count(1, "balls")
ToothCount = _count(5, "teeth")
Ratio = Annotated[float, BeforeValidator(_plain_number),
                  WithJsonSchema({"type": "number", "minimum": 0})]
