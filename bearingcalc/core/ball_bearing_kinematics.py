"""Ball-bearing kinematics: the cage speed, the defect frequencies and the spin of the
balls under race control (``docs/physics.md`` §7).

Every function takes SI values as floats or numpy arrays, which broadcast, and returns
arrays.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def ball_kinematics(ball_count: ArrayLike, ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
                    contact_angle: ArrayLike, inner_speed: ArrayLike, outer_speed: ArrayLike,
                    race_control: str = "outer", thrust: bool = False) -> dict[str, NDArray]:
    r"""Defect frequencies, cage and ball speeds and the spin of a ball bearing.

    Rolling without slip at both contact centres (both at the angle α, no centrifugal
    shift) fixes the cage: with γ = Dw·cosα/Dpw and ring speeds f_i, f_o,

    .. math:: f_c = \tfrac12[f_i(1 - \gamma) + f_o(1 + \gamma)], \quad
              BPFO = Z|f_c - f_o|, \quad BPFI = Z|f_i - f_c|, \quad
              BSF = \frac{D_{pw}}{2D_w}(1 - \gamma^2)|f_i - f_o|

    Race control (Jones): in the cage frame the ball turns in the meridian plane, and
    at the controlling race it does not spin. With R = Dpw/2, r = Dw/2, e_x the bearing
    axis, e_r from the axis to the ball centre and ω'_j the rings' speeds in the cage
    frame, the ball's angular velocity relative to the cage is

    .. math:: \omega_b = \omega'_o\left[\left(1 + \tfrac{R}{r}\cos\alpha\right)e_x
              - \tfrac{R}{r}\sin\alpha\, e_r\right] \ \text{(outer control)}, \quad
              \omega'_i\left[\left(1 - \tfrac{R}{r}\cos\alpha\right)e_x
              + \tfrac{R}{r}\sin\alpha\, e_r\right] \ \text{(inner control)}

    so the attitude β (ω_b ∥ cosβ·e_x − sinβ·e_r) has tanβ = sinα/(cosα ± r/R), as in
    Harris. At each race the race relative to the ball turns at ω'_j·e_x − ω_b: spin
    is its component along the contact normal (from the ball centre to the contact,
    ±(cosα·e_r + sinα·e_x)) and roll its component along t = cosα·e_x − sinα·e_r.

    Parameters
    ----------
    ball_count : Z. [1]
    ball_diameter, pitch_diameter : Dw, Dpw. [m]
    contact_angle : α (π/2 for a thrust bearing). [rad]
    inner_speed, outer_speed : ring speeds in the fixed frame. [rad/s]
    race_control : "outer" or "inner".
    thrust : a thrust bearing (γ = 0: cos α taken as 0).

    Source: Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
    ch. 8 (kinematics, race control); docs/physics.md §7.

    >>> k = ball_kinematics(9, 0.3126, 1.537, 0.0, 2 * np.pi, 0.0)
    >>> [round(float(k[key]), 4) for key in ("ball_pass_frequency_inner",
    ...  "ball_pass_frequency_outer", "cage_frequency")]
    [5.4152, 3.5848, 0.3983]
    """
    z = np.asarray(ball_count, dtype=float)
    big_r = 0.5 * np.asarray(pitch_diameter, dtype=float)
    r = 0.5 * np.asarray(ball_diameter, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    cos_alpha = np.zeros_like(alpha) if thrust else np.cos(alpha)
    sin_alpha = np.ones_like(alpha) if thrust else np.sin(alpha)
    gamma = r * cos_alpha / big_r
    w_i, w_o = np.asarray(inner_speed, dtype=float), np.asarray(outer_speed, dtype=float)
    cage = 0.5 * (w_i * (1.0 - gamma) + w_o * (1.0 + gamma))
    rel_i, rel_o = w_i - cage, w_o - cage
    ratio = big_r / r
    if race_control == "inner":
        ball_x, ball_r = rel_i * (1.0 - ratio * cos_alpha), rel_i * ratio * sin_alpha
    else:
        ball_x, ball_r = rel_o * (1.0 + ratio * cos_alpha), -rel_o * ratio * sin_alpha
    normal_x, normal_r = sin_alpha, cos_alpha      # n, toward the outer contact
    tangent_x, tangent_r = cos_alpha, -sin_alpha   # t

    def spin_to_roll(ring: NDArray, side: float) -> NDArray:
        rel_x, rel_r = ring - ball_x, -ball_r
        spin = side * (rel_x * normal_x + rel_r * normal_r)
        roll = rel_x * tangent_x + rel_r * tangent_r
        return spin / roll

    hz = 1.0 / (2.0 * np.pi)
    # The axis line's angle in (−90°, 90°]: an axis has no sense of its own.
    attitude = np.arctan2(-ball_r, ball_x)
    attitude = np.where(attitude > np.pi / 2, attitude - np.pi,
                        np.where(attitude <= -np.pi / 2, attitude + np.pi, attitude))
    return {
        "cage_frequency": cage * hz,
        "ball_pass_frequency_outer": z * np.abs(cage - w_o) * hz,
        "ball_pass_frequency_inner": z * np.abs(w_i - cage) * hz,
        "ball_spin_frequency": ratio * (1.0 - gamma ** 2) * np.abs(w_i - w_o) * hz / 2.0,
        "cage_speed": cage,
        "ball_speed_relative_to_cage": np.hypot(ball_x, ball_r),
        "ball_attitude_angle": attitude,
        # The controlling race does not spin by construction: exactly 0, not rounding dust.
        "inner_spin_to_roll": spin_to_roll(rel_i, -1.0) * (race_control != "inner"),
        "outer_spin_to_roll": spin_to_roll(rel_o, 1.0) * (race_control == "inner"),
    }
