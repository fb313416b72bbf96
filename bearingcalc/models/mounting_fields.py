"""The forms a bearing's ``mounting`` writes its values in: a seat as its ISO 286 class
or its diameter, a clearance group or the clearance itself, a seat's material by name or
by its constants, the roughness of each joint, the bearing's ISO 492 class. Each reads a
near miss with a message that says what would be right."""

from __future__ import annotations

import re
from typing import Annotated, Any, Literal, NamedTuple

from pydantic import (
    BeforeValidator,
    Discriminator,
    Field,
    PlainValidator,
    WithJsonSchema,
    model_validator,
)

from bearingcalc.models.base import BRANCH_MARK, SpecModel, branch
from bearingcalc.models.plain_numbers import PoissonRatio
from bearingcalc.models.quantities import (
    ElasticModulus,
    Measured,
    Plausible,
    PositiveLength,
    ThermalExpansion,
    quantity,
)
from bearingcalc.units import LENGTH

_CLASS = r"[A-Za-z]{1,2}\s?\d{1,2}"
#: A seat's ISO 286 class, with or without its nominal diameter in mm: "k5", "40 k5",
#: "40 mm k5" (a space inside the class, "k 5", read as written).
_SEAT_CLASS = re.compile(rf"^\s*(?:(?P<nominal>\d+(?:\.\d+)?)\s*(?:mm\s+)?)?"
                         rf"(?P<symbol>{_CLASS})\s*$")
#: A clearance group's name, any case: C2, CN, C3, C4, C5, the matched rings' C1NA …,
#: ISO 5753-1's own N, and the makers' names (normal, CC1 …).
_GROUP = re.compile(r"^\s*(C[0-9A-Z]{1,3}|N|NA|NORMAL)\s*$", re.IGNORECASE)
#: ISO 5753-1 calls the normal group N.
_GROUP_NAMES = {"N": "CN", "NORMAL": "CN"}
GROUPS_WORDS = "C2, CN, C3, C4, C5"
#: A joint's Rz: up to 100 µm, rougher than any seat a bearing sits on (ground some 1 to
#: 4 µm, turned up to some 25 µm).
RoughnessRz = quantity(LENGTH, "non-negative", plausible=Plausible(
    1e-9, 100e-6, "Rz up to 100 µm", ("µm",)))

_READ_LENGTH = PositiveLength.__metadata__[0].func
_READ_ANY_LENGTH = quantity(LENGTH).__metadata__[0].func
#: A length that may be zero: a solid shaft's bore, a polished surface's Rz.
NonNegativeLength = quantity(LENGTH, "non-negative")


class SeatClass(NamedTuple):
    """A seat given by its ISO 286 class: its symbol (``k5``, ``H7``) and its nominal
    diameter [m], None for the bearing's own."""

    symbol: str
    nominal: float | None


def _seat(value: Any) -> Any:
    """A seat's class (:class:`SeatClass`) or its diameter, with a tolerance where given
    (``40.008 mm ± 0.004 mm``)."""
    if isinstance(value, (SeatClass, Measured, float)):
        return value
    if isinstance(value, str):
        match = _SEAT_CLASS.match(value)
        if match:
            nominal = match["nominal"]
            return SeatClass(match["symbol"].replace(" ", ""), None if nominal is None
                             else float(nominal) * 1e-3)
    try:
        return _READ_LENGTH(value)
    except ValueError as problem:
        raise ValueError(f"{problem}; or an ISO 286 class, like k5 (40 k5 with its nominal "
                         "diameter in mm)") from None


def _group(value: Any) -> Any:
    """A clearance group's name, or the clearance itself (a study's value)."""
    if isinstance(value, str) and (match := _GROUP.match(value)):
        name = match[1].upper()
        return _GROUP_NAMES.get(name, name)
    if isinstance(value, (Measured, float)):
        return value
    try:
        return _READ_ANY_LENGTH(value)
    except ValueError:
        raise ValueError(f"{value!r} is not a clearance group: give {GROUPS_WORDS} (ISO "
                         "5753-1), or the initial_clearance with a unit") from None


_TEXT = {"type": "string"}
#: A seat: its ISO 286 class (with its nominal diameter in mm, or the bearing's), or its
#: diameter with its own tolerance.
Seat = Annotated[Any, PlainValidator(_seat), WithJsonSchema({
    "anyOf": [{"type": "string",
               "pattern": r"^\s*(?:\d+(?:\.\d+)?\s*(?:mm\s+)?)?[A-Za-z]{1,2}\s?\d{1,2}\s*$"},
              _TEXT, {"type": "object"}],
    "description": "an ISO 286 class (k5, or 40 k5 with its nominal diameter in mm), or the "
                   "seat's diameter with its tolerance (40.008 mm ± 0.004 mm)"})]
ClearanceGroup = Annotated[Any, PlainValidator(_group), WithJsonSchema({
    "type": "string", "description": f"ISO 5753-1's radial clearance group: {GROUPS_WORDS}"})]
#: The bearing's ISO 492 class, its number written with or without quotes.
ToleranceClass = Annotated[Literal["normal", "6", "5"],
                           BeforeValidator(lambda value: str(value) if isinstance(value, int)
                                           and not isinstance(value, bool) else value)]


class SeatMaterial(SpecModel):
    """A seat's material given by its constants."""

    elastic_modulus: ElasticModulus = Field(description="Young's modulus E")
    poisson_ratio: PoissonRatio = Field(description="Poisson's ratio ν")
    thermal_expansion: ThermalExpansion = Field(description="the expansion coefficient α, "
                                                "like 23e-6 1/K")


def _material_form(value: object) -> str:
    return BRANCH_MARK + ("given" if isinstance(value, (dict, SeatMaterial)) else "named")


#: A seat's material by name: E [Pa], ν, α [1/K], typical of the material (give your
#: own as a mapping where it matters).
NAMED_MATERIALS = {"steel": (210e9, 0.3, 11.5e-6), "aluminium": (70e9, 0.33, 23e-6),
                   "cast iron": (110e9, 0.26, 10.5e-6)}


def material_constants(material: Any) -> tuple[float, float, float]:
    """E [Pa], ν and α [1/K] of a seat's material, named or given."""
    if isinstance(material, str):
        return NAMED_MATERIALS[material]
    return material.elastic_modulus, material.poisson_ratio, material.thermal_expansion


Material = Annotated[
    Annotated[Literal["steel", "aluminium", "cast iron"], branch("named")]
    | Annotated[SeatMaterial, branch("given")],
    Discriminator(_material_form)]


class Roughness(SpecModel):
    """The roughness pressed down in each fit, as Rz: the seat's and its ring's summed
    (a ground ring's is small beside a turned seat's)."""

    shaft: RoughnessRz = Field(0.0, description="Rz of the shaft seat and the ring's bore")
    housing: RoughnessRz = Field(0.0, description="Rz of the housing seat and the ring's "
                                 "outside")

    @model_validator(mode="before")
    @classmethod
    def _a_mapping(cls, value: Any) -> Any:
        if not isinstance(value, (dict, Roughness)):
            raise ValueError("give the Rz of each joint as {shaft: 2.5 µm, housing: 4 µm}")
        return value


def band_ends(value: Any) -> tuple[float, float]:
    """A value's band [low, high], [v, v] where it carries no tolerance."""
    tolerance = getattr(value, "tolerance", None)
    if tolerance is None:
        return float(value), float(value)
    return tolerance.low, tolerance.high
