"""What the cross-field rules of a rolling bearing read of its spec model
(:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`, whose rules a drive's
bearings share), and the helpers they share."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from bearingcalc.core.bearing_types import BearingTraits, LoadRule
from bearingcalc.errors import SpecFieldError


class ReadsBearing:
    """What the rules read of a rolling bearing's spec model."""

    if TYPE_CHECKING:  # the spec model's fields and properties these rules read; not
        # annotations pydantic would see, or it would take them for fields of its own
        type: str
        type_traits: BearingTraits
        rollers: bool
        arrangement: str
        rows: int
        speed: Any
        inner_speed: Any
        outer_speed: Any
        relative_speed: Any
        radial_load: float
        axial_load: float
        load_factors: Any
        contact_angle: float | None
        angle: float
        bore_diameter: float | None
        outside_diameter: float | None
        pitch_diameter: float | None
        ball_count: int | None
        ball_diameter: float | None
        width: float | None
        roller_count: int | None
        roller_diameter: float | None
        roller_length: float | None
        roller_profile_radius: float | None
        raceway_radius: float | None
        dynamic_load_rating: float | None
        static_load_rating: float | None
        static_factor: float | None
        fatigue_load_limit: float | None
        has_geometry: bool
        mean_diameter: float | None
        lubrication: Any
        contamination_factor: float | None
        inner_groove_conformity: float | None
        outer_groove_conformity: float | None
        model_fields_set: set[str]
        limits: Any
        designation: str | None

    def _element_fits(self, field: str, element: str, *, in_section: bool
                      ) -> SpecFieldError | None:
        """A rolling element of diameter ``field`` smaller than the pitch diameter and,
        where ``in_section``, than the ring section (D − d)/2."""
        diameter = getattr(self, field)
        if diameter is None:
            return None
        if self.pitch_diameter is not None and not diameter < self.pitch_diameter:
            return SpecFieldError(field, "must be smaller than pitch_diameter")
        envelope = self._envelope_mm()
        if envelope is None or not in_section:
            return None
        section = (envelope[1] - envelope[0]) / 2
        if diameter * 1e3 < section:
            return None
        return SpecFieldError(field, f"{diameter * 1e3:g} mm does not fit the ring section: "
                              f"the {element} must be smaller than "
                              f"(outside_diameter − bore_diameter)/2 = {section:g} mm")

    def _missing_geometry(self) -> list[str]:
        """The fields of the rolling elements' geometry (their count and sizes, and the
        pitch diameter or the rings' mean) that a spec giving part of it leaves out: none
        where it gives all of them, or none of the elements' sizes."""
        sizes = (("roller_count", "roller_diameter", "roller_length") if self.rollers
                 else ("ball_count", "ball_diameter"))
        missing = [name for name in sizes if getattr(self, name) is None]
        if len(missing) == len(sizes):
            return []
        return missing + (["pitch_diameter"] if self.mean_diameter is None else [])

    @property
    def _axial_only(self) -> bool:
        """A thrust ball bearing (α = 90°): P = Fa, and it carries no radial load."""
        return self.type_traits.load_rule is LoadRule.AXIAL_ONLY

    @property
    def _straight(self) -> bool:
        """A cylindrical or needle roller bearing: no contact angle, and ISO 281's P = Fr."""
        return self.type_traits.load_rule is LoadRule.RADIAL_ONLY

    def _envelope_mm(self) -> tuple[float, float] | None:
        """(d, D) in mm where both are given and in order, else None."""
        if self.bore_diameter is None or self.outside_diameter is None or not (
                self.bore_diameter < self.outside_diameter):
            return None
        return self.bore_diameter * 1e3, self.outside_diameter * 1e3
