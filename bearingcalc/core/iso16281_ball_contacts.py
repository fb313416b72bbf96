"""A radial ball bearing's contacts at a displacement of its inner ring (ISO/TS
16281:2008, 5 and 6): each ball between the groove curvature centres of its two rings,
its compression and load, and the energy, internal force and tangent stiffness they
sum to. Vectorised over designs, the balls padded to the largest count. Frame and signs
as :mod:`bearingcalc.core.iso16281_balls`, which solves the equilibrium from them.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray


class BallGeometry(NamedTuple):
    """A radial ball bearing's contacts, arrays over designs. [m, N/m^1.5]"""

    ball_count: NDArray        # Z [1]
    groove_distance: NDArray   # A = (fi + fe − 1)·Dw, the groove centres' distance at contact
    axial_offset: NDArray      # the inner groove centre's axial offset from the outer's at q = 0
    radial_offset: NDArray     # and its radial offset
    lever: NDArray             # the tilt's lever, Dpw/2
    spring_constant: NDArray   # K of a ball between both rings, Q = K·δ^1.5
    #: an angular-contact bearing: its outer ring has one shoulder, so a ball touches it
    #: only at a positive contact angle (a deep-groove bearing's grooves take both)
    one_sided: NDArray


def ball_geometry(ball_count: ArrayLike, ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
                  inner_conformity: ArrayLike, outer_conformity: ArrayLike,
                  spring_constant: ArrayLike, *, diametral_clearance: ArrayLike | None = None,
                  free_contact_angle: ArrayLike | None = None) -> BallGeometry:
    r"""The groove centres of a deep-groove bearing with diametral clearance Pd (axial
    datum: the centred ring) or of an angular-contact bearing at first contact with its
    free contact angle α0 (ISO/TS 16281, 6.1):

    .. math:: A = (f_i + f_e - 1) D_w, \quad (s_{x0}, s_{r0}) = (0, A - P_d/2)
              \ \text{or}\ (A \sin\alpha_0, A \cos\alpha_0)
    """
    dw = np.asarray(ball_diameter, dtype=float)
    distance = (np.asarray(inner_conformity, dtype=float)
                + np.asarray(outer_conformity, dtype=float) - 1.0) * dw
    if free_contact_angle is None:
        clearance = np.asarray(0.0 if diametral_clearance is None else diametral_clearance,
                               dtype=float)
        axial, radial = np.zeros_like(distance), distance - clearance / 2.0
    else:
        alpha = np.asarray(free_contact_angle, dtype=float)
        axial, radial = distance * np.sin(alpha), distance * np.cos(alpha)
    arrays = np.broadcast_arrays(np.asarray(ball_count, dtype=float), distance, axial, radial,
                                 np.asarray(pitch_diameter, dtype=float) / 2.0,
                                 np.asarray(spring_constant, dtype=float),
                                 np.full(np.shape(distance), free_contact_angle is not None))
    *numbers, one_sided = (np.atleast_1d(a) for a in arrays)
    return BallGeometry(*(a.astype(float) for a in numbers), one_sided.astype(bool))


#: Each coordinate's part of ∂s/∂u: whether it moves s_x (else s_r), and its factor as
#: powers of (cos ψ, sin ψ).
_PARTS = {0: (True, (0, 0)), 1: (False, (1, 0)), 2: (False, (0, 1)), 3: (True, (0, 1)),
          4: (True, (1, 0))}


class BallSet(NamedTuple):
    """Every ball of a set of designs, (N, Zmax): the products of cos ψ and sin ψ that
    the force and the stiffness weigh, keyed by their powers, and each ball's groove
    distance A (+inf for padding, which so never touches)."""

    trig: dict[tuple[int, int], NDArray]
    reach: NDArray

    def take(self, rows: NDArray) -> BallSet:
        return BallSet({key: value[rows] for key, value in self.trig.items()},
                      self.reach[rows])


def ball_set(geometry: BallGeometry, width: int) -> tuple[BallSet, NDArray]:
    """Every ball (ψ_j = 2πj/Z) and the mask of real balls, (N, width)."""
    count = geometry.ball_count.astype(int)
    j = np.arange(width)
    mask = j[None, :] < count[:, None]
    psi = 2.0 * np.pi * j[None, :] / count[:, None]
    cos, sin = np.cos(psi), np.sin(psi)
    trig = {(1, 0): cos, (0, 1): sin, (2, 0): cos * cos, (0, 2): sin * sin,
            (1, 1): cos * sin}
    return BallSet(trig, np.where(mask, geometry.groove_distance[:, None], np.inf)), mask


class BallState(NamedTuple):
    energy: NDArray     # (N,) the contacts' elastic energy [J]
    force: NDArray      # (N, k) internal force along the coordinates solved for [N]
    hessian: NDArray    # (N, k, k) [N/m]
    load: NDArray       # (N, Zmax) [N]
    angle: NDArray | None  # (N, Zmax) signed atan2(s_x, s_r) [rad], where asked for


def _weighed(weight: NDArray, balls: BallSet, power: tuple[int, int]) -> NDArray:
    """Σ over the balls of weight·cos^a ψ·sin^b ψ, (N,)."""
    if power == (0, 0):
        return weight.sum(axis=1)
    return np.einsum("nz,nz->n", weight, balls.trig[power])


def ball_contacts(geometry: BallGeometry, u: NDArray, balls: BallSet
              ) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """s_x, s_r, 1/|s| and δ₊ of every ball at u, (N, Zmax) [m, m, 1/m, m]."""
    cos, sin = balls.trig[(1, 0)], balls.trig[(0, 1)]
    # each temporary is made once and then updated in place: the chunk's arrays stay in
    # cache and no allocation is repeated
    sx = cos * u[:, 4:5]
    sx += geometry.axial_offset[:, None] + u[:, 0:1]
    sr = cos * u[:, 1:2]
    sr += geometry.radial_offset[:, None]
    if np.any(u[:, 3]):
        sx += sin * u[:, 3:4]
    if np.any(u[:, 2]):
        sr += sin * u[:, 2:3]
    inverse = sx * sx
    inverse += sr * sr
    np.sqrt(inverse, out=inverse)
    deflection = inverse - balls.reach
    np.maximum(deflection, 0.0, out=deflection)
    # a ball touches its rings only between them (α < 90°), and an angular-contact
    # bearing's only on its shoulder (α > 0)
    off = sr <= 0.0
    if geometry.one_sided.any():
        off |= geometry.one_sided[:, None] & (sx <= 0.0)
    np.copyto(deflection, 0.0, where=off)
    np.divide(1.0, inverse, out=inverse)
    return sx, sr, inverse, deflection


def contact_state(geometry: BallGeometry, u: NDArray, balls: BallSet, columns: list[int], *,
           angles: bool = False) -> BallState:
    r"""The contacts at the scaled displacement u = (δx, δy, δz, L·θy, L·θz):

    .. math:: s_x = s_{x0} + δx + L(θ_z\cos ψ + θ_y\sin ψ), \quad
              s_r = s_{r0} + δy\cos ψ + δz\sin ψ, \quad δ = |s| - A, \quad Q = Kδ_+^{3/2}

    The energy Σ 2/5·K·δ₊^(5/2), its gradient Σ Q·∂δ/∂u and its Hessian
    Σ 3/2·K·δ₊^(1/2)·g gᵀ + Q/|s|·t tᵀ (g = n·∂s/∂u, t = n⊥·∂s/∂u, n = s/|s|), along
    the coordinates ``columns``. With ∂s/∂u = (f, 0) for an axial coordinate and (0, f)
    for a radial one, the Hessian's entries are Σ w·f_i·f_j with w = a, b or c for two
    axial, two radial or mixed coordinates (a = k_t + (k_n − k_t)·n_x², b = k_t +
    (k_n − k_t)·n_r², c = (k_n − k_t)·n_x·n_r), the force's Σ Q·n·f.
    """
    sx, sr, inverse, deflection = ball_contacts(geometry, u, balls)
    k = geometry.spring_constant[:, None]
    root = np.sqrt(deflection)
    load = deflection * root
    load *= k
    nx, nr = sx * inverse, sr * inverse
    across = load * inverse
    difference = root * (1.5 * k)
    difference -= across
    weights = {"x": load * nx, "r": load * nr}
    along_x = difference * nx
    weights["xr"] = weights["rx"] = along_x * nr
    along_x *= nx
    along_x += across
    difference *= nr
    difference *= nr
    difference += across
    weights["xx"], weights["rr"] = along_x, difference
    size = len(columns)
    hessian = np.empty((u.shape[0], size, size))
    force = np.empty((u.shape[0], size))
    for i, ci in enumerate(columns):
        axial_i, (a_i, b_i) = _PARTS[ci]
        force[:, i] = _weighed(weights["x" if axial_i else "r"], balls, (a_i, b_i))
        for j in range(i, size):
            axial_j, (a_j, b_j) = _PARTS[columns[j]]
            key = ("x" if axial_i else "r") + ("x" if axial_j else "r")
            hessian[:, i, j] = hessian[:, j, i] = _weighed(weights[key], balls,
                                                           (a_i + a_j, b_i + b_j))
    return BallState(0.4 * np.einsum("nz,nz->n", load, deflection), force, hessian, load,
                  np.arctan2(sx, sr) if angles else None)


def _groove_centres(geometry: BallGeometry, displacement: NDArray, azimuth: NDArray
                    ) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """s_x, s_r, δ = |s| − A and where the model gives a ball no contact (α ≥ 90°, or an
    angular-contact ball at α ≤ 0), (N, Zmax), at the displacement (N, 5) in SI."""
    q = displacement
    cos, sin = np.cos(azimuth), np.sin(azimuth)
    sx = (geometry.axial_offset[:, None] + q[:, 0:1]
          + geometry.lever[:, None] * (q[:, 4:5] * cos + q[:, 3:4] * sin))
    sr = geometry.radial_offset[:, None] + q[:, 1:2] * cos + q[:, 2:3] * sin
    deflection = np.sqrt(sx * sx + sr * sr) - geometry.groove_distance[:, None]
    off = (sr <= 0.0) | (geometry.one_sided[:, None] & (sx <= 0.0))
    return sx, sr, deflection, off


def ball_deflections(geometry: BallGeometry, displacement: NDArray, azimuth: NDArray
                     ) -> NDArray:
    """Every ball's signed deflection δ = |s| − A [m] at the displacement (N, 5): its
    compression where positive, its play where negative (an angular-contact ball off
    its shoulder has no contact: its δ is made negative). ``azimuth`` (N, Zmax) as the
    equilibrium gives it, NaN past Z."""
    _, _, deflection, off = _groove_centres(geometry, displacement, azimuth)
    return np.where(off, -np.abs(deflection), deflection)


def pressed_beyond_contacts(geometry: BallGeometry, displacement: NDArray, azimuth: NDArray
                            ) -> NDArray:
    """Where a ball is pressed (δ > 0) at a place the model gives it no contact, (N,)
    bool: an angular-contact ball pushed past its groove's bottom (α ≤ 0, onto the side
    of the groove a one-sided bearing's model leaves out) or a ring pushed over its
    balls (α ≥ 90°, see :func:`pushed_over_balls`). The rings of such a state rest on
    contacts the model does not hold, so it is no equilibrium of the bearing: a single
    angular-contact bearing with too little axial load reaches one, its ring pushed
    back until its balls sit on the groove's bottom."""
    _, _, deflection, off = _groove_centres(geometry, displacement, azimuth)
    return np.any(off & (deflection > 0.0), axis=1)


def pushed_over_balls(geometry: BallGeometry, displacement: NDArray, azimuth: NDArray
                      ) -> NDArray:
    """Where a ring has been pushed over a ball, (N,) bool: the ball pressed (δ > 0)
    with its groove centres past each other radially (α ≥ 90°), its contact beyond the
    shoulder. A deep-groove bearing reaches it under an axial load when its clearance
    lets the ring move axially by about the grooves' distance."""
    _, sr, deflection, _ = _groove_centres(geometry, displacement, azimuth)
    return np.any((sr <= 0.0) & (deflection > 0.0), axis=1)


class BallContacts(NamedTuple):
    """Every ball's contacts at a displacement in SI (see :func:`ball_contacts_at`)."""

    energy: NDArray            # (N,) Σ 2/5·K·δ₊^(5/2) [J]
    force: NDArray             # (N, 5) the rings' internal force ∂U/∂q [N, N·m]
    stiffness: NDArray         # (N, 5, 5) ∂²U/∂q² [SI]
    element_load: NDArray      # (N, Zmax) Q of each ball, NaN past Z [N]
    contact_angle: NDArray     # (N, Zmax) |α| of each ball's operating contact [rad]
    azimuth: NDArray           # (N, Zmax) ψ of each ball, NaN past Z [rad]
    #: (N,) a ball pressed where the model gives it no contact (see
    #: :func:`pressed_beyond_contacts`)
    beyond_contacts: NDArray


def ball_contacts_at(geometry: BallGeometry, displacement: NDArray) -> BallContacts:
    """The balls' energy, force, tangent stiffness and loads at the inner ring's
    displacement q (N, 5) = (δx, δy, δz, θy, θz) [m, rad], for a caller that solves its
    own equilibrium (a shaft on several bearings): the same contacts as
    :func:`solve_ball_equilibrium`'s, in SI (u = S·q, S = diag(1, 1, 1, L, L): the force
    is S·∂U/∂u, the stiffness S·H·S)."""
    lever = geometry.lever
    to_si = np.array([1.0, 1.0, 1.0, 0.0, 0.0])[None, :] + np.outer(lever, [0, 0, 0, 1, 1])
    width = int(geometry.ball_count.max())
    balls, mask = ball_set(geometry, width)
    state = contact_state(geometry, np.asarray(displacement, dtype=float) * to_si, balls,
                   list(range(5)), angles=True)
    blank = np.where(mask, 1.0, np.nan)
    azimuth = (np.arctan2(balls.trig[(0, 1)], balls.trig[(1, 0)]) % (2.0 * np.pi)) * blank
    return BallContacts(state.energy, state.force * to_si,
                        state.hessian * to_si[:, :, None] * to_si[:, None, :],
                        state.load * blank, np.abs(state.angle) * blank, azimuth,
                        pressed_beyond_contacts(geometry, np.asarray(displacement, dtype=float),
                                                azimuth))
