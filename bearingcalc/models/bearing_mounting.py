"""A bearing's ``mounting``: how it sits on the drawing (its clearance group, its seats'
ISO 286 classes, its ISO 492 tolerance class, the seats' bodies and materials, the
temperatures), from which ISO/TS 16281's method finds the operating clearance
(:mod:`bearingcalc.core.mounted_clearance`, ``docs/physics.md``, the mounting chain).

Every band of the chain (the group's clearance, each seat's class, the ring's bore and
outside) becomes a toleranced value at the band's middle, uniform over it, so that
tolerance studies vary it as any toleranced field, by its own name
(``mounting.shaft``), and a study's corner may write a plain value there.
"""

from __future__ import annotations

from typing import Any

from pydantic import Field, PrivateAttr

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import SpecModel
from bearingcalc.models.mounting_fields import (
    GROUPS_WORDS,
    ClearanceGroup,
    Material,
    NonNegativeLength,
    Roughness,
    Seat,
    ToleranceClass,
    band_ends,
)
from bearingcalc.models.quantities import (
    Length,
    PositiveLength,
    Temperature,
    ThermalExpansion,
)
from bearingcalc.models.rules import rule

#: The assembly's temperature where the spec gives none: 20 °C, ISO 1's reference.
ASSEMBLY_TEMPERATURE = 293.15
#: Bearing steel's expansion coefficient where the spec gives none [1/K].
RING_EXPANSION = 11.5e-6
#: The temperatures a bearing runs at [K]: bearing steel keeps its hardness to some
#: 150 °C (stabilised to 300 °C), and no lubricant holds far below −60 °C.
COLDEST, HOTTEST = 273.15 - 100.0, 273.15 + 400.0


class BearingMounting(SpecModel):
    """How the bearing sits on the drawing: the chain to its operating clearance."""

    clearance_group: ClearanceGroup | None = Field(
        None, description=f"ISO 5753-1's radial clearance group: {GROUPS_WORDS}")
    initial_clearance: Length | None = Field(
        None, description="the unmounted bearing's radial clearance, in place of a group, "
        "like 15 µm ± 5 µm")
    tolerance_class: ToleranceClass = Field(
        "normal", description="the bearing's ISO 492 tolerance class: normal, 6 or 5")
    bore_deviation: Length | None = Field(
        None, description="the ring's mean bore less its nominal (default: the tolerance "
        "class's band, Δdmp)")
    outside_deviation: Length | None = Field(
        None, description="the ring's mean outside less its nominal (default: the class's "
        "band, ΔDmp)")
    shaft: Seat | None = Field(None, description="the shaft seat's ISO 286 class, like k5 "
                               "(or 40 k5), or its diameter with its tolerance")
    housing: Seat | None = Field(None, description="the housing seat's ISO 286 class, like "
                                 "H7, or its diameter with its tolerance")
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
    assembly_temperature: Temperature = Field(
        ASSEMBLY_TEMPERATURE, description="where the drawing's dimensions hold and the parts "
        "come to rest together (ISO 1's 20 °C), not a heating temperature for mounting")
    ring_thermal_expansion: ThermalExpansion = Field(
        RING_EXPANSION, description="the rings' and elements' α (bearing steel's)")

    #: each band's [low, high], by the chain's link (set as the mounting is resolved)
    _bands: dict[str, tuple[float, float]] = PrivateAttr(default_factory=dict)
    #: what the spec wrote of each class, for the notes
    _written: dict[str, str] = PrivateAttr(default_factory=dict)
    #: what the tables refused as the mounting was resolved, for its rules to say
    _refused: list[SpecFieldError] = PrivateAttr(default_factory=list)
    #: the bearing's (bore, outside, type) it was resolved at, and the mounting as
    #: written: a design of another size (a sweep, a catalogue's row) resolves it anew
    _resolved_at: tuple[float, float, str] | None = PrivateAttr(default=None)
    _written_form: Any = PrivateAttr(default=None)

    @rule
    def _given_in_full(self) -> list[SpecFieldError]:
        problems = []
        if self.clearance_group is not None and self.initial_clearance is not None:
            problems.append(SpecFieldError("initial_clearance", "give a clearance_group or "
                                           "the initial_clearance, not both"))
        for seat, like in (("shaft", "k5"), ("housing", "H7")):
            if getattr(self, seat) is None:
                problems.append(SpecFieldError(seat, f"missing: give the {seat} seat's ISO "
                                               f"286 class, like {seat}: {like}, or its "
                                               "diameter with its tolerance"))
        return problems + list(self._refused)

    @rule
    def _temperatures_a_bearing_runs_at(self) -> list[SpecFieldError]:
        low, high = COLDEST - 273.15, HOTTEST - 273.15
        return [SpecFieldError(name, f"{value - 273.15:.6g} °C is no temperature a bearing "
                               f"runs or is assembled at: give one from {low:g} °C to "
                               f"{high:g} °C")
                for name in ("inner_ring_temperature", "outer_ring_temperature",
                             "shaft_temperature", "housing_temperature",
                             "assembly_temperature")
                if (value := getattr(self, name)) is not None
                and not COLDEST <= value <= HOTTEST]

    def bands(self) -> dict[str, tuple[float, float]]:
        return dict(self._bands)

    def written_classes(self) -> dict[str, str]:
        return dict(self._written)


#: A hollow shaft's largest bore, a share of its seat's diameter: a thinner wall is no
#: seat a ring is pressed onto.
THINNEST_WALL_RATIO = 0.95
#: A deviation from a nominal diameter beyond 0.2 mm and 1 % of it is a slip: ISO 286's
#: widest bands here (grade 12, and the fundamental deviations up to grade 8) stay
#: inside it, as every ISO 492 band does.
SLIP_MM, SLIP_SHARE = 0.2e-3, 0.01


#: The arrangements of a pair set against itself, whose end play a mounting moves.
ADJUSTED = ("back-to-back", "face-to-face")


def mounting_in_place(bearing: Any, adjusted: bool = False) -> list[SpecFieldError]:
    """The problems of a ``bearing``'s mounting in place of its operating clearance (of
    its pair's end play, where it is a one-way bearing ``adjusted`` against another, or
    a pair itself): given with it, for a bearing without one, without the ring's
    diameters, or with bands and bodies that do not fit the ring."""
    if bearing.operating_clearance is not None:
        return [SpecFieldError("operating_clearance", "give the operating_clearance or the "
                               "mounting it follows from, not both")]
    one_way = bearing.type_traits.one_way
    if bearing.arrangement in ADJUSTED or (adjusted and one_way):
        problems = _pair_mounting(bearing.mounting)
    elif one_way or bearing.arrangement != "single":
        return [SpecFieldError("mounting", f"is for a bearing with a radial clearance "
                               f"(deep-groove, cylindrical, needle), or a pair set against "
                               f"itself (back-to-back, face-to-face): this {bearing.type} "
                               f"bearing ({bearing.arrangement}) sits at its contact angle; "
                               "leave mounting out")]
    else:
        problems = _clearance_given(bearing.mounting)
    if bearing.drawn_cup:
        return [SpecFieldError("mounting", "a drawn-cup needle roller bearing has no inner "
                               "ring and a cup pressed to the housing's bore: its clearance "
                               "is the shaft's and the housing's, not ISO 5753-1's; give "
                               "operating_clearance")]
    bore, outside = bearing.bore_diameter, bearing.outside_diameter
    if bore is None or outside is None:
        return [SpecFieldError("bore_diameter" if bore is None else "outside_diameter",
                               "missing: a bearing's mounting takes its bore_diameter and "
                               "outside_diameter (or a designation)", at="mounting")]
    return [*problems, *_bodies_fit(bearing.mounting, bore, outside), *_no_slips(bearing)]


def _clearance_given(mounting: BearingMounting) -> list[SpecFieldError]:
    """A bearing alone takes its clearance from its group or as given."""
    if mounting.clearance_group is None and mounting.initial_clearance is None:
        return [SpecFieldError("mounting.clearance_group", f"missing: give the bearing's "
                               f"clearance_group ({GROUPS_WORDS}) or its initial_clearance, "
                               "like 15 µm ± 5 µm")]
    return []


def _pair_mounting(mounting: BearingMounting) -> list[SpecFieldError]:
    """A pair set against itself has its setting's end play, not a clearance of its
    own."""
    return [SpecFieldError(f"mounting.{field}", "a pair set against itself has no radial "
                           "clearance of its own: its setting's end_play (or preload) is "
                           "where the chain starts; leave it out")
            for field in ("clearance_group", "initial_clearance")
            if getattr(mounting, field) is not None]


def _bodies_fit(mounting: BearingMounting, bore: float, outside: float
                ) -> list[SpecFieldError]:
    """The housing's wall around the ring, the hollow shaft's inside its seat."""
    problems = []
    if mounting.housing_outside_diameter is not None and not (
            mounting.housing_outside_diameter > outside):
        problems.append(SpecFieldError(
            "mounting.housing_outside_diameter", f"must be larger than the bearing's outside "
            f"diameter, {outside * 1e3:g} mm: the housing's wall lies around the ring"))
    if not mounting.shaft_bore <= THINNEST_WALL_RATIO * bore:
        problems.append(SpecFieldError(
            "mounting.shaft_bore", f"must be at most {THINNEST_WALL_RATIO:g} of the "
            f"bearing's bore, {THINNEST_WALL_RATIO * bore * 1e3:.4g} mm: a hollow shaft's "
            "bore lies inside its seat with a wall around it (0: solid)"))
    return problems


def _no_slips(bearing: Any) -> list[SpecFieldError]:
    """Each band's ends within a slip's reach of its nominal, and the clearance's within
    what the rolling elements' grooves or rollers take."""
    mounting, problems = bearing.mounting, []
    for field, nominal, offset in (
            ("bore_deviation", bearing.bore_diameter, 0.0),
            ("outside_deviation", bearing.outside_diameter, 0.0),
            ("shaft", bearing.bore_diameter, bearing.bore_diameter),
            ("housing", bearing.outside_diameter, bearing.outside_diameter)):
        value = getattr(mounting, field)
        if not isinstance(value, float):
            continue
        reach = SLIP_MM + SLIP_SHARE * nominal
        if max(abs(end - offset) for end in band_ends(value)) > reach:
            problems.append(SpecFieldError(
                f"mounting.{field}", f"lies more than {reach * 1e3:.3g} mm from the "
                f"nominal {nominal * 1e3:g} mm: no seat or ring deviates that far (a unit "
                "slip?); give the deviation in µm, or the seat's class"))
    clearance = mounting.clearance_group if isinstance(mounting.clearance_group, float) \
        else mounting.initial_clearance
    largest = _largest_clearance(bearing)
    if clearance is not None and not max(
            abs(end) for end in band_ends(clearance)) < largest[0]:
        field = "clearance_group" if isinstance(mounting.clearance_group, float) \
            else "initial_clearance"
        problems.append(SpecFieldError(f"mounting.{field}", f"must be smaller in size than "
                                       f"{largest[1]}, {largest[0] * 1e6:.4g} µm"))
    return problems


def _largest_clearance(bearing: Any) -> tuple[float, str]:
    """The largest clearance the rolling elements take: a ball's grooves' distance
    (fi + fo − 1)·Dw, a tenth of a roller's diameter, 1 % of the bore where the geometry
    is to be estimated."""
    distance = bearing._groove_distance()
    if distance is not None:
        return distance, "the grooves' distance (fi + fo − 1)·Dw"
    if bearing.roller_diameter is not None:
        return 0.1 * bearing.roller_diameter, "a tenth of the roller's diameter"
    # the geometry estimated later: ISO 5753-1's C5 stays within 1 % of the bore
    return SLIP_SHARE * bearing.bore_diameter, "1 % of the bore, past any clearance group"


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
        if getattr(self, "arrangement", "single") in ADJUSTED:
            return SpecFieldError("limits.min_operating_clearance", "is judged on a single "
                                  "bearing's radial clearance: a pair set against itself "
                                  "runs at its operating_end_play (with its _min and _max "
                                  "over the bands), which no limit judges; leave it out")
        return None
