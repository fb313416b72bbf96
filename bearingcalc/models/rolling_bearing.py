"""Spec of ``kind: rolling-bearing`` (and its alias ``kind: ball-bearing``): ISO 281
rating life and ISO 76 static safety of ball and roller bearings (``docs/physics.md``
§5)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Annotated, Any, ClassVar, Literal

import numpy as np
from pydantic import BeforeValidator, Field, StringConstraints, WithJsonSchema

from bearingcalc.core.bearing_types import SPEC_NAMES, BearingTraits, traits, type_name
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import Spec, SpecModel
from bearingcalc.models.bearing_estimate import GeometryEstimate
from bearingcalc.models.bearing_geometry_rules import GeometryRules
from bearingcalc.models.bearing_limits import BallBearingLimits
from bearingcalc.models.bearing_load_rules import LoadFactorRules, LoadRules
from bearingcalc.models.bearing_method_rules import (
    MOUNTED_LIMITS,
    MethodRules,
    MountingFields,
)
from bearingcalc.models.bearing_mounting import ClearanceLimitRules
from bearingcalc.models.bearing_operating_rules import (
    ArrangementRules,
    LubricationRules,
    OperatingRules,
)
from bearingcalc.models.bearing_pair_rules import PairRules
from bearingcalc.models.bearing_rating_rules import AngleRules, RatingRules
from bearingcalc.models.duty import (
    OIL_BIN_FIELDS,
    OIL_BIN_PATHS,
    BinOilRules,
    DutyCycleRules,
    bin_model,
)
from bearingcalc.models.element_fit_rules import ElementFitRules
from bearingcalc.models.lubrication import Lubrication
from bearingcalc.models.materials import ElasticMaterial
from bearingcalc.models.plain_numbers import (
    BallCount,
    Ratio,
    RollerCount,
    ranged_number,
    reliability,
    whole_choice,
)
from bearingcalc.models.quantities import (
    Angle,
    AngularSpeed,
    Conformity,
    Force,
    PositiveForce,
    PositiveLength,
)
from bearingcalc.models.rules import rule

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import RollingBearingInputs

RELIABILITY_RANGE = (0.90, 0.9995)
#: ISO 76:2006 6.1: the contact pressure at C0 of a ball and of a roller bearing [Pa].
ISO_76_PRESSURE = 4.2e9
ISO_76_ROLLER_PRESSURE = 4.0e9
#: How far a given pitch diameter may lie from (d + D)/2 before it is questioned: real
#: bearings are not exactly symmetric, but a larger offset is usually a typing slip.
PITCH_OFF_CENTRE = 0.05
#: The spec's spellings of the bearing types (:mod:`bearingcalc.core.bearing_types`).
BearingType = Literal[SPEC_NAMES]  # type: ignore[valid-type]
Arrangement = Literal["single", "back-to-back", "face-to-face", "tandem"]


Reliability = reliability(*RELIABILITY_RANGE, "ISO 281's range for a1")
RollerRows = whole_choice(1, 2)

UnitFraction = ranged_number(0.0, 1.0, "a fraction", "0.5")


def _designation_text(value: Any) -> Any:
    """YAML reads ``designation: 6205`` as a number: it means the same as '6205'."""
    if isinstance(value, int) and not isinstance(value, bool):
        return str(value)
    return value


Designation = Annotated[str, BeforeValidator(_designation_text),
                        StringConstraints(strip_whitespace=True, min_length=1, max_length=100),
                        WithJsonSchema({"anyOf": [{"type": "string", "minLength": 1,
                                                   "maxLength": 100},
                                                  {"type": "integer", "minimum": 0}]})]


class LoadFactors(SpecModel):
    """Catalogue X, Y, e (and X0, Y0) in place of ISO 281's and ISO 76's tables. A ball
    bearing takes x, y, e; a single-row roller bearing e and y (the Y above e); a double
    row, a back-to-back or face-to-face pair, or a self-aligning ball bearing e, y1, y2."""

    x: Ratio | None = Field(None, description="radial factor X (above e)")
    y: Ratio | None = Field(None, description="axial factor Y (above e)")
    e: Ratio | None = Field(None, description="limit of Fa/Fr between the two sets of "
                            "factors")
    y1: Ratio | None = Field(None, description="double row: Y for Fa/Fr <= e (X = 1)")
    y2: Ratio | None = Field(None, description="double row: Y for Fa/Fr > e")
    x0: Ratio | None = Field(None, description="static radial factor X0")
    y0: Ratio | None = Field(None, description="static axial factor Y0")


class BearingFields(SpecModel):
    """What a rolling bearing is, apart from how it is loaded and run: its type,
    arrangement, catalogue ratings, internal geometry, load factors, grooves, material
    and race control. ``kind: rolling-bearing`` adds loads, speeds and lubrication; a
    drive's bearing entry (``kind: bevel-drive``) adds its position on the shaft."""

    designation: Designation | None = Field(
        None, description="the catalogue's designation, like 6205-2RS: the row fills every "
        "rating and dimension the spec leaves out")
    maker: str | None = Field(None, description="the maker whose catalogue row to take, "
                              "where the catalogue has the designation from several")
    type: BearingType = "deep-groove"
    arrangement: Arrangement = Field("single", description="a matched pair of single-row "
                                     "angular-contact ball or tapered roller bearings")
    dynamic_load_rating: PositiveForce | None = Field(None, description="C, catalogue")
    static_load_rating: PositiveForce | None = Field(None, description="C0, catalogue")
    fatigue_load_limit: PositiveForce | None = Field(None, description="Cu, catalogue")
    static_factor: Ratio | None = Field(None, description="f0 from the catalogue")
    ball_count: BallCount | None = None
    ball_diameter: PositiveLength | None = Field(None, description="Dw")
    pitch_diameter: PositiveLength | None = Field(None, description="Dpw")
    bore_diameter: PositiveLength | None = Field(None, description="d (for dm only)")
    outside_diameter: PositiveLength | None = Field(None, description="D (for dm only)")
    width: PositiveLength | None = Field(None, description="B (T of a tapered bearing, H of "
                                         "a thrust bearing); select's widest")
    roller_count: RollerCount | None = Field(None, description="Z, per row")
    roller_diameter: PositiveLength | None = Field(None, description="Dwe (a tapered "
                                                   "roller's mean diameter)")
    roller_length: PositiveLength | None = Field(None, description="Lwe, the effective "
                                                 "contact length")
    rows: RollerRows = Field(1, description="i, the rows of rollers")
    drawn_cup: bool = Field(False, description="a drawn-cup needle roller bearing (outer "
                            "ring drawn from sheet): bm = 1.0, ISO 281 Table 1")
    roller_profile_radius: PositiveLength | None = Field(
        None, description="a spherical roller's crown radius")
    raceway_radius: PositiveLength | None = Field(
        None, description="a spherical roller bearing's raceway radius across the rolling "
        "direction")
    contact_angle: Angle | None = Field(None, description="α; 0 deg for deep-groove, "
                                        "cylindrical and needle, 90 deg for thrust by "
                                        "default")
    race_control: Literal["outer", "inner"] = Field(
        "outer", description="the race at which the ball does not spin (Jones)")
    load_factors: LoadFactors | None = None
    inner_groove_conformity: Conformity | None = Field(
        None, description="fi = inner groove radius / Dw (> 0.5)")
    outer_groove_conformity: Conformity | None = Field(
        None, description="fo = outer groove radius / Dw (> 0.5)")
    material: ElasticMaterial = ElasticMaterial()

    @property
    def type_traits(self) -> BearingTraits:
        """What the bearing's type is: its family, rows, angle, ratings, load factors."""
        return traits(self.type)

    @rule
    def _drawn_cup_needles(self) -> SpecFieldError | None:
        if self.drawn_cup and not self.type_traits.drawn_cup:
            return SpecFieldError("drawn_cup", f"a drawn cup is a needle roller bearing's "
                                  f"outer ring: use type: needle-roller, or leave drawn_cup "
                                  f"out of a {self.type} bearing")
        return None

    @rule
    def _maker_of_a_designation(self) -> SpecFieldError | None:
        if self.maker is not None and self.designation is None:
            return SpecFieldError("maker", "names whose catalogue row to take: give the "
                                  "designation too, like designation: 6205")
        return None


BearingBin = bin_model("BearingBin", {
    "radial_load": (Force, "Fr"), "axial_load": (Force, "Fa"),
    "speed": (AngularSpeed, "the rotating ring relative to the other; 0: at rest"),
    "inner_speed": (AngularSpeed, "inner ring, fixed frame"),
    "outer_speed": (AngularSpeed, "outer ring, fixed frame"), **OIL_BIN_FIELDS})


class RollingBearingSpec(ClearanceLimitRules, MethodRules, PairRules, GeometryEstimate, BinOilRules,
                         DutyCycleRules, ElementFitRules, LubricationRules, ArrangementRules,
                         LoadFactorRules, LoadRules, OperatingRules, AngleRules, RatingRules,
                         GeometryRules, MountingFields, BearingFields, Spec):
    """A rolling bearing sized by ISO 281 (life) and ISO 76 (static safety), at one
    operating point or over a duty cycle."""

    BIN_FIELDS: ClassVar[Mapping[str, str]] = {
        "radial_load": "radial_load", "axial_load": "axial_load", "speed": "speed",
        "inner_speed": "inner_speed", "outer_speed": "outer_speed", **OIL_BIN_PATHS}
    #: a bin's ring speeds replace the spec's speed, and its speed the spec's ring speeds
    ALTERNATIVES: ClassVar[Mapping[str, str | tuple[str, ...]]] = {
        "speed": ("inner_speed", "outer_speed"), "inner_speed": "speed",
        "outer_speed": "speed"}

    CATALOGUE_PLACES: ClassVar[tuple[str, ...]] = ("",)

    kind: Literal["rolling-bearing", "ball-bearing"]
    name: str | None = None
    catalogue: str | None = Field(None, description="a catalogue file (CSV), relative to "
                                  "the spec, for designation")
    radial_load: Force = Field(0.0, description="Fr")
    axial_load: Force = Field(0.0, description="Fa")
    speed: AngularSpeed | None = Field(None, description="the rotating ring relative to the "
                                       "other (inner turning, outer fixed)")
    inner_speed: AngularSpeed | None = Field(None, description="inner ring, fixed frame")
    outer_speed: AngularSpeed | None = Field(None, description="outer ring, fixed frame")
    reliability: Reliability = 0.9
    lubrication: Lubrication | None = None
    contamination_factor: UnitFraction | None = Field(None, description="eC, 0 to 1")
    limits: BallBearingLimits = BallBearingLimits()
    duty_cycle: list[BearingBin] | None = Field(  # type: ignore[valid-type]
        None, description="load cases with their shares of the time, in place of one "
        "operating point (a field a bin leaves out is the spec's)")

    def turning_speed(self) -> Any:
        """The speed whose revolutions the life counts: the rings' relative speed; None
        where the spec gives no speed."""
        if self.speed is None and self.inner_speed is None and self.outer_speed is None:
            return None
        return self.relative_speed

    def with_turning_speed(self, speed: Any) -> RollingBearingSpec:
        """The bearing with its inner ring at ``speed`` and its outer ring fixed."""
        return self.model_copy(update={"speed": speed, "inner_speed": None, "outer_speed": None})

    @property
    def angle(self) -> float:
        """α used. [rad]"""
        if self.contact_angle is not None:
            return self.contact_angle
        own = self.type_traits.contact_angle
        return 0.0 if own is None else own

    @property
    def relative_speed(self) -> Any:
        """n, the rotating ring relative to the other: ``speed`` or |inner − outer|. [rad/s]"""
        if self.speed is not None:
            return self.speed
        return np.abs(self.ring_speeds[0] - self.ring_speeds[1])

    @property
    def ring_speeds(self) -> tuple[Any, Any]:
        """(inner, outer) ring speeds in the fixed frame; ``speed`` alone turns the inner
        ring with the outer fixed, and a ring speed left out is 0. [rad/s]"""
        if self.speed is not None:
            return self.speed, 0.0
        return (0.0 if self.inner_speed is None else self.inner_speed,
                0.0 if self.outer_speed is None else self.outer_speed)

    @property
    def rollers(self) -> bool:
        """Whether the rolling elements are rollers."""
        return self.type_traits.family == "roller"

    @property
    def has_geometry(self) -> bool:
        """The rolling elements' count and diameter (and a roller's length) and a pitch
        diameter (given, or the rings' mean), or their estimate as mounted."""
        if self.rollers and not self.estimated_inputs():
            return None not in (self.roller_count, self.roller_diameter, self.roller_length,
                                self.mean_diameter)
        return bool(self.estimated_inputs()) or None not in (
            self.ball_count, self.ball_diameter, self.mean_diameter)

    @property
    def mean_diameter(self) -> float | None:
        """dm for ν1 and Cu: Dpw, else (d + D)/2. [m]"""
        if self.pitch_diameter is not None:
            return self.pitch_diameter
        if self.bore_diameter is not None and self.outside_diameter is not None:
            return 0.5 * (self.bore_diameter + self.outside_diameter)
        return None

    def lubrication_note(self) -> str | None:
        """What the modified life leaves out without lubrication (a drive gives its
        bearings its own lubrication, and says this once)."""
        if self.lubrication is not None:
            return None
        return ("no lubrication given: aISO = 1, so the modified life ignores "
                "lubrication and contamination")

    def warnings(self) -> list[str]:
        """What the reader should know about how the results were found."""
        notes = []
        catalogue = [name for name in ("dynamic_load_rating", "static_load_rating")
                     if getattr(self, name) is not None]
        if catalogue and self.has_geometry:
            notes.append(f"catalogue {' and '.join(catalogue)} used for the results; the "
                         "ISO values from the geometry are reported as *_iso")
        lubrication = self.lubrication_note()
        if lubrication is not None:
            notes.append(lubrication)
        static = self.static_left_out()
        if static is not None:
            notes.append(static)
        notes += self.roller_notes() + self.element_notes() + self.estimate_notes()
        envelope = self._envelope_mm()
        if envelope is not None:
            middle = (envelope[0] + envelope[1]) / 2
            if self.pitch_diameter is None and self.has_geometry and not self.estimates_geometry:
                notes.append(f"no pitch_diameter: the geometry takes the rings' mean "
                             f"(d + D)/2 = {middle:g} mm")
            elif self.pitch_diameter is not None and abs(
                    self.pitch_diameter * 1e3 - middle) > PITCH_OFF_CENTRE * middle:
                notes.append(f"pitch_diameter {self.pitch_diameter * 1e3:g} mm is more than "
                             f"{PITCH_OFF_CENTRE:.0%} from the rings' mean (d + D)/2 = "
                             f"{middle:g} mm: check it against the catalogue")
        return notes

    def static_left_out(self) -> str | None:
        """Why the static results are left out, or None: no C0, from the catalogue or the
        geometry."""
        if self.static_load_rating is not None:
            return None
        if self.type_traits.family == "ball" and self.type_traits.thrust:
            return ("no static_load_rating: ISO 76's thrust f0 is not implemented, so the "
                    "static results are left out")
        if not self.has_geometry:
            return ("no static_load_rating (or geometry): the static results are left "
                    "out")
        return None

    def solver_inputs(self) -> RollingBearingInputs:
        """SI inputs of :func:`bearingcalc.core.rolling_bearing.evaluate`: of the
        operating point, or of every bin of the duty cycle."""
        if self.duty_cycle is not None:
            return self.cycle_inputs()
        lubrication = self.lubrication
        factors = self.load_factors
        return {
            "bearing_type": type_name(self.type),
            "arrangement": self.arrangement,
            "dynamic_load_rating": self.dynamic_load_rating,
            "static_load_rating": self.static_load_rating,
            "fatigue_load_limit": self.fatigue_load_limit,
            "static_factor": self.static_factor,
            "ball_count": self.ball_count,
            "ball_diameter": self.ball_diameter,
            **self._roller_inputs(),
            "pitch_diameter": self.mean_diameter,
            "mean_diameter": self.mean_diameter,
            "contact_angle": self.angle,
            "radial_load": self.radial_load,
            "axial_load": self.axial_load,
            "speed": self.relative_speed,
            "inner_speed": self.ring_speeds[0],
            "outer_speed": self.ring_speeds[1],
            "race_control": self.race_control,
            "max_spin_to_roll": self.limits.max_spin_to_roll,
            "reliability": self.reliability,
            **{name: getattr(lubrication, name) if lubrication else None
               for name in ("viscosity", "viscosity_40", "viscosity_100", "temperature")},
            "ep_additives": lubrication.ep_additives if lubrication else False,
            "contamination_factor": self.contamination_factor,
            **{f"load_{name}": getattr(factors, name) if factors else None
               for name in ("x", "y", "e", "y1", "y2", "x0", "y0")},
            "min_rating_life": self.limits.min_rating_life,
            "min_static_safety": self.limits.min_static_safety,
            "inner_groove_conformity": self.inner_groove_conformity,
            "outer_groove_conformity": self.outer_groove_conformity,
            "elastic_modulus": self.material.elastic_modulus,
            "poisson_ratio": self.material.poisson_ratio,
            "max_contact_pressure": self.contact_pressure_limit,
            **self.mounting_inputs(),
            **{name: getattr(self.limits, name) for name in MOUNTED_LIMITS},
        }

    def field_as_written(self, field: str) -> str:
        """A clearance refused as mounted is the mounting's where the spec gives one."""
        return "mounting" if field == "operating_clearance" and self.mounting is not None \
            else field

    @property
    def contact_pressure_limit(self) -> float:
        """The limit given, else ISO 76's pressure at C0 for the rolling elements. [Pa]"""
        if self.limits.max_contact_pressure is not None:
            return self.limits.max_contact_pressure
        return ISO_76_ROLLER_PRESSURE if self.rollers else ISO_76_PRESSURE

    def _roller_inputs(self) -> dict[str, Any]:
        """The roller bearing's own solver inputs; none for a ball bearing, whose results
        do not depend on them."""
        if not self.rollers:
            return {}
        spherical = self.type_traits.crowned
        return {"roller_count": self.roller_count, "roller_diameter": self.roller_diameter,
                "roller_length": self.roller_length, "rows": self.rows,
                "drawn_cup": self.drawn_cup,
                "roller_profile_radius": self.roller_profile_radius if spherical else None,
                "raceway_radius": self.raceway_radius if spherical else None}
