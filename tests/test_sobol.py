"""bearingcalc.tolerance.sobol draws scipy.stats.qmc.Sobol's scrambled points bit for bit."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.stats import qmc

from bearingcalc.tolerance.sobol import SobolStream, _lowest_zero_bits


@pytest.mark.parametrize("d", [1, 2, 3, 5, 14, 40])
@pytest.mark.parametrize("seed", [0, 1, 12345])
def test_points_equal_scipys_bit_for_bit(d, seed):
    for start in (0, 1, 5, 65535, 65536 * 3 + 7, 2**20 - 3):
        for count in (1, 2, 7, 1024, 70_001):
            reference = qmc.Sobol(d, scramble=True, rng=seed)
            if start:
                reference.fast_forward(start)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # balance warnings: count not a power of 2
                expected = reference.random(count)
            assert np.array_equal(SobolStream(d, seed, start).next(count), expected), (
                d, seed, start, count)


def test_a_stream_cut_into_pieces_is_the_same_stream():
    whole = SobolStream(4, 3).next(200_000)
    stream = SobolStream(4, 3)
    pieces = np.vstack([stream.next(n) for n in (1, 65535, 3, 100_000, 34_461)])
    assert np.array_equal(whole, pieces)


def test_lowest_zero_bit_positions():
    for first in (0, 1, 65530, 2**31 - 5):
        positions = _lowest_zero_bits(first, 20)
        expected = [(~k & (k + 1)).bit_length() - 1 for k in range(first, first + 20)]
        assert positions.tolist() == expected
