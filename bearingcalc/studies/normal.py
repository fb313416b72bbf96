"""The inverse of the standard normal CDF without importing scipy.special.

``scipy.special.ndtri`` is the reference, but importing ``scipy.special`` costs about
0.3 s, more than a default 10^5-sample tolerance study spends drawing and solving.
:func:`ndtri` computes the same numbers, bit for bit (``tests/test_normal.py`` pins it
to scipy over the whole of (0, 1), its tails and its edges), by Cephes' algorithm as
scipy evaluates it: rational approximations in Horner form, without fused
multiply-adds, and the C library's ``log`` for the tails (``math.log``; numpy's own
vectorised log may differ from it in the last bit, so it is not used).

For |y − ½| ≤ ½ − e⁻² (73 % of a uniform sample):

.. math:: x = \\sqrt{2\\pi}\\,\\bigl(w + w\\,w^2 P_0(w^2)/Q_0(w^2)\\bigr), \\quad w = y - ½

and in the tails, with z = √(−2 ln y') and y' = min(y, 1 − y):

.. math:: x = \\pm\\bigl(z - \\ln z / z - (1/z)\\,P(1/z)/Q(1/z)\\bigr)

with (P₁, Q₁) for z < 8 and (P₂, Q₂) beyond.

Reference: S. L. Moshier, Cephes Math Library, ``ndtri.c`` (1984, 1987, 1989, 2000),
as carried in scipy.special; docs/physics.md §10.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

SQRT_2PI = 2.50662827463100050242e0
EXP_MINUS_2 = 0.13533528323661269189

# Cephes ndtri.c, highest power first; the Q polynomials' leading 1 is implied.
_P0 = (-5.99633501014107895267e1, 9.80010754185999661536e1, -5.66762857469070293439e1,
       1.39312609387279679503e1, -1.23916583867381258016e0)
_Q0 = (1.95448858338141759834e0, 4.67627912898881538453e0, 8.63602421390890590575e1,
       -2.25462687854119370527e2, 2.00260212380060660359e2, -8.20372256168333339912e1,
       1.59056225126211695515e1, -1.18331621121330003142e0)
_P1 = (4.05544892305962419923e0, 3.15251094599893866154e1, 5.71628192246421288162e1,
       4.40805073893200834700e1, 1.46849561928858024014e1, 2.18663306850790267539e0,
       -1.40256079171354495875e-1, -3.50424626827848203418e-2, -8.57456785154685413611e-4)
_Q1 = (1.57799883256466749731e1, 4.53907635128879210584e1, 4.13172038254672030440e1,
       1.50425385692907503408e1, 2.50464946208309415979e0, -1.42182922854787788574e-1,
       -3.80806407691578277194e-2, -9.33259480895457427372e-4)
_P2 = (3.23774891776946035970e0, 6.91522889068984211695e0, 3.93881025292474443415e0,
       1.33303460815807542389e0, 2.01485389549179081538e-1, 1.23716634817820021358e-2,
       3.01581553508235416007e-4, 2.65806974686737550832e-6, 6.23974539184983293730e-9)
_Q2 = (6.02427039364742014255e0, 3.67983563856160859403e0, 1.37702099489081330271e0,
       2.16236993594496635890e-1, 1.34204006088543189037e-2, 3.28014464682127739104e-4,
       2.89247864745380683936e-6, 6.79019408009981274425e-9)


def _horner(x: NDArray, coefficients: tuple[float, ...], leading_one: bool = False) -> NDArray:
    """Cephes' polevl (or p1evl with ``leading_one``): ((c₀x + c₁)x + c₂)…, rounding
    after every multiply and every add as the C code does."""
    value = np.add(x, coefficients[0]) if leading_one else np.full_like(x, coefficients[0])
    for c in coefficients[1:]:
        np.multiply(value, x, out=value)
        np.add(value, c, out=value)
    return value


def ndtri(y: NDArray, out: NDArray | None = None) -> NDArray:
    """x with Φ(x) = y, for a float64 array y in [0, 1]: scipy.special.ndtri's numbers.

    Parameters
    ----------
    y : probabilities [1]; 0 gives −inf, 1 gives +inf, anything else outside [0, 1] NaN.
    out : optional float64 array of y's shape for the result.

    Returns
    -------
    Standard normal quantiles. [1]
    """
    y = np.asarray(y, dtype=float)
    if out is not None and (not out.flags.c_contiguous or np.may_share_memory(out, y)):
        out[...] = ndtri(y)   # written whole at the end: y is read to the last
        return out
    result = np.empty(y.shape) if out is None else out
    flat_y, flat_out = y.reshape(-1), result.reshape(-1)
    with np.errstate(all="ignore"):   # the tails' values here are replaced below
        # The central formula on every element (whole-array passes are cheaper than
        # gathering the 73 % that need it), then the tails written over it.
        w = np.subtract(flat_y, 0.5, out=flat_out)
        w2 = w * w
        ratio = _horner(w2, _P0)
        np.multiply(w2, ratio, out=ratio)
        np.divide(ratio, _horner(w2, _Q0, leading_one=True), out=ratio)
        np.multiply(w, ratio, out=ratio)
        np.add(w, ratio, out=flat_out)
        np.multiply(flat_out, SQRT_2PI, out=flat_out)
        # Cephes' own tests decide the branch: y > e⁻² and not y > 1 − e⁻².
        tail = np.flatnonzero(~((flat_y > EXP_MINUS_2) & (flat_y <= 1.0 - EXP_MINUS_2)))
        if tail.size:
            flat_out[tail] = _tails(flat_y[tail])
    return result


def _tails(y0: NDArray) -> NDArray:
    """Cephes ndtri for y outside the central interval, 0 < y < e⁻² or y > 1 − e⁻²."""
    upper = y0 > 1.0 - EXP_MINUS_2
    y = np.where(upper, 1.0 - y0, y0)
    inside = (y > 0.0) & (y < 1.0)   # not 0, 1, NaN or outside [0, 1]
    y = np.where(inside, y, 0.5)
    x = np.sqrt(-2.0 * _c_log(y))
    x0 = x - _c_log(x) / x
    z = 1.0 / x
    near = x < 8.0
    numerator = np.where(near, _horner(z, _P1), _horner(z, _P2))
    denominator = np.where(near, _horner(z, _Q1, leading_one=True),
                           _horner(z, _Q2, leading_one=True))
    x = x0 - z * numerator / denominator
    x = np.where(upper, x, -x)
    if not inside.all():
        special = np.where(y0 == 0.0, -np.inf, np.where(y0 == 1.0, np.inf, np.nan))
        x = np.where(inside, x, special)
    return x


def _c_log(x: NDArray) -> NDArray:
    """The C library's log of each element: scipy's, to the last bit (numpy's vectorised
    log is not always the same function)."""
    return np.fromiter(map(math.log, x.tolist()), dtype=float, count=x.size)
