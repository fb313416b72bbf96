"""The pure-rolling geometry of the thrust bearing: the pitch radius, contact angle or
ball radius at which the shaft contact rolls without spin, the spin-to-roll ratio of
any geometry, and the window of pitch radii that keeps it within a limit
(``docs/physics.md`` §1).

The frame is :mod:`bearingcalc.core.thrust_bearing`'s: ball radius r, pitch radius b,
shaft contact angle θ. Every function takes SI values (m, rad) as floats or numpy
arrays, which broadcast, and returns numpy arrays; geometrically impossible points
give NaN.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def pure_rolling_pitch_radius(ball_radius: ArrayLike, contact_angle: ArrayLike) -> NDArray:
    r"""Pitch radius at which the shaft contact rolls without spin.

    .. math:: b^* = r\,\frac{1 + \sin\theta}{\cos\theta - \sin\theta}

    Parameters
    ----------
    ball_radius : Ball radius r. [m]
    contact_angle : Shaft contact angle θ, finite only for 0 < θ < π/4. [rad]

    Returns
    -------
    Pitch radius b*. [m] NaN outside 0 < θ < π/4.

    Source: docs/physics.md §1 (Jackman, *Rolling constraints*, thrust bearing, final relation).

    >>> round(float(pure_rolling_pitch_radius(1.0, np.radians(30.0))), 4)
    4.0981
    """
    r = np.asarray(ball_radius, dtype=float)
    theta = _angle_in_range(contact_angle)
    return r * (1.0 + np.sin(theta)) / (np.cos(theta) - np.sin(theta))


def pure_rolling_contact_angle(ball_radius: ArrayLike, pitch_radius: ArrayLike) -> NDArray:
    r"""Contact angle at which a ball of radius r at pitch radius b rolls purely.

    Solves b·cosθ − (b + r)·sinθ = r in closed form:

    .. math:: \theta = \arccos\frac{r}{M} - \operatorname{atan2}(b + r, b),
              \quad M = \sqrt{b^2 + (b + r)^2}

    Parameters
    ----------
    ball_radius : Ball radius r > 0. [m]
    pitch_radius : Pitch radius b; a solution exists for every b > r. [m]

    Returns
    -------
    Contact angle θ in (0, π/4). [rad] NaN where b <= r.

    Source: docs/physics.md §1.
    """
    r = np.asarray(ball_radius, dtype=float)
    b = np.asarray(pitch_radius, dtype=float)
    with np.errstate(invalid="ignore"):
        theta = np.arccos(r / np.hypot(b, b + r)) - np.arctan2(b + r, b)
    return np.where((r > 0) & (b > r), theta, np.nan)


def pure_rolling_ball_radius(contact_angle: ArrayLike, pitch_radius: ArrayLike) -> NDArray:
    r"""Ball radius that rolls purely at pitch radius b and contact angle θ.

    .. math:: r = b\,\frac{\cos\theta - \sin\theta}{1 + \sin\theta}

    Parameters
    ----------
    contact_angle : Shaft contact angle θ, 0 < θ < π/4. [rad]
    pitch_radius : Pitch radius b. [m]

    Returns
    -------
    Ball radius r. [m] NaN outside 0 < θ < π/4.

    Source: docs/physics.md §1.
    """
    theta = _angle_in_range(contact_angle)
    b = np.asarray(pitch_radius, dtype=float)
    return b * (np.cos(theta) - np.sin(theta)) / (1.0 + np.sin(theta))


def spin_to_roll_ratio(ball_radius: ArrayLike, contact_angle: ArrayLike,
                       pitch_radius: ArrayLike) -> NDArray:
    r"""Spin-to-roll ratio ρ of the shaft relative to the ball at the shaft contact.

    .. math:: \rho = \frac{K\sin\theta + \sin\theta - \cos\theta}
                          {K\cos\theta + \sin\theta + \cos\theta},
              \quad K = \frac{r(1 + \sin\theta + \cos\theta)}{b - r\cos\theta}

    ρ falls monotonically from tanθ (as d → 0) through 0 (at b = b*) toward
    −tan(π/4 − θ) (as b → ∞). It does not depend on the shaft speed.

    Parameters
    ----------
    ball_radius : r. [m]
    contact_angle : θ. [rad]
    pitch_radius : b. [m]

    Returns
    -------
    ρ. [1] NaN where the geometry is impossible.

    Source: docs/physics.md §1.
    """
    r = np.asarray(ball_radius, dtype=float)
    theta = np.asarray(contact_angle, dtype=float)
    b = np.asarray(pitch_radius, dtype=float)
    return np.where(geometry_possible(r, theta, b), _spin_to_roll_unchecked(r, theta, b), np.nan)


def _spin_to_roll_unchecked(r: NDArray, theta: NDArray, b: NDArray) -> NDArray:
    return spin_to_roll_from(r, b, np.sin(theta), np.cos(theta))


def spin_to_roll_from(r: NDArray, b: NDArray, sin: NDArray, cos: NDArray) -> NDArray:
    """ρ from r, b and the contact angle's sine and cosine (see spin_to_roll_ratio)."""
    return spin_to_roll_from_terms(r * (1.0 + sin + cos), b - r * cos, sin, cos)


def spin_to_roll_from_terms(r_rolling: NDArray, d: NDArray, sin: NDArray, cos: NDArray
                            ) -> NDArray:
    """ρ from r(1 + sinθ + cosθ), d = b − r·cosθ, sinθ and cosθ, each computed once by
    the caller (the same arithmetic, so the same bits, as :func:`spin_to_roll_from`)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        k = r_rolling / d
        return (k * sin + sin - cos) / (k * cos + sin + cos)


def pitch_radius_window(ball_radius: ArrayLike, contact_angle: ArrayLike,
                        max_spin_to_roll: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""Range of pitch radii that keeps |ρ| <= ρ_max.

    Solving ρ = ±ρ_max for K and then b = r·cosθ + r(1 + sinθ + cosθ)/K:

    .. math:: K(\rho) = \frac{\rho(\sin\theta + \cos\theta) + \cos\theta - \sin\theta}
                             {\sin\theta - \rho\cos\theta}

    The lower edge solves ρ = +ρ_max; when ρ_max >= tanθ no b reaches it and the
    edge is the geometric bound b → r·cosθ. The upper edge solves ρ = −ρ_max; when
    ρ_max >= tan(π/4 − θ) there is no upper edge and it is +inf.

    Parameters
    ----------
    ball_radius : r. [m]
    contact_angle : θ, 0 < θ < π/4. [rad]
    max_spin_to_roll : ρ_max >= 0. [1]

    Returns
    -------
    (b_min, b_max). [m]

    Source: docs/physics.md §1.
    """
    r = np.asarray(ball_radius, dtype=float)
    theta = _angle_in_range(contact_angle)
    b_min, b_max = _window_from(r, theta, np.sin(theta), np.cos(theta), max_spin_to_roll)
    nan = np.isnan(theta) | np.isnan(np.asarray(max_spin_to_roll, dtype=float)) | np.isnan(r)
    return np.where(nan, np.nan, b_min), np.where(nan, np.nan, b_max)


def _window_from(r: NDArray, theta: NDArray, sin: NDArray, cos: NDArray,
                 max_spin_to_roll: ArrayLike) -> tuple[NDArray, NDArray]:
    """The window's edges from the contact angle and its sine and cosine (NaN in, NaN
    out for the lower edge; see pitch_radius_window)."""
    return pitch_radius_window_from_terms(r, theta, sin, cos, r * cos,
                                          r * (1.0 + sin + cos), max_spin_to_roll)


def pitch_radius_window_from_terms(r: NDArray, theta: NDArray, sin: NDArray, cos: NDArray,
                                   r_cos: NDArray, r_rolling: NDArray,
                                   max_spin_to_roll: ArrayLike) -> tuple[NDArray, NDArray]:
    """:func:`_window_from` with r·cosθ and r(1 + sinθ + cosθ) computed once by the caller."""
    rho_max = np.asarray(max_spin_to_roll, dtype=float)
    sin_plus_cos = sin + cos

    def edge(rho: NDArray) -> NDArray:
        with np.errstate(divide="ignore", invalid="ignore"):
            k = (rho * sin_plus_cos + cos - sin) / (sin - rho * cos)
            return r_cos + r_rolling / k

    # K must be positive for a real edge; otherwise the edge is out of reach. With
    # 0 < θ < π/4 that is ρ_max < tanθ for the lower edge and ρ_max < tan(π/4 − θ) for
    # the upper, compared here as the signs of K's numerator and denominator are.
    low_reachable = rho_max * cos < sin
    high_reachable = rho_max * sin_plus_cos < cos - sin
    # The usual study has every edge in reach: no selection pass is needed then.
    b_min = edge(rho_max)
    if not low_reachable.all():
        b_min = np.where(low_reachable, b_min, r_cos)
    b_max = edge(-rho_max)
    if not high_reachable.all():
        b_max = np.where(high_reachable, b_max, np.inf)
    # An impossible geometry (θ NaN) has no window: NaN, not the unbounded edge.
    if np.isnan(theta).any() or np.isnan(r).any():
        b_max = np.where(np.isnan(theta) | np.isnan(r), np.nan, b_max)
    return b_min, b_max


def complete_geometry(ball_radius: ArrayLike | None, contact_angle: ArrayLike | None,
                      pitch_radius: ArrayLike | None) -> tuple[NDArray, NDArray, NDArray]:
    """(r, θ, b) with the one missing value solved for pure rolling. [m, rad, m]"""
    missing = [ball_radius is None, contact_angle is None, pitch_radius is None]
    if sum(missing) > 1:
        raise ValueError("at most one of ball_radius, contact_angle and pitch_radius may be None")
    if ball_radius is None:
        ball_radius = pure_rolling_ball_radius(contact_angle, pitch_radius)  # type: ignore[arg-type]
    elif contact_angle is None:
        contact_angle = pure_rolling_contact_angle(ball_radius, pitch_radius)  # type: ignore[arg-type]
    elif pitch_radius is None:
        pitch_radius = pure_rolling_pitch_radius(ball_radius, contact_angle)
    return (np.asarray(ball_radius, dtype=float), np.asarray(contact_angle, dtype=float),
            np.asarray(pitch_radius, dtype=float))


def _angle_in_range(contact_angle: ArrayLike) -> NDArray:
    theta = np.asarray(contact_angle, dtype=float)
    return np.where((theta > 0) & (theta < np.pi / 4), theta, np.nan)


def geometry_possible(r: NDArray, theta: NDArray, b: NDArray, cos: NDArray | None = None
                      ) -> NDArray:
    """Where r > 0, b > 0, 0 < θ < π/4 and d = b − r·cosθ > 0; ``cos`` is cosθ when the
    caller has it."""
    with np.errstate(invalid="ignore"):
        if cos is None:
            cos = np.cos(theta)
        return (r > 0) & (b > 0) & (theta > 0) & (theta < np.pi / 4) & (b - r * cos > 0)
