"""bearingcalc: rolling-contact machine design, from YAML specs to every speed.

The solvers are plain numpy functions on SI values and accept arrays::

    >>> import numpy as np
    >>> from bearingcalc import solve_thrust_bearing
    >>> out = solve_thrust_bearing(0.00635, np.radians(20), None, 157.08)
    >>> round(float(out["pitch_radius"]) * 1e3, 4)  # mm
    14.2584
"""

from bearingcalc.core.thrust_bearing import (
    pitch_radius_window,
    pure_rolling_ball_radius,
    pure_rolling_contact_angle,
    pure_rolling_pitch_radius,
    solve_thrust_bearing,
    spin_to_roll_ratio,
)

__version__ = "0.1.0"

__all__ = [
    "pitch_radius_window",
    "pure_rolling_ball_radius",
    "pure_rolling_contact_angle",
    "pure_rolling_pitch_radius",
    "solve_thrust_bearing",
    "spin_to_roll_ratio",
]
