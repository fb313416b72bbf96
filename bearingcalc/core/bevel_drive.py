"""A bevel drive: a bevel pair on two shafts, each on its rolling bearings, from the
input torque to every bearing's life (``docs/physics.md`` §9).

The pair is solved by :mod:`bearingcalc.core.bevel_gears` and each bearing by
:mod:`bearingcalc.core.rolling_bearing`; this module adds the statics of each shaft
(:mod:`bearingcalc.core.shaft_statics`: two bearings, located or adjusted against each
other) and the system life. A shaft holds a list of bearings: one of any other number
is refused by the statics alone. The bearings' results run along the ``member`` axis;
a duty cycle solves the same path per bin and combines the pair's and each bearing's
bins by their own kinds' rules. Inputs are SI floats or broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core import bevel_gears, mounted_drive, rolling_bearing
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.common import broadcast_all, first_failure
from bearingcalc.core.drive_bearings import (
    BEARING_RESULTS,
    LIVES,
    MOUNTED_LIVES,
    OWN_RESULTS,
    MountedBearing,
    assemble,
)
from bearingcalc.core.duty_cycle import (
    BIN_MEANING,
    at_bin,
    bins_along,
    cycle_solution,
    rolling_bearing_cycle,
)
from bearingcalc.core.duty_cycle_gears import (
    DRIVE_COLUMNS,
    DRIVE_CYCLE_RESULTS,
    gear_pair_cycle,
    normalised,
)
from bearingcalc.core.mounted_bearing import METHOD
from bearingcalc.core.mounted_clearance import WARNINGS as CHAIN_WARNINGS
from bearingcalc.core.mounted_drive import evaluate_mounted
from bearingcalc.core.shaft_statics import (  # noqa: F401  (the drive's statics, re-exported)
    ARRANGEMENTS,
    mean_pitch_point,
    shaft_axial_loads,
    shaft_bending_lines,
    shaft_bending_moments,
    shaft_reactions,
)
from bearingcalc.core.solver import Along, AxisResults, DutyCycle, Members, Solution, Solver

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import BevelDriveInputs

#: The load cases of an adjusted pair, as the table shows them.
LOAD_CASES = {1.0: "1a", 2.0: "1b", 3.0: "1c", 4.0: "2a", 5.0: "2b", 6.0: "2c"}
SHAFTS = ("pinion", "gear")


#: A shaft's statics take this many bearings (more is statically indeterminate).
BEARINGS_PER_SHAFT = 2


def _bearing_names() -> list[str]:
    """The bearings' rows along the member axis, for the statics' two per shaft."""
    return [_row(shaft, i) for shaft in SHAFTS for i in range(1, BEARINGS_PER_SHAFT + 1)]


def _row(shaft: str, position: int) -> str:
    """A bearing's row along the member axis (``pinion_bearing_2``), and the stem of
    its flat result keys."""
    return f"{shaft}_bearing_{position}"


#: Results of one value per design, their SI unit and meaning, in report order: the
#: pair's, then the drive's; the bearings' follow ``gear_speed`` along the member axis.
RESULTS: dict[str, tuple[str, str]] = {
    **bevel_gears.RESULTS,
    "gear_speed": ("rad/s", "the gear shaft's speed, input_speed·z1/z2"),
    "system_basic_rating_life": ("s", "(Σ L10ᵢ^(−e))^(−1/e), e = 10/9 (9/8 with a roller "
                                      "bearing)"),
    "system_modified_rating_life": ("s", "(Σ Lnmᵢ^(−e))^(−1/e), e = 10/9 (9/8 with a "
                                         "roller bearing)"),
    "life_margin": ("1", "system_modified_rating_life / min_rating_life − 1"),
    "static_safety_margin": ("1", "the smallest s0 − min_static_safety"),
    **mounted_drive.RESULTS,
}

#: The table: the pair under its headings, then a block per shaft with a row per bearing.
GROUPS: dict[str, tuple[str, ...]] = {
    **bevel_gears.GROUPS,
    "system": ("gear_speed", "system_basic_rating_life", "system_modified_rating_life",
               "life_margin", "static_safety_margin"),
    "as mounted (ISO/TS 16281)": tuple(mounted_drive.RESULTS),
}
#: The bearings' results, a row per bearing under its shaft's heading.
MEMBER_RESULTS = AxisResults(BEARING_RESULTS, after="gear_speed",
                             # an unloaded bearing of a drive as mounted lives for ever
                             unbounded=("reference_rating_life",
                                        "modified_reference_rating_life"))
#: A bin's results of a drive's duty cycle.
DRIVE_BINS = AxisResults(DRIVE_COLUMNS, by_row=False, meaning=BIN_MEANING,
                         unbounded=("system_modified_rating_life",))

WARNINGS: dict[str, str] = {
    **bevel_gears.WARNINGS,
    **{f"weakest_{name}": f"weakest bearing: {name} (the shortest modified life)"
       for name in _bearing_names()},
    **{f"one_way_{name}_{way}": f"{name} locates its shaft, and a single-row "
       "angular-contact or tapered roller bearing carries thrust one way only: mount it "
       f"to take the gear's thrust, which points {way.replace('_', ' ')} the apex (a drive "
       "that runs both ways needs a locating bearing that carries both)"
       for name in _bearing_names() for way in ("away_from", "toward")},
    **{f"{key}_{name}": f"{name}: {message}" for key, message in CHAIN_WARNINGS.items()
       for name in _bearing_names()},
}
#: The arrangements in which a type that carries thrust one way only in a single row
#: (its trait ``one_way``) still does (a back-to-back or face-to-face pair carries it
#: both ways).
ONE_WAY_ARRANGEMENTS = ("single", "tandem")

#: The drive's own status codes: the pair's (1-8), then a shaft's coinciding bearings,
#: then a shaft on a number of bearings its statics do not take.
COINCIDING_BEARINGS = {"pinion": 20, "gear": 21}
BEARING_COUNT = {"pinion": 22, "gear": 23}
STATUS_REASONS: dict[int, tuple[str, str]] = {
    **bevel_gears.STATUS_REASONS,
    **{code: (f"{shaft}_bearings.2.position", "two bearings at the same position cannot "
              "carry the shaft's moment") for shaft, code in COINCIDING_BEARINGS.items()},
    **{code: (f"{shaft}_bearings", f"the shaft's statics take exactly "
              f"{BEARINGS_PER_SHAFT} bearings: on more the shaft is statically "
              "indeterminate, and how its bearings share the load depends on their "
              "stiffness") for shaft, code in BEARING_COUNT.items()},
    **mounted_drive.STATUS_REASONS,
}
#: The bearings, by their names in the spec, each solved as a ``kind: rolling-bearing``.
#: Their loads and speeds come from the drive: a bearing refused for its load or speed
#: names the drive's torque or input_speed, and one refused for its lubrication the
#: drive's lubrication.
BEARINGS = Members(rolling_bearing.SOLVER,
                   tuple(f"{shaft}_bearings.{i}" for shaft in SHAFTS for i in (1, 2)),
                   {"lubrication": "lubrication", "speed": "input_speed",
                    "radial_load": "torque", "axial_load": "torque"})



def evaluate(inputs: BevelDriveInputs, wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: the pair, each shaft's statics, each bearing's life and the
    system's (see :meth:`bearingcalc.models.bevel_drive.BevelDriveSpec.solver_inputs`).

    ``inputs["shafts"]`` maps a shaft to the list of its bearings' inputs:
    ``position``, ``locating``, ``induced_axial_factor`` and a rolling bearing's inputs
    without loads and speeds; ``inputs["arrangements"]`` maps a shaft to its
    arrangement. Each bearing's status codes are reported by its name in the spec
    (``pinion_bearings.2``). With a duty cycle every number has the bins first, and
    the solution keeps the pair's and the bearings' own (``parts``) for
    :func:`drive_cycle`.
    """
    pair = bevel_gears.evaluate(inputs)
    input_speed = np.abs(np.asarray(inputs["input_speed"], dtype=float))
    gear_speed = input_speed * np.asarray(inputs["gear_a_teeth"], dtype=float) / np.asarray(
        inputs["gear_b_teeth"], dtype=float)
    checks = [(code, np.asarray(len(inputs["shafts"].get(shaft, ())) != BEARINGS_PER_SHAFT))
              for shaft, code in BEARING_COUNT.items() if shaft in inputs["shafts"]]
    if any(refused.any() for _, refused in checks):
        return _refused(pair, checks)
    mounted: list[MountedBearing] = []
    warnings: dict[str, ArrayLike] = dict(pair.warnings)
    for shaft, speed, gear in (("pinion", input_speed, "a"), ("gear", gear_speed, "b")):
        if shaft in inputs["shafts"]:
            found, coinciding, one_way = _shaft(inputs, pair, shaft, gear, speed)
            mounted += found
            warnings.update(one_way)
            checks.append((COINCIDING_BEARINGS[shaft], coinciding))
    lives, as_mounted = LIVES, {}
    if inputs.get("method") == METHOD:
        mounted, as_mounted, own_checks = evaluate_mounted(
            inputs, pair, {"pinion": input_speed, "gear": gear_speed})
        checks += own_checks
        lives = MOUNTED_LIVES
        warnings.update({f"{key}_{bearing.row}": flag for bearing in mounted
                         for key, flag in bearing.solved.warnings.items()
                         if key in CHAIN_WARNINGS})
    results, along, weakest = assemble(pair.results, gear_speed, mounted,
                                       inputs.get("min_rating_life"),
                                       inputs["min_static_safety"], lives)
    results.update(as_mounted)
    results = {key: results[key] for key in RESULTS if key in results}
    warnings.update(weakest)
    shape = np.broadcast_shapes(np.shape(pair.status), *(np.shape(v) for v in results.values()),
                                *(np.shape(c) for _, c in checks))
    status = np.where(np.broadcast_to(pair.status, shape) != 0,
                      np.broadcast_to(pair.status, shape), first_failure(checks, shape))
    return Solution(broadcast_all(results), status,
                    {key: np.broadcast_to(np.asarray(flag, dtype=bool), shape)
                     for key, flag in warnings.items()},
                    {bearing.member: np.broadcast_to(bearing.solved.status, shape)
                     for bearing in mounted},
                    {"member": along.broadcast(shape)},
                    {"pair": pair, **{bearing.member: bearing.solved
                                      for bearing in mounted}})


def _member(shaft: str, position: int) -> str:
    """A bearing's name in the spec (``pinion_bearings.2``), which its status codes and
    its part of the solution go by."""
    return f"{shaft}_bearings.{position}"


def _refused(pair: Solution, checks: list[tuple[int, NDArray]]) -> Solution:
    """A drive whose statics cannot be solved: the pair's results, the refusal."""
    shape = np.shape(pair.status)
    status = np.where(pair.status != 0, pair.status, first_failure(checks, shape))
    return Solution(dict(pair.results), status, dict(pair.warnings))


def _shaft(inputs: Mapping[str, Any], pair: Solution, shaft: str, gear: str, speed: NDArray
           ) -> tuple[list[MountedBearing], NDArray, dict[str, NDArray]]:
    """A shaft's bearings loaded by its statics and solved, where two coincide, and the
    warnings of a one-way bearing that locates the shaft."""
    bearings = inputs["shafts"][shaft]
    positions = tuple(bearing["position"] for bearing in bearings)
    axial_force = pair.results[f"gear_{gear}_axial_force"]
    radial = shaft_reactions(
        positions, *mean_pitch_point(pair.results["mean_cone_distance"],
                                     pair.results[f"gear_{gear}_pitch_angle"]),
        pair.results["tangential_force"], pair.results[f"gear_{gear}_radial_force"],
        axial_force)
    axial, adjusted = shaft_axial_loads(inputs["arrangements"][shaft], bearings, radial,
                                        axial_force)
    mounted = []
    one_way: dict[str, NDArray] = {}
    for i, bearing in enumerate(bearings):
        row = _row(shaft, i + 1)
        one_way.update(_one_way(row, bearing, axial_force))
        loads = {"radial_load": radial[i], "axial_load": axial[i],
                 **{key: values[i] for key, values in adjusted.items()}}
        member_inputs = {**bearing, "radial_load": radial[i], "axial_load": axial[i],
                         "speed": speed, "inner_speed": speed, "outer_speed": 0.0,
                         "min_rating_life": None}
        mounted.append(MountedBearing(row, _member(shaft, i + 1), f"{shaft} shaft bearings",
                                      member_inputs, loads,
                                      rolling_bearing.evaluate(member_inputs)))
    return mounted, np.asarray(positions[0]) == np.asarray(positions[1]), one_way


def _one_way(row: str, bearing: Mapping[str, Any], axial_force: NDArray) -> dict[str, NDArray]:
    """Where a locating bearing that carries thrust one way only takes the gear's thrust
    the other way (``rows``, like every number, may vary along bins or a study)."""
    if (bearing.get("locating") != "locating" or not traits(bearing["bearing_type"]).one_way
            or bearing.get("arrangement", "single") not in ONE_WAY_ARRANGEMENTS):
        return {}
    single_row = np.asarray(1.0 if bearing.get("rows") is None else bearing["rows"],
                            dtype=float) == 1
    return {f"one_way_{row}_away_from": single_row & (axial_force >= 0),
            f"one_way_{row}_toward": single_row & (axial_force < 0)}


def drive_cycle(per_bin: Solution, inputs: Mapping[str, Any]) -> Solution:
    """The cycle of a drive: the pair's by the bevel pair's rule
    (:func:`~bearingcalc.core.duty_cycle_gears.gear_pair_cycle`), each bearing's by the
    rolling bearing's (:func:`~bearingcalc.core.duty_cycle.rolling_bearing_cycle`),
    then the drive's results from those as at one point (:func:`assemble`). The
    statics' loads are the largest over the bins, the load case that of the bin doing
    the bearings' most damage, which governs every other result."""
    # Time at rest counts in the hours, not in the damage: 1/L = Σ tᵢ/Lᵢ over the bins
    # that turn is the Palmgren–Miner sum in revolutions at the cycle's mean speed.
    time_share = np.asarray(inputs["duty_time"], dtype=float)
    turning = np.asarray(inputs["duty_speed"], dtype=float) > 0
    system = per_bin.results["system_modified_rating_life"]
    system_damage = time_share / np.sum(time_share, axis=0) * turning / system
    governing = np.argmax(system_damage, axis=0)
    pair = gear_pair_cycle(per_bin.parts["pair"], inputs, governing)
    mounted = [_bearing_cycle(per_bin, inputs, shaft, position, governing)
               for shaft, bearings in inputs["shafts"].items()
               for position in range(1, len(bearings) + 1)]
    first = {key: np.asarray(inputs[key], dtype=float)[0]
             for key in ("min_static_safety",) if key in inputs}
    min_life = inputs.get("min_rating_life")
    pair_results = {key: pair.results[key] for key in bevel_gears.RESULTS
                    if key in pair.results}
    out, along, weakest = assemble(
        pair_results, at_bin(per_bin.results["gear_speed"], governing), mounted,
        None if min_life is None else np.asarray(min_life, dtype=float)[0],
        first["min_static_safety"])
    out = {key: out[key] for key in RESULTS if key in out}
    out.update({key: pair.results[key] for key in ("bending_damage", "contact_damage")
                if key in pair.results})
    out["mean_speed"] = _mean_speed(inputs)
    bins = _drive_bins(per_bin, inputs, system, system_damage, turning, pair)
    return cycle_solution(per_bin, out, bins, weakest, {"member": along})


#: The statics' loads of a bearing over a cycle: the largest of any bin; the load case
#: is the governing bin's.
CYCLE_LOADS = ("radial_load", "axial_load", "induced_axial_load")
#: A bearing's per-bin results its cycle needs for what the drive reads of it.
CYCLE_INPUTS = (*OWN_RESULTS, "basic_rating_life_revolutions",
                "modified_rating_life_revolutions", "dynamic_load_rating",
                "pair_dynamic_load_rating")


def _bearing_cycle(per_bin: Solution, inputs: Mapping[str, Any], shaft: str, position: int,
                   governing: NDArray) -> MountedBearing:
    """A bearing over the cycle: its bins combined as a rolling bearing's, each at its
    shaft's speed in the bin (the gear shaft's is the pinion's·z1/z2)."""
    members = per_bin.along["member"]
    row = _row(shaft, position)
    index = members.rows.index(row)
    ratio = 1.0 if shaft == SHAFTS[0] else np.asarray(inputs["gear_a_teeth"], dtype=float) \
        / np.asarray(inputs["gear_b_teeth"], dtype=float)
    bearing_inputs = {**inputs["shafts"][shaft][position - 1],
                      "radial_load": members.values["radial_load"][index],
                      "axial_load": members.values["axial_load"][index],
                      "duty_time": inputs["duty_time"],
                      "duty_speed": np.asarray(inputs["duty_speed"], dtype=float) * ratio,
                      "min_rating_life": None}
    loads = {key: np.max(members.values[key][index], axis=0) for key in CYCLE_LOADS
             if members.has(key, index)}
    if members.has("load_case", index):
        loads["load_case"] = at_bin(members.values["load_case"][index], governing)
    member = _member(shaft, position)
    own = per_bin.parts[member]
    # the cycle of what the drive reads of a bearing, not of every result it has
    own = replace(own, results={key: own.results[key] for key in CYCLE_INPUTS
                                if key in own.results})
    return MountedBearing(row, member, members.headings[index], bearing_inputs, loads,
                          rolling_bearing_cycle(own, bearing_inputs))


def _mean_speed(inputs: Mapping[str, Any]) -> NDArray:
    """n_m = Σ tᵢ·nᵢ of the pinion shaft. [rad/s]"""
    time_share = np.asarray(inputs["duty_time"], dtype=float)
    return np.sum(time_share / np.sum(time_share, axis=0)
                  * np.abs(np.asarray(inputs["duty_speed"], dtype=float)), axis=0)


def _drive_bins(per_bin: Solution, inputs: Mapping[str, Any], system: NDArray,
                system_damage: NDArray, turning: NDArray, pair: Solution) -> Along:
    """Each bin's time share, speed, torque, system life alone and shares of the
    damage (the bearings', and the teeth's where the pair is rated)."""
    results = per_bin.results
    # The torque as given; of a bin that gives power, from its tooth force.
    from_force = results["tangential_force"] * results["gear_a_mean_pitch_diameter"] / 2.0
    given = inputs.get("torque")
    torque = from_force if given is None else np.where(
        np.isnan(given), from_force, np.abs(np.asarray(given, dtype=float)))
    columns = {"time_share": inputs["duty_time"], "speed": inputs["duty_speed"],
               "torque": torque,
               "system_modified_rating_life": np.where(turning, system, np.inf),
               "damage_share": normalised(system_damage)}
    gear_bins = pair.along["bin"]
    columns.update({key: gear_bins.values[key] for key in ("bending_damage_share",
                                                           "contact_damage_share")
                    if key in gear_bins.values and "bending_safety" in results})
    return bins_along(columns)


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, WARNINGS, GROUPS,
                members=BEARINGS,
                labels={"load_case": LOAD_CASES},
                duty=DutyCycle(drive_cycle, DRIVE_CYCLE_RESULTS, DRIVE_BINS),
                along={"member": MEMBER_RESULTS}, inputs="BevelDriveInputs")
