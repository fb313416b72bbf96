"""A disk rolling without slipping on a circle that may turn.

Source: H. Jackman, *Rolling constraints* (Karlstad University course note), "Rolling on a fixed
surface in two dimensions" and "Rolling on a moving surface in two dimensions";
docs/physics.md §2.

Disk radius r, absolute angular velocity ω (and ω̇); circular surface of radius R
turning with Ω (and Ω̇) about its centre O; Ω = 0 is the fixed surface. In
external contact the disk rolls on the outside of the circle (centre distance
R + r), in internal contact on the inside of a ring (R − r, needs r < R).

Signs: every angular quantity is positive in one sense of rotation about the
axis normal to the plane; the centre speed and tangential acceleration are
components along e_t, the direction in which G moves when it orbits O in that
positive sense. Inputs in SI (m, rad/s, rad/s²), floats or broadcasting arrays.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.common import broadcast_all, first_failure, nan_where
from bearingcalc.core.solver import Solution, Solver

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import DiskOnCircleInputs

RESULTS: dict[str, tuple[str, str]] = {
    "center_distance": ("m", "distance OG: R + r (external) or R − r (internal)"),
    "center_speed": ("m/s", "velocity of the disk centre G along e_t"),
    "center_tangential_accel": ("m/s²", "acceleration of G along e_t"),
    "center_normal_accel": ("m/s²", "acceleration of G toward O"),
    "center_accel": ("m/s²", "magnitude of the acceleration of G"),
    "orbit_speed": ("rad/s", "angular speed of the line OG"),
    "contact_point_accel": ("m/s²", "acceleration of the disk's material contact point"),
}

STATUS_REASONS: dict[int, tuple[str, str]] = {
    1: ("disk_radius", "the disk radius must be positive"),
    2: ("surface_radius", "the surface radius must be positive"),
    3: ("disk_radius", "internal contact needs disk_radius < surface_radius"),
}


def disk_on_circle_status(disk_radius: ArrayLike, surface_radius: ArrayLike,
                          internal: ArrayLike = False) -> NDArray:
    """0 where the geometry is possible, else a key of ``STATUS_REASONS``."""
    r = np.asarray(disk_radius, dtype=float)
    big_r = np.asarray(surface_radius, dtype=float)
    inside = np.asarray(internal, dtype=bool)
    with np.errstate(invalid="ignore"):
        checks = [(1, ~(r > 0)), (2, ~(big_r > 0)), (3, inside & ~(r < big_r))]
    return first_failure(checks, np.broadcast_shapes(r.shape, big_r.shape, inside.shape))


def solve_disk_on_circle(disk_radius: ArrayLike, surface_radius: ArrayLike,
                         disk_speed: ArrayLike, *, disk_accel: ArrayLike = 0.0,
                         surface_speed: ArrayLike = 0.0, surface_accel: ArrayLike = 0.0,
                         internal: ArrayLike = False) -> dict[str, NDArray]:
    r"""Velocity and acceleration of the centre and of the contact point of a rolling disk.

    With s = +1 for external and −1 for internal contact, D = R + s·r:

    .. math::
        v_G = R\Omega + s\,r\omega, \qquad
        a_t = R\dot\Omega + s\,r\dot\omega, \qquad
        a_n = \frac{v_G^2}{D}, \qquad \dot\theta = \frac{v_G}{D}

    and the disk's material point at the contact has tangential acceleration
    RΩ̇ and, toward O, v_G²/D − s·rω².

    Parameters
    ----------
    disk_radius : r > 0. [m]
    surface_radius : R > 0 (and R > r for internal contact). [m]
    disk_speed : ω, absolute. [rad/s]
    disk_accel : ω̇. [rad/s²]
    surface_speed : Ω; 0 for a fixed surface. [rad/s]
    surface_accel : Ω̇. [rad/s²]
    internal : True for a disk inside a ring.

    Returns
    -------
    dict of arrays keyed as :data:`RESULTS`; NaN where the geometry is impossible.

    Source: Jackman, *Rolling constraints*, "Rolling on a moving surface in two dimensions";
    docs/physics.md §2.

    Examples
    --------
    A disk of radius 1 rolling at 2 rad/s on a fixed circle of radius 3:

    >>> out = solve_disk_on_circle(1.0, 3.0, 2.0)
    >>> float(out["center_speed"]), float(out["center_normal_accel"])
    (2.0, 1.0)
    """
    r = np.asarray(disk_radius, dtype=float)
    big_r = np.asarray(surface_radius, dtype=float)
    omega, omega_dot = np.asarray(disk_speed, dtype=float), np.asarray(disk_accel, dtype=float)
    big_omega = np.asarray(surface_speed, dtype=float)
    big_omega_dot = np.asarray(surface_accel, dtype=float)
    side = np.where(np.asarray(internal, dtype=bool), -1.0, 1.0)
    bad = disk_on_circle_status(r, big_r, internal) != 0

    distance = nan_where(bad, big_r + side * r)
    v_g = big_r * big_omega + side * r * omega
    a_t = big_r * big_omega_dot + side * r * omega_dot
    a_n = v_g**2 / distance
    contact_normal = a_n - side * r * omega**2
    return broadcast_all({
        "center_distance": distance,
        "center_speed": nan_where(bad, v_g),
        "center_tangential_accel": nan_where(bad, a_t),
        "center_normal_accel": a_n,
        "center_accel": np.hypot(a_t, a_n),
        "orbit_speed": v_g / distance,
        "contact_point_accel": np.hypot(big_r * big_omega_dot, contact_normal),
    })


def evaluate(inputs: DiskOnCircleInputs,
             wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: results and status codes from the spec's SI inputs.

    ``wanted`` (the results a caller needs) is a hint this solver does not need:
    it computes everything at once.
    """
    internal = inputs["internal"]
    status = disk_on_circle_status(inputs["disk_radius"], inputs["surface_radius"], internal)
    results = solve_disk_on_circle(
        inputs["disk_radius"], inputs["surface_radius"], inputs["disk_speed"],
        disk_accel=inputs["disk_accel"], surface_speed=inputs["surface_speed"],
        surface_accel=inputs["surface_accel"], internal=internal)
    return Solution(results, status)


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, inputs="DiskOnCircleInputs")
