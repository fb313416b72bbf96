"""Plain-number fields: counts of balls and teeth, ratios, numbers within a range and
reliabilities ('99 %' or 0.99)."""

from __future__ import annotations

import math
import re
from typing import Annotated, Any, Literal

from pydantic import BeforeValidator, WithJsonSchema

from bearingcalc.number_grammar import DECIMAL, UNSIGNED_DECIMAL
from bearingcalc.units import MAX_MAGNITUDE

#: Largest count of balls or teeth: far above any real part, and small enough that
#: every product a solver forms stays finite.
MAX_COUNT = 100_000


class _Count:
    """Validator of a whole-number field (teeth, balls) with a minimum.

    ``12.0`` counts as 12, as JSON Schema's ``integer`` type has it.
    """

    def __init__(self, minimum: int, what: str, maximum: int = MAX_COUNT) -> None:
        self.minimum = minimum
        self.what = what
        self.maximum = maximum

    def __call__(self, value: Any) -> int:
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError(f"must be a whole number of {self.what}, got {value!r}")
        if value < self.minimum:
            raise ValueError(f"must be at least {self.minimum}, got {value}")
        if value > self.maximum:
            shown = value if value < 10**12 else f"a number of {len(str(value))} digits"
            raise ValueError(f"must be at most {self.maximum}, got {shown}")
        return value


def _count(minimum: int, what: str, maximum: int = MAX_COUNT) -> Any:
    schema = {"type": "integer", "minimum": minimum, "maximum": maximum,
              "description": f"number of {what}"}
    return Annotated[int, BeforeValidator(_Count(minimum, what, maximum)),
                     WithJsonSchema(schema)]


def _plain_number(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"must be a plain number, like 0.01, got {value!r}")
    number = float(value) if not isinstance(value, int) or abs(value) < 10**300 else math.inf
    if not (math.isfinite(number) and 0 <= number <= MAX_MAGNITUDE):
        shown = f"{value!r}" if math.isfinite(number) else "a number out of range"
        raise ValueError(f"must be a finite number from 0 to {MAX_MAGNITUDE:g}, got {shown}")
    return number


BallCount = _count(1, "balls")
RollerCount = _count(1, "rollers")
#: ISO/TS 16281's slices of a roller: fewer than 10 cannot follow a profile, more than
#: 200 refine nothing a designer reads.
LaminaCount = _count(10, "laminae", 200)
ToothCount = _count(5, "teeth")
Ratio = Annotated[float, BeforeValidator(_plain_number),
                  WithJsonSchema({"type": "number", "minimum": 0})]


def shown(value: int) -> str:
    """A whole number for a message: itself, or how many digits it has when it is long."""
    return str(value) if abs(value) < 10**12 else f"a number of {len(str(abs(value)))} digits"


class _RangedNumber:
    """Validator of a plain number within [low, high] (or (low, high) when ``exclusive``),
    refused with a message that names the range and what the number is."""

    def __init__(self, low: float, high: float, what: str, example: str, whole: bool,
                 exclusive: bool) -> None:
        self.low, self.high, self.what, self.example = low, high, what, example
        self.whole, self.exclusive = whole, exclusive

    def __call__(self, value: Any) -> float:
        low, high, what = self.low, self.high, self.what
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"must be a number, like {self.example}, got {value!r}")
        if isinstance(value, int) and abs(value) > MAX_MAGNITUDE:
            raise ValueError(f"must be from {low:g} to {high:g} ({what}), got {shown(value)}")
        if self.whole and not float(value).is_integer():
            raise ValueError(f"must be a whole number ({what}), got {value!r}")
        if self.exclusive and not low < value < high:
            raise ValueError(f"must be between {low:g} and {high:g}, exclusive ({what}), "
                             f"like {self.example}, got {value!r}")
        if not low <= value <= high:
            raise ValueError(f"must be from {low:g} to {high:g} ({what}), got {value!r}")
        return float(value)


def ranged_number(low: float, high: float, what: str, example: str, *,
                  whole: bool = False, exclusive: bool = False) -> Any:
    """A plain-number field within [low, high] (or (low, high) when ``exclusive``)."""
    bounds = ({"exclusiveMinimum": low, "exclusiveMaximum": high} if exclusive
              else {"minimum": low, "maximum": high})
    return Annotated[float, BeforeValidator(_RangedNumber(low, high, what, example, whole,
                                                          exclusive)),
                     WithJsonSchema({"type": "integer" if whole else "number", **bounds})]


PoissonRatio = ranged_number(-1.0, 0.5, "Poisson's ratio", "0.3", exclusive=True)


class _Percentage:
    """Validator of a percentage: '99 %' or the fraction 0.99, from ``low`` to ``high``
    (a reliability, a share of the time).

    A bare number above 1 is refused (it is a percentage written without its sign).
    ``what`` names the quantity and ``source`` the rule the range comes from, for the
    message; ``example`` is written as a percentage.
    """

    def __init__(self, low: float, high: float, source: str, what: str = "reliability",
                 example: str = "99") -> None:
        self.low, self.high, self.source = low, high, source
        self.what, self.example = what, example

    def __call__(self, value: Any) -> float:
        written = f"write a {self.what} as '{self.example} %' or {float(self.example) / 100:g}"
        if isinstance(value, str):
            match = re.fullmatch(rf"\s*({DECIMAL})\s*%\s*", value, re.ASCII)
            if match is None:
                raise ValueError(f"{written}, got {value!r}")
            fraction = float(match[1]) / 100.0
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            if isinstance(value, int) and value > 100:
                raise ValueError(f"a bare number is a fraction, at most 1, got {shown(value)}")
            if value > 1:
                raise ValueError(f"a bare number is a fraction, at most 1; for percent write "
                                 f"'{value:g} %'")
            fraction = float(value)
        else:
            raise ValueError(f"{written}, got {value!r}")
        if not self.low <= fraction <= self.high:
            raise ValueError(f"must be from {100 * self.low:g} % to {100 * self.high:g} % "
                             f"({self.source}), got {100 * fraction:g} %")
        return fraction


def percentage(low: float, high: float, source: str, what: str = "reliability",
               example: str = "99") -> Any:
    """A percentage field: '99 %' or the fraction 0.99, from ``low`` to ``high``."""
    validator = _Percentage(low, high, source, what, example)
    return Annotated[float, BeforeValidator(validator), WithJsonSchema({
        "anyOf": [{"type": "string", "pattern": rf"^\s*{UNSIGNED_DECIMAL}\s*%\s*$"},
                  {"type": "number", "minimum": low, "maximum": high}],
        "description": f"{what}, '{example} %' or {float(example) / 100:g}, from "
                       f"{100 * low:g} % to {100 * high:g} %"})]


def reliability(low: float, high: float, source: str) -> Any:
    """A reliability field: '99 %' or the fraction 0.99, from ``low`` to ``high``."""
    return percentage(low, high, source)


def whole_choice(*choices: int) -> Any:
    """One of a few whole numbers (a grade, a number of rows). YAML's true and false are
    refused: Python counts them as 1 and 0, which would pass for a choice."""
    def not_a_truth_value(value: Any) -> Any:
        if isinstance(value, bool):
            raise ValueError(f"must be one of {', '.join(map(str, choices))}, got "
                             f"{str(value).lower()}")
        return value

    return Annotated[Literal[choices], BeforeValidator(not_a_truth_value)]  # type: ignore[valid-type]
