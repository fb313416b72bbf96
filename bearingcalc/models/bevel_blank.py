"""A spiral or Zerol bevel pair's blank as ISO 23509 draws it: the profile shift, the
thickness modifications, the basic rack's addendum and dedendum, the tool's edge
radius, the face cutter and the tooth taper, mixed into
:class:`bearingcalc.models.bevel_gears.BevelPair` (``docs/physics.md`` §8, the ISO
23509 blank). A per-member value is written ``{pinion: X, gear: Y}``; a plain value is
both members'.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Discriminator, Field

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import BRANCH_MARK, SpecModel, branch
from bearingcalc.models.plain_numbers import ranged_number
from bearingcalc.models.quantities import PositiveLength
from bearingcalc.models.rules import rule

ThicknessModification = ranged_number(-0.5, 0.5, "x_sm, a member's thickness "
                                      "modification over m_mn", "0.03")


class MemberThickness(SpecModel):
    """Each member's thickness modification x_sm."""

    pinion: ThicknessModification = Field(description="x_sm1")  # type: ignore[valid-type]
    gear: ThicknessModification = Field(description="x_sm2")  # type: ignore[valid-type]


class MemberEdgeRadius(SpecModel):
    """Each member's cutting tool's edge radius ρ_a0."""

    pinion: PositiveLength = Field(description="ρ_a01")
    gear: PositiveLength = Field(description="ρ_a02")


#: The blank's fields, which only a spiral or Zerol pair takes.
BLANK_FIELDS = ("profile_shift", "thickness_modification", "addendum_factor",
                "dedendum_factor", "tool_edge_radius", "cutter_radius", "taper")


#: The blank's fields' types, which the pair declares after its own fields.
ProfileShift = Annotated[ranged_number(-1.0, 1.0, "x_hm1, the pinion's profile shift "  # type: ignore[valid-type]
                                       "over m_mn at the mean point; the wheel's is −x_hm1",
                                       "0.35") | None, Field(
    description="x_hm1, the pinion's profile shift at the mean point (the wheel's is "
    "−x_hm1); default Gleason's k_hap·(1 − 2·(0.210 + 0.290/u_a)), u_a = "
    "z2·cosδ1/(z1·cosδ2)")]
def _member_form(value: object) -> str:
    return BRANCH_MARK + ("members" if isinstance(value, (dict, SpecModel)) else "both")


Thickness = Annotated[Annotated[
    Annotated[ThicknessModification, branch("both")]  # type: ignore[valid-type]
    | Annotated[MemberThickness, branch("members")], Discriminator(_member_form)] | None,
    Field(description="x_sm, the thickness modification over m_mn: a plain value for both "
    "members or {pinion: …, gear: …} (default 0)")]
AddendumFactor = Annotated[ranged_number(0.5, 1.5, "k_hap, the basic crown gear's "  # type: ignore[valid-type]
                                         "addendum over m_mn", "1.0"),
                           Field(description="k_hap, the basic crown gear's addendum "
                                 "over m_mn (default 1.0)")]
DedendumFactor = Annotated[ranged_number(0.8, 2.0, "k_hfp, the basic crown gear's "  # type: ignore[valid-type]
                                         "dedendum over m_mn", "1.25"),
                           Field(description="k_hfp, the basic crown gear's dedendum "
                                 "over m_mn (default 1.25)")]
EdgeRadius = Annotated[Annotated[
    Annotated[PositiveLength, branch("both")]
    | Annotated[MemberEdgeRadius, branch("members")], Discriminator(_member_form)] | None,
    Field(description="ρ_a0, the cutting tool's edge radius: a plain length for both members "
    "or {pinion: …, gear: …} (default 0.2·m_mn)")]
CutterRadius = Annotated[PositiveLength | None, Field(
    description="r_c0, the face cutter's nominal radius, like 114.3 mm (also accepted in "
    "rating:)")]
Taper = Annotated[Literal["standard-depth", "uniform-depth", "duplex"] | None, Field(
    description="the tooth taper: standard-depth (root lines through the pitch apex), "
    "uniform-depth, or duplex (a face-milled completing cut's constant slot width, from "
    "the cutter radius); default standard-depth")]


class BlankRules:
    """What ISO 23509 takes of a spiral or Zerol pair besides its pitch cones: the rules
    and solver inputs of the fields :data:`BLANK_FIELDS` declares (declared on the pair
    itself, after its own, so that they read in that order)."""

    if TYPE_CHECKING:  # the pair's fields these rules read
        spiral_angle: float | None
        rating: Any
        model_fields_set: set[str]
        profile_shift: float | None
        thickness_modification: Any
        addendum_factor: float
        dedendum_factor: float
        tool_edge_radius: Any
        cutter_radius: float | None
        taper: str | None

    def face_cutter(self) -> float | None:
        """r_c0, where the spec gives it (at the top level or in its rating)."""
        if self.cutter_radius is not None:
            return self.cutter_radius
        return None if self.rating is None else self.rating.cutter_radius

    @rule
    def _blank_of_a_spiral_pair(self) -> list[SpecFieldError]:
        given = [name for name in BLANK_FIELDS if name in self.model_fields_set
                 and getattr(self, name) is not None]
        if self.spiral_angle is None:
            return [SpecFieldError(name, "shapes a spiral or Zerol pair's blank (ISO "
                                   "23509): give spiral_angle (0 deg for Zerol), or leave "
                                   "it out of a straight pair") for name in given[:1]]
        problems = []
        inner = None if self.rating is None else self.rating.cutter_radius
        if self.cutter_radius is not None and inner is not None and not (
                abs(self.cutter_radius - inner) <= 1e-12 * inner):
            problems.append(SpecFieldError("rating.cutter_radius", "differs from "
                                           "cutter_radius: give the face cutter's radius "
                                           "once (cutter_radius)"))
        if self.taper == "duplex" and self.face_cutter() is None:
            problems.append(SpecFieldError("cutter_radius", "missing: a duplex taper takes "
                                           "its slot width from the face cutter's radius, "
                                           "like cutter_radius: 114.3 mm", at="taper"))
        return problems

    def blank_inputs(self) -> dict[str, Any]:
        """The blank's SI solver inputs (empty for a straight pair)."""
        if self.spiral_angle is None:
            return {}
        thickness, edge = self.thickness_modification, self.tool_edge_radius
        both = not isinstance(thickness, MemberThickness)
        taper = self.taper or "standard-depth"
        return {
            "profile_shift": self.profile_shift,
            "thickness_modification_pinion": (thickness or 0.0) if both
            else thickness.pinion,  # type: ignore[union-attr]
            "thickness_modification_gear": (thickness or 0.0) if both
            else thickness.gear,  # type: ignore[union-attr]
            "addendum_factor": self.addendum_factor,
            "dedendum_factor": self.dedendum_factor,
            "tool_edge_radius_pinion": edge.pinion if isinstance(edge, MemberEdgeRadius)
            else edge,
            "tool_edge_radius_gear": edge.gear if isinstance(edge, MemberEdgeRadius)
            else edge,
            "taper": taper,
        }
