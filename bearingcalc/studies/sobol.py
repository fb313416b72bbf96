"""Scrambled Sobol' points without importing scipy.stats.

``scipy.stats.qmc.Sobol`` is the reference, but importing ``scipy.stats`` costs well
over half a second (its distributions are built at import), which every tolerance
study would pay before drawing its first point. This module draws the same points,
bit for bit (``tests/test_sobol.py`` pins it to scipy for many dimensions, seeds,
starting points and lengths), from the same direction numbers (Joe & Kuo, "new-joe-kuo-
6.21201", which scipy ships), the same random draws for the scrambling (a left linear
matrix scramble and a digital shift, in scipy's order) and whole blocks at a time:
consecutive points of a Gray-code Sobol' sequence differ by one direction number, so
a block is one cumulative XOR over those direction numbers.

References: P. Bratley & B. L. Fox, "Algorithm 659: Implementing Sobol's quasirandom
sequence generator", ACM TOMS 14 (1988); S. Joe & F. Y. Kuo, "Remark on algorithm
659", ACM TOMS 29 (2003); J. Matoušek, "On the L2-discrepancy for anchored boxes",
J. Complexity 14 (1998) (linear matrix scrambling).

The direction numbers are read from a private data file of scipy.stats. Should a
scipy release move or change it, :func:`sobol_stream` draws the same points with
``scipy.stats.qmc.Sobol`` itself instead, and pays for importing scipy.stats.
"""

from __future__ import annotations

import functools
import importlib.util
import threading
import warnings
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

BITS = 30
SCALE = 1.0 / 2**BITS


@functools.cache
def direction_file() -> Path:
    """Where scipy keeps the direction numbers of its Sobol' engine, found without
    importing scipy.stats."""
    spec = importlib.util.find_spec("scipy")
    if spec is None or not spec.submodule_search_locations:
        raise ImportError("scipy is required for Sobol' direction numbers")
    return Path(next(iter(spec.submodule_search_locations))) / "stats" / \
        "_sobol_direction_numbers.npz"


@functools.cache
def _direction_table(path: Path) -> tuple[NDArray, NDArray] | None:
    """(poly, vinit): the primitive polynomials and initial direction numbers that
    scipy ships with its Sobol' engine, read from its data file at ``path``; None
    when the file is not there, is no longer a NumPy archive or holds no such arrays."""
    try:
        with np.load(path) as data:
            return data["poly"].astype(np.int64), data["vinit"].astype(np.int64)
    except (OSError, ValueError, KeyError):
        return None


def direction_numbers(d: int) -> list[list[int]]:
    """The unscrambled direction numbers v[dim][j], already shifted to BITS bits.

    Row 0 is all ones (the van der Corput sequence). Row k takes its first m entries
    from the table (m the degree of its primitive polynomial) and the rest from
    Bratley & Fox's recurrence v_j = v_{j−m} ⊕ (2^m·v_{j−m}) ⊕ ⊕_{i<m} a_i·2^i·v_{j−i};
    finally column j is multiplied by 2^(BITS−1−j).
    """
    path = direction_file()
    table = _direction_table(path)
    if table is None:
        raise FileNotFoundError(f"no Sobol' direction numbers in {path}; "
                                "sobol_stream draws with scipy.stats.qmc.Sobol instead")
    poly, vinit = table
    rows = [[1] * BITS]
    for k in range(1, d):
        p = int(poly[k])
        m = p.bit_length() - 1
        v = [int(x) for x in vinit[k, :m]]
        for j in range(m, BITS):
            new = v[j - m]
            for i in range(m):
                if (p >> (m - 1 - i)) & 1:
                    new ^= v[j - i - 1] << (i + 1)
            v.append(new)
        rows.append(v)
    return [[value << (BITS - 1 - j) for j, value in enumerate(row)] for row in rows]


def _parity(x: int) -> int:
    return bin(x).count("1") & 1


class SobolStream:
    """Points ``start``, ``start + 1``, … of scipy's scrambled Sobol' sequence in d
    dimensions with seed ``seed`` (``scipy.stats.qmc.Sobol(d, scramble=True,
    rng=seed)`` fast-forwarded to ``start``), drawn in blocks."""

    def __init__(self, d: int, seed: int, start: int = 0) -> None:
        # scipy turns the seed into a Generator and spawns its own child from it.
        parent = np.random.default_rng(seed)
        rng = np.random.Generator(type(parent.bit_generator)(
            parent.bit_generator.seed_seq.spawn(1)[0]))
        # The digital shift, then the lower-triangular scramble matrices: scipy's order.
        shift_bits = rng.integers(2, size=(d, BITS), dtype=np.uint32)
        matrices = np.tril(rng.integers(2, size=(d, BITS, BITS), dtype=np.uint32))
        self.shift = [sum(int(bit) << j for j, bit in enumerate(row)) for row in shift_bits]
        directions = direction_numbers(d)
        scrambled = []
        for k in range(d):
            # Row p of the matrix (unit diagonal) read as an integer, its column i the
            # bit BITS−1−i: bit BITS−1−p of a scrambled number is its parity with v.
            rows = []
            for p in range(BITS):
                bits = matrices[k, p].tolist()
                bits[p] = 1
                rows.append(sum(bit << (BITS - 1 - i) for i, bit in enumerate(bits)))
            scrambled.append([sum(_parity(rows[p] & v) << (BITS - 1 - p) for p in range(BITS))
                              for v in directions[k]])
        self.d = d
        self.directions = np.array(scrambled, dtype=np.uint32).T   # (BITS, d)
        self.position = start

    def point_bits(self, index: int) -> NDArray:
        """The integer coordinates of point ``index``: the shift ⊕ the direction numbers
        of the set bits of its Gray code index ^ (index >> 1)."""
        gray = index ^ (index >> 1)
        value = np.array(self.shift, dtype=np.uint32)
        for j in range(BITS):
            if (gray >> j) & 1:
                value ^= self.directions[j]
        return value

    def next(self, count: int) -> NDArray:
        """The next ``count`` points, shape (count, d), in [0, 1) (column-major: each
        input's values are contiguous, as the inverse CDFs read them)."""
        out = np.empty((self.d, max(count, 0)))
        if count <= 0:
            return out.T
        first = self.position
        lowest_zero = _lowest_zero_bits(first, count - 1)
        start = self.point_bits(first)
        steps = np.empty(count, dtype=np.uint32)
        for j in range(self.d):
            steps[0] = start[j]
            np.take(self.directions[:, j], lowest_zero, out=steps[1:])
            np.bitwise_xor.accumulate(steps, out=steps)
            np.multiply(steps, SCALE, out=out[j])
        self.position += count
        return out.T


#: The start of the warning scipy.stats.qmc.Sobol gives when a sequence's first draw is
#: not a power of 2 points long: a study cuts its stream where its chunks end, and the
#: points are the sequence's all the same.
_BALANCE_WARNING = "The balance properties of Sobol' points"
#: warnings.catch_warnings swaps the filters of the whole process, and the Monte Carlo
#: workers draw in parallel threads: they take turns at changing the filters.
_WARNING_FILTERS = threading.Lock()


class ScipySobolStream:
    """The points of :class:`SobolStream`, drawn by ``scipy.stats.qmc.Sobol(d,
    scramble=True, rng=seed)`` fast-forwarded to ``start``: the fallback for a scipy
    whose direction numbers are not where :func:`direction_file` looks."""

    def __init__(self, d: int, seed: int, start: int = 0) -> None:
        from scipy.stats import qmc

        self.d = d
        self.engine = qmc.Sobol(d, scramble=True, rng=seed)
        if start:
            self.engine.fast_forward(start)

    def next(self, count: int) -> NDArray:
        """The next ``count`` points, shape (count, d), column-major like SobolStream's
        (a copy: the caller may write to it)."""
        if count <= 0:
            return np.empty((self.d, 0)).T
        with _WARNING_FILTERS, warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=_BALANCE_WARNING, category=UserWarning)
            points = self.engine.random(count)
        return np.array(points, order="F")


def sobol_stream(d: int, seed: int, start: int = 0) -> SobolStream | ScipySobolStream:
    """Points ``start``, ``start + 1``, … of scipy's scrambled Sobol' sequence in d
    dimensions with seed ``seed``: by :class:`SobolStream` from scipy's direction
    numbers, or by scipy.stats.qmc.Sobol when its data file is not where it was."""
    if _direction_table(direction_file()) is None:
        return ScipySobolStream(d, seed, start)
    return SobolStream(d, seed, start)


#: Trailing one bits of every 16-bit number: the lowest zero bit of k is found from its
#: low 16 bits, except when those are all ones (once in 65,536 indices).
_LOW16 = 1 << 16


@functools.cache
def _trailing_ones_table() -> NDArray:
    k = np.arange(_LOW16, dtype=np.int64)
    table = np.zeros(_LOW16, dtype=np.intp)
    rest = k.copy()
    for bit in range(16):
        ones = (rest & 1) == 1
        table += ones & (table == bit)
        rest >>= 1
    return table


def _lowest_zero_bits(first: int, count: int) -> NDArray:
    """For k = first … first + count − 1, the position of the lowest zero bit of k (the
    direction number that takes point k to point k + 1).

    The positions repeat with period 2^16 except where the low 16 bits of k are all
    ones: the table, rotated to ``first``, is tiled, and those few are fixed.
    """
    table = _trailing_ones_table()
    offset = first & (_LOW16 - 1)
    positions = np.resize(np.roll(table, -offset), count)
    for i in range(_LOW16 - 1 - offset, count, _LOW16):
        k = first + i
        positions[i] = (~k & (k + 1)).bit_length() - 1
    return positions
