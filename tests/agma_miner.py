"""AGMA 2003's stress-cycle curves and a load spectrum's Miner sum, written here from
Budynas & Nisbett (*Shigley's Mechanical Engineering Design*, 10th ed., eqs. 15-14 and
15-15) without bearingcalc: each bin's cycles to failure by scipy.optimize.brentq on the
curve itself, and the spectrum safety by brentq on the Miner residual."""

from __future__ import annotations

import math

from scipy.optimize import brentq


def bending_factor(n: float) -> float:
    """K_L, eq. (15-14): 6.1514·N^−0.1192 from 10³ to 3·10⁶ cycles, 1.683·N^−0.0323 on."""
    return 6.1514 * n ** -0.1192 if n < 3e6 else 1.683 * n ** -0.0323


def contact_factor(n: float) -> float:
    """C_L, eq. (15-15): 2 from 10³ to 10⁴ cycles, 3.4822·N^−0.0602 on."""
    return 2.0 if n < 1e4 else 3.4822 * n ** -0.0602


CURVES = {"bending": bending_factor, "contact": contact_factor}


def endured_cycles(needed: float, load: str) -> float:
    """The cycles at which the curve falls to ``needed`` (the root of K(N) − needed in
    log N); a factor above the curve's 10³-cycle value lasts one cycle, as
    docs/physics.md says of stresses beyond the curve."""
    factor = CURVES[load]
    if needed > factor(1e3):
        return 1.0
    if needed <= 0:
        return math.inf
    return math.exp(brentq(lambda log_n: factor(math.exp(log_n)) - needed,
                           math.log(1e3), math.log(1e300), xtol=1e-14, rtol=1e-15))


def miner_sum(shares: list[float], safeties: list[float], cycles: float, load: str,
              scale: float = 1.0) -> float:
    """D = Σ Uᵢ·N/Nᵢ with every bin's stress times ``scale``: bin i then needs the
    factor scale·K(N)/Sᵢ of the allowable stress."""
    factor = CURVES[load](max(cycles, 1e3))
    return sum(u * cycles / endured_cycles(scale * factor / s, load)
               for u, s in zip(shares, safeties, strict=True) if u > 0 and s != math.inf)


def spectrum_safety(shares: list[float], safeties: list[float], cycles: float,
                    load: str) -> float:
    """The factor on every stress at which the Miner sum reaches 1 (brentq between just
    below the smallest safety, where every bin lasts its cycles and the sum is at most
    1, and three times the largest, where every bin is beyond the curve and the sum is
    N)."""
    loaded = [s for u, s in zip(shares, safeties, strict=True) if u > 0]
    return brentq(lambda s: miner_sum(shares, safeties, cycles, load, s) - 1.0,
                  min(loaded) * (1 - 1e-12), 3.0 * max(loaded), xtol=1e-15, rtol=1e-14)
