"""Spec of ``kind: bevel-gears``: the seed's epicyclic bevel pair (docs/physics.md §4)."""

from __future__ import annotations

import math
from typing import Any, Literal

from pydantic import Field, model_validator

from bearingcalc.errors import SpecFieldError
from bearingcalc.spec.fields import (
    Angle,
    AngularSpeed,
    PositiveLength,
    Ratio,
    SpecModel,
    ToothCount,
)


class Gear(SpecModel):
    teeth: ToothCount | None = None
    pitch_radius: PositiveLength | None = None
    pitch_angle: Angle | None = Field(None, description="pitch-cone half-angle; usually "
                                      "left out and solved from the shaft angle")


class BevelGearsLimits(SpecModel):
    max_apex_mismatch: Ratio = Field(0.001, description="largest allowed "
                                     "|b·sinα/(a·sinβ) − 1|")


class BevelGearsSpec(SpecModel):
    """Gear B on a shaft turning at Ω; gear A meshing with it on an arm turning at ω_Z."""

    kind: Literal["bevel-gears"]
    name: str | None = None
    gear_a: Gear
    gear_b: Gear
    module: PositiveLength | None = Field(None, description="module m: pitch radius = m·teeth/2")
    shaft_angle: Angle | None = Field(None, description="shaft angle γ between the gear axes")
    arm_speed: AngularSpeed = Field(description="ω_Z, the arm carrying gear A")
    gear_b_speed: AngularSpeed = Field(0.0, description="Ω, gear B's shaft")
    limits: BevelGearsLimits = BevelGearsLimits()

    @model_validator(mode="after")
    def _geometry_is_determined(self) -> BevelGearsSpec:
        for label, gear in (("gear_a", self.gear_a), ("gear_b", self.gear_b)):
            if gear.pitch_radius is None and gear.teeth is None:
                raise SpecFieldError(label, f"give {label}.pitch_radius, or {label}.teeth "
                                     "with module")
            if gear.pitch_radius is None and self.module is None:
                raise SpecFieldError("module", f"{label}.teeth without a pitch radius needs "
                                     "the module, e.g. module: 2 mm")
            if gear.pitch_radius is not None and gear.teeth is not None and self.module:
                from_teeth = self.module * gear.teeth / 2.0
                if not math.isclose(gear.pitch_radius, from_teeth, rel_tol=1e-9):
                    raise SpecFieldError(
                        f"{label}.pitch_radius",
                        f"disagrees with module × teeth / 2 = {from_teeth * 1e3:g} mm; "
                        "give one or make them agree")
        a, b = self.gear_a, self.gear_b
        if (self.module is None and None not in (a.teeth, b.teeth, a.pitch_radius, b.pitch_radius)
                and not math.isclose(a.pitch_radius * b.teeth, b.pitch_radius * a.teeth,
                                     rel_tol=1e-9)):
            # Meshing gears share a module, so their pitch radii are in the ratio of teeth.
            raise SpecFieldError(
                "gear_b.teeth", f"the teeth ({a.teeth}/{b.teeth}) disagree with the pitch radii "
                f"({a.pitch_radius * 1e3:g} mm/{b.pitch_radius * 1e3:g} mm): meshing gears "
                "have pitch radii in the ratio of their teeth; leave the teeth or the radii "
                "out, or make them agree")
        if self.shaft_angle is None and (self.gear_a.pitch_angle is None
                                         or self.gear_b.pitch_angle is None):
            raise SpecFieldError("shaft_angle", "missing: give shaft_angle (90 deg for the "
                                 "usual right-angle pair), or both pitch angles")
        return self

    def solver_inputs(self) -> dict[str, Any]:
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
            "arm_speed": self.arm_speed,
            "gear_b_speed": self.gear_b_speed,
            "max_apex_mismatch": self.limits.max_apex_mismatch,
        }
