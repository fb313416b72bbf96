"""A rolling bearing's method: ISO 281's catalogue method, or ISO/TS 16281's load
distribution of the bearing as mounted (its fields and the rules that keep them
consistent), mixed into :class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`
(``docs/physics.md`` §12)."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from bearingcalc.core.bearing_types import names_where
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import SpecModel
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.quantities import Angle, Length, Moment
from bearingcalc.models.rules import rule, whole_spec_rule

#: The types ISO/TS 16281's method solves here (their trait ``mounted``).
MOUNTED_TYPES = names_where(mounted=True)
#: The method's own solver inputs (a drive's bearings take none of them).
MOUNTING_INPUTS = ("method", "operating_clearance", "tilting_moment", "misalignment")
#: The internal geometry the method needs of a ball bearing.
MOUNTED_GEOMETRY = ("ball_count", "ball_diameter", "pitch_diameter",
                    "inner_groove_conformity", "outer_groove_conformity")


class MountingFields(SpecModel):
    """How the bearing is solved, and what ISO/TS 16281's method takes besides the
    catalogue method's fields."""

    method: Literal["iso-281", "iso-16281"] = Field(
        "iso-281", description="iso-281: the catalogue method; iso-16281: the load on "
        "every ball from the rings' displacements (clearance, tilt, stiffness)")
    operating_clearance: Length | None = Field(
        None, description="iso-16281: the mounted bearing's diametral radial clearance at "
        "its temperature (negative: preload)")
    tilting_moment: Moment | None = Field(
        None, description="iso-16281: the moment on the inner ring in the plane of the "
        "radial load (the ring finds its own tilt)")
    misalignment: Angle | None = Field(
        None, description="iso-16281: the inner ring's tilt relative to the outer, imposed")

    def mounting_inputs(self) -> dict[str, object]:
        """The method's solver inputs (SI)."""
        return {"method": self.method, "operating_clearance": self.operating_clearance,
                "tilting_moment": self.tilting_moment, "misalignment": self.misalignment}


class MethodRules(ReadsBearing):
    """What each method takes."""

    def _groove_distance(self) -> float | None:
        """A = (fi + fo − 1)·Dw, the groove centres' distance at contact [m]; None where
        the spec leaves a part of it out."""
        parts = (self.inner_groove_conformity, self.outer_groove_conformity,
                 self.ball_diameter)
        if None in parts:
            return None
        fi, fo, dw = parts
        return (fi + fo - 1.0) * dw

    @rule
    def _mounting_fields_need_the_method(self) -> SpecFieldError | None:
        if self.method == "iso-16281":
            return None
        for name in ("operating_clearance", "tilting_moment", "misalignment"):
            if getattr(self, name) is not None:
                return SpecFieldError(name, "is for the bearing as mounted: give method: "
                                      f"iso-16281, or leave {name} out")
        return None

    @rule
    def _mounted_type(self) -> SpecFieldError | None:
        if self.method != "iso-16281":
            return None
        if not self.type_traits.mounted:
            return SpecFieldError("type", f"method: iso-16281 solves "
                                  f"{' and '.join(MOUNTED_TYPES)} bearings here; a "
                                  f"{self.type} bearing takes method: iso-281", at="method")
        if self.arrangement != "single":
            return SpecFieldError("arrangement", "method: iso-16281 solves a single bearing "
                                  "here: give arrangement: single, or method: iso-281 for the "
                                  "pair", at="method")
        return None

    @whole_spec_rule
    def _mounted_at_one_point(self) -> SpecFieldError | None:
        if self.method == "iso-16281" and self.duty_cycle is not None:
            return SpecFieldError("duty_cycle", "method: iso-16281 solves one operating "
                                  "point: give the loads and speed, or method: iso-281 for "
                                  "the duty cycle", at="method")
        return None

    @rule
    def _mounted_geometry(self) -> SpecFieldError | None:
        if self.method != "iso-16281" or not self.type_traits.mounted:
            return None
        missing = [name for name in MOUNTED_GEOMETRY if getattr(self, name) is None]
        if len(missing) == 1 and missing[0].endswith("groove_conformity"):
            return None  # one conformity of two: the contacts' own rule names it
        if missing:
            return SpecFieldError(missing[0], "missing: method: iso-16281 needs the internal "
                                  f"geometry ({', '.join(MOUNTED_GEOMETRY)})", at="method")
        return None

    @rule
    def _mounted_clearance(self) -> SpecFieldError | None:
        if self.method != "iso-16281" or not self.type_traits.mounted:
            return None
        # one whose single row carries thrust one way sits at its free contact angle
        takes_clearance = not self.type_traits.one_way
        if takes_clearance and self.operating_clearance is None:
            return SpecFieldError("operating_clearance", "missing: a deep-groove bearing "
                                  "under method: iso-16281 needs its operating clearance, like "
                                  "operating_clearance: 10 µm (negative: preload)",
                                  at="method")
        if not takes_clearance and self.operating_clearance is not None:
            return SpecFieldError("operating_clearance", "a single angular-contact bearing "
                                  "takes its free contact_angle, not a clearance: leave "
                                  "operating_clearance out")
        distance = self._groove_distance()
        if takes_clearance and distance is not None and not abs(
                self.operating_clearance) < distance:
            return SpecFieldError("operating_clearance", f"must be smaller in size than "
                                  f"the grooves' distance (fi + fo − 1)·Dw = "
                                  f"{distance * 1e6:.4g} µm: beyond it the balls would "
                                  "not sit in their grooves")
        return None

    @rule
    def _moment_or_misalignment(self) -> SpecFieldError | None:
        if self.tilting_moment is not None and self.misalignment is not None:
            return SpecFieldError("misalignment", "give a tilting_moment (the ring finds its "
                                  "tilt) or a misalignment (the tilt imposed), not both")
        distance = self._groove_distance()
        if self.misalignment is None or distance is None or self.pitch_diameter is None:
            return None
        largest = distance / (self.pitch_diameter / 2.0)
        if not abs(self.misalignment) < largest:
            return SpecFieldError("misalignment", f"must be smaller in size than "
                                  f"(fi + fo − 1)·Dw/(Dpw/2) = {largest * 1e3:.4g} mrad: "
                                  "beyond it the tilt moves a ball past its groove")
        return None
