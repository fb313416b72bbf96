"""The cross-field rules of a rolling bearing's family, arrangement and load factors, mixed
into its spec model (:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`): which
fields belong to balls and which to rollers, the roller bearings' contact angles,
ratings and loads, and which bearings pair (``docs/physics.md`` §5)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from bearingcalc.catalogue.designation import parse_designation
from bearingcalc.core.bearing_types import AngleRule, BearingTraits, LoadRule, RatingFormula
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.rules import rule

#: Ball field -> the roller field in its place, and the other way round.
_BALL_TO_ROLLER = {"ball_count": "roller_count", "ball_diameter": "roller_diameter"}
_BALL_ONLY = ("inner_groove_conformity", "outer_groove_conformity", "static_factor",
              "race_control")
_ROLLER_ONLY = ("roller_length", "roller_profile_radius", "raceway_radius")
_TOLERANCE = 1e-12


class _ReadsRollerBearing:
    if TYPE_CHECKING:  # the spec model's fields these rules read (see _ReadsBallBearing)
        type: str
        type_traits: BearingTraits
        rollers: bool
        arrangement: str
        rows: int
        contact_angle: float | None
        angle: float
        radial_load: float
        axial_load: float
        load_factors: Any
        dynamic_load_rating: float | None
        static_load_rating: float | None
        roller_count: int | None
        roller_diameter: float | None
        roller_length: float | None
        roller_profile_radius: float | None
        raceway_radius: float | None
        pitch_diameter: float | None
        mean_diameter: float | None
        bore_diameter: float | None
        outside_diameter: float | None
        model_fields_set: set[str]
        limits: Any
        designation: str | None

        def _element_fits(self, field: str, element: str, *, in_section: bool
                          ) -> SpecFieldError | None: ...


class RollerRules(_ReadsRollerBearing):
    """Balls or rollers, the roller bearings' own rules, pairs and catalogue factors."""

    @property
    def _straight(self) -> bool:
        """A cylindrical or needle roller bearing: no contact angle, and ISO 281's P = Fr."""
        return self.type_traits.load_rule is LoadRule.RADIAL_ONLY

    @rule
    def _ribless_ring_takes_no_thrust(self) -> SpecFieldError | None:
        """An NU bearing has no ribs on its inner ring, an N bearing none on its outer:
        neither carries an axial load (NJ, NUP and NF do)."""
        parsed = parse_designation(self.designation) if self.designation else None
        if parsed is None or not self.axial_load > 0:
            return None
        form = parsed.basic.rstrip("0123456789")
        ring = dict(self.type_traits.ribless_forms).get(form)
        if ring is None:
            return None
        return SpecFieldError("axial_load", f"{self.designation} is an {form} bearing, with "
                              f"no ribs on its {ring} ring: it carries no axial load; choose "
                              "an NJ or NUP bearing, or let another bearing take the thrust",
                              at="designation")

    @rule
    def _straight_rollers_loaded_radially(self) -> SpecFieldError | None:
        """ISO 281 rates a cylindrical or needle roller bearing on P = Fr: its ribs carry
        an axial load, but not into the life."""
        if not self._straight or self.radial_load > 0 or not (
                self.axial_load > 0):
            return None
        return SpecFieldError("radial_load", f"a {self.type} bearing's life counts only the "
                              "radial load (P = Fr), and it is zero: give the radial load, "
                              "like 5 kN; a thrust bearing carries an axial load alone")

    @rule
    def _family_fields(self) -> list[SpecFieldError]:
        """Each family's fields on its own types only, naming the field that fits."""
        given = self.model_fields_set
        problems = []
        if self.rollers:
            for ball, roller in _BALL_TO_ROLLER.items():
                if ball in given:
                    problems.append(SpecFieldError(ball, f"a {self.type} bearing has "
                                                   f"rollers: give {roller}"))
            for field in _BALL_ONLY:
                if field in given:
                    problems.append(SpecFieldError(field, f"applies to ball bearings only, "
                                                   f"not to a {self.type} bearing"))
        else:
            for ball, roller in _BALL_TO_ROLLER.items():
                if roller in given:
                    problems.append(SpecFieldError(roller, f"a {self.type} bearing has "
                                                   f"balls: give {ball}"))
            for field in (*_ROLLER_ONLY, "rows"):
                if field in given:
                    problems.append(SpecFieldError(field, f"applies to roller bearings only, "
                                                   f"not to a {self.type} ball bearing"))
        if self.rollers and self.limits.max_spin_to_roll is not None:
            problems.append(SpecFieldError("limits.max_spin_to_roll", "judges the spin of "
                                           "balls on their races; a roller bearing's rollers "
                                           "do not spin so: leave it out"))
        if "rows" in given and self.rollers and self.rows not in self.type_traits.rows:
            problems.append(SpecFieldError("rows", "a thrust roller bearing here has one "
                                           "row: give 1"))
        return problems

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
    def _roller_in_section(self) -> SpecFieldError | None:
        # A thrust roller's diameter lies along the axis: the ring section does not bound it.
        return self._element_fits("roller_diameter", "roller",
                                  in_section=not self.type_traits.thrust)

    @rule
    def _spherical_profile(self) -> SpecFieldError | None:
        crowned = (self.roller_profile_radius, self.raceway_radius)
        if crowned == (None, None):
            return None
        if not self.type_traits.crowned:
            field = "roller_profile_radius" if crowned[0] is not None else "raceway_radius"
            return SpecFieldError(field, "applies to spherical roller bearings only")
        if None in crowned:
            missing = "raceway_radius" if crowned[1] is None else "roller_profile_radius"
            return SpecFieldError(missing, "the point contact of a spherical roller needs both "
                                  "roller_profile_radius and raceway_radius")
        if not self.roller_profile_radius < self.raceway_radius:  # type: ignore[operator]
            return SpecFieldError("raceway_radius", "must exceed roller_profile_radius: the "
                                  "roller would not fit its raceway")
        return None

    @rule
    def _paired(self) -> SpecFieldError | None:
        if self.arrangement == "single":
            return None
        if not self.type_traits.pairable:
            return SpecFieldError("arrangement", f"{self.arrangement} pairs single-row "
                                  "angular-contact ball or tapered-roller bearings, not "
                                  f"{self.type}: use arrangement: single")
        if self.rows != 1:
            return SpecFieldError("rows", "a matched pair is of single-row bearings: give 1",
                                  at="arrangement")
        return None

    @rule
    def _thrust_roller_loads(self) -> SpecFieldError | None:
        if not (self.rollers and self.type_traits.thrust) or (self.contact_angle is None and (
                self.type_traits.angle_rule is not AngleRule.FIXED)):
            return None
        alpha = self.angle
        if abs(alpha - math.pi / 2) <= _TOLERANCE:
            if self.radial_load > 0:
                return SpecFieldError("radial_load", "a thrust roller bearing with α = 90° "
                                      "carries no radial load: set it to 0 kN, or use a "
                                      "radial bearing")
            return None
        if not math.pi / 4 < alpha < math.pi / 2:
            return None
        limit = 1.5 * math.tan(alpha)
        if self.radial_load > 0 and not self.axial_load > limit * self.radial_load:
            return SpecFieldError("axial_load", f"a thrust roller bearing at α = "
                                  f"{math.degrees(alpha):g} deg needs Fa/Fr > e = "
                                  f"1.5·tanα = {limit:.3g} (ISO 281 8.2); Fa/Fr is "
                                  f"{self.axial_load / self.radial_load:.3g}")
        return None

    @rule
    def _factors_complete(self) -> SpecFieldError | None:
        """The catalogue factors of the bearing's form: x, y, e (ball, single row); e, y
        (roller, single row); e, y1, y2 (double row, a pair, self-aligning)."""
        factors = self.load_factors
        self_aligning = self.type_traits.load_rule is LoadRule.SELF_ALIGNING
        double = (self.rows == 2 or self.arrangement in ("back-to-back", "face-to-face")
                  or self_aligning)
        if factors is None:
            if self_aligning and self.axial_load > 0:
                return SpecFieldError("load_factors", "a self-aligning ball bearing under "
                                      "axial load needs the catalogue's factors: "
                                      "load_factors: {e, y1, y2, y0}", at="axial_load")
            return None
        needed = self.type_traits.load_factor_names(double)
        missing = [name for name in needed if getattr(factors, name) is None]
        if not missing:
            return None
        form = ("a double row or a back-to-back or face-to-face pair" if double
                else "a single row")
        return SpecFieldError(f"load_factors.{missing[0]}", f"missing: the catalogue's "
                              f"factors of {form} are {', '.join(needed)}",
                              at="load_factors")

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

    def roller_notes(self) -> list[str]:
        """What the reader of a roller bearing's results should know."""
        notes = []
        if self._straight and self.axial_load > 0:
            notes.append(f"the axial load of a {self.type} bearing is carried by its ribs "
                         "and is not part of ISO 281's P = Fr: check it against the maker's "
                         "permissible axial load")
        if self.rollers and None not in (
                self.roller_count, self.roller_diameter, self.roller_length) and (
                self.roller_profile_radius is None):
            notes.append("the contact pressures are those of a straight line contact: they "
                         "ignore the rollers' crowning and their edge stresses")
        return notes
