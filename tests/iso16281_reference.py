"""ISO/TS 16281 load distribution and reference rating life: a slow, scalar reference.

What this is
------------
An independent reference the tests hold the package's vectorised ISO/TS 16281 solver
against. It imports nothing of bearingcalc (numpy and scipy only) and is written from the
formulas: a loop over the rolling elements, ``scipy.optimize.root`` on an equilibrium
residual written here, exact Hertz contacts from ``scipy.special.ellipk``/``ellipe``, and the
tangent stiffness by central differences. It is meant to be read, not to be fast.

Units: SI in and out (m, N, N·m, rad, Pa); lives in 10^6 revolutions where named
``*_million``.

Conventions (as the bearing's documentation pins them)
------------------------------------------------------
* Frame: x along the bearing axis, positive in the direction of the axial load on the
  inner ring; y along the radial load; the element at azimuth ψ = 0 lies on +y and ψ is
  counted toward +z.
* Displacement of the inner ring relative to the outer ring:
  q = (δx, δy, δz, θy, θz) [m, m, m, rad, rad]. A tilt moves the inner ring's raceway at
  azimuth ψ and pitch radius r axially by r·(θz·cos ψ + θy·sin ψ) and, at axial position
  x along the raceway, radially by −x·(θz·cos ψ + θy·sin ψ). So a positive θz (and a
  positive tilting moment Mz) increases the axial approach of the element at ψ = 0, as
  ISO/TS 16281's planar form V = A·sin α0 + δa + (Dpw/2)·sin θ·cos ψ writes it; θy is the
  same tilt turned by 90° (it increases the approach at ψ = 90°, i.e. it is the
  right-handed rotation about +y). sin θ = θ to θ²/6 (< 1e-5 below 8 mrad).
* Forces F = (Fx, Fy, Fz, My, Mz) are the loads applied to the inner ring at the origin,
  work-conjugate to q: the centre plane for balls and cylindrical rollers, the pressure
  centre (where the normal to the cup raceway through the mean roller meets the axis)
  for tapered rollers. The stiffness matrix is ∂F/∂q in the same order.
* Balls: the contact lies on the line through both groove curvature centres (inner
  ri = fi·Dw, outer re = fe·Dw, A = ri + re − Dw); the tilt lever is Dpw/2. Deep-groove
  bearings: diametral clearance Pd, axial datum the centred ring. Angular-contact: free
  contact angle α0, axial datum first contact.
* Rollers: laminae along the (cup) raceway, q = (c_L/ns)·δ^(10/9) with
  c_L = 35 948·Lwe^(8/9) N/mm^(10/9) (ISO/TS 16281) shared among the ns laminae, ISO's
  logarithmic profile on the roller (both contacts, hence 2·p_k). Tapered: the cup's
  contact angle for the cone's motion and for the roller's equilibrium.

ISO/TS 16281:2008 equations followed (numbering as minzhun/ISO16281 cites it; the
standard's text was not at hand): (2)-(4) ellipticity from the curvature difference with
the complete elliptic integrals, (10) the point-contact spring constant (here the exact
Hertz constant in place of its rounded 1.48), (12) the ball's deflection from the groove
centres, (16)-(18) equilibrium, (19)-(24) the raceway ratings Q_ci, Q_ce from C (with
cos α to the first power), (25)-(28) the equivalent element loads, (29) L10r for balls;
(38)-(41) the lamina deflections, (42)-(44) the logarithmic profile, (45)-(46)
equilibrium, (47)-(57) the roller ratings and lamina ratings, (61)-(64) the equivalent
lamina loads and (65) L10r for rollers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import integrate, optimize, special

DOF_NAMES = ("x", "y", "z", "tilt_y", "tilt_z")

#: ISO/TS 16281's line-contact spring constant, c_L = 35 948·Lwe^(8/9) N/mm^(10/9),
#: in SI: 35 948·(1e3)^(8/9 + 10/9) = 35 948e6 [N / m^(10/9) / m^(8/9)].
LINE_SPRING_SI = 35948.0e6


# --------------------------------------------------------------------------- Hertz
def ellipticity(curvature_difference: float) -> float:
    """Ellipticity κ = a/b of a Hertz point contact from the curvature difference F(ρ).

    F(ρ) = [(κ² + 1)·E(m) − 2·K(m)] / [(κ² − 1)·E(m)],  m = 1 − 1/κ²
    (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., Part 1, eq. 6.26; ISO/TS 16281
    eq. 2). K, E: complete elliptic integrals of the first and second kind (parameter m).
    Solved by Brent's method on κ in (1, 1e4).
    """

    def residual(kappa: float) -> float:
        m = 1.0 - 1.0 / kappa**2
        ek, ee = special.ellipk(m), special.ellipe(m)
        return ((kappa**2 + 1.0) * ee - 2.0 * ek) / ((kappa**2 - 1.0) * ee) - curvature_difference

    # below κ − 1 ≈ 1e-7 the residual is lost to cancellation (F ≈ 0.75·(κ − 1))
    return optimize.brentq(residual, 1.0 + 1e-7, 1e4, xtol=1e-15, rtol=1e-15)


def ball_raceway_curvatures(ball_diameter: float, pitch_diameter: float, conformity: float,
                            contact_angle: float, ring: str) -> tuple[float, float]:
    """Curvature sum Σρ [1/m] and difference F(ρ) [1] of a ball on a groove.

    γ = Dw·cos α/Dpw; ball 2/Dw in both planes; raceway in the rolling direction
    +2γ/(Dw(1−γ)) (inner) or −2γ/(Dw(1+γ)) (outer), across the groove −1/(f·Dw).
    F(ρ) = (ρ_II1 − ρ_II2)/Σρ (Harris & Kotzalas, Part 1, eqs. 2.27-2.33).
    """
    gamma = ball_diameter * math.cos(contact_angle) / pitch_diameter
    along = 2.0 / ball_diameter * (gamma / (1 - gamma) if ring == "inner" else -gamma / (1 + gamma))
    across = -1.0 / (conformity * ball_diameter)
    total = 4.0 / ball_diameter + along + across
    return total, abs(along - across) / total


def point_contact(sum_rho: float, curvature_difference: float, reduced_modulus: float,
                  load: float | None = None) -> dict[str, float]:
    """Exact Hertz point contact [Harris & Kotzalas, Part 1, eqs. 6.36-6.43].

    With 1/E* = 2(1−ν²)/E for two equal steels, Q = K·δ^(3/2) where
        δ = (2·K(m)/π)·(π/(2κ²E(m)))^(1/3)·(Σρ/2)·(3Q/(2Σρ E*))^(2/3),
    and the semi-axes a = (3κ²E(m)Q/(πΣρE*))^(1/3), b = (3E(m)Q/(πκΣρE*))^(1/3), the
    maximum pressure 3Q/(2πab). Returns K [N/m^1.5], κ and, given a load [N], a, b [m] and
    p_max [Pa].
    """
    kappa = ellipticity(curvature_difference)
    m = 1.0 - 1.0 / kappa**2
    ek, ee = special.ellipk(m), special.ellipe(m)
    delta_star = 2.0 * ek / math.pi * (math.pi / (2.0 * kappa**2 * ee)) ** (1.0 / 3.0)
    # δ = c·Q^(2/3)
    c = delta_star * sum_rho / 2.0 * (3.0 / (2.0 * sum_rho * reduced_modulus)) ** (2.0 / 3.0)
    out = {"stiffness": c**-1.5, "ellipticity": kappa, "compliance": c}
    if load is not None:
        a = (3.0 * kappa**2 * ee * load / (math.pi * sum_rho * reduced_modulus)) ** (1 / 3)
        b = (3.0 * ee * load / (math.pi * kappa * sum_rho * reduced_modulus)) ** (1 / 3)
        out.update(a=a, b=b, pressure=1.5 * load / (math.pi * a * b) if load > 0 else 0.0)
    return out


def reduced_modulus(elastic_modulus: float, poisson_ratio: float) -> float:
    """E* = E/(2(1−ν²)) [Pa] of two bodies of the same steel (Johnson, Contact Mechanics, 4.22)."""
    return elastic_modulus / (2.0 * (1.0 - poisson_ratio**2))


# --------------------------------------------------------------------------- balls
@dataclass(frozen=True)
class BallBearing:
    """A radial ball bearing's internal geometry [m, rad] and steel [Pa, 1].

    ``free_contact_angle`` None: deep-groove with ``diametral_clearance`` Pd (negative is
    preload), axial datum the centred ring. Otherwise angular-contact at first contact
    with that angle. ``rows`` only enters the ratings (i in ISO's formulas).
    """

    ball_count: int
    ball_diameter: float
    pitch_diameter: float
    inner_conformity: float
    outer_conformity: float
    diametral_clearance: float = 0.0
    free_contact_angle: float | None = None
    elastic_modulus: float = 2.1e11
    poisson_ratio: float = 0.3
    first_azimuth: float = 0.0
    rows: int = 1

    @property
    def groove_distance(self) -> float:
        """A = ri + re − Dw = (fi + fe − 1)·Dw [m]."""
        return (self.inner_conformity + self.outer_conformity - 1.0) * self.ball_diameter

    @property
    def nominal_contact_angle(self) -> float:
        """α of the ratings and of the spring constant: 0 for deep-groove, else α0 [rad]."""
        return 0.0 if self.free_contact_angle is None else self.free_contact_angle

    @property
    def unloaded_offset(self) -> tuple[float, float]:
        """(axial, radial) offset [m] of the inner groove centre from the outer's at q = 0."""
        a = self.groove_distance
        if self.free_contact_angle is None:
            return 0.0, a - self.diametral_clearance / 2.0
        return a * math.sin(self.free_contact_angle), a * math.cos(self.free_contact_angle)

    @property
    def azimuths(self) -> np.ndarray:
        """ψ_j = ψ_0 + 2πj/Z [rad]."""
        return self.first_azimuth + 2.0 * math.pi * np.arange(self.ball_count) / self.ball_count

    def contact(self, contact_angle: float, ring: str, load: float | None = None) -> dict:
        """Hertz contact of one ball on the inner or outer ring at a contact angle."""
        conformity = self.inner_conformity if ring == "inner" else self.outer_conformity
        total, diff = ball_raceway_curvatures(self.ball_diameter, self.pitch_diameter,
                                              conformity, contact_angle, ring)
        return point_contact(total, diff, reduced_modulus(self.elastic_modulus,
                                                          self.poisson_ratio), load)

    @property
    def spring_constant(self) -> float:
        """K [N/m^1.5] of a ball between both rings, Q = K·δ^1.5, in series:
        K = (c_i + c_e)^(−3/2) with δ_i = c_i·Q^(2/3) (ISO/TS 16281 eq. 10 with exact
        Hertz), at the nominal contact angle."""
        alpha = self.nominal_contact_angle
        return (self.contact(alpha, "inner")["compliance"]
                + self.contact(alpha, "outer")["compliance"]) ** -1.5


def ball_kinematics(bearing: BallBearing, q: np.ndarray) -> tuple[np.ndarray, ...]:
    """Per ball: axial and radial groove-centre offsets s_x, s_r [m] and ∂s/∂q rows.

    s_x = x0 + δx + (Dpw/2)(θz cos ψ + θy sin ψ),  s_r = r0 + δy cos ψ + δz sin ψ
    (ISO/TS 16281 eq. 12 in five degrees of freedom).
    """
    psi = bearing.azimuths
    x0, r0 = bearing.unloaded_offset
    lever = bearing.pitch_diameter / 2.0
    c, s = np.cos(psi), np.sin(psi)
    dsx = np.stack([np.ones_like(c), 0 * c, 0 * c, lever * s, lever * c], axis=1)
    dsr = np.stack([0 * c, c, s, 0 * c, 0 * c], axis=1)
    return x0 + dsx @ q, r0 + dsr @ q, dsx, dsr


def ball_state(bearing: BallBearing, q) -> dict[str, np.ndarray]:
    """Deflection δ = |s| − A [m], load Q = K·max(δ, 0)^1.5 [N], signed contact angle
    atan2(s_x, s_r) [rad] of every ball, and the ring's internal force Σ Q·∂δ/∂q."""
    q = np.asarray(q, dtype=float)
    sx, sr, dsx, dsr = ball_kinematics(bearing, q)
    dist = np.hypot(sx, sr)
    deflection = dist - bearing.groove_distance
    load = bearing.spring_constant * np.maximum(deflection, 0.0) ** 1.5
    ddelta = (sx[:, None] * dsx + sr[:, None] * dsr) / dist[:, None]
    energy = 0.4 * bearing.spring_constant * np.sum(np.maximum(deflection, 0.0) ** 2.5)
    return {"azimuth": bearing.azimuths, "deflection": deflection, "load": load,
            "angle": np.arctan2(sx, sr), "force": load @ ddelta, "energy": energy}


def ball_pressures(bearing: BallBearing, load: np.ndarray, angle: np.ndarray):
    """Maximum Hertz pressures [Pa] of every ball at the inner and outer ring, with the
    curvatures at each ball's operating contact angle."""
    inner = [bearing.contact(abs(a), "inner", q)["pressure"] if q > 0 else 0.0
             for q, a in zip(load, angle, strict=True)]
    outer = [bearing.contact(abs(a), "outer", q)["pressure"] if q > 0 else 0.0
             for q, a in zip(load, angle, strict=True)]
    return np.array(inner), np.array(outer)


# --------------------------------------------------------------------------- rollers
@dataclass(frozen=True)
class RollerBearing:
    """A cylindrical (contact_angle 0) or tapered (the cup's angle) roller bearing [m, rad].

    ``diametral_clearance``: the cylindrical bearing's Pd; the lamina gap is (Pd/2)·cos α.
    ``profile``: "iso" (ISO/TS 16281's logarithmic profile) or "none".
    ``line_spring``: c_L of the whole roller [N/m^(10/9)], default ISO's 35 948·Lwe^(8/9).
    """

    roller_count: int
    roller_diameter: float
    effective_length: float
    pitch_diameter: float
    contact_angle: float = 0.0
    diametral_clearance: float = 0.0
    laminae: int = 30
    profile: str = "iso"
    line_spring: float | None = None
    elastic_modulus: float = 2.1e11
    poisson_ratio: float = 0.3
    first_azimuth: float = 0.0
    rows: int = 1

    @property
    def azimuths(self) -> np.ndarray:
        return self.first_azimuth + 2.0 * math.pi * np.arange(self.roller_count) / self.roller_count

    @property
    def lamina_positions(self) -> np.ndarray:
        """ℓ_k [m]: lamina centres along the raceway from the roller's middle."""
        ns, length = self.laminae, self.effective_length
        return (np.arange(ns) - ns / 2.0 + 0.5) * length / ns

    @property
    def spring_constant(self) -> float:
        """c_L [N/m^(10/9)] of a whole roller (both contacts), ISO/TS 16281."""
        if self.line_spring is not None:
            return self.line_spring
        return LINE_SPRING_SI * self.effective_length ** (8.0 / 9.0)

    @property
    def profile_drop(self) -> np.ndarray:
        """p_k [m], ISO/TS 16281 eqs. 42-44 (radial roller bearings):
        Lwe ≤ 2.5·Dwe: p = 0.00035·Dwe·ln(1/(1 − (2ℓ/Lwe)²));
        Lwe > 2.5·Dwe: p = 0 for |ℓ| ≤ (Lwe − 2.5Dwe)/2, else
        p = 0.0005·Dwe·ln(1/(1 − ((2|ℓ| − Lwe + 2.5·Dwe)/(2.5·Dwe))²))."""
        ell = np.abs(self.lamina_positions)
        dwe, lwe = self.roller_diameter, self.effective_length
        if self.profile == "none":
            return np.zeros_like(ell)
        if lwe <= 2.5 * dwe:
            return 0.00035 * dwe * np.log(1.0 / (1.0 - (2.0 * ell / lwe) ** 2))
        u = np.clip((2.0 * ell - lwe + 2.5 * dwe) / (2.5 * dwe), 0.0, None)
        return 0.0005 * dwe * np.log(1.0 / (1.0 - u**2))


def roller_state(bearing: RollerBearing, q) -> dict[str, np.ndarray]:
    """Lamina deflections and loads (ISO/TS 16281 eqs. 38-41 in five degrees of freedom).

    δ_jk = δx·sin α + (δy cos ψ + δz sin ψ)·cos α − ℓ_k·(θz cos ψ + θy sin ψ)
           − (Pd/2)·cos α − 2·p_k,
    q_jk = (c_L/ns)·max(δ_jk, 0)^(10/9) [N]; the internal force Σ q_jk·∂δ_jk/∂q.
    """
    q = np.asarray(q, dtype=float)
    psi = bearing.azimuths
    alpha = bearing.contact_angle
    ell = bearing.lamina_positions
    c, s = np.cos(psi), np.sin(psi)
    # ∂δ_jk/∂q: shape (Z, ns, 5)
    grad = np.zeros((psi.size, ell.size, 5))
    grad[:, :, 0] = math.sin(alpha)
    grad[:, :, 1] = (math.cos(alpha) * c)[:, None]
    grad[:, :, 2] = (math.cos(alpha) * s)[:, None]
    grad[:, :, 3] = -ell[None, :] * s[:, None]
    grad[:, :, 4] = -ell[None, :] * c[:, None]
    gap = bearing.diametral_clearance / 2.0 * math.cos(alpha) + 2.0 * bearing.profile_drop
    deflection = grad @ q - gap[None, :]
    lamina = bearing.spring_constant / bearing.laminae * np.maximum(deflection, 0.0) ** (10 / 9)
    energy = 9 / 19 * bearing.spring_constant / bearing.laminae * np.sum(
        np.maximum(deflection, 0.0) ** (19 / 9))
    return {"azimuth": psi, "deflection": deflection, "lamina_load": lamina, "energy": energy,
            "load": lamina.sum(axis=1), "force": np.einsum("jk,jkd->d", lamina, grad)}


def roller_pressures(bearing: RollerBearing, lamina_load: np.ndarray):
    """Maximum line-contact pressures [Pa] per lamina at the inner and outer ring:
    p = sqrt(q'·E*/(π·R')), q' = q/(Lwe/ns), 1/R' = 2/(Dwe(1 ∓ γ)), γ = Dwe cos α/Dpw
    (Johnson, Contact Mechanics, eq. 4.45)."""
    gamma = bearing.roller_diameter * math.cos(bearing.contact_angle) / bearing.pitch_diameter
    per_length = lamina_load / (bearing.effective_length / bearing.laminae)
    e_star = reduced_modulus(bearing.elastic_modulus, bearing.poisson_ratio)
    inner = np.sqrt(per_length * e_star * 2.0 / (bearing.roller_diameter * (1 - gamma)) / math.pi)
    outer = np.sqrt(per_length * e_star * 2.0 / (bearing.roller_diameter * (1 + gamma)) / math.pi)
    return inner, outer


# --------------------------------------------------------------------------- equilibrium
def _state(bearing, q):
    return ball_state(bearing, q) if isinstance(bearing, BallBearing) else roller_state(bearing, q)


def _scales(bearing) -> tuple[np.ndarray, float]:
    """Displacement scales (1 µm; 1 µm over the pitch radius) and the lever [m] that puts
    moments on the scale of forces."""
    lever = bearing.pitch_diameter / 2.0
    return np.array([1e-6, 1e-6, 1e-6, 1e-6 / lever, 1e-6 / lever]), lever


def _initial_guesses(bearing, free: np.ndarray, forces: np.ndarray) -> list[np.ndarray]:
    """Starting points in scaled units: along the loads, at several magnitudes."""
    _, lever = _scales(bearing)
    direction = forces / np.array([1.0, 1.0, 1.0, lever, lever])
    norm = np.linalg.norm(direction[free])
    unit = direction / norm if norm > 0 else np.zeros(5)
    guesses = []
    for size in (10.0, 30.0, 3.0, 100.0, 1.0, 0.3, 0.1):
        g = size * unit
        g[0] += 0.5 * size if forces[0] == 0 else 0.0  # break the deep-groove symmetry
        guesses.append(g[free])
        if forces[0] > 0:  # a one-sided bearing: every element in contact to start
            g = g.copy()
            g[0] = 3.0 * size
            guesses.append(g[free])
    return guesses


def solve_equilibrium(bearing, forces=(0.0, 0.0, 0.0, 0.0, 0.0), imposed=None,
                      x0=None) -> dict:
    """Inner-ring equilibrium Σ_j Q_j·∂δ_j/∂q = F (ISO/TS 16281 eqs. 16-18, 45-46).

    forces: (Fx, Fy, Fz, My, Mz) [N, N, N, N·m, N·m] on the inner ring.
    imposed: {dof name: value} held fixed (e.g. {"tilt_z": 1e-3} for a misalignment, or
    {"z": 0, "tilt_y": 0} for a planar case); their forces are reactions, reported in
    ``reaction``. A cylindrical roller bearing's x is held at 0.
    Solved with scipy.optimize.root (hybr) in µm-scaled unknowns from several starts.
    Returns q [m, rad], the per-element state, ``reaction`` (the force vector the
    contacts carry), the relative residual and the 5×5 tangent stiffness [N/m ... N·m/rad].
    """
    forces = np.asarray(forces, dtype=float)
    imposed = dict(imposed or {})
    if isinstance(bearing, RollerBearing) and bearing.contact_angle == 0.0:
        imposed.setdefault("x", 0.0)
    free = np.array([name not in imposed for name in DOF_NAMES])
    scale, lever = _scales(bearing)
    q_fixed = np.array([imposed.get(name, 0.0) for name in DOF_NAMES])
    force_scale = np.array([1.0, 1.0, 1.0, 1.0 / lever, 1.0 / lever])
    reference = max(np.linalg.norm((forces * force_scale)[free]), 1.0)

    def full(u):
        q = q_fixed.copy()
        q[free] = u * scale[free]
        return q

    def residual(u):
        return ((_state(bearing, full(u))["force"] - forces) * force_scale)[free] / reference

    starts = [np.asarray(x0)[free] / scale[free]] if x0 is not None else []
    best = None
    for start in starts + _initial_guesses(bearing, free, forces):
        sol = optimize.root(residual, start, method="hybr", options={"xtol": 1e-14})
        err = np.max(np.abs(residual(sol.x)))
        if best is None or err < best[1]:
            best = (sol.x, err)
        if err < 1e-12:
            break
    q = full(best[0])
    state = _state(bearing, q)
    state.update(q=q, residual=best[1], reaction=state["force"],
                 stiffness=stiffness_matrix(bearing, q))
    return state


def stiffness_matrix(bearing, q, step: float = 1e-9) -> np.ndarray:
    """Tangent stiffness K_ab = ∂F_a/∂q_b [SI] by central differences of the contacts'
    force vector, steps of 1 nm in translation and 1 nm over the pitch radius in tilt."""
    q = np.asarray(q, dtype=float)
    lever = bearing.pitch_diameter / 2.0
    steps = step * np.array([1.0, 1.0, 1.0, 1.0 / lever, 1.0 / lever])
    k = np.zeros((5, 5))
    for b in range(5):
        dq = np.zeros(5)
        dq[b] = steps[b]
        ahead, behind = _state(bearing, q + dq)["force"], _state(bearing, q - dq)["force"]
        k[:, b] = (ahead - behind) / (2 * steps[b])
    return k


# --------------------------------------------------------------------------- life
def equivalent_load(loads: np.ndarray, exponent: float) -> float:
    """(1/Z·Σ Q_j^e)^(1/e) over all Z elements (ISO/TS 16281 eqs. 25-28, 61-64)."""
    loads = np.asarray(loads, dtype=float)
    return float(np.mean(loads**exponent, axis=0) ** (1.0 / exponent))


def ball_raceway_ratings(bearing: BallBearing, dynamic_rating: float) -> tuple[float, float]:
    """Q_ci, Q_ce [N] from C (ISO/TS 16281 eqs. 19-24, cos α to the first power):

    Q_ci = C/(0.407·Z·i^0.7·cos α)·[1 + (1.044·X)^(10/3)]^0.3,
    Q_ce = C/(0.389·Z·i^0.7·cos α)·[1 + (1.044·X)^(−10/3)]^0.3,
    X = ((1−γ)/(1+γ))^1.72·(fi(2fe − 1)/(fe(2fi − 1)))^0.41, γ = Dw cos α/Dpw:
    Lundberg–Palmgren's C = 0.407·Z·i^0.7·cos α·Q_ci·(1 + (C_i/C_e)^(10/3))^(−0.3).
    """
    alpha = bearing.nominal_contact_angle
    gamma = bearing.ball_diameter * math.cos(alpha) / bearing.pitch_diameter
    fi, fe = bearing.inner_conformity, bearing.outer_conformity
    x = ((1 - gamma) / (1 + gamma)) ** 1.72 * (fi * (2 * fe - 1) / (fe * (2 * fi - 1))) ** 0.41
    base = dynamic_rating / (bearing.ball_count * bearing.rows**0.7 * math.cos(alpha))
    q_ci = base / 0.407 * (1 + (1.044 * x) ** (10 / 3)) ** 0.3
    q_ce = base / 0.389 * (1 + (1.044 * x) ** (-10 / 3)) ** 0.3
    return q_ci, q_ce


def ball_reference_life(bearing: BallBearing, loads, dynamic_rating: float,
                        rotating: str = "inner") -> dict[str, float]:
    """L10r = [(Q_ci/Q_ei)^(−10/3) + (Q_ce/Q_ee)^(−10/3)]^(−9/10) [10^6 rev] (ISO/TS 16281
    eq. 29); the rotating ring's Q_e the cubic mean, the stationary one's the 10/3 mean."""
    q_ci, q_ce = ball_raceway_ratings(bearing, dynamic_rating)
    cubic, tenth = equivalent_load(loads, 3.0), equivalent_load(loads, 10.0 / 3.0)
    q_ei, q_ee = (cubic, tenth) if rotating == "inner" else (tenth, cubic)
    life = ((q_ci / q_ei) ** (-10 / 3) + (q_ce / q_ee) ** (-10 / 3)) ** -0.9
    return {"life_million": life, "Q_ci": q_ci, "Q_ce": q_ce, "Q_ei": q_ei, "Q_ee": q_ee,
            "reference_load": dynamic_rating / life ** (1 / 3)}


def roller_raceway_ratings(bearing: RollerBearing, dynamic_rating: float) -> tuple[float, ...]:
    """Q_ci, Q_ce and the lamina ratings q_ci, q_ce [N] (ISO/TS 16281 eqs. 47-57):

    Q_ci = C/(λν·0.378·Z·i^(7/9)·cos α)·[1 + (1.038·((1−γ)/(1+γ))^(143/108))^(9/2)]^(2/9),
    Q_ce = C/(λν·0.364·Z·i^(7/9)·cos α)·[1 + (1.038·((1−γ)/(1+γ))^(143/108))^(−9/2)]^(2/9),
    λν = 0.83, q_c = Q_c·(1/ns)^(7/9).
    """
    alpha = bearing.contact_angle
    gamma = bearing.roller_diameter * math.cos(alpha) / bearing.pitch_diameter
    x = 1.038 * ((1 - gamma) / (1 + gamma)) ** (143 / 108)
    rows = bearing.rows ** (7 / 9)
    base = dynamic_rating / (0.83 * bearing.roller_count * rows * math.cos(alpha))
    q_ci = base / 0.378 * (1 + x**4.5) ** (2 / 9)
    q_ce = base / 0.364 * (1 + x**-4.5) ** (2 / 9)
    share = (1.0 / bearing.laminae) ** (7 / 9)
    return q_ci, q_ce, q_ci * share, q_ce * share


def roller_reference_life(bearing: RollerBearing, lamina_loads, dynamic_rating: float,
                          rotating: str = "inner") -> dict[str, float]:
    """L10r = [Σ_k (q_kei/q_ci)^(9/2) + (q_kee/q_ce)^(9/2)]^(−8/9) [10^6 rev] (ISO/TS 16281
    eq. 65); per lamina the rotating ring's equivalent load the mean of exponent 4, the
    stationary one's of exponent 4.5, over the Z rollers (eqs. 61-64); edge factor off."""
    _, _, qc_i, qc_e = roller_raceway_ratings(bearing, dynamic_rating)
    loads = np.asarray(lamina_loads, dtype=float)
    four = np.mean(loads**4, axis=0) ** 0.25
    four_half = np.mean(loads**4.5, axis=0) ** (1 / 4.5)
    q_ei, q_ee = (four, four_half) if rotating == "inner" else (four_half, four)
    life = float(np.sum((q_ei / qc_i) ** 4.5 + (q_ee / qc_e) ** 4.5) ** (-8 / 9))
    return {"life_million": life, "q_ci": qc_i, "q_ce": qc_e,
            "reference_load": dynamic_rating / life ** 0.3}


# --------------------------------------------------------------------------- integrals
def load_integrals(eps: float, exponent: float) -> tuple[float, float]:
    """Sjövall's J_r(ε), J_a(ε) [Harris & Kotzalas, Part 1, eqs. 7.22-7.23, 7.46-7.47]:

    J_r = (1/2π)∫ [1 − (1 − cos ψ)/(2ε)]^n cos ψ dψ,  J_a = (1/2π)∫ [ ... ]^n dψ,
    over the load zone cos ψ ≥ 1 − 2ε (the whole ring for ε ≥ 1); n = 3/2 point,
    10/9 line contact. Evaluated with scipy.integrate.quad.
    """
    limit = math.pi if eps >= 1.0 else math.acos(1.0 - 2.0 * eps)

    def shape(psi):
        return max(1.0 - (1.0 - math.cos(psi)) / (2.0 * eps), 0.0) ** exponent

    jr = integrate.quad(lambda p: shape(p) * math.cos(p), 0, limit, epsabs=1e-14, epsrel=1e-13)
    ja = integrate.quad(shape, 0, limit, epsabs=1e-14, epsrel=1e-13)
    return jr[0] / math.pi, ja[0] / math.pi


def mean_power_integral(eps: float, exponent: float) -> float:
    """(1/2π)∫ [1 − (1 − cos ψ)/(2ε)]^p dψ over the load zone: the mean of Q^(p/n) of a
    continuous distribution, in units of Q_max^(p/n) (for the equivalent loads)."""
    limit = math.pi if eps >= 1.0 else math.acos(1.0 - 2.0 * eps)
    value = integrate.quad(lambda p: max(1 - (1 - math.cos(p)) / (2 * eps), 0.0) ** exponent,
                           0, limit, epsabs=1e-14, epsrel=1e-13)[0]
    return value / math.pi
