"""The cross-field rules of how a rolling bearing is run: its speed, its arrangement
and its lubrication, mixed into
:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec` (``docs/physics.md`` §5)."""

from __future__ import annotations

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.rules import rule


class OperatingRules(ReadsBearing):
    """How the bearing turns."""

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


class ArrangementRules(ReadsBearing):
    """Which bearings pair, and as what."""

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


class LubricationRules(ReadsBearing):
    """What the life's lubrication factor needs."""

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
        if self.lubrication is None or self._missing_geometry():
            return None  # a geometry given in part: the ratings' rule names what it lacks
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
