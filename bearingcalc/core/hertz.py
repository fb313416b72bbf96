"""Hertz point contact of two elastic bodies: the contact ellipse, the approach and the
peak pressure, exact with complete elliptic integrals (``docs/physics.md`` §6), which
:mod:`bearingcalc.core.elliptic` computes by the arithmetic-geometric mean.

Vectorised over whole arrays: the ellipticity is found by Newton's method on every
contact at once (with a bisection safeguard), to full double precision, so tolerance
studies and sweeps can solve millions of contacts per call.
"""

from __future__ import annotations

import functools
from fractions import Fraction

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.elliptic import complete_elliptic_integrals

#: Newton iterations at most; from the tabulated start two or three reach full precision.
MAX_ITERATIONS = 30
#: Below this modulus F(ρ) is summed as a power series: the closed form loses digits
#: to cancellation there (its numerator is of order m² out of terms of order 1).
SERIES_LIMIT = 0.3
SERIES_TERMS = 40


def _series_coefficients() -> NDArray:
    """Coefficients c_j of N(m)/m = (π/2)·Σ c_j m^j, N = (2 − m)E − 2(1 − m)K, from
    K = (π/2)Σ a_n m^n and E = (π/2)Σ a_n m^n/(1 − 2n), a_n = (C(2n, n)/4^n)²."""
    a = [Fraction(1)]
    for n in range(1, SERIES_TERMS + 2):
        a.append(a[-1] * Fraction(2 * n - 1, 2 * n) ** 2)
    e = [a_n / (1 - 2 * n) for n, a_n in enumerate(a)]
    coefficients = [2 * e[n] - e[n - 1] - 2 * a[n] + 2 * a[n - 1]
                    for n in range(1, SERIES_TERMS + 2)]   # of m^n in N, n >= 1
    return np.array([float(c) for c in coefficients])      # of m^(n−1) in N/m


_SERIES = _series_coefficients()
_SERIES_SLOPE = _SERIES[1:] * np.arange(1, len(_SERIES))


def _e_slope_coefficients() -> NDArray:
    """Coefficients of E'(m) = (π/2)·Σ n·a_n/(1 − 2n)·m^(n−1)."""
    a, out = Fraction(1), []
    for n in range(1, SERIES_TERMS + 2):
        a *= Fraction(2 * n - 1, 2 * n) ** 2
        out.append(float(n * a / (1 - 2 * n)))
    return np.array(out)


_E_SLOPE = _e_slope_coefficients()


def _difference_and_slope(m: NDArray) -> tuple[NDArray, NDArray]:
    """F(m) and dF/dm, accurate to rounding for every 0 <= m < 1."""
    big_k, big_e = complete_elliptic_integrals(m)
    one_minus = 1.0 - m
    with np.errstate(all="ignore"):  # m = 0 divides by zero here; the series takes over
        numerator = (2.0 - m) * big_e - 2.0 * one_minus * big_k
        d_e = (big_e - big_k) / (2.0 * m)
        d_k = (big_e - one_minus * big_k) / (2.0 * m * one_minus)
        d_numerator = (2.0 - m) * d_e - big_e + 2.0 * big_k - 2.0 * one_minus * d_k
        over_m = numerator / m
        over_m_slope = (d_numerator - over_m) / m
    small = np.flatnonzero(m < SERIES_LIMIT)
    if small.size:
        # N/m by its power series, and E' by K' − E' ... from the series of K − E.
        ms = m[small]
        over_m[small] = np.polynomial.polynomial.polyval(ms, _SERIES) * (np.pi / 2)
        over_m_slope[small] = np.polynomial.polynomial.polyval(ms, _SERIES_SLOPE) * (np.pi / 2)
        d_e[small] = np.polynomial.polynomial.polyval(ms, _E_SLOPE) * (np.pi / 2)
    return over_m / big_e, (over_m_slope * big_e - over_m * d_e) / (big_e * big_e)


def curvature_difference(ellipse_modulus: ArrayLike) -> NDArray:
    r"""The curvature difference F(ρ) of a contact whose ellipse has modulus m.

    With k = a/b and m = 1 − 1/k²,

    .. math:: F = \frac{(k^2 + 1)E(m) - 2K(m)}{(k^2 - 1)E(m)}
                = \frac{(2 - m)E(m) - 2(1 - m)K(m)}{m\,E(m)}

    which rises from 0 (a circle, m → 0) toward 1 (a line, m → 1). Below m = 0.3 the
    numerator is summed as its power series, free of cancellation.

    Source: Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
    eq. (6.26); Hamrock, Schmid & Jacobson, *Fundamentals of Machine Elements*, ch. 8.
    """
    m = np.asarray(ellipse_modulus, dtype=float)
    return _difference_and_slope(m.reshape(-1))[0].reshape(m.shape)


#: The starting table: m at evenly spaced v = ln((1 + F)/(1 − F)) from 0 to START_V_MAX.
START_POINTS, START_V_MAX = 8192, 40.0


@functools.cache
def _start_table() -> NDArray:
    """m at ``START_POINTS`` evenly spaced v, found by inverting a fine table of F(m)."""
    u = np.concatenate([np.linspace(0.0, 1.0, 4000, endpoint=False)[1:] ** 2,
                        np.linspace(1.0, 40.0, 8000)])
    m = -np.expm1(-u)
    f = curvature_difference(m)
    v = np.concatenate([[0.0], np.log1p(f) - np.log1p(-f)])
    grid = np.linspace(0.0, START_V_MAX, START_POINTS)
    return np.interp(grid, v, np.concatenate([[0.0], m]))


def _start(f: NDArray) -> NDArray:
    """A starting m for each F by linear interpolation in the evenly spaced table."""
    table = _start_table()
    position = np.minimum((np.log1p(f) - np.log1p(-f)) * ((START_POINTS - 1) / START_V_MAX),
                          START_POINTS - 1.000001)
    index = position.astype(np.intp)
    fraction = position - index
    return table[index] * (1.0 - fraction) + table[index + 1] * fraction


def ellipse_modulus(curvature_diff: ArrayLike) -> NDArray:
    """m = 1 − (b/a)² of the contact ellipse from the curvature difference F, 0 <= F < 1.

    Solves :func:`curvature_difference` (m) = F for m on whole arrays: Newton's method
    started from a table of the function (interpolated in ln((1 + F)/(1 − F))), with
    steps kept inside (0, 1); two or three steps reach full precision. F = 0 gives
    m = 0 (a circle) exactly; F outside [0, 1) gives NaN.
    """
    f = np.asarray(curvature_diff, dtype=float)
    valid = (f > 0.0) & (f < 1.0)
    target = np.where(valid, f, 0.5)
    m = _start(target)
    active = np.arange(m.size)
    flat_m, flat_target = m.reshape(-1).copy(), target.reshape(-1)
    for _ in range(MAX_ITERATIONS):
        current, goal = flat_m[active], flat_target[active]
        value, slope = _difference_and_slope(current)
        proposal = current - (value - goal) / slope
        # Stay inside (0, 1): a step out is cut to halfway toward the edge it crossed.
        proposal = np.where(proposal <= 0.0, 0.5 * current,
                            np.where(proposal >= 1.0, 0.5 * (current + 1.0), proposal))
        flat_m[active] = proposal
        moving = np.abs(proposal - current) > 1e-9 * np.minimum(proposal, 1.0 - proposal)
        active = active[moving]
        if active.size == 0:
            break
    m = flat_m.reshape(f.shape)
    return np.where(valid, m, np.where(f == 0.0, 0.0, np.nan))


def hertz_point_contact(load: ArrayLike, curvature_1a: ArrayLike, curvature_1b: ArrayLike,
                        curvature_2a: ArrayLike, curvature_2b: ArrayLike,
                        modulus_1: ArrayLike, poisson_1: ArrayLike,
                        modulus_2: ArrayLike, poisson_2: ArrayLike) -> dict[str, NDArray]:
    r"""Contact ellipse, approach and peak pressure of two bodies pressed together.

    Body 1 has principal curvatures ρ1a, ρ1b and body 2 ρ2a, ρ2b, in two common
    principal planes a and b (convex positive, concave negative). With
    Σρ = ρ1a + ρ1b + ρ2a + ρ2b, F = |(ρ1a − ρ1b) + (ρ2a − ρ2b)|/Σρ, the ellipticity
    k = a/b >= 1 from F (:func:`ellipse_modulus`) and
    S = 3Q/(2Σρ)·[(1 − ν1²)/E1 + (1 − ν2²)/E2]:

    .. math:: a = \left(\frac{2k^2E}{\pi}\right)^{1/3} S^{1/3}, \quad
              b = \left(\frac{2E}{\pi k}\right)^{1/3} S^{1/3}, \quad
              \delta = \frac{2K}{\pi}\left(\frac{\pi}{2k^2E}\right)^{1/3} S^{2/3}
                       \frac{\Sigma\rho}{2}, \quad
              p_{max} = \frac{3Q}{2\pi ab}

    Parameters
    ----------
    load : Normal load Q >= 0. [N]
    curvature_1a, curvature_1b, curvature_2a, curvature_2b : Principal curvatures. [1/m]
    modulus_1, modulus_2 : Young's moduli. [Pa]
    poisson_1, poisson_2 : Poisson's ratios, −1 < ν < 0.5. [1]

    Returns
    -------
    dict with semi_major a [m], semi_minor b [m], approach δ [m], max_pressure
    p_max [Pa] and ellipticity k [1]; NaN where Σρ <= 0 or F >= 1 (no point contact).

    Source: Hertz (1882); Harris & Kotzalas, *Essential Concepts of Bearing
    Technology*, 5th ed., ch. 6, eqs. (6.36)–(6.43).

    Examples
    --------
    A steel ball of radius 6.35 mm on a flat under 10 N (Johnson, *Contact Mechanics*,
    eq. 4.22): a = (3QR/4E*)^(1/3).

    >>> out = hertz_point_contact(10.0, 1 / 6.35e-3, 1 / 6.35e-3, 0.0, 0.0,
    ...                           210e9, 0.3, 210e9, 0.3)
    >>> round(float(out["semi_major"]) * 1e3, 4), round(float(out["max_pressure"]) / 1e6)
    (0.0745, 861)
    """
    inputs = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (
        load, curvature_1a, curvature_1b, curvature_2a, curvature_2b, modulus_1, poisson_1,
        modulus_2, poisson_2)))
    shape = inputs[0].shape
    flat = [x.reshape(-1) for x in inputs]
    out = {key: np.empty(flat[0].size) for key in CONTACT_KEYS}
    # Chunks small enough that every temporary stays in the processor's cache: on whole
    # arrays of millions the same arithmetic waits on memory and runs 2–3 times slower.
    for start in range(0, flat[0].size, CHUNK):
        part = _contact(*(x[start:start + CHUNK] for x in flat))
        for key in CONTACT_KEYS:
            out[key][start:start + CHUNK] = part[key]
    return {key: value.reshape(shape) for key, value in out.items()}


#: Result keys of :func:`hertz_point_contact`.
CONTACT_KEYS = ("semi_major", "semi_minor", "approach", "max_pressure", "ellipticity")
#: Contacts solved per step of :func:`hertz_point_contact`.
CHUNK = 1 << 13


def _contact(q: NDArray, r1a: NDArray, r1b: NDArray, r2a: NDArray, r2b: NDArray,
             e1: NDArray, nu1: NDArray, e2: NDArray, nu2: NDArray) -> dict[str, NDArray]:
    total = r1a + r1b + r2a + r2b
    safe_total = np.where(total > 0, total, 1.0)
    difference = np.abs((r1a - r1b) + (r2a - r2b)) / safe_total
    # A point contact needs Σρ > 0 and F < 1 (F = 1 is a line: a ball in a groove of its
    # own radius).
    convex = (total > 0) & (difference < 1.0)
    m = ellipse_modulus(np.where(convex, difference, 0.0))
    k = 1.0 / np.sqrt(1.0 - m)
    big_k, big_e = complete_elliptic_integrals(m)
    compliance = (1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2
    s = np.cbrt(1.5 * q / safe_total * compliance)
    a = np.cbrt(2.0 * k * k * big_e / np.pi) * s
    b = np.cbrt(2.0 * big_e / (np.pi * k)) * s
    approach = big_k / np.pi * np.cbrt(np.pi / (2.0 * k * k * big_e)) * s * s * safe_total
    with np.errstate(invalid="ignore", divide="ignore"):
        pressure = np.where(q > 0, 1.5 * q / (np.pi * a * b), 0.0)
    nan = np.where(convex, 0.0, np.nan)
    return {"semi_major": a + nan, "semi_minor": b + nan, "approach": approach + nan,
            "max_pressure": pressure + nan, "ellipticity": k + nan}
