"""The cross-field rules of a rolling bearing's geometry: its rings, the fields of its
rolling elements (balls or rollers, as its type says), grooves and crown, mixed into
:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec` (``docs/physics.md`` §5)."""

from __future__ import annotations

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.rules import rule

#: Ball field -> the roller field in its place, and the other way round.
_BALL_TO_ROLLER = {"ball_count": "roller_count", "ball_diameter": "roller_diameter"}
_BALL_ONLY = ("inner_groove_conformity", "outer_groove_conformity", "static_factor",
              "race_control")
_ROLLER_ONLY = ("roller_length", "roller_profile_radius", "raceway_radius")


class GeometryRules(ReadsBearing):
    """The bearing's rings, its elements' fields, grooves and crown."""

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
    def _roller_in_section(self) -> SpecFieldError | None:
        # A thrust roller's diameter lies along the axis: the ring section does not bound it.
        return self._element_fits("roller_diameter", "roller",
                                  in_section=not self.type_traits.thrust)

    @rule
    def _grooves(self) -> SpecFieldError | None:
        if self.type_traits.family != "ball":  # no grooves: _family_fields refuses the fields
            return None
        if (self.inner_groove_conformity is None) != (self.outer_groove_conformity is None):
            missing, given = (("inner_groove_conformity", "outer_groove_conformity")
                              if self.inner_groove_conformity is None
                              else ("outer_groove_conformity", "inner_groove_conformity"))
            return SpecFieldError(missing, "the contact stresses need both groove "
                                  "conformities (like 0.52 and 0.53)", at=given)
        # a geometry given in part: the ratings' rule names what it lacks
        if (self.inner_groove_conformity is not None and not self.has_geometry
                and not self._missing_geometry()):
            return SpecFieldError("inner_groove_conformity", "the contact stresses need the "
                                  "geometry too: ball_count, ball_diameter and pitch_diameter")
        return None

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
