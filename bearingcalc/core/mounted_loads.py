"""What loads a rolling bearing's elements as mounted besides its forces (a tilting
moment, an imposed misalignment, a preload), for the checks that a bearing is loaded at
all and that it carries the makers' minimum load (``docs/kinds/rolling-bearing.md``).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.mounted_bearing import METHOD, or_zero


def loaded(inputs: Mapping[str, Any], radial: NDArray, axial: NDArray) -> NDArray:
    """Where the bearing carries a load: a force, or as mounted a tilting moment, an
    imposed misalignment or a pair's preload (or negative end play), which load its
    elements without one."""
    force = (radial > 0) | (axial > 0)
    if inputs.get("method") != METHOD:
        return force
    return force | _loaded_beyond_forces(inputs)


def _loaded_beyond_forces(inputs: Mapping[str, Any], *, clearance: bool = False) -> NDArray:
    """Where something besides the forces loads the elements as mounted: a tilting
    moment, an imposed misalignment, a pair's preload or negative end play (and, where
    ``clearance``, a negative operating clearance)."""
    def given(key: str) -> NDArray:
        return np.asarray(or_zero(inputs.get(key)), dtype=float)

    preload = inputs.get("setting_preload")
    return ((given("tilting_moment") != 0) | (given("misalignment") != 0)
            | (given("setting_end_play") < 0) | (clearance & (given("operating_clearance") < 0))
            | (preload is not None and np.asarray(preload, dtype=float) > 0))


def below_minimum_load(inputs: Mapping[str, Any], results: Mapping[str, Any],
                       iso281: Mapping[str, Any], c: ArrayLike, share: float) -> NDArray:
    """Where the load on the elements is below the makers' minimum, ``share``·C: ISO
    281's equivalent load P, or where a preload (a negative clearance, a pair's preload
    or interference) or a moment loads the elements besides the forces, the larger of P
    and the reference load P_ref (preloading is the makers' cure for skidding; P_ref
    alone would count a light load on one ball of a loose bearing as a heavy one)."""
    reference = np.asarray(results["dynamic_equivalent_reference_load"], dtype=float)
    load = np.broadcast_to(np.asarray(iso281["equivalent_dynamic_load"], dtype=float),
                           reference.shape)
    load = np.where(np.broadcast_to(_loaded_beyond_forces(inputs, clearance=True),
                                    reference.shape), np.maximum(load, reference), load)
    return load < share * np.asarray(c, dtype=float)
