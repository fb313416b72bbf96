"""The load on every ball of a radial ball bearing from the rings' displacements
(ISO/TS 16281:2008, 5 to 7): rigid rings, elastic Hertz contacts, low speed.

Vectorised over designs: every input is an array over N designs (or a scalar), the balls
of each design padded to the largest count and masked. The equilibrium is found by a
damped Newton method on the bearing's potential energy, which is convex in the inner
ring's displacement, with its analytic gradient (the ring's internal force) and Hessian
(the tangent stiffness), on chunks of designs small enough for their per-ball arrays to
stay in cache, from a start at the play along each load plus a deflection estimate.

Frame and signs: x along the bearing axis, positive along the axial load on the inner
ring; y along the radial load; the ball at azimuth ψ = 0 on +y, ψ counted toward +z. The
inner ring's displacement relative to the outer ring is q = (δx, δy, δz, θy, θz) [m, m,
m, rad, rad]; a positive θz (and tilting moment Mz) increases the axial approach of the
ball at ψ = 0. The loads F = (Fx, Fy, Fz, My, Mz) act on the inner ring at the bearing's
centre plane, work-conjugate to q.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.iso16281_ball_contacts import (
    BallGeometry,
    BallSet,
    ball_set,
    contact_state,
    pressed_beyond_contacts,
)

#: The displacements' order, and the stiffness matrix's.
DEGREES_OF_FREEDOM = ("x", "y", "z", "tilt_y", "tilt_z")
#: The degrees of freedom a load in the plane of the radial load moves: δx, δy, θz.
IN_PLANE = (0, 1, 4)
#: The relative residual at which the equilibrium counts as found.
RESIDUAL_TOLERANCE = 1e-12
MAX_ITERATIONS = 80
#: The Levenberg–Marquardt damping of the first step, relative to Z·K·√|u|: the undamped
#: step from the rough start is often too long and refused. Not larger: from 1e-3 on, an
#: angular-contact bearing with no axial load slides to a stationary point with its ring
#: pulled through the balls (contact angles past 90°) instead of failing.
INITIAL_DAMPING = 1e-4


class BallEquilibrium(NamedTuple):
    """The solved bearing, arrays over designs (and balls, padded with NaN)."""

    displacement: NDArray      # q, (N, 5) [m, rad]
    reaction: NDArray          # the rings' internal force at q, (N, 5) [N, N·m]
    azimuth: NDArray           # ψ of each ball, (N, Zmax) [rad]
    element_load: NDArray      # Q of each ball, (N, Zmax) [N]
    contact_angle: NDArray     # |α| of each ball's operating contact, (N, Zmax) [rad]
    stiffness: NDArray         # the tangent stiffness ∂F/∂q, (N, 5, 5) [SI]
    residual: NDArray          # the relative equilibrium residual, (N,) [1]
    converged: NDArray         # (N,) bool


#: Designs solved together: a chunk's (designs × balls) temporaries stay in cache.
CHUNK = 1 << 11


def solve_ball_equilibrium(geometry: BallGeometry, load: ArrayLike, *,
                           fixed_tilt: ArrayLike | None = None) -> BallEquilibrium:
    """The inner ring's displacement under ``load`` (N, 5) = (Fx, Fy, Fz, My, Mz) [N, N·m],
    each ball's load and contact angle, and the tangent stiffness there.

    Where the loads lie in the plane of the radial load (Fz = My = 0) only the in-plane
    degrees of freedom (δx, δy, θz) move, the others staying 0 by symmetry; else all
    five.
    With ``fixed_tilt`` (the imposed misalignment θz [rad]) the tilt is held and its
    moment is a result (``reaction``). ``converged`` is False where no equilibrium was
    found (an angular-contact bearing that the loads pull off its contacts).
    """
    lever = geometry.lever
    n = geometry.ball_count.size
    applied = np.broadcast_to(np.asarray(load, dtype=float), (n, 5)).copy()
    # moments as forces at the lever L, so that every coordinate is a length
    target = applied / (np.array([1.0, 1.0, 1.0, 0.0, 0.0])[None, :]
                        + np.outer(lever, [0.0, 0.0, 0.0, 1.0, 1.0]))
    out_of_plane = bool(np.any(target[:, [2, 3]] != 0.0))
    free = list(IN_PLANE) if not out_of_plane else list(range(5))
    if fixed_tilt is not None:
        free = [0, 1, 2] if out_of_plane else [0, 1]
    u = _start(geometry, target)
    if fixed_tilt is not None:
        u[:, 4] = np.broadcast_to(np.asarray(fixed_tilt, dtype=float), (n,)) * lever
    width = int(geometry.ball_count.max())
    residual, force, hessian = np.empty(n), np.empty((n, 5)), np.empty((n, 5, 5))
    azimuth, loads, angles = (np.empty((n, width)) for _ in range(3))
    for first in range(0, n, CHUNK):
        rows = slice(first, first + CHUNK)
        (u[rows], residual[rows], force[rows], hessian[rows], azimuth[rows], loads[rows],
         angles[rows]) = _solve_chunk(_take(geometry, rows), u[rows], target[rows], free,
                                      width)
    # u = S·q with S = diag(1, 1, 1, L, L): the force is S·∂U/∂u, the stiffness S·H·S
    to_si = np.array([1.0, 1.0, 1.0, 0.0, 0.0])[None, :] + np.outer(lever, [0, 0, 0, 1, 1])
    displacement = u / to_si
    # a stationary point with a ball pressed where the model gives it no contact is no
    # equilibrium of the bearing (the one-sided contacts make the potential non-convex)
    holds = ~pressed_beyond_contacts(geometry, displacement, azimuth)
    return BallEquilibrium(displacement, force * to_si, azimuth, loads, angles,
                           hessian * to_si[:, :, None] * to_si[:, None, :], residual,
                           (residual <= RESIDUAL_TOLERANCE) & holds)


def _solve_chunk(geometry: BallGeometry, u: NDArray, target: NDArray, free: list[int],
                 width: int) -> tuple[NDArray, ...]:
    """One chunk's equilibrium: u, the residual, the force and Hessian in all five
    coordinates, and each ball's azimuth, load and |contact angle| (NaN for padding)."""
    balls, mask = ball_set(geometry, width)
    u, residual = _newton(geometry, u, target, free, balls)
    state = contact_state(geometry, u, balls, list(range(5)), angles=True)
    blank = np.where(mask, 1.0, np.nan)
    azimuth = np.arctan2(balls.trig[(0, 1)], balls.trig[(1, 0)]) % (2.0 * np.pi)
    return (u, residual, state.force, state.hessian, azimuth * blank, state.load * blank,
            np.abs(state.angle) * blank)


def _start(geometry: BallGeometry, target: NDArray) -> NDArray:
    """A first displacement that brings the balls under the load into contact: the
    first-contact play along each load, plus the deflection that would carry it on a
    fifth of the balls; axially, where every ball would carry an equal share."""
    u = np.zeros_like(target)
    a, x0, r0 = geometry.groove_distance, geometry.axial_offset, geometry.radial_offset
    share = np.maximum(geometry.ball_count / 5.0, 1.0) * geometry.spring_constant
    radial_play = np.maximum(a - np.hypot(x0, r0), 0.0)
    axial_play = np.sqrt(np.maximum(a * a - r0 * r0, 0.0)) - x0
    for d, play in ((0, np.maximum(axial_play, 0.0)), (1, radial_play), (2, radial_play),
                    (3, np.maximum(axial_play, 0.0)), (4, np.maximum(axial_play, 0.0))):
        u[:, d] = np.sign(target[:, d]) * (play + (np.abs(target[:, d]) / share) ** (2 / 3))
    u[:, 0] = np.sign(target[:, 0]) * _axial_start(geometry, np.abs(target[:, 0]))
    return u




def _axial_start(geometry: BallGeometry, force: NDArray) -> NDArray:
    """The axial displacement at which every ball carries an equal share of ``force``
    [m]: F = Z·K·δ^1.5·sin α, sin α = s_x/(A + δ), s_x² = (A + δ)² − s_r0², by a few
    fixed-point steps on δ (a contraction: δ enters the right side at a power ≤ 1/3)."""
    a, x0, r0 = geometry.groove_distance, geometry.axial_offset, geometry.radial_offset
    zk = geometry.ball_count * geometry.spring_constant
    # a preloaded ring's balls are deflected by s_r0 − A at least; sin α ≥ 1e-3 bounds
    # the estimate of a bearing at zero clearance
    least = np.maximum(r0 - a, 0.0)
    deflection = np.maximum((force / zk) ** (2 / 3), least)
    for _ in range(6):
        axial = np.sqrt(np.maximum((a + deflection) ** 2 - r0 * r0, (1e-3 * a) ** 2))
        deflection = np.maximum((force * (a + deflection) / (zk * axial)) ** (2 / 3), least)
    return np.sqrt(np.maximum((a + deflection) ** 2 - r0 * r0, 0.0)) - x0


def _solve(matrix: NDArray, vector: NDArray) -> NDArray:
    """x of M·x = v for each design, (N, k): a symmetric 3×3 M by its cofactors (a
    quarter of LAPACK's time on small batches), any other by LAPACK."""
    if matrix.shape[1] != 3:
        return np.linalg.solve(matrix, vector[..., None])[..., 0]
    a00, a01, a02 = matrix[:, 0, 0], matrix[:, 0, 1], matrix[:, 0, 2]
    a11, a12, a22 = matrix[:, 1, 1], matrix[:, 1, 2], matrix[:, 2, 2]
    c00, c01, c02 = a11 * a22 - a12 * a12, a02 * a12 - a01 * a22, a01 * a12 - a02 * a11
    c11, c12, c22 = a00 * a22 - a02 * a02, a01 * a02 - a00 * a12, a00 * a11 - a01 * a01
    v0, v1, v2 = vector[:, 0], vector[:, 1], vector[:, 2]
    inverse_det = 1.0 / (a00 * c00 + a01 * c01 + a02 * c02)
    return np.stack([c00 * v0 + c01 * v1 + c02 * v2, c01 * v0 + c11 * v1 + c12 * v2,
                     c02 * v0 + c12 * v1 + c22 * v2], axis=1) * inverse_det[:, None]


def _take(geometry: BallGeometry, rows: NDArray | slice) -> BallGeometry:
    return BallGeometry(*(values[rows] for values in geometry))


def _newton(geometry: BallGeometry, u: NDArray, target: NDArray, free: list[int],
            balls: BallSet) -> tuple[NDArray, NDArray]:
    """Damped Newton on U(u) = Σ 2/5·K·δ₊^(5/2) − F·u over the ``free`` coordinates, on
    the designs not yet solved: a step is taken where it lowers U (Armijo) or halves the
    residual, else the damping grows tenfold; the contacts at a step taken are those
    the next iteration starts from. Returns u and the relative residual."""
    n = u.shape[0]
    u = u.copy()
    typical = geometry.ball_count * geometry.spring_constant * np.sqrt(
        np.maximum(np.abs(u).max(axis=1), geometry.groove_distance * 1e-6))
    damping = np.full(n, INITIAL_DAMPING)
    residual = np.full(n, np.inf)
    goal = target[:, free]
    size = np.maximum(np.max(np.abs(goal), axis=1), 1e-300)
    eye = np.eye(len(free))
    state = contact_state(geometry, u, balls, free)
    energy, force, hessian = state.energy - np.einsum("nd,nd->n", goal, u[:, free]), \
        state.force, state.hessian
    active, rows = np.arange(n), slice(None)
    for _ in range(MAX_ITERATIONS):
        gradient = force[rows] - goal[rows]
        residual[rows] = np.max(np.abs(gradient), axis=1) / np.maximum(
            size[rows], np.max(np.abs(force[rows]), axis=1))
        unsolved = residual[rows] > RESIDUAL_TOLERANCE
        active, gradient = active[unsolved], gradient[unsolved]
        if active.size == 0:
            break
        # while every design is unsolved, views instead of copies
        rows = active if active.size < n else slice(None)
        damped = hessian[rows] + (damping[rows] * typical[rows])[:, None, None] * eye
        step = -_solve(damped, gradient)
        trial = u[active]
        trial[:, free] += step
        new = contact_state(_take(geometry, rows), trial, balls.take(rows), free)
        energy_new = new.energy - np.einsum("nd,nd->n", goal[rows], trial[:, free])
        # near the solution U's change is lost in its rounding: a step that shrinks the
        # residual counts as well
        shrinks = (np.max(np.abs(new.force - goal[rows]), axis=1)
                   < 0.5 * np.max(np.abs(gradient), axis=1))
        better = (energy_new <= energy[rows] + 1e-4 * np.einsum("nd,nd->n", gradient, step)
                  ) | shrinks
        taken = active[better]
        u[taken], energy[taken] = trial[better], energy_new[better]
        force[taken], hessian[taken] = new.force[better], new.hessian[better]
        damping[rows] = np.where(better, np.maximum(damping[rows] / 10.0, 1e-14),
                                 damping[rows] * 10.0)
    return u, residual
