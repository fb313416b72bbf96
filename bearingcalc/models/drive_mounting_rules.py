"""The rules of a bevel drive as mounted (``method: iso-16281``): how its adjusted
shafts are set, which bearing may locate a shaft on its contacts, and what the method
solves; mixed into :class:`bearingcalc.models.bevel_drive.BevelDriveSpec`
(``docs/physics.md`` §12)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from bearingcalc.core.bearing_types import traits
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_method_rules import at_one_point
from bearingcalc.models.rules import rule, whole_spec_rule

if TYPE_CHECKING:
    from collections.abc import Callable

#: The limits of the gears' displacements at the mesh, judged as mounted.
MESH_LIMITS = ("max_mesh_offset_change", "max_pinion_axial_shift", "max_gear_axial_shift",
               "max_shaft_angle_change")


class DriveMountingRules:
    """What a drive as mounted takes."""

    if TYPE_CHECKING:  # the drive's fields and methods these rules read
        method: str
        pinion_setting: Any
        gear_setting: Any
        duty_cycle: Any
        limits: Any
        shafts: Callable[[], list[tuple[str, list[Any]]]]
        arrangement: Callable[[str], str]

    @rule
    def _shaft_settings(self) -> list[SpecFieldError]:
        problems = []
        for shaft in ("pinion", "gear"):
            field = f"{shaft}_setting"
            setting = getattr(self, field)
            adjusted = self.arrangement(shaft) != "locating-floating"
            if setting is not None and self.method != "iso-16281":
                problems.append(SpecFieldError(field, "is for the drive as mounted: give "
                                               f"method: iso-16281, or leave {field} out"))
            elif setting is not None and not adjusted:
                problems.append(SpecFieldError(field, f"a locating-floating {shaft} shaft is "
                                               "not set against itself: leave it out, or "
                                               f"give {shaft}_arrangement: back-to-back or "
                                               "face-to-face"))
            elif (setting is None and adjusted and self.method == "iso-16281"
                  and shaft in dict(self.shafts())):
                problems.append(SpecFieldError(field, f"missing: an adjusted {shaft} shaft "
                                               "as mounted is set against itself: give "
                                               f"{field}: {{end_play: 20 µm}} (negative: "
                                               "preload) or {preload: 1.5 kN}",
                                               at=f"{shaft}_arrangement"))
        return problems

    @rule
    def _pair_mountings(self) -> list[SpecFieldError]:
        """An adjusted pair's mountings give its end play together: both bearings', on
        one shaft in one housing, assembled at one temperature."""
        problems = []
        for shaft, bearings in self.shafts():
            setting = getattr(self, f"{shaft}_setting")
            adjusted = self.arrangement(shaft) != "locating-floating"
            mounted = [b for b in bearings if b.mounting is not None
                       and traits(b.type).one_way]
            if setting is not None and setting.stage == "bench" and not mounted:
                problems.append(SpecFieldError(
                    f"{shaft}_setting.stage", "bench: the end play as set before the rings "
                    "are pressed on needs the angular-contact or tapered bearings' "
                    "mountings, whose fits take up part of it: give each its mounting, or "
                    "leave stage out"))
            if not adjusted or not mounted or self.method != "iso-16281":
                continue
            if len(mounted) < len(bearings):
                missing = next(i for i, b in enumerate(bearings, 1) if b not in mounted)
                problems.append(SpecFieldError(
                    f"{shaft}_bearings.{missing}.mounting", "missing: the pair's end play "
                    "follows from both bearings' mountings (two one-way bearings, each with "
                    "its fits): give this one's too, or leave both out", at=f"{shaft}_bearings"))
                continue
            for field in ("shaft_material", "housing_material", "assembly_temperature"):
                first, second = (getattr(b.mounting, field) for b in mounted)
                if first != second:
                    problems.append(SpecFieldError(
                        f"{shaft}_bearings.2.mounting.{field}", "differs from bearing 1's: "
                        "an adjusted pair sits on one shaft in one housing, assembled at one "
                        "temperature; give both the same"))
        return problems

    @rule
    def _one_bearing_a_position(self) -> list[SpecFieldError]:
        if self.method != "iso-16281":
            return []
        problems = []
        for shaft, bearings in self.shafts():
            for i, bearing in enumerate(bearings, 1):
                where = f"{shaft}_bearings.{i}"
                if bearing.arrangement != "single":
                    problems.append(SpecFieldError(
                        f"{where}.arrangement", "method: iso-16281 solves each position "
                        "of a drive as one bearing: leave arrangement out, or give "
                        "method: iso-281"))
        return problems

    @rule
    def _mesh_limits_need_the_method(self) -> SpecFieldError | None:
        if self.method == "iso-16281":
            return None
        for name in MESH_LIMITS:
            if getattr(self.limits, name, None) is not None:
                return SpecFieldError(f"limits.{name}", "is judged on the drive as mounted: "
                                      "give method: iso-16281, or leave it out")
        return None

    @whole_spec_rule
    def _mounted_drive_at_one_point(self) -> SpecFieldError | None:
        return at_one_point(self.method, self.duty_cycle, "the torque and speed")
