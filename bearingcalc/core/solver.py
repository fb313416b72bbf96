"""What a solver module tells the registry about itself, and what it returns.

Every solver module exports one :class:`Solver`: its results (SI unit and meaning),
status reasons, warnings, table layout and its ``evaluate`` function, which maps SI
inputs (floats or broadcasting arrays) to a :class:`Solution`. The registry
(:mod:`bearingcalc.kinds`) reads that object and nothing else.

Besides one value per design, a solver may return results along an axis of its own
(:data:`AXES`): a drive's bearings (``member``), a duty cycle's bins (``bin``), and a
bearing's rolling elements and a roller's laminae (``element``, ``lamina``). It declares
each axis's results once (:class:`AxisResults`) and returns them as arrays with that axis
first (:class:`Along`); the flat keys users read (``pinion_bearing_2_axial_load``,
``duty_3_speed``) are made from those at the output edge, by
:func:`bearingcalc.result_keys.flatten`, and nothing parses a key back.

A composite solver (a drive of bearings) solves its members with a member solver and
reports each member's status codes as data, by the member's name in the spec
(``pinion_bearings.2``); the registry gives those failures codes of their own.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, field, replace
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

#: The axes a result may run along besides the designs'.
AXES = ("member", "bin", "element", "lamina")


class AxisResults(NamedTuple):
    """What a solver declares of its results along one axis of :data:`AXES`."""

    #: column -> (SI unit, meaning), in report order
    columns: Mapping[str, tuple[str, str]]
    #: the flat keys follow this result of one value per design ("": after them all)
    after: str = ""
    #: the flat keys row by row (each bearing's together), else column by column
    by_row: bool = True
    #: a flat key's meaning from the column's: ``{meaning}``, the row's ``{position}``
    #: (1 up) and its name in words, ``{row}``
    meaning: str = "{meaning}"
    #: columns that may be +inf (a bin that does not turn lives for ever)
    unbounded: tuple[str, ...] = ()
    #: a design may have fewer rows than another solved with it (its rolling elements):
    #: its rows past its own are NaN, absent rather than out of range
    sparse: bool = False


@dataclass(frozen=True)
class Along:
    """One solution's results along an axis: each array has the axis first, a row per
    position (then the designs' shape)."""

    #: each row's name, the stem of its flat keys (``pinion_bearing_1``, ``duty_3``)
    rows: tuple[str, ...]
    #: column -> values, shape (rows, *designs)
    values: dict[str, NDArray]
    #: the table heading each row is shown under (one per row; empty: the axis's own)
    headings: tuple[str, ...] = ()
    #: column -> which rows have it (a column missing here: every row has it)
    present: Mapping[str, tuple[bool, ...]] = field(default_factory=dict)

    def broadcast(self, shape: tuple[int, ...]) -> Along:
        """The rows with every column broadcast to the designs' ``shape``."""
        return replace(self, values={key: rows_to(values, shape)
                                     for key, values in self.values.items()})

    def has(self, column: str, row: int) -> bool:
        """Whether row ``row`` (from 0) has a value of ``column``."""
        present = self.present.get(column)
        return column in self.values and (present is None or present[row])


def rows_to(values: NDArray, shape: tuple[int, ...]) -> NDArray:
    """Values with a row axis first, (rows, *s), broadcast to (rows, *shape): the
    designs' shape s is aligned to ``shape`` from the right, as numpy aligns it."""
    values = np.asarray(values)
    designs = values.shape[1:]
    padded = values.reshape((values.shape[0],) + (1,) * (len(shape) - len(designs)) + designs)
    return np.broadcast_to(padded, (values.shape[0], *shape))


@dataclass(frozen=True)
class Solution:
    """A solver's answer for a batch of designs, every array of the same shape."""

    #: result key -> values [SI]; NaN where the design is impossible
    results: dict[str, NDArray]
    #: 0 where the design is possible, else a key of the solver's status reasons
    status: NDArray
    #: warning key -> where the warning holds (bool)
    warnings: dict[str, NDArray] = field(default_factory=dict)
    #: member name -> the member solver's status codes (composite solvers only)
    members: dict[str, NDArray] = field(default_factory=dict)
    #: axis (of :data:`AXES`) -> the results along it
    along: dict[str, Along] = field(default_factory=dict)
    #: a composite's parts solved by their own solvers (the pair, each bearing), by
    #: name: what its duty cycle combines by each part's rule
    parts: dict[str, Solution] = field(default_factory=dict)


@dataclass(frozen=True)
class Members:
    """The members of a composite solver: which solver solves them, their names in the
    spec, and the member fields the composite sets from fields of its own (a bearing's
    speed is the drive's input_speed): a member's failure of those names the composite's
    field."""

    solver: Solver
    names: tuple[str, ...]
    set_by_composite: Mapping[str, str] = field(default_factory=dict)


def bin_rows(count: int) -> tuple[str, ...]:
    """The rows of a duty cycle's ``bin`` axis, one per bin: ``duty_1`` … ``duty_{count}``
    (the prefix of each bin's flat result keys)."""
    return tuple(f"duty_{k}" for k in range(1, count + 1))

#: At most this many bins (a spectrum from a load measurement is binned coarser).
MAX_BINS = 1000


@dataclass(frozen=True)
class DutyCycle:
    """How a solver combines the bins of a duty cycle.

    With a duty cycle, every numeric solver input carries the bins along its first axis
    (the designs follow), with ``duty_time`` (each bin's share of the time) and
    ``duty_speed`` (its speed, 0 for a bin that counts for the static safety only). The
    solver solves every bin at once; ``combine`` turns that per-bin :class:`Solution`
    into the cycle's, whose results keep their keys and meanings for the whole cycle,
    add ``results``, and along the ``bin`` axis ``bins``' columns."""

    #: ``combine(per_bin, inputs)`` -> the cycle's Solution
    combine: Callable[[Solution, Mapping[str, Any]], Solution]
    #: results only a cycle has: key -> (SI unit, meaning)
    results: Mapping[str, tuple[str, str]]
    #: the results along the bins
    bins: AxisResults


@dataclass(frozen=True)
class Solver:
    """A solver module's description of itself."""

    #: ``evaluate(inputs, wanted)``: ``wanted`` names the results a caller needs (None:
    #: all); a solver may compute only those and its margins, or everything.
    evaluate: Callable[[Mapping[str, Any], Collection[str] | None], Solution]
    #: result key -> (SI unit, meaning), in report order
    results: Mapping[str, tuple[str, str]]
    #: status code -> (the field at fault, why the design is impossible)
    status_reasons: Mapping[int, tuple[str, str]]
    #: warning key -> the message shown where it holds
    warnings: Mapping[str, str] = field(default_factory=dict)
    #: table heading -> its results, for kinds with many results
    groups: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    #: axis -> its results (a drive's bearings along ``member``)
    along: Mapping[str, AxisResults] = field(default_factory=dict)
    #: result key -> (table unit, factor from SI), where the SI unit's usual one won't do
    display: Mapping[str, tuple[str, float]] = field(default_factory=dict)
    #: the members of a composite solver, or None
    members: Members | None = None
    #: result key -> {value: text}: results a table shows as words (a load case "1a"),
    #: while JSON and CSV keep the number
    labels: Mapping[str, Mapping[float, str]] = field(default_factory=dict)
    #: how the solver combines a duty cycle's bins, or None (no duty cycles)
    duty: DutyCycle | None = None
    #: the name of the typed mapping ``evaluate`` takes in
    #: :mod:`bearingcalc.core.solver_inputs` (by name: a solve never needs the class)
    inputs: str = ""

    def input_type(self) -> type:
        """The ``TypedDict`` of what ``evaluate`` takes."""
        from bearingcalc.core import solver_inputs

        return getattr(solver_inputs, self.inputs)
