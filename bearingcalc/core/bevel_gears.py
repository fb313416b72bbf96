"""Epicyclic bevel gears: gear B on a shaft, gear A turning freely on an arm.

Source: seed note, "Beveled gears"; docs/physics.md §4.

Gear B turns at Ω about k; the arm S turns at ω_Z about k through the common
apex O and carries gear A, which meshes with B. Pitch radii a (A) and b (B) at
the contact point C, pitch-cone half-angles α (A) and β (B), shaft angle
γ = α + β between the axes; n3 is A's axis, with k·n3 = cosγ. The pitch cones
roll on each other without slip when they share their apex: b/a = sinβ/sinα.

Inputs in SI (m, rad, rad/s), floats or broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.common import broadcast_all, first_failure, nan_where

RESULTS: dict[str, tuple[str, str]] = {
    "gear_a_pitch_radius": ("m", "pitch radius a of gear A"),
    "gear_b_pitch_radius": ("m", "pitch radius b of gear B"),
    "gear_a_pitch_angle": ("rad", "pitch-cone half-angle α of gear A"),
    "gear_b_pitch_angle": ("rad", "pitch-cone half-angle β of gear B"),
    "shaft_angle": ("rad", "shaft angle γ = α + β"),
    "gear_ratio": ("1", "b/a"),
    "cone_distance": ("m", "apex to pitch point, a/sinα"),
    "gear_a_speed_relative_to_arm": ("rad/s", "ω_AS = (b/a)(ω_Z − Ω)"),
    "relative_speed": ("rad/s", "|ω_A − ω_B|, gear A relative to gear B"),
    "gear_a_speed": ("rad/s", "|ω_Z·k + ω_AS·n3|, gear A's absolute angular speed"),
    "contact_point_speed": ("m/s", "gear B's material point at the contact, b·|Ω|"),
    "pitch_line_speed": ("m/s", "pitch point speed relative to the arm, b·|ω_Z − Ω|"),
    "apex_mismatch": ("1", "b·sinα/(a·sinβ) − 1; 0 when the pitch cones share their apex"),
    "slip_margin": ("1", "max_apex_mismatch − |apex_mismatch|"),
}

STATUS_REASONS: dict[int, tuple[str, str]] = {
    1: ("gear_a.pitch_radius", "the pitch radius of gear A must be positive"),
    2: ("gear_b.pitch_radius", "the pitch radius of gear B must be positive"),
    3: ("shaft_angle", "the shaft angle must be between 0 deg and 180 deg"),
    4: ("gear_a.pitch_angle", "the pitch angle of gear A must be between 0 deg and the "
                              "shaft angle"),
    5: ("gear_b.pitch_angle", "the pitch angle of gear B must be between 0 deg and the "
                              "shaft angle"),
    6: ("shaft_angle", "the shaft angle must equal the sum of the two pitch angles"),
}

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

    No slip at the pitch point C (seed, "Beveled gears"):

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

    Source: seed "Beveled gears"; docs/physics.md §4.
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
        "slip_margin": np.asarray(max_apex_mismatch, dtype=float) - np.abs(mismatch),
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


def evaluate(inputs: Mapping[str, ArrayLike | None],
             wanted: Collection[str] | None = None) -> tuple[dict[str, NDArray], NDArray]:
    """Registry entry point: results and status codes from the spec's SI inputs.

    ``wanted`` (the results a caller needs) is a hint this solver does not need:
    it computes everything at once.
    """
    a, b, alpha, beta, gamma = complete_geometry(inputs)
    status = bevel_gears_status(a, b, alpha, beta, gamma)
    results = solve_bevel_gears(a, b, alpha, beta, inputs["arm_speed"],  # type: ignore[arg-type]
                                gear_b_speed=inputs["gear_b_speed"],  # type: ignore[arg-type]
                                max_apex_mismatch=inputs["max_apex_mismatch"])  # type: ignore[arg-type]
    return results, status
