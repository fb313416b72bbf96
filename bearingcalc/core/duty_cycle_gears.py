"""Duty cycles of bevel pairs and of drives: AGMA 2003's stress-cycle curves with Miner's
rule for the pair, and each bearing's life over the cycle (``docs/physics.md`` §11).

As in :mod:`bearingcalc.core.duty_cycle`, every per-bin array has the bins on its first
axis.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core.agma_life import (
    BENDING_LIFE_CURVE,
    CONTACT_LIFE_CURVE,
    Curve,
    spectrum_damage,
    spectrum_safety,
)
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.duty_cycle import (
    LIFE_EXPONENT,
    at_bin,
    cycle_solution,
    mean_load,
    miner_life,
    per_bin_results,
    revolution_shares,
)
from bearingcalc.core.solver import Solution

GEAR_COLUMNS: dict[str, tuple[str, str]] = {
    "time_share": ("1", "share of the time"),
    "speed": ("rad/s", "the pinion's speed (0: at rest, no damage)"),
    "bending_stress": ("Pa", "AGMA 2003 s_F (0 at rest: no running stress)"),
    "contact_stress": ("Pa", "AGMA 2003 s_H (0 at rest)"),
    "bending_damage_share": ("1", "share of the bending damage"),
    "contact_damage_share": ("1", "share of the contact damage"),
}
GEAR_CYCLE_RESULTS: dict[str, tuple[str, str]] = {
    "bending_damage": ("1", "D = Σ nᵢ/Nᵢ in bending at the specified loads"),
    "contact_damage": ("1", "D = Σ nᵢ/Nᵢ in contact at the specified loads"),
}
DRIVE_COLUMNS: dict[str, tuple[str, str]] = {
    **{key: GEAR_COLUMNS[key] for key in ("time_share", "speed")},
    "torque": ("N·m", "the pinion's torque"),
    "system_modified_rating_life": ("s", "the bearings' system life at this bin alone"),
    "damage_share": ("1", "share of the bearings' damage, tᵢ·L/Lᵢ"),
    **{key: GEAR_COLUMNS[key] for key in ("bending_damage_share", "contact_damage_share")},
}
DRIVE_CYCLE_RESULTS: dict[str, tuple[str, str]] = {
    "mean_speed": ("rad/s", "n_m = Σ tᵢ·nᵢ of the pinion shaft"),
    **GEAR_CYCLE_RESULTS,
}
#: The pair's results that are the worst over the bins.
GEAR_LARGEST = ("bending_stress", "contact_stress", "gear_b_bending_stress")


def _spectrum(shares: NDArray, safeties: NDArray, cycles: NDArray,
              curve: Curve) -> tuple[NDArray, NDArray]:
    """A member's safety over the spectrum, and each bin's damage at the given loads."""
    return (spectrum_safety(shares, safeties, cycles, curve),
            spectrum_damage(shares, safeties, cycles, curve))


def _member_cycles(inputs: Mapping[str, Any]) -> tuple[NDArray, NDArray]:
    """The design-life cycles of the pinion and of gear B (N·z_A/z_B)."""
    def first_bin(key: str) -> NDArray:
        values = np.asarray(inputs[key], dtype=float)
        return values[0] if values.ndim else values

    pinion = first_bin("cycles")
    return pinion, pinion * first_bin("gear_a_teeth") / first_bin("gear_b_teeth")


def _gear_cycle(results: Mapping[str, NDArray], shares: NDArray, inputs: Mapping[str, Any],
                out: dict[str, NDArray]) -> tuple[NDArray, NDArray]:
    """The pair's rating over the cycle into ``out``; (bending, contact) damage per bin."""
    if "bending_safety" not in results:
        return np.zeros_like(shares), np.zeros_like(shares)
    per_bin = {}
    pinion, gear = _member_cycles(inputs)
    for load, curve in (("bending", BENDING_LIFE_CURVE), ("contact", CONTACT_LIFE_CURVE)):
        safety, damage = _spectrum(shares, results[f"{load}_safety"], pinion, curve)
        out[f"{load}_safety"] = safety
        out[f"{load}_damage"] = np.sum(damage, axis=0)
        weaker = safety
        if f"gear_b_{load}_safety" in results:  # gear B's spectrum, at its own cycles
            out[f"gear_b_{load}_safety"] = spectrum_safety(
                shares, results[f"gear_b_{load}_safety"], gear, curve)
            weaker = np.minimum(safety, out[f"gear_b_{load}_safety"])
        out[f"{load}_safety_margin"] = weaker - np.asarray(
            inputs[f"min_{load}_safety"], dtype=float)[0]
        per_bin[load] = damage
    turning = _turning(inputs)
    for key in GEAR_LARGEST:
        if key in results:  # a running stress: a bin at rest has none
            out[key] = np.max(np.where(turning, results[key], -np.inf), axis=0)
    return per_bin["bending"], per_bin["contact"]


def _turning(inputs: Mapping[str, Any]) -> NDArray:
    """Where a bin turns (its speed above 0)."""
    return np.asarray(inputs["duty_speed"], dtype=float) > 0


def gear_pair_cycle(per_bin: Solution, inputs: Mapping[str, Any]) -> Solution:
    """The cycle of a bevel pair: the spectrum safeties and damages in bending and
    contact, the largest running stresses (of the bins that turn); every other result
    that of the bin doing the most bending damage."""
    results = per_bin.results
    shares, _ = _shares(inputs)
    out = _at_governing(results, shares, inputs)
    bending, contact = _gear_cycle(results, shares, inputs, out)
    turning = _turning(inputs)

    def running(key: str) -> NDArray | None:
        values = results.get(key)
        return None if values is None else np.where(turning, np.abs(values), 0.0)

    columns = {"time_share": inputs["duty_time"], "speed": inputs["duty_speed"],
               "bending_stress": running("bending_stress"),
               "contact_stress": running("contact_stress"),
               "bending_damage_share": _normalised(bending),
               "contact_damage_share": _normalised(contact)}
    per_bin_results(out, {k: v for k, v in columns.items() if v is not None})
    return cycle_solution(per_bin, out)


def drive_cycle(per_bin: Solution, inputs: Mapping[str, Any]) -> Solution:
    """The cycle of a drive: the pair's as :func:`gear_pair_cycle`, each bearing's life
    over the cycle (1/L = Σ tᵢ/Lᵢ over the bins that turn, in time; P_m by its family's
    exponent), the system life of those, the smallest static safety."""
    from bearingcalc.core import bevel_drive

    results = per_bin.results
    shares, mean_speed = _shares(inputs)
    # Time at rest counts in the hours, not in the damage: 1/L = Σ tᵢ/Lᵢ over the bins
    # that turn is the Palmgren–Miner sum in revolutions at the cycle's mean speed.
    time_share = np.asarray(inputs["duty_time"], dtype=float)
    moving = time_share / np.sum(time_share, axis=0) * _turning(inputs)
    system = results["system_modified_rating_life"]
    system_damage = moving / system
    governing = np.argmax(system_damage, axis=0)
    out = {key: at_bin(values, governing) for key, values in results.items()}
    bending, contact = _gear_cycle(results, shares, inputs, out)
    basic, modified, rollers = [], [], False
    for shaft, bearings in inputs["shafts"].items():
        for i, bearing in enumerate(bearings, 1):
            name = f"{shaft}_bearing_{i}"
            family = traits(bearing["bearing_type"]).family
            rollers |= family == "roller"
            for key, life in (("basic_rating_life", basic), ("modified_rating_life", modified)):
                lives = results[f"{name}_{key}"]
                out[f"{name}_{key}"] = miner_life(moving, lives,
                                                  np.argmax(moving / lives, axis=0))
                life.append(out[f"{name}_{key}"])
            loads = results[f"{name}_equivalent_dynamic_load"]
            out[f"{name}_equivalent_dynamic_load"] = mean_load(
                shares, loads, LIFE_EXPONENT[family],
                np.argmax(shares * loads ** LIFE_EXPONENT[family], axis=0))
            for key in ("radial_load", "axial_load", "induced_axial_load"):
                if f"{name}_{key}" in results:
                    out[f"{name}_{key}"] = np.max(results[f"{name}_{key}"], axis=0)
            if f"{name}_static_safety_factor" in results:
                out[f"{name}_static_safety_factor"] = np.min(
                    results[f"{name}_static_safety_factor"], axis=0)
    slope = bevel_drive.ROLLER_WEIBULL_SLOPE if rollers else bevel_drive.WEIBULL_SLOPE
    out["system_basic_rating_life"] = bevel_drive.system_life(basic, slope)
    out["system_modified_rating_life"] = bevel_drive.system_life(modified, slope)
    if "life_margin" in results:
        out["life_margin"] = out["system_modified_rating_life"] / np.asarray(
            inputs["min_rating_life"], dtype=float)[0] - 1.0
    if "static_safety_margin" in results:
        out["static_safety_margin"] = np.min(results["static_safety_margin"], axis=0)
    out["mean_speed"] = mean_speed
    bin_life = np.where(_turning(inputs), system, np.inf)
    # The torque as given; of a bin that gives power, from its tooth force.
    from_force = results["tangential_force"] * results["gear_a_mean_pitch_diameter"] / 2.0
    given = inputs.get("torque")
    torque = from_force if given is None else np.where(
        np.isnan(given), from_force, np.abs(np.asarray(given, dtype=float)))
    columns = {"time_share": inputs["duty_time"], "speed": inputs["duty_speed"],
               "torque": torque,
               "system_modified_rating_life": bin_life,
               "damage_share": _normalised(system_damage)}
    if "bending_safety" in results:  # the pair is rated
        columns.update(bending_damage_share=_normalised(bending),
                       contact_damage_share=_normalised(contact))
    per_bin_results(out, columns)
    names = [f"{shaft}_bearing_{i}" for shaft, bearings in inputs["shafts"].items()
             for i in range(1, len(bearings) + 1)]
    weakest = np.argmin(np.stack(np.broadcast_arrays(*modified)), axis=0)
    return cycle_solution(per_bin, out, {f"weakest_{name}": weakest == i
                                    for i, name in enumerate(names)})


def _shares(inputs: Mapping[str, Any]) -> tuple[NDArray, NDArray]:
    time_share = np.asarray(inputs["duty_time"], dtype=float)
    return revolution_shares(time_share / np.sum(time_share, axis=0), inputs["duty_speed"])


def _at_governing(results: Mapping[str, NDArray], shares: NDArray,
                  inputs: Mapping[str, Any]) -> dict[str, NDArray]:
    """Every result at the bin doing the most bending damage (the first bin without a
    rating)."""
    safeties = results.get("bending_safety")
    if safeties is None:
        governing = np.zeros(np.shape(shares)[1:], dtype=int)
    else:
        damage = spectrum_damage(shares, safeties, _member_cycles(inputs)[0],
                                 BENDING_LIFE_CURVE)
        governing = np.argmax(damage, axis=0)
    return {key: at_bin(values, governing) for key, values in results.items()}


def _normalised(damage: NDArray) -> NDArray:
    total = np.sum(damage, axis=0)
    return np.where(total > 0, damage / np.where(total > 0, total, 1.0), 0.0)
