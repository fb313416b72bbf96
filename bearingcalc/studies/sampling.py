"""Drawing designs: a uniform sample stream (scrambled Sobol' points or PCG64) that is
one sequence however it is cut, and the inverse CDFs that carry it into each input's
distribution (see :class:`bearingcalc.models.quantities.Tolerance`)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from bearingcalc.models.quantities import Tolerance
from bearingcalc.studies.sobol import sobol_stream
from bearingcalc.studies.study import StudyError, StudyInput

SAMPLERS = ("sobol", "random")
#: Distinct points of a 30-bit Sobol' sequence (scipy's default, and ours).
SOBOL_MAX_SAMPLES = 1 << 30
#: Most Monte Carlo samples: 1e10 takes about half an hour on two cores.
MAX_SAMPLES = 10**10
#: Normal draws in a study above which scipy.special.ndtri is worth its import (about
#: 0.3 s); below it, bearingcalc.studies.normal.ndtri, whose tails run per element in
#: Python. Both give the same bits, so the choice never shows in a result.
SCIPY_NDTRI_ABOVE = 1 << 21


class SampleStream:
    """A uniform sample stream on (0, 1)^d from ``start`` on, drawn in pieces.

    ``sobol``: scrambled Sobol points, those of scipy.stats.qmc.Sobol bit for bit
    (:func:`bearingcalc.studies.sobol.sobol_stream`), from ``start`` on; ``random``:
    numpy's PCG64 advanced to ``start``. Either way the points are those of one
    sequence, however it is cut.
    """

    def __init__(self, d: int, seed: int, sampler: str, start: int = 0) -> None:
        self.d = d
        if sampler == "sobol":
            self.engine = sobol_stream(d, seed, start)
            self.generator = None
        elif sampler == "random":
            bits = np.random.PCG64(seed)
            bits.advance(start * d)  # one 64-bit draw per double
            self.generator = np.random.Generator(bits)
        else:
            raise StudyError(f"unknown sampler {sampler!r}; use sobol or random", "--sampler")

    def next(self, count: int) -> NDArray:
        if self.generator is not None:
            # Drawn row by row as ever, then laid out column by column like the Sobol'
            # points, so that each input's values are contiguous.
            points = np.asfortranarray(self.generator.random((count, self.d)))
        else:
            points = self.engine.next(count)
        # Keep the inverse CDFs finite: a point exactly at 0 would map to −inf. (Neither
        # sampler reaches 1: Sobol' points are at most 1 − 2⁻³⁰, PCG64's 1 − 2⁻⁵³.)
        return np.maximum(points, 1e-300, out=points)


def normal_quantile_function(draws: int) -> Callable[..., NDArray]:
    """The inverse normal CDF to use for ``draws`` normal values: scipy.special.ndtri
    or its bit-for-bit twin that needs no scipy import (see SCIPY_NDTRI_ABOVE)."""
    if draws > SCIPY_NDTRI_ABOVE:
        from scipy.special import ndtri

        return ndtri  # type: ignore[no-any-return]
    from bearingcalc.studies.normal import ndtri as light_ndtri

    return light_ndtri


def inverse_cdf(tolerance: Tolerance, u: NDArray, out: NDArray,
                normal_quantile: Callable[..., NDArray]) -> NDArray:
    """Map uniform points ``u`` to the tolerance's distribution, into ``out``;
    ``normal_quantile`` is the inverse normal CDF to use (normal_quantile_function)."""
    low, width = tolerance.low, tolerance.high - tolerance.low
    if tolerance.distribution == "uniform":
        np.multiply(u, width, out=out)
        return np.add(out, low, out=out)   # low + u·width
    if tolerance.distribution == "triangular":
        lower = low + width * np.sqrt(u / 2.0)
        upper = tolerance.high - width * np.sqrt((1.0 - u) / 2.0)
        out[...] = np.where(u < 0.5, lower, upper)
        return out
    normal_quantile(u, out=out)
    np.multiply(out, tolerance.std, out=out)
    return np.add(out, tolerance.center, out=out)   # center + std·Φ⁻¹(u)


def designs_at(inputs: Sequence[StudyInput], uniform: NDArray,
               normal_quantile: Callable[..., NDArray] | None = None) -> NDArray:
    """The designs at uniform points (n, d): an (n, d) view of a (d, n) array, so
    that each input's values, which the solver reads whole, are contiguous."""
    quantile = normal_quantile or normal_quantile_function(len(uniform))
    out = np.empty((len(inputs), len(uniform)))
    for i, item in enumerate(inputs):
        inverse_cdf(item.tolerance, uniform[:, i], out[i], quantile)
    return out.T


def draw(inputs: Sequence[StudyInput], start: int, count: int, seed: int, sampler: str
         ) -> NDArray:
    """Samples ``start`` to ``start + count`` of a study's sample stream, shape (count, d).

    The stream is the same however it is cut into pieces.
    """
    return designs_at(inputs, SampleStream(len(inputs), seed, sampler, start).next(count))
