"""AGMA 2003's stress-cycle curves of steel bevel gears, the life factors K_L (bending)
and C_L (contact), and the safety of a load spectrum on them by Miner's rule
(``docs/physics.md`` §8 and §11).

A curve is a sequence of branches (N_start, a, b): from N_start cycles up to the next
branch's start the factor is a·N^(−b) (b = 0: a flat branch). Inputs are floats or
broadcasting numpy arrays.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: A stress-cycle curve: branches (first cycle count, coefficient a, slope b), a·N^(−b).
Curve = Sequence[tuple[float, float, float]]

#: K_L = 6.1514·N^(−0.1192) for 10³ <= N < 3·10⁶, 1.683·N^(−0.0323) for 3·10⁶ <= N <= 10¹⁰.
BENDING_LIFE_CURVE: Curve = ((1e3, 6.1514, 0.1192), (3e6, 1.683, 0.0323))
#: C_L = 2 for 10³ <= N < 10⁴, 3.4822·N^(−0.0602) for 10⁴ <= N <= 10¹⁰.
CONTACT_LIFE_CURVE: Curve = ((1e3, 2.0, 0.0), (1e4, 3.4822, 0.0602))
#: The fewest cycles the curves rate.
FIRST_RATED_CYCLES = 1e3
#: The bisection steps of :func:`spectrum_safety`: each halves the bracket's logarithm
#: (ln 3 on AGMA's curves, plus the logarithm of the bins' spread of safeties), so 80
#: reach the spacing of doubles for any spread below 10¹⁰.
SPECTRUM_BISECTIONS = 80


def life_factor(cycles: ArrayLike, curve: Curve) -> NDArray:
    r"""The stress-cycle factor of a curve at N cycles.

    .. math:: K_L = \begin{cases} 6.1514\,N^{-0.1192} & 10^3 \le N < 3\cdot10^6 \\
              1.683\,N^{-0.0323} & 3\cdot10^6 \le N \le 10^{10}\end{cases} \qquad
              C_L = \begin{cases} 2 & 10^3 \le N < 10^4 \\
              3.4822\,N^{-0.0602} & 10^4 \le N \le 10^{10}\end{cases}

    for :data:`BENDING_LIFE_CURVE` and :data:`CONTACT_LIFE_CURVE`. Below 10³ cycles,
    where the curves are not drawn, the factor is held at its 10³-cycle value (gear B of
    a pinion rated at 10³ cycles turns fewer times): no more strength than the curve
    gives is credited.

    Parameters
    ----------
    cycles : N, load cycles of the member. [1]
    curve : the branches (N_start, a, b). [1]

    Source: ANSI/AGMA 2003-B97, Figs. 18 and 19; Budynas & Nisbett, *Shigley's
    Mechanical Engineering Design*, 10th ed., eqs. (15-14) and (15-15).
    """
    n = np.maximum(np.asarray(cycles, dtype=float), curve[0][0])
    factor = np.full(n.shape, np.nan)
    for start, coefficient, slope in curve:
        factor = np.where(n >= start, coefficient * n ** -slope, factor)
    return factor


def cycles_to_failure(factor: ArrayLike, curve: Curve) -> NDArray:
    r"""The cycles a stress endures that needs ``factor`` times the allowable stress
    number: the first N at which the curve falls below that factor.

    .. math:: N(K) = \inf\,\{N \ge 10^3 : K_L(N) < K\}

    On a sloped branch N = (a/K)^(1/b); a flat branch at or above K holds to its end
    (C_L = 2 lasts to 10⁴ cycles, then the next branch's 2.0001 to 1.0009·10⁴); beyond
    10¹⁰ the last branch goes on. Where the printed coefficients leave a branch's start
    a little above the end of the one before (C_L at 10⁴), the first crossing counts, so
    N falls as K rises. A factor above the curve's 10³-cycle value is endured for one
    cycle: the stress exceeds what the curve rates.

    Parameters
    ----------
    factor : K, the stress over the allowable stress number. [1]
    curve : the branches (N_start, a, b). [1]

    Returns
    -------
    N [1]: +inf where K <= 0.

    Source: ANSI/AGMA 2003-B97, Figs. 18 and 19 (the curves inverted).
    """
    k = np.asarray(factor, dtype=float)
    ends = [start for start, _, _ in curve[1:]] + [np.inf]
    cycles = np.where(k > 0, np.nan, np.inf)
    with np.errstate(divide="ignore", over="ignore"):
        for index, ((start, coefficient, slope), end) in enumerate(zip(curve, ends,
                                                                        strict=True)):
            below_at_start = np.isnan(cycles) & (k > coefficient * start ** -slope)
            cycles = np.where(below_at_start, start if index else 1.0, cycles)
            if slope > 0:
                crossing = (coefficient / k) ** (1.0 / slope)
                cycles = np.where(np.isnan(cycles) & (crossing < end), crossing, cycles)
    return cycles


def spectrum_damage(shares: ArrayLike, safeties: ArrayLike, cycles: ArrayLike,
                    curve: Curve, scale: ArrayLike = 1.0) -> NDArray:
    r"""Each bin's Miner damage with every bin's stress times ``scale``.

    A bin of safety Sᵢ at the design life N (the allowable stress times K(N) over its
    stress) runs Uᵢ·N cycles; with its stress times s it needs the factor
    K = s·K(N)/Sᵢ, which it endures Nᵢ = N(K) cycles (:func:`cycles_to_failure`):

    .. math:: D_i = \frac{U_i N}{N_i}

    Parameters
    ----------
    shares : Uᵢ, each bin's share of the member's cycles (first axis). [1]
    safeties : Sᵢ at the design life, stress-based (+inf: a bin without stress). [1]
    cycles : N, the member's cycles over the design life. [1]
    curve : the branches (N_start, a, b). [1]
    scale : s, the factor on every bin's stress. [1]

    Returns
    -------
    Dᵢ [1], bins on the first axis.

    Source: ANSI/AGMA 2101-D04, Annex A (load spectra by Miner's rule).
    """
    n = np.asarray(cycles, dtype=float)
    return _damage(np.asarray(shares, dtype=float), np.asarray(safeties, dtype=float), n,
                   life_factor(n, curve), curve, scale)


def _damage(u: NDArray, safeties: NDArray, n: NDArray, factor_at_life: NDArray,
            curve: Curve, scale: ArrayLike) -> NDArray:
    """:func:`spectrum_damage` with K(N) given (the bisection's steps share it)."""
    with np.errstate(divide="ignore"):
        needed = np.asarray(scale, dtype=float) * factor_at_life / safeties
    endured = cycles_to_failure(needed, curve)
    return np.where(u > 0, u * n / endured, 0.0)


def spectrum_safety(shares: ArrayLike, safeties: ArrayLike, cycles: ArrayLike,
                    curve: Curve) -> NDArray:
    r"""The safety factor of a load spectrum: the factor S on every bin's stress at which
    Miner's sum of :func:`spectrum_damage` is 1.

    .. math:: \sum_i \frac{U_i N}{N\!\left(S\,K(N)/S_i\right)} = 1

    On one power law K ∝ N^(−b) that is S = (Σ Uᵢ Sᵢ^(−1/b))^(−b); on AGMA's two
    branches the sum mixes powers, and S is found by bisection of log S, all designs at
    once. The sum rises with S, so S is bracketed by the smallest Sᵢ (where every bin
    lasts at least N cycles, D <= 1) and by the largest finite Sᵢ times K(10³)/K(N)
    (where every stressed bin exceeds the curve and lasts one cycle, D = N > 1). A bin
    whose stress crosses the curve's 10³-cycle strength makes the sum jump past 1: S is
    the largest s with D(s) <= 1, that crossing if the sum is still below 1 there.

    Parameters
    ----------
    shares : Uᵢ, each bin's share of the member's cycles (first axis). [1]
    safeties : Sᵢ at the design life, stress-based. [1]
    cycles : N, the member's cycles over the design life. [1]
    curve : the branches (N_start, a, b). [1]

    Returns
    -------
    S [1], +inf where no bin is stressed.

    Source: ANSI/AGMA 2003-B97 (the life factors K_L, C_L) with Miner's rule
    (ANSI/AGMA 2101-D04, Annex A, load spectra).
    """
    u = np.asarray(shares, dtype=float)
    safeties = np.asarray(safeties, dtype=float)
    n = np.asarray(cycles, dtype=float)
    counted = (u > 0) & np.isfinite(safeties)
    low = np.min(np.where(counted, safeties, np.inf), axis=0)
    stressed = np.isfinite(low)
    low = np.where(stressed, low, 1.0)
    factor_at_life = life_factor(n, curve)
    high = np.max(np.where(counted, safeties, 1.0), axis=0) * life_factor(
        FIRST_RATED_CYCLES, curve) / factor_at_life
    for _ in range(SPECTRUM_BISECTIONS):
        middle = np.sqrt(low * high)
        within = np.sum(_damage(u, safeties, n, factor_at_life, curve, middle),
                        axis=0) <= 1.0
        low, high = np.where(within, middle, low), np.where(within, high, middle)
    return np.where(stressed, low, np.inf)
