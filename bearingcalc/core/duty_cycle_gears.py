"""Duty cycles of bevel pairs: AGMA 2003's stress-cycle curves with Miner's rule, and
the results a drive's cycle declares (``docs/physics.md`` §11).

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
from bearingcalc.core.duty_cycle import (
    BIN_MEANING,
    at_bin,
    bins_along,
    cycle_solution,
    revolution_shares,
)
from bearingcalc.core.solver import AxisResults, Solution

GEAR_COLUMNS: dict[str, tuple[str, str]] = {
    "time_share": ("1", "share of the time"),
    "speed": ("rad/s", "the pinion's speed (0: at rest, no damage)"),
    "bending_stress": ("Pa", "AGMA 2003 s_F (0 at rest: no running stress)"),
    "contact_stress": ("Pa", "AGMA 2003 s_H (0 at rest)"),
    "bending_damage_share": ("1", "share of the bending damage"),
    "contact_damage_share": ("1", "share of the contact damage"),
}
GEAR_BINS = AxisResults(GEAR_COLUMNS, by_row=False, meaning=BIN_MEANING)
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


def _gear_cycle(results: Mapping[str, NDArray], shares: NDArray, inputs: Mapping[str, Any]
                ) -> tuple[dict[str, NDArray], NDArray, NDArray]:
    """The pair's rating over the cycle, and its bending and contact damage per bin."""
    out: dict[str, NDArray] = {}
    if "bending_safety" not in results:
        return out, np.zeros_like(shares), np.zeros_like(shares)
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
    return out, per_bin["bending"], per_bin["contact"]


def _turning(inputs: Mapping[str, Any]) -> NDArray:
    """Where a bin turns (its speed above 0)."""
    return np.asarray(inputs["duty_speed"], dtype=float) > 0


def gear_pair_cycle(per_bin: Solution, inputs: Mapping[str, Any],
                    governing: NDArray | None = None) -> Solution:
    """The cycle of a bevel pair: the spectrum safeties and damages in bending and
    contact, the largest running stresses (of the bins that turn); every other result
    that of the ``governing`` bin, by default the bin doing the most bending damage."""
    results = per_bin.results
    shares, _ = _shares(inputs)
    out = (_at_governing(results, shares, inputs) if governing is None
           else {key: at_bin(values, governing) for key, values in results.items()})
    cycle, bending, contact = _gear_cycle(results, shares, inputs)
    out.update(cycle)
    turning = _turning(inputs)

    def running(key: str) -> NDArray | None:
        values = results.get(key)
        return None if values is None else np.where(turning, np.abs(values), 0.0)

    columns = {"time_share": inputs["duty_time"], "speed": inputs["duty_speed"],
               "bending_stress": running("bending_stress"),
               "contact_stress": running("contact_stress"),
               "bending_damage_share": normalised(bending),
               "contact_damage_share": normalised(contact)}
    return cycle_solution(per_bin, out,
                          bins_along({k: v for k, v in columns.items() if v is not None}))


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


def normalised(damage: NDArray) -> NDArray:
    total = np.sum(damage, axis=0)
    return np.where(total > 0, damage / np.where(total > 0, total, 1.0), 0.0)
