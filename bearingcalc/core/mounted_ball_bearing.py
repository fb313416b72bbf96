"""A ball bearing as it is mounted (``method: iso-16281``): its operating clearance, the
rings' displacements under the loads and a tilting moment or misalignment, the load on
every ball, the reference rating life from them and the bearing's stiffness (ISO/TS
16281:2008). The results of one value per design, and each ball's along ``element``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core.bearing_life import life_margin
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.common import DerivedTest, Found
from bearingcalc.core.iso281 import life_modification_factor
from bearingcalc.core.iso16281_balls import (
    ball_deflections,
    ball_geometry,
    solve_ball_equilibrium,
)
from bearingcalc.core.iso16281_life import (
    ball_reference_life,
    ball_spring_constant,
    largest_ball_contacts,
)
from bearingcalc.core.solver import Along, AxisResults

#: The method's name in a spec's ``method``.
METHOD = "iso-16281"

RESULTS: dict[str, tuple[str, str]] = {
    "ring_displacement_radial": ("m", "the inner ring's displacement along the radial load"),
    "ring_displacement_axial": ("m", "along the axis, from the centred ring (deep-groove) or "
                                "first contact (angular-contact)"),
    "ring_tilt": ("rad", "the inner ring's tilt in the plane of the radial load"),
    "tilting_moment_reaction": ("N·m", "the moment the bearing carries at an imposed "
                                "misalignment"),
    "max_element_load": ("N", "the largest ball load Q"),
    "loaded_elements": ("1", "the balls that carry load"),
    "load_zone_angle": ("rad", "2ψ_l, ψ_l the azimuth where a ball's deflection falls to 0 "
                        "(between balls, interpolated); 2π where every ball is loaded"),
    "operating_contact_angle_min": ("rad", "the smallest contact angle of a loaded ball"),
    "operating_contact_angle_max": ("rad", "the largest contact angle of a loaded ball"),
    "max_contact_pressure_inner": ("Pa", "the largest Hertz pressure at the inner ring"),
    "max_contact_pressure_outer": ("Pa", "the largest Hertz pressure at the outer ring"),
    "reference_rating_life": ("s", "L10r, ISO/TS 16281's reference rating life"),
    "reference_rating_life_revolutions": ("1", "L10r in revolutions"),
    "dynamic_equivalent_reference_load": ("N", "P_ref with L10r = (C/P_ref)³ 10⁶ revolutions"),
    "modified_reference_rating_life": ("s", "a1·aISO·L10r, aISO with P_ref"),
    "life_ratio_to_iso281": ("1", "L10r over ISO 281's L10 of the same bearing and loads"),
    "stiffness_radial": ("N/m", "∂Fy/∂δy of the tangent stiffness at the equilibrium"),
    "stiffness_axial": ("N/m", "∂Fx/∂δx"),
    "stiffness_tilt": ("N·m/rad", "∂Mz/∂θz"),
    "equilibrium_residual": ("1", "the largest unbalanced force over the largest load"),
}
#: Each ball's results, a row per ball.
ELEMENT_RESULTS = AxisResults({
    "azimuth": ("rad", "its azimuth ψ (0 under the radial load)"),
    "load": ("N", "its load Q"),
    "contact_angle": ("rad", "its operating contact angle"),
}, after="equilibrium_residual", meaning="ball {position}: {meaning}")
#: The table's heading of the method's results.
GROUP = "as mounted (ISO/TS 16281)"
#: Warnings of the method: flag -> message.
WARNINGS = {
    "single_element_loaded": "one ball carries the whole load (ISO/TS 16281): check the "
                             "clearance and the loads",
    "narrow_load_zone": "the load zone is below 90°: a few balls carry the load; a smaller "
                        "operating clearance spreads it",
    "below_minimum_load": "the equivalent load is below 1 % of C, the makers' minimum load of "
                          "a ball bearing: the balls may skid",
}
#: The makers' minimum load of a ball bearing, a share of C.
MINIMUM_LOAD_SHARE = 0.01
#: Status codes of the method: no equilibrium; a contact beyond Hertz's theory.
NO_EQUILIBRIUM = 25
#: by the input that loads the bearing beyond Hertz: (code, in words)
CONTACT_TOO_LARGE = {"radial_load": (26, "load"), "tilting_moment": (27, "tilting moment"),
                     "misalignment": (28, "misalignment")}
STATUS_REASONS = {
    NO_EQUILIBRIUM: ("axial_load", "the rings find no equilibrium under these loads: the "
                     "balls cannot carry them (a bearing at its free contact angle needs an "
                     "axial load that holds its balls on their contact, about Fr·tanα or "
                     "more, and any bearing a tilting moment its balls can carry)"),
    **{code: (field, DerivedTest(
        "the most heavily loaded ball's contact ellipse outgrows the ball (a semi-axis "
        "above Dw/2): Hertz's theory does not hold, and the bearing would be crushed; "
        f"the {what} is too large for it"))
       for field, (code, what) in CONTACT_TOO_LARGE.items()},
}


#: The numeric inputs the method reads, any of which a study or sweep may vary.
_NUMBERS = ("ball_count", "ball_diameter", "pitch_diameter", "inner_groove_conformity",
            "outer_groove_conformity", "radial_load", "axial_load", "contact_angle",
            "elastic_modulus", "poisson_ratio", "inner_speed", "outer_speed",
            "operating_clearance", "tilting_moment", "misalignment", "reliability",
            "contamination_factor", "min_rating_life", "max_contact_pressure")


def as_mounted(inputs: Mapping[str, Any], c: NDArray, iso281: Mapping[str, Any],
               speed: NDArray) -> tuple[Found, dict[str, Along]]:
    """The method's results and each ball's (along ``element``) where the spec asks for
    it (``method: iso-16281``); nothing otherwise."""
    if inputs.get("method") != METHOD:
        return Found(), {}
    found, elements = mounted_results(inputs, c, iso281, speed)
    return found, {"element": elements}


def mounted_results(inputs: Mapping[str, Any], c: NDArray, iso281: Mapping[str, Any],
                    speed: NDArray) -> tuple[Found, Along]:
    """The method's results from the bearing's inputs, C and ISO 281's results of the
    same bearing (its L10 and life factors), at the rings' relative speed [rad/s]."""
    used = [inputs[key] for key in _NUMBERS if inputs.get(key) is not None]
    shape = np.broadcast_shapes(*(np.shape(np.asarray(v, dtype=float)) for v in used),
                                np.shape(c), np.shape(speed))

    def flat(value: Any) -> NDArray:
        return np.broadcast_to(np.asarray(value, dtype=float), shape).reshape(-1)

    one_way = traits(str(inputs["bearing_type"])).one_way
    z, dw, dpw, fi, fe, alpha = (flat(inputs[k]) for k in (
        "ball_count", "ball_diameter", "pitch_diameter", "inner_groove_conformity",
        "outer_groove_conformity", "contact_angle"))
    modulus, poisson = flat(inputs["elastic_modulus"]), flat(inputs["poisson_ratio"])
    nominal = alpha if one_way else np.zeros_like(alpha)
    spring = ball_spring_constant(dw, dpw, fi, fe, nominal, modulus, poisson)
    geometry = ball_geometry(z, dw, dpw, fi, fe, spring,
                             diametral_clearance=None if one_way else flat(
                                 _or_zero(inputs.get("operating_clearance"))),
                             free_contact_angle=alpha if one_way else None)
    loads = np.zeros((z.size, 5))
    loads[:, 0], loads[:, 1] = flat(inputs["axial_load"]), flat(inputs["radial_load"])
    loads[:, 4] = flat(_or_zero(inputs.get("tilting_moment")))
    misalignment = inputs.get("misalignment")
    solved = solve_ball_equilibrium(geometry, loads, fixed_tilt=None if misalignment is None
                                    else flat(misalignment))
    life = ball_reference_life(solved.element_load, z, dw, dpw, fi, fe, nominal, flat(c),
                               inner_rotates=flat(np.abs(inputs["inner_speed"])
                                                  >= np.abs(inputs["outer_speed"])) > 0)
    found = _found(inputs, solved, life, (dw, dpw, fi, fe, modulus, poisson), iso281,
                   speed, shape)
    zone = load_zone_angle(ball_deflections(geometry, solved.displacement, solved.azimuth),
                           solved.azimuth).reshape(shape)
    found.results["load_zone_angle"] = zone
    found.flags.update(
        single_element_loaded=found.results["loaded_elements"] == 1,
        narrow_load_zone=zone < np.pi / 2,
        below_minimum_load=np.asarray(iso281["equivalent_dynamic_load"], dtype=float)
        < MINIMUM_LOAD_SHARE * np.asarray(c, dtype=float))
    rows = tuple(f"element_{k}" for k in range(1, solved.element_load.shape[1] + 1))
    values = {"azimuth": solved.azimuth, "load": solved.element_load,
              "contact_angle": solved.contact_angle}
    return found, Along(rows, {key: value.T.reshape((len(rows), *shape))
                               for key, value in values.items()})


def load_zone_angle(deflection: NDArray, azimuth: NDArray) -> NDArray:
    """2ψ_l [rad]: ψ_l where the deflection, walking from the ball at ψ = 0 (under the
    radial load) toward ψ = π, falls to zero, linearly between the two balls around it;
    2π where every ball is loaded or the zone reaches past ψ = π, 0 where the ball at
    ψ = 0 is not loaded."""
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


def _crushing_code(inputs: Mapping[str, Any]) -> int:
    """The status code of a contact beyond Hertz's theory, by what tilts the ring if
    anything does (an imposed misalignment, a moment), else the loads."""
    for field in ("misalignment", "tilting_moment"):
        if inputs.get(field) is not None:
            return CONTACT_TOO_LARGE[field][0]
    return CONTACT_TOO_LARGE["radial_load"][0]


def _or_zero(value: Any) -> Any:
    """An optional number, 0 where the spec leaves it out."""
    return 0.0 if value is None else value


def _found(inputs: Mapping[str, Any], solved: Any, life: Any, contact: tuple, iso281:
           Mapping[str, Any], speed: NDArray, shape: tuple[int, ...]) -> Found:
    """The scalars of the solved bearing, each reshaped to the designs' ``shape``."""
    loaded = np.nan_to_num(solved.element_load) > 0
    none_loaded = ~loaded.any(axis=1)
    angle_min = np.where(none_loaded, np.nan,
                         np.min(np.where(loaded, solved.contact_angle, np.inf), axis=1))
    angle_max = np.where(none_loaded, np.nan,
                         np.max(np.where(loaded, solved.contact_angle, -np.inf), axis=1))
    hertz = largest_ball_contacts(solved.element_load, solved.contact_angle, *contact,
                                  quantities=("max_pressure", "semi_major"))
    inner, outer = hertz["max_pressure"]
    ellipse = np.maximum(*hertz["semi_major"])
    revolutions_per_second = np.abs(speed) / (2.0 * np.pi)
    l10r = life.revolutions.reshape(shape)
    a1 = np.asarray(iso281["reliability_factor"], dtype=float)
    a_iso = 1.0
    if "viscosity_ratio" in iso281:
        a_iso = life_modification_factor(iso281["viscosity_ratio"],
                                         inputs["contamination_factor"],
                                         iso281["fatigue_load_limit"],
                                         life.equivalent_load.reshape(shape))
    modified = a1 * a_iso * l10r / revolutions_per_second
    with np.errstate(invalid="ignore", all="ignore"):
        results = {
            "ring_displacement_radial": solved.displacement[:, 1],
            "ring_displacement_axial": solved.displacement[:, 0],
            "ring_tilt": solved.displacement[:, 4],
            "max_element_load": np.max(np.nan_to_num(solved.element_load), axis=1),
            "loaded_elements": loaded.sum(axis=1).astype(float),
            "operating_contact_angle_min": angle_min,
            "operating_contact_angle_max": angle_max,
            "max_contact_pressure_inner": inner, "max_contact_pressure_outer": outer,
            "dynamic_equivalent_reference_load": life.equivalent_load,
            "stiffness_radial": solved.stiffness[:, 1, 1],
            "stiffness_axial": solved.stiffness[:, 0, 0],
            "stiffness_tilt": solved.stiffness[:, 4, 4],
            "equilibrium_residual": solved.residual,
        }
    if inputs.get("misalignment") is not None:
        results["tilting_moment_reaction"] = solved.reaction[:, 4]
    found = Found({key: value.reshape(shape) for key, value in results.items()},
                  checks=[(NO_EQUILIBRIUM, ~solved.converged.reshape(shape)),
                          (_crushing_code(inputs),
                           ~(ellipse <= contact[0] / 2.0).reshape(shape))])
    found.results.update({
        "reference_rating_life": l10r / revolutions_per_second,
        "reference_rating_life_revolutions": l10r,
        "modified_reference_rating_life": modified,
        "life_ratio_to_iso281": l10r / np.asarray(iso281["basic_rating_life_revolutions"]),
    })
    if inputs.get("min_rating_life") is not None:
        found.results["life_margin"] = life_margin(modified, inputs["min_rating_life"])
    # the limit judges the operating contacts, not ISO 76's at P0
    largest = np.maximum(inner, outer).reshape(shape)
    found.results["max_contact_pressure"] = largest
    if inputs.get("max_contact_pressure") is not None:
        found.results["contact_pressure_margin"] = 1.0 - largest / np.asarray(
            inputs["max_contact_pressure"], dtype=float)
    return found
