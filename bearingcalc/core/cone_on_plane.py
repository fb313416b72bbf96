"""A right circular cone rolling without slipping on a fixed plane, apex fixed.

Source: H. Jackman, *Rolling constraints* (Karlstad University course note), "Cone rolling on a flat
plane"; docs/physics.md §3.

Frame S: n1 along the line of contact (from the apex), k normal to the plane,
n2 = k × n1. Every point of the contact line is at rest, so the cone turns
about it: ω_B = ω·n1. β is the half-angle of the cone, ω the spin about the
contact line. Inputs in SI (rad, rad/s, rad/s², m), floats or broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.common import broadcast_all, first_failure, nan_where
from bearingcalc.core.solver import Solution, Solver

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import ConeOnPlaneInputs

RESULTS: dict[str, tuple[str, str]] = {
    "precession_speed": ("rad/s", "Ω = −ω·tanβ, the contact line turning about the normal"),
    "angular_accel": ("rad/s²", "magnitude of the angular acceleration ω̇·n1 − ω²·tanβ·n2"),
    "axis_point_speed": ("m/s", "speed a·|ω| of the axis point at height a"),
    "axis_point_accel": ("m/s²", "acceleration magnitude of the axis point at height a"),
}

STATUS_REASONS: dict[int, tuple[str, str]] = {
    1: ("half_angle", "the cone half-angle must be between 0 deg and 90 deg"),
    2: ("axis_point_height", "the axis point height must be positive"),
}


def cone_on_plane_status(half_angle: ArrayLike,
                         axis_point_height: ArrayLike | None = None) -> NDArray:
    """0 where the geometry is possible, else a key of ``STATUS_REASONS``."""
    beta = np.asarray(half_angle, dtype=float)
    height = np.asarray(1.0 if axis_point_height is None else axis_point_height, dtype=float)
    with np.errstate(invalid="ignore"):
        checks = [(1, ~((beta > 0) & (beta < np.pi / 2))), (2, ~(height > 0))]
    return first_failure(checks, np.broadcast_shapes(beta.shape, height.shape))


def solve_cone_on_plane(half_angle: ArrayLike, spin_speed: ArrayLike, *,
                        spin_accel: ArrayLike = 0.0,
                        axis_point_height: ArrayLike | None = None) -> dict[str, NDArray]:
    r"""Precession and accelerations of a cone rolling on a plane.

    .. math::
        \Omega = -\omega\tan\beta, \qquad
        \dot{\vec\omega} = \dot\omega\,n_1 - \omega^2\tan\beta\,n_2, \qquad
        \vec v_P = -a\omega\,n_2, \qquad
        \vec a_P = -a\dot\omega\,n_2 - a\omega^2\tan\beta\,n_1

    Parameters
    ----------
    half_angle : β, 0 < β < π/2. [rad]
    spin_speed : ω about the contact line. [rad/s]
    spin_accel : ω̇. [rad/s²]
    axis_point_height : a, height above the plane of a point on the axis;
        optional, adds ``axis_point_speed`` and ``axis_point_accel``. [m]

    Returns
    -------
    dict of arrays keyed as :data:`RESULTS`; NaN where the geometry is impossible.

    Source: Jackman, *Rolling constraints*, "Cone rolling on a flat plane"; docs/physics.md §3.

    Examples
    --------
    >>> out = solve_cone_on_plane(np.radians(45.0), 2.0)
    >>> round(float(out["precession_speed"]), 12)
    -2.0
    """
    beta = np.asarray(half_angle, dtype=float)
    omega = np.asarray(spin_speed, dtype=float)
    omega_dot = np.asarray(spin_accel, dtype=float)
    bad = cone_on_plane_status(beta, axis_point_height) != 0
    tan = nan_where(bad, np.tan(beta))
    results = {
        "precession_speed": -omega * tan,
        "angular_accel": np.hypot(omega_dot, omega**2 * tan),
    }
    if axis_point_height is not None:
        a = np.asarray(axis_point_height, dtype=float)
        results["axis_point_speed"] = nan_where(bad, a * np.abs(omega))
        results["axis_point_accel"] = a * np.hypot(omega_dot, omega**2 * tan)
    return broadcast_all(results)


def evaluate(inputs: ConeOnPlaneInputs,
             wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: results and status codes from the spec's SI inputs.

    ``wanted`` (the results a caller needs) is a hint this solver does not need:
    it computes everything at once.
    """
    height = inputs.get("axis_point_height")
    status = cone_on_plane_status(inputs["half_angle"], height)  # type: ignore[arg-type]
    results = solve_cone_on_plane(inputs["half_angle"], inputs["spin_speed"],  # type: ignore[arg-type]
                                  spin_accel=inputs["spin_accel"],  # type: ignore[arg-type]
                                  axis_point_height=height)
    return Solution(results, status)


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, inputs="ConeOnPlaneInputs")
