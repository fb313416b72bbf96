"""A rigid shaft on several bearings as mounted (ISO/TS 16281): the shaft carries the
inner rings, the outer rings sit in a rigid housing, and every bearing's contacts
(balls or laminae, :mod:`bearingcalc.core.iso16281_balls`,
:mod:`bearingcalc.core.iso16281_rollers`) act on it. A matched pair is two bearings
on one shaft, mirrored and set against each other; a drive's shaft is its bearings.

Coordinates as a single bearing's: Q = (δx, δy, δz, θy, θz) of the shaft at x = 0,
θz the tilt that moves the element at azimuth 0 toward +x (the left-handed rotation
about +z), θy the right-handed one about +y. A bearing whose reference point (a ball
bearing's ball plane, a roller bearing's pressure centre) lies at x_i moves with

  q_i = S_i·T_i·Q + o_i·e_x,  T_i·Q = (δx, δy − x_i·θz, δz − x_i·θy, θy, θz),

S_i = diag(1, 1, 1, 1, 1) for a bearing that carries thrust when the shaft moves +x
and diag(−1, 1, 1, −1, −1) for one mirrored in its own plane, o_i the axial offset
that sets it (a pair's −end_play/2). The shaft's internal force is Σ (S_i T_i)ᵀ f_i and
its stiffness Σ (S_i T_i)ᵀ K_i (S_i T_i); the equilibrium minimises the convex
potential Σ U_i(q_i) − F·Q by the damped Newton method of the single bearings.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.iso16281_newton import (
    RESIDUAL_TOLERANCE,
    bracketed_newton,
    damped_newton,
)

#: How many of its levers a shaft may move before its design counts as having no
#: equilibrium (the shaft runs off, the potential unbounded below).
REACH = 4.0
#: The in-plane coordinates (δx, δy, θz), all that move under loads in the radial
#: load's plane.
IN_PLANE = (0, 1, 4)


class ShaftBearing(NamedTuple):
    """One bearing on the shaft, arrays over designs."""

    #: q (N, 5) -> its contacts: an object with ``energy`` (N,), ``force`` (N, 5) and
    #: ``stiffness`` (N, 5, 5) in SI (:func:`~bearingcalc.core.iso16281_balls.
    #: ball_contacts_at` or :func:`~bearingcalc.core.iso16281_rollers.roller_contacts_at`
    #: with its geometry bound)
    contacts: Callable[[NDArray], Any]
    #: x_i, its reference point on the shaft's axis [m]
    position: NDArray
    #: +1: carries thrust when the shaft moves +x; −1: mirrored (or (N,) of them)
    orientation: ArrayLike
    #: o_i, added to its own δx [m]
    offset: NDArray


class ShaftEquilibrium(NamedTuple):
    """The solved shaft, arrays over designs."""

    displacement: NDArray      # Q (N, 5) [m, rad]
    local: list[NDArray]       # each bearing's q_i (N, 5)
    contacts: list[Any]        # each bearing's contacts at its q_i
    force: NDArray             # (N, 5) Σ (S T)ᵀ f_i, the contacts' force on the shaft
    stiffness: NDArray         # (N, 5, 5) the shaft's tangent stiffness [SI]
    residual: NDArray          # (N,) [1]
    converged: NDArray         # (N,) bool


def transfer(position: ArrayLike, orientation: ArrayLike) -> NDArray:
    """S·T of a bearing at x_i (N,) with its orientation (±1, or (N,) of them): (N, 5, 5),
    q_i − o_i·e_x = (S·T)·Q."""
    x = np.atleast_1d(np.asarray(position, dtype=float))
    matrix = np.zeros((x.size, 5, 5))
    matrix[:, range(5), range(5)] = 1.0
    matrix[:, 1, 4] = -x
    matrix[:, 2, 3] = -x
    s = np.broadcast_to(np.asarray(orientation, dtype=float), x.shape)
    mirror = np.stack([s, np.ones_like(s), np.ones_like(s), s, s], axis=1)
    return matrix * mirror[:, :, None]


class _Shaft(NamedTuple):
    energy: NDArray
    force: NDArray
    stiffness: NDArray
    local: list[NDArray]
    contacts: list[Any]


def shaft_state(bearings: Sequence[ShaftBearing], matrices: Sequence[NDArray],
                displacement: NDArray) -> _Shaft:
    """The bearings' energy, force on the shaft and stiffness at its displacement Q."""
    energy = np.zeros(displacement.shape[0])
    force = np.zeros_like(displacement)
    stiffness = np.zeros((displacement.shape[0], 5, 5))
    local, contacts = [], []
    for bearing, matrix in zip(bearings, matrices, strict=True):
        q = np.einsum("nij,nj->ni", matrix, displacement)
        q[:, 0] += bearing.offset
        state = bearing.contacts(q)
        energy += state.energy
        force += np.einsum("nji,nj->ni", matrix, state.force)
        stiffness += np.swapaxes(matrix, 1, 2) @ state.stiffness @ matrix
        local.append(q)
        contacts.append(state)
    return _Shaft(energy, force, stiffness, local, contacts)


def solve_shaft(bearings: Sequence[ShaftBearing], load: ArrayLike, lever: ArrayLike, *,
                fixed_tilt: ArrayLike | None = None, start: ArrayLike | None = None
                ) -> ShaftEquilibrium:
    """The shaft's displacement under ``load`` (N, 5) = (Fx, Fy, Fz, My, Mz) at x = 0
    [N, N·m], each bearing's contacts there and the shaft's tangent stiffness.

    ``lever`` (N,) [m] puts tilts on the scale of lengths (the bearings' spread or
    pitch radius). Where every load lies in the radial load's plane only (δx, δy, θz)
    move; ``fixed_tilt`` holds θz (an imposed misalignment). ``converged`` is False where
    no equilibrium was found (the loads pull the bearings off their contacts).
    """
    n = np.shape(bearings[0].offset)[0]
    applied = np.broadcast_to(np.asarray(load, dtype=float), (n, 5))
    matrices = [transfer(np.broadcast_to(b.position, (n,)), b.orientation)
                for b in bearings]
    free = list(IN_PLANE) if not np.any(applied[:, [2, 3]]) else list(range(5))
    q = np.zeros((n, 5)) if start is None else np.array(start, dtype=float)
    if fixed_tilt is not None:
        free = [d for d in free if d != 4]
        q[:, 4] = np.broadcast_to(np.asarray(fixed_tilt, dtype=float), (n,))
    scale = np.ones((n, 5))
    scale[:, 3:] = np.broadcast_to(np.asarray(lever, dtype=float), (n,))[:, None]
    q, residual = _newton(bearings, matrices, q, applied, free, scale)
    state = shaft_state(bearings, matrices, q)
    # a stationary point with an element pressed where its bearing's model gives it no
    # contact is no equilibrium of the shaft
    beyond = np.logical_or.reduce([contacts.beyond_contacts for contacts in state.contacts])
    return ShaftEquilibrium(q, state.local, state.contacts, state.force, state.stiffness,
                            residual, (residual <= RESIDUAL_TOLERANCE) & ~beyond)


def _typical_stiffness(bearings: Sequence[ShaftBearing], matrices: Sequence[NDArray],
                       scale: NDArray) -> NDArray:
    """A stiffness scale of each design [N/m]: the trace of the shaft's scaled stiffness
    with every bearing pushed 10 µm into its contacts, axially and radially (only the
    size of the Newton method's damping follows from it)."""
    n = scale.shape[0]
    total = np.zeros(n)
    for bearing, matrix in zip(bearings, matrices, strict=True):
        probe = np.zeros((n, 5))
        probe[:, 0] = np.maximum(-bearing.offset, 0.0) + 1e-5
        probe[:, 1] = 1e-5
        stiffness = np.swapaxes(matrix, 1, 2) @ bearing.contacts(probe).stiffness @ matrix
        total += np.trace(stiffness / scale[:, :, None] / scale[:, None, :], axis1=1,
                          axis2=2) / 5.0
    return np.where(total > 0.0, total, 1e8)


class _Potential(NamedTuple):
    energy: NDArray
    force: NDArray
    hessian: NDArray


def _newton(bearings: Sequence[ShaftBearing], matrices: Sequence[NDArray], q: NDArray,
            applied: NDArray, free: list[int], scale: NDArray) -> tuple[NDArray, NDArray]:
    """The shaft's equilibrium by :func:`~bearingcalc.core.iso16281_newton.damped_newton`
    on U(Q) = Σ U_i(q_i) − F·Q over the ``free`` coordinates. Returns Q and the relative
    residual."""
    moving = np.zeros(q.shape, dtype=bool)
    moving[:, free] = True

    def potential(trial: NDArray) -> _Potential:
        state = shaft_state(bearings, matrices, trial)
        return _Potential(state.energy, state.force, state.stiffness)

    # the bearings' own forces at the start (a pair's preload) cancel on the shaft, but
    # they set the rounding of the sum
    start = shaft_state(bearings, matrices, q)
    internal = sum(np.max(np.abs(contacts.force[:, :3]), axis=1)
                   for contacts in start.contacts)
    # no equilibrium moves the shaft by several of its levers: one that runs off has none
    return damped_newton(potential, q, applied, moving, scale,
                         _typical_stiffness(bearings, matrices, scale), internal,
                         reach=REACH * scale[:, 3])



def axial_deflection_for_load(contacts: Callable[[NDArray], Any], load: ArrayLike,
                              upper: ArrayLike = 1e-3) -> NDArray:
    r"""The axial displacement δa [m] of one bearing's inner ring (from its own datum)
    at which its contacts carry the axial ``load`` [N] alone, q = (δa, 0, 0, 0, 0):

    .. math:: F_x(δ_a) = \text{load}

    F_x grows with δa, so Newton's steps on it (its slope the contacts' K_xx) are kept
    inside a bracket that bisection narrows where a step would leave it; the bracket
    starts at 0 and ``upper`` and widens until it holds the load. A pair set to a
    preload P at rest has each bearing at δa(P). Source: ISO/TS 16281:2008, 6 (the
    single bearing's equilibrium).
    """
    target = np.atleast_1d(np.asarray(load, dtype=float))
    low = np.zeros_like(target)
    high = np.broadcast_to(np.asarray(upper, dtype=float), target.shape).copy()

    def axial(deflection: NDArray) -> tuple[NDArray, NDArray]:
        q = np.zeros((target.size, 5))
        q[:, 0] = deflection
        state = contacts(q)
        return state.force[:, 0], state.stiffness[:, 0, 0]

    # widen the bracket until it holds the load (a preload that crushes the contacts
    # is then refused by their check, not cut short here)
    for _ in range(20):
        short = axial(high)[0] < target
        if not short.any():
            break
        low = np.where(short, high, low)
        high = np.where(short, 2.0 * high, high)
    def axial_error(deflection: NDArray) -> tuple[NDArray, NDArray, NDArray]:
        force, slope = axial(deflection)
        return force - target, slope, 1e-13 * target

    return bracketed_newton(axial_error, 0.5 * (low + high), low, high)
