"""A bearing's ``mounting``: how it sits on the drawing (its clearance group, its seats'
ISO 286 classes, its ISO 492 tolerance class, the seats' bodies and materials, the
temperatures), from which ISO/TS 16281's method finds the operating clearance
(:mod:`bearingcalc.core.mounted_clearance`, ``docs/physics.md``, the mounting chain).

Every band of the chain (the group's clearance, each seat's class, the ring's bore and
outside) becomes a toleranced value at the band's middle, uniform over it, so that
tolerance studies vary it as any toleranced field, by its own name
(``mounting.shaft``), and a sweep or a study's corner may write a plain value there.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from typing import Annotated, Any, Literal, NamedTuple

from pydantic import Discriminator, Field, PlainValidator, PrivateAttr, WithJsonSchema

from bearingcalc.catalogue import iso286, iso492, iso5753
from bearingcalc.core.bearing_types import traits
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import BRANCH_MARK, SpecModel, branch
from bearingcalc.models.plain_numbers import PoissonRatio
from bearingcalc.models.quantities import (
    ElasticModulus,
    Length,
    Measured,
    PositiveLength,
    Temperature,
    ThermalExpansion,
    Tolerance,
    quantity,
)
from bearingcalc.models.rules import rule
from bearingcalc.units import LENGTH

#: A seat's ISO 286 class, with or without its nominal diameter in mm: "k5", "40 k5",
#: "40 mm k5".
_SEAT_CLASS = re.compile(r"^\s*(?:(?P<nominal>\d+(?:\.\d+)?)\s*(?:mm\s+)?)?"
                         r"(?P<symbol>[A-Za-z]{1,2}\d{1,2})\s*$")
#: A clearance group's name (C2, CN, C3 …, and the makers' matched groups).
_GROUP = re.compile(r"^\s*C[0-9A-Z]{1,3}\s*$")
#: The assembly's temperature where the spec gives none: 20 °C, ISO 1's reference.
ASSEMBLY_TEMPERATURE = 293.15
#: Bearing steel's expansion coefficient where the spec gives none [1/K].
RING_EXPANSION = 11.5e-6
#: A seat's material by name: E [Pa], ν, α [1/K], typical of the material (give your
#: own as a mapping where it matters).
NAMED_MATERIALS = {"steel": (210e9, 0.3, 11.5e-6), "aluminium": (70e9, 0.33, 23e-6),
                   "cast iron": (110e9, 0.26, 10.5e-6)}

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
            return SeatClass(match["symbol"], None if nominal is None
                             else float(nominal) * 1e-3)
    return _READ_LENGTH(value)


def _group(value: Any) -> Any:
    """A clearance group's name, or the clearance itself (a study's value)."""
    if isinstance(value, str) and _GROUP.match(value):
        return value.strip()
    if isinstance(value, (Measured, float)):
        return value
    return _READ_ANY_LENGTH(value)


_TEXT = {"type": "string"}
#: A seat: its ISO 286 class (with its nominal diameter in mm, or the bearing's), or its
#: diameter with its own tolerance.
Seat = Annotated[Any, PlainValidator(_seat), WithJsonSchema({
    "anyOf": [{"type": "string",
               "pattern": r"^\s*(?:\d+(?:\.\d+)?\s*(?:mm\s+)?)?[A-Za-z]{1,2}\d{1,2}\s*$"},
              _TEXT,
              {"type": "object"}],
    "description": "an ISO 286 class (k5, or 40 k5 with its nominal diameter in mm), or the "
                   "seat's diameter with its tolerance (40.008 mm ± 0.004 mm)"})]
ClearanceGroup = Annotated[Any, PlainValidator(_group), WithJsonSchema({
    "type": "string", "description": "ISO 5753-1's radial clearance group: C2, CN, C3, "
    "C4, C5"})]


class SeatMaterial(SpecModel):
    """A seat's material given by its constants."""

    elastic_modulus: ElasticModulus = Field(description="Young's modulus E")
    poisson_ratio: PoissonRatio = Field(description="Poisson's ratio ν")
    thermal_expansion: ThermalExpansion = Field(description="the expansion coefficient α, "
                                                "like 23e-6 1/K")


def _material_form(value: object) -> str:
    return BRANCH_MARK + ("given" if isinstance(value, (dict, SeatMaterial)) else "named")


Material = Annotated[
    Annotated[Literal["steel", "aluminium", "cast iron"], branch("named")]
    | Annotated[SeatMaterial, branch("given")],
    Discriminator(_material_form)]


class Roughness(SpecModel):
    """The roughness pressed down in each fit, as Rz: the seat's and its ring's summed
    (a ground ring's is small beside a turned seat's)."""

    shaft: NonNegativeLength = Field(0.0, description="Rz of the shaft seat and the ring's "
                                     "bore")
    housing: NonNegativeLength = Field(0.0, description="Rz of the housing seat and the "
                                       "ring's outside")


class BearingMounting(SpecModel):
    """How the bearing sits on the drawing: the chain to its operating clearance."""

    clearance_group: ClearanceGroup | None = Field(
        None, description="ISO 5753-1's radial clearance group: C2, CN, C3, C4, C5")
    initial_clearance: Length | None = Field(
        None, description="the unmounted bearing's radial clearance, in place of a group, "
        "like 15 µm ± 5 µm")
    tolerance_class: Literal["normal", "6", "5"] = Field(
        "normal", description="the bearing's ISO 492 tolerance class")
    bore_deviation: Length | None = Field(
        None, description="the ring's mean bore less its nominal (default: the tolerance "
        "class's band, Δdmp)")
    outside_deviation: Length | None = Field(
        None, description="the ring's mean outside less its nominal (default: the class's "
        "band, ΔDmp)")
    shaft: Seat = Field(description="the shaft seat's ISO 286 class, like k5 (or 40 k5), or "
                        "its diameter with its tolerance")
    housing: Seat = Field(description="the housing seat's ISO 286 class, like H7, or its "
                          "diameter with its tolerance")
    shaft_bore: NonNegativeLength = Field(0.0, description="a hollow shaft's bore (0: "
                                          "solid)")
    housing_outside_diameter: PositiveLength | None = Field(
        None, description="the housing's wall around the ring (default: an unbounded body "
        "of its material)")
    shaft_material: Material = Field("steel", description="steel, aluminium, cast iron, or "
                                     "{elastic_modulus, poisson_ratio, thermal_expansion}")
    housing_material: Material = Field("steel", description="as shaft_material")
    roughness: Roughness | None = Field(None, description="Rz pressed down in each fit: "
                                        "{shaft: …, housing: …} (default: none)")
    inner_ring_temperature: Temperature | None = Field(
        None, description="the inner ring's operating temperature (default: the assembly's)")
    outer_ring_temperature: Temperature | None = Field(
        None, description="the outer ring's (default: the assembly's)")
    shaft_temperature: Temperature | None = Field(
        None, description="the shaft seat's (default: the inner ring's)")
    housing_temperature: Temperature | None = Field(
        None, description="the housing seat's (default: the outer ring's)")
    assembly_temperature: Temperature = Field(ASSEMBLY_TEMPERATURE,
                                              description="where the fits are measured")
    ring_thermal_expansion: ThermalExpansion = Field(
        RING_EXPANSION, description="the rings' and elements' α (bearing steel's)")

    #: each band's [low, high], by the chain's link (set as the mounting is resolved)
    _bands: dict[str, tuple[float, float]] = PrivateAttr(default_factory=dict)
    #: what the spec wrote of each class, for the notes
    _written: dict[str, str] = PrivateAttr(default_factory=dict)

    @rule
    def _group_or_clearance(self) -> SpecFieldError | None:
        if self.clearance_group is not None and self.initial_clearance is not None:
            return SpecFieldError("initial_clearance", "give a clearance_group or the "
                                  "initial_clearance, not both")
        if self.clearance_group is None and self.initial_clearance is None:
            return SpecFieldError("clearance_group", "missing: give the bearing's "
                                  "clearance_group (C2, CN, C3, C4, C5) or its "
                                  "initial_clearance, like 15 µm ± 5 µm")
        return None

    def bands(self) -> dict[str, tuple[float, float]]:
        return dict(self._bands)

    def written_classes(self) -> dict[str, str]:
        return dict(self._written)


def _band(low: float, high: float, written_unit: str) -> Measured:
    """A band's middle, uniform over it."""
    middle = 0.5 * (low + high)
    return Measured(middle, Tolerance(middle, low, high, "uniform", unit="m",
                                      written_unit=written_unit))


def _ends(value: Any) -> tuple[float, float]:
    """A value's band, [v, v] where it has none."""
    tolerance = getattr(value, "tolerance", None)
    if tolerance is None:
        return float(value), float(value)
    return tolerance.low, tolerance.high


def _looked_up(field: str, lookup: Any, *args: Any, **kwargs: Any) -> tuple[float, float]:
    """A table's band, its refusal located at the mounting's ``field``."""
    try:
        return lookup(*args, **kwargs)
    except ValueError as problem:
        raise SpecFieldError(f"mounting.{field}", str(problem)) from None


def resolve(mounting: BearingMounting, bearing: Mapping[str, Any]) -> BearingMounting:
    """``mounting`` with every class and group turned into its band (a toleranced value
    at its middle) and the bands kept, from the bearing's ``bore_diameter``,
    ``outside_diameter`` and ``type`` (validated before the mounting). Raises
    SpecFieldError where a table refuses a class, a group or a diameter."""
    bore, outside = bearing.get("bore_diameter"), bearing.get("outside_diameter")
    if bore is None or outside is None:
        missing = "bore_diameter" if bore is None else "outside_diameter"
        raise SpecFieldError(missing, "missing: a bearing's mounting takes its "
                             "bore_diameter and outside_diameter (or a designation)",
                             at="mounting")
    bore, outside = float(bore), float(outside)
    updates: dict[str, Any] = {}
    written: dict[str, str] = {}
    group = mounting.clearance_group
    if isinstance(group, str):
        written["clearance_group"] = group
        updates["clearance_group"] = _group_band(group, bore, str(bearing.get("type")))
    for field, nominal in (("bore_deviation", bore), ("outside_deviation", outside)):
        if getattr(mounting, field) is None:
            band = _looked_up(field, getattr(iso492, field), nominal,
                              tolerance_class=mounting.tolerance_class)
            updates[field] = _band(*band, "µm")
    for field, nominal, hole in (("shaft", bore, False), ("housing", outside, True)):
        seat = getattr(mounting, field)
        if isinstance(seat, SeatClass):
            updates[field] = _seat_band(field, seat, nominal, hole)
            written[field] = seat.symbol
    resolved = mounting.model_copy(update=updates)
    given = resolved.clearance_group if resolved.clearance_group is not None \
        else resolved.initial_clearance
    bands = {} if given is None else {"initial_clearance": _ends(given)}
    for link, nominal, field in (("bore_diameter", bore, "bore_deviation"),
                                 ("outside_diameter", outside, "outside_deviation")):
        low, high = _ends(getattr(resolved, field))
        bands[link] = (nominal + low, nominal + high)
    for field in ("shaft", "housing"):
        bands[f"{field}_diameter"] = _ends(getattr(resolved, field))
    resolved._bands, resolved._written = bands, written
    return resolved


def _group_band(group: str, bore: float, bearing_type: str) -> Measured:
    """A clearance group's band of initial clearances, for the bearing's type."""
    kind = traits(bearing_type).clearance_table
    if kind is None:
        raise SpecFieldError("mounting.clearance_group", f"ISO 5753-1's groups are of "
                             f"deep-groove, cylindrical and needle roller bearings, not of a "
                             f"{bearing_type} bearing: give its initial_clearance")
    return _band(*_looked_up("clearance_group", iso5753.radial_clearance, bore, group,
                             bearing_kind=kind), "µm")


def _seat_band(field: str, seat: SeatClass, nominal: float, hole: bool) -> Measured:
    """A seat class's band of diameters: the nominal (the ring's, where the class names
    none) plus its ISO 286 deviations."""
    ring = "bore" if field == "shaft" else "outside diameter"
    if seat.nominal is not None and not math.isclose(seat.nominal, nominal, rel_tol=1e-9):
        raise SpecFieldError(f"mounting.{field}", f"the seat's nominal {seat.nominal * 1e3:g} "
                             f"mm is not the bearing's {ring}, {nominal * 1e3:g} mm: write "
                             f"{seat.symbol} alone, or the ring's {ring}")
    if seat.symbol[0].isupper() != hole:
        which, like = ("a hole's", "upper case, like H7") if hole else (
            "a shaft's", "lower case, like k5")
        raise SpecFieldError(f"mounting.{field}", f"{seat.symbol} is not {which} class: "
                             f"the {field} seat takes {which} ({like})")
    low, high = _looked_up(field, iso286.limit_deviations, seat.symbol, nominal)
    return _band(nominal + low, nominal + high, "mm")


def chain_inputs(mounting: BearingMounting, bore: Any, outside: Any,
                 ring_modulus: Any, ring_poisson: Any) -> dict[str, Any]:
    """The chain's solver inputs (SI; arrays where a study varies a link): see
    :func:`bearingcalc.core.mounted_clearance.mounted_clearance`."""
    m = mounting
    shaft, housing = (_constants(material) for material in (m.shaft_material,
                                                             m.housing_material))
    roughness = m.roughness or Roughness()
    inner = m.assembly_temperature if m.inner_ring_temperature is None \
        else m.inner_ring_temperature
    outer = m.assembly_temperature if m.outer_ring_temperature is None \
        else m.outer_ring_temperature
    initial = m.clearance_group if m.clearance_group is not None else m.initial_clearance
    return {
        "initial_clearance": initial, "shaft_diameter": m.shaft,
        "bore_diameter": bore + m.bore_deviation, "housing_diameter": m.housing,
        "outside_diameter": outside + m.outside_deviation,
        "band_low": {name: low for name, (low, _) in m.bands().items()},
        "band_high": {name: high for name, (_, high) in m.bands().items()},
        "shaft_bore": m.shaft_bore,
        "housing_outside": math.inf if m.housing_outside_diameter is None
        else m.housing_outside_diameter,
        "shaft_modulus": shaft[0], "shaft_poisson": shaft[1], "shaft_expansion": shaft[2],
        "housing_modulus": housing[0], "housing_poisson": housing[1],
        "housing_expansion": housing[2], "ring_modulus": ring_modulus,
        "ring_poisson": ring_poisson, "ring_expansion": m.ring_thermal_expansion,
        "shaft_roughness": roughness.shaft, "housing_roughness": roughness.housing,
        "assembly_temperature": m.assembly_temperature, "inner_ring_temperature": inner,
        "outer_ring_temperature": outer,
        "shaft_temperature": inner if m.shaft_temperature is None else m.shaft_temperature,
        "housing_temperature": outer if m.housing_temperature is None
        else m.housing_temperature}


def _constants(material: Any) -> tuple[float, float, float]:
    """E [Pa], ν and α [1/K] of a seat's material."""
    if isinstance(material, str):
        return NAMED_MATERIALS[material]
    return material.elastic_modulus, material.poisson_ratio, material.thermal_expansion


def mounting_in_place(bearing: Any) -> SpecFieldError | None:
    """A problem of a ``bearing``'s mounting in place of its operating clearance: given
    with it, for a bearing without one, or with seat bodies that do not fit the ring."""
    if bearing.operating_clearance is not None:
        return SpecFieldError("operating_clearance", "give the operating_clearance or "
                              "the mounting it follows from, not both")
    if bearing.type_traits.one_way or bearing.arrangement != "single":
        return SpecFieldError("mounting", f"is for a single bearing with a radial "
                              f"clearance (deep-groove, cylindrical, needle): a "
                              f"{bearing.type} bearing ({bearing.arrangement}) sits at its "
                              "contact angle or its pair's setting; leave mounting out")
    mounting = bearing.mounting
    if mounting.housing_outside_diameter is not None and bearing.outside_diameter is not None \
            and not mounting.housing_outside_diameter > bearing.outside_diameter:
        return SpecFieldError("mounting.housing_outside_diameter", f"must be larger than "
                              f"the bearing's outside diameter, "
                              f"{bearing.outside_diameter * 1e3:g} mm: the housing's wall "
                              "lies around the ring")
    if bearing.bore_diameter is not None and not mounting.shaft_bore < bearing.bore_diameter:
        return SpecFieldError("mounting.shaft_bore", f"must be smaller than the "
                              f"bearing's bore, {bearing.bore_diameter * 1e3:g} mm: a hollow "
                              "shaft's bore lies inside its seat (0: solid)")
    return None


class ClearanceLimitRules(SpecModel):
    """The least operating clearance is judged on the clearance a mounting gives."""

    @rule
    def _clearance_limit_needs_a_mounting(self) -> SpecFieldError | None:
        limits = getattr(self, "limits", None)
        if getattr(limits, "min_operating_clearance", None) is None:
            return None
        if getattr(self, "mounting", None) is None:
            return SpecFieldError("limits.min_operating_clearance", "is judged on the "
                                  "operating clearance a mounting gives: give mounting (and "
                                  "method: iso-16281), or leave it out")
        return None
