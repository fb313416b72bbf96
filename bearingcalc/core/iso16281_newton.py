"""The damped Newton method that finds a bearing's or a shaft's equilibrium as mounted
(ISO/TS 16281): the minimum of a convex potential U(q) = U_contacts(q) − F·q over
some of the five coordinates q = (δx, δy, δz, θy, θz), vectorised over designs.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

#: The relative residual at which the equilibrium counts as found.
RESIDUAL_TOLERANCE = 1e-12
MAX_ITERATIONS = 100
#: The last digits of a displacement its rounding leaves uncertain.
ROUNDING_ULPS = 8.0


def damped_newton(potential: Callable[[NDArray], Any], q: NDArray, applied: NDArray,
                  moving: NDArray, scale: NDArray, typical: NDArray,
                  internal: NDArray | None = None, reach: NDArray | None = None
                  ) -> tuple[NDArray, NDArray]:
    r"""Minimise U(q) = U_c(q) − F·q over the coordinates ``moving`` (N, 5) holds, from
    ``q`` (N, 5), with F = ``applied`` (N, 5):

    .. math:: (H + λ\,k\,I)\,Δu = -(∇U_c - F), \qquad u = D\,q

    in coordinates scaled to lengths by ``scale`` (N, 5) = D (1 for translations, a
    lever [m] for tilts); ``potential(q)`` gives the contacts' ``energy`` (N,),
    ``force`` (N, 5) = ∇U_c and ``hessian`` (N, 5, 5), and any further arrays over the
    designs, all in SI. A step is taken where it lowers U (Armijo's rule) or halves the
    residual, and the Levenberg damping λ (times the stiffness scale ``typical`` (N,)
    [N/m]) then falls tenfold; else it grows tenfold. Returns q and the relative residual
    max|∇U|/max(|F|, |∇U_c|, ``internal``, f_ε/tolerance), ``internal`` (N,) [N] the
    size of forces that cancel inside (a preloaded pair's), whose rounding no step can
    beat, and f_ε the force that rounding the displacement makes (:func:`_rounding_force`). A design
    whose scaled displacement outgrows ``reach`` (N,) [m] has no equilibrium (its ring
    runs off: U is unbounded below) and is left there, its residual infinite.
    Source: J. Nocedal and S. J. Wright, *Numerical Optimization*, 2nd ed., 3.1 (Armijo)
    and 10.3 (Levenberg–Marquardt).
    """
    n = q.shape[0]
    target = np.where(moving, applied / scale, 0.0)
    damping = np.full(n, 1e-3)
    residual = np.full(n, np.inf)
    size = np.maximum(np.max(np.abs(target), axis=1), 1e-300)
    if internal is not None:
        size = np.maximum(size, internal)
    held = ~moving[:, :, None] | ~moving[:, None, :]
    state = potential(q)
    gone = np.zeros(n, dtype=bool)
    for _ in range(MAX_ITERATIONS):
        force = np.where(moving, state.force / scale, 0.0)
        gradient = force - target
        residual = np.max(np.abs(gradient), axis=1) / np.maximum.reduce([
            size, np.max(np.abs(force), axis=1),
            _rounding_force(state.hessian, q, scale, moving) / RESIDUAL_TOLERANCE])
        if reach is not None:
            gone |= np.max(np.abs(np.where(moving, q * scale, 0.0)), axis=1) > reach
        done = (residual <= RESIDUAL_TOLERANCE) | gone
        if done.all():
            break
        hessian = np.where(held, 0.0, state.hessian / scale[:, :, None] / scale[:, None, :])
        hessian += np.eye(5) * np.where(moving, (damping * typical)[:, None], 1.0)[:, None, :]
        step = -np.linalg.solve(hessian, gradient[..., None])[..., 0]
        step[done] = 0.0
        trial = q + step / scale
        new = potential(trial)
        energy = state.energy - np.sum(target * q * scale, axis=1)
        energy_new = new.energy - np.sum(target * trial * scale, axis=1)
        shrinks = (np.max(np.abs(np.where(moving, new.force / scale, 0.0) - target), axis=1)
                   < 0.5 * np.max(np.abs(gradient), axis=1))
        better = ((energy_new <= energy + 1e-4 * np.sum(gradient * step, axis=1)) | shrinks
                  ) & ~done
        q = np.where(better[:, None], trial, q)
        state = type(state)(*(np.where(better.reshape((n,) + (1,) * (a.ndim - 1)), b, a)
                              for a, b in zip(state, new, strict=True)))
        damping = np.where(better, np.maximum(damping / 10.0, 1e-14), damping * 10.0)
    return q, np.where(gone, np.inf, residual)


def _rounding_force(hessian: NDArray, q: NDArray, scale: NDArray, moving: NDArray
                    ) -> NDArray:
    """The force [N] that rounding the displacement to its last digits makes,
    ROUNDING_ULPS·ε·max_i |H_ii·u_i| in the scaled coordinates u = D·q: no step resolves
    less (a load of millinewtons on a ring some micrometres from its datum)."""
    stiffness = np.abs(np.diagonal(hessian, axis1=1, axis2=2)) / (scale * scale)
    return ROUNDING_ULPS * np.finfo(float).eps * np.max(
        np.where(moving, stiffness * np.abs(q * scale), 0.0), axis=1)


def bracketed_newton(residual: Callable[[NDArray], tuple[NDArray, NDArray, NDArray]],
                     start: NDArray, low: NDArray, high: NDArray,
                     max_iterations: int = 100) -> NDArray:
    r"""The root x of an increasing function of one unknown per design, f(x) = 0:
    ``residual(x)`` gives f, its slope f′ and the size below which |f| counts as 0.
    Newton's step x − f/f′ is kept where it stays inside the bracket [``low``,
    ``high``], which each evaluation narrows, else the bracket is halved; a
    bracket narrower than 10⁻¹⁷ ends the search too. [SI] Source: W. H. Press et al.,
    *Numerical Recipes*, 3rd ed., 9.4 (Newton's method with bisection).
    """
    x, low, high = start.copy(), low.copy(), high.copy()
    for _ in range(max_iterations):
        value, slope, size = residual(x)
        if np.all((np.abs(value) <= size) | (high - low <= 1e-17)):
            break
        low = np.where(value < 0.0, x, low)
        high = np.where(value > 0.0, x, high)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = x - value / slope
        inside = (slope > 0.0) & (step > low) & (step < high)
        x = np.where(value == 0.0, x, np.where(inside, step, 0.5 * (low + high)))
    return x
