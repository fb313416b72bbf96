"""What each kind's solver takes: one typed mapping per kind, SI throughout.

Every number is a float or an array over designs (a study or a sweep hands millions of
values at once; a duty cycle puts its bins on the first axis); ``None`` leaves an
optional group out (ratings given or geometry, lubrication, load factors, a limit). The
models' ``solver_inputs()`` build these, and ``tests/test_solver_inputs.py`` checks that
every example's inputs have exactly the keys declared here.

A ``TypedDict`` rather than a dataclass: studies and sweeps replace a few values of the
nominal inputs by arrays, which a mapping does by copy without knowing the kind.
"""

from __future__ import annotations

from typing import Any, TypedDict

from numpy.typing import ArrayLike

#: A number or an array of numbers over designs (and bins). [SI]
Numbers = ArrayLike
#: An optional number: None where the spec leaves it out.
MaybeNumbers = ArrayLike | None


class CycleInputs(TypedDict, total=False):
    """A duty cycle's own inputs, with every other number's bins on its first axis."""

    duty_time: Numbers    # each bin's share of the time [1]
    duty_speed: Numbers   # each bin's speed, 0 for a bin at rest [rad/s]


class ThrustBearingInputs(TypedDict):
    """:func:`bearingcalc.core.thrust_bearing.evaluate`."""

    ball_radius: MaybeNumbers            # [m]
    contact_angle: MaybeNumbers          # θ [rad]
    pitch_radius: MaybeNumbers           # b [m]
    shaft_speed: Numbers                 # [rad/s]
    ball_count: MaybeNumbers             # [1]
    max_spin_to_roll: MaybeNumbers       # [1]
    axial_load: MaybeNumbers             # [N]
    elastic_modulus: Numbers             # [Pa]
    poisson_ratio: Numbers               # [1]
    density: Numbers                     # [kg/m³]
    max_contact_pressure: Numbers        # [Pa]


class DiskOnCircleInputs(TypedDict):
    """:func:`bearingcalc.core.disk_on_circle.evaluate`."""

    disk_radius: Numbers       # [m]
    surface_radius: Numbers    # [m]
    internal: bool             # inside the circle
    disk_speed: Numbers        # ω [rad/s]
    disk_accel: Numbers        # [rad/s²]
    surface_speed: Numbers     # Ω [rad/s]
    surface_accel: Numbers     # [rad/s²]


class ConeOnPlaneInputs(TypedDict):
    """:func:`bearingcalc.core.cone_on_plane.evaluate`."""

    half_angle: Numbers          # [rad]
    spin_speed: Numbers          # [rad/s]
    spin_accel: Numbers          # [rad/s²]
    axis_point_height: Numbers   # [m]


class _RollerInputs(TypedDict, total=False):
    """A roller bearing's own inputs (a ball bearing's results do not depend on them)."""

    roller_count: MaybeNumbers           # Z [1]
    roller_diameter: MaybeNumbers        # Dwe [m]
    roller_length: MaybeNumbers          # Lwe [m]
    rows: Numbers                        # i [1]
    drawn_cup: bool
    roller_profile_radius: MaybeNumbers  # spherical rollers [m]
    raceway_radius: MaybeNumbers         # spherical rollers [m]


class _BearingOwnInputs(TypedDict):
    """A rolling bearing's inputs other than the load and speed it runs at."""

    bearing_type: str                    # a name of ``core.bearing_types.TYPES``
    arrangement: str                     # "single" or a pair's arrangement
    dynamic_load_rating: MaybeNumbers    # C [N]
    static_load_rating: MaybeNumbers     # C0 [N]
    fatigue_load_limit: MaybeNumbers     # Cu [N]
    static_factor: MaybeNumbers          # f0 [1]
    ball_count: MaybeNumbers             # Z [1]
    ball_diameter: MaybeNumbers          # Dw [m]
    pitch_diameter: MaybeNumbers         # Dpw [m]
    mean_diameter: MaybeNumbers          # dm [m]
    contact_angle: Numbers               # α [rad]
    race_control: str
    max_spin_to_roll: MaybeNumbers       # [1]
    reliability: Numbers                 # [1]
    viscosity: MaybeNumbers              # ν [m²/s]
    viscosity_40: MaybeNumbers           # [m²/s]
    viscosity_100: MaybeNumbers          # [m²/s]
    temperature: MaybeNumbers            # [K]
    ep_additives: Numbers | bool
    contamination_factor: MaybeNumbers   # eC [1]
    load_x: MaybeNumbers                 # the catalogue's X, Y, e, Y1, Y2, X0, Y0 [1]
    load_y: MaybeNumbers
    load_e: MaybeNumbers
    load_y1: MaybeNumbers
    load_y2: MaybeNumbers
    load_x0: MaybeNumbers
    load_y0: MaybeNumbers
    min_static_safety: Numbers           # [1]
    inner_groove_conformity: MaybeNumbers  # fi [1]
    outer_groove_conformity: MaybeNumbers  # fe [1]
    elastic_modulus: Numbers             # [Pa]
    poisson_ratio: Numbers               # [1]
    max_contact_pressure: Numbers        # [Pa]


class _OperatingInputs(TypedDict):
    radial_load: Numbers                 # Fr [N]
    axial_load: Numbers                  # Fa [N]
    speed: Numbers                       # the rings' relative speed [rad/s]
    inner_speed: Numbers                 # [rad/s]
    outer_speed: Numbers                 # [rad/s]
    min_rating_life: MaybeNumbers        # [s]


class _MountingInputs(TypedDict, total=False):
    """ISO/TS 16281's method (absent in a drive's bearing)."""

    method: str                          # "iso-281" or "iso-16281"
    operating_clearance: MaybeNumbers    # the mounted diametral clearance [m]
    tilting_moment: MaybeNumbers         # on the inner ring, about z [N·m]
    misalignment: MaybeNumbers           # the inner ring's tilt, imposed [rad]
    roller_profile: str                  # "iso", "none" or "crown" (rollers)
    crown_radius: MaybeNumbers           # a "crown" profile's radius [m]
    laminae: MaybeNumbers                # slices of each roller [1]
    roller_included_angle: MaybeNumbers  # a tapered roller's included angle [rad]
    edge_stress_factor: bool             # ISO/TS 16281's edge-stress factor in the life
    min_stiffness_radial: MaybeNumbers   # the least radial stiffness as mounted [N/m]
    min_stiffness_axial: MaybeNumbers    # the least axial stiffness as mounted [N/m]
    min_operating_clearance: MaybeNumbers  # the least clearance a mounting gives [m]
    #: the drawing the operating clearance follows from (see
    #: :func:`bearingcalc.core.mounted_clearance.mounted_clearance`), in its place
    mounting: dict[str, Any] | None
    setting_end_play: MaybeNumbers       # a pair's end play, negative: preload [m]
    setting_preload: MaybeNumbers        # a pair's preload at rest, each bearing [N]
    setting_stage: str | None            # where the end play was set: mounted, bench
    pair_spacing: MaybeNumbers           # a pair's pressure centres' distance [m]
    width: MaybeNumbers                  # B (T): a pair's spacing, a double row's [m]


class RollingBearingInputs(_BearingOwnInputs, _OperatingInputs, _RollerInputs, _MountingInputs,
                           CycleInputs):
    """:func:`bearingcalc.core.rolling_bearing.evaluate` (ball and roller bearings)."""


class _BevelPairInputs(TypedDict):
    gear_a_teeth: MaybeNumbers           # [1]
    gear_b_teeth: MaybeNumbers           # [1]
    module: MaybeNumbers                 # [m]
    gear_a_pitch_radius: MaybeNumbers    # [m]
    gear_b_pitch_radius: MaybeNumbers    # [m]
    gear_a_pitch_angle: MaybeNumbers     # [rad]
    gear_b_pitch_angle: MaybeNumbers     # [rad]
    shaft_angle: Numbers                 # Σ [rad]
    arm_speed: Numbers                   # ω_Z [rad/s]
    gear_b_speed: Numbers                # Ω [rad/s]
    max_apex_mismatch: Numbers           # [m]
    face_width: MaybeNumbers             # b [m]
    pressure_angle: Numbers              # [rad]
    torque: MaybeNumbers                 # on gear A [N·m]
    power: MaybeNumbers                  # [W]
    spiral_angle: MaybeNumbers           # [rad]
    cutter_radius: MaybeNumbers          # [m]
    thrust_sign: MaybeNumbers            # ±1
    quality_number: MaybeNumbers         # AGMA Qv [1]
    hardness: MaybeNumbers               # [HB]
    material: str | None
    grade: MaybeNumbers                  # [1]
    gear_hardness: MaybeNumbers          # [HB]
    temperature: MaybeNumbers            # [K]
    geometry_factor_bending_gear: MaybeNumbers  # [1]
    mounting_factor: MaybeNumbers        # [1]
    crowned: MaybeNumbers                # 1 crowned, 0 not
    geometry_factor_bending: MaybeNumbers  # [1]
    geometry_factor_pitting: MaybeNumbers  # [1]
    overload_factor: MaybeNumbers        # [1]
    cycles: MaybeNumbers                 # [1]
    reliability: MaybeNumbers            # [1]
    max_face_width_ratio: Numbers        # [1]
    min_bending_safety: Numbers          # [1]
    min_contact_safety: Numbers          # [1]
    axes: str                            # "fixed" or "epicyclic"


class _BlankInputs(TypedDict, total=False):
    """A spiral or Zerol pair's ISO 23509 blank (absent for a straight pair)."""

    profile_shift: MaybeNumbers          # x_hm1, None: Gleason's [1]
    thickness_modification_pinion: MaybeNumbers  # x_sm1 [1]
    thickness_modification_gear: MaybeNumbers    # x_sm2 [1]
    addendum_factor: MaybeNumbers        # k_hap [1]
    dedendum_factor: MaybeNumbers        # k_hfp [1]
    tool_edge_radius_pinion: MaybeNumbers  # ρ_a01, None: 0.2·m_mn [m]
    tool_edge_radius_gear: MaybeNumbers    # ρ_a02 [m]
    taper: str                           # standard-depth, uniform-depth or duplex


class BevelGearsInputs(_BevelPairInputs, _BlankInputs, CycleInputs):
    """:func:`bearingcalc.core.bevel_gears.evaluate`."""


class _MountedBearingInputs(TypedDict):
    position: Numbers                    # along the shaft from the gear's mean point [m]
    locating: str                        # "locating" or "floating"
    induced_axial_factor: MaybeNumbers   # the catalogue's induced-force factor [1]


class _ElementMountingInputs(TypedDict, total=False):
    """A drive's bearing as mounted (absent under the catalogue method)."""

    operating_clearance: MaybeNumbers    # the mounted diametral clearance [m]
    mounting: dict[str, Any] | None      # the drawing it follows from, in its place
    roller_profile: str                  # "iso", "none" or "crown" (rollers)
    crown_radius: MaybeNumbers           # [m]
    laminae: MaybeNumbers                # [1]
    roller_included_angle: MaybeNumbers  # [rad]
    edge_stress_factor: bool             # in the life
    width: MaybeNumbers                  # B: where a double row's rows lie [m]


class MountedBearingInputs(_MountedBearingInputs, _BearingOwnInputs, _RollerInputs,
                           _ElementMountingInputs):
    """One of a shaft's bearings: where it sits, whether it locates, and its rolling
    bearing inputs without the loads and speeds the drive finds."""


class _BevelDriveInputs(_BevelPairInputs, _BlankInputs):
    input_speed: Numbers                 # the pinion's [rad/s]
    min_rating_life: MaybeNumbers        # [s]
    min_static_safety: Numbers           # [1]
    max_mesh_offset_change: MaybeNumbers   # as mounted, the largest |E| [m]
    max_pinion_axial_shift: MaybeNumbers   # |P| [m]
    max_gear_axial_shift: MaybeNumbers     # |G| [m]
    max_shaft_angle_change: MaybeNumbers   # |Σ| [rad]
    #: "pinion" and "gear" -> the shaft's bearings
    shafts: dict[str, list[MountedBearingInputs]]
    #: "pinion" and "gear" -> "locating-floating", "back-to-back" or "face-to-face"
    arrangements: dict[str, str]
    method: str                          # "iso-281" or "iso-16281"
    #: "pinion" and "gear" -> an adjusted shaft's {"end_play", "preload"} [m, N] or None
    settings: dict[str, dict[str, MaybeNumbers] | None]


class BevelDriveInputs(_BevelDriveInputs, CycleInputs):
    """:func:`bearingcalc.core.bevel_drive.evaluate`."""
