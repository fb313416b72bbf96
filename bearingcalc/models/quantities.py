"""Quantity fields: a number with a unit (``"12.7 mm"``), optionally with a tolerance
(``"12.7 mm ± 0.005 mm"``), read into an SI float; the conversion happens here and
nowhere else. Magnitudes no machine element has are refused with a hint.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Annotated, Any

from pydantic import PlainValidator, WithJsonSchema

from bearingcalc.number_grammar import NUMBER
from bearingcalc.units import (
    ANGLE,
    ANGULAR_ACCEL,
    ANGULAR_SPEED,
    DENSITY,
    DIMENSIONLESS,
    FORCE,
    KINEMATIC_VISCOSITY,
    LENGTH,
    POWER,
    STIFFNESS,
    STRESS,
    TEMPERATURE,
    THERMAL_EXPANSION,
    TIME,
    TORQUE,
    Dimension,
    parse_quantity,
)

#: The JSON Schema's form of a quantity: an ASCII number, then a unit or a ± band
#: ("12.7 mm", "12.7 mm ± 0.005 mm", "12.7 +/- 0.005 mm"). Units themselves are
#: checked by ``bearingcalc check``.
QUANTITY_PATTERN = (rf"^\s*{NUMBER}\s*"
                    r"([A-Za-z_°µμ%Ω]|\s1\s*/|(±|\+/-|\+-)\s*[0-9.]).*$")



DISTRIBUTIONS = ("normal", "uniform", "triangular")
#: A normal tolerance's band is ±sigma_level·σ. Below 1 the distribution is wider than
#: its own band (a band of ±5 µm read as σ = 500 µm is a typo, not a process).
MIN_SIGMA_LEVEL, MAX_SIGMA_LEVEL = 1.0, 10.0


def _unit_of(written: Any) -> str:
    """The unit of a quantity as written ('80 degC' -> 'degC'); '' for a bare number."""
    match = re.match(rf"\s*{NUMBER}\s*(.*?)\s*$", written) if isinstance(written, str) else None
    return match.group(1) if match else ""


@dataclass(frozen=True)
class Tolerance:
    """A manufacturing tolerance on one input, in SI units.

    The band is [low, high] = [nominal − minus, nominal + plus]. ``uniform``
    covers the band; ``triangular`` has its mode at the band centre and the band
    as support; ``normal`` has its mean at the band centre and
    σ = (half-width of the band) / ``sigma_level``, not truncated.
    """

    nominal: float
    low: float
    high: float
    distribution: str = "normal"
    sigma_level: float = 3.0
    unit: str = ""          # SI unit of the values
    written_unit: str = ""  # the nominal's unit as the spec writes it ("degC")

    @property
    def center(self) -> float:
        return 0.5 * (self.low + self.high)

    @property
    def half_width(self) -> float:
        return 0.5 * (self.high - self.low)

    @property
    def std(self) -> float:
        """Standard deviation of the distribution. [SI unit of the input]"""
        width = self.high - self.low
        if self.distribution == "uniform":
            return width / math.sqrt(12.0)
        if self.distribution == "triangular":
            return width / math.sqrt(24.0)
        return self.half_width / self.sigma_level


class Measured(float):
    """A quantity's nominal SI value that remembers its tolerance.

    It is a float, so solving and checking use the nominal value unchanged;
    tolerance studies read ``tolerance``.
    """

    tolerance: Tolerance | None

    def __new__(cls, value: float, tolerance: Tolerance | None = None) -> Measured:
        obj = super().__new__(cls, value)
        obj.tolerance = tolerance
        return obj

    def __reduce__(self) -> tuple[Any, ...]:
        return (Measured, (float(self), self.tolerance))


_PLUS_MINUS = re.compile(r"\s*(?:±|\+/-|\+-)\s*")
_MAPPING_KEYS = {"nominal", "tolerance", "plus", "minus", "distribution", "sigma_level"}


@dataclass(frozen=True)
class Plausible:
    """The magnitudes a quantity field takes in real machines. Far outside them a unit
    slip (MPa typed for GPa, m for mm) is likelier than a design, so the value is
    refused with the unit that would bring it in range."""

    low: float                 # smallest magnitude other than zero [SI]
    high: float                # largest magnitude [SI]
    shown: str                 # the range in engineering units, for the message
    suggest: tuple[str, ...]   # units to try on the written number, in order

    def check(self, si: float, written: Any, dimension: Dimension) -> None:
        if si == 0 or self.low <= abs(si) <= self.high:
            return
        text = str(written).strip()
        message = f"{text} is outside the range of real machine elements ({self.shown})"
        match = _NUMBER_AND_UNIT.match(text)
        for unit in self.suggest if match else ():
            if unit == match["unit"]:
                continue
            guess = f"{match['number']} {unit}"
            if self.low <= abs(parse_quantity(guess, dimension)) <= self.high:
                raise ValueError(f"{message}: did you mean {guess}?")
        raise ValueError(message)


_NUMBER_AND_UNIT = re.compile(rf"(?P<number>{NUMBER})\s*(?P<unit>.+)")

#: Real lengths of machine elements: above a micrometre (a surface's roughness) and
#: below 100 m. Positions may be zero, so they have no lower end.
PLAUSIBLE_LENGTH = Plausible(1e-6, 100.0, "1 µm to 100 m", ("mm", "m", "µm"))
PLAUSIBLE_POSITION = Plausible(0.0, 100.0, "up to 100 m", ("mm", "m"))
#: Loads from a micronewton (a hair's weight is some 10 µN; below it the lives' powers of
#: C/P leave double precision) up to 10⁹ N (10⁶ kN, the largest slewing bearings carry a
#: few 10⁷ N).
PLAUSIBLE_FORCE = Plausible(1e-6, 1e9, "1 µN to 10⁶ kN", ("N", "kN"))
#: Stresses and pressure limits from a kilopascal to 10⁶ MPa (steels' contact limits are
#: near 4000 MPa).
#: Stiffnesses from 1 N/mm to 10⁷ N/µm (a bearing's is some 10 to 10⁴ N/µm).
PLAUSIBLE_STIFFNESS = Plausible(1e3, 1e13, "1 N/mm to 10⁷ N/µm", ("N/µm", "N/mm", "N/m"))
PLAUSIBLE_STRESS = Plausible(1e3, 1e12, "1 kPa to 10⁶ MPa", ("MPa", "GPa", "Pa"))
#: Times from a millisecond to 10⁹ hours (required lives are 10² to 10⁶ h).
PLAUSIBLE_TIME = Plausible(1e-3, 3.6e12, "1 ms to 10⁹ h", ("h", "s"))
#: Speeds up to 10⁶ rpm (turbomachinery and dental drills stay well below).
PLAUSIBLE_SPEED = Plausible(0.0, 1e6 * math.pi / 30.0, "up to 10⁶ rpm", ("rpm",))
#: Kinematic viscosities up to 10⁶ mm²/s (heavy gear oils are near 10⁴ mm²/s cold).
PLAUSIBLE_VISCOSITY = Plausible(0.0, 1.0, "up to 10⁶ mm²/s", ("mm^2/s",))
#: Young's moduli of engineering solids, from polymers (~1 GPa) to diamond (~1000 GPa).
PLAUSIBLE_MODULUS = Plausible(1e9, 1e12, "1 GPa to 1000 GPa", ("GPa", "MPa"))


class _Quantity:
    """Validator turning a quantity (with an optional tolerance) into SI, with a sign check
    and, where given, a check of its plausible magnitude."""

    def __init__(self, dimension: Dimension, sign: str | None,
                 bounds: tuple[float, float] | None = None,
                 plausible: Plausible | None = None) -> None:
        self.dimension = dimension
        self.sign = sign
        self.bounds = bounds  # open interval every value of the band must lie in
        self.plausible = plausible

    def __call__(self, value: Any) -> float:
        if isinstance(value, dict):
            tolerance = self._mapping(value)
            written = value["nominal"]
        elif isinstance(value, str) and _PLUS_MINUS.search(value):
            tolerance = self._plus_minus(value)
            written = _PLUS_MINUS.split(value, maxsplit=1)[0]
        else:
            nominal = parse_quantity(value, self.dimension)
            self._check_sign(nominal, f"'{value}'")
            self._check_plausible(nominal, value)
            return nominal
        self._check_sign(tolerance.nominal, "the nominal value")
        self._check_plausible(tolerance.nominal, written)
        unit = "" if self.dimension.si_unit == "1" else f" {self.dimension.si_unit}"
        self._check_sign(tolerance.low, f"the band's low end ({tolerance.low:g}{unit})")
        self._check_sign(tolerance.high, f"the band's high end ({tolerance.high:g}{unit})")
        return Measured(tolerance.nominal, tolerance)

    def _check_sign(self, si: float, what: str) -> None:
        if self.bounds is not None and not self.bounds[0] < si < self.bounds[1]:
            raise ValueError(f"must be between {self.bounds[0]:g} and {self.bounds[1]:g} "
                             f"(exclusive), got {what}")
        if self.sign == "positive" and not si > 0:
            raise ValueError(f"must be greater than zero, got {what}")
        if self.sign == "non-negative" and not si >= 0:
            raise ValueError(f"must not be negative, got {what}")

    def _check_plausible(self, si: float, written: Any) -> None:
        if self.plausible is not None:
            self.plausible.check(si, written, self.dimension)

    def _plus_minus(self, text: str) -> Tolerance:
        nominal_text, tolerance_text = _PLUS_MINUS.split(text, maxsplit=1)
        if not _has_unit(nominal_text):  # "12.7 ± 0.005 mm": the unit is shared
            unit = tolerance_text.strip().lstrip("0123456789.eE+-").strip()
            nominal_text = f"{nominal_text} {unit}"
        nominal = parse_quantity(nominal_text, self.dimension)
        band = self._deviation(tolerance_text, "tolerance")
        return Tolerance(nominal, nominal - band, nominal + band, unit=self.dimension.si_unit,
                         written_unit=_unit_of(nominal_text))

    def _mapping(self, value: dict[str, Any]) -> Tolerance:
        unknown = sorted(set(value) - _MAPPING_KEYS)
        if unknown:
            raise ValueError(f"unknown key '{unknown[0]}' in a tolerance; use nominal with "
                             "tolerance, or plus and minus, and optionally distribution and "
                             "sigma_level")
        if "nominal" not in value:
            raise ValueError(f"a tolerance mapping needs nominal, e.g. {{nominal: "
                             f"{self.dimension.example}, tolerance: ...}}")
        nominal = parse_quantity(value["nominal"], self.dimension)
        if "tolerance" in value:
            if "plus" in value or "minus" in value:
                raise ValueError("give tolerance, or plus and minus, not both")
            plus = minus = self._deviation(value["tolerance"], "tolerance")
        elif "plus" in value and "minus" in value:
            plus = self._deviation(value["plus"], "plus")
            minus = self._deviation(value["minus"], "minus")
        else:
            raise ValueError("a tolerance mapping needs tolerance, or both plus and minus")
        distribution = value.get("distribution", "normal")
        if distribution not in DISTRIBUTIONS:
            raise ValueError(f"unknown distribution {distribution!r}; use one of "
                             f"{', '.join(DISTRIBUTIONS)}")
        sigma_level = value.get("sigma_level", 3.0)
        if "sigma_level" in value and distribution != "normal":
            raise ValueError("sigma_level applies to the normal distribution only")
        if isinstance(sigma_level, bool) or not isinstance(sigma_level, (int, float)) or not (
                MIN_SIGMA_LEVEL <= sigma_level <= MAX_SIGMA_LEVEL):
            raise ValueError(
                f"sigma_level must be a number from {MIN_SIGMA_LEVEL:g} to {MAX_SIGMA_LEVEL:g} "
                f"(the band is ±sigma_level·σ; below 1 the distribution is wider than its "
                f"band), like 3, got {sigma_level!r}")
        return Tolerance(nominal, nominal - minus, nominal + plus, distribution,
                         float(sigma_level), self.dimension.si_unit,
                         _unit_of(value["nominal"]))

    def _deviation(self, text: Any, what: str) -> float:
        deviation = parse_quantity(text, self.dimension)
        if self.dimension is TEMPERATURE and isinstance(text, str):
            # A temperature difference: 5 degC is 5 K, not 278.15 K.
            deviation -= parse_quantity(f"0 {text.split(maxsplit=1)[-1]}", self.dimension)
        if deviation < 0:
            raise ValueError(f"{what} must not be negative, got '{text}'")
        return deviation


def _has_unit(text: str) -> bool:
    return bool(re.search(r"[^\s\d.eE+-]", text))


def quantity(dimension: Dimension, sign: str | None = None,
             bounds: tuple[float, float] | None = None,
             plausible: Plausible | None = None) -> Any:
    """Annotated float type of a quantity field of ``dimension``.

    ``sign`` is None (any finite value), "positive" or "non-negative"; ``plausible``
    refuses magnitudes no machine element has (see :class:`Plausible`). The value
    may carry a tolerance (``"12.7 mm ± 0.005 mm"`` or a mapping, see
    :class:`Tolerance`), and then arrives as a :class:`Measured`.
    """
    words = {"positive": "positive ", "non-negative": "non-negative ", None: ""}[sign]
    text_form = {
        "type": "string",
        "description": f"{words}{dimension.name} with a unit, e.g. '{dimension.example}', "
                       f"optionally with a tolerance ('{dimension.example} ± ...')",
        "examples": [dimension.example],
        # A number, then a unit: refuses bare numbers and unit-less strings.
        "pattern": QUANTITY_PATTERN,
    }
    text_schema = {"type": "string", "pattern": QUANTITY_PATTERN}
    mapping_form = {
        "type": "object",
        "description": "a toleranced value: nominal with tolerance, or plus and minus",
        "properties": {
            "nominal": text_schema, "tolerance": text_schema, "plus": text_schema,
            "minus": text_schema, "distribution": {"enum": list(DISTRIBUTIONS)},
            "sigma_level": {"type": "number", "minimum": MIN_SIGMA_LEVEL,
                            "maximum": MAX_SIGMA_LEVEL},
        },
        "required": ["nominal"],
        "additionalProperties": False,
    }
    # Annotations in standard keywords only: strict validators refuse unknown ones.
    schema = {"anyOf": [text_form, mapping_form],
              "$comment": f"dimension: {dimension.name}; SI unit: {dimension.si_unit}",
              "examples": [dimension.example]}
    if dimension is DIMENSIONLESS:
        number = {"type": "number"}
        if bounds is not None:
            number.update({"exclusiveMinimum": bounds[0], "exclusiveMaximum": bounds[1]})
        schema["anyOf"].insert(0, number)
        for key in ("nominal", "tolerance", "plus", "minus"):
            mapping_form["properties"][key] = {"anyOf": [{"type": "number"}, text_schema]}
    return Annotated[float, PlainValidator(_Quantity(dimension, sign, bounds, plausible),
                                           json_schema_input_type=str),
                     WithJsonSchema(schema)]


Length = quantity(LENGTH, plausible=PLAUSIBLE_POSITION)
PositiveLength = quantity(LENGTH, "positive", plausible=PLAUSIBLE_LENGTH)
Angle = quantity(ANGLE)
PositiveAngle = quantity(ANGLE, "positive")
AngularSpeed = quantity(ANGULAR_SPEED, plausible=PLAUSIBLE_SPEED)
AngularAccel = quantity(ANGULAR_ACCEL)
Force = quantity(FORCE, "non-negative", plausible=PLAUSIBLE_FORCE)
PositiveForce = quantity(FORCE, "positive", plausible=PLAUSIBLE_FORCE)
PositiveStress = quantity(STRESS, "positive", plausible=PLAUSIBLE_STRESS)
PositiveStiffness = quantity(STIFFNESS, "positive", plausible=PLAUSIBLE_STIFFNESS)
ElasticModulus = quantity(STRESS, "positive", plausible=PLAUSIBLE_MODULUS)
PositiveTime = quantity(TIME, "positive", plausible=PLAUSIBLE_TIME)
PositiveViscosity = quantity(KINEMATIC_VISCOSITY, "positive", plausible=PLAUSIBLE_VISCOSITY)
Temperature = quantity(TEMPERATURE, "positive")
#: Expansion coefficients of engineering solids, from invar's 1e-6/K to polymers' 2e-4/K.
ThermalExpansion = quantity(THERMAL_EXPANSION, "positive",
                            plausible=Plausible(1e-7, 1e-3, "1e-7 to 1e-3 1/K",
                                                ("1/K", "ppm/K")))
PositiveDensity = quantity(DENSITY, "positive")
PositivePower = quantity(POWER, "positive")
Torque = quantity(TORQUE, "positive")
#: A moment of either sense (a tilting moment). [N·m]
Moment = quantity(TORQUE)

#: Groove radius over ball diameter: above 0.5 (at 0.5 or below the ball would not fit
#: its groove) and below 1. A plain number that may carry a tolerance (0.52 ± 0.005).
Conformity = quantity(DIMENSIONLESS, bounds=(0.5, 1.0))
