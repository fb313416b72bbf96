"""Spec of ``kind: bevel-drive``: a bevel pair on two shafts, each on two rolling bearings,
located by one of them or adjusted against each other (``docs/physics.md`` §9)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, ClassVar, Literal

from pydantic import Field, model_validator

from bearingcalc.core.bearing_types import traits
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_method_rules import (
    ELEMENT_MOUNTING_FIELDS,
    ELEMENT_MOUNTING_INPUTS,
    MOUNTED_LIMITS,
    MOUNTING_INPUTS,
    ElementMountingFields,
)
from bearingcalc.models.bearing_pair_rules import PairSetting
from bearingcalc.models.bevel_gears import BevelGearsLimits, BevelPair
from bearingcalc.models.drive_mounting_rules import MESH_LIMITS, DriveMountingRules
from bearingcalc.models.duty import (
    OIL_BIN_FIELDS,
    OIL_BIN_PATHS,
    BinOilRules,
    DutyCycleRules,
    bin_model,
)
from bearingcalc.models.lubrication import Lubrication
from bearingcalc.models.plain_numbers import Ratio
from bearingcalc.models.quantities import (
    AngularSpeed,
    Length,
    PositiveAngle,
    PositiveLength,
    PositivePower,
    PositiveTime,
    Torque,
)
from bearingcalc.models.rolling_bearing import (
    BallBearingLimits,
    BearingFields,
    Reliability,
    RollingBearingSpec,
    UnitFraction,
)
from bearingcalc.models.rules import own_problems, rule

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import BevelDriveInputs, MountedBearingInputs

#: Keys of a ball-bearing spec that the drive sets for every bearing itself.
_DRIVE_SETS = ("radial_load", "axial_load", "speed", "inner_speed", "outer_speed")
SHAFTS = ("pinion", "gear")


ShaftArrangement = Literal["locating-floating", "back-to-back", "face-to-face"]


class DriveBearing(ElementMountingFields, BearingFields):
    """One rolling bearing of a shaft: where it sits, whether it locates the shaft
    axially, and every field of ``kind: rolling-bearing`` except loads and speeds (and,
    as mounted, what a bearing alone takes of its own: clearance, roller profile)."""

    position: Length = Field(description="along the shaft axis, from the pitch-cone apex "
                             "toward the gear's back face; in an adjusted arrangement, the "
                             "bearing's pressure centre (the catalogue's distance a)")
    locating: bool = Field(False, description="takes the shaft's whole axial force "
                           "(locating-floating arrangement only)")
    induced_axial_factor: Ratio | None = Field(
        None, description="R, the induced axial force over the radial load in an adjusted "
        "arrangement (by default 0.5/Y for tapered rollers, the makers' table for "
        "angular-contact balls)")

    @model_validator(mode="before")
    @classmethod
    def _no_loads_or_speeds(cls, data: Any) -> Any:
        if isinstance(data, dict):
            given = [key for key in _DRIVE_SETS if key in data]
            if given:
                raise ValueError(f"a drive's bearing takes no {given[0]}: the drive finds its "
                                 "loads and speeds from the gear forces and input_speed")
        return data


class BevelDriveLimits(BevelGearsLimits):
    min_rating_life: PositiveTime | None = Field(None, description="judged on the system's "
                                                 "modified rating life")
    min_static_safety: Ratio = Field(1.0, description="judged on the smallest s0")
    max_mesh_offset_change: PositiveLength | None = Field(
        None, description="iso-16281: the largest |E| at the mesh")
    max_pinion_axial_shift: PositiveLength | None = Field(
        None, description="iso-16281: the largest |P| at the mesh")
    max_gear_axial_shift: PositiveLength | None = Field(
        None, description="iso-16281: the largest |G| at the mesh")
    max_shaft_angle_change: PositiveAngle | None = Field(
        None, description="iso-16281: the largest |Σ| at the mesh")


DriveBin = bin_model("DriveBin", {
    "torque": (Torque, "on the pinion"), "power": (PositivePower, "through the pinion"),
    "input_speed": (AngularSpeed, "the pinion shaft's speed; 0: at rest"), **OIL_BIN_FIELDS})


class BevelDriveSpec(DriveMountingRules, BinOilRules, DutyCycleRules, BevelPair):
    """A right-angle (or any-angle) bevel drive: the pair, its two shafts and their
    bearings, from the input torque to every bearing's life, at one operating point or
    over a duty cycle."""

    ALTERNATIVES: ClassVar[Mapping[str, str]] = {"torque": "power", "power": "torque"}
    POWER_FIELD: ClassVar[str | None] = "power"
    BIN_FIELDS: ClassVar[Mapping[str, str]] = {
        **{field: field for field in ("torque", "power", "input_speed")}, **OIL_BIN_PATHS}

    CATALOGUE_PLACES: ClassVar[tuple[str, ...]] = ("pinion_bearings", "gear_bearings")

    kind: Literal["bevel-drive"]
    input_speed: AngularSpeed = Field(description="the pinion shaft's speed")
    pinion_bearings: list[DriveBearing] = Field(description="exactly two, on the pinion "
                                                "shaft")
    gear_bearings: list[DriveBearing] | None = Field(None, description="exactly two, on the "
                                                     "gear shaft (optional)")
    pinion_arrangement: ShaftArrangement = Field(
        "locating-floating", description="how the pinion shaft's bearings share its axial "
        "force: one locating, or two adjusted against each other")
    gear_arrangement: ShaftArrangement = Field(
        "locating-floating", description="the same for the gear shaft")
    method: Literal["iso-281", "iso-16281"] = Field(
        "iso-281", description="iso-281: each shaft's statics and its bearings' catalogue "
        "method; iso-16281: each shaft rigid on its bearings' contacts (clearance, "
        "preload, stiffness) and the gears' displacements at the mesh")
    pinion_setting: PairSetting | None = Field(
        None, description="iso-16281, an adjusted pinion shaft: {end_play: …} or "
        "{preload: …}")
    gear_setting: PairSetting | None = Field(
        None, description="iso-16281, an adjusted gear shaft: {end_play: …} or "
        "{preload: …}")
    reliability: Reliability = 0.9
    lubrication: Lubrication | None = None
    contamination_factor: UnitFraction | None = None
    catalogue: str | None = Field(None, description="a catalogue file (CSV), relative to "
                                  "the spec, for the bearings' designations")
    limits: BevelDriveLimits = BevelDriveLimits()
    duty_cycle: list[DriveBin] | None = Field(  # type: ignore[valid-type]
        None, description="load cases with their shares of the time (a field a bin leaves "
        "out is the spec's)")

    def turning_speed(self) -> Any:
        """The pinion shaft's speed."""
        return self.input_speed

    def with_turning_speed(self, speed: Any) -> BevelDriveSpec:
        """The drive with its pinion shaft at ``speed``."""
        return self.model_copy(update={"input_speed": speed})

    @rule
    def _pair_sized(self) -> SpecFieldError | None:
        if self.face_width is None or self.module is None or None in (self.gear_a.teeth,
                                                                      self.gear_b.teeth):
            return SpecFieldError("face_width", "a drive needs the pair's teeth, module and "
                                  "face_width for its tooth forces")
        return None

    @rule
    def _loaded(self) -> SpecFieldError | None:
        if self.torque is None and self.power is None:
            return SpecFieldError("torque", "a drive needs the load: torque (like 60 N*m) or "
                                  "power (like 9.4 kW) on the pinion")
        return None

    @rule
    def _turning(self) -> SpecFieldError | None:
        if self.input_speed == 0:
            return SpecFieldError("input_speed", "must not be zero: the lives need a turning "
                                  "drive, like 1500 rpm")
        return None

    @rule
    def _shafts_carried(self) -> list[SpecFieldError]:
        """Each shaft on two bearings or more, apart, one of them locating, none a thrust
        bearing (how many the statics solve is theirs to say):
        read from the bearing lists alone, so a bad shared field hides none of it."""
        problems: list[SpecFieldError] = []
        for shaft, bearings in self.shafts():
            field = f"{shaft}_bearings"
            if len(bearings) < 2:  # more is the statics' to refuse, not the data's
                problems.append(SpecFieldError(field, "one bearing cannot carry a shaft's "
                                               "moment, and the statics take exactly two "
                                               f"bearings, got {len(bearings)}"))
                continue
            positions = [bearing.position for bearing in bearings]
            problems += [SpecFieldError(f"{field}.{i}.position", "two bearings at the "
                                        "same position cannot carry the shaft's moment")
                         for i, position in enumerate(positions, 1)
                         if position in positions[:i - 1]]
            arrangement = self.arrangement(shaft)
            if arrangement == "locating-floating":
                problems += self._one_locating(field, bearings)
            else:
                problems += self._adjusted(field, arrangement, bearings)
            for i, bearing in enumerate(bearings, 1):
                if traits(bearing.type).thrust:
                    problems.append(SpecFieldError(
                        f"{field}.{i}.type", "a thrust bearing takes no radial load, and "
                        "the gear forces load every bearing of the shaft radially"))
                if bearing.arrangement != "single" and arrangement != "locating-floating":
                    # A matched pair is one position of a locating-floating shaft, rated
                    # as the pair; adjusted shafts pair their own two bearings.
                    problems.append(SpecFieldError(
                        f"{field}.{i}.arrangement", f"a {arrangement} shaft adjusts its two "
                        "bearings against each other, each one bearing: leave arrangement "
                        f"out, or give {shaft}_arrangement: locating-floating for a matched "
                        "pair as one position"))
        return problems

    @staticmethod
    def _one_locating(field: str, bearings: list[DriveBearing]) -> list[SpecFieldError]:
        # R is the share of an adjusted pair's preload; a locating bearing takes the whole
        # force whatever R is, so a given R would change no number.
        problems = [SpecFieldError(
            f"{field}.{i}.induced_axial_factor", "not used in a locating-floating "
            "arrangement: the locating bearing takes the whole axial force; leave it out, "
            f"or give {field.removesuffix('_bearings')}_arrangement: back-to-back or "
            "face-to-face for two bearings adjusted against each other")
            for i, bearing in enumerate(bearings, 1)
            if "induced_axial_factor" in bearing.model_fields_set]
        locating = [i for i, bearing in enumerate(bearings, 1) if bearing.locating]
        if len(locating) == 1:
            return problems
        return [*problems, SpecFieldError(
            f"{field}.1.locating" if not locating else f"{field}.{locating[1]}.locating",
            "exactly one bearing of a shaft is locating: it takes the whole axial force "
            f"(got {len(locating)})")]

    @staticmethod
    def _adjusted(field: str, arrangement: str, bearings: list[DriveBearing]
                  ) -> list[SpecFieldError]:
        problems = []
        for i, bearing in enumerate(bearings, 1):
            where = f"{field}.{i}"
            if "locating" in bearing.model_fields_set:
                problems.append(SpecFieldError(
                    f"{where}.locating", f"not used in a {arrangement} arrangement: each "
                    "bearing carries the axial force in one direction; leave it out"))
            # one-way bearings are the ones adjusted against each other
            if not traits(bearing.type).one_way:
                problems.append(SpecFieldError(
                    f"{where}.type", f"a {arrangement} arrangement adjusts two single-row "
                    f"angular-contact ball or tapered-roller bearings, not {bearing.type}"))
            elif (traits(bearing.type).family == "ball" and bearing.induced_axial_factor is None
                  and bearing.contact_angle is not None
                  and not math.radians(20) - 1e-12 <= bearing.contact_angle
                  <= math.radians(40) + 1e-12):
                problems.append(SpecFieldError(
                    f"{where}.induced_axial_factor", "the makers' table of R covers 20 to 40 "
                    "deg: give induced_axial_factor from the catalogue",
                    at=f"{where}.contact_angle"))
        return problems

    def arrangement(self, shaft: str) -> str:
        """The arrangement of a shaft's bearings."""
        return self.pinion_arrangement if shaft == "pinion" else self.gear_arrangement

    @rule
    def _bearings_as_rolling_bearings(self) -> list[SpecFieldError]:
        """Everything ``kind: ball-bearing`` refuses of each bearing, with the drive's
        reliability, lubrication and contamination."""
        problems: list[SpecFieldError] = []
        for shaft, bearings in self.shafts():
            for i, bearing in enumerate(bearings, 1):
                if not traits(bearing.type).thrust:
                    problems += self._as_rolling_bearing(f"{shaft}_bearings.{i}",
                                                      self._bearing_under_load(shaft, bearing))
        # A rule of the drive's shared fields (lubrication, contamination) fails for every
        # bearing alike: report it once.
        return list({(p.field, p.message): p for p in problems}.values())

    def field_as_written(self, field: str) -> str:
        """A bearing refused for its load names the drive's load as the spec gives it."""
        return "power" if field == "torque" and self.torque is None else field

    def warnings(self) -> list[str]:
        """Each bearing's notes, named by the bearing (once where all share them), and
        which bearings the static safety leaves out."""
        notes: dict[str, None] = {}
        without_c0 = []
        for shaft, bearings in self.shafts():
            for i, bearing in enumerate(bearings, 1):
                name = f"{shaft}_bearings.{i}"
                spec = self._bearing_under_load(shaft, bearing)
                static = spec.static_left_out()
                for note in spec.warnings():
                    if note == static:  # said once for all bearings, below
                        continue
                    shared = note == spec.lubrication_note()  # the drive's lubrication
                    notes[note if shared else f"{name}: {note}"] = None
                if static is not None:
                    without_c0.append(name)
        if without_c0:
            notes[f"no static_load_rating (or geometry) for {', '.join(without_c0)}: "
                  "static_safety_margin is the smallest s0 of the other bearings"] = None
        return list(notes)

    def shafts(self) -> list[tuple[str, list[DriveBearing]]]:
        """(shaft, its bearings) for the pinion shaft and, when given, the gear shaft."""
        out = [("pinion", self.pinion_bearings)]
        if self.gear_bearings is not None:
            out.append(("gear", self.gear_bearings))
        return out

    def rolling_bearing(self, bearing: DriveBearing, radial: Any = 1.0, axial: Any = 0.0,
                     speed: Any = 1.0) -> RollingBearingSpec:
        """The bearing as a ``kind: ball-bearing`` spec with these loads and speed: one
        definition of the rules and results for a bearing alone and in a drive. Its fields
        were validated by the drive's own (the same) field types."""
        names = (*BearingFields.model_fields, *ELEMENT_MOUNTING_FIELDS)
        fields = {name: getattr(bearing, name) for name in names}
        fields.update(_fields_set=bearing.model_fields_set & set(names), method=self.method,
                      kind="rolling-bearing", radial_load=radial, axial_load=axial, speed=speed,
                      reliability=self.reliability, lubrication=self.lubrication,
                      contamination_factor=self.contamination_factor,
                      # unvalidated, as the rest: a study may make the limit an array
                      limits=BallBearingLimits.model_construct(
                          min_static_safety=self.limits.min_static_safety))
        return RollingBearingSpec.model_construct(**fields)

    def _bearing_under_load(self, shaft: str, bearing: DriveBearing) -> RollingBearingSpec:
        """The bearing as a ``kind: rolling-bearing`` spec under the kind of load it will
        carry: radial, and axial too where it locates or is adjusted against the other."""
        adjusted = self.arrangement(shaft) != "locating-floating"
        spec = self.rolling_bearing(bearing, radial=1.0,
                                    axial=1.0 if bearing.locating or adjusted else 0.0,
                                    speed=1.0)
        spec._adjusted_shaft = adjusted
        return spec

    def _as_rolling_bearing(self, where: str, spec: RollingBearingSpec) -> list[SpecFieldError]:
        """Everything ``kind: rolling-bearing`` refuses of the bearing (``spec``, from
        :meth:`_bearing_under_load`), checked by that kind's own rules."""
        problems = []
        for problem in own_problems(spec):
            if problem.field in ("lubrication", "contamination_factor", "reliability"):
                problems.append(problem)
                continue
            field = problem.field if problem.field not in _DRIVE_SETS else "locating"
            at = None if problem.at is None or problem.at in _DRIVE_SETS else (
                f"{where}.{problem.at}")
            problems.append(SpecFieldError(f"{where}.{field}", problem.message, at=at))
        return problems

    def solver_inputs(self) -> BevelDriveInputs:
        """SI inputs of :func:`bearingcalc.core.bevel_drive.evaluate`: the pair's (gear A
        turning at input_speed relative to a resting arm), and under ``shafts`` each
        shaft's bearings: position, locating, and its ball-bearing inputs without the
        loads and speeds the drive finds; of every bin of a duty cycle."""
        if self.duty_cycle is not None:
            return self.cycle_inputs()
        ratio = self.gear_a.teeth / self.gear_b.teeth  # type: ignore[operator]
        inputs: dict[str, Any] = self.pair_inputs(0.0, -self.input_speed * ratio, self.limits)
        inputs["axes"] = "fixed"
        inputs["input_speed"] = self.input_speed
        inputs["min_rating_life"] = self.limits.min_rating_life
        inputs["min_static_safety"] = self.limits.min_static_safety
        inputs.update({name: getattr(self.limits, name) for name in MESH_LIMITS})
        inputs["shafts"] = {shaft: [self._bearing_inputs(bearing) for bearing in bearings]
                            for shaft, bearings in self.shafts()}
        inputs["arrangements"] = {shaft: self.arrangement(shaft) for shaft, _ in self.shafts()}
        inputs["method"] = self.method
        inputs["settings"] = {shaft: None if setting is None else {
            "end_play": setting.end_play, "preload": setting.preload,
            "stage": setting.stage}
            for shaft, setting in (("pinion", self.pinion_setting),
                                   ("gear", self.gear_setting))}
        return inputs

    def _bearing_inputs(self, bearing: DriveBearing) -> MountedBearingInputs:
        kept = ELEMENT_MOUNTING_INPUTS if self.method == "iso-16281" else ()
        own = {key: value for key, value in self.rolling_bearing(bearing).solver_inputs().items()
               if key in kept or key not in (*_DRIVE_SETS, *MOUNTING_INPUTS,
                                             *MOUNTED_LIMITS, "min_rating_life")}
        return {"position": bearing.position,
                "locating": "locating" if bearing.locating else "floating",
                "induced_axial_factor": bearing.induced_axial_factor, **own}
