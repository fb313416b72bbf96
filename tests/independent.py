"""Independent computations the solvers are tested against.

Nothing here imports bearingcalc: each system is set up as bodies in 3-D and
its rolling constraints are solved numerically, as physics.md "How to verify"
describes, so a slip in a closed form cannot hide behind the same slip here.
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
