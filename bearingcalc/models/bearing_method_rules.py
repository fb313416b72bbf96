"""A rolling bearing's method: ISO 281's catalogue method, or ISO/TS 16281's load
distribution of the bearing as mounted (its fields and the rules that keep them
consistent), mixed into :class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`
(``docs/physics.md`` §12)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Discriminator, Field, PrivateAttr, ValidationInfo, field_validator

from bearingcalc.core.bearing_types import names_where
from bearingcalc.core.mounted_roller_bearing import CROWN_DROP_SHARE
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import BRANCH_MARK, SpecModel, branch
from bearingcalc.models.bearing_mounting import BearingMounting, mounting_in_place
from bearingcalc.models.bearing_pair_rules import PairSetting
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.mounting_resolution import chain_inputs, resolve
from bearingcalc.models.plain_numbers import LaminaCount
from bearingcalc.models.quantities import (
    Angle,
    Length,
    Moment,
    PositiveLength,
)
from bearingcalc.models.rules import rule, whole_spec_rule

#: The types ISO/TS 16281's method solves here (their trait ``mounted``).
MOUNTED_TYPES = names_where(mounted=True)
#: The method's own solver inputs (a drive's bearings take none of them).
MOUNTING_INPUTS = ("method", "operating_clearance", "mounting", "tilting_moment",
                   "misalignment", "roller_profile", "crown_radius", "laminae",
                   "roller_included_angle", "edge_stress_factor", "setting_end_play",
                   "setting_preload", "pair_spacing", "width")
#: The internal geometry the method needs, by the family of the rolling elements.
MOUNTED_GEOMETRY = {
    "ball": ("ball_count", "ball_diameter", "pitch_diameter", "inner_groove_conformity",
             "outer_groove_conformity"),
    "roller": ("roller_count", "roller_diameter", "roller_length", "pitch_diameter"),
}
#: The fields that size the rolling elements, by family.
ELEMENT_FIELDS = {"ball": ("ball_count", "ball_diameter"),
                  "roller": ("roller_count", "roller_diameter", "roller_length")}
#: The limits judged only as mounted: the least stiffnesses.
STIFFNESS_LIMITS = ("min_stiffness_radial", "min_stiffness_axial")
#: Every limit judged only as mounted, a solver input each.
MOUNTED_LIMITS = (*STIFFNESS_LIMITS, "min_operating_clearance")
#: The method's fields of roller bearings alone.
ROLLER_MOUNTING_FIELDS = ("roller_profile", "laminae", "roller_included_angle",
                          "edge_stress_factor")
#: The largest operating clearance (or preload) of a roller bearing, a share of Dwe.
ROLLER_CLEARANCE_SHARE = 0.1
#: ISO/TS 16281's count of laminae where the spec gives none.
DEFAULT_LAMINAE = 30


def at_one_point(method: str, duty_cycle: object, given: str) -> SpecFieldError | None:
    """ISO/TS 16281's method solves one operating point: a duty cycle is refused, naming
    what to ``given`` instead."""
    if method == "iso-16281" and duty_cycle is not None:
        return SpecFieldError("duty_cycle", f"method: iso-16281 solves one operating point: "
                              f"give {given}, or method: iso-281 for the duty cycle",
                              at="method")
    return None


class CrownProfile(SpecModel):
    """A roller crowned by one circular arc over its length."""

    crown_radius: PositiveLength = Field(description="the arc's radius in the roller's "
                                         "axial section")


def _profile_form(value: object) -> str:
    """Which form of roller_profile a value is: a mapping is a crown, anything else
    names a profile (so a wrong value gets one line, of the form it was meant as)."""
    return BRANCH_MARK + ("crown" if isinstance(value, (dict, CrownProfile)) else "named")


#: A roller's profile: a named one, or a crown of its radius.
RollerProfile = Annotated[
    Annotated[Literal["iso", "none"], branch("named")]
    | Annotated[CrownProfile, branch("crown")],
    Discriminator(_profile_form)]


class ElementMountingFields(SpecModel):
    """What a bearing as mounted takes of its own, alone or on a drive's shaft."""

    operating_clearance: Length | None = Field(
        None, description="iso-16281: the mounted bearing's diametral radial clearance at "
        "its temperature (negative: preload)")
    mounting: BearingMounting | None = Field(
        None, description="iso-16281: the drawing the operating clearance follows from, in "
        "its place: clearance_group, shaft and housing classes, temperatures")
    roller_profile: RollerProfile | None = Field(
        None, description="iso-16281, rollers: the rollers' profile: iso (ISO/TS 16281's "
        "logarithmic profile, the default), none (straight) or {crown_radius: …}")
    laminae: LaminaCount | None = Field(
        None, description=f"iso-16281, rollers: the slices of each roller (default "
        f"{DEFAULT_LAMINAE})")
    roller_included_angle: Angle | None = Field(
        None, description="iso-16281, tapered rollers: the roller's included angle θ, for "
        "the rib's load 2·Q·sin(θ/2)")
    edge_stress_factor: bool | None = Field(
        None, description="iso-16281, rollers: true raises each lamina's load towards the "
        "roller's ends by ISO/TS 16281's edge-stress factor in the life (default false)")

    #: a drive's bearing on a shaft adjusted against the other bearing: its mounting
    #: moves the pair's end play (set where the drive builds the bearing's own spec)
    _adjusted_shaft: bool = PrivateAttr(default=False)


    @field_validator("mounting", mode="after")
    @classmethod
    def _mounting_bands(cls, value: BearingMounting | None, info: ValidationInfo
                        ) -> BearingMounting | None:
        # the bearing's bore, outside and type are validated before its mounting
        return None if value is None else resolve(value, info.data)


#: The fields of a bearing as mounted, alone or on a drive's shaft.
ELEMENT_MOUNTING_FIELDS = tuple(ElementMountingFields.model_fields)
#: Their solver inputs, which a drive's bearing passes on as mounted.
ELEMENT_MOUNTING_INPUTS = ("operating_clearance", "mounting", "roller_profile", "crown_radius",
                           "laminae", "roller_included_angle", "edge_stress_factor",
                           "width")


class MountingFields(ElementMountingFields):
    """How the bearing is solved, and what ISO/TS 16281's method takes besides the
    catalogue method's fields."""

    method: Literal["iso-281", "iso-16281"] = Field(
        "iso-281", description="iso-281: the catalogue method; iso-16281: the load on "
        "every ball from the rings' displacements (clearance, tilt, stiffness)")
    tilting_moment: Moment | None = Field(
        None, description="iso-16281: the moment on the inner ring in the plane of the "
        "radial load (the ring finds its own tilt)")
    misalignment: Angle | None = Field(
        None, description="iso-16281: the inner ring's tilt relative to the outer, imposed")
    setting: PairSetting | None = Field(
        None, description="iso-16281, a back-to-back or face-to-face pair: {end_play: …} "
        "or {preload: …}")
    pair_spacing: PositiveLength | None = Field(
        None, description="iso-16281, a matched pair: the distance of the two bearings' "
        "pressure centres (default: two bearings side by side, from width and the "
        "geometry)")

    def mounting_inputs(self) -> dict[str, object]:
        """The method's solver inputs (SI); a roller bearing's own only where it has
        rollers."""
        inputs: dict[str, object] = {
            "method": self.method, "operating_clearance": self.operating_clearance,
            "tilting_moment": self.tilting_moment, "misalignment": self.misalignment,
            "mounting": None if self.mounting is None else chain_inputs(
                self.mounting, self.bore_diameter, self.outside_diameter,
                self.material.elastic_modulus, self.material.poisson_ratio)}
        if self.method == "iso-16281":
            inputs["width"] = self.width
        if self.method == "iso-16281" and self.arrangement != "single":
            setting = self.setting
            inputs.update(setting_end_play=setting.end_play if setting else None,
                          setting_preload=setting.preload if setting else None,
                          setting_stage=setting.stage if setting else None,
                          pair_spacing=self.pair_spacing)
        inputs.update(self.estimated_inputs())
        if self.method != "iso-16281" or self.type_traits.family != "roller":
            return inputs
        profile = self.roller_profile
        crowned = isinstance(profile, CrownProfile)
        return {**inputs, "roller_profile": "crown" if crowned else (profile or "iso"),
                "crown_radius": profile.crown_radius if crowned else None,
                "laminae": DEFAULT_LAMINAE if self.laminae is None else self.laminae,
                "roller_included_angle": self.roller_included_angle,
                "edge_stress_factor": bool(self.edge_stress_factor)}


class RollerMountingRules(ReadsBearing):
    """What a roller bearing as mounted takes of its own."""

    if TYPE_CHECKING:  # the method's fields these rules read (MountingFields)
        method: str
        roller_profile: Any
        laminae: int | None
        roller_included_angle: float | None
        edge_stress_factor: bool | None

    @rule
    def _roller_mounting_fields(self) -> SpecFieldError | None:
        if self.method != "iso-16281":
            return None
        for name in ROLLER_MOUNTING_FIELDS:
            if getattr(self, name) is not None and not self.rollers:
                return SpecFieldError(name, f"is for roller bearings: a {self.type} bearing "
                                      f"has balls; leave {name} out")
        if self.roller_included_angle is not None and not self.type_traits.one_way:
            return SpecFieldError("roller_included_angle", "is a tapered roller's: the rib "
                                  f"of a {self.type} bearing carries no load from it; leave "
                                  "roller_included_angle out")
        profile = self.roller_profile
        if isinstance(profile, CrownProfile) and all(
                value is not None for value in (self.roller_length, self.roller_diameter)):
            half, radius = self.roller_length / 2.0, profile.crown_radius
            if not radius > half:
                return SpecFieldError("roller_profile.crown_radius", f"must be larger than "
                                      f"half the roller's length, Lwe/2 = {half * 1e3:g} mm: "
                                      "a smaller arc does not span the roller (a crown's "
                                      "radius is of the order of a metre)")
            drop = radius - math.sqrt(radius * radius - half * half)
            if not drop < CROWN_DROP_SHARE * self.roller_diameter:
                return SpecFieldError("roller_profile.crown_radius", f"drops the roller's "
                                      f"ends by {drop * 1e6:.4g} µm, more than "
                                      f"{CROWN_DROP_SHARE:.0%} of its diameter: a crown's "
                                      "radius is of the order of a metre (its ends drop some "
                                      "micrometres to tens)")
        # the cup's angle is its own rule's to refuse: compared only where it is valid
        cup = self.angle if self.contact_angle is not None and self.angle > 0.0 else math.pi / 2
        if self.roller_included_angle is not None and not (
                0.0 < self.roller_included_angle < cup):
            return SpecFieldError("roller_included_angle", f"must be above 0 deg and below "
                                  f"the cup's contact_angle, {math.degrees(cup):.4g} "
                                  "deg: the cone's raceway lies at their difference (a "
                                  "tapered roller's included angle is a few degrees)")
        return None

    @rule
    def _mounted_double_row(self) -> SpecFieldError | None:
        # a pair's own rule refuses a double row in a matched pair
        if not (self.method == "iso-16281" and self.rollers and self.rows != 1
                and self.arrangement == "single"):
            return None
        if self.type_traits.one_way:
            return SpecFieldError("rows", "a double-row tapered bearing is two rows set "
                                  "against each other: as mounted, give rows: 1 with "
                                  "arrangement: back-to-back (or face-to-face) and the "
                                  "pair's setting", at="method")
        missing = [name for name in ELEMENT_FIELDS["roller"] if getattr(self, name) is None]
        if missing:
            return SpecFieldError(missing[0], "missing: a double-row bearing as mounted "
                                  "takes its rollers' geometry (the estimate from the "
                                  f"catalogue is of single rows): give {', '.join(missing)}")
        return None

    @rule
    def _mounted_axial_load(self) -> SpecFieldError | None:
        # a ribless ring's own rule says why an NU or N bearing takes no axial load
        if (self.method == "iso-16281" and self.type_traits.mounted and self.rollers
                and not self.type_traits.one_way and self.axial_load != 0.0
                and self.ribless_ring() is None):
            return SpecFieldError("axial_load", f"a {self.type} bearing's rollers carry no "
                                  "axial load as mounted (its ribs do, which ISO/TS 16281 "
                                  "leaves out): let another bearing take the thrust, or give "
                                  "method: iso-281")
        return None


class MethodRules(RollerMountingRules):
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
    def _stiffness_limits_need_the_method(self) -> SpecFieldError | None:
        if self.method == "iso-16281":
            return None
        for name in STIFFNESS_LIMITS:
            if getattr(self.limits, name, None) is not None:
                return SpecFieldError(f"limits.{name}", "is judged on the bearing as "
                                      "mounted: give method: iso-16281, or leave it out")
        return None

    @rule
    def _mounting_fields_need_the_method(self) -> SpecFieldError | None:
        if self.method == "iso-16281":
            return None
        for name in ("operating_clearance", "mounting", "tilting_moment", "misalignment",
                     *ROLLER_MOUNTING_FIELDS, "setting", "pair_spacing"):
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
        return None

    @whole_spec_rule
    def _mounted_at_one_point(self) -> SpecFieldError | None:
        return at_one_point(self.method, self.duty_cycle, "the loads and speed")

    @rule
    def _mounted_geometry(self) -> SpecFieldError | None:
        if (self.method != "iso-16281" or not self.type_traits.mounted
                or self.estimates_geometry):  # the estimate's own rule says if none fits
            return None
        family = self.type_traits.family
        if any(getattr(self, name) is not None for other, names in MOUNTED_GEOMETRY.items()
               if other != family for name in names if name != "pitch_diameter"):
            return None  # the other family's elements given: their own rules say so
        needed = MOUNTED_GEOMETRY[family]
        missing = [name for name in needed if getattr(self, name) is None
                   and not (name == "pitch_diameter" and self.mean_diameter is not None)]
        if any(getattr(self, name) is not None for name in ELEMENT_FIELDS[family]):
            # a set of elements begun: the geometry's own rules name what it lacks
            missing = [name for name in missing if name.endswith("groove_conformity")]
        if len(missing) == 1 and missing[0].endswith("groove_conformity"):
            return None  # one conformity of two: the contacts' own rule names it
        if missing:
            return SpecFieldError(missing[0], "missing: method: iso-16281 needs the internal "
                                  f"geometry ({', '.join(needed)}), or bore_diameter, "
                                  "outside_diameter and the ratings to estimate it",
                                  at="method")
        return None

    @rule
    def _mounted_clearance(self) -> SpecFieldError | None:
        if self.method != "iso-16281" or not self.type_traits.mounted:
            return None
        # one whose single row carries thrust one way sits at its free contact angle
        takes_clearance = not self.type_traits.one_way
        if self.mounting is not None:
            return mounting_in_place(self, adjusted=self._adjusted_shaft)
        if takes_clearance and self.operating_clearance is None:
            return SpecFieldError("operating_clearance", f"missing: a {self.type} bearing "
                                  "under method: iso-16281 needs its operating clearance, like "
                                  "operating_clearance: 10 µm (negative: preload), or its "
                                  "mounting", at="method")
        if not takes_clearance and self.operating_clearance is not None:
            return SpecFieldError("operating_clearance", f"a single {self.type} bearing "
                                  "takes its free contact_angle, not a clearance: leave "
                                  "operating_clearance out")
        distance = self._groove_distance()
        if takes_clearance and distance is not None and not abs(
                self.operating_clearance) < distance:
            return SpecFieldError("operating_clearance", f"must be smaller in size than "
                                  f"the grooves' distance (fi + fo − 1)·Dw = "
                                  f"{distance * 1e6:.4g} µm: beyond it the balls would "
                                  "not sit in their grooves")
        largest = None if self.roller_diameter is None else ROLLER_CLEARANCE_SHARE * (
            self.roller_diameter)
        if takes_clearance and largest is not None and not abs(
                self.operating_clearance) < largest:
            return SpecFieldError("operating_clearance", f"must be smaller in size than a "
                                  f"tenth of the roller's diameter, {largest * 1e6:.4g} µm: "
                                  "a mounted bearing's clearance or preload is some "
                                  "micrometres to a few tens")
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
