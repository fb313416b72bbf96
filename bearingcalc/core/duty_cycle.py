"""Duty cycles: a design's bins, solved at once along the first axis of every input, and
combined into the cycle's results by the Palmgren–Miner rule (``docs/physics.md`` §11).

A bin is one load case with its share of the time. Every function takes arrays whose
first axis runs over the bins (the designs follow) and returns the cycle's, without it.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.bearing_life import life_margin
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.iso281 import LIFE_EXPONENT
from bearingcalc.core.solver import Along, AxisResults, Solution, bin_rows

#: Per-bin results: column -> (SI unit, meaning).
BEARING_COLUMNS: dict[str, tuple[str, str]] = {
    "time_share": ("1", "share of the time"),
    "speed": ("rad/s", "speed (0: counts for the static safety only)"),
    "radial_load": ("N", "Fr"),
    "axial_load": ("N", "Fa"),
    "equivalent_dynamic_load": ("N", "P"),
    "modified_rating_life": ("s", "Lnm at this bin's load and speed alone"),
    "damage_share": ("1", "share of the cycle's damage, Uᵢ·Lnm/Lnmᵢ"),
}
#: A bin's results are keyed ``duty_{k}_{column}``, column by column; one that does
#: not turn lives for ever.
BIN_MEANING = "bin {position}: {meaning}"
BEARING_BINS = AxisResults(BEARING_COLUMNS, by_row=False, meaning=BIN_MEANING,
                           unbounded=("modified_rating_life",))
#: Results only a cycle has.
BEARING_CYCLE_RESULTS: dict[str, tuple[str, str]] = {
    "mean_speed": ("rad/s", "n_m = Σ tᵢ·nᵢ"),
    "mean_equivalent_load": ("N", "P_m = (Σ Uᵢ·Pᵢ^p)^(1/p), Uᵢ = tᵢ·nᵢ/n_m"),
}
#: Results that are the worst over the bins: the smallest, and the largest.
SMALLEST = ("static_safety_factor", "static_safety_margin", "contact_pressure_margin",
            "spin_to_roll_margin")
LARGEST = ("static_equivalent_load", "max_ball_load", "max_roller_load",
           "inner_contact_pressure", "outer_contact_pressure", "max_contact_pressure",
           "inner_contact_semi_major", "inner_contact_semi_minor", "outer_contact_semi_major",
           "outer_contact_semi_minor", "inner_contact_approach", "outer_contact_approach",
           "inner_contact_half_width", "outer_contact_half_width")


def revolution_shares(time_share: ArrayLike, speed: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""Each bin's share of the revolutions, and the mean speed.

    .. math:: U_i = \frac{t_i n_i}{\sum_j t_j n_j}, \qquad n_m = \sum_j t_j n_j

    Parameters
    ----------
    time_share : tᵢ, adding up to 1 over the bins (first axis). [1]
    speed : nᵢ, >= 0. [rad/s]

    Returns
    -------
    (Uᵢ [1], n_m [rad/s]).

    Source: ISO 281:2007 with the Palmgren–Miner rule; SKF, *Rolling bearings*, 2018,
    "Calculation of the rating life under fluctuating operating conditions".
    """
    revolutions = np.asarray(time_share, dtype=float) * np.abs(np.asarray(speed, dtype=float))
    mean_speed = np.sum(revolutions, axis=0)
    return revolutions / mean_speed, mean_speed


def miner_life(shares: ArrayLike, lives: ArrayLike, governing: NDArray) -> NDArray:
    r"""The life over a cycle of bins each with its own life, by the Palmgren–Miner rule.

    .. math:: \frac{1}{L} = \sum_i \frac{U_i}{L_i}

    written as L = L_g / Σ Uᵢ·L_g/Lᵢ about the governing bin g, which is exact for one
    bin and keeps the sum's terms near 1.

    Parameters
    ----------
    shares : Uᵢ, each bin's share of the revolutions (first axis). [1]
    lives : Lᵢ, in revolutions. [1]
    governing : the index of the governing bin of each design.
    """
    lives = np.asarray(lives, dtype=float)
    reference = at_bin(lives, governing)
    return reference / np.sum(np.asarray(shares, dtype=float) * (reference / lives), axis=0)


def mean_load(shares: ArrayLike, loads: ArrayLike, exponent: float,
              governing: NDArray) -> NDArray:
    r"""The mean equivalent load of a cycle.

    .. math:: P_m = \left(\sum_i U_i P_i^p\right)^{1/p}

    written about the governing bin g as P_g·(Σ Uᵢ·(Pᵢ/P_g)^p)^(1/p).

    Parameters
    ----------
    shares : Uᵢ (first axis). [1]
    loads : Pᵢ. [N]
    exponent : p, 3 for ball bearings and 10/3 for roller bearings.
    governing : the index of the governing bin of each design.

    Source: ISO 281:2007; SKF, *Rolling bearings*, 2018, "Fluctuating load".
    """
    loads = np.asarray(loads, dtype=float)
    reference = at_bin(loads, governing)
    return reference * np.sum(np.asarray(shares, dtype=float)
                              * (loads / reference) ** exponent, axis=0) ** (1.0 / exponent)


def first_failure_over_bins(status: NDArray) -> NDArray:
    """Each design's status: that of its first bin that fails, 0 where every bin is
    possible."""
    status = np.asarray(status)
    failed = status != 0
    first = np.argmax(failed, axis=0)
    return np.where(failed.any(axis=0), at_bin(status, first), 0).astype(status.dtype)


def rolling_bearing_cycle(per_bin: Solution, inputs: Mapping[str, Any]) -> Solution:
    """The cycle of a rolling bearing from its bins (see :class:`DutyCycle`).

    P_m and the basic life from the bins' P by the Palmgren–Miner rule; the modified
    life from the bins' own Lnm (each with its κ and aISO); the static safety the
    smallest over the bins; the contact the worst; every other result that of the
    bin doing the most damage.
    """
    results = per_bin.results
    time_share = np.asarray(inputs["duty_time"], dtype=float)
    speed = np.asarray(inputs["duty_speed"], dtype=float)
    shares, mean_speed = revolution_shares(time_share / np.sum(time_share, axis=0), speed)
    lives = results["modified_rating_life_revolutions"]
    damage = shares / lives
    governing = np.argmax(damage, axis=0)
    modified = miner_life(shares, lives, governing)
    basic = miner_life(shares, results["basic_rating_life_revolutions"], governing)
    exponent = LIFE_EXPONENT[traits(str(inputs["bearing_type"])).family]
    p_mean = mean_load(shares, results["equivalent_dynamic_load"], exponent, governing)
    revolutions_per_second = mean_speed / (2.0 * np.pi)
    out: dict[str, NDArray] = {}
    for key, values in results.items():
        if key in SMALLEST:
            out[key] = np.min(values, axis=0)
        elif key in LARGEST:
            out[key] = np.max(values, axis=0)
        else:
            out[key] = at_bin(values, governing)
    rating = results.get("pair_dynamic_load_rating", results["dynamic_load_rating"])
    out.update({
        "equivalent_dynamic_load": p_mean, "load_ratio": at_bin(rating, governing) / p_mean,
        "basic_rating_life": basic / revolutions_per_second,
        "basic_rating_life_revolutions": basic,
        "modified_rating_life": modified / revolutions_per_second,
        "modified_rating_life_revolutions": modified,
        "mean_speed": mean_speed, "mean_equivalent_load": p_mean,
    })
    if "life_margin" in results:
        out["life_margin"] = life_margin(modified / revolutions_per_second,
                                         np.asarray(inputs["min_rating_life"], dtype=float)[0])
    bin_life = np.where(speed > 0, lives / (np.abs(speed) / (2.0 * np.pi)), np.inf)
    bins = bins_along({
        "time_share": time_share, "speed": speed, "radial_load": inputs["radial_load"],
        "axial_load": inputs["axial_load"],
        "equivalent_dynamic_load": results["equivalent_dynamic_load"],
        "modified_rating_life": bin_life, "damage_share": damage / np.sum(damage, axis=0)})
    return cycle_solution(per_bin, out, bins)


def bins_along(columns: Mapping[str, ArrayLike]) -> Along:
    """Each column's values per bin as the rows ``duty_{k}`` (k from 1) of the ``bin``
    axis; every column given with the bins first."""
    shape = np.broadcast_shapes(*(np.shape(np.asarray(values))[1:]
                                  for values in columns.values()))
    bins = len(np.asarray(next(iter(columns.values()))))
    return Along(bin_rows(bins),
                 {column: np.broadcast_to(np.asarray(values, dtype=float), (bins, *shape))
                  for column, values in columns.items()})


def cycle_solution(per_bin: Solution, out: dict[str, NDArray], bins: Along,
                   warnings: Mapping[str, NDArray] | None = None,
                   along: Mapping[str, Along] | None = None) -> Solution:
    """The cycle's Solution: ``out`` of one value per design, ``bins`` along the bins
    (and any other axis's results in ``along``); a design fails where a bin does; a
    warning holds where it holds in a bin (or as ``warnings`` say)."""
    status = first_failure_over_bins(per_bin.status)
    axes = {**(along or {}), "bin": bins}
    shape = np.broadcast_shapes(status.shape, *(np.shape(v) for v in out.values()),
                                *(np.shape(v)[1:] for rows in axes.values()
                                  for v in rows.values.values()))
    flags = {key: np.any(flag, axis=0) for key, flag in per_bin.warnings.items()}
    flags.update(warnings or {})
    return Solution({key: np.broadcast_to(value, shape) for key, value in out.items()},
                    np.broadcast_to(status, shape),
                    {key: np.broadcast_to(flag, shape) for key, flag in flags.items()},
                    {name: np.broadcast_to(first_failure_over_bins(codes), shape)
                     for name, codes in per_bin.members.items()},
                    {axis: rows.broadcast(shape) for axis, rows in axes.items()})


def at_bin(values: ArrayLike, index: NDArray) -> NDArray:
    """``values`` along the first axis at each design's ``index``."""
    values = np.asarray(values)
    index = np.asarray(index)
    values = np.broadcast_to(values, (values.shape[0], *np.broadcast_shapes(
        values.shape[1:], index.shape)))
    picked = np.take_along_axis(values, np.broadcast_to(index, values.shape[1:])[None], 0)
    return picked[0]
