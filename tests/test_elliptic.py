"""Complete elliptic integrals by the arithmetic-geometric mean, against scipy.special
(Cephes) and against mpmath at 40 digits, over the whole of m < 1."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from scipy.special import ellipe, ellipk

from bearingcalc.core.elliptic import complete_elliptic_integrals

#: m over [0, 1): an even grid, m piling up toward 1 (to 1 − 2⁻⁵³, the last double below
#: it) and toward 0, and random points.
PARAMETERS = np.unique(np.concatenate([
    np.linspace(0.0, 1.0, 20001)[:-1],
    1.0 - 10.0 ** -np.arange(1.0, 16.0),
    1.0 - 2.0 ** -np.arange(1.0, 54.0),
    10.0 ** -np.arange(1.0, 300.0, 7.0),
    np.random.default_rng(2).uniform(0.0, 1.0, 20000),
    1.0 - 10.0 ** np.random.default_rng(3).uniform(-15.5, 0.0, 20000),
]))


def _relative_error(value: np.ndarray, reference: np.ndarray) -> float:
    return float(np.max(np.abs(value / reference - 1.0)))


def test_k_and_e_agree_with_scipy_to_1e_15_over_the_whole_range():
    k, e = complete_elliptic_integrals(PARAMETERS)
    assert PARAMETERS.max() == 1.0 - 2.0 ** -53 and 1.0 - 1e-15 in PARAMETERS
    assert _relative_error(k, ellipk(PARAMETERS)) <= 1e-15
    assert _relative_error(e, ellipe(PARAMETERS)) <= 1e-15


def test_k_and_e_agree_with_scipy_near_m_equal_1():
    m = 1.0 - np.geomspace(1e-16, 1e-6, 2000)
    k, e = complete_elliptic_integrals(m)
    assert _relative_error(k, ellipk(m)) <= 1e-15
    assert _relative_error(e, ellipe(m)) <= 1e-15


def test_k_and_e_are_within_a_few_units_in_the_last_place_of_40_digit_values():
    mpmath.mp.dps = 40
    m = PARAMETERS[::25]
    k, e = complete_elliptic_integrals(m)
    exact_k = np.array([float(mpmath.ellipk(mpmath.mpf(x))) for x in m])
    exact_e = np.array([float(mpmath.ellipe(mpmath.mpf(x))) for x in m])
    # Cephes, behind scipy, is within 2; near m = 1 the series for E as Abramowitz and
    # Stegun write it is some 30 off, and the closed form of its sums alone some 7.
    assert np.max(np.abs(k - exact_k) / np.spacing(exact_k)) <= 4
    assert np.max(np.abs(e - exact_e) / np.spacing(exact_e)) <= 4


def test_negative_parameters_agree_with_scipy():
    m = -np.concatenate([np.geomspace(1e-12, 1e12, 500), [1e300]])
    k, e = complete_elliptic_integrals(m)
    assert _relative_error(k, ellipk(m)) <= 2e-15
    assert _relative_error(e, ellipe(m)) <= 2e-15


def test_the_edges_of_the_domain():
    k, e = complete_elliptic_integrals([0.0, 1.0, -np.inf, 1.5, np.inf, np.nan])
    assert k[0] == e[0] == math.pi / 2           # a circle: both are π/2 exactly
    assert k[1] == np.inf and e[1] == 1.0
    assert k[2] == 0.0 and e[2] == np.inf
    assert np.isnan(k[3:]).all() and np.isnan(e[3:]).all()


@pytest.mark.parametrize("shape", [(), (0,), (3,), (2, 3)])
def test_the_shape_of_the_parameter_is_kept(shape):
    m = np.full(shape, 0.5)
    k, e = complete_elliptic_integrals(m)
    assert k.shape == e.shape == shape
    assert np.all(k == complete_elliptic_integrals(0.5)[0])


def test_legendres_relation_holds():
    """E·K' + E'·K − K·K' = π/2, with K', E' at the complementary parameter 1 − m: a
    check that needs no other implementation."""
    m = np.linspace(0.01, 0.99, 99)
    k, e = complete_elliptic_integrals(m)
    k1, e1 = complete_elliptic_integrals(1.0 - m)
    assert np.allclose(e * k1 + e1 * k - k * k1, math.pi / 2, rtol=4e-15, atol=0.0)
