"""Running statistics of Monte Carlo results: exact sums, extremes and a fixed
histogram for the quantiles, none of which depend on how the samples are chunked."""

from __future__ import annotations

import copy
import math

import numpy as np
from numpy.typing import NDArray

#: Samples per block: the unit of exact summation and the pilot for histogram ranges.
BLOCK = 1 << 16
#: Histogram bins per result for the Monte Carlo quantiles.
HISTOGRAM_BINS = 1 << 16
QUANTILES = {"p00135": 0.00135, "p50": 0.5, "p99865": 0.99865}


class _Scratch:
    """One worker's temporary arrays, grown as needed and reused for every result and
    chunk, so that counting a chunk allocates nothing."""

    def __init__(self) -> None:
        self._floats = np.empty(0)
        self._ints = np.empty(0, dtype=np.int64)

    def floats(self, size: int) -> NDArray:
        if self._floats.size < size:
            self._floats = np.empty(size)
        return self._floats[:size]

    def ints(self, size: int) -> NDArray:
        if self._ints.size < size:
            self._ints = np.empty(size, dtype=np.int64)
        return self._ints[:size]


class _Histogram:
    """Counts of one result in ``HISTOGRAM_BINS`` bins spanning three times the range
    of a pilot sample, centred on it, plus one bin each side for values outside.

    A value's bin is floor((x − edge)·(1/width)) + 1, clipped to [0,
    HISTOGRAM_BINS + 1] (the two overflow bins), in that order of operations.
    """

    def __init__(self, pilot: NDArray) -> None:
        finite = pilot[np.isfinite(pilot)]
        low, high = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
        span = high - low
        if span <= 0:
            span = max(abs(low) * 1e-9, 1e-300)
        self.edge = low - span
        self.width = 3.0 * span / HISTOGRAM_BINS
        self.counts = np.zeros(HISTOGRAM_BINS + 2, dtype=np.int64)

    def empty_like(self) -> _Histogram:
        """A histogram with the same bins and nothing counted."""
        twin = copy.copy(self)
        twin.counts = np.zeros_like(self.counts)
        return twin

    def add(self, values: NDArray, low: float, high: float, scratch: _Scratch) -> None:
        """Count finite ``values`` whose min and max are ``low`` and ``high``, in place
        (no 65,538-bin array to allocate, zero and add a chunk)."""
        scale = 1.0 / self.width
        if low == high:
            # A result that does not vary (a speed the spec fixes): one bin takes all.
            index = math.floor((low - self.edge) * scale)
            self.counts[min(max(index, -1), HISTOGRAM_BINS) + 1] += len(values)
            return
        index = scratch.floats(len(values))
        np.subtract(values, self.edge, out=index)
        np.multiply(index, scale, out=index)
        bins = scratch.ints(len(values))
        # (x − edge)·scale rounds monotonically, so the chunk's extremes bound every
        # index: when all lie in [0, HISTOGRAM_BINS + 1), truncation is the floor and
        # nothing is clipped, and the same bins take three passes fewer.
        if (low - self.edge) * scale >= 0.0 and (high - self.edge) * scale < HISTOGRAM_BINS + 1:
            np.copyto(bins, index, casting="unsafe")
            np.add.at(self.counts[1:], bins, 1)   # bin floor(index) + 1
            return
        np.floor(index, out=index)
        np.clip(index, -1, HISTOGRAM_BINS, out=index)
        np.add(index, 1.0, out=index)
        np.copyto(bins, index, casting="unsafe")
        np.add.at(self.counts, bins, 1)

    def merge(self, other: _Histogram) -> None:
        """Add the counts of a histogram with the same bins."""
        self.counts += other.counts

    def order_statistic(self, cumulative: NDArray, rank: int, low: float, high: float
                        ) -> float:
        """The value of rank ``rank`` (0-based) placed within its bin; ``cumulative`` is
        the running sum of the counts, ``low`` and ``high`` the extremes counted (all
        that is known of a value in an overflow bin)."""
        index = int(np.searchsorted(cumulative, rank, side="right"))
        before = int(cumulative[index - 1]) if index > 0 else 0
        if index == 0:
            return low  # below the histogram: only the minimum is known
        if index == len(self.counts) - 1:
            return high
        fraction = (rank - before + 0.5) / int(self.counts[index])
        return self.edge + (index - 1 + fraction) * self.width

    def in_range(self) -> tuple[NDArray, NDArray]:
        """(edges, counts) of the in-range bins."""
        edges = self.edge + self.width * np.arange(HISTOGRAM_BINS + 1)
        return edges, self.counts[1:-1].copy()


class _Accumulator:
    """Running statistics of one result, exact however the samples are chunked.

    Values are shifted by the nominal result before summing, which keeps the
    variance free of cancellation. Quantiles come from a histogram of
    ``HISTOGRAM_BINS`` bins spanning three times the range of the first
    ``BLOCK`` samples (the pilot), centred on it, plus one bin each side for
    values outside. A quantile interpolates between the two order statistics
    around it, each placed within its bin, so it is off by at most one bin
    width, 1/21845 of the pilot's range.
    """

    def __init__(self, shift: float, pilot: NDArray) -> None:
        self.shift = shift if math.isfinite(shift) else 0.0
        self.bins = _Histogram(pilot)
        self.sums: list[float] = []
        self.squares: list[float] = []
        self.count = 0
        self.low, self.high = math.inf, -math.inf

    def empty_like(self) -> _Accumulator:
        """An accumulator with the same shift and bins and nothing counted."""
        twin = copy.copy(self)
        twin.sums, twin.squares = [], []
        twin.bins = self.bins.empty_like()
        return twin

    def add(self, values: NDArray, scratch: _Scratch | None = None) -> None:
        """Count a chunk of values that starts on a block boundary; NaN is skipped.

        ``scratch`` holds the worker's temporary arrays, reused from chunk to chunk.
        """
        scratch = scratch or _Scratch()
        size = len(values)
        blocks = -(-size // BLOCK)
        padded = scratch.floats(blocks * BLOCK)
        shifted = padded[:size]
        np.subtract(values, self.shift, out=shifted)
        padded[size:] = 0.0
        per_block = padded.reshape(blocks, BLOCK)
        sums = per_block.sum(axis=1)
        kept = values
        if not np.isfinite(sums).all():
            # A NaN or an infinity somewhere in the chunk (a finite chunk's block sums
            # are finite unless they overflow): what is not finite counts as 0 here and
            # is left out of the count, the extremes and the histogram.
            finite = np.isfinite(values)
            shifted[~finite] = 0.0
            sums = per_block.sum(axis=1)
            kept = values[finite]
        self.sums.extend(sums.tolist())
        # np.sum's pairwise order depends only on the block, not on where the chunk
        # sits in memory (einsum's does), which keeps the result chunk-invariant.
        np.square(per_block, out=per_block)
        self.squares.extend(per_block.sum(axis=1).tolist())
        self.count += kept.size
        if kept.size == 0:
            return
        # + 0.0 makes a zero positive: which signed zero np.min meets first depends on
        # the chunking, and the result must not.
        low, high = float(kept.min()) + 0.0, float(kept.max()) + 0.0
        self.low, self.high = min(self.low, low), max(self.high, high)
        self.bins.add(kept, low, high, scratch)

    def merge(self, other: _Accumulator) -> None:
        """Add another accumulator's counts (sums are exact, so order does not matter)."""
        self.sums.extend(other.sums)
        self.squares.extend(other.squares)
        self.count += other.count
        self.low = min(self.low, other.low)
        self.high = max(self.high, other.high)
        self.bins.merge(other.bins)

    def summary(self) -> dict[str, float | None]:
        n = self.count
        if n == 0:
            return {name: None for name in ("mean", "std", "min", "max", *QUANTILES)}
        total, squares = math.fsum(self.sums), math.fsum(self.squares)
        mean_shifted = total / n
        variance = max(squares - total * mean_shifted, 0.0) / (n - 1) if n > 1 else 0.0
        out: dict[str, float | None] = {
            "mean": self.shift + mean_shifted,
            "std": math.sqrt(variance),
            "min": self.low,
            "max": self.high,
        }
        for name, q in QUANTILES.items():
            out[name] = self.quantile(q)
        return out

    def quantile(self, q: float) -> float:
        """The q-quantile as numpy's default (linear) method defines it, placing the two
        order statistics around it each within its bin: off by at most one bin width."""
        if self.low == self.high:
            return self.low
        rank = q * (self.count - 1)
        below = math.floor(rank)
        cumulative = np.cumsum(self.bins.counts)
        lower = self.bins.order_statistic(cumulative, below, self.low, self.high)
        upper = self.bins.order_statistic(cumulative, min(below + 1, self.count - 1),
                                          self.low, self.high)
        value = lower + (rank - below) * (upper - lower)
        return float(min(max(value, self.low), self.high))

    def histogram(self) -> tuple[NDArray, NDArray]:
        """(edges, counts) of the in-range bins."""
        return self.bins.in_range()


def coarse_histogram(edges: NDArray, counts: NDArray, bins: int
                     ) -> tuple[NDArray, NDArray, NDArray]:
    """(low edges, high edges, counts) of at most ``bins`` bars merging the fine bins
    between the first and last occupied one; empty when nothing was counted."""
    occupied = np.flatnonzero(counts)
    if occupied.size == 0:
        return np.empty(0), np.empty(0), np.empty(0, dtype=np.int64)
    first, last = occupied[0], occupied[-1] + 1
    groups = np.array_split(np.arange(first, last), min(bins, last - first))
    lows = np.array([edges[g[0]] for g in groups])
    highs = np.array([edges[g[-1] + 1] for g in groups])
    totals = np.array([counts[g].sum() for g in groups], dtype=np.int64)
    return lows, highs, totals
