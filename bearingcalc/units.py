"""Quantities with units: parsing spec strings into SI floats, and display units.

pint is the authority on units. Building its registry costs about three times a
numpy import, so the units engineers write every day are looked up in
``COMMON_UNITS``, a table of pint's own factors (``tests/test_units.py`` checks
every entry against pint), and pint is loaded only for anything else.

Angles need care: pint treats the radian as dimensionless, so a plain number or
``Hz`` would pass as an angle or an angular speed. Every dimension here therefore
names the root units pint must reduce to, radian included, and ``25 Hz`` is
refused for a speed rather than read silently as 25 rad/s.

Speeds of rotation are written in many ways (``rpm``, ``r/min`` as ISO 281 and
bearing catalogues write it, ``min⁻¹`` as DIN does); ``RPM_NOTATIONS`` reads them
all as rpm, but only where an angular speed is expected: to pint, ``1/min`` is a
frequency. Percent is a unit on its own (``90 %``) and never a factor of another
unit, where it would scale silently (``20 deg%`` would be 0.2°).
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass
from typing import Any, NoReturn

from bearingcalc.number_grammar import DECIMAL, NUMBER
from bearingcalc.wording import article


class UnitError(ValueError):
    """A quantity string that cannot be read, or is of the wrong dimension."""


@dataclass(frozen=True)
class Dimension:
    """A physical dimension as spec fields use it."""

    name: str            # "length"
    si_unit: str         # "m", as results and JSON name it
    root: str            # pint's root units, "meter"
    example: str         # "12.7 mm"
    display_unit: str    # engineering unit of tables, "mm"
    si_per_root: float = 1.0  # SI units per pint root unit (pint's mass root is the gram)


LENGTH = Dimension("length", "m", "meter", "12.7 mm", "mm")
ANGLE = Dimension("angle", "rad", "radian", "20 deg", "deg")
ANGULAR_SPEED = Dimension("angular speed", "rad/s", "radian / second", "1500 rpm", "rpm")
ANGULAR_ACCEL = Dimension("angular acceleration", "rad/s²", "radian / second ** 2",
                          "10 rad/s^2", "rad/s²")
FORCE = Dimension("force", "N", "gram * meter / second ** 2", "10 kN", "kN", 1e-3)
STRESS = Dimension("stress", "Pa", "gram / meter / second ** 2", "4200 MPa", "MPa", 1e-3)
TIME = Dimension("time", "s", "second", "20000 h", "h")
KINEMATIC_VISCOSITY = Dimension("kinematic viscosity", "m²/s", "meter ** 2 / second",
                                "20 mm^2/s", "mm²/s")
#: Temperatures carry an offset (0 degC = 273.15 K), which pint's root factor leaves out:
#: they are read from ``TEMPERATURE_UNITS`` only.
TEMPERATURE = Dimension("temperature", "K", "kelvin", "80 degC", "degC")
DENSITY = Dimension("density", "kg/m³", "gram / meter ** 3", "7850 kg/m^3", "kg/m³", 1e-3)
POWER = Dimension("power", "W", "gram * meter ** 2 / second ** 3", "9.4 kW", "kW", 1e-3)
TORQUE = Dimension("torque", "N·m", "gram * meter ** 2 / second ** 2", "150 N*m", "N·m", 1e-3)
MASS = Dimension("mass", "kg", "gram", "0.13 kg", "kg", 1e-3)
STIFFNESS = Dimension("stiffness", "N/m", "gram / second ** 2", "100 N/µm", "N/µm", 1e-3)
#: A linear expansion coefficient, per kelvin (a temperature difference: no offset).
THERMAL_EXPANSION = Dimension("thermal expansion", "1/K", "1 / kelvin", "11.5e-6 1/K", "1/K")
#: A plain number (a ratio such as a groove conformity), written without a unit.
DIMENSIONLESS = Dimension("plain number", "1", "dimensionless", "0.52", "")
DIMENSIONS = {d.name: d for d in (LENGTH, ANGLE, ANGULAR_SPEED, ANGULAR_ACCEL, FORCE, STRESS,
                                  TIME, KINEMATIC_VISCOSITY, TEMPERATURE, DENSITY, POWER,
                                  TORQUE, MASS, STIFFNESS, THERMAL_EXPANSION)}

#: unit -> (scale, offset): kelvin = scale · value + offset.
TEMPERATURE_UNITS: dict[str, tuple[float, float]] = {
    "K": (1.0, 0.0), "kelvin": (1.0, 0.0),
    "degC": (1.0, 273.15), "°C": (1.0, 273.15), "celsius": (1.0, 273.15),
    "degF": (5.0 / 9.0, 273.15 - 32.0 * 5.0 / 9.0), "°F": (5.0 / 9.0, 273.15 - 32.0 * 5.0 / 9.0),
}

_TAU = 2.0 * math.pi
_DEG = math.pi / 180.0

#: unit text -> (pint root units, factor to SI). Verified against pint in the tests.
#: Decimal sub-units divide (26 mm -> 26 / 1000 = 0.026 exactly as typed, where
#: 26 * 1e-3 would give 0.026000000000000002); see ``_DIVISORS``.
COMMON_UNITS: dict[str, tuple[str, float]] = {
    "m": ("meter", 1.0),
    "cm": ("meter", 1e-2),
    "mm": ("meter", 1e-3),
    "um": ("meter", 1e-6),
    "µm": ("meter", 1e-6),
    "μm": ("meter", 1e-6),
    "in": ("meter", 0.0254),
    "inch": ("meter", 0.0254),
    "ft": ("meter", 0.3048),
    "rad": ("radian", 1.0),
    "mrad": ("radian", 1e-3),
    "deg": ("radian", _DEG),
    "degree": ("radian", _DEG),
    "°": ("radian", _DEG),
    "arcmin": ("radian", _DEG / 60.0),
    "arcsec": ("radian", _DEG / 3600.0),
    "turn": ("radian", _TAU),
    "rad/s": ("radian / second", 1.0),
    "deg/s": ("radian / second", _DEG),
    "rpm": ("radian / second", _TAU / 60.0),
    "rev/min": ("radian / second", _TAU / 60.0),
    "rps": ("radian / second", _TAU),
    "rev/s": ("radian / second", _TAU),
    "rad/s^2": ("radian / second ** 2", 1.0),
    "rad/s**2": ("radian / second ** 2", 1.0),
    "rad/s²": ("radian / second ** 2", 1.0),
    "rpm/s": ("radian / second ** 2", _TAU / 60.0),
    "deg/s^2": ("radian / second ** 2", _DEG),
    "N": ("gram * meter / second ** 2", 1e3),
    "kN": ("gram * meter / second ** 2", 1e6),
    "s": ("second", 1.0),
    "min": ("second", 60.0),
    "h": ("second", 3600.0),
    "mm^2/s": ("meter ** 2 / second", 1e-6),
    "mm²/s": ("meter ** 2 / second", 1e-6),
    "cSt": ("meter ** 2 / second", 1e-6),
    "MPa": ("gram / meter / second ** 2", 1e9),
    "GPa": ("gram / meter / second ** 2", 1e12),
    "N*m": ("gram * meter ** 2 / second ** 2", 1e3),
    "N·m": ("gram * meter ** 2 / second ** 2", 1e3),
    "W": ("gram * meter ** 2 / second ** 3", 1e3),
    "kW": ("gram * meter ** 2 / second ** 3", 1e6),
    "kg/m^3": ("gram / meter ** 3", 1e3),
    "kg": ("gram", 1e3),
    "g": ("gram", 1.0),
    "kg/m³": ("gram / meter ** 3", 1e3),
}

#: Notations of revolutions per minute, read as ``rpm`` where an angular speed is
#: expected (and nowhere else: ``1/min`` is a frequency to pint, and ``r`` or ``RPM``
#: are not units to it). Keys are written without spaces; ``1 / min`` is ``1/min``.
#: ``tests/test_units.py`` checks each against pint's ``revolution / minute``.
RPM_NOTATIONS = frozenset({"rpm", "RPM", "r/min", "rev/min", "1/min", "min^-1", "min**-1",
                           "min⁻¹", "min-1", "U/min"})  # U/min: German catalogues' Umdrehungen

_DIVISORS: dict[str, float] = {"cm": 1e2, "mm": 1e3, "um": 1e6, "µm": 1e6, "μm": 1e6,
                               "mrad": 1e3}

#: SI unit -> (engineering unit, factor from SI), for tables.
DISPLAY_UNITS: dict[str, tuple[str, float]] = {
    "m": ("mm", 1e3),
    "rad": ("deg", 1.0 / _DEG),
    "rad/s": ("rpm", 60.0 / _TAU),
    "rad/s²": ("rad/s²", 1.0),
    "m/s": ("m/s", 1.0),
    "m/s²": ("m/s²", 1.0),
    "Hz": ("Hz", 1.0),
    "1": ("", 1.0),
    "N": ("kN", 1e-3),
    "Pa": ("MPa", 1e-6),
    "s": ("h", 1.0 / 3600.0),
    "m²/s": ("mm²/s", 1e6),
    "W": ("kW", 1e-3),
    "N·m": ("N·m", 1.0),
    "kg/m³": ("kg/m³", 1.0),
    "kg": ("kg", 1.0),
}

#: A number in plain ASCII digits (full-width digits and the like are refused, as the
#: JSON Schema refuses them), then the unit text.
_QUANTITY = re.compile(
    rf"^\s*(?P<number>{NUMBER})\s*(?P<unit>\S.*?)?\s*$",
    re.ASCII)
#: A unit is words (with optional small whole exponents, ``^-1`` or ``⁻¹``) joined by
#: *, / or spaces, the first of which may be a 1 over the rest (``1/min``); or ``%`` on
#: its own. Anything else (brackets, stray operators, punctuation) is refused before
#: pint sees it.
_UNIT_WORD = r"(?:[A-Za-z_°µμΩ]+(?:\s*(?:\^|\*\*)\s*[-+]?[1-9][0-9]?|⁻?[¹²³])?)"
_UNIT = re.compile(rf"^(?:%|(?:{_UNIT_WORD}|1(?=\s*/))(?:\s*[*/·]\s*{_UNIT_WORD}"
                  rf"|\s+{_UNIT_WORD})*)$")
#: Percent anywhere in a unit, as the sign or as pint's word for it.
_PERCENT = re.compile(r"%|(?<![A-Za-z_])percent(?![A-Za-z_])")
#: Longest quantity text handed on: longer ones are typos or attacks, and pint's parser
#: is super-linear in the length.
MAX_QUANTITY_CHARS = 80
#: Largest magnitude of any quantity in SI units. Nothing in machine design comes near;
#: beyond it tables in engineering units and the solvers' products would overflow.
MAX_MAGNITUDE = 1e15


def parse_quantity(text: Any, dimension: Dimension) -> float:
    """Read ``"12.7 mm"`` as a value of ``dimension`` and return it in SI units.

    The whole text must parse: a number in ASCII digits, then a unit made of unit
    words, small whole exponents and the operators * and /. Anything else is refused.

    Raises
    ------
    UnitError : bare number, unknown unit, wrong dimension, trailing junk, or a value
        that is not a finite number within ±MAX_MAGNITUDE; the message says how to
        write the quantity.
    """
    what = article(dimension.name)
    if dimension is DIMENSIONLESS:
        return _plain_number(text)
    if isinstance(text, bool) or not isinstance(text, str):
        _refuse_not_text(text, dimension, what)
    match = _read_quantity(text, dimension, what)
    number, unit = float(match["number"]), _checked_unit(text, match, dimension, what)
    if dimension is TEMPERATURE:
        return _temperature(number, unit, text)
    return _in_si(number, unit, text, dimension, what)


def _refuse_not_text(value: Any, dimension: Dimension, what: str) -> NoReturn:
    """Refuse a quantity that is not text: a bare number has no unit (one that says which,
    where the number is finite)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise UnitError(f"expected {what} with a unit, like '{dimension.example}'")
    if isinstance(value, float) and not math.isfinite(value):
        raise UnitError(f"{value} is not a finite number; give {what} like "
                        f"'{dimension.example}'")
    unit = dimension.example.split()[1]
    shown = f"{value:g}" if isinstance(value, float) else _shorten(str(value))
    raise UnitError(f"a bare number has no unit: write it as '{shown} {unit}' "
                    f"({what}, like '{dimension.example}')")


def _read_quantity(text: str, dimension: Dimension, what: str) -> re.Match[str]:
    """The number and unit of a quantity's text, or why it cannot be read as one."""
    if len(text) > MAX_QUANTITY_CHARS:
        raise UnitError(f"'{_shorten(text)}' is too long for {what} (at most "
                        f"{MAX_QUANTITY_CHARS} characters); write it like '{dimension.example}'")
    match = _QUANTITY.match(text)
    if match is None:
        # the number's place holds it (not a word of the unit's or of a longer text)
        if re.match(r"\s*[-+]?\.?(nan|inf|infinity)(?![A-Za-z])", text, re.IGNORECASE):
            raise UnitError(f"'{text}' is not a finite number; give {what} like "
                            f"'{dimension.example}'")
        raise UnitError(f"cannot read '{text}' as {what}; write a number and a unit, "
                        f"like '{dimension.example}'")
    return match


def _checked_unit(text: str, match: re.Match[str], dimension: Dimension, what: str) -> str:
    """The unit of a read quantity, refused with the likely slip where it is none: no
    unit, a decimal comma, percent as a factor, a number run into '1/min'."""
    unit = match["unit"]
    if unit is None:
        raise UnitError(f"'{text}' has no unit: write it like '{dimension.example}'")
    if re.match(r"^,[0-9]", unit):
        raise UnitError(f"'{text}': write the decimal point as '.', like "
                        f"'{match['number']}.{unit[1:]}'")
    if _PERCENT.search(unit) and unit not in ("%", "percent"):
        raise UnitError(f"cannot read '{unit}' in '{text}' as a unit: percent is a unit on "
                        f"its own, as in '90 %', never a factor of another unit; write "
                        f"{what} like '{dimension.example}'")
    if dimension is ANGULAR_SPEED and unit.replace(" ", "") in RPM_NOTATIONS:
        unit = "rpm"  # the notations of speeds of rotation, "min-1" among them
    if not _UNIT.match(unit):
        before_one = _number_before_one(match["number"], unit)
        if before_one is not None:  # "15001/min": the 1 of 1/min read as a digit
            raise UnitError(f"cannot read '{text}': put a space between the number and "
                            f"'1{unit}', like '{before_one} 1{unit}', or write {what} like "
                            f"'{dimension.example}'")
        raise UnitError(f"cannot read '{unit}' in '{text}' as a unit; write a number and a "
                        f"unit with nothing after it, like '{dimension.example}'")
    return unit


def _in_si(number: float, unit: str, text: str, dimension: Dimension, what: str) -> float:
    """``number`` ``unit`` in the SI unit of ``dimension`` (not a temperature), refused
    when the unit is another quantity's or the value is out of range."""
    rpm_notation = re.sub(r"\s+", "", unit) in RPM_NOTATIONS
    if rpm_notation and dimension is ANGULAR_SPEED:
        unit = "rpm"
    try:
        root, factor = COMMON_UNITS.get(unit) or _pint_unit(unit)
    except UnitError:
        if not rpm_notation:
            raise
        root, factor = COMMON_UNITS["rpm"]  # "r/min" for a length: say what it is
    factor *= dimension.si_per_root
    if root != dimension.root:
        raise UnitError(f"'{unit}' is not a unit of {dimension.name} ({_describe_root(root)}); "
                        f"write it like '{dimension.example}'")
    divisor = _DIVISORS.get(unit)
    value = number / divisor if divisor else number * factor
    if not (math.isfinite(value) and abs(value) <= MAX_MAGNITUDE):
        raise UnitError(f"'{text}' is out of range for {what} (at most {MAX_MAGNITUDE:g} "
                        f"{dimension.si_unit} in size)")
    return value


def unit_scale(unit: str, dimension: Dimension) -> tuple[float, bool]:
    """How :func:`parse_quantity` turns a number written with ``unit`` into SI: (factor,
    divides), so that a column of numbers in one unit is read at once with the same
    arithmetic (``26 mm`` is 26/1000, not 26·0.001). Raises UnitError as parsing
    ``'1 unit'`` would."""
    one = parse_quantity(f"1 {unit}", dimension)
    divisor = _DIVISORS.get(unit.strip())
    return (divisor, True) if divisor else (one, False)


def _number_before_one(number: str, unit: str) -> str | None:
    """The number of ``15001/min`` written without the 1 of ``1/min`` (``1500``), or None
    when the unit does not start with / or no number is left."""
    if not unit.startswith("/") or not number.endswith("1"):
        return None
    rest = number[:-1]
    return rest if re.fullmatch(DECIMAL, rest, re.ASCII) else None


def _plain_number(text: Any) -> float:
    """A plain number, as a YAML number or a string of one (with no unit)."""
    if isinstance(text, str) and len(text) <= MAX_QUANTITY_CHARS and re.fullmatch(
            rf"\s*{NUMBER}\s*", text, re.ASCII):
        value = float(text)
    elif isinstance(text, (int, float)) and not isinstance(text, bool):
        value = float(text) if abs(text) < 1e300 else math.inf
    else:
        raise UnitError(f"expected a plain number without a unit, like 0.52, got {text!r}")
    if not (math.isfinite(value) and abs(value) <= MAX_MAGNITUDE):
        raise UnitError(f"{text!r} is not a finite number within ±{MAX_MAGNITUDE:g}")
    return value


def _temperature(number: float, unit: str, text: str) -> float:
    if unit not in TEMPERATURE_UNITS:
        raise UnitError(f"'{unit}' is not a unit of temperature; write it like '80 degC' "
                        "(degC, K or degF)")
    scale, offset = TEMPERATURE_UNITS[unit]
    kelvin = scale * number + offset
    if not (math.isfinite(kelvin) and 0 < kelvin <= MAX_MAGNITUDE):
        raise UnitError(f"'{text}' is not a temperature above absolute zero")
    return kelvin


def _shorten(text: str, keep: int = 24) -> str:
    return text if len(text) <= 2 * keep else f"{text[:keep]}…{text[-8:]}"


@functools.lru_cache(maxsize=256)
def _pint_unit(unit: str) -> tuple[str, float]:
    """(root units, factor to SI) of a unit pint knows; the registry loads on first use."""

    registry = _registry()
    try:
        factor, root = registry.get_root_units(registry.parse_units(unit))
    except Exception as exc:  # pint raises many types (KeyError, TokenError, ...) on junk
        raise UnitError(f"unknown unit '{unit}'") from exc
    if not math.isfinite(float(factor)):
        raise UnitError(f"unknown unit '{unit}'")
    return str(root), float(factor)


@functools.lru_cache(maxsize=1)
def unit_registry() -> Any:
    """The one pint registry of the process (:func:`make_registry`), made on first use."""
    return make_registry()


_registry = unit_registry


def make_registry() -> Any:
    """pint's default registry, plus ``rev`` (as in rev/min), which machinists write."""
    import pint

    registry = pint.UnitRegistry()
    registry.define("rev = revolution")
    return registry


def _describe_root(root: str) -> str:
    for dimension in DIMENSIONS.values():
        if dimension.root == root:
            return f"it is {article(dimension.name)}"
    if root in ("", "dimensionless"):
        return "it is dimensionless"
    if root == "1 / second":
        return "it is a frequency; for a speed of rotation write rpm, rev/s or rad/s"
    return f"it reduces to {root}"


def to_display(value: float, si_unit: str) -> tuple[float, str]:
    """(value, unit) in the engineering unit of ``si_unit`` for tables."""
    unit, factor = DISPLAY_UNITS.get(si_unit, (si_unit, 1.0))
    return value * factor, unit
