"""The rules of a bevel pair's fields, grouped by what they check: the spiral's terms,
the geometry, the sizing and its load, the pressure angle and the axes."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.rules import rule


class PairRules:
    """The cross-field rules of :class:`bearingcalc.models.bevel_gears.BevelPair`."""

    if TYPE_CHECKING:
        gear_a: Any
        gear_b: Any
        module: float | None
        shaft_angle: float | None
        face_width: float | None
        pressure_angle: float
        torque: float | None
        power: float | None
        spiral_angle: float | None
        hand: str | None
        rotation: str | None
        rating: Any
        face_cutter: Any

    @rule
    def _spiral_given(self) -> SpecFieldError | None:
        if self.spiral_angle is None:
            for field in ("hand", "rotation"):
                if getattr(self, field) is not None:
                    return SpecFieldError(field, "applies to a spiral bevel pair: give "
                                          "spiral_angle too, like 35 deg")
            if self.rating is not None and self.rating.cutter_radius is not None:
                return SpecFieldError("rating.cutter_radius", "applies to a spiral bevel "
                                      "pair: give spiral_angle too, like 35 deg, or leave "
                                      "it out (a straight pair's K_x is 1)")
            return None
        if not 0 <= self.spiral_angle <= math.radians(50):
            return SpecFieldError("spiral_angle", "must be from 0 deg (Zerol) to 50 deg, "
                                  "like 35 deg")
        if self.face_width is None:  # the kinematics do not depend on the spiral
            return SpecFieldError("face_width", "a spiral_angle gives a sized pair its "
                                  "normal section and tooth forces: give face_width too, "
                                  "like 15 mm (and a torque or power for the forces)",
                                  at="spiral_angle")
        for field, example in (("hand", "right"), ("rotation", "clockwise")):
            if getattr(self, field) is None and self.spiral_angle > 0:
                return SpecFieldError(field, f"a spiral bevel pair's forces need the "
                                      f"pinion's {field}, like {field}: {example}",
                                      at="spiral_angle")
        if self.rating is not None and self.face_cutter() is None and (
                self.spiral_angle > 0):
            return SpecFieldError("rating.cutter_radius", "a spiral pair's rating needs the "
                                  "face cutter's radius for AGMA 2003's lengthwise curvature "
                                  "factor K_x, like 114.3 mm (4.5 in)", at="spiral_angle")
        return None

    @rule
    def _geometry_is_determined(self) -> SpecFieldError | None:
        for label, gear in (("gear_a", self.gear_a), ("gear_b", self.gear_b)):
            if gear.pitch_radius is None and gear.teeth is None:
                return SpecFieldError(label, f"give {label}.pitch_radius, or {label}.teeth "
                                      "with module")
            if gear.pitch_radius is None and self.module is None:
                return SpecFieldError("module", f"{label}.teeth without a pitch radius needs "
                                      "the module, e.g. module: 2 mm", at=label)
            if gear.pitch_radius is not None and gear.teeth is not None and self.module:
                from_teeth = self.module * gear.teeth / 2.0
                if not math.isclose(gear.pitch_radius, from_teeth, rel_tol=1e-9):
                    return SpecFieldError(
                        f"{label}.pitch_radius",
                        f"disagrees with module × teeth / 2 = {from_teeth * 1e3:g} mm; "
                        "give one or make them agree")
        a, b = self.gear_a, self.gear_b
        if (self.module is None and None not in (a.teeth, b.teeth, a.pitch_radius, b.pitch_radius)
                and not math.isclose(a.pitch_radius * b.teeth, b.pitch_radius * a.teeth,
                                     rel_tol=1e-9)):
            # Meshing gears share a module, so their pitch radii are in the ratio of teeth.
            return SpecFieldError(
                "gear_b.teeth", f"the teeth ({a.teeth}/{b.teeth}) disagree with the pitch radii "
                f"({a.pitch_radius * 1e3:g} mm/{b.pitch_radius * 1e3:g} mm): meshing gears "
                "have pitch radii in the ratio of their teeth; leave the teeth or the radii "
                "out, or make them agree")
        return None

    @rule
    def _sizing_is_determined(self) -> SpecFieldError | None:
        sizing = [name for name in ("face_width", "torque", "power", "rating")
                  if getattr(self, name) is not None]
        if sizing and (self.module is None or self.gear_a.teeth is None
                       or self.gear_b.teeth is None):
            return SpecFieldError(sizing[0], "sizing needs the teeth of both gears and the "
                                  "(outer) module, not pitch radii alone")
        if sizing and self.face_width is None:
            return SpecFieldError(sizing[0], "sizing needs face_width, like 28 mm")
        return None

    @rule
    def _one_load(self) -> SpecFieldError | None:
        if self.torque is not None and self.power is not None:
            return SpecFieldError("power", "give torque or power on gear A, not both")
        if self.rating is not None and self.torque is None and self.power is None:
            return SpecFieldError("rating", "the strength rating needs a load: give torque "
                                  "(like 150 N*m) or power (like 9.4 kW) on gear A")
        return None

    @rule
    def _pressure_angle(self) -> SpecFieldError | None:
        if not 0 < self.pressure_angle < math.radians(45):
            return SpecFieldError("pressure_angle", "must be between 0 deg and 45 deg, like "
                                  "20 deg")
        return None

    @rule
    def _axes_placed(self) -> SpecFieldError | None:
        if self.shaft_angle is None and (self.gear_a.pitch_angle is None
                                         or self.gear_b.pitch_angle is None):
            return SpecFieldError("shaft_angle", "missing: give shaft_angle (90 deg for the "
                                  "usual right-angle pair), or both pitch angles")
        return None
