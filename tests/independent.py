"""Independent computations the solvers are tested against.

Nothing here imports bearingcalc: each system is set up as bodies in 3-D and
its rolling constraints are solved numerically, as docs/physics.md ("How the tests
check these relations") describes, so a slip in a closed form cannot hide behind the same slip here.
"""

from __future__ import annotations

import numpy as np


def skew(v: np.ndarray) -> np.ndarray:
    """Matrix S(v) with S(v) @ w == np.cross(v, w)."""
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def thrust_bearing_3d(r: float, theta: float, b: float, shaft_speed: float) -> dict[str, float]:
    """Ball velocities of a thrust bearing from the no-slip conditions at its three contacts.

    Frame: axis through the origin along e2 = (0, 1, 0); the ball centre G lies at
    (−b, 0, 0), so e1 = (1, 0, 0) points from G toward the axis and e3 = e1 × e2.
    Unknowns: the ball's angular velocity w and centre velocity v (6 numbers).
    Conditions: the ball's material points at C1 and C2 are at rest; at C3 the
    ball point moves with the shaft point, whose velocity is ω_S e2 × C3. That
    is nine linear equations of rank six, solved by least squares (the residual
    is returned so a test can check that the constraints are consistent).
    """
    e1, e2 = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    g = -b * e1
    contacts = {
        "C1": g - r * e1,
        "C2": g - r * e2,
        "C3": g + r * (np.cos(theta) * e1 + np.sin(theta) * e2),
    }
    rows, rhs = [], []
    for name, point in contacts.items():
        # v + w × (P − G) = target  <=>  [I, −S(P − G)] @ [v, w] = target
        rows.append(np.hstack([np.eye(3), -skew(point - g)]))
        target = np.cross(shaft_speed * e2, point) if name == "C3" else np.zeros(3)
        rhs.append(target)
    a, y = np.vstack(rows), np.concatenate(rhs)
    solution, *_ = np.linalg.lstsq(a, y, rcond=None)
    v, w = solution[:3], solution[3:]
    residual = float(np.linalg.norm(a @ solution - y))
    rel = shaft_speed * e2 - w
    normal = np.cos(theta) * e1 + np.sin(theta) * e2
    tangent = -np.sin(theta) * e1 + np.cos(theta) * e2
    e3 = np.cross(e1, e2)
    c3 = contacts["C3"]
    return {
        "ball_speed": float(w @ (e1 - e2) / np.sqrt(2.0)),
        "ball_angular_velocity": w,
        "ball_center_speed": float(v @ e3),
        # Orbital speed about the axis: G is at distance b, moving along e3.
        "cage_speed": float(v @ e3 / b),
        "shaft_contact_speed": float(np.cross(shaft_speed * e2, c3) @ e3),
        "shaft_contact_radius": float(np.hypot(c3[0], c3[2])),
        "spin_speed": float(rel @ normal),
        "roll_speed": float(rel @ tangent),
        "rel_e3": float(rel @ e3),
        "residual": residual,
    }


def bevel_pair_3d(a: float, b: float, shaft_angle: float, arm_speed: float,
                  gear_b_speed: float) -> dict[str, float]:
    """An epicyclic bevel pair placed in 3-D and solved for no slip at the pitch point.

    The pitch angles come from a root find of the common-apex condition
    a/sinα = b/sin(γ − α) (scipy.optimize.brentq), not from the tangent formula.
    Gear B's axis is k = z through the apex O; the contact line makes β with k;
    gear A's axis n3 lies in the same plane at γ from k (so k·n3 = cosγ). The
    unknown spin w of A on the arm solves (ω_Z k + w n3) × C = Ω k × C by least
    squares.
    """
    from scipy.optimize import brentq

    alpha = brentq(lambda x: a * np.sin(shaft_angle - x) - b * np.sin(x), 1e-12,
                   shaft_angle - 1e-12, xtol=1e-15, rtol=1e-15)
    beta = shaft_angle - alpha
    cone_distance = b / np.sin(beta)
    k = np.array([0.0, 0.0, 1.0])
    contact = cone_distance * np.array([np.sin(beta), 0.0, np.cos(beta)])
    n3 = np.array([np.sin(shaft_angle), 0.0, np.cos(shaft_angle)])
    lhs = np.cross(n3, contact)[:, None]
    rhs = np.cross(gear_b_speed * k, contact) - np.cross(arm_speed * k, contact)
    (w,), *_ = np.linalg.lstsq(lhs, rhs, rcond=None)
    omega_a = arm_speed * k + w * n3
    return {
        "gear_a_pitch_angle": alpha,
        "gear_b_pitch_angle": beta,
        "cone_distance": float(np.linalg.norm(contact)),
        "distance_from_a_axis": float(np.linalg.norm(np.cross(n3, contact))),
        "gear_a_speed_relative_to_arm": float(w),
        "gear_a_speed": float(np.linalg.norm(omega_a)),
        "relative_speed": float(np.linalg.norm(omega_a - gear_b_speed * k)),
        "contact_point_speed": float(np.linalg.norm(np.cross(gear_b_speed * k, contact))),
        "pitch_line_speed": float(np.linalg.norm(np.cross(w * n3, contact))),
        "residual": float(np.linalg.norm(lhs[:, 0] * w - rhs)),
    }
