"""What a rolling bearing as mounted (``method: iso-16281``) reports whatever its rolling
elements: the results, warnings and status reasons both families share, the load zone
and the life from the reference rating life (ISO/TS 16281:2008). The ball bearing's own
part is :mod:`bearingcalc.core.mounted_ball_bearing`, the roller bearing's
:mod:`bearingcalc.core.mounted_roller_bearing`; ``docs/physics.md`` §12.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.bearing_life import life_margin
from bearingcalc.core.common import Family, Found
from bearingcalc.core.iso281 import life_modification_factor
from bearingcalc.core.mounted_clearance import WARNINGS as CHAIN_WARNINGS
from bearingcalc.core.mounted_clearance import chain_warnings, mounted_clearance
from bearingcalc.core.solver import Along, AxisResults

#: A family's results as mounted from (inputs, C, ISO 281's results, speed).
MountedResults = Callable[[Mapping[str, Any], NDArray, Mapping[str, Any], NDArray],
                          tuple[Found, dict[str, Along]]]

#: The method's name in a spec's ``method``.
METHOD = "iso-16281"

#: The results of one value per design of every bearing as mounted, in report order.
RESULTS: dict[str, tuple[str, str]] = {
    "ring_displacement_radial": ("m", "the inner ring's (a pair's shaft's, midway between "
                                 "its pressure centres) displacement along the radial load"),
    "ring_displacement_axial": ("m", "along the axis, from the centred ring (deep-groove, "
                                "cylindrical), first contact (angular-contact, tapered) or a "
                                "pair's place at rest"),
    "ring_tilt": ("rad", "the inner ring's tilt in the plane of the radial load"),
    "tilting_moment_reaction": ("N·m", "the moment the bearing carries at an imposed "
                                "misalignment"),
    "max_element_load": ("N", "the largest rolling-element load Q"),
    "loaded_elements": ("1", "the rolling elements that carry load"),
    "load_zone_angle": ("rad", "2ψ_l, ψ_l the azimuth where an element's deflection falls "
                        "to 0 (between elements, interpolated); 2π where every element is "
                        "loaded"),
    "max_contact_pressure_inner": ("Pa", "the largest Hertz pressure at the inner ring"),
    "max_contact_pressure_outer": ("Pa", "the largest Hertz pressure at the outer ring"),
    "reference_rating_life": ("s", "L10r, ISO/TS 16281's reference rating life"),
    "reference_rating_life_revolutions": ("1", "L10r in revolutions"),
    "dynamic_equivalent_reference_load": ("N", "P_ref with L10r = (C/P_ref)^p 10⁶ "
                                          "revolutions (p = 3 balls, 10/3 rollers)"),
    "modified_reference_rating_life": ("s", "a1·aISO·L10r, aISO with P_ref"),
    "life_ratio_to_iso281": ("1", "L10r over ISO 281's L10 of the same bearing and loads"),
    "stiffness_radial": ("N/m", "∂Fy/∂δy of the tangent stiffness at the equilibrium"),
    "stiffness_axial": ("N/m", "∂Fx/∂δx"),
    "stiffness_tilt": ("N·m/rad", "∂Mz/∂θz"),
    "equilibrium_residual": ("1", "the largest unbalanced force over the largest load"),
    "stiffness_radial_margin": ("1", "stiffness_radial / min_stiffness_radial − 1"),
    "stiffness_axial_margin": ("1", "stiffness_axial / min_stiffness_axial − 1"),
}
#: The tangent stiffness matrix's coordinates, in its order: the displacements x, y, z
#: and the tilts about y and z (a pair's: its shaft's, midway between its pressure
#: centres).
STIFFNESS_ORDER = ("x", "y", "z", "tilt_y", "tilt_z")
#: Its entries on and above the diagonal (it is symmetric), ∂F_a/∂q_b in SI.
STIFFNESS_MATRIX = {
    f"stiffness_matrix_{a}_{b}": (
        {0: "N/m", 1: "N/rad", 2: "N·m/rad"}[(i > 2) + (j > 2)],
        f"∂F_{a}/∂q_{b} of the tangent stiffness matrix (symmetric)")
    for i, a in enumerate(STIFFNESS_ORDER) for j, b in enumerate(STIFFNESS_ORDER) if j >= i}
RESULTS.update(STIFFNESS_MATRIX)
#: Each rolling element's results, a row per element.
ELEMENT_RESULTS = AxisResults({
    "azimuth": ("rad", "its azimuth ψ (0 under the radial load)"),
    "load": ("N", "its load Q"),
    "contact_angle": ("rad", "its operating contact angle"),
}, after="equilibrium_residual", meaning="{row}: {meaning}", sparse=True)
#: The table's heading of the method's results.
GROUP = "as mounted (ISO/TS 16281)"
#: Warnings of every bearing as mounted: flag -> message.
WARNINGS = {
    **CHAIN_WARNINGS,
    "single_element_loaded": "one rolling element carries the whole load (ISO/TS 16281): "
                             "check the clearance and the loads",
    "narrow_load_zone": "the load zone is below 90°: a few rolling elements carry the load; "
                        "a smaller operating clearance spreads it",
    "tilted_beyond_model": "the inner ring tilts more than 10 mrad, beyond the small "
                           "displacements of ISO/TS 16281's rigid rings: a bearing left free "
                           "to tilt does so where nothing else holds its shaft; give the "
                           "shaft's misalignment, or the pair or drive it sits in",
}
#: The status code of a bearing whose rings find no equilibrium.
NO_EQUILIBRIUM = 25
STATUS_REASONS = {
    NO_EQUILIBRIUM: ("axial_load", "the rings find no equilibrium under these loads: the "
                     "rolling elements cannot carry them (a bearing at its free contact angle "
                     "needs an axial load that holds its elements on their contact, a "
                     "tapered bearing's above Fr·tanα, and any bearing a tilting moment its "
                     "elements can carry)"),
}


class LifeOf(NamedTuple):
    """A reference rating life and its load, of a bearing or of a pair."""

    revolutions: NDArray       # L10r [revolutions]
    equivalent_load: NDArray   # P_ref [N]


def results_with(own: Mapping[str, tuple[str, str]], after: str,
                 pair: Mapping[str, tuple[str, str]]) -> dict[str, tuple[str, str]]:
    """The shared :data:`RESULTS` with a family's ``own`` results inserted after the key
    ``after``, and a matched ``pair``'s after the stiffness."""
    merged: dict[str, tuple[str, str]] = {}
    for key, value in RESULTS.items():
        merged[key] = value
        if key == after:
            merged.update(own)
        if key == "stiffness_tilt":
            merged.update(pair)
    return merged


def crushing_code(inputs: Mapping[str, Any], codes: Mapping[str, tuple[int, str]]) -> int:
    """The status code of a contact beyond Hertz's theory, of ``codes`` by the input that
    causes it: what tilts the ring if anything does (an imposed misalignment, a moment),
    else a pair's preload or interference, else a negative clearance, else the larger of
    the loads."""
    for field in ("misalignment", "tilting_moment"):
        if inputs.get(field) is not None:
            return codes[field][0]
    if inputs.get("setting_preload") is not None:
        return codes["setting.preload"][0]
    for field, key in (("setting.end_play", "setting_end_play"),
                       ("operating_clearance", "operating_clearance")):
        value = inputs.get(key)
        if value is not None and np.any(np.asarray(value) < 0.0):
            return codes[field][0]
    if np.any(np.abs(np.asarray(inputs["axial_load"], dtype=float))
              > np.abs(np.asarray(inputs["radial_load"], dtype=float))):
        return codes["axial_load"][0]
    return codes["radial_load"][0]


#: The largest tilt [rad] and displacement (a share of the pitch radius) at which a
#: shaft's equilibrium is taken as found: beyond them the rings' small-displacement model
#: does not hold (bearings as mounted tilt by a few milliradians and move by micrometres).
LARGEST_TILT = 0.01
LARGEST_SHIFT = 0.1


def within_model(displacement: NDArray, pitch_radius: NDArray) -> NDArray:
    """Where a solved displacement (N, 5) lies within the small-displacement model."""
    return ((np.max(np.abs(displacement[:, 3:]), axis=1) <= LARGEST_TILT)
            & (np.max(np.abs(displacement[:, :3]), axis=1) <= LARGEST_SHIFT * pitch_radius))


def rib_load(inputs: Mapping[str, Any], max_element_load: NDArray, flat: Any
             ) -> dict[str, NDArray]:
    """A tapered roller bearing's largest rib load, 2·Q·sin(θ/2) [N] of its most heavily
    loaded roller, where the spec gives the roller's included angle θ."""
    angle = inputs.get("roller_included_angle")
    if angle is None:
        return {}
    return {"max_rib_load": 2.0 * max_element_load * np.sin(flat(angle) / 2.0)}


def or_zero(value: Any) -> Any:
    """An optional number, 0 where the spec leaves it out."""
    return 0.0 if value is None else value


def numbers_in(values: Mapping[str, Any]) -> list[Any]:
    """Every number of ``values`` and of the mappings it holds (a bearing's mounting):
    any of them a study or sweep may vary."""
    found = []
    for value in values.values():
        if isinstance(value, Mapping):
            found += numbers_in(value)
        elif value is not None and not isinstance(value, str):
            found.append(value)
    return found


def designs(inputs: Mapping[str, Any], *others: ArrayLike
            ) -> tuple[tuple[int, ...], Callable[[Any], NDArray]]:
    """The designs' shape (the broadcast of every number of ``inputs`` and of
    ``others``: any of them a study or sweep may vary) and a function that lays a value
    out flat over them."""
    shape = np.broadcast_shapes(*(np.shape(value) for value in numbers_in(inputs)),
                                *(np.shape(v) for v in others))

    def flat(value: Any) -> NDArray:
        return np.broadcast_to(np.asarray(value, dtype=float), shape).reshape(-1)

    return shape, flat


def as_mounted(inputs: Mapping[str, Any], mounted_results: MountedResults, c: NDArray,
               iso281: Mapping[str, Any], speed: NDArray) -> tuple[Found, dict[str, Along]]:
    """A family's ``mounted_results`` with its results along their axes (each element,
    a pair's bearings) where the spec asks for the method (``method: iso-16281``);
    nothing otherwise."""
    if inputs.get("method") != METHOD:
        return Found(), {}
    if inputs.get("mounting") is None or inputs.get("arrangement", "single") != "single":
        # a pair's mounting moves its end play (mounted_pair)
        return mounted_results(inputs, c, iso281, speed)
    # the operating clearance follows from the drawing: the chain at the bands' middles
    # (a study's samples) sets it, and its extremes are reported beside it
    chain = mounted_clearance(inputs)
    found, along = mounted_results({**inputs, "operating_clearance": chain[
        "operating_clearance"]}, c, iso281, speed)
    found.results.update(chain)
    found.flags.update(chain_warnings(inputs, chain))
    return found, along


def element_rows(values: Mapping[str, NDArray], shape: tuple[int, ...]) -> Along:
    """Each element's ``values`` (N, Zmax) as rows ``element_1`` … along ``element``, each
    row in the designs' ``shape``."""
    width = next(iter(values.values())).shape[1]
    rows = tuple(f"element_{k}" for k in range(1, width + 1))
    return Along(rows, {key: value.T.reshape((len(rows), *shape))
                        for key, value in values.items()})


def applied_loads(inputs: Mapping[str, Any], flat: Any, size: int) -> NDArray:
    """(Fx, Fy, Fz, My, Mz) on the inner ring, (N, 5) [N, N·m]: the axial and radial
    loads and the tilting moment in the radial load's plane."""
    loads = np.zeros((size, 5))
    loads[:, 0], loads[:, 1] = flat(inputs["axial_load"]), flat(inputs["radial_load"])
    loads[:, 4] = flat(or_zero(inputs.get("tilting_moment")))
    return loads


def load_zone_angle(deflection: NDArray, azimuth: NDArray) -> NDArray:
    """2ψ_l [rad]: ψ_l where the deflection, walking from the element at ψ = 0 (under the
    radial load) toward ψ = π, falls to zero, linearly between the two elements around it;
    2π where every element is loaded or the zone reaches past ψ = π, 0 where the element
    at ψ = 0 is not loaded."""
    valid = ~np.isnan(azimuth)
    half = valid & (azimuth <= np.pi)
    unloaded = half & ~(deflection > 0)
    first = np.argmax(unloaded, axis=1)[:, None]
    before = np.maximum(first - 1, 0)

    def at(values: NDArray, index: NDArray) -> NDArray:
        return np.take_along_axis(values, index, axis=1)[:, 0]

    d_after, d_before = at(deflection, first), at(deflection, before)
    psi_after, psi_before = at(azimuth, first), at(azimuth, before)
    with np.errstate(invalid="ignore", divide="ignore"):
        crossing = psi_before + (psi_after - psi_before) * d_before / (d_before - d_after)
    loaded_at_zero = deflection[:, 0] > 0
    whole = np.all(~valid | (deflection > 0), axis=1) | (loaded_at_zero & ~unloaded.any(axis=1))
    return np.where(whole, 2 * np.pi, np.where(loaded_at_zero, 2 * crossing, 0.0))


def equilibrium_results(solved: Any, deflection: NDArray) -> dict[str, NDArray]:
    """The results of one value per design that every family's equilibrium gives: the
    ring's displacements, the loads, the load zone (from each element's ``deflection``)
    and the diagonal of the tangent stiffness."""
    loaded = np.nan_to_num(solved.element_load) > 0
    return {
        "ring_displacement_radial": solved.displacement[:, 1],
        "ring_displacement_axial": solved.displacement[:, 0],
        "ring_tilt": solved.displacement[:, 4],
        "max_element_load": np.max(np.nan_to_num(solved.element_load), axis=1),
        "loaded_elements": loaded.sum(axis=1).astype(float),
        "load_zone_angle": load_zone_angle(deflection, solved.azimuth),
        "stiffness_radial": solved.stiffness[:, 1, 1],
        "stiffness_axial": solved.stiffness[:, 0, 0],
        "stiffness_tilt": solved.stiffness[:, 4, 4],
        "equilibrium_residual": solved.residual,
        **stiffness_entries(solved.stiffness),
    }


def contact_angle_range(element_load: NDArray, contact_angle: NDArray
                        ) -> dict[str, NDArray]:
    """The smallest and largest contact angle over the loaded balls [rad]; NaN where
    none is loaded."""
    loaded = np.nan_to_num(element_load) > 0
    none_loaded = ~loaded.any(axis=1)
    return {"operating_contact_angle_min": np.where(none_loaded, np.nan, np.min(
                np.where(loaded, contact_angle, np.inf), axis=1)),
            "operating_contact_angle_max": np.where(none_loaded, np.nan, np.max(
                np.where(loaded, contact_angle, -np.inf), axis=1))}


def stiffness_entries(stiffness: NDArray) -> dict[str, NDArray]:
    """The tangent stiffness matrix (N, 5, 5) as its entries on and above the diagonal,
    :data:`STIFFNESS_MATRIX`."""
    return {f"stiffness_matrix_{a}_{b}": stiffness[:, i, j]
            for i, a in enumerate(STIFFNESS_ORDER) for j, b in enumerate(STIFFNESS_ORDER)
            if j >= i}


def life_results(inputs: Mapping[str, Any], reference_life: Any, iso281: Mapping[str, Any],
                 speed: NDArray, shape: tuple[int, ...], family: Family) -> dict[str, NDArray]:
    r"""The lives from the reference rating life L10r [revolutions] and its load P_ref:

    .. math:: L_{10r,m} = a_1\,a_{ISO}(κ, e_C C_u/P_{ref})\,L_{10r}

    in time at the rings' relative ``speed`` [rad/s], the ratio to ISO 281's L10 and the
    life margin. Source: ISO/TS 16281:2008, 9 (the modified reference rating life).
    """
    revolutions_per_second = np.abs(speed) / (2.0 * np.pi)
    l10r = reference_life.revolutions.reshape(shape)
    a1 = np.asarray(iso281["reliability_factor"], dtype=float)
    a_iso = 1.0
    if "viscosity_ratio" in iso281:
        a_iso = life_modification_factor(iso281["viscosity_ratio"],
                                         inputs["contamination_factor"],
                                         iso281["fatigue_load_limit"],
                                         reference_life.equivalent_load.reshape(shape),
                                         family=family)
    modified = a1 * a_iso * l10r / revolutions_per_second
    results = {
        "dynamic_equivalent_reference_load": reference_life.equivalent_load.reshape(shape),
        "reference_rating_life": l10r / revolutions_per_second,
        "reference_rating_life_revolutions": l10r,
        "modified_reference_rating_life": modified,
        "life_ratio_to_iso281": l10r / np.asarray(iso281["basic_rating_life_revolutions"]),
    }
    if inputs.get("min_rating_life") is not None:
        results["life_margin"] = life_margin(modified, inputs["min_rating_life"])
    return results


def pressure_results(inputs: Mapping[str, Any], inner: NDArray, outer: NDArray,
                     shape: tuple[int, ...]) -> dict[str, NDArray]:
    """The largest operating pressures at each ring and the limit's margin on the larger:
    the limit judges the operating contacts, not ISO 76's at P0."""
    largest = np.maximum(inner, outer).reshape(shape)
    results = {"max_contact_pressure_inner": inner.reshape(shape),
               "max_contact_pressure_outer": outer.reshape(shape),
               "max_contact_pressure": largest}
    if inputs.get("max_contact_pressure") is not None:
        results["contact_pressure_margin"] = 1.0 - largest / np.asarray(
            inputs["max_contact_pressure"], dtype=float)
    return results


def completed(inputs: Mapping[str, Any], found: Found, pressures: tuple[NDArray, NDArray],
              reference_life: Any, iso281: Mapping[str, Any], speed: NDArray,
              shape: tuple[int, ...], family: Family) -> Found:
    """A solve's ``found`` over the flat designs reshaped to theirs, with the pressures
    at the inner and outer ring and their limit, the lives from ``reference_life`` and
    the warnings every bearing as mounted raises."""
    found = reshaped(found, shape)
    found.results.update(pressure_results(inputs, *pressures, shape))
    found.results.update(stiffness_margins(inputs, found.results))
    found.results.update(life_results(inputs, reference_life, iso281, speed, shape, family))
    found.flags.update(warning_flags(found.results))
    return found


def stiffness_margins(inputs: Mapping[str, Any], results: Mapping[str, NDArray]
                      ) -> dict[str, NDArray]:
    """k/k_min − 1 of the radial and axial stiffness, where the limits give k_min."""
    margins = {}
    for direction in ("radial", "axial"):
        least = inputs.get(f"min_stiffness_{direction}")
        if least is not None:
            margins[f"stiffness_{direction}_margin"] = (
                results[f"stiffness_{direction}"] / np.asarray(least, dtype=float) - 1.0)
    return margins


def warning_flags(results: Mapping[str, NDArray]) -> dict[str, NDArray]:
    """The warnings every bearing as mounted raises from its results."""
    return {"single_element_loaded": results["loaded_elements"] == 1,
            "narrow_load_zone": results["load_zone_angle"] < np.pi / 2,
            "tilted_beyond_model": np.abs(results["ring_tilt"]) > LARGEST_TILT}


def reshaped(found: Found, shape: tuple[int, ...]) -> Found:
    """``found`` with every result and check reshaped to the designs' ``shape``."""
    return Found({key: np.reshape(value, shape) for key, value in found.results.items()},
                 {key: np.reshape(value, shape) for key, value in found.flags.items()},
                 [(code, np.reshape(bad, shape)) for code, bad in found.checks])
