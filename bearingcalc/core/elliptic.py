r"""Complete elliptic integrals of the first and second kind by the arithmetic-geometric
mean, in plain numpy (``docs/physics.md`` §6).

K(m) and E(m) take the parameter m = k² (as ``scipy.special.ellipk`` and ``ellipe``
do). Gauss's arithmetic-geometric mean converges quadratically, so a handful of
whole-array steps give both integrals to within a few units in the last place for
every m < 1; no special-function library has to be loaded for them.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: The sum for E changes form at the first step n where the rest of the series,
#: 2ⁿ·c²ₙ₊₁, falls below this fraction of the partial value: see
#: :func:`complete_elliptic_integrals`.
SERIES_SWITCH = 0.25
#: The means have met when |aₙ − bₙ| <= this fraction of aₙ: the next term of E's series
#: is then of order 10⁻²⁰ of the sum and aₙ₊₁ equals the limit to 10⁻²¹.
CONVERGED = 1e-10
#: More steps than any m < 1 needs (m = 0.99 takes 5, m = 1 − 2⁻⁵³ 7, m = −10³⁰⁰ 11).
MAX_STEPS = 64


def complete_elliptic_integrals(parameter: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""K(m) and E(m), the complete elliptic integrals of the first and second kind.

    .. math:: K(m) = \int_0^{\pi/2} \frac{d\theta}{\sqrt{1 - m\sin^2\theta}}, \qquad
              E(m) = \int_0^{\pi/2} \sqrt{1 - m\sin^2\theta}\, d\theta

    With a₀ = 1, b₀ = √(1 − m), c₀ = √m and the arithmetic-geometric mean
    aₙ₊₁ = (aₙ + bₙ)/2, bₙ₊₁ = √(aₙbₙ), cₙ₊₁ = (aₙ − bₙ)/2, whose common limit is M:

    .. math:: K = \frac{\pi}{2M}, \qquad
              E = K\left(1 - \sum_{n \ge 0} 2^{n-1} c_n^2\right)

    Near m = 1 the bracket, of order 1/K, is the difference of terms of order one. Its
    partial sums up to n have the closed form (by induction, as a²ₙ − b²ₙ = c²ₙ and
    b²ₙ₊₁ = aₙbₙ)

    .. math:: 1 - \sum_{j=0}^{n} 2^{j-1} c_j^2 = 2^{n-1} a_n^2 - \sum_{j=1}^{n-1} 2^{j-1} b_j^2,
              \quad n \ge 1

    whose terms are small where the cⱼ are large; the series goes on from the first n
    at which its rest has become small against the sum (``SERIES_SWITCH``), so no step
    cancels more than a bit or two.

    Parameters
    ----------
    parameter : m = k², m <= 1 (negative m too). [1]

    Returns
    -------
    (K, E). [1] K = ∞ and E = 1 at m = 1, K = 0 and E = ∞ at m = −∞; NaN for m > 1
    or NaN.

    Source: Abramowitz & Stegun, *Handbook of Mathematical Functions* (1964),
    17.6.1–17.6.4 (the arithmetic-geometric mean and the series for E).

    >>> k, e = complete_elliptic_integrals([0.0, 0.5, 1.0])
    >>> [round(float(x), 12) for x in k[:2]], [round(float(x), 12) for x in e]
    ([1.570796326795, 1.854074677301], [1.570796326795, 1.350643881048, 1.0])
    """
    shape = np.shape(parameter)
    m = np.asarray(parameter, dtype=float).reshape(-1)   # arrays throughout, never scalars
    b0, ordinary, smallest, largest = _ordinary_start(m)
    steps = _steps_needed(smallest, largest)

    # Step 1 by hand: a₀b₀ = b₀, so b₁ = √b₀ with one rounding.
    a = 1.0 + b0
    a *= 0.5
    b_squared = b0
    b = np.sqrt(b0)
    rest = np.subtract(a, b)
    np.square(rest, out=rest)
    rest *= 0.5                                    # 2ⁿ·c²ₙ₊₁ = 2ⁿ⁻²(aₙ − bₙ)², n = 1
    bracket = a * a                                # the closed form at n = 1
    # Its rest is small at once for most m; only m near 1 (or far below 0) stay on the
    # closed form a step or more, and the extremes of b₀ are the last to leave it.
    any_closed = not (_starts_series(smallest) and _starts_series(largest))
    if any_closed:
        closed_form = rest > SERIES_SWITCH * bracket
        any_closed = bool(closed_form.any())
    bracket -= rest
    weight = 1.0                                   # 2ⁿ⁻¹ at step n
    b_sum = np.zeros_like(a) if any_closed else None   # Σ_{j<n} 2ʲ⁻¹·b²ⱼ
    scratch = rest
    for step in range(2, steps + 1):
        if any_closed:
            b_sum += weight * b_squared
        np.add(a, b, out=scratch)
        np.multiply(a, b, out=b)                   # b²ₙ
        if any_closed:
            b_squared = b.copy()
        np.multiply(scratch, 0.5, out=a)
        np.sqrt(b, out=b)
        weight *= 2.0
        if step == steps and not any_closed:
            break   # |aₙ − bₙ| <= CONVERGED·aₙ: the term is below 10⁻²⁰ of the sum
        np.subtract(a, b, out=scratch)
        np.square(scratch, out=scratch)
        scratch *= 0.5 * weight                    # 2ⁿ·c²ₙ₊₁
        if any_closed:
            partial = weight * (a * a) - b_sum
            start = closed_form & (scratch <= SERIES_SWITCH * partial)
            bracket = np.where(start, partial, bracket)
            closed_form &= ~start
            any_closed = bool(closed_form.any())
            bracket -= np.where(closed_form, 0.0, scratch)
        else:
            bracket -= scratch
    k = np.add(a, b, out=scratch)
    np.divide(np.pi, k, out=k)
    e = np.multiply(k, bracket, out=bracket)
    if ordinary is not None:
        k = np.where(ordinary, k, np.where(m == 1.0, np.inf, np.where(m == -np.inf, 0.0,
                                                                          np.nan)))
        e = np.where(ordinary, e, np.where(m == 1.0, 1.0, np.where(m == -np.inf, np.inf,
                                                                       np.nan)))
    return k.reshape(shape), e.reshape(shape)


def _ordinary_start(m: NDArray) -> tuple[NDArray, NDArray | None, float, float]:
    """b₀ = √(1 − m) with m = 1, −∞, m > 1 and NaN set to 1 (their K and E are set
    apart at the end), the mask of the ordinary m (None where all are), and the
    smallest and largest b₀."""
    with np.errstate(invalid="ignore"):                  # m > 1: NaN, set apart
        b0 = np.sqrt(1.0 - m)
    smallest, largest = (float(b0.min()), float(b0.max())) if b0.size else (1.0, 1.0)
    if smallest > 0.0 and largest < np.inf:              # False with a NaN too
        return b0, None, smallest, largest
    ordinary = (b0 > 0.0) & (b0 < np.inf)
    b0 = np.where(ordinary, b0, 1.0)
    smallest, largest = (float(b0.min()), float(b0.max())) if b0.size else (1.0, 1.0)
    return b0, ordinary, smallest, largest


def _starts_series(b0: float) -> bool:
    """Whether the series of E begins at step 1 for this b₀ (see SERIES_SWITCH)."""
    a, b = 0.5 * (1.0 + b0), math.sqrt(b0)
    return 0.5 * (a - b) ** 2 <= SERIES_SWITCH * (a * a)


def _steps_needed(smallest: float, largest: float) -> int:
    """Steps n after which |aₙ − bₙ| <= ``CONVERGED``·aₙ for every b₀ of an array, from
    its smallest and largest b₀.

    The ratio bₙ/aₙ moves toward 1 the more slowly the farther b₀ is from 1 (either
    way), so the smallest and the largest b₀ take the most steps: only they are
    iterated, in scalars, and the arrays then take that many steps without a test.
    """
    steps = 1
    for start in (smallest, largest):
        a, b, n = 0.5 * (1.0 + start), math.sqrt(start), 1
        while abs(a - b) > CONVERGED * a and n < MAX_STEPS:
            a, b, n = 0.5 * (a + b), math.sqrt(a * b), n + 1
        steps = max(steps, n)
    return steps
