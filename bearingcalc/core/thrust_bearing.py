"""Thrust bearing with pure rolling at the shaft contact.

Source: H. Jackman, *Rolling constraints* (Karlstad University course note), "Thrust bearing
example"; re-derived in ``docs/physics.md`` §1.

Geometry, in the meridian plane of one ball: ``e2`` along the shaft axis, ``e1``
radial toward the axis, ``e3 = e1 × e2``. Ball radius r, ball centre G at pitch
radius b. The ball touches the fixed race at C1 = G − r·e1 and C2 = G − r·e2 and
the shaft at C3 = G + r(cosθ·e1 + sinθ·e2), θ being the shaft contact angle.

Every function takes SI values (m, rad, rad/s) as floats or numpy arrays, which
broadcast against each other, and returns numpy arrays. NaN passes through;
geometrically impossible points give NaN (see :func:`thrust_bearing_status` for
the reason).

The pure-rolling geometry is in :mod:`bearingcalc.core.thrust_bearing_geometry` and the
loads and Hertz pressures of a ball in :mod:`bearingcalc.core.thrust_bearing_contacts`;
this module gives every speed, the status of each design and the registry's entry point.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.common import (
    STATUS_DTYPE,
    DerivedTest,
    balls_fit,
    broadcast_all,
    first_failure,
)
from bearingcalc.core.solver import Solution, Solver
from bearingcalc.core.thrust_bearing_contacts import ball_contact_loads
from bearingcalc.core.thrust_bearing_geometry import (
    complete_geometry,
    geometry_possible,
    pitch_radius_window,
    pitch_radius_window_from_terms,
    pure_rolling_ball_radius,
    pure_rolling_contact_angle,
    pure_rolling_pitch_radius,
    spin_to_roll_from,
    spin_to_roll_from_terms,
    spin_to_roll_ratio,
)

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import ThrustBearingInputs

#: What the package and the registry read from this module, the geometry's functions
#: among them.
__all__ = [
    "ball_contact_loads",
    "complete_geometry",
    "evaluate",
    "pitch_radius_window",
    "pure_rolling_ball_radius",
    "pure_rolling_contact_angle",
    "pure_rolling_pitch_radius",
    "solve_thrust_bearing",
    "spin_to_roll_ratio",
    "thrust_bearing_status",
]

HALF_SQRT2 = np.sqrt(0.5)

#: Result keys, their SI unit and meaning, in report order.
RESULTS: dict[str, tuple[str, str]] = {
    "ball_radius": ("m", "ball radius r"),
    "contact_angle": ("rad", "shaft contact angle θ"),
    "pitch_radius": ("m", "pitch radius b as used"),
    "pitch_radius_pure_rolling": ("m", "pure-rolling pitch radius b*"),
    "pitch_radius_deviation": ("m", "b − b*"),
    "shaft_contact_radius": ("m", "shaft contact radius d = b − r·cosθ"),
    "shaft_speed": ("rad/s", "shaft speed ω_S"),
    "ball_speed": ("rad/s", "ball angular speed ω_B in the fixed frame"),
    "cage_speed": ("rad/s", "orbital speed of the ball set"),
    "ball_center_speed": ("m/s", "ball centre speed v_G"),
    "shaft_contact_speed": ("m/s", "shaft surface speed at the contact, d·ω_S"),
    "spin_speed": ("rad/s", "shaft-relative-to-ball spin about the contact normal"),
    "roll_speed": ("rad/s", "shaft-relative-to-ball rolling about the contact tangent"),
    "spin_to_roll": ("1", "spin_speed / roll_speed"),
    "slip_margin": ("1", "max_spin_to_roll − |spin_to_roll|"),
    "pitch_radius_min": ("m", "smallest b with |spin/roll| within the limit"),
    "pitch_radius_max": ("m", "largest b with |spin/roll| within the limit"),
    "ball_pass_frequency_race": ("Hz", "balls passing a point of the race"),
    "ball_pass_frequency_shaft": ("Hz", "balls passing a point of the shaft"),
    "shaft_contact_load": ("N", "Q3, the shaft's normal force on a ball at C3"),
    "race_radial_contact_load": ("N", "Q1, the race wall's normal force at C1"),
    "race_axial_contact_load": ("N", "Q2, the race floor's normal force at C2"),
    "ball_centrifugal_force": ("N", "m·b·ω_cage² of one ball"),
    "shaft_contact_pressure": ("Pa", "Hertz peak pressure at C3 (ball on the cone)"),
    "race_radial_contact_pressure": ("Pa", "Hertz peak pressure at C1 (ball on the bore)"),
    "race_axial_contact_pressure": ("Pa", "Hertz peak pressure at C2 (ball on the floor)"),
    "max_contact_pressure": ("Pa", "the largest of the three"),
    "contact_pressure_margin": ("1", "1 − max_contact_pressure / limit"),
}

#: Status codes of :func:`thrust_bearing_status`: code -> (field at fault, reason).
FEASIBLE = 0
STATUS_REASONS: dict[int, tuple[str, str]] = {
    1: ("ball_radius", "the ball radius must be positive"),
    2: ("pitch_radius", "the pitch radius must be positive"),
    3: ("contact_angle", "pure rolling needs 0 deg < θ < 45 deg"),
    4: ("pitch_radius", "the shaft contact radius d = b − r·cosθ must be positive"),
    5: ("ball_count", DerivedTest("the balls do not fit on the pitch circle: Z·asin(r/b) "
                                  "must be <= π")),
    6: ("pitch_radius", "a pure-rolling contact angle exists only for b > r"),
    7: ("axial_load", "a ball's contact ellipse is not small against the ball (its "
                      "semi-major axis exceeds the ball radius), so Hertz theory does not hold: "
                      "lower the axial load, or use more or larger balls"),
}
#: The status of a design whose contact ellipse is too large for Hertz theory.
CONTACT_TOO_LARGE = 7


def thrust_bearing_status(ball_radius: ArrayLike, contact_angle: ArrayLike,
                          pitch_radius: ArrayLike, ball_count: ArrayLike | None = None,
                          cos: NDArray | None = None) -> NDArray:
    """Feasibility code of each design: 0 when feasible, else a key of ``STATUS_REASONS``.

    Checks, in order: r > 0, b > 0, 0 < θ < π/4, d = b − r·cosθ > 0 and, with a ball
    count Z, Z·asin(r/b) <= π (the balls fit on the pitch circle). NaN inputs fail
    the first check they take part in. ``cos`` is cosθ when the caller has it.
    """
    r = np.asarray(ball_radius, dtype=float)
    theta = np.asarray(contact_angle, dtype=float)
    b = np.asarray(pitch_radius, dtype=float)
    if cos is None:
        cos = np.cos(theta)
    shape = np.broadcast_shapes(r.shape, theta.shape, b.shape,
                                np.shape(ball_count) if ball_count is not None else ())
    with np.errstate(invalid="ignore"):
        # θ before b: a b solved from an impossible θ is NaN, and θ is then the fault.
        checks = [
            (1, ~(r > 0)),
            (3, ~((theta > 0) & (theta < np.pi / 4))),
            (2, ~(b > 0)),
            (4, ~(b - r * cos > 0)),
        ]
        if ball_count is not None:
            z = np.asarray(ball_count, dtype=float)
            fits = balls_fit(z, r / b)
            # A single ball always fits; two or more need b >= r.
            checks.append((5, ~(fits & ((z <= 1) | (b >= r)))))
    return first_failure(checks, shape)


def solve_thrust_bearing(ball_radius: ArrayLike | None, contact_angle: ArrayLike | None,
                         pitch_radius: ArrayLike | None, shaft_speed: ArrayLike, *,
                         ball_count: ArrayLike | None = None,
                         max_spin_to_roll: ArrayLike = 0.01) -> dict[str, NDArray]:
    r"""Every speed of a thrust bearing driven by its shaft, and its slip figures.

    At most one of ``ball_radius``, ``contact_angle`` and ``pitch_radius`` may be
    None; it is then solved so that the shaft contact rolls purely.

    Kinematics (docs/physics.md §1): the ball turns about the line C1C2 at ω_B,

    .. math:: \omega_S = \frac{\sqrt2}{2}\,\frac{r(1 + \sin\theta + \cos\theta)}
                                          {b - r\cos\theta}\,\omega_B,
              \quad v_G = \frac{\sqrt2}{2} r\omega_B,
              \quad \omega_{cage} = v_G / b

    and the shaft relative to the ball turns at
    ω_rel = ω_S·e2 − ω_B(√2/2)(e1 − e2), whose component along the contact normal
    n = cosθ·e1 + sinθ·e2 is the spin and along t = −sinθ·e1 + cosθ·e2 the roll.

    Parameters
    ----------
    ball_radius : r, or None to solve it. [m]
    contact_angle : θ, or None to solve it. [rad]
    pitch_radius : b, or None to solve it. [m]
    shaft_speed : ω_S, signed about e2. [rad/s]
    ball_count : Z, optional; adds the ball-pass frequencies. [1]
    max_spin_to_roll : ρ_max, the limit on |spin/roll|. [1]

    Returns
    -------
    dict of arrays keyed as :data:`RESULTS`; NaN where the design is impossible.

    Raises
    ------
    ValueError : when more than one of r, θ, b is None.

    Examples
    --------
    >>> out = solve_thrust_bearing(1.0, np.radians(20.0), None, 1.0)
    >>> round(float(out["pitch_radius"]), 5), round(float(out["spin_to_roll"]), 12)
    (2.24541, 0.0)
    """
    solved = ball_radius is None or contact_angle is None or pitch_radius is None
    r, theta, b = complete_geometry(ball_radius, contact_angle, pitch_radius)
    return _solve(r, theta, b, shaft_speed, ball_count, max_spin_to_roll, solved)


def _solve(r: NDArray, theta: NDArray, b: NDArray, shaft_speed: ArrayLike,
           ball_count: ArrayLike | None, max_spin_to_roll: ArrayLike,
           solved: bool, ok: NDArray | None = None, cos: NDArray | None = None
           ) -> dict[str, NDArray]:
    """:func:`solve_thrust_bearing` on a complete geometry; ``solved`` says that one of
    r, θ, b was solved for pure rolling, so spin is zero by construction. ``ok`` (where
    the geometry is possible) and ``cos`` (cosθ) may come from the caller's checks."""
    omega_s = np.asarray(shaft_speed, dtype=float)
    rho_max = np.asarray(max_spin_to_roll, dtype=float)
    r, theta, b, cos, ok, all_ok = _possible_geometry(r, theta, b, ok, cos)
    # Each shared term is computed once, in the order of operations the formulas
    # below were always evaluated in, so the numbers do not change.
    sin = np.sin(theta)
    r_cos = r * cos
    d = b - r_cos
    one_plus_sin = 1.0 + sin
    rolling_factor = one_plus_sin + cos           # 1 + sinθ + cosθ
    r_rolling = r * rolling_factor
    omega_b = omega_s * d / (HALF_SQRT2 * r * rolling_factor)
    v_g = HALF_SQRT2 * r * omega_b
    cage = v_g / b
    # ω_rel = −(√2/2)ω_B·e1 + (ω_S + (√2/2)ω_B)·e2, projected on n and t.
    rel_1 = -HALF_SQRT2 * omega_b
    rel_2 = omega_s + HALF_SQRT2 * omega_b
    spin = rel_1 * cos + rel_2 * sin
    roll = -rel_1 * sin + rel_2 * cos
    # ρ is a property of the geometry alone; computing it from K keeps it finite
    # (and exact) when the shaft is at rest and spin and roll are both zero.
    rho = spin_to_roll_from_terms(r_rolling, d, sin, cos)
    if solved:
        # Pure rolling by construction: the formulas would leave rounding dust of
        # order 1e-17, which a limit of exactly 0 must not see.
        spin, rho = spin * 0.0, rho * 0.0
    b_star = r * one_plus_sin / (cos - sin)
    b_min, b_max = pitch_radius_window_from_terms(r, theta, sin, cos, r_cos, r_rolling, rho_max)

    results = {
        "ball_radius": r,
        "contact_angle": theta,
        "pitch_radius": b,
        "pitch_radius_pure_rolling": b_star,
        "pitch_radius_deviation": b - b_star,
        "shaft_contact_radius": d,
        "shaft_speed": omega_s if all_ok else omega_s * np.where(ok, 1.0, np.nan),
        "ball_speed": omega_b,
        "cage_speed": cage,
        "ball_center_speed": v_g,
        "shaft_contact_speed": d * omega_s,
        "spin_speed": spin,
        "roll_speed": roll,
        "spin_to_roll": rho,
        "slip_margin": rho_max - np.abs(rho),
        "pitch_radius_min": b_min,
        "pitch_radius_max": b_max,
    }
    if ball_count is not None:
        z = np.asarray(ball_count, dtype=float)
        results["ball_pass_frequency_race"] = z * np.abs(cage) / (2 * np.pi)
        results["ball_pass_frequency_shaft"] = z * np.abs(omega_s - cage) / (2 * np.pi)
    return broadcast_all(results)


def _possible_geometry(r: NDArray, theta: NDArray, b: NDArray, ok: NDArray | None,
                       cos: NDArray | None
                       ) -> tuple[NDArray, NDArray, NDArray, NDArray, NDArray, bool]:
    """r, θ, b and cosθ with NaN where the geometry is impossible, where it is possible
    (``ok`` and ``cos`` computed unless given), and whether it is everywhere."""
    if cos is None:
        cos = np.cos(theta)
    if ok is None:
        ok = geometry_possible(r, theta, b, cos)
    all_ok = bool(np.all(ok))
    if not all_ok:
        # NaN where impossible: cos(NaN) is NaN, so masking cosθ equals taking the
        # cosine of the masked θ, bit for bit.
        r, theta, b, cos = (np.where(ok, x, np.nan) for x in (r, theta, b, cos))
    return r, theta, b, cos, ok, all_ok


#: Results that :func:`evaluate` can compute alone, without every speed.
_RATIO_ONLY = frozenset({"spin_to_roll", "slip_margin"})


def evaluate(inputs: ThrustBearingInputs,
             wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: results and status codes from the spec's SI inputs.

    ``inputs`` holds ball_radius, contact_angle, pitch_radius (one may be None),
    shaft_speed, ball_count (may be None) and max_spin_to_roll. When ``wanted``
    names only spin_to_roll and slip_margin, only those are computed: the hot
    path of Monte Carlo studies of the slip limit.
    """
    r, theta, b = complete_geometry(inputs["ball_radius"], inputs["contact_angle"],
                                    inputs["pitch_radius"])
    cos = np.cos(theta)
    status = thrust_bearing_status(r, theta, b, inputs.get("ball_count"), cos)
    if inputs["pitch_radius"] is not None and inputs["contact_angle"] is None:
        # θ came out NaN because no pure-rolling angle exists: say why.
        status = np.where((status == 3) & ~(b > r), STATUS_DTYPE(6), status)
    solved = any(inputs[key] is None for key in ("ball_radius", "contact_angle", "pitch_radius"))
    if wanted is not None and set(wanted) <= _RATIO_ONLY:
        rho = spin_to_roll_from(r, b, np.sin(theta), cos)
        feasible = status == FEASIBLE
        if not feasible.all():
            rho = np.where(feasible, rho, np.nan)
        if solved:
            rho = rho * 0.0
        margin = np.asarray(inputs.get("max_spin_to_roll", 0.01), dtype=float) - np.abs(rho)
        return Solution({"spin_to_roll": rho, "slip_margin": margin}, status)
    # Checks 1 to 4 of the status are the geometry's; 5 (the balls' fit) is not.
    geometry_ok = (status == FEASIBLE) | (status == 5)
    results = _solve(r, theta, b, inputs["shaft_speed"], inputs.get("ball_count"),
                     inputs.get("max_spin_to_roll", 0.01), solved, geometry_ok, cos)
    if inputs.get("axial_load") is not None:
        results.update(ball_contact_loads(
            r, theta, b, results["cage_speed"], inputs["ball_count"], inputs["axial_load"],
            inputs["elastic_modulus"], inputs["poisson_ratio"], inputs["density"],
            inputs["max_contact_pressure"]))
        largest = results.pop("_largest_semi_major")
        status = np.where((status == FEASIBLE) & ~(largest <= r), STATUS_DTYPE(CONTACT_TOO_LARGE),
                          status)
        results = broadcast_all(results)
    return Solution(results, status)


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, inputs="ThrustBearingInputs")
