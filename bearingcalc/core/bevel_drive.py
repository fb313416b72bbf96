"""A bevel drive: a bevel pair on two shafts, each on two ball bearings, from the input
torque to every bearing's life (``docs/physics.md`` §9).

The pair is solved by :mod:`bearingcalc.core.bevel_gears` and each bearing by
:mod:`bearingcalc.core.ball_bearing`; this module adds the statics of each shaft and
the system life. Inputs are SI floats or broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core import ball_bearing, bevel_gears
from bearingcalc.core.common import broadcast_all

#: The Weibull slope of ball bearings in bearing makers' system-life formula.
WEIBULL_SLOPE = 10.0 / 9.0
SHAFTS = ("pinion", "gear")
BEARING_RESULTS: dict[str, tuple[str, str]] = {
    "radial_load": ("N", "radial load from the shaft's statics"),
    "axial_load": ("N", "axial load (the locating bearing takes the gear's whole thrust)"),
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
    "system_basic_rating_life": ("s", "(Σ L10ᵢ^(−e))^(−1/e), e = 10/9"),
    "system_modified_rating_life": ("s", "(Σ Lnmᵢ^(−e))^(−1/e), e = 10/9"),
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
    **{f"_warn_weakest_{name}": f"weakest bearing: {name} (the shortest modified life)"
       for name in _bearing_names()},
}

#: Status codes: the pair's (1-8), the shafts' own, then each bearing's code from
#: ball_bearing at an offset.
COINCIDING_BEARINGS = {"pinion": 20, "gear": 21}
_BEARING_CODES = max(ball_bearing.STATUS_REASONS) + 1
BEARING_CODE_OFFSETS = {name: 30 + _BEARING_CODES * i for i, name in enumerate(_bearing_names())}
#: A bearing's fields that the drive sets from its own: the drive's field is at fault.
_DRIVE_FIELDS = {"lubrication": "lubrication", "speed": "input_speed", "radial_load": "torque",
                 "axial_load": "torque"}


def _status_reasons() -> dict[int, tuple[str, str]]:
    reasons = dict(bevel_gears.STATUS_REASONS)
    for shaft, code in COINCIDING_BEARINGS.items():
        reasons[code] = (f"{shaft}_bearings.2.position", "two bearings at the same position "
                         "cannot carry the shaft's moment")
    for name, offset in BEARING_CODE_OFFSETS.items():
        shaft, _, index = name.rpartition("_bearing_")
        for code, (field, why) in ball_bearing.STATUS_REASONS.items():
            root = field.split(".", 1)[0]
            where = (field if root == "lubrication" else _DRIVE_FIELDS[root]
                     ) if root in _DRIVE_FIELDS else f"{shaft}_bearings.{index}.{field}"
            reasons[offset + code] = (where, why)
    return reasons


STATUS_REASONS = _status_reasons()


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
    x1, x2 = (np.asarray(x, dtype=float) for x in positions)
    xp, rp = np.asarray(mesh_position, dtype=float), np.asarray(mesh_radius, dtype=float)
    wt, wr, wa = (np.asarray(w, dtype=float) for w in (tangential, radial, axial))
    span = x2 - x1
    r2y = (wr * (xp - x1) + wa * rp) / span
    r2z = wt * (xp - x1) / span
    return np.hypot(wr - r2y, wt - r2z), np.hypot(r2y, r2z)


def system_life(lives: list[NDArray]) -> NDArray:
    r"""L_sys = (Σ L_i^(−e))^(−1/e) with e = 10/9, the ball bearings' Weibull slope.

    Source: Lundberg & Palmgren; the system-life formula of bearing makers' catalogues
    (e.g. SKF, *Rolling bearings*, "System life").
    """
    stacked = np.stack(np.broadcast_arrays(*(np.asarray(life, dtype=float) for life in lives)))
    return np.sum(stacked ** -WEIBULL_SLOPE, axis=0) ** (-1.0 / WEIBULL_SLOPE)


def evaluate(inputs: Mapping[str, Any],
             wanted: Collection[str] | None = None) -> tuple[dict[str, NDArray], NDArray]:
    """Registry entry point: the pair, each shaft's statics, each bearing's life and the
    system's, with status codes (see :mod:`bearingcalc.models.bevel_drive`)."""
    pair, status = bevel_gears.evaluate(inputs)
    out: dict[str, ArrayLike] = dict(pair)
    input_speed = np.abs(np.asarray(inputs["input_speed"], dtype=float))
    ratio = np.asarray(inputs["gear_a_teeth"], dtype=float) / np.asarray(
        inputs["gear_b_teeth"], dtype=float)
    out["gear_speed"] = input_speed * ratio
    mean_cone = pair["mean_cone_distance"]
    modified, basic, safety, names = [], [], [], []
    checks: list[tuple[int, NDArray]] = []
    for shaft, speed, delta, gear in (("pinion", input_speed, pair["gear_a_pitch_angle"], "a"),
                                      ("gear", input_speed * ratio, pair["gear_b_pitch_angle"],
                                       "b")):
        if f"{shaft}_bearing_1.position" not in inputs:
            continue
        radial_force = pair[f"gear_{gear}_radial_force"]
        axial_force = pair[f"gear_{gear}_axial_force"]
        positions = (inputs[f"{shaft}_bearing_1.position"], inputs[f"{shaft}_bearing_2.position"])
        coinciding = np.asarray(positions[0]) == np.asarray(positions[1])
        checks.append((0, np.where(coinciding, np.int8(COINCIDING_BEARINGS[shaft]), np.int8(0))))
        loads = shaft_reactions(
            positions,
            mean_cone * np.cos(delta), mean_cone * np.sin(delta), pair["tangential_force"],
            radial_force, axial_force)
        for i, radial in enumerate(loads, 1):
            name = f"{shaft}_bearing_{i}"
            prefix = name + "."
            locating = inputs[prefix + "locating"] == "locating"
            axial = axial_force if locating else np.zeros_like(axial_force)
            bearing_inputs = {key[len(prefix):]: value for key, value in inputs.items()
                              if key.startswith(prefix)}
            bearing_inputs.update(radial_load=radial, axial_load=axial, speed=speed,
                                  inner_speed=speed, outer_speed=0.0, min_rating_life=None)
            results, code = ball_bearing.evaluate(bearing_inputs)
            checks.append((BEARING_CODE_OFFSETS[name], np.asarray(code)))
            out[f"{name}_radial_load"] = radial
            out[f"{name}_axial_load"] = axial
            for key in ("equivalent_dynamic_load", "basic_rating_life", "modified_rating_life",
                        "static_safety_factor"):
                if key in results:
                    out[f"{name}_{key}"] = results[key]
            modified.append(results["modified_rating_life"])
            basic.append(results["basic_rating_life"])
            names.append(name)
            if "static_safety_factor" in results:
                safety.append(results["static_safety_factor"])
    out["system_basic_rating_life"] = system_life(basic)
    out["system_modified_rating_life"] = system_life(modified)
    if inputs.get("min_rating_life") is not None:
        out["life_margin"] = out["system_modified_rating_life"] / np.asarray(
            inputs["min_rating_life"], dtype=float) - 1.0
    if safety:
        out["static_safety_margin"] = np.min(np.stack(np.broadcast_arrays(*safety)), axis=0) \
            - np.asarray(inputs["min_static_safety"], dtype=float)
    weakest = np.argmin(np.stack(np.broadcast_arrays(*modified)), axis=0)
    for i, name in enumerate(names):
        out[f"_warn_weakest_{name}"] = (weakest == i).astype(float)
    shape = np.broadcast_shapes(np.shape(status), *(np.shape(c) for _, c in checks),
                                *(np.shape(v) for v in out.values()))
    status = np.broadcast_to(status, shape).copy()
    for offset, codes in checks:
        code = np.broadcast_to(codes, shape)
        status = np.where((status == 0) & (code != 0), (offset + code).astype(np.int8), status)
    ordered = {key: out[key] for key in RESULTS if key in out}
    ordered.update({key: value for key, value in out.items() if key.startswith("_warn_")})
    return broadcast_all(ordered), status
