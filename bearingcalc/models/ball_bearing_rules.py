"""The cross-field rules of a ball bearing, mixed into its spec model
(:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`), which a drive's bearings
share (``docs/physics.md`` §5)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from bearingcalc.core.bearing_types import AngleRule, BearingTraits, LoadRule
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.rules import rule

#: ISO 281's largest e of a radial bearing: 1.5·tanα at α = 45° (7.2.1).
LARGEST_RADIAL_E = 1.5


class _ReadsBallBearing:
    """What the rules read of a ball bearing's spec model."""

    if TYPE_CHECKING:  # the spec model's fields and properties these rules read; not
        # annotations pydantic would see, or it would take them for fields of its own
        type: str
        type_traits: BearingTraits
        arrangement: str
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
        ball_diameter: float | None
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

    @property
    def _axial_only(self) -> bool:
        """A thrust ball bearing (α = 90°): P = Fa, and it carries no radial load."""
        return self.type_traits.load_rule is LoadRule.AXIAL_ONLY

    def _envelope_mm(self) -> tuple[float, float] | None:
        """(d, D) in mm where both are given and in order, else None."""
        if self.bore_diameter is None or self.outside_diameter is None or not (
                self.bore_diameter < self.outside_diameter):
            return None
        return self.bore_diameter * 1e3, self.outside_diameter * 1e3


class OperatingRules(_ReadsBallBearing):
    """How the bearing turns, is loaded and is lubricated."""

    @rule
    def _turning(self) -> SpecFieldError | None:
        ring_speeds = self.inner_speed is not None or self.outer_speed is not None
        if self.speed is not None and ring_speeds:
            return SpecFieldError("speed", "give speed (the inner ring turning, the outer "
                                  "fixed), or inner_speed and outer_speed, not both")
        if self.speed is None and not ring_speeds:
            return SpecFieldError("speed", "missing: give speed, like 3000 rpm, or the ring "
                                  "speeds inner_speed and outer_speed")
        if self.speed is not None and not self.speed > 0:
            return SpecFieldError("speed", "must be positive: the life in hours needs a "
                                  "turning bearing, like 3000 rpm")
        if not self.relative_speed > 0:
            return SpecFieldError("inner_speed", "the rings must turn relative to each "
                                  "other: the life in hours needs inner_speed ≠ outer_speed")
        return None

    @rule
    def _loaded(self) -> SpecFieldError | None:
        if self.radial_load == 0 and self.axial_load == 0:
            return SpecFieldError("radial_load", "both loads are zero, so the life is "
                                  "undefined: give radial_load or axial_load, like 10 kN")
        if self._axial_only and self.radial_load > 0:
            return SpecFieldError("radial_load", "a thrust ball bearing (α = 90°) carries no "
                                  "radial load; use angular-contact, or set it to 0 kN")
        return None

    @rule
    def _axial_load_counts(self) -> SpecFieldError | None:
        """Above e, P = X·Fr + Y·Fa (Y2 of a double row): a zero factor drops a load the
        bearing carries."""
        factors = self.load_factors
        if factors is None:
            return None
        for name in ("y", "y2"):
            if getattr(factors, name) == 0 and self.axial_load > 0:
                return SpecFieldError(f"load_factors.{name}", f"{name.upper()} = 0 leaves the "
                                      "axial load out of the equivalent load P = X·Fr + Y·Fa: "
                                      f"give the catalogue's {name.upper()}, above 0")
        if factors.x == 0 and self.radial_load > 0 and not self._axial_only:
            return SpecFieldError("load_factors.x", "X = 0 leaves the radial load out of the "
                                  "equivalent load P = X·Fr + Y·Fa above e: give the "
                                  "catalogue's X, above 0 (0.4 to 0.76 in ISO 281's tables)")
        return None

    @rule
    def _limit_e_of_a_radial_bearing(self) -> SpecFieldError | None:
        """A radial bearing's e within ISO 281's: e = 1.5·tanα of the radial roller
        bearings (7.2.1) is at most 1.5, at α = 45°, and Table 4 gives angular-contact
        ball bearings at most 1.34, at 45° (makers' catalogues stop near 1.14, at 40°,
        and 0.87, steep tapered rollers at 30°). A thrust bearing's e grows without bound
        as α nears 90°."""
        factors = self.load_factors
        if factors is None or factors.e is None or self.type_traits.thrust or (
                factors.e <= LARGEST_RADIAL_E):
            return None
        return SpecFieldError("load_factors.e", f"{factors.e:g} is above {LARGEST_RADIAL_E:g}, "
                              "the largest e of a radial bearing (ISO 281: 1.5·tanα at "
                              "α = 45°; catalogues: 1.14 for angular-contact balls at 40°, "
                              "about 0.87 for tapered rollers at 30°): give the catalogue's e")

    @rule
    def _contact_angle(self) -> SpecFieldError | None:
        if self.type_traits.family != "ball":  # a roller bearing's angle: RollerRules
            return None
        thrust = self._axial_only
        if thrust and self.contact_angle is not None and not math.isclose(
                self.contact_angle, math.pi / 2, rel_tol=1e-12):
            return SpecFieldError("contact_angle", "a thrust ball bearing has α = 90 deg; "
                                  "leave contact_angle out")
        if self.type_traits.angle_rule is AngleRule.GIVEN and self.contact_angle is None:
            return SpecFieldError("contact_angle", "an angular-contact bearing needs its "
                                  "contact angle, like 40 deg")
        if not thrust and not 0 <= self.angle < math.pi / 2:
            return SpecFieldError("contact_angle", "must be from 0 deg to below 90 deg for a "
                                  "radial bearing")
        return None

    @rule
    def _angle_in_tables(self) -> SpecFieldError | None:
        alpha = self.angle
        # A missing angle is its own problem (_contact_angle): the tables are not one.
        if self.type_traits.load_rule is not LoadRule.ANGLE_TABLE or self.contact_angle is None or (
                math.radians(20) - 1e-12 <= alpha <= math.radians(45) + 1e-12):
            return None
        factors = self.load_factors
        paired = self.arrangement in ("back-to-back", "face-to-face")
        static = ("y0",) if paired else ("x0", "y0")  # a pair's X0 is 1
        if factors is None or any(getattr(factors, name) is None for name in static):
            needed = "e, y1, x, y2, y0" if paired else "x, y, e, x0, y0"
            return SpecFieldError("load_factors", "ISO 281 tables X, Y, e (and ISO 76 "
                                  "X0, Y0) only for 20 deg <= α <= 45 deg: give "
                                  f"load_factors: {{{needed}}} from the catalogue",
                                  at="contact_angle")
        return None

    @rule
    def _axial_factors_found(self) -> SpecFieldError | None:
        if self.type_traits.load_rule is not LoadRule.GROOVE_TABLE or not self.axial_load > 0 or (
                self.load_factors is not None or self.has_geometry):
            return None
        if self.static_load_rating is not None and self.static_factor is not None:
            return None
        field = "static_load_rating" if self.static_load_rating is None else "static_factor"
        return SpecFieldError(field, "a deep-groove bearing under axial load needs f0 and C0 "
                              "to find e and Y: give static_factor and static_load_rating "
                              "from the catalogue, or the geometry (ball_count, "
                              "ball_diameter, pitch_diameter)", at="axial_load")

    @rule
    def _contamination_with_lubrication(self) -> SpecFieldError | None:
        if self.lubrication is not None and self.contamination_factor is None:
            return SpecFieldError("contamination_factor", "lubrication needs the "
                                  "contamination factor eC (0 to 1, like 0.5; see the "
                                  "cleanliness classes in docs/kinds/ball-bearing.md)",
                                  at="lubrication")
        if self.lubrication is None and self.contamination_factor is not None:
            return SpecFieldError("contamination_factor", "applies with lubrication only: "
                                  "give lubrication: {viscosity: ...} too, or leave it out")
        return None

    @rule
    def _lubrication_sizes(self) -> SpecFieldError | None:
        if self.lubrication is None:
            return None
        if self.mean_diameter is None and (self.bore_diameter is None) == (
                self.outside_diameter is None):  # one ring diameter alone: _envelope says so
            return SpecFieldError("pitch_diameter", "lubrication needs the pitch diameter "
                                  "for ν1: give pitch_diameter, or bore_diameter and "
                                  "outside_diameter", at="lubrication")
        if (self.fatigue_load_limit is None and self.static_load_rating is None
                and (self._axial_only or not self.has_geometry)):
            return SpecFieldError("fatigue_load_limit", "aISO needs Cu: give "
                                  "fatigue_load_limit, or static_load_rating to find it",
                                  at="lubrication")
        return None


class GeometryRules(_ReadsBallBearing):
    """The bearing's rings, balls, grooves and ratings."""

    @rule
    def _envelope(self) -> SpecFieldError | None:
        """Bore and outside diameter: both or neither, in order."""
        if (self.bore_diameter is None) != (self.outside_diameter is None):
            given, missing = (("bore_diameter", "outside_diameter")
                              if self.outside_diameter is None
                              else ("outside_diameter", "bore_diameter"))
            return SpecFieldError(missing, "give both bore_diameter and outside_diameter, or "
                                  "neither", at=given)
        if self.bore_diameter is not None and not (
                self.bore_diameter < self.outside_diameter):  # type: ignore[operator]
            return SpecFieldError("outside_diameter", "must be larger than bore_diameter")
        return None

    @rule
    def _pitch_circle_in_envelope(self) -> SpecFieldError | None:
        envelope = self._envelope_mm()
        if envelope is None or self.pitch_diameter is None:
            return None
        bore, outside = envelope
        pitch = self.pitch_diameter * 1e3
        if bore < pitch < outside:
            return None
        return SpecFieldError("pitch_diameter", f"{pitch:g} mm is outside the rings: the "
                              f"pitch circle lies between bore_diameter ({bore:g} mm) and "
                              f"outside_diameter ({outside:g} mm), near their mean "
                              f"{(bore + outside) / 2:g} mm")

    @rule
    def _ball_in_section(self) -> SpecFieldError | None:
        return self._element_fits("ball_diameter", "ball", in_section=True)

    @rule
    def _rated(self) -> SpecFieldError | None:
        if self.type_traits.family != "ball":  # a roller bearing's ratings: RollerRules
            return None
        if self.dynamic_load_rating is None and not self.has_geometry:
            return SpecFieldError("dynamic_load_rating", "missing: give dynamic_load_rating "
                                  "(C from the catalogue, like 55.3 kN), or the geometry "
                                  "ball_count, ball_diameter and pitch_diameter (or "
                                  "bore_diameter and outside_diameter)")
        return None

    @rule
    def _grooves(self) -> SpecFieldError | None:
        if self.type_traits.family != "ball":  # no grooves: RollerRules refuses the fields
            return None
        if (self.inner_groove_conformity is None) != (self.outer_groove_conformity is None):
            missing, given = (("inner_groove_conformity", "outer_groove_conformity")
                              if self.inner_groove_conformity is None
                              else ("outer_groove_conformity", "inner_groove_conformity"))
            return SpecFieldError(missing, "the contact stresses need both groove "
                                  "conformities (like 0.52 and 0.53)", at=given)
        if self.inner_groove_conformity is not None and not self.has_geometry:
            return SpecFieldError("inner_groove_conformity", "the contact stresses need the "
                                  "geometry too: ball_count, ball_diameter and pitch_diameter")
        return None
