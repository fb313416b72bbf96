"""How a matched pair as mounted (``method: iso-16281``) is set (an end play or a
preload, and where), and its rules: how it is set and how far apart its pressure
centres are, mixed into :class:`bearingcalc.models.rolling_bearing.RollingBearingSpec`
(``docs/physics.md`` §12)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Literal

from pydantic import Field

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import SpecModel
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.quantities import Length, PositiveForce
from bearingcalc.models.rules import rule

#: The pairs set against each other (a tandem pair shares its load instead).
OPPOSED = ("back-to-back", "face-to-face")


class PairSetting(SpecModel):
    """How a matched pair is set against itself: an end play or a preload."""

    end_play: Length | None = Field(
        None, description="the pair's axial clearance between first contacts (negative: "
        "preload by interference), like 20 µm")
    preload: PositiveForce | None = Field(
        None, description="the axial load each bearing carries at rest, like 1.5 kN")
    stage: Literal["mounted", "bench"] = Field(
        "mounted", description="with the bearings' mounting: where the setting was made, "
        "in place after the rings were pressed on, at the assembly's temperature "
        "(mounted), or on the bench before (bench: the fits take up part of it)")

    @rule
    def _end_play_or_preload(self) -> SpecFieldError | None:
        if self.end_play is not None and self.preload is not None:
            return SpecFieldError("preload", "give the end_play or the preload the pair is "
                                  "set to, not both")
        if self.end_play is None and self.preload is None:
            return SpecFieldError("end_play", "missing: give end_play (like 20 µm, "
                                  "negative: preload) or preload (like 1.5 kN)")
        return None


class PairRules(ReadsBearing):
    """What a matched pair as mounted takes."""

    if TYPE_CHECKING:  # the method's fields these rules read (MountingFields)
        method: str
        setting: Any
        pair_spacing: float | None

    @rule
    def _setting_of_a_pair(self) -> SpecFieldError | None:
        if self.method != "iso-16281":
            return None  # the method's own rule refuses the field
        if self.setting is not None and self.arrangement not in OPPOSED:
            what = ("a tandem pair shares its load and is not set against itself"
                    if self.arrangement == "tandem" else "a single bearing has no setting")
            return SpecFieldError("setting", f"{what}: leave setting out, or give "
                                  "arrangement: back-to-back or face-to-face")
        if self.setting is None and self.arrangement in OPPOSED:
            return SpecFieldError("setting", f"missing: a {self.arrangement} pair as mounted "
                                  "is set against itself: give setting: {end_play: 20 µm} "
                                  "(negative: preload) or setting: {preload: 1.5 kN}",
                                  at="arrangement")
        if (self.setting is not None and self.setting.stage == "bench"
                and getattr(self, "mounting", None) is None):
            return SpecFieldError("setting.stage", "bench: the end play as set before the "
                                  "rings are pressed on needs the pair's mounting, whose fits "
                                  "take up part of it: give mounting, or leave stage out")
        return None

    @rule
    def _spacing_of_a_pair(self) -> SpecFieldError | None:
        if self.method != "iso-16281":
            return None
        if self.pair_spacing is not None and self.arrangement == "single":
            return SpecFieldError("pair_spacing", "is a matched pair's: leave it out of a "
                                  "single bearing, or give its arrangement")
        if (self.arrangement != "single" and self.pair_spacing is None
                and self.width is None):
            return SpecFieldError("pair_spacing", "missing: a matched pair as mounted needs "
                                  "the distance of its pressure centres, like pair_spacing: "
                                  "60 mm, or the bearing's width for two bearings side by "
                                  "side", at="arrangement")
        return None
