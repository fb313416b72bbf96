"""Spec of ``kind: bevel-gears``: a bevel pair on fixed axes, or an epicyclic one
(docs/physics.md §4)."""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from typing import TYPE_CHECKING, Any, ClassVar, Literal

from pydantic import Field

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import Spec, SpecModel
from bearingcalc.models.bevel_blank import (
    BLANK_FIELDS,
    AddendumFactor,
    BlankRules,
    CutterRadius,
    DedendumFactor,
    EdgeRadius,
    ProfileShift,
    Taper,
    Thickness,
)
from bearingcalc.models.bevel_pair_rules import PairRules
from bearingcalc.models.bevel_rating import BevelRating, rating_inputs
from bearingcalc.models.duty import DutyCycleRules, bin_model
from bearingcalc.models.plain_numbers import Ratio, ToothCount
from bearingcalc.models.quantities import (
    Angle,
    AngularSpeed,
    PositiveLength,
    PositivePower,
    Torque,
)
from bearingcalc.models.rules import rule, whole_spec_rule

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import BevelGearsInputs


class Gear(SpecModel):
    teeth: ToothCount | None = None
    pitch_radius: PositiveLength | None = None
    pitch_angle: Angle | None = Field(None, description="pitch-cone half-angle; usually "
                                      "left out and solved from the shaft angle")


class BevelGearsLimits(SpecModel):
    max_apex_mismatch: Ratio = Field(0.001, description="largest allowed "
                                     "|b·sinα/(a·sinβ) − 1|")
    max_face_width_ratio: Ratio = Field(1 / 3, description="largest b/Re")
    min_bending_safety: Ratio = Field(1.0, description="smallest S_F")
    min_contact_safety: Ratio = Field(1.0, description="smallest S_H")


class BevelPair(BlankRules, PairRules, Spec):
    """The fields of a bevel pair, its sizing and its rating, shared by the kinds that
    hold one (``bevel-gears``, ``bevel-drive``)."""

    kind: str
    name: str | None = None
    gear_a: Gear
    gear_b: Gear
    module: PositiveLength | None = Field(None, description="module m: pitch radius = m·teeth/2")
    shaft_angle: Angle | None = Field(None, description="shaft angle γ between the gear axes")
    face_width: PositiveLength | None = Field(None, description="b; enables sizing")
    pressure_angle: Angle = Field(math.radians(20.0), description="φ, default 20 deg")
    torque: Torque | None = Field(None, description="on gear A (the pinion)")
    power: PositivePower | None = Field(None, description="through gear A, instead of torque")
    spiral_angle: Angle | None = Field(
        None, description="β_m at the mean point: a spiral bevel pair (0 for Zerol)")
    hand: Literal["left", "right"] | None = Field(
        None, description="hand of the pinion's spiral (gear B's is the other)")
    rotation: Literal["clockwise", "counterclockwise"] | None = Field(
        None, description="the pinion's, seen from its back (large end) toward the apex")
    rating: BevelRating | None = None
    # a spiral or Zerol pair's blank (ISO 23509): bevel_blank.BLANK_FIELDS
    profile_shift: ProfileShift = None
    thickness_modification: Thickness = None
    addendum_factor: AddendumFactor = 1.0
    dedendum_factor: DedendumFactor = 1.25
    tool_edge_radius: EdgeRadius = None
    cutter_radius: CutterRadius = None
    taper: Taper = None

    @property
    def thrust_sign(self) -> float:
        """s of the spiral forces: +1 for a right-hand pinion turning clockwise or a
        left-hand one turning counterclockwise (seen from its back), else −1."""
        return 1.0 if (self.hand == "right") == (self.rotation == "clockwise") else -1.0

    #: Inputs of the tooth geometry that AGMA 2003's geometry factors J and I depend on.
    TOOTH_GEOMETRY: ClassVar[tuple[str, ...]] = (
        "gear_a.teeth", "gear_b.teeth", "gear_a.pitch_radius", "gear_b.pitch_radius",
        "gear_a.pitch_angle", "gear_b.pitch_angle", "module", "pressure_angle",
        "face_width", "shaft_angle", "spiral_angle", *BLANK_FIELDS)

    def study_notes(self, varied: Collection[str]) -> list[str]:
        """J and I are typed for the spec's own tooth geometry: a study that varies that
        geometry rates every other design with them."""
        moved = [name for name in varied if name in self.TOOTH_GEOMETRY]
        if self.rating is None or not moved:
            return []
        return [f"the geometry factors J and I (rating.geometry_factor_bending, "
                f"rating.geometry_factor_pitting) are held at their typed values while "
                f"{', '.join(moved)} {'varies' if len(moved) == 1 else 'vary'}: the other "
                "designs are rated with the factors of the spec's own tooth geometry"]

    def pair_inputs(self, arm_speed: Any, gear_b_speed: Any, limits: BevelGearsLimits
                    ) -> dict[str, Any]:
        """SI inputs of :func:`bearingcalc.core.bevel_gears.evaluate`."""
        return {
            "gear_a_teeth": self.gear_a.teeth,
            "gear_b_teeth": self.gear_b.teeth,
            "module": self.module,
            "gear_a_pitch_radius": self.gear_a.pitch_radius,
            "gear_b_pitch_radius": self.gear_b.pitch_radius,
            "gear_a_pitch_angle": self.gear_a.pitch_angle,
            "gear_b_pitch_angle": self.gear_b.pitch_angle,
            "shaft_angle": self.shaft_angle,
            "arm_speed": arm_speed,
            "gear_b_speed": gear_b_speed,
            "max_apex_mismatch": limits.max_apex_mismatch,
            **self._sizing_inputs(limits),
        }

    def _sizing_inputs(self, limits: BevelGearsLimits) -> dict[str, Any]:
        rating = rating_inputs(self.rating)
        return {
            "face_width": self.face_width,
            "pressure_angle": self.pressure_angle,
            "torque": self.torque,
            "power": self.power,
            "spiral_angle": self.spiral_angle,
            "cutter_radius": self.face_cutter(),
            "thrust_sign": None if self.spiral_angle is None else self.thrust_sign,
            **{key: value for key, value in rating.items() if key != "cutter_radius"},
            **self.blank_inputs(),
            "max_face_width_ratio": limits.max_face_width_ratio,
            "min_bending_safety": limits.min_bending_safety,
            "min_contact_safety": limits.min_contact_safety,
        }


GearsBin = bin_model("GearsBin", {
    "torque": (Torque, "on gear A"), "power": (PositivePower, "through gear A"),
    "gear_a_speed": (AngularSpeed, "the pinion's speed (fixed axes)"),
    "arm_speed": (AngularSpeed, "ω_Z (epicyclic)"), "gear_b_speed": (AngularSpeed, "Ω")})

#: The speeds of the two forms of a pair, named in one line where a spec gives neither.
SPEED_FORMS = ("a pair on fixed axes takes gear_a_speed (the pinion's) or gear_b_speed; "
               "an epicyclic pair takes arm_speed (ω_Z) and gear_b_speed (its shaft, Ω)")


class BevelGearsSpec(DutyCycleRules, BevelPair):
    """A bevel pair on fixed axes, turning at the pinion's speed (or gear B's); or the
    epicyclic pair: gear B on a shaft turning at Ω, gear A meshing with it on an arm
    turning at ω_Z."""

    #: a bin's torque replaces the spec's power; on fixed axes, a bin's gear_a_speed the
    #: spec's gear_b_speed (an epicyclic pair takes no gear_a_speed)
    ALTERNATIVES: ClassVar[Mapping[str, str]] = {
        "torque": "power", "power": "torque", "gear_a_speed": "gear_b_speed",
        "gear_b_speed": "gear_a_speed"}
    POWER_FIELD: ClassVar[str | None] = "power"
    BIN_FIELDS: ClassVar[Mapping[str, str]] = {
        field: field for field in ("torque", "power", "gear_a_speed", "arm_speed",
                                   "gear_b_speed")}
    #: unknown key -> (what to say instead of a near name, the fields whose missing it
    #: covers): ``speed`` is near ``arm_speed`` and ``gear_a_speed``, which differ
    UNKNOWN_KEY_HINTS: ClassVar[Mapping[str, tuple[str, tuple[str, ...]]]] = {
        "speed": (SPEED_FORMS, ("gear_a_speed",))}

    kind: Literal["bevel-gears"]
    gear_a_speed: AngularSpeed | None = Field(
        None, description="the pinion's speed, of a pair on fixed axes")
    arm_speed: AngularSpeed | None = Field(
        None, description="ω_Z, the arm carrying gear A: an epicyclic pair")
    gear_b_speed: AngularSpeed | None = Field(
        None, description="gear B's speed: its shaft's Ω in an epicyclic pair (0 by "
        "default)")
    limits: BevelGearsLimits = BevelGearsLimits()
    duty_cycle: list[GearsBin] | None = Field(  # type: ignore[valid-type]
        None, description="load cases with their shares of the time, for the strength "
        "rating (a field a bin leaves out is the spec's)")

    @property
    def fixed_axes(self) -> bool:
        """Whether the pair's axes are fixed (no arm)."""
        return self.arm_speed is None

    def speeds(self) -> tuple[Any, Any]:
        """(ω_Z, Ω) of the epicyclic form; a pair on fixed axes has a resting arm and gear B
        at the speed that turns the pinion at gear_a_speed. [rad/s]"""
        if not self.fixed_axes:
            return self.arm_speed, 0.0 if self.gear_b_speed is None else self.gear_b_speed
        if self.gear_a_speed is None:
            return 0.0, self.gear_b_speed
        return 0.0, -self.gear_a_speed * self._ratio()

    def _ratio(self) -> float:
        """a/b, gear A's pitch radius over gear B's (their teeth's ratio)."""
        a, b = self.gear_a, self.gear_b
        if a.teeth is not None and b.teeth is not None:
            return a.teeth / b.teeth
        return a.pitch_radius / b.pitch_radius  # type: ignore[operator]

    @rule
    def _turning_given(self) -> SpecFieldError | None:
        if not self.fixed_axes:
            if self.gear_a_speed is not None:
                return SpecFieldError("gear_a_speed", "is of a pair on fixed axes; an "
                                      "epicyclic pair (with arm_speed) takes gear_b_speed, "
                                      "its shaft's speed Ω")
            return None
        if self.gear_a_speed is None and self.gear_b_speed is None:
            return SpecFieldError("gear_a_speed", f"missing: {SPEED_FORMS}")
        if self.gear_a_speed is not None and self.gear_b_speed is not None:
            return SpecFieldError("gear_b_speed", "a pair on fixed axes takes one speed: "
                                  "gear_a_speed or gear_b_speed, not both",
                                  at="gear_a_speed")
        return None

    def turning_speed(self) -> Any:
        """The pinion's speed relative to its arm, ω_AS = (b/a)(ω_Z − Ω); None where the
        spec gives no speed. [rad/s]"""
        if self.fixed_axes and self.gear_a_speed is None and self.gear_b_speed is None:
            return None
        arm, shaft = self.speeds()
        return (arm - shaft) / self._ratio()

    def with_turning_speed(self, speed: Any) -> BevelGearsSpec:
        """The pair with its pinion at ``speed`` relative to its arm, in the spec's form."""
        if self.fixed_axes:
            return self.model_copy(update={"gear_a_speed": speed, "gear_b_speed": None})
        return self.model_copy(update={"arm_speed": speed * self._ratio(),
                                       "gear_b_speed": 0.0})

    @whole_spec_rule
    def _bins_keep_the_form(self) -> SpecFieldError | None:
        """A bin cannot turn a pair on fixed axes into an epicyclic one, or back."""
        for k, item in enumerate(self.duty_cycle or [], 1):
            if self.fixed_axes and item.arm_speed is not None:
                return SpecFieldError(f"duty_cycle.{k}.arm_speed", f"bin {self.bin_label(k)}: "
                                      "the pair is on fixed axes (the spec gives no "
                                      "arm_speed): give the bin's gear_a_speed")
            if not self.fixed_axes and item.gear_a_speed is not None:
                return SpecFieldError(f"duty_cycle.{k}.gear_a_speed", f"bin "
                                      f"{self.bin_label(k)}: the pair is epicyclic: give the "
                                      "bin's arm_speed or gear_b_speed")
        return None

    @whole_spec_rule
    def _cycle_rated(self) -> SpecFieldError | None:
        if self.duty_cycle is not None and self.rating is None:
            return SpecFieldError("duty_cycle", "a duty cycle is for the strength rating: "
                                  "give face_width, torque or power, and rating too")
        return None

    def solver_inputs(self) -> BevelGearsInputs:
        """SI inputs of :func:`bearingcalc.core.bevel_gears.evaluate`: of the operating
        point, or of every bin of the duty cycle."""
        if self.duty_cycle is not None:
            return self.cycle_inputs()
        inputs = self.pair_inputs(*self.speeds(), self.limits)
        inputs["axes"] = "fixed" if self.fixed_axes else "epicyclic"
        return inputs
