"""The cross-field rules of a rolling bearing's loads and load factors: what its type
carries, and the factors of ISO 281's equivalent load (the tables' or the
catalogue's), mixed into :class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`
(``docs/physics.md`` §5)."""

from __future__ import annotations

import math

from bearingcalc.core.bearing_types import AngleRule, LoadRule
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.rules import rule

#: ISO 281's largest e of a radial bearing: 1.5·tanα at α = 45° (7.2.1).
LARGEST_RADIAL_E = 1.5
_TOLERANCE = 1e-12


class LoadRules(ReadsBearing):
    """The loads the type carries."""

    @rule
    def _loaded(self) -> SpecFieldError | None:
        if self.radial_load == 0 and self.axial_load == 0 and not self._loaded_as_mounted():
            return SpecFieldError("radial_load", "both loads are zero, so the life is "
                                  "undefined: give radial_load or axial_load, like 10 kN")
        if self._axial_only and self.radial_load > 0:
            return SpecFieldError("radial_load", "a thrust ball bearing (α = 90°) carries no "
                                  "radial load; use angular-contact, or set it to 0 kN")
        return None

    def _loaded_as_mounted(self) -> bool:
        """Whether the bearing as mounted carries a tilting moment, an imposed
        misalignment or a pair's preload (or negative end play), which load its elements
        without a force."""
        if getattr(self, "method", None) != "iso-16281":
            return False
        setting = getattr(self, "setting", None)
        return (any(getattr(self, name, None) not in (None, 0.0)
                    for name in ("tilting_moment", "misalignment"))
                or (setting is not None and (setting.preload is not None or (
                    setting.end_play is not None and setting.end_play < 0))))

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

    def ribless_ring(self) -> tuple[str, str] | None:
        """(form, ring) of a designation whose ring has no ribs (NU: inner, N: outer),
        else None."""
        if not self.designation:
            return None
        from bearingcalc.catalogue.designation import parse_designation  # only with one

        parsed = parse_designation(self.designation)
        if parsed is None:
            return None
        form = parsed.basic.rstrip("0123456789")
        ring = dict(self.type_traits.ribless_forms).get(form)
        return None if ring is None else (form, ring)

    @rule
    def _ribless_ring_takes_no_thrust(self) -> SpecFieldError | None:
        """An NU bearing has no ribs on its inner ring, an N bearing none on its outer:
        neither carries an axial load (NJ, NUP and NF do)."""
        if not self.axial_load > 0:
            return None
        ribless = self.ribless_ring()
        if ribless is None:
            return None
        form, ring = ribless
        return SpecFieldError("axial_load", f"{self.designation} is an {form} bearing, with "
                              f"no ribs on its {ring} ring: it carries no axial load; choose "
                              "an NJ or NUP bearing, or let another bearing take the thrust",
                              at="designation")

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

    def roller_notes(self) -> list[str]:
        """What the reader of a roller bearing's results should know."""
        notes = []
        if self._straight and self.axial_load > 0:
            notes.append(f"the axial load of a {self.type} bearing is carried by its ribs "
                         "and is not part of ISO 281's P = Fr: check it against the maker's "
                         "permissible axial load")
        if self.rollers and None not in (
                self.roller_count, self.roller_diameter, self.roller_length) and (
                self.roller_profile_radius is None) and self.method != "iso-16281":
            # as mounted, every lamina's pressure follows the profile, and the limit
            # judges those
            notes.append("the contact pressures are those of a straight line contact: they "
                         "ignore the rollers' crowning and their edge stresses")
        return notes


class LoadFactorRules(ReadsBearing):
    """The factors of P: the tables' range, the catalogue's complete and in range."""

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
                self.load_factors is not None or self.has_geometry
                or self._missing_geometry()):  # in part: the ratings' rule names what lacks
            return None
        if self.static_load_rating is not None and self.static_factor is not None:
            return None
        field = "static_load_rating" if self.static_load_rating is None else "static_factor"
        return SpecFieldError(field, "a deep-groove bearing under axial load needs f0 and C0 "
                              "to find e and Y: give static_factor and static_load_rating "
                              "from the catalogue, or the geometry (ball_count, "
                              "ball_diameter, pitch_diameter)", at="axial_load")

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
