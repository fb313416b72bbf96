"""The most heavily loaded ball of a ball bearing: its load and its Hertz contacts with
both races (``docs/physics.md`` §6).

Every function takes SI values as floats or numpy arrays, which broadcast, and returns
arrays.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.hertz import hertz_point_contact


def ball_contacts(ball_count: ArrayLike, ball_diameter: ArrayLike, pitch_diameter: ArrayLike,  # noqa: PLR0913  a numpy kernel of the contacts' array inputs
                  contact_angle: ArrayLike, thrust: bool, static_equivalent_load: ArrayLike,
                  inner_conformity: ArrayLike, outer_conformity: ArrayLike,
                  elastic_modulus: ArrayLike, poisson_ratio: ArrayLike,
                  max_contact_pressure: ArrayLike) -> dict[str, NDArray]:
    r"""Hertz contacts of the most heavily loaded ball with both races.

    The ball carries Stribeck's share of the load (the basis of ISO 76's C0) in a radial
    bearing, and an equal share of the axial load in a thrust bearing:

    .. math:: Q = \frac{5 P_0}{Z\cos\alpha} \ \text{(radial)}, \qquad
              Q = \frac{F_a}{Z\sin\alpha} \ \text{(thrust)}

    With γ = Dw·cosα/Dpw the principal curvatures are 2/Dw (ball, both planes);
    2γ/(Dw(1 − γ)) and −1/(fi·Dw) at the inner race; −2γ/(Dw(1 + γ)) and −1/(fo·Dw) at
    the outer race (rolling plane, then across the groove), and each contact follows
    :func:`bearingcalc.core.hertz.hertz_point_contact`.

    Parameters
    ----------
    ball_count : Z. [1]
    ball_diameter, pitch_diameter : Dw, Dpw. [m]
    contact_angle : α. [rad]
    thrust : a thrust bearing (α = 90°).
    static_equivalent_load : P0 (Fa for thrust). [N]
    inner_conformity, outer_conformity : fi, fo > 0.5. [1]
    elastic_modulus, poisson_ratio : of ball and races alike. [Pa], [1]
    max_contact_pressure : the limit. [Pa]

    Returns
    -------
    dict of the ball's load Q [N], each contact's peak pressure [Pa], semi-axes [m] and
    approach [m], the larger pressure [Pa] and its margin to the limit [1].

    Source: ISO 76:2006 6.1 and its basis; Harris & Kotzalas, *Essential Concepts of
    Bearing Technology*, 5th ed., ch. 2 (curvatures) and ch. 6 (Hertz).
    """
    z = np.asarray(ball_count, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    cos_alpha = np.where(thrust, 0.0, np.cos(alpha))
    gamma = dw * cos_alpha / np.asarray(pitch_diameter, dtype=float)
    load = (np.asarray(static_equivalent_load, dtype=float) / z
            / (np.sin(alpha) if thrust else cos_alpha / 5.0))
    e, nu = elastic_modulus, poisson_ratio
    inner = hertz_point_contact(load, *raceway_curvatures(dw, gamma, inner_conformity, True),
                                e, nu, e, nu)
    outer = hertz_point_contact(load, *raceway_curvatures(dw, gamma, outer_conformity, False),
                                e, nu, e, nu)
    peak = np.maximum(inner["max_pressure"], outer["max_pressure"])
    return {
        "max_ball_load": load,
        "inner_contact_pressure": inner["max_pressure"],
        "outer_contact_pressure": outer["max_pressure"],
        "inner_contact_semi_major": inner["semi_major"],
        "inner_contact_semi_minor": inner["semi_minor"],
        "outer_contact_semi_major": outer["semi_major"],
        "outer_contact_semi_minor": outer["semi_minor"],
        "inner_contact_approach": inner["approach"],
        "outer_contact_approach": outer["approach"],
        "max_contact_pressure": peak,
        "contact_pressure_margin": 1.0 - peak / np.asarray(max_contact_pressure),
    }


def raceway_curvatures(ball_diameter: ArrayLike, gamma: ArrayLike, conformity: ArrayLike,
                       inner: bool) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """A ball's principal curvatures (2/Dw in both planes) and its raceway's, in the
    rolling direction ±2γ/(Dw(1 ∓ γ)) (inner, outer) and across the groove −1/(f·Dw),
    γ = Dw·cosα/Dpw [1/m] (Harris & Kotzalas, ch. 2)."""
    dw = np.asarray(ball_diameter, dtype=float)
    gamma = np.asarray(gamma, dtype=float)
    ball = 2.0 / dw
    rolling = (2.0 * gamma / (dw * (1.0 - gamma)) if inner
               else -2.0 * gamma / (dw * (1.0 + gamma)))
    return ball, ball, rolling, -1.0 / (np.asarray(conformity) * dw)
