"""bearingcalc.studies.sobol draws scipy.stats.qmc.Sobol's scrambled points bit for bit."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.stats import qmc

from bearingcalc.studies import sobol
from bearingcalc.studies.sobol import (
    ScipySobolStream,
    SobolStream,
    _lowest_zero_bits,
    sobol_stream,
)
from tests.conftest import ROOT


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


def test_the_direction_numbers_are_read_from_scipys_file_where_it_is():
    assert sobol.direction_file().is_file()
    assert isinstance(sobol_stream(3, 0), SobolStream)


@pytest.fixture
def moved_direction_file(tmp_path, monkeypatch):
    """scipy's direction numbers gone from where SobolStream reads them."""
    monkeypatch.setattr(sobol, "direction_file", lambda: tmp_path / "moved.npz")


@pytest.mark.parametrize(("d", "seed", "start"), [(1, 0, 0), (3, 7, 0), (5, 1, 65_535),
                                                  (14, 12345, 3 * 65_536 + 7)])
def test_without_the_file_scipys_engine_draws_the_same_points(d, seed, start, request):
    pieces = (7, 1, 70_001, 1016)
    direct = SobolStream(d, seed, start)
    expected = [direct.next(n) for n in pieces]
    reference = qmc.Sobol(d, scramble=True, rng=seed)
    if start:
        reference.fast_forward(start)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # balance warnings: count not a power of 2
        scipys = reference.random(sum(pieces))
    request.getfixturevalue("moved_direction_file")
    with pytest.raises(FileNotFoundError, match="no Sobol' direction numbers"):
        SobolStream(d, seed, start)
    stream = sobol_stream(d, seed, start)
    assert isinstance(stream, ScipySobolStream)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the stream is cut at will: scipy's warning is noise
        got = [stream.next(n) for n in pieces]
    for mine, theirs in zip(got, expected, strict=True):
        assert np.array_equal(mine, theirs) and mine.flags.f_contiguous and mine.flags.writeable
    assert np.array_equal(np.vstack(got), scipys)


@pytest.mark.parametrize("contents", [b"not an archive", "other arrays"])
def test_a_changed_file_also_leaves_the_points_to_scipys_engine(tmp_path, monkeypatch,
                                                                contents):
    path = tmp_path / "changed.npz"
    if isinstance(contents, bytes):
        path.write_bytes(contents)
    else:
        np.savez(path, polynomials=np.arange(3), initial=np.arange(3))
    expected = SobolStream(4, 2, 9).next(100)
    monkeypatch.setattr(sobol, "direction_file", lambda: path)
    stream = sobol_stream(4, 2, 9)
    assert isinstance(stream, ScipySobolStream)
    assert np.array_equal(stream.next(100), expected)


def test_a_study_without_the_file_reports_the_same_numbers(cli, monkeypatch, tmp_path):
    spec = ROOT / "specs" / "tolerances" / "thrust-bearing.yaml"
    args = ("tolerance", spec, "--samples", "70000", "--format", "json")
    usual = cli(*args)
    drawn_by_scipy = []

    class CountedScipySobolStream(ScipySobolStream):
        def __init__(self, *args):
            drawn_by_scipy.append(args)
            super().__init__(*args)

    monkeypatch.setattr(sobol, "direction_file", lambda: tmp_path / "moved.npz")
    monkeypatch.setattr(sobol, "ScipySobolStream", CountedScipySobolStream)
    fallback = cli(*args)
    # the worst case's search points, the Monte Carlo pilot and each worker's stream
    assert len(drawn_by_scipy) >= 3
    assert usual.code == 0 and (fallback.code, fallback.out, fallback.err) == (
        usual.code, usual.out, usual.err)
