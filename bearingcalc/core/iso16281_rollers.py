"""The load on every lamina of every roller of a cylindrical or tapered roller bearing
from the rings' displacements (ISO/TS 16281:2008, 5 to 7): rigid rings, each roller cut
into laminae along the raceway that carry q = (c_L/n_s)·δ^(10/9), low speed.

Frame, signs and the displacement q = (δx, δy, δz, θy, θz) as in
:mod:`bearingcalc.core.iso16281_balls`; for a tapered bearing the loads act at its
pressure centre and α is the cup's contact angle, for the cone's motion and the
roller's equilibrium alike. A cylindrical bearing carries no axial load: its δx is held
at 0. Vectorised over designs in chunks (rollers padded to the largest count, masked).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.iso16281_newton import RESIDUAL_TOLERANCE, damped_newton

#: ISO/TS 16281's line-contact constant c_L = 35 948·Lwe^(8/9) N/mm^(10/9) of a roller
#: (both contacts), in SI: N/m^(10/9) per m^(8/9).
LINE_CONSTANT = 35948.0 * 1e3 ** (10 / 9) * 1e3 ** (8 / 9)
#: The lamina law's exponent, q ∝ δ^(10/9).
LAMINA_EXPONENT = 10.0 / 9.0
#: How many of its rollers' half lengths a ring may move before its design counts as
#: having no equilibrium (its ring runs off, the potential unbounded below): far past
#: any displacement of a bearing that holds, even a one-way bearing's just above the
#: axial load it needs, whose ring moves some millimetres along its axis.
REACH = 40.0
#: Designs solved together: a chunk's (designs, rollers, laminae) arrays stay small.
CHUNK = 512


class RollerGeometry(NamedTuple):
    """A roller bearing's laminae, arrays over designs. [m, rad, N/m^(10/9)]"""

    roller_count: NDArray
    contact_angle: NDArray     # α (tapered: the cup's)
    gap: NDArray               # (N, n_s) each lamina's gap at q = 0: (Pd/2)·cosα + 2·p_k
    positions: NDArray         # (N, n_s) ℓ_k along the raceway from the roller's middle
    lamina_constant: NDArray   # c_L/n_s of one lamina


class RollerEquilibrium(NamedTuple):
    displacement: NDArray      # (N, 5) [m, rad]
    reaction: NDArray          # (N, 5) [N, N·m]
    azimuth: NDArray           # (N, Zmax) [rad], NaN past Z
    element_load: NDArray      # (N, Zmax) each roller's load, the sum of its laminae [N]
    lamina_load: NDArray       # (N, Zmax, n_s) [N]
    stiffness: NDArray         # (N, 5, 5) [SI]
    residual: NDArray          # (N,) [1]
    converged: NDArray         # (N,) bool


def logarithmic_profile(positions: NDArray, roller_diameter: ArrayLike,
                        effective_length: ArrayLike) -> NDArray:
    r"""ISO/TS 16281's logarithmic profile drop p_k [m] of a roller at ℓ_k from its middle:

    .. math:: L_{we} \le 2.5D_{we}:\ p = 0.00035\,D_{we}\ln\frac{1}{1 - (2ℓ/L_{we})^2}

    .. math:: L_{we} > 2.5D_{we}:\ p = 0.0005\,D_{we}\ln\frac{1}{1 - \left(
              \frac{2|ℓ| - L_{we} + 2.5D_{we}}{2.5D_{we}}\right)^2}\ \text{past the flat
              middle } |ℓ| \le (L_{we} - 2.5D_{we})/2,\ 0\ \text{on it}

    Source: ISO/TS 16281:2008, 7.2 (eqs. 42 to 44).
    """
    dwe = np.asarray(roller_diameter, dtype=float)[..., None]
    lwe = np.asarray(effective_length, dtype=float)[..., None]
    ell = np.abs(positions)
    short = 0.00035 * dwe * -np.log(1.0 - (2.0 * ell / lwe) ** 2)
    u = np.clip((2.0 * ell - lwe + 2.5 * dwe) / (2.5 * dwe), 0.0, None)
    long = 0.0005 * dwe * -np.log(1.0 - u * u)
    return np.where(lwe <= 2.5 * dwe, short, long)


def crowned_profile(positions: NDArray, crown_radius: ArrayLike) -> NDArray:
    r"""The drop p_k [m] of a roller crowned by one circular arc of radius R over its
    length, at ℓ_k from its middle:

    .. math:: p = R - \sqrt{R^2 - ℓ^2}

    Source: Harris & Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., 1.7
    (crowned rollers).
    """
    radius = np.asarray(crown_radius, dtype=float)[..., None]
    return radius - np.sqrt(radius * radius - positions * positions)


def roller_geometry(roller_count: ArrayLike, roller_diameter: ArrayLike,
                    effective_length: ArrayLike, contact_angle: ArrayLike, *,
                    diametral_clearance: ArrayLike = 0.0, laminae: ArrayLike = 30,
                    profile: str = "iso", line_constant: ArrayLike | None = None,
                    crown_radius: ArrayLike | None = None, row_distance: ArrayLike = 0.0
                    ) -> RollerGeometry:
    """The laminae of each design: n_s slices of Lwe/n_s, their positions, gaps (the
    clearance along the contact normal and the profile at both contacts) and constant.
    ``profile``: "iso" (ISO/TS 16281's logarithmic profile), "none" or "crown" (one arc
    of ``crown_radius``). ``laminae`` may differ between designs: a design's laminae past
    its own count are padding, at an infinite gap, so they never touch.

    A design with a ``row_distance`` d > 0 has two rows: two rollers at each azimuth
    whose middles lie d apart along the axis (0: a single row). Roller j's laminae are
    then the first row's n_s (at ℓ_k − d/2) and the second's (at ℓ_k + d/2), each row
    padded to the largest n_s, each profiled about its own middle."""
    arrays = np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, dtype=float)) for v in (
        roller_count, roller_diameter, effective_length, contact_angle, diametral_clearance,
        np.inf if crown_radius is None else crown_radius, laminae, row_distance)))
    count, dwe, lwe, alpha, clearance, crown, slices, distance = arrays
    k = np.arange(int(slices.max()))[None, :]
    real = k < slices[:, None]
    positions = np.where(real, (k - slices[:, None] / 2.0 + 0.5) * (lwe / slices)[:, None],
                         0.0)
    if profile == "none":
        drop = np.zeros_like(positions)
    elif profile == "crown":
        drop = crowned_profile(positions, crown)
    else:
        drop = logarithmic_profile(positions, dwe, lwe)
    gap = np.where(real, (clearance * np.cos(alpha) / 2.0)[:, None] + 2.0 * drop, np.inf)
    if distance.max() > 0.0:
        double = (distance > 0.0)[:, None]
        half = np.where(double, distance[:, None] / 2.0, 0.0)
        positions = np.concatenate([np.where(real, positions - half, 0.0),
                                    np.where(real & double, positions + half, 0.0)], axis=1)
        gap = np.concatenate([gap, np.where(double, gap, np.inf)], axis=1)
    constant = (LINE_CONSTANT * lwe ** (8 / 9) if line_constant is None
                else np.broadcast_to(np.asarray(line_constant, dtype=float), lwe.shape))
    return RollerGeometry(count, alpha, gap, positions, constant / slices)


def row_loads(lamina_load: NDArray, rows: int) -> NDArray:
    """Each row's roller loads (N, Zmax, ``rows``) [N] from the laminae (N, Zmax,
    rows·n_s) of :func:`roller_geometry`'s layout, NaN past Z."""
    n, z, width = lamina_load.shape
    return np.sum(lamina_load.reshape(n, z, rows, width // rows), axis=3)


def lamina_deflections(geometry: RollerGeometry, displacement: NDArray, azimuth: NDArray
                       ) -> NDArray:
    """Every lamina's signed deflection δ_jk [m], (N, Zmax, n_s), at the displacement
    (N, 5): its compression where positive, its play where negative. ``azimuth``
    (N, Zmax) as the equilibrium gives it, NaN past Z (and so its deflections)."""
    q = displacement
    alpha = geometry.contact_angle[:, None]
    cos, sin = np.cos(azimuth), np.sin(azimuth)
    approach = np.sin(alpha) * q[:, 0:1] + np.cos(alpha) * (cos * q[:, 1:2] + sin * q[:, 2:3])
    tilt = cos * q[:, 4:5] + sin * q[:, 3:4]
    return (approach[..., None] - geometry.positions[:, None, :] * tilt[..., None]
            - geometry.gap[:, None, :])


class _State(NamedTuple):
    energy: NDArray
    force: NDArray
    hessian: NDArray
    lamina: NDArray


class _Rollers(NamedTuple):
    """Every roller of a set of designs, (N, Zmax): cos ψ and sin ψ (0 for padding), an
    offset that keeps a padded roller off its raceways (0, or +inf), and the laminae's
    positions ℓ_k and ℓ_k² (N, n_s)."""

    cos: NDArray
    sin: NDArray
    padding: NDArray
    positions: NDArray
    squares: NDArray


def _rollers(geometry: RollerGeometry, azimuth: NDArray, mask: NDArray) -> _Rollers:
    cos = np.where(mask, np.cos(azimuth), 0.0)
    sin = np.where(mask, np.sin(azimuth), 0.0)
    return _Rollers(cos, sin, np.where(mask, 0.0, np.inf), geometry.positions,
                    geometry.positions ** 2)


def _state(geometry: RollerGeometry, rollers: _Rollers, q: NDArray) -> _State:
    r"""The laminae at q: the energy Σ (c/n_s)·9/19·δ₊^(19/9), its gradient Σ q_jk·g_jk
    and Hessian Σ (10/9)(c/n_s)·δ₊^(1/9)·g_jk g_jkᵀ, with

    .. math:: δ_{jk} = a_j - ℓ_k b_j - \text{gap}_k, \quad a_j = δ_x\sinα
              + (δ_y\cosψ_j + δ_z\sinψ_j)\cosα, \quad b_j = θ_z\cosψ_j + θ_y\sinψ_j

    and g_jk = (sinα, cosα·cosψ_j, cosα·sinψ_j, −ℓ_k sinψ_j, −ℓ_k cosψ_j): every sum over
    a roller's laminae is formed once (its load, moment and the slopes' moments of order
    0, 1 and 2), so each entry is a sum over the rollers alone.
    """
    sa = np.sin(geometry.contact_angle)[:, None]
    ca = np.cos(geometry.contact_angle)[:, None]
    cos, sin = rollers.cos, rollers.sin
    approach = sa * q[:, 0:1] + ca * (cos * q[:, 1:2] + sin * q[:, 2:3]) - rollers.padding
    tilt = cos * q[:, 4:5] + sin * q[:, 3:4]
    # each temporary of (designs, rollers, laminae) made once and updated in place
    deflection = rollers.positions[:, None, :] * tilt[..., None]
    np.subtract(approach[..., None], deflection, out=deflection)
    deflection -= geometry.gap[:, None, :]
    np.maximum(deflection, 0.0, out=deflection)
    c = geometry.lamina_constant[:, None, None]
    slope = np.cbrt(deflection)
    np.cbrt(slope, out=slope)
    lamina = deflection * slope
    lamina *= c
    slope *= LAMINA_EXPONENT * c
    load = lamina.sum(axis=2)
    moment = np.einsum("nzk,nk->nz", lamina, rollers.positions)
    slopes = (slope.sum(axis=2), np.einsum("nzk,nk->nz", slope, rollers.positions),
              np.einsum("nzk,nk->nz", slope, rollers.squares))
    trig = {"1": np.ones_like(cos), "c": cos, "s": sin, "cc": cos * cos, "cs": cos * sin,
            "ss": sin * sin}

    def total(weight: NDArray, key: str) -> NDArray:
        return np.einsum("nz,nz->n", weight, trig[key])

    force = np.stack([sa[:, 0] * load.sum(axis=1), ca[:, 0] * total(load, "c"),
                      ca[:, 0] * total(load, "s"), -total(moment, "s"),
                      -total(moment, "c")], axis=1)
    s0, s1, s2 = slopes
    sa, ca = sa[:, 0], ca[:, 0]
    entries = {(0, 0): sa * sa * total(s0, "1"), (0, 1): sa * ca * total(s0, "c"),
               (0, 2): sa * ca * total(s0, "s"), (0, 3): -sa * total(s1, "s"),
               (0, 4): -sa * total(s1, "c"), (1, 1): ca * ca * total(s0, "cc"),
               (1, 2): ca * ca * total(s0, "cs"), (1, 3): -ca * total(s1, "cs"),
               (1, 4): -ca * total(s1, "cc"), (2, 2): ca * ca * total(s0, "ss"),
               (2, 3): -ca * total(s1, "ss"), (2, 4): -ca * total(s1, "cs"),
               (3, 3): total(s2, "ss"), (3, 4): total(s2, "cs"), (4, 4): total(s2, "cc")}
    hessian = np.empty((q.shape[0], 5, 5))
    for (i, j), value in entries.items():
        hessian[:, i, j] = hessian[:, j, i] = value
    return _State(np.einsum("nzk,nzk->n", lamina, deflection) * 9.0 / 19.0, force, hessian,
                  lamina)


def solve_roller_equilibrium(geometry: RollerGeometry, load: ArrayLike, *,
                             fixed_tilt: ArrayLike | None = None) -> RollerEquilibrium:
    """The inner ring's displacement under ``load`` (N, 5), every lamina's load, the
    tangent stiffness; ``fixed_tilt`` holds θz (a misalignment). A cylindrical bearing's
    δx is held at 0."""
    n = geometry.roller_count.size
    applied = np.broadcast_to(np.asarray(load, dtype=float), (n, 5))
    tilt = np.zeros(n) if fixed_tilt is None else np.broadcast_to(
        np.asarray(fixed_tilt, dtype=float), (n,))
    parts = [_solve_chunk(RollerGeometry(*(v[s] for v in geometry)), applied[s], tilt[s],
                          fixed_tilt is not None)
             for s in (slice(i, i + CHUNK) for i in range(0, n, CHUNK))]
    zmax = int(geometry.roller_count.max())

    def joined(index: int) -> NDArray:
        pieces = [p[index] for p in parts]
        if pieces[0].ndim >= 2 and index in (2, 3, 4):
            pieces = [np.pad(p, [(0, 0), (0, zmax - p.shape[1])] + [(0, 0)] * (p.ndim - 2),
                             constant_values=np.nan) for p in pieces]
        return np.concatenate(pieces)

    return RollerEquilibrium(*(joined(i) for i in range(8)))


def _solve_chunk(geometry: RollerGeometry, applied: NDArray, tilt: NDArray, fixed: bool
                 ) -> tuple[NDArray, ...]:
    count = geometry.roller_count.astype(int)
    j = np.arange(int(count.max()))
    mask = j[None, :] < count[:, None]
    psi = 2.0 * np.pi * j[None, :] / count[:, None]
    rollers = _rollers(geometry, psi, mask)
    out_of_plane = bool(np.any(applied[:, [2, 3]] != 0.0))
    free = [0, 1, 2, 3, 4] if out_of_plane else [0, 1, 4]
    if fixed:
        free = [d for d in free if d != 4]
    cylindrical = geometry.contact_angle == 0.0
    q = np.zeros_like(applied)
    q[:, 4] = tilt
    q[:, 1] = np.sign(applied[:, 1]) * geometry.gap.min(axis=1) / np.maximum(
        np.cos(geometry.contact_angle), 1e-3)
    q, residual = _newton(geometry, rollers, q, applied, free, cylindrical)
    state = _state(geometry, rollers, q)
    blank = np.where(mask, 1.0, np.nan)
    return (q, state.force, (psi % (2 * np.pi)) * blank, state.lamina.sum(axis=2) * blank,
            np.where(mask[..., None], state.lamina, np.nan), state.hessian, residual,
            residual <= RESIDUAL_TOLERANCE)


def _newton(geometry: RollerGeometry, rollers: _Rollers, q: NDArray,
            applied: NDArray, free: list[int], cylindrical: NDArray
            ) -> tuple[NDArray, NDArray]:
    """The laminae's equilibrium by :func:`~bearingcalc.core.iso16281_newton.damped_newton`
    on U(q) = Σ (c/n_s)·9/19·δ₊^(19/9) − F·q, tilts scaled by the roller's half length;
    a cylindrical bearing's δx held. Returns q and the relative residual."""
    n = q.shape[0]
    lever = np.abs(geometry.positions).max(axis=1)
    scale = np.ones((n, 5))
    scale[:, 3:] = lever[:, None]
    moving = np.zeros((n, 5), dtype=bool)
    moving[:, free] = True
    moving[:, 0] &= ~cylindrical
    widest = np.max(np.where(np.isfinite(geometry.gap), geometry.gap, 0.0), axis=1)
    typical = geometry.roller_count * geometry.lamina_constant * geometry.gap.shape[1] * (
        np.maximum(widest, 1e-6 * lever)) ** (1.0 / 9.0)
    # a preloaded bearing's rollers push on the ring from every side: their loads cancel
    # in its force but set the rounding of the sum
    internal = np.sum(_state(geometry, rollers, q).lamina, axis=(1, 2))
    # no equilibrium moves a ring by many of its rollers' lengths: one that runs off has none
    return damped_newton(lambda trial: _state(geometry, rollers, trial), q, applied,
                         moving, scale, typical, internal, reach=REACH * lever)


class RollerContacts(NamedTuple):
    """Every lamina's contacts at a displacement (see :func:`roller_contacts_at`)."""

    energy: NDArray            # (N,) Σ (c_L/n_s)·9/19·δ₊^(19/9) [J]
    force: NDArray             # (N, 5) the rings' internal force ∂U/∂q [N, N·m]
    stiffness: NDArray         # (N, 5, 5) ∂²U/∂q² [SI]
    element_load: NDArray      # (N, Zmax) each roller's load, NaN past Z [N]
    lamina_load: NDArray       # (N, Zmax, n_s) [N]
    azimuth: NDArray           # (N, Zmax) [rad], NaN past Z
    #: (N,) False: a roller's laminae touch wherever they are pressed (the balls' own
    #: contacts have places the model leaves out)
    beyond_contacts: NDArray


def roller_contacts_at(geometry: RollerGeometry, displacement: NDArray) -> RollerContacts:
    """The laminae's energy, force, tangent stiffness and loads at the inner ring's
    displacement q (N, 5) [m, rad], for a caller that solves its own equilibrium (a
    shaft on several bearings): the same contacts as :func:`solve_roller_equilibrium`'s."""
    count = geometry.roller_count.astype(int)
    j = np.arange(int(count.max()))
    mask = j[None, :] < count[:, None]
    psi = 2.0 * np.pi * j[None, :] / count[:, None]
    state = _state(geometry, _rollers(geometry, psi, mask),
                   np.asarray(displacement, dtype=float))
    blank = np.where(mask, 1.0, np.nan)
    return RollerContacts(state.energy, state.force, state.hessian,
                          state.lamina.sum(axis=2) * blank,
                          np.where(mask[..., None], state.lamina, np.nan),
                          (psi % (2 * np.pi)) * blank, np.zeros(count.size, dtype=bool))
