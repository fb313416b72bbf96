"""A rigid shaft on N ISO/TS 16281 bearings: a slow, scalar reference.

What this is
------------
An independent reference for a rigid shaft that carries the inner rings of N bearings
whose outer rings are fixed. Each bearing's contacts are those of the single-bearing
reference ``tests/iso16281_reference.py`` (``ball_state``, ``roller_state``: ISO/TS
16281:2008 eqs. 12, 16-18 for balls and 38-41, 45-46 for roller laminae); what is added
here is the rigid-body map from the shaft to each ring (ISO/TS 16281:2008 4.2 and 5.2
give one bearing's internal load distribution; a shaft on several is the "general load"
it refers to other methods for), the mirror of a bearing mounted the other way round,
the axial offsets of a matched pair's end play, the shaft's equilibrium
(``scipy.optimize.root`` on a residual written here) and its stiffness by central
differences. It imports nothing of bearingcalc. Units: SI (m, rad, N, N·m).

Coordinates (those of iso16281_reference, derived from its kinematics)
----------------------------------------------------------------------
A bearing's q = (δx, δy, δz, θy, θz) [m, m, m, rad, rad] is the inner ring's displacement
at the bearing's origin (the centre plane for balls and cylindrical rollers, the pressure
centre for tapered rollers) relative to the fixed outer ring. Its kinematics say a tilt
moves a ring point at azimuth ψ, radius r, axial position ξ (from the origin) by
    axially   r·(θz cos ψ + θy sin ψ),    radially   −ξ·(θz cos ψ + θy sin ψ)
(ball_kinematics' s_x; roller_state's −ℓ_k(θz cos ψ + θy sin ψ)). A small rigid rotation
ω moves the point p = (ξ, r cos ψ, r sin ψ) by ω × p, whose axial part is
r(ωy sin ψ − ωz cos ψ) and whose radial part is ξ(ωz cos ψ − ωy sin ψ); both match with
    θy = ωy,   θz = −ωz,
i.e. θy is the right-handed rotation about +y and θz the left-handed one about +z (so
that a positive θz pushes the element at ψ = 0, on +y, toward +x). The forces
F = (Fx, Fy, Fz, My, Mz) are work-conjugate to q: My is the moment about +y, Mz minus the
moment about +z.

The shaft's map T_i (translation of the ring at x_i)
----------------------------------------------------
The shaft's displacement Q = (δx, δy, δz, θy, θz) is taken at x = 0. A rigid shaft point
on the axis at x_i moves by u(x_i) = u(0) + ω × (x_i, 0, 0) = u(0) + (0, ωz·x_i, −ωy·x_i),
i.e. (θz = −ωz, θy = ωy)
    δx_i = δx,  δy_i = δy − x_i·θz,  δz_i = δz − x_i·θy,  θy_i = θy,  θz_i = θz,
the same −ξ·θ the single bearing's laminae use. As a matrix, q_i = T_i·Q with
    T_i = [[1, 0, 0, 0, 0], [0, 1, 0, 0, −x_i], [0, 0, 1, −x_i, 0], [0, 0, 0, 1, 0],
           [0, 0, 0, 0, 1]].

The mirror S_i (a bearing mounted the other way round)
------------------------------------------------------
Orientation s_i = −1 reflects the bearing in the plane x = x_i: its own axis points along
−x, y and z unchanged (so its element at azimuth 0 stays on +y and ψ is unchanged). Its
own axial coordinate is ξ' = −ξ and its own axial displacement −δx. Putting the reflected
fields into the tilt's definition: the axial motion r(θz' cos ψ + θy' sin ψ) must equal
−r(θz cos ψ + θy sin ψ), so θ' = −θ, and the radial motion −ξ'·θ' = −ξ·θ agrees. Hence
    S_i = diag(1, 1, 1, 1, 1) for s_i = +1,   S_i = diag(−1, 1, 1, −1, −1) for s_i = −1,
the same on forces (f' = S·f: the thrust and both moments change sign, the radial forces
do not), and S_i = S_iᵀ = S_i⁻¹.

A bearing's own displacement, with the axial offset o_i [m] added to its own δx, is
    q_i = S_i·T_i·Q + o_i·e_x,
so a pair with end play e has o_i = −e/2 on each bearing: at Q = 0 each one-sided
bearing stands e/2 short of its axial datum, first contact (e < 0: preload by
interference; for a profiled tapered bearing see the closed forms below).

Equilibrium and stiffness
-------------------------
By virtual work (δW = Σ f_i·δq_i = Σ (S_i T_i)ᵀ f_i · δQ) the shaft's internal force is
    F_int(Q) = Σ_i T_iᵀ·S_i·f_i(q_i),
    T_iᵀ f = (fx, fy, fz, My − x_i·fz, Mz − x_i·fy),
the last two the moments about x = 0 of the ring's radial forces (in the θ convention
above: the moment about +y of fz at x_i is −x_i·fz; minus the moment about +z of fy is
−x_i·fy). Equilibrium is F_int(Q) = F, the applied loads at x = 0 (ISO/TS 16281 eqs.
16-18, 45-46 for each ring, summed). The tangent stiffness ∂F_int/∂Q equals
Σ (S_i T_i)ᵀ·K_i·(S_i T_i) (the parallel-axis sum of the rings' own stiffness K_i); here
it is taken by central differences of F_int so that the sum can check it.

Closed forms for a pure axial displacement
------------------------------------------
Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., Part 1, ch. 7, eq. 7.33 (numbered as
tests/test_iso16281_reference.py cites it) for an angular-contact ball bearing; ISO/TS
16281:2008 5.2, eqs. 38-41 (laminae) for a tapered roller bearing; both with the
reference module's constants (exact Hertz K at α0, c_L) and its axial datum. That datum
is first contact for angular-contact balls; for a profiled tapered bearing it is where
the unprofiled line would touch, and its first lamina touches first_contact(bearing) =
min_k(2·p_k)/sin α later (22.6 nm for 30 laminae of Dwe = 7.5 mm, Lwe = 14 mm at 15°).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize

from tests.iso16281_reference import (
    DOF_NAMES,
    BallBearing,
    RollerBearing,
    ball_state,
    roller_state,
)

__all__ = [
    "ShaftBearing", "axial_load", "ball_axial_load", "end_play_for_preload", "first_contact",
    "lift_off_thrust", "matched_pair", "mirror", "origin_for_pressure_centre",
    "preload_from_end_play", "roller_axial_load", "shaft_force", "shaft_stiffness",
    "solve_shaft", "transfer",
]


# --------------------------------------------------------------------------- maps
def transfer(position: float) -> np.ndarray:
    """T(x_i): the shaft's Q at x = 0 to the ring's displacement at x_i [m],
    q = (δx, δy − x_i·θz, δz − x_i·θy, θy, θz) (derivation in the module docstring)."""
    t = np.eye(5)
    t[1, 4] = -position
    t[2, 3] = -position
    return t


def mirror(orientation: int) -> np.ndarray:
    """S: identity for s = +1, diag(−1, 1, 1, −1, −1) for s = −1 (the reflection in the
    bearing's plane; the same matrix maps forces and moments)."""
    if orientation not in (1, -1):
        raise ValueError(f"orientation must be +1 or -1, not {orientation!r}")
    return np.diag([orientation, 1.0, 1.0, orientation, orientation]).astype(float)


@dataclass(frozen=True)
class ShaftBearing:
    """A bearing on the shaft: the reference's BallBearing or RollerBearing, the axial
    position x_i [m] of its origin (centre plane for balls and cylindrical rollers,
    pressure centre for tapered rollers), its orientation s_i (+1: carries thrust when the
    shaft moves +x; −1: mirrored) and the offset o_i [m] added to its own δx."""

    bearing: BallBearing | RollerBearing
    position: float = 0.0
    orientation: int = 1
    offset: float = 0.0

    @property
    def matrix(self) -> np.ndarray:
        """S_i·T_i [1, m]: q_i = S_i·T_i·Q + o_i·e_x."""
        return mirror(self.orientation) @ transfer(self.position)

    def local(self, shaft_q) -> np.ndarray:
        """The bearing's own q_i [m, rad] for the shaft's Q."""
        q = self.matrix @ np.asarray(shaft_q, dtype=float)
        q[0] += self.offset
        return q

    def state(self, shaft_q) -> dict:
        """The reference's ball_state or roller_state at q_i."""
        q = self.local(shaft_q)
        if isinstance(self.bearing, BallBearing):
            return ball_state(self.bearing, q)
        return roller_state(self.bearing, q)


def origin_for_pressure_centre(bearing, pressure_centre: float, orientation: int) -> float:
    """x_i [m] of the bearing's origin whose nominal pressure centre is at ``pressure_centre``.

    Balls: in the reference's kinematics the normal approach of every ball is
    sin α·(δx + (Dpw/2)·θ cos ψ) + cos α·cos ψ·δy; a tilt about the axial point ξ moves the
    origin radially by ξ·θ, and the approach vanishes for ξ = −(Dpw/2)·tan α0: the pressure
    centre lies at ξ = −(Dpw/2)·tan α0 in the bearing's own axis, i.e. at
    x_i − s_i·(Dpw/2)·tan α0 on the shaft; so x_i = x_pc + s_i·(Dpw/2)·tan α0. Deep-groove
    balls (α0 = 0) and rollers: the origin is the pressure centre (tapered: by ISO/TS
    16281's choice of origin in the reference)."""
    if isinstance(bearing, BallBearing):
        angle = bearing.nominal_contact_angle
        return pressure_centre + orientation * bearing.pitch_diameter / 2.0 * math.tan(angle)
    return pressure_centre


def matched_pair(bearing, pressure_centres: tuple[float, float], arrangement: str,
                 end_play: float = 0.0) -> list[ShaftBearing]:
    """Two identical one-sided bearings with end play e [m] (negative: preload), o = −e/2.

    ``arrangement`` "back-to-back" (O, DB: the pressure centres outside the bearings: the
    bearing at the smaller x has s = +1) or "face-to-face" (X, DF: inside, the bearing at
    the smaller x has s = −1). Returned in the order [s = +1, s = −1]: bearing 1 carries
    the thrust of a shaft pushed toward +x.
    """
    low, high = sorted(pressure_centres)
    if arrangement == "back-to-back":
        placed = ((low, 1), (high, -1))
    elif arrangement == "face-to-face":
        placed = ((high, 1), (low, -1))
    else:
        raise ValueError(f"arrangement {arrangement!r}: back-to-back or face-to-face")
    return [ShaftBearing(bearing, origin_for_pressure_centre(bearing, x, s), s, -end_play / 2)
            for x, s in placed]


# --------------------------------------------------------------------------- statics
def shaft_force(bearings, shaft_q) -> np.ndarray:
    """F_int(Q) = Σ_i T_iᵀ·S_i·f_i(S_i·T_i·Q + o_i·e_x) [N, N, N, N·m, N·m]: the force the
    contacts exert on the shaft, reduced to x = 0 (module docstring)."""
    total = np.zeros(5)
    for item in bearings:
        total += item.matrix.T @ item.state(shaft_q)["force"]
    return total


def _lever(bearings) -> float:
    """L [m]: the largest of the bearings' |x_i| and pitch radii, the length that puts
    tilts on the scale of translations and moments on the scale of forces."""
    return max(max(abs(b.position), b.bearing.pitch_diameter / 2.0) for b in bearings)


def shaft_stiffness(bearings, shaft_q, step: float = 1e-9) -> np.ndarray:
    """∂F_int/∂Q [N/m, N/rad, N·m/m, N·m/rad] by central differences, steps of 1 nm in
    translation and 1 nm over L (_lever) in tilt."""
    shaft_q = np.asarray(shaft_q, dtype=float)
    lever = _lever(bearings)
    steps = step * np.array([1.0, 1.0, 1.0, 1.0 / lever, 1.0 / lever])
    k = np.zeros((5, 5))
    for col in range(5):
        dq = np.zeros(5)
        dq[col] = steps[col]
        k[:, col] = (shaft_force(bearings, shaft_q + dq)
                     - shaft_force(bearings, shaft_q - dq)) / (2.0 * steps[col])
    return k


def _starts(forces: np.ndarray, free: np.ndarray, lever: float) -> list[np.ndarray]:
    """Starting points in µm-scaled unknowns: rest, then along the loads at several sizes
    (as iso16281_reference's: half a size of axial shift without thrust to break a
    deep-groove bearing's symmetry, and a start with every element of a one-sided bearing
    in contact under thrust)."""
    direction = forces / np.array([1.0, 1.0, 1.0, lever, lever])
    norm = np.linalg.norm(direction[free])
    unit = direction / norm if norm > 0 else np.zeros(5)
    starts = [np.zeros(int(free.sum()))]
    for size in (10.0, 30.0, 3.0, 100.0, 1.0, 0.3, 0.1):
        g = size * unit
        g[0] += 0.5 * size if forces[0] == 0 else 0.0
        starts.append(g[free])
        if forces[0] != 0:
            g = g.copy()
            g[0] = 3.0 * size * math.copysign(1.0, forces[0])
            starts.append(g[free])
    return starts


def _outcome(bearings, shaft_q, residual: float) -> dict:
    """The solved state: per-bearing q_i, states, loads and axial loads."""
    states = [b.state(shaft_q) for b in bearings]
    return {
        "Q": shaft_q,
        "q": [b.local(shaft_q) for b in bearings],
        "states": states,
        "load": [s["load"] for s in states],
        "lamina_load": [s.get("lamina_load") for s in states],
        "axial_load": np.array([abs(s["force"][0]) for s in states]),
        "bearing_force": [s["force"] for s in states],
        "reaction": shaft_force(bearings, shaft_q),
        "residual": residual,
        "stiffness": shaft_stiffness(bearings, shaft_q),
    }


def solve_shaft(bearings, forces=(0.0, 0.0, 0.0, 0.0, 0.0), imposed=None) -> dict:
    """Shaft equilibrium Σ_i T_iᵀ·S_i·f_i(S_i·T_i·Q + o_i·e_x) = F (ISO/TS 16281:2008 4.2
    eqs. 16-18 and 5.2 eqs. 45-46 per ring, summed over the rings by virtual work).

    bearings: a list of ShaftBearing. forces: (Fx, Fy, Fz, My, Mz) [N, N, N, N·m, N·m]
    applied to the shaft at x = 0. imposed: {dof name: value} held fixed (the names of
    DOF_NAMES); their forces are reactions (in ``reaction``). When every bearing is a
    cylindrical roller bearing x is held at 0. Solved by scipy.optimize.root (hybr) in
    unknowns of 1 µm (tilts: 1 µm over L) and residuals of 1 N (moments over L), divided by
    max(|F|, 1 N), from several starts; the best is kept.

    Returns a dict: ``Q`` [m, rad] the shaft's displacement at x = 0; ``q`` each bearing's
    own displacement; ``states`` each bearing's ball_state/roller_state; ``load`` each
    bearing's element loads [N]; ``lamina_load`` each roller bearing's lamina loads [N]
    (None for balls); ``axial_load`` [N] |f_x| of each bearing along its own axis;
    ``bearing_force`` each bearing's own force vector; ``reaction`` F_int(Q); ``residual``
    the largest scaled residual relative to max(|F|, 1 N); ``stiffness`` the 5×5
    ∂F_int/∂Q by central differences.
    """
    forces = np.asarray(forces, dtype=float)
    imposed = dict(imposed or {})
    if all(isinstance(b.bearing, RollerBearing) and b.bearing.contact_angle == 0.0
           for b in bearings):
        imposed.setdefault("x", 0.0)
    free = np.array([name not in imposed for name in DOF_NAMES])
    lever = _lever(bearings)
    scale = 1e-6 * np.array([1.0, 1.0, 1.0, 1.0 / lever, 1.0 / lever])
    force_scale = np.array([1.0, 1.0, 1.0, 1.0 / lever, 1.0 / lever])
    fixed = np.array([imposed.get(name, 0.0) for name in DOF_NAMES])
    reference = max(np.linalg.norm((forces * force_scale)[free]), 1.0)

    def full(u):
        q = fixed.copy()
        q[free] = u * scale[free]
        return q

    def residual(u):
        return ((shaft_force(bearings, full(u)) - forces) * force_scale)[free] / reference

    best = None
    for start in _starts(forces, free, lever):
        sol = optimize.root(residual, start, method="hybr", options={"xtol": 1e-14})
        err = float(np.max(np.abs(residual(sol.x)), initial=0.0))
        if best is None or err < best[1]:
            best = (sol.x, err)
        if err < 1e-12:
            break
    return _outcome(bearings, full(best[0]), best[1])


# --------------------------------------------------------------------------- closed forms
def ball_axial_load(bearing: BallBearing, delta_a: float) -> float:
    """Fa [N] of an angular-contact ball bearing displaced axially by δa [m] from first
    contact (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., Part 1, ch. 7, eq. 7.33
    and the groove-centre geometry it rests on):
        A = (fi + fe − 1)·Dw,  tan α = (A sin α0 + δa)/(A cos α0),
        δ = A·(cos α0/cos α − 1),  Fa = Z·K·δ^1.5·sin α,
    K the reference's spring constant at α0 [N/m^1.5] (ISO/TS 16281:2008 4.2, eq. 10, exact
    Hertz);
    0 for δa ≤ 0."""
    if delta_a <= 0.0:
        return 0.0
    a, alpha0 = bearing.groove_distance, bearing.free_contact_angle
    alpha = math.atan2(a * math.sin(alpha0) + delta_a, a * math.cos(alpha0))
    delta = a * (math.cos(alpha0) / math.cos(alpha) - 1.0)
    return bearing.ball_count * bearing.spring_constant * delta**1.5 * math.sin(alpha)


def roller_axial_load(bearing: RollerBearing, delta_a: float) -> float:
    """Fa [N] of a tapered roller bearing displaced axially by δa [m] (ISO/TS 16281:2008
    5.2, eqs. 38-41 with every roller alike, untilted):
        Fa = Z·sin α·Σ_k (c_L/ns)·(δa·sin α − g_k)₊^(10/9),
        g_k = (Pd/2)·cos α + 2·p_k,
    c_L the reference's roller spring constant [N/m^(10/9)], p_k its ISO profile drop."""
    alpha = bearing.contact_angle
    gap = bearing.diametral_clearance / 2.0 * math.cos(alpha) + 2.0 * bearing.profile_drop
    approach = np.maximum(delta_a * math.sin(alpha) - gap, 0.0)
    lamina = bearing.spring_constant / bearing.laminae * approach ** (10.0 / 9.0)
    return float(bearing.roller_count * math.sin(alpha) * lamina.sum())


def axial_load(bearing, delta_a: float) -> float:
    """Fa(δa) [N] of a one-sided bearing: ball_axial_load or roller_axial_load."""
    if isinstance(bearing, BallBearing):
        if bearing.free_contact_angle is None:
            raise ValueError("the closed form is for angular-contact (one-sided) balls")
        return ball_axial_load(bearing, delta_a)
    if bearing.contact_angle <= 0.0:
        raise ValueError("the closed form is for tapered (one-sided) rollers")
    return roller_axial_load(bearing, delta_a)


def first_contact(bearing) -> float:
    """δa [m] of first contact in the reference's axial datum: 0 for angular-contact balls;
    min_k g_k/sin α for tapered rollers, g_k = (Pd/2)·cos α + 2·p_k (ISO/TS 16281:2008 5.2,
    eqs. 38-44: the ISO profile leaves a gap at every lamina centre, since none sits at
    ℓ = 0)."""
    if isinstance(bearing, BallBearing):
        return 0.0
    alpha = bearing.contact_angle
    gap = bearing.diametral_clearance / 2.0 * math.cos(alpha) + 2.0 * bearing.profile_drop
    return float(gap.min() / math.sin(alpha))


def lift_off_thrust(bearing, end_play: float) -> float:
    """Fx [N] on the shaft at which bearing 2 of a preloaded pair (end play e < 0) lifts
    off: bearing 2 at its first contact δa0 means the shaft moved −e/2 − δa0, bearing 1 at
    δa = −e − δa0, so Fx = Fa(−e − δa0) (Fa = 0 at δa0 by definition)."""
    return axial_load(bearing, -end_play - first_contact(bearing))


def preload_from_end_play(bearing, end_play: float) -> float:
    """Preload [N] of a pair of identical one-sided bearings with end play e [m] at rest:
    each stands at δa = −e/2 from first contact, so each carries Fa(−e/2) (0 for e ≥ 0)."""
    return axial_load(bearing, -end_play / 2.0)


def end_play_for_preload(bearing, preload: float) -> float:
    """The end play e = −2·δa [m] (negative) at which each bearing of a pair of identical
    one-sided bearings carries ``preload`` [N]: Fa(δa) = preload by brentq (Fa is monotone
    in δa), the bracket doubled from 1 µm until it holds."""
    if preload <= 0.0:
        raise ValueError("preload must be positive")
    high = 1e-6
    while axial_load(bearing, high) < preload:
        high *= 2.0
        if high > 1.0:
            raise ValueError("no axial displacement below 1 m carries that preload")
    delta_a = optimize.brentq(lambda d: axial_load(bearing, d) - preload, 0.0, high,
                              xtol=1e-18, rtol=1e-15)
    return -2.0 * delta_a
