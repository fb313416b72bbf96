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

#: The Python API (:mod:`bearingcalc.api`), loaded on first use so that the command
#: line's start pays nothing for it.
_API = ("solve", "tolerance", "sweep", "Result", "Study", "Sweep", "SpecError",
        "ArgumentError", "Problem")


def __getattr__(name: str) -> object:
    if name in _API:
        from bearingcalc import api

        return getattr(api, name)
    raise AttributeError(f"module 'bearingcalc' has no attribute {name!r}")

__all__ = [
    "ArgumentError",
    "Problem",
    "Result",
    "SpecError",
    "Study",
    "Sweep",
    "pitch_radius_window",
    "pure_rolling_ball_radius",
    "pure_rolling_contact_angle",
    "pure_rolling_pitch_radius",
    "solve",
    "solve_thrust_bearing",
    "spin_to_roll_ratio",
    "sweep",
    "tolerance",
]
