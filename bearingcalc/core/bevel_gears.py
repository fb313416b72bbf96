"""Epicyclic bevel gears: gear B on a shaft, gear A turning freely on an arm.

Source: H. Jackman, *Rolling constraints* (Karlstad University course note), "Beveled gears";
docs/physics.md §4.

Gear B turns at Ω about k; the arm S turns at ω_Z about k through the common
apex O and carries gear A, which meshes with B. Pitch radii a (A) and b (B) at
the contact point C, pitch-cone half-angles α (A) and β (B), shaft angle
γ = α + β between the axes; n3 is A's axis, with k·n3 = cosγ. The pitch cones
roll on each other without slip when they share their apex: b/a = sinβ/sinα.

Inputs in SI (m, rad, rad/s), floats or broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core import (
    bevel_rating,
    bevel_sizing,
    gear_materials,
    iso10300_virtual,
    iso23509,
)
from bearingcalc.core.bevel_gears_results import (
    APEX_MISMATCH_MARGIN,
    BLANK_RESULTS,
    GROUPS,
    RESULTS,
    STATUS_REASONS,
    WARNINGS,
)
from bearingcalc.core.common import broadcast_all, first_failure, nan_where
from bearingcalc.core.duty_cycle_gears import GEAR_BINS, GEAR_CYCLE_RESULTS, gear_pair_cycle
from bearingcalc.core.solver import DutyCycle, Solution, Solver

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import BevelGearsInputs

#: |γ − (α + β)| above which given angles are inconsistent. [rad] (about 2e-7 deg)
ANGLE_SUM_TOLERANCE = 1e-9 * np.pi


def pitch_angles(gear_a_pitch_radius: ArrayLike, gear_b_pitch_radius: ArrayLike,
                 shaft_angle: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""Pitch-cone half-angles of a bevel pair that share their apex.

    .. math:: \tan\alpha = \frac{\sin\gamma}{b/a + \cos\gamma}, \qquad \beta = \gamma - \alpha

    (the standard bevel pitch-angle formula, as atan2 so that γ > 90° works).

    Parameters
    ----------
    gear_a_pitch_radius : a. [m] (or tooth count z_A: only the ratio matters)
    gear_b_pitch_radius : b. [m] (or z_B)
    shaft_angle : γ, 0 < γ < π. [rad]

    Returns
    -------
    (α, β). [rad]

    Source: docs/physics.md §4.

    >>> alpha, beta = pitch_angles(12, 24, np.radians(90.0))
    >>> round(float(np.degrees(alpha)), 3), round(float(np.degrees(beta)), 3)
    (26.565, 63.435)
    """
    a = np.asarray(gear_a_pitch_radius, dtype=float)
    b = np.asarray(gear_b_pitch_radius, dtype=float)
    gamma = np.asarray(shaft_angle, dtype=float)
    alpha = np.arctan2(np.sin(gamma), b / a + np.cos(gamma))
    return alpha, gamma - alpha


def bevel_gears_status(a: ArrayLike, b: ArrayLike, alpha: ArrayLike, beta: ArrayLike,
                       gamma: ArrayLike) -> NDArray:
    """0 where the geometry is possible, else a key of ``STATUS_REASONS``."""
    a, b, alpha, beta, gamma = (np.asarray(x, dtype=float) for x in (a, b, alpha, beta, gamma))
    with np.errstate(invalid="ignore"):
        checks = [
            (1, ~(a > 0)),
            (2, ~(b > 0)),
            (3, ~((gamma > 0) & (gamma < np.pi))),
            (4, ~((alpha > 0) & (alpha < gamma))),
            (5, ~((beta > 0) & (beta < gamma))),
            (6, ~(np.abs(gamma - alpha - beta) <= ANGLE_SUM_TOLERANCE)),
        ]
    shape = np.broadcast_shapes(a.shape, b.shape, alpha.shape, beta.shape, gamma.shape)
    return first_failure(checks, shape)


def solve_bevel_gears(gear_a_pitch_radius: ArrayLike, gear_b_pitch_radius: ArrayLike,
                      gear_a_pitch_angle: ArrayLike, gear_b_pitch_angle: ArrayLike,
                      arm_speed: ArrayLike, *, gear_b_speed: ArrayLike = 0.0,
                      max_apex_mismatch: ArrayLike = 0.001) -> dict[str, NDArray]:
    r"""Speeds of an epicyclic bevel pair and how far its pitch cones are from pure rolling.

    No slip at the pitch point C (Jackman, *Rolling constraints*, "Beveled gears"):

    .. math::
        \omega_{AS} = \frac{b}{a}(\omega_Z - \Omega), \qquad
        \vec\omega_A = \omega_Z\,k + \omega_{AS}\,n_3, \quad k\cdot n_3 = \cos\gamma

    and A relative to B turns at ω_A − Ω·k, of magnitude |ω_Z − Ω|·sinγ/sinα when
    the cones share their apex.

    Parameters
    ----------
    gear_a_pitch_radius : a. [m]
    gear_b_pitch_radius : b. [m]
    gear_a_pitch_angle : α. [rad]
    gear_b_pitch_angle : β. [rad]; the shaft angle is γ = α + β.
    arm_speed : ω_Z. [rad/s]
    gear_b_speed : Ω. [rad/s]
    max_apex_mismatch : the limit on |b·sinα/(a·sinβ) − 1|. [1]

    Returns
    -------
    dict of arrays keyed as :data:`RESULTS`; NaN where the geometry is impossible.

    Source: Jackman, *Rolling constraints*, "Beveled gears"; docs/physics.md §4.
    """
    a = np.asarray(gear_a_pitch_radius, dtype=float)
    b = np.asarray(gear_b_pitch_radius, dtype=float)
    alpha = np.asarray(gear_a_pitch_angle, dtype=float)
    beta = np.asarray(gear_b_pitch_angle, dtype=float)
    gamma = alpha + beta
    omega_z = np.asarray(arm_speed, dtype=float)
    big_omega = np.asarray(gear_b_speed, dtype=float)
    bad = bevel_gears_status(a, b, alpha, beta, gamma) != 0
    a, b, alpha, beta, gamma = (nan_where(bad, x) for x in (a, b, alpha, beta, gamma))

    carrier = omega_z - big_omega
    omega_as = b / a * carrier
    cos_gamma = np.cos(gamma)
    # |u·k + w·n3| with k·n3 = cosγ, written so that rounding cannot make it negative.
    gear_a_speed = np.sqrt(np.maximum(
        omega_z**2 + omega_as**2 + 2 * omega_z * omega_as * cos_gamma, 0.0))
    relative_speed = np.sqrt(np.maximum(
        carrier**2 + omega_as**2 + 2 * carrier * omega_as * cos_gamma, 0.0))
    mismatch = b * np.sin(alpha) / (a * np.sin(beta)) - 1.0
    return broadcast_all({
        "gear_a_pitch_radius": a,
        "gear_b_pitch_radius": b,
        "gear_a_pitch_angle": alpha,
        "gear_b_pitch_angle": beta,
        "shaft_angle": gamma,
        "gear_ratio": b / a,
        "cone_distance": a / np.sin(alpha),
        "gear_a_speed_relative_to_arm": omega_as,
        "relative_speed": relative_speed,
        "gear_a_speed": gear_a_speed,
        "contact_point_speed": b * np.abs(big_omega),
        "pitch_line_speed": b * np.abs(carrier),
        "apex_mismatch": mismatch,
        APEX_MISMATCH_MARGIN: np.asarray(max_apex_mismatch, dtype=float) - np.abs(mismatch),
    })


def complete_geometry(inputs: Mapping[str, ArrayLike | None]) -> tuple[NDArray, ...]:
    """(a, b, α, β, γ) from whichever of radii, teeth, module and angles are given.

    A pitch radius comes from ``gear_*_pitch_radius`` or from module·teeth/2; a
    missing shaft angle is α + β; a missing pitch angle is γ minus the other;
    with both missing, the pair shares its apex (:func:`pitch_angles`).
    """
    def radius(gear: str) -> NDArray:
        given = inputs.get(f"{gear}_pitch_radius")
        if given is not None:
            return np.asarray(given, dtype=float)
        return np.asarray(inputs["module"], dtype=float) * np.asarray(
            inputs[f"{gear}_teeth"], dtype=float) / 2.0

    a, b = radius("gear_a"), radius("gear_b")
    alpha, beta, gamma = (inputs.get(key) for key in
                          ("gear_a_pitch_angle", "gear_b_pitch_angle", "shaft_angle"))
    if gamma is None:
        gamma = np.asarray(alpha, dtype=float) + np.asarray(beta, dtype=float)
    gamma = np.asarray(gamma, dtype=float)
    if alpha is None and beta is None:
        alpha, beta = pitch_angles(a, b, gamma)
    elif alpha is None:
        alpha = gamma - np.asarray(beta, dtype=float)
    elif beta is None:
        beta = gamma - np.asarray(alpha, dtype=float)
    return a, b, np.asarray(alpha, dtype=float), np.asarray(beta, dtype=float), gamma


#: Results of the epicyclic pair only: speeds relative to the arm and of gear B's shaft.
EPICYCLIC_ONLY = ("gear_a_speed_relative_to_arm", "relative_speed", "contact_point_speed")
#: Results that are zero by construction where the pitch angles are solved for a
#: common apex.
APEX_ONLY = ("apex_mismatch", APEX_MISMATCH_MARGIN)


def left_out(inputs: Mapping[str, ArrayLike | None]) -> tuple[str, ...]:
    """The results that carry no information for this pair: the epicyclic pair's own on
    fixed axes, and the apex mismatch where the pitch angles were solved (not given)."""
    fixed = inputs.get("axes") == "fixed"
    solved = inputs.get("gear_a_pitch_angle") is None and inputs.get(
        "gear_b_pitch_angle") is None
    return (EPICYCLIC_ONLY if fixed else ()) + (APEX_ONLY if fixed and solved else ())


def evaluate(inputs: BevelGearsInputs,
             wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: results and status codes from the spec's SI inputs.

    ``wanted`` (the results a caller needs) is a hint this solver does not need:
    it computes everything at once.
    """
    a, b, alpha, beta, gamma = complete_geometry(inputs)
    status = bevel_gears_status(a, b, alpha, beta, gamma)
    results = solve_bevel_gears(a, b, alpha, beta, inputs["arm_speed"],  # type: ignore[arg-type]
                                gear_b_speed=inputs["gear_b_speed"],  # type: ignore[arg-type]
                                max_apex_mismatch=inputs["max_apex_mismatch"])  # type: ignore[arg-type]
    if inputs.get("face_width") is None:
        return Solution(_without(results, left_out(inputs)), status)
    sized, checks = size_pair(inputs, results)
    undercut = sized.pop("undercut")
    shape = np.broadcast_shapes(status.shape, np.shape(undercut),
                                *(np.shape(c) for _, c in checks))
    status = np.where(np.broadcast_to(status, shape) != 0, np.broadcast_to(status, shape),
                      first_failure(checks, shape))
    results = broadcast_all(_without({**results, **sized}, left_out(inputs)))
    return Solution(results, status, {"undercut": np.broadcast_to(undercut, status.shape)})


def _without(results: dict[str, NDArray], keys: Collection[str]) -> dict[str, NDArray]:
    return {key: value for key, value in results.items() if key not in keys}


def size_pair(inputs: Mapping[str, ArrayLike | None], kinematics: Mapping[str, NDArray]
              ) -> tuple[dict[str, NDArray], list[tuple[int, NDArray]]]:
    """Blank geometry, tooth forces and AGMA rating of a pair given by teeth and module,
    and the status checks they add (see :mod:`bearingcalc.core.bevel_sizing`)."""
    alpha, beta = kinematics["gear_a_pitch_angle"], kinematics["gear_b_pitch_angle"]
    phi = np.asarray(inputs["pressure_angle"], dtype=float)
    face = np.asarray(inputs["face_width"], dtype=float)
    out = bevel_sizing.blank_geometry(inputs["gear_a_teeth"], inputs["gear_b_teeth"],  # type: ignore[arg-type]
                                      inputs["module"], alpha, beta, face, phi)  # type: ignore[arg-type]
    checks: list[tuple[int, NDArray]] = [(7, ~(face < 0.5 * out["outer_cone_distance"]))]
    out["face_width_margin"] = np.asarray(inputs["max_face_width_ratio"]) - out["face_width_ratio"]
    if inputs.get("spiral_angle") is not None:
        out, blank_checks = _spiral_blank(inputs, out, phi, (alpha, beta))
        checks += blank_checks
    # Not a result: the undercut warning's flag, which evaluate() takes out: a straight
    # pair's (a spiral or Zerol pair's teeth are checked against its profile shift)
    out["undercut"] = (out["gear_a_virtual_teeth"] < 2.0 / np.sin(phi) ** 2) & (
        inputs.get("spiral_angle") is None)
    speed = np.abs(kinematics["gear_a_speed_relative_to_arm"])
    given, power = inputs.get("torque"), inputs.get("power")
    if given is None and power is None:
        return out, checks
    # A duty cycle's bins may give either: NaN marks a bin that gives the other.
    torque = np.full(np.shape(speed), np.nan) if given is None else np.abs(
        np.asarray(given, dtype=float))
    if power is not None:
        by_power = np.isnan(torque)
        checks.append((8, by_power & ~(speed > 0)))
        with np.errstate(divide="ignore", invalid="ignore"):
            torque = np.where(by_power, np.asarray(power, dtype=float) / speed, torque)
    if inputs.get("spiral_angle") is None:
        out.update(bevel_sizing.tooth_forces(torque, out["gear_a_mean_pitch_diameter"], phi,
                                             alpha, beta))
    else:
        out.update(bevel_sizing.spiral_tooth_forces(
            torque, out["gear_a_mean_pitch_diameter"], phi, inputs["spiral_angle"], alpha,
            beta, inputs["thrust_sign"]))
    if inputs.get("quality_number") is None:
        return out, checks
    curvature = 1.0
    if inputs.get("spiral_angle") is not None:
        curvature = out["lengthwise_curvature_factor"] = bevel_rating.lengthwise_curvature_factor(
            inputs["spiral_angle"], inputs["cutter_radius"],  # type: ignore[arg-type]
            out["mean_cone_distance"])
    rating = bevel_rating.rate_pair(bevel_rating.PairRatingInput(
        torque, speed, inputs["module"], out["gear_a_outer_pitch_diameter"], face,  # type: ignore[arg-type]
        inputs["quality_number"], inputs["hardness"], inputs["mounting_factor"],  # type: ignore[arg-type]
        inputs["crowned"], inputs["geometry_factor_bending"],  # type: ignore[arg-type]
        inputs["geometry_factor_pitting"], inputs["overload_factor"], inputs["cycles"],  # type: ignore[arg-type]
        inputs["reliability"], lengthwise_curvature_factor=curvature,  # type: ignore[arg-type]
        **gear_materials.rating_terms(inputs)))
    out.update(rating.as_results())
    # the rating's own v_et, at the pinion's outer pitch circle
    outer_speed = 0.5 * out["gear_a_outer_pitch_diameter"] * speed
    checks.append((9, outer_speed > bevel_rating.max_pitch_line_speed(
        inputs["quality_number"])))  # type: ignore[arg-type]
    out.update(_safety_margins(rating, inputs))
    return out, checks


#: The Gleason proportions a spiral or Zerol pair's ISO 23509 blank replaces.
GLEASON_BLANK = tuple(f"gear_{gear}_{key}" for key in (
    "addendum", "dedendum", "dedendum_angle", "outside_diameter", "crown_to_apex")
    for gear in ("a", "b"))
#: The status codes of a tooth undercut or pointed, by member.
UNDERCUT = {"pinion": 10, "gear": 12}
POINTED = {"pinion": 11, "gear": 13}
POINTED_BY_RACK = {"pinion": 14, "gear": 15}
#: The status code of a duplex taper whose cutter is too small for the spiral.
DUPLEX_CUTTER = 16


def _spiral_blank(inputs: Mapping[str, ArrayLike | None], sized: Mapping[str, NDArray],
                  phi: NDArray, pitch_angles: tuple[NDArray, NDArray]
                  ) -> tuple[dict[str, NDArray], list[tuple[int, NDArray]]]:
    """A spiral or Zerol pair's sizing: the straight pair's ``sized`` with its normal
    section, and its blank by ISO 23509 in place of the Gleason proportions
    (:data:`GLEASON_BLANK`); and the checks of each member's teeth."""
    out = {key: value for key, value in sized.items() if key not in GLEASON_BLANK}
    out.update(bevel_sizing.spiral_normal_section(
        out["mean_module"], out["gear_a_virtual_teeth"], out["gear_b_virtual_teeth"],
        inputs["spiral_angle"], phi))  # type: ignore[arg-type]
    blank, checks = _iso23509_blank(inputs, out, phi, pitch_angles)
    return {**out, **blank}, checks


def _iso23509_blank(inputs: Mapping[str, ArrayLike | None], out: Mapping[str, NDArray],
                    phi: NDArray, pitch_angles: tuple[NDArray, NDArray]
                    ) -> tuple[dict[str, NDArray], list[tuple[int, NDArray]]]:
    """A spiral or Zerol pair's blank by ISO 23509 from the sizing's ``out`` on the
    pair's ``pitch_angles``, with the virtual cylindrical pair's transverse contact
    ratio, and the checks of the duplex taper's cutter and of each member's teeth:
    undercut, pointed (by the shift, or by the basic rack itself)."""
    z1, z2 = inputs["gear_a_teeth"], inputs["gear_b_teeth"]
    delta1, delta2 = pitch_angles
    shift = inputs.get("profile_shift")
    if shift is None:
        shift = iso23509.gleason_profile_shift(z1, z2, delta1, delta2,  # type: ignore[arg-type]
                                               inputs["addendum_factor"])  # type: ignore[arg-type]
    cutter = inputs.get("cutter_radius")
    cutter = np.asarray(np.nan if cutter is None else cutter, dtype=float)
    blank = iso23509.blank(iso23509.BlankInputs(
        z1, z2, delta1 + delta2, out["gear_b_outer_pitch_diameter"],  # type: ignore[arg-type]
        inputs["face_width"], inputs["spiral_angle"], phi, cutter, shift,  # type: ignore[arg-type]
        inputs["thickness_modification_pinion"], inputs["thickness_modification_gear"],  # type: ignore[arg-type]
        inputs["addendum_factor"], inputs["dedendum_factor"], str(inputs["taper"]),  # type: ignore[arg-type]
        pitch_angles))
    virtual = iso10300_virtual.virtual_gears(iso10300_virtual.MeanSection(
        z1, z2, (blank["mean_pitch_diameter_pinion"], blank["mean_pitch_diameter_gear"]),  # type: ignore[arg-type]
        pitch_angles, (blank["mean_addendum_pinion"], blank["mean_addendum_gear"]),
        (blank["mean_dedendum_pinion"], blank["mean_dedendum_gear"]),
        blank["mean_normal_module"], inputs["spiral_angle"], phi,  # type: ignore[arg-type]
        inputs["face_width"]))  # type: ignore[arg-type]
    limits = iso23509.tooth_limits(blank, (virtual["zvn1"], virtual["zvn2"]), phi,
                                   (inputs["addendum_factor"], inputs["dedendum_factor"]),  # type: ignore[arg-type]
                                   (inputs.get("tool_edge_radius_pinion"),
                                    inputs.get("tool_edge_radius_gear")))
    found = {key: value for key, value in {**blank, **limits}.items()
             if key in BLANK_RESULTS}
    found["profile_shift"] = np.asarray(shift, dtype=float)
    found["contact_ratio"] = virtual["eps_v_alpha"]
    shifts = {"pinion": np.asarray(shift, dtype=float), "gear": -np.asarray(shift, dtype=float)}
    checks = []
    if inputs["taper"] == "duplex":  # the slot widens toward the toe: no duplex taper
        checks.append((DUPLEX_CUTTER, ~(cutter > blank["mean_cone_distance"] * np.sin(
            np.asarray(inputs["spiral_angle"], dtype=float)))))
    for member in ("pinion", "gear"):
        checks.append((UNDERCUT[member], shifts[member]
                       < limits[f"least_profile_shift_{member}"] - 1e-12))
        checks.append((POINTED_BY_RACK[member], ~(limits[f"rack_top_land_{member}"] > 0.0)))
        checks.append((POINTED[member], ~(limits[f"top_land_{member}"] > 0.0)))
    return found, checks


def _safety_margins(rating: bevel_rating.PairRating, inputs: Mapping[str, ArrayLike | None]
                    ) -> dict[str, NDArray]:
    """S − S_min in bending and in contact, of the weaker member where both are rated."""
    bending, contact = rating.bending_safety, rating.contact_safety
    if rating.gear_b is not None:  # the weaker member of the two governs
        bending = np.minimum(bending, rating.gear_b.bending_safety)
        contact = np.minimum(contact, rating.gear_b.contact_safety)
    return {"bending_safety_margin": bending - np.asarray(inputs["min_bending_safety"]),
            "contact_safety_margin": contact - np.asarray(inputs["min_contact_safety"])}


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, WARNINGS, GROUPS,
                duty=DutyCycle(gear_pair_cycle, GEAR_CYCLE_RESULTS, GEAR_BINS),
                inputs="BevelGearsInputs")
