"""A bevel drive: a bevel pair on two shafts, each on two rolling bearings, from the
input torque to every bearing's life (``docs/physics.md`` §9).

The pair is solved by :mod:`bearingcalc.core.bevel_gears` and each bearing by
:mod:`bearingcalc.core.rolling_bearing`; this module adds the statics of each shaft,
the axial loads of a locating bearing or of two bearings adjusted against each other
(:mod:`bearingcalc.core.arrangements`), and the system life. Inputs are SI floats or
broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core import bevel_gears, rolling_bearing
from bearingcalc.core.arrangements import (
    adjusted_axial_loads,
    induced_axial_factor_ball,
    induced_axial_factor_tapered,
    supports_positive,
)
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.common import broadcast_all, first_failure
from bearingcalc.core.duty_cycle_gears import DRIVE_COLUMNS, DRIVE_CYCLE_RESULTS, drive_cycle
from bearingcalc.core.solver import DutyCycle, Members, Solution, Solver

#: The Weibull slope of bearing makers' system-life formula: 10/9 when every bearing is a
#: ball bearing, 9/8 when any is a roller bearing.
WEIBULL_SLOPE = 10.0 / 9.0
ROLLER_WEIBULL_SLOPE = 9.0 / 8.0
#: How a shaft's two bearings share its axial force.
ARRANGEMENTS = ("locating-floating", "back-to-back", "face-to-face")
#: The load cases of an adjusted pair, as the table shows them.
LOAD_CASES = {1.0: "1a", 2.0: "1b", 3.0: "1c", 4.0: "2a", 5.0: "2b", 6.0: "2c"}
SHAFTS = ("pinion", "gear")
BEARING_RESULTS: dict[str, tuple[str, str]] = {
    "radial_load": ("N", "radial load from the shaft's statics"),
    "axial_load": ("N", "axial load (a locating bearing takes the gear's whole thrust; an "
                        "adjusted pair shares it by the load cases)"),
    "induced_axial_load": ("N", "R·Fr, the axial force the radial load induces in an "
                                "adjusted bearing"),
    "load_case": ("1", "the adjusted pair's load case, 1 to 6 (1a to 2c)"),
    "equivalent_dynamic_load": ("N", "P (ISO 281)"),
    "basic_rating_life": ("s", "L10 in time"),
    "modified_rating_life": ("s", "Lnm in time"),
    "static_safety_factor": ("1", "s0 = C0/P0"),
}


def _bearing_names() -> list[str]:
    return [f"{shaft}_bearing_{i}" for shaft in SHAFTS for i in (1, 2)]


#: Result keys, their SI unit and meaning, in report order: the pair's, then the drive's.
RESULTS: dict[str, tuple[str, str]] = {
    **bevel_gears.RESULTS,
    "gear_speed": ("rad/s", "the gear shaft's speed, input_speed·z1/z2"),
    **{f"{name}_{key}": value for name in _bearing_names()
       for key, value in BEARING_RESULTS.items()},
    "system_basic_rating_life": ("s", "(Σ L10ᵢ^(−e))^(−1/e), e = 10/9 (9/8 with a roller "
                                      "bearing)"),
    "system_modified_rating_life": ("s", "(Σ Lnmᵢ^(−e))^(−1/e), e = 10/9 (9/8 with a "
                                         "roller bearing)"),
    "life_margin": ("1", "system_modified_rating_life / min_rating_life − 1"),
    "static_safety_margin": ("1", "the smallest s0 − min_static_safety"),
}

#: The table: the pair under its headings, then a block per shaft with a row per bearing.
GROUPS: dict[str, tuple[str, ...]] = {
    **bevel_gears.GROUPS,
    "system": ("gear_speed", "system_basic_rating_life", "system_modified_rating_life",
               "life_margin", "static_safety_margin"),
}
MATRICES: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    f"{shaft} shaft bearings": ((f"{shaft}_bearing_1", f"{shaft}_bearing_2"),
                                tuple(BEARING_RESULTS))
    for shaft in SHAFTS
}

WARNINGS: dict[str, str] = {
    **bevel_gears.WARNINGS,
    **{f"weakest_{name}": f"weakest bearing: {name} (the shortest modified life)"
       for name in _bearing_names()},
    **{f"one_way_{name}_{way}": f"{name} locates its shaft, and a single-row "
       "angular-contact or tapered roller bearing carries thrust one way only: mount it "
       f"to take the gear's thrust, which points {way.replace('_', ' ')} the apex (a drive "
       "that runs both ways needs a locating bearing that carries both)"
       for name in _bearing_names() for way in ("away_from", "toward")},
}
#: The arrangements in which a type that carries thrust one way only in a single row
#: (its trait ``one_way``) still does (a back-to-back or face-to-face pair carries it
#: both ways).
ONE_WAY_ARRANGEMENTS = ("single", "tandem")

#: The drive's own status codes: the pair's (1-8), then a shaft's coinciding bearings.
COINCIDING_BEARINGS = {"pinion": 20, "gear": 21}
STATUS_REASONS: dict[int, tuple[str, str]] = {
    **bevel_gears.STATUS_REASONS,
    **{code: (f"{shaft}_bearings.2.position", "two bearings at the same position cannot "
              "carry the shaft's moment") for shaft, code in COINCIDING_BEARINGS.items()},
}
#: The bearings, by their names in the spec, each solved as a ``kind: rolling-bearing``.
#: Their loads and speeds come from the drive: a bearing refused for its load or speed
#: names the drive's torque or input_speed, and one refused for its lubrication the
#: drive's lubrication.
BEARINGS = Members(rolling_bearing.SOLVER,
                   tuple(f"{shaft}_bearings.{i}" for shaft in SHAFTS for i in (1, 2)),
                   {"lubrication": "lubrication", "speed": "input_speed",
                    "radial_load": "torque", "axial_load": "torque"})


def shaft_reactions(positions: tuple[ArrayLike, ArrayLike], mesh_position: ArrayLike,
                    mesh_radius: ArrayLike, tangential: ArrayLike, radial: ArrayLike,
                    axial: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""Radial loads of the two simple supports of a rigid shaft carrying a gear force.

    x runs along the shaft from the pitch-cone apex toward the gear's back face; the
    mean pitch point is at x_p, at radius r_p from the axis. The gear force there has
    W_t across the plane of the axis and the pitch point, W_r toward the axis and W_a
    along +x (away from the apex). Moments about the first support in the two planes:

    .. math:: R_{2y} = \frac{W_r(x_p - x_1) + W_a r_p}{x_2 - x_1}, \quad
              R_{1y} = W_r - R_{2y}, \quad
              R_{2z} = \frac{W_t(x_p - x_1)}{x_2 - x_1}, \quad R_{1z} = W_t - R_{2z}

    Each bearing's radial load is |(R_y, R_z)|. Straddle (x1 < x_p < x2) and overhung
    (both supports on one side) mountings alike.

    Parameters
    ----------
    positions : (x1, x2) of the bearings. [m]
    mesh_position, mesh_radius : x_p, r_p of the mean pitch point. [m]
    tangential, radial, axial : W_t, W_r, W_a. [N]

    Source: statics of a beam on two simple supports (Budynas & Nisbett, *Shigley's
    Mechanical Engineering Design*, 10th ed., Example 13-8 sets up the same balance).
    """
    (r1y, r1z), (r2y, r2z) = _support_forces(positions, mesh_position, mesh_radius,
                                             tangential, radial, axial)
    return np.hypot(r1y, r1z), np.hypot(r2y, r2z)


def _support_forces(positions: tuple[ArrayLike, ArrayLike], mesh_position: ArrayLike,
                    mesh_radius: ArrayLike, tangential: ArrayLike, radial: ArrayLike,
                    axial: ArrayLike) -> tuple[tuple[NDArray, NDArray], tuple[NDArray, NDArray]]:
    """((R1y, R1z), (R2y, R2z)) of :func:`shaft_reactions`, in the two planes. [N]"""
    x1, x2 = (np.asarray(x, dtype=float) for x in positions)
    xp, rp = np.asarray(mesh_position, dtype=float), np.asarray(mesh_radius, dtype=float)
    wt, wr, wa = (np.asarray(w, dtype=float) for w in (tangential, radial, axial))
    span = x2 - x1
    r2y = (wr * (xp - x1) + wa * rp) / span
    r2z = wt * (xp - x1) / span
    return (wr - r2y, wt - r2z), (r2y, r2z)


def mean_pitch_point(mean_cone_distance: ArrayLike, pitch_angle: ArrayLike
                     ) -> tuple[NDArray, NDArray]:
    """(x_p, r_p) = (Rm·cosδ, Rm·sinδ): where a gear's mean pitch point lies along its
    shaft from the pitch-cone apex, and how far from the axis. [m]"""
    distance, angle = np.asarray(mean_cone_distance), np.asarray(pitch_angle)
    return distance * np.cos(angle), distance * np.sin(angle)


def shaft_bending_moments(x: ArrayLike, positions: tuple[float, float], mesh_position: float,
                          mesh_radius: float, tangential: float, radial: float,
                          axial: float) -> tuple[NDArray, NDArray]:
    r"""The bending moment along a shaft of :func:`shaft_reactions`, in its two planes.

    With the supports' reactions from the balance of the whole shaft, the moment at a
    section x is that of every force on the side nearer the apex (x' < x):

    .. math:: M_y(x) = \sum_i R_{iy}\langle x - x_i\rangle - W_r\langle x - x_p\rangle
              + W_a r_p H(x - x_p), \quad
              M_z(x) = \sum_i R_{iz}\langle x - x_i\rangle - W_t\langle x - x_p\rangle

    (⟨u⟩ = max(u, 0), H the unit step; W_a r_p is the couple of the axial force at
    the pitch point). Both vanish beyond the last force, and each slope jumps by the
    reaction at a support. [N·m] at x [m]; inputs as in :func:`shaft_reactions`.

    Source: singularity functions of a beam, Budynas & Nisbett, *Shigley's Mechanical
    Engineering Design*, 10th ed., §3-3.
    """
    x = np.asarray(x, dtype=float)
    first, second = _support_forces(positions, mesh_position, mesh_radius, tangential,
                                    radial, axial)
    reactions = ((positions[0], *first), (positions[1], *second))

    def arm(at: float) -> NDArray:
        return np.maximum(x - at, 0.0)

    moment_y = sum(ry * arm(at) for at, ry, _ in reactions) - radial * arm(mesh_position) \
        + axial * mesh_radius * (x > mesh_position)
    moment_z = sum(rz * arm(at) for at, _, rz in reactions) - tangential * arm(mesh_position)
    return np.asarray(moment_y), np.asarray(moment_z)


def system_life(lives: list[NDArray], slope: float = WEIBULL_SLOPE) -> NDArray:
    r"""L_sys = (Σ L_i^(−e))^(−1/e), e the Weibull slope: 10/9 for ball bearings, 9/8
    when any bearing is a roller bearing.

    Source: Lundberg & Palmgren; the system-life formula of bearing makers' catalogues
    (e.g. SKF, *Rolling bearings*, "System life").
    """
    stacked = np.stack(np.broadcast_arrays(*(np.asarray(life, dtype=float) for life in lives)))
    return np.sum(stacked ** -slope, axis=0) ** (-1.0 / slope)


def induced_axial_factor(bearing: Mapping[str, Any]) -> NDArray:
    """R of one bearing of an adjusted pair: the spec's ``induced_axial_factor``, else
    0.5/Y for a tapered roller bearing (the catalogue's Y above e, or ISO's 0.4·cotα) and
    the makers' table against α for an angular-contact ball bearing."""
    if bearing.get("induced_axial_factor") is not None:
        return np.asarray(bearing["induced_axial_factor"], dtype=float)
    alpha = np.asarray(bearing["contact_angle"], dtype=float)
    if traits(bearing["bearing_type"]).family == "roller":  # a tapered roller bearing
        y = bearing.get("load_y")
        return induced_axial_factor_tapered(0.4 / np.tan(alpha) if y is None else y)
    return induced_axial_factor_ball(alpha)


def shaft_axial_loads(arrangement: str, bearings: list[Mapping[str, Any]],
                      radial: tuple[NDArray, NDArray], axial_force: NDArray
                      ) -> tuple[list[NDArray], dict[str, list[NDArray]]]:
    """Each bearing's axial load, and for an adjusted pair the induced forces and the
    load case of each. Locating-floating: the locating bearing takes the whole force."""
    if arrangement == "locating-floating":  # a spiral pair's force may point either way
        return [np.abs(axial_force) if bearing["locating"] == "locating"
                else np.zeros_like(axial_force) for bearing in bearings], {}
    factors = [induced_axial_factor(bearing) for bearing in bearings]
    positions = [np.asarray(bearing["position"], dtype=float) for bearing in bearings]
    # Cases 1: Ka acts in the direction the second bearing supports.
    second_positive = supports_positive(positions[1], positions[0], arrangement)
    loads = adjusted_axial_loads(radial[0], radial[1], factors[0], factors[1], axial_force,
                                 second_positive == (axial_force >= 0))
    case = loads.case
    return [loads.first, loads.second], {
        "induced_axial_load": [factors[0] * radial[0], factors[1] * radial[1]],
        "load_case": [case, case]}


def evaluate(inputs: Mapping[str, Any], wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: the pair, each shaft's statics, each bearing's life and the
    system's (see :meth:`bearingcalc.models.bevel_drive.BevelDriveSpec.solver_inputs`).

    ``inputs["shafts"]`` maps a shaft to its two bearings' inputs: ``position``,
    ``locating``, ``induced_axial_factor`` and a rolling bearing's inputs without loads
    and speeds; ``inputs["arrangements"]`` maps a shaft to its arrangement. Each bearing's
    status codes are reported by its name in the spec (``pinion_bearings.2``).
    """
    pair = bevel_gears.evaluate(inputs)
    out: dict[str, ArrayLike] = dict(pair.results)
    warnings: dict[str, ArrayLike] = dict(pair.warnings)
    input_speed = np.abs(np.asarray(inputs["input_speed"], dtype=float))
    ratio = np.asarray(inputs["gear_a_teeth"], dtype=float) / np.asarray(
        inputs["gear_b_teeth"], dtype=float)
    out["gear_speed"] = input_speed * ratio
    mean_cone = pair.results["mean_cone_distance"]
    modified, basic, safety, names = [], [], [], []
    checks: list[tuple[int, NDArray]] = []
    members: dict[str, NDArray] = {}
    rollers = False
    for shaft, speed, delta, gear in (
            ("pinion", input_speed, pair.results["gear_a_pitch_angle"], "a"),
            ("gear", input_speed * ratio, pair.results["gear_b_pitch_angle"], "b")):
        bearings = inputs["shafts"].get(shaft)
        if bearings is None:
            continue
        positions = (bearings[0]["position"], bearings[1]["position"])
        checks.append((COINCIDING_BEARINGS[shaft],
                       np.asarray(positions[0]) == np.asarray(positions[1])))
        axial_force = pair.results[f"gear_{gear}_axial_force"]
        loads = shaft_reactions(
            positions, *mean_pitch_point(mean_cone, delta), pair.results["tangential_force"],
            pair.results[f"gear_{gear}_radial_force"], axial_force)
        axial_loads, adjusted = shaft_axial_loads(inputs["arrangements"][shaft], bearings,
                                                  loads, axial_force)
        for i, (bearing, radial, axial) in enumerate(zip(bearings, loads, axial_loads,
                                                         strict=True), 1):
            name = f"{shaft}_bearing_{i}"
            if (bearing.get("locating") == "locating" and traits(bearing["bearing_type"]).one_way
                    and bearing.get("arrangement", "single") in ONE_WAY_ARRANGEMENTS):
                # rows, like every number, may vary along a duty cycle's bins or a study
                single_row = np.asarray(1.0 if bearing.get("rows") is None
                                        else bearing["rows"], dtype=float) == 1
                warnings[f"one_way_{name}_away_from"] = single_row & (axial_force >= 0)
                warnings[f"one_way_{name}_toward"] = single_row & (axial_force < 0)
            solved = rolling_bearing.evaluate({
                **bearing, "radial_load": radial, "axial_load": axial, "speed": speed,
                "inner_speed": speed, "outer_speed": 0.0, "min_rating_life": None})
            members[f"{shaft}_bearings.{i}"] = solved.status
            rollers |= traits(bearing["bearing_type"]).family == "roller"
            out[f"{name}_radial_load"] = radial
            out[f"{name}_axial_load"] = axial
            for key, values in adjusted.items():
                out[f"{name}_{key}"] = values[i - 1]
            for key in ("equivalent_dynamic_load", "basic_rating_life", "modified_rating_life",
                        "static_safety_factor"):
                if key in solved.results:
                    out[f"{name}_{key}"] = solved.results[key]
            modified.append(solved.results["modified_rating_life"])
            basic.append(solved.results["basic_rating_life"])
            names.append(name)
            if "static_safety_factor" in solved.results:
                safety.append(solved.results["static_safety_factor"])
    slope = ROLLER_WEIBULL_SLOPE if rollers else WEIBULL_SLOPE
    out["system_basic_rating_life"] = system_life(basic, slope)
    out["system_modified_rating_life"] = system_life(modified, slope)
    if inputs.get("min_rating_life") is not None:
        out["life_margin"] = out["system_modified_rating_life"] / np.asarray(
            inputs["min_rating_life"], dtype=float) - 1.0
    if safety:
        out["static_safety_margin"] = np.min(np.stack(np.broadcast_arrays(*safety)), axis=0) \
            - np.asarray(inputs["min_static_safety"], dtype=float)
    weakest = np.argmin(np.stack(np.broadcast_arrays(*modified)), axis=0)
    for i, name in enumerate(names):
        warnings[f"weakest_{name}"] = weakest == i
    results = broadcast_all({key: out[key] for key in RESULTS if key in out})
    shape = np.broadcast_shapes(np.shape(pair.status), *(np.shape(v) for v in results.values()),
                                *(np.shape(c) for _, c in checks))
    status = np.where(np.broadcast_to(pair.status, shape) != 0,
                      np.broadcast_to(pair.status, shape), first_failure(checks, shape))
    return Solution(results, status,
                    {key: np.broadcast_to(np.asarray(flag, dtype=bool), shape)
                     for key, flag in warnings.items()},
                    {name: np.broadcast_to(codes, shape) for name, codes in members.items()})


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, WARNINGS, GROUPS, MATRICES,
                members=BEARINGS,
                labels={f"{name}_load_case": LOAD_CASES for name in _bearing_names()},
                duty=DutyCycle(drive_cycle, DRIVE_CYCLE_RESULTS, DRIVE_COLUMNS,
                               unbounded=("system_modified_rating_life",)))
