"""bearingcalc.studies.normal.ndtri gives scipy.special.ndtri's numbers bit for bit."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.special import ndtri as scipy_ndtri

from bearingcalc.studies import SCIPY_NDTRI_ABOVE, normal_quantile_function
from bearingcalc.studies.normal import EXP_MINUS_2, ndtri


def assert_same_bits(y: np.ndarray) -> None:
    expected = scipy_ndtri(y)
    got = ndtri(y)
    same = (got.view(np.int64) == expected.view(np.int64)) | (np.isnan(got) & np.isnan(expected))
    assert same.all(), (y[~same][:5], got[~same][:5], expected[~same][:5])


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_uniform_points_over_the_whole_interval(seed):
    assert_same_bits(np.random.default_rng(seed).random(1_000_000))


def test_the_far_tails_on_both_sides():
    rng = np.random.default_rng(7)
    small = 10.0 ** rng.uniform(-320, -1, 300_000)   # z beyond 8 below exp(-32)
    assert_same_bits(small)
    assert_same_bits(1.0 - small[small > 1e-16])


def test_the_branch_edges_and_the_special_values():
    edges = [EXP_MINUS_2, 1.0 - EXP_MINUS_2, np.exp(-32.0), 0.5, 2.0**-53, 1.0 - 2.0**-53,
             1e-300, 5e-324]
    around = [np.nextafter(e, d) for e in edges for d in (0.0, 1.0)]
    special = [0.0, 1.0, -0.0, -1e-300, 1.5, -np.inf, np.inf, np.nan]
    assert_same_bits(np.array(edges + around + special))


def test_shapes_and_out():
    y = np.random.default_rng(3).random((40, 50))
    out = np.empty_like(y)
    assert ndtri(y, out=out) is out
    assert np.array_equal(out, scipy_ndtri(y))
    assert ndtri(np.array(0.975)).shape == ()


def test_large_studies_take_scipys_function_and_small_ones_the_light_one():
    assert normal_quantile_function(SCIPY_NDTRI_ABOVE + 1) is scipy_ndtri
    assert normal_quantile_function(1000) is ndtri


def test_a_strided_out_array_gets_the_values():
    y = np.random.default_rng(4).random(1000)
    out = np.empty((1000, 2))
    ndtri(y, out=out[:, 1])
    assert np.array_equal(out[:, 1], scipy_ndtri(y))


def test_out_may_be_the_input():
    y = np.random.default_rng(5).random(10_000)
    expected = scipy_ndtri(y)
    assert np.array_equal(ndtri(y, out=y), expected) and np.array_equal(y, expected)
