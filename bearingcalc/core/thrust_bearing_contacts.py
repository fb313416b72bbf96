"""The thrust bearing under an axial load: the forces on one ball and the Hertz pressure
at each of its three contacts (``docs/physics.md`` §1 and §6).

The frame is :mod:`bearingcalc.core.thrust_bearing`'s. Every function takes SI values as
floats or numpy arrays, which broadcast, and returns numpy arrays.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.hertz import hertz_point_contact


def ball_contact_loads(ball_radius: ArrayLike, contact_angle: ArrayLike,
                       pitch_radius: ArrayLike, cage_speed: ArrayLike, ball_count: ArrayLike,
                       axial_load: ArrayLike, elastic_modulus: ArrayLike,
                       poisson_ratio: ArrayLike, density: ArrayLike,
                       max_contact_pressure: ArrayLike) -> dict[str, NDArray]:
    r"""Contact forces on one ball and the Hertz pressure at each of its three contacts.

    Static balance of a ball in its meridian plane (gravity, friction and gyroscopic
    moments neglected): the shaft pushes along −n with Q3, the race wall along +e1 with
    Q1 and the race floor along +e2 with Q2, and the centrifugal force m·b·ω_cage² acts
    along −e1. All pass through the ball's centre, so

    .. math:: Q_3 = \frac{F_a}{Z\sin\theta}, \quad Q_2 = Q_3\sin\theta, \quad
              Q_1 = Q_3\cos\theta + m\,b\,\omega_{cage}^2

    Curvatures: the ball 1/r in every plane; the race bore, a concave cylinder of
    radius b + r, −1/(b + r) about the axis and 0 along it; the floor, flat; the shaft's
    cone cosθ/d about the axis (d = b − r·cosθ) and 0 along its generator.

    Parameters
    ----------
    ball_radius, contact_angle, pitch_radius : r [m], θ [rad], b [m].
    cage_speed : ω_cage. [rad/s]
    ball_count : Z. [1]
    axial_load : Fa on the shaft. [N]
    elastic_modulus, poisson_ratio, density : of balls, race and shaft alike.
        [Pa], [1], [kg/m³]
    max_contact_pressure : the limit. [Pa]

    Source: docs/physics.md §1 (geometry) and §6 (Hertz).
    """
    r, theta, b = (np.asarray(x, dtype=float) for x in (ball_radius, contact_angle,
                                                         pitch_radius))
    sin, cos = np.sin(theta), np.cos(theta)
    mass = np.asarray(density, dtype=float) * (4.0 / 3.0) * np.pi * r ** 3
    centrifugal = mass * b * np.asarray(cage_speed, dtype=float) ** 2
    q3 = np.asarray(axial_load, dtype=float) / (np.asarray(ball_count, dtype=float) * sin)
    q2 = q3 * sin
    q1 = q3 * cos + centrifugal
    ball = 1.0 / r
    e, nu = elastic_modulus, poisson_ratio
    shaft = hertz_point_contact(q3, ball, ball, cos / (b - r * cos), 0.0, e, nu, e, nu)
    wall = hertz_point_contact(q1, ball, ball, -1.0 / (b + r), 0.0, e, nu, e, nu)
    floor = hertz_point_contact(q2, ball, ball, 0.0, 0.0, e, nu, e, nu)
    peak = np.maximum(np.maximum(shaft["max_pressure"], wall["max_pressure"]),
                      floor["max_pressure"])
    return {
        "shaft_contact_load": q3, "race_radial_contact_load": q1,
        "race_axial_contact_load": q2, "ball_centrifugal_force": centrifugal,
        "shaft_contact_pressure": shaft["max_pressure"],
        "race_radial_contact_pressure": wall["max_pressure"],
        "race_axial_contact_pressure": floor["max_pressure"],
        "max_contact_pressure": peak,
        "contact_pressure_margin": 1.0 - peak / np.asarray(max_contact_pressure),
        # Not a result: evaluate() judges Hertz theory's validity by it.
        "_largest_semi_major": np.maximum(np.maximum(shaft["semi_major"], wall["semi_major"]),
                                          floor["semi_major"]),
    }
