"""Whether a rolling bearing's elements fit the bearing they are given for: on the pitch
circle, in the rings' width, and a spherical roller's crown on its length; and what is
merely unusual in them (``docs/physics.md`` §5). Mixed into
:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`, so a drive's bearings take
them too.

Each rule tests a necessary condition that no real bearing breaks, so a spec that breaks
one holds a slip (a length in the wrong unit, a field for another), not a design.
"""

from __future__ import annotations

import math

from bearingcalc.core import iso281, roller_ratings
from bearingcalc.core.common import FIT_SLACK
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.rules import rule

#: The smallest contact angle of the tapered and spherical roller bearings in makers'
#: catalogues, about 5 deg (a spherical roller bearing's e = 1.5·tanα from 0.13 up):
#: below it ISO 281's Y = 0.4·cotα passes 4.6.
SHALLOWEST_ANGLE = math.radians(5.0)
#: ISO 281:2007 7.1.1: the fc of Table 7 holds for Lwe up to 2.5·Dwe; longer rollers (as
#: in needle roller bearings) may have a lower one.
LONG_ROLLER = 2.5


class _ElementsInPlace(ReadsBearing):
    """Balls and rollers that fit on their pitch circle, within the width and between
    the rings, in the proportions the rating tables cover."""

    @rule
    def _elements_fit_on_pitch_circle(self) -> SpecFieldError | None:
        r"""Z elements of diameter D side by side on the pitch circle Dpw:
        Z·asin(D/Dpw) <= π (each subtends 2·asin(D/Dpw) of the circle)."""
        element = "roller" if self.rollers else "ball"
        count, diameter = ((self.roller_count, self.roller_diameter) if self.rollers
                           else (self.ball_count, self.ball_diameter))
        pitch = self.pitch_diameter
        if None in (count, diameter, pitch) or not diameter < pitch:  # type: ignore[operator]
            return None  # a missing value, or an element wider than the circle: said apart
        half_angle = math.asin(diameter / pitch)  # type: ignore[operator]
        fill = count * half_angle  # type: ignore[operator]
        if fill <= math.pi * (1.0 + FIT_SLACK):
            return None
        most = math.floor(math.pi * (1.0 + FIT_SLACK) / half_angle)
        symbol = "Dwe" if self.rollers else "Dw"
        return SpecFieldError(f"{element}_count", f"the {element}s do not fit on the pitch "
                              f"circle: {count} of {diameter * 1e3:g} mm on {pitch * 1e3:g} mm "  # type: ignore[operator]
                              f"give Z·asin({symbol}/Dpw) = {fill:.4g}, above π = "
                              f"{math.pi:.4g} (at most {most} fit)")

    @rule
    def _size_ratio_in_tables(self) -> SpecFieldError | None:
        """γ = D·cosα/Dpw (a thrust ball bearing's Dw/Dpw) within ISO 281's fc table that
        rates the bearing: of ball bearings whenever their geometry is given, of radial
        roller bearings where C comes from it."""
        if self.rollers:
            if self.type_traits.thrust or self.dynamic_load_rating is not None:
                return None
            diameter, field = self.roller_diameter, "roller_diameter"
            table, what = roller_ratings.RADIAL_FC_GAMMA, "Dwe·cosα/Dpw"
            which = "of radial roller bearings (Table 7)"
        else:
            thrust = self.type_traits.thrust
            diameter, field = self.ball_diameter, "ball_diameter"
            table = iso281.THRUST_FC_GAMMA if thrust else iso281.RADIAL_FC_GAMMA
            what = "Dw/Dpw" if thrust else "Dw·cosα/Dpw"
            which = "of thrust ball bearings" if thrust else "of radial ball bearings"
        pitch = self.pitch_diameter
        if diameter is None or pitch is None or not self.has_geometry or not diameter < pitch:
            return None
        gamma = diameter * (1.0 if what == "Dw/Dpw" else math.cos(self.angle)) / pitch
        low, high = float(table[0]), float(table[-1])
        if low <= gamma <= high:
            return None
        return SpecFieldError(field, f"γ = {what} = {gamma:.4g} is outside ISO 281's fc table "
                              f"{which}, {low:g} to {high:g}: the {field.split('_')[0]} is "
                              f"too {'small' if gamma < low else 'large'} for the pitch "
                              f"circle of {pitch * 1e3:g} mm")

    @rule
    def _elements_in_width(self) -> SpecFieldError | None:
        """The elements within the bearing's width (B, T of a tapered bearing, H of a
        thrust bearing): a radial bearing's rollers side by side, each row's at least
        i·Lwe·cosα long along the axis; a thrust roller at least Dwe·sinα; a ball Dw."""
        width = self.width
        if width is None:
            return None
        if not self.rollers:
            if self.ball_diameter is None or self.ball_diameter < width:
                return None
            return SpecFieldError("ball_diameter", f"{self.ball_diameter * 1e3:g} mm does not "
                                  f"fit the bearing's width {width * 1e3:g} mm: a ball lies "
                                  "within the rings' width", at="width")
        if self.type_traits.thrust:
            if self.roller_diameter is None:
                return None
            extent = self.roller_diameter * math.sin(self.angle)
            if extent < width:
                return None
            return SpecFieldError("roller_diameter", f"the rollers reach {extent * 1e3:.4g} mm "
                                  f"along the axis (Dwe·sinα), not less than the bearing's "
                                  f"height, width = {width * 1e3:g} mm: they lie between the "
                                  "washers", at="width")
        if self.roller_length is None:
            return None
        extent = self.rows * self.roller_length * math.cos(self.angle)
        if extent < width:
            return None
        what = ("Lwe" if self.angle == 0 else "Lwe·cosα") if self.rows == 1 else (
            f"{self.rows}·Lwe" if self.angle == 0 else f"{self.rows}·Lwe·cosα")
        rows = "a row's rollers lie" if self.rows == 1 else "the rows' rollers lie side by side"
        return SpecFieldError("roller_length", f"{self.roller_length * 1e3:g} mm does not fit "
                              f"the bearing's width {width * 1e3:g} mm: {rows} within the "
                              f"rings' width, and {what} = {extent * 1e3:.4g} mm",
                              at="width")

    @rule
    def _elements_within_the_rings(self) -> SpecFieldError | None:
        """A radial bearing's elements between bore and outside diameter where they sit:
        d < Dpw − D·cosα and Dpw + D·cosα < D_outside (D the element's diameter), not
        merely smaller than the section."""
        envelope = self._envelope_mm()
        diameter = self.roller_diameter if self.rollers else self.ball_diameter
        if envelope is None or diameter is None or self.pitch_diameter is None or (
                self.type_traits.thrust):
            return None
        bore, outside = envelope
        pitch = self.pitch_diameter * 1e3
        across = diameter * 1e3 * (math.cos(self.angle) if self.rollers else 1.0)
        if not (pitch > across and bore < pitch < outside) or (
                across >= (outside - bore) / 2):
            return None  # said by the pitch circle's and the section's rules
        element = "roller" if self.rollers else "ball"
        if pitch - across <= bore:
            return SpecFieldError("pitch_diameter", f"the {element}s on {pitch:g} mm reach "
                                  f"down to {pitch - across:.4g} mm, into the bore "
                                  f"({bore:g} mm): the pitch circle lies nearer the rings' "
                                  f"mean, {(bore + outside) / 2:g} mm")
        if pitch + across >= outside:
            return SpecFieldError("pitch_diameter", f"the {element}s on {pitch:g} mm reach "
                                  f"out to {pitch + across:.4g} mm, past the outside "
                                  f"diameter ({outside:g} mm): the pitch circle lies nearer "
                                  f"the rings' mean, {(bore + outside) / 2:g} mm")
        return None


class ElementFitRules(_ElementsInPlace):
    """Balls and rollers that fit their bearing; inclined rollers that are inclined."""

    @rule
    def _thrust_rollers_in_section(self) -> SpecFieldError | None:
        """A thrust roller's length lies across the washers: Lwe·sinα within the section
        (D − d)/2."""
        envelope = self._envelope_mm()
        if not (self.rollers and self.type_traits.thrust) or envelope is None or (
                self.roller_length is None):
            return None
        section = (envelope[1] - envelope[0]) / 2
        extent = self.roller_length * 1e3 * math.sin(self.angle)
        if extent < section:
            return None
        return SpecFieldError("roller_length", f"the rollers reach {extent:.4g} mm across the "
                              "washers (Lwe·sinα): they must be shorter than "
                              f"(outside_diameter − bore_diameter)/2 = {section:g} mm")

    @rule
    def _crown_on_the_roller(self) -> SpecFieldError | None:
        r"""A crown arc of radius R over the roller's length Lwe: R > Lwe/2, and its drop
        at the ends h = R − √(R² − (Lwe/2)²) below the roller's radius Dwe/2."""
        crown, length, diameter = (self.roller_profile_radius, self.roller_length,
                                   self.roller_diameter)
        if crown is None or length is None or self.raceway_radius is None:
            return None  # _spherical_profile asks for both radii
        if not crown > length / 2:
            return SpecFieldError("roller_profile_radius", f"{crown * 1e3:g} mm is not above "
                                  f"half the roller's length, Lwe/2 = {length * 500:g} mm: no "
                                  "crown arc spans the roller (a spherical roller's crown "
                                  "radius is several times its length)")
        drop = crown - math.sqrt(crown * crown - length * length / 4)
        if diameter is None or drop < diameter / 2:
            return None
        return SpecFieldError("roller_profile_radius", f"a crown of {crown * 1e3:g} mm over "
                              f"Lwe = {length * 1e3:g} mm drops {drop * 1e3:.4g} mm at the "
                              f"roller's ends, more than its radius Dwe/2 = "
                              f"{diameter * 500:g} mm: no roller is left there")

    @rule
    def _inclined_rollers(self) -> SpecFieldError | None:
        # Rollers inclined to the axis by α: at α = 0 they would carry no axial load, and
        # ISO 281's Y = 0.4·cotα has no bound (a negative angle is the range rule's).
        if not self.type_traits.inclined or self.contact_angle != 0.0:
            return None
        return SpecFieldError("contact_angle", f"a {self.type} bearing's rollers are inclined: "
                              "at 0 deg it would carry no axial load (ISO 281's Y = "
                              "0.4·cotα has no bound); give the catalogue's angle, like "
                              "12 deg" + (", or use type: cylindrical-roller"
                                          if not self.type_traits.crowned else ""))

    def element_notes(self) -> list[str]:
        """What is unusual in the elements, though possible."""
        notes = []
        alpha = self.contact_angle
        if self.type_traits.inclined and alpha is not None and 0 < alpha < SHALLOWEST_ANGLE:
            notes.append(f"contact_angle {math.degrees(alpha):g} deg is below the "
                         f"{math.degrees(SHALLOWEST_ANGLE):g} deg of the shallowest "
                         f"{self.type} bearings in makers' catalogues: ISO 281's "
                         f"Y = 0.4·cotα = {0.4 / math.tan(alpha):.3g} weighs the axial load "
                         "heavily; check the angle against the catalogue")
        length, diameter = self.roller_length, self.roller_diameter
        if (self.rollers and self.dynamic_load_rating is None and self.has_geometry
                and length is not None and diameter is not None
                and length > LONG_ROLLER * diameter):
            notes.append(f"roller_length {length * 1e3:g} mm is above {LONG_ROLLER:g}·Dwe = "
                         f"{LONG_ROLLER * diameter * 1e3:g} mm: ISO 281 (7.1.1) says a lower "
                         "fc than its Table 7 may be expected for such long rollers (as in "
                         "needle roller bearings), so C from the geometry may be high; give "
                         "the catalogue's dynamic_load_rating")
        return notes

