"""The bearings of a drive's shafts, each solved as a rolling bearing, and the drive's
results from them: the system life, the margins, and each bearing's results along the
member axis (``docs/physics.md`` §9). Inputs are SI floats or broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.bearing_life import (
    ROLLER_WEIBULL_SLOPE,
    WEIBULL_SLOPE,
    life_margin,
    system_life,
)
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.solver import Along, Solution

#: Each bearing's results, along the member axis: column -> (SI unit, meaning).
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
    # as mounted (method: iso-16281), from each bearing's contacts
    "max_element_load": ("N", "its largest rolling-element load (ISO/TS 16281)"),
    "reference_rating_life": ("s", "L10r (ISO/TS 16281)"),
    "modified_reference_rating_life": ("s", "a1·aISO·L10r (ISO/TS 16281)"),
    "operating_clearance": ("m", "with a mounting: its operating clearance from the drawing, "
                                 "at the middle of every band (ISO/TS 16281)"),
    "operating_clearance_min": ("m", "with a mounting: its least over the bands"),
    "operating_clearance_max": ("m", "with a mounting: its largest over the bands"),
}


class MountedBearing(NamedTuple):
    """One bearing on its shaft, solved: its row along the member axis, its name in the
    spec, the shaft's heading, the loads from the statics [N], and its own solution as
    a rolling bearing (per bin, in a duty cycle)."""

    row: str
    member: str
    heading: str
    inputs: Mapping[str, Any]
    loads: dict[str, NDArray]
    solved: Solution

    @property
    def roller(self) -> bool:
        return traits(self.inputs["bearing_type"]).family == "roller"


#: Which of each bearing's lives the system's basic and modified life combine: ISO 281's,
#: or, as mounted, ISO/TS 16281's reference lives.
LIVES = ("basic_rating_life", "modified_rating_life")
MOUNTED_LIVES = ("reference_rating_life", "modified_reference_rating_life")
#: The bearings' results taken from each one's own solution as a rolling bearing.
OWN_RESULTS = ("equivalent_dynamic_load", "basic_rating_life", "modified_rating_life",
               "static_safety_factor")


def assemble(pair: Mapping[str, NDArray], gear_speed: NDArray,
             mounted: list[MountedBearing], min_rating_life: ArrayLike | None,
             min_static_safety: ArrayLike, lives: tuple[str, str] = LIVES
             ) -> tuple[dict[str, NDArray], Along, dict[str, NDArray]]:
    """The drive's results from the pair's and the bearings' (of one operating point,
    or of a whole duty cycle): the results of one value per design (the pair's first),
    the bearings' along the member axis, and where each bearing is the weakest.

    L_sys = (Σ Lᵢ^(−e))^(−1/e) (:func:`system_life`); life_margin = L_sys,nm/L_req − 1;
    static_safety_margin = min s0ᵢ − s0_req.
    """
    out: dict[str, NDArray] = {**pair, "gear_speed": gear_speed}
    slope = ROLLER_WEIBULL_SLOPE if any(bearing.roller for bearing in mounted) \
        else WEIBULL_SLOPE
    basic, modified_key = lives
    modified = [bearing.solved.results[modified_key] for bearing in mounted]
    out["system_basic_rating_life"] = system_life(
        [bearing.solved.results[basic] for bearing in mounted], slope)
    out["system_modified_rating_life"] = system_life(modified, slope)
    if min_rating_life is not None:
        out["life_margin"] = life_margin(out["system_modified_rating_life"], min_rating_life)
    safety = [bearing.solved.results["static_safety_factor"] for bearing in mounted
              if "static_safety_factor" in bearing.solved.results]
    if safety:
        out["static_safety_margin"] = np.min(np.stack(np.broadcast_arrays(*safety)), axis=0) \
            - np.asarray(min_static_safety, dtype=float)
    weakest = np.argmin(np.stack(np.broadcast_arrays(*modified)), axis=0)
    flags = {f"weakest_{bearing.row}": weakest == i for i, bearing in enumerate(mounted)}
    return out, _member_rows(mounted), flags


def _member_rows(mounted: list[MountedBearing]) -> Along:
    """The bearings' results along the member axis, a row per bearing (a column that a
    bearing lacks, as an adjusted pair's load case on a located shaft, is absent in
    that row)."""
    columns: dict[str, list[ArrayLike | None]] = {}
    for i, bearing in enumerate(mounted):
        own = {key: bearing.solved.results[key] for key in OWN_RESULTS
               if key in bearing.solved.results}
        for key, values in {**bearing.loads, **own}.items():
            columns.setdefault(key, [None] * len(mounted))[i] = values
    columns = {key: columns[key] for key in BEARING_RESULTS if key in columns}
    present = {key: tuple(value is not None for value in values)
               for key, values in columns.items()}
    values = {key: np.stack(np.broadcast_arrays(*(np.nan if value is None else value
                                                  for value in rows)))
              for key, rows in columns.items()}
    return Along(tuple(bearing.row for bearing in mounted), values,
                 tuple(bearing.heading for bearing in mounted), present)
