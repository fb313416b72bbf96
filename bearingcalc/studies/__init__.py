"""Tolerance studies on the vectorised solvers: worst case, RSS, Monte Carlo, Sobol indices.

Every method evaluates whole arrays of designs per solver call, never a Python
loop per sample. Inputs are the spec fields that carry a tolerance (see
:class:`bearingcalc.models.quantities.Tolerance` for the distributions).

- :mod:`~bearingcalc.studies.study`: the study of one spec, its toleranced inputs,
  the tolerance box and the evaluation of designs;
- :mod:`~bearingcalc.studies.worst_case`: the exact extremes over the box;
- :mod:`~bearingcalc.studies.rss`: first-order propagation of the spreads;
- :mod:`~bearingcalc.studies.monte_carlo`: the streamed, threaded sampling loop,
  with the running statistics of :mod:`~bearingcalc.studies.accumulator`;
- :mod:`~bearingcalc.studies.sampling`: the sample streams and inverse CDFs, on
  :mod:`~bearingcalc.studies.sobol` (scipy's Sobol' points) and
  :mod:`~bearingcalc.studies.normal` (scipy's ndtri);
- :mod:`~bearingcalc.studies.sensitivity`: Sobol sensitivity indices;
- :mod:`~bearingcalc.studies.run`: :func:`run_study`, which runs the chosen methods
  and assembles the :class:`StudyReport`.
"""

from bearingcalc.studies.accumulator import (
    BLOCK,
    HISTOGRAM_BINS,
    QUANTILES,
    _Accumulator,
    _Scratch,
    coarse_histogram,
)
from bearingcalc.studies.monte_carlo import MonteCarloResult
from bearingcalc.studies.run import METHODS, StudyReport, run_study
from bearingcalc.studies.sampling import (
    SAMPLERS,
    SCIPY_NDTRI_ABOVE,
    SOBOL_MAX_SAMPLES,
    SampleStream,
    inverse_cdf,
    normal_quantile_function,
)
from bearingcalc.studies.study import Study, StudyError, StudyInput, check_band_ends

__all__ = [
    "BLOCK",
    "HISTOGRAM_BINS",
    "METHODS",
    "QUANTILES",
    "SAMPLERS",
    "SCIPY_NDTRI_ABOVE",
    "SOBOL_MAX_SAMPLES",
    "MonteCarloResult",
    "SampleStream",
    "Study",
    "StudyError",
    "StudyInput",
    "StudyReport",
    "_Accumulator",
    "_Scratch",
    "check_band_ends",
    "coarse_histogram",
    "inverse_cdf",
    "normal_quantile_function",
    "run_study",
]
