"""What a solver module tells the registry about itself, and what it returns.

Every solver module exports one :class:`Solver`: its results (SI unit and meaning),
status reasons, warnings, table layout and its ``evaluate`` function, which maps SI
inputs (floats or broadcasting arrays) to a :class:`Solution`. The registry
(:mod:`bearingcalc.kinds`) reads that object and nothing else.

A composite solver (a drive of bearings) solves its members with a member solver and
reports each member's status codes as data, by the member's name in the spec
(``pinion_bearings.2``); the registry gives those failures codes of their own.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, field
from typing import Any

from numpy.typing import NDArray


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


@dataclass(frozen=True)
class Members:
    """The members of a composite solver: which solver solves them, their names in the
    spec, and the member fields the composite sets from fields of its own (a bearing's
    speed is the drive's input_speed): a member's failure of those names the composite's
    field."""

    solver: Solver
    names: tuple[str, ...]
    set_by_composite: Mapping[str, str] = field(default_factory=dict)


#: A duty cycle's per-bin results are keyed ``{BIN_PREFIX}{k}_{column}``, k from 1.
BIN_PREFIX = "duty_"
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
    add ``results``, and per bin ``duty_{k}_{column}`` (k from 1) for each of
    ``columns``."""

    #: ``combine(per_bin, inputs)`` -> the cycle's Solution
    combine: Callable[[Solution, Mapping[str, Any]], Solution]
    #: results only a cycle has: key -> (SI unit, meaning)
    results: Mapping[str, tuple[str, str]]
    #: per-bin results: column -> (SI unit, meaning)
    columns: Mapping[str, tuple[str, str]]
    #: columns that are +inf for a bin that does not turn
    unbounded: tuple[str, ...] = ()


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
    #: table heading -> (row prefixes, column suffixes): results shown as a small table,
    #: a row per member (``pinion_bearing_1``) and a column per quantity, keyed
    #: ``{row}_{column}``
    matrices: Mapping[str, tuple[tuple[str, ...], tuple[str, ...]]] = field(
        default_factory=dict)
    #: result key -> (table unit, factor from SI), where the SI unit's usual one won't do
    display: Mapping[str, tuple[str, float]] = field(default_factory=dict)
    #: the members of a composite solver, or None
    members: Members | None = None
    #: result key -> {value: text}: results a table shows as words (a load case "1a"),
    #: while JSON and CSV keep the number
    labels: Mapping[str, Mapping[float, str]] = field(default_factory=dict)
    #: how the solver combines a duty cycle's bins, or None (no duty cycles)
    duty: DutyCycle | None = None
