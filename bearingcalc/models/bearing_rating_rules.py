"""The cross-field rules of a rolling bearing's ratings and contact angle: C and C0 from
the catalogue or the geometry, and the angle its type takes, mixed into
:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec` (``docs/physics.md`` §5)."""

from __future__ import annotations

import math

from bearingcalc.core.bearing_types import AngleRule, RatingFormula
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.rules import rule

_TOLERANCE = 1e-12


class RatingRules(ReadsBearing):
    """Where the ratings come from."""

    @rule
    def _rated(self) -> SpecFieldError | None:
        if self.type_traits.family != "ball":  # a roller bearing's ratings: _roller_rated
            return None
        missing = self._missing_geometry()
        if missing and self.type_traits.rating_formula is not RatingFormula.CATALOGUE:
            given = next(name for name in ("ball_count", "ball_diameter", "pitch_diameter")
                         if name not in missing)
            return SpecFieldError(missing[0], "the ball geometry is incomplete: give "
                                  f"{', '.join(missing)} too, or leave the geometry out",
                                  at=given)
        if self.dynamic_load_rating is None and not self.has_geometry:
            return SpecFieldError("dynamic_load_rating", "missing: give dynamic_load_rating "
                                  "(C from the catalogue, like 55.3 kN), or the geometry "
                                  "ball_count, ball_diameter and pitch_diameter (or "
                                  "bore_diameter and outside_diameter)")
        return None

    @rule
    def _roller_rated(self) -> SpecFieldError | None:
        if not self.rollers:
            return None
        geometry = {"roller_count": self.roller_count, "roller_diameter": self.roller_diameter,
                    "roller_length": self.roller_length}
        missing = [name for name, value in geometry.items() if value is None]
        if self.mean_diameter is None:
            missing.append("pitch_diameter")
        if {"ball_count", "ball_diameter"} & self.model_fields_set:
            return None  # _family_fields names the roller field to give instead
        if self.dynamic_load_rating is not None:
            if len(missing) in (0, len(geometry) + 1) or (
                    self.mean_diameter is not None and len(missing) == len(geometry)):
                return None
            return SpecFieldError(missing[0], f"the roller geometry is incomplete: give "
                                  f"{', '.join(missing)} too, or leave the geometry out")
        if missing:
            return SpecFieldError(missing[0], f"missing: give dynamic_load_rating (C from the "
                                  f"catalogue), or the roller geometry: "
                                  f"{', '.join(missing)}")
        return None

    @rule
    def _self_aligning_rated(self) -> SpecFieldError | None:
        if self.type_traits.rating_formula is not RatingFormula.CATALOGUE:
            return None
        if self.dynamic_load_rating is None:
            return SpecFieldError("dynamic_load_rating", "missing: a self-aligning ball "
                                  "bearing takes its ratings from the catalogue, like 22.9 kN")
        for field in ("ball_count", "ball_diameter"):
            if field in self.model_fields_set:
                return SpecFieldError(field, "a self-aligning ball bearing takes its ratings "
                                      "from the catalogue only: ISO 281's fc of self-aligning "
                                      "ball bearings is not built in; leave the ball geometry "
                                      "out")
        return None


class AngleRules(ReadsBearing):
    """The contact angle the type takes: its own, required, and in ISO 281's range."""

    @rule
    def _contact_angle(self) -> SpecFieldError | None:
        if self.type_traits.family != "ball":  # a roller bearing's angle: _roller_angle
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
    def _roller_angle(self) -> SpecFieldError | None:
        if not self.rollers:
            return None
        kind = self.type_traits
        if self.contact_angle is None:
            if kind.angle_rule is AngleRule.FIXED:
                return None
            return SpecFieldError("contact_angle", f"a {self.type} bearing needs its contact "
                                  f"angle, like {kind.example_angle}"
                                  " (the outer raceway's, for tapered rollers)")
        alpha = self.contact_angle
        if kind.angle_rule is AngleRule.FIXED and kind.contact_angle == 0 and (
                abs(alpha) > _TOLERANCE):
            return SpecFieldError("contact_angle", f"a {self.type} bearing has α = 0 deg; "
                                  "leave contact_angle out (a tapered-roller bearing has "
                                  "an angle)")
        if kind.angle_rule is AngleRule.FIXED and kind.thrust and (
                abs(alpha - math.pi / 2) > _TOLERANCE):
            return SpecFieldError("contact_angle", f"a {self.type} bearing has "
                                  "α = 90 deg; leave contact_angle out")
        if not kind.thrust and not 0 <= alpha <= math.pi / 4 + _TOLERANCE:
            return SpecFieldError("contact_angle", f"{math.degrees(alpha):g} deg is outside "
                                  "0 to 45 deg, the radial roller bearings of ISO 281; above "
                                  "45 deg use a thrust roller type")
        if kind.thrust and not (
                math.pi / 4 + _TOLERANCE < alpha <= math.pi / 2 + _TOLERANCE):
            return SpecFieldError("contact_angle", f"{math.degrees(alpha):g} deg is outside "
                                  "45 to 90 deg, the thrust roller bearings of ISO 281; at "
                                  "45 deg or below use a radial roller type")
        return None
