"""Duty cycles in specs: a list of bins, each a share of the time with the operating
fields that differ from the spec's own (``docs/specs.md``, "Duty cycles").

A kind that takes a duty cycle mixes in :class:`DutyCycleRules`, declares
``duty_cycle: list[<its bin model>] | None`` (made by :func:`bin_model`) and names its
bin fields in ``BIN_FIELDS``. Each bin is the spec with the bin's fields in place of the
spec's (the spec's own values are the defaults): the kind's rules check every bin as a
spec of its own, and the solver receives every bin at once, along the first axis of
each input (:class:`bearingcalc.core.solver.DutyCycle`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from pydantic import Field, create_model

from bearingcalc.core.solver import MAX_BINS, bin_rows
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import SpecModel
from bearingcalc.models.field_path import FieldPath, replaced
from bearingcalc.models.plain_numbers import percentage
from bearingcalc.models.quantities import PositiveViscosity, Temperature
from bearingcalc.models.rules import whole_spec_problems, whole_spec_rule

if TYPE_CHECKING:  # the results' layout only: made above the models
    from bearingcalc.result_keys import ResultTable


class _NoBins:
    """No table of bins: every column of it absent."""

    @staticmethod
    def column(column: str) -> list[None]:
        return [None]


_NO_BINS = _NoBins()
#: The bins' shares of the damage a note names the worst bin by: the bearings', else the
#: teeth's in bending.
_DAMAGE_SHARES = (("damage_share", "damage"), ("bending_damage_share", "bending damage"))

#: How far the time shares may add up from 100 %.
SHARE_TOLERANCE = 0.001

TimeShare = percentage(0.0, 1.0, "a share of the cycle's time", what="time share",
                       example="15")


class DutyBin(SpecModel):
    """One bin of a duty cycle: a share of the time, and optionally a name."""

    name: str | None = Field(None, description="the bin's name; its number by default")
    time: TimeShare = Field(description="the bin's share of the time, like 15 % or 0.15")


def bin_model(name: str, fields: Mapping[str, tuple[Any, str]]) -> type[DutyBin]:
    """A kind's bin model: :class:`DutyBin` with each of ``fields`` (annotation,
    description) optional."""
    return create_model(name, __base__=DutyBin,  # type: ignore[call-overload, no-any-return]
                        **{field: (annotation | None, Field(None, description=description))
                           for field, (annotation, description) in fields.items()})


#: The oil a bin of a kind with rolling bearings may set (bin field -> annotation and
#: description), and the spec's field each sets: a cold start, a hot peak.
OIL_BIN_FIELDS: dict[str, tuple[Any, str]] = {
    "temperature": (Temperature, "operating temperature of the bearings' oil (with its "
                    "grade)"),
    "viscosity": (PositiveViscosity, "operating viscosity ν of the bearings' oil")}
OIL_BIN_PATHS = {"temperature": "lubrication.temperature",
                 "viscosity": "lubrication.viscosity"}


class BinOilRules:
    """The rule of a spec whose bins may set its oil (:data:`OIL_BIN_FIELDS`)."""

    if TYPE_CHECKING:
        duty_cycle: list[Any] | None
        lubrication: Any

        def bin_label(self, k: int) -> str: ...

    @whole_spec_rule
    def _bins_and_oil(self) -> SpecFieldError | None:
        """A bin's temperature needs the oil's grade, a bin's viscosity the oil given by
        its viscosity: the spec's lubrication says which."""
        lubrication = self.lubrication
        for k, item in enumerate(self.duty_cycle or [], 1):
            for field, needed in (("temperature", "viscosity_40"), ("viscosity", "viscosity")):
                if getattr(item, field) is not None and (
                        lubrication is None or getattr(lubrication, needed) is None):
                    return SpecFieldError(
                        f"duty_cycle.{k}.{field}", f"bin {self.bin_label(k)}: a bin's {field} "
                        f"needs lubrication: {{{needed}: ...}} in the spec itself"
                        + (", with viscosity_100" if needed == "viscosity_40" else ""))
        return None


class DutyCycleRules:
    """The rules and solver inputs of a spec with an optional duty cycle."""

    #: bin field -> the spec's dotted field it sets
    BIN_FIELDS: ClassVar[Mapping[str, str]] = {}
    #: bin field -> the field, or fields, it stands in for where the bin leaves them out
    #: (a bin's torque replaces the spec's power; its ring speeds the spec's speed)
    ALTERNATIVES: ClassVar[Mapping[str, str | tuple[str, ...]]] = {}
    #: the bin field that gives the load as a power, which a bin at rest cannot take
    POWER_FIELD: ClassVar[str | None] = None
    #: the fields the rules' subjects are made from (see rules.whole_spec_rule)
    SUBJECT_FIELDS: ClassVar[tuple[str, ...]] = ("duty_cycle",)

    if TYPE_CHECKING:
        duty_cycle: list[Any] | None

        def solver_inputs(self) -> Mapping[str, Any]: ...

        def model_copy(self, *, update: Mapping[str, Any] | None = None) -> Any: ...

    def turning_speed(self) -> Any:
        """The speed whose revolutions a life counts. [rad/s]"""
        raise NotImplementedError

    def with_turning_speed(self, speed: Any) -> Any:
        """The spec turning at ``speed`` instead. [rad/s]"""
        raise NotImplementedError

    def bin_label(self, k: int) -> str:
        """How messages name bin ``k`` (from 1): its number, and its name if it has one."""
        assert self.duty_cycle is not None
        name = self.duty_cycle[k - 1].name
        return f"{k} ({name})" if name else str(k)

    def bins(self, stand_in: bool = True) -> list[Any]:
        """Each bin as a spec of its own (without a duty cycle). With ``stand_in``, a bin
        at rest turns at the cycle's fastest speed, so the kind's rules and solver, which
        need a turning spec, take it: its life counts for nothing."""
        views = self._as_written()
        return _standing_in(views) if stand_in else views

    def _as_written(self) -> list[Any]:
        """Each bin as a spec of its own, speeds as the bins and the spec give them."""
        assert self.duty_cycle is not None
        base = self.model_copy(update={"duty_cycle": None})
        views = []
        for item in self.duty_cycle:
            changes = []
            for field, path in self.BIN_FIELDS.items():
                if getattr(item, field) is not None:
                    changes.append((FieldPath.parse(path), getattr(item, field)))
                    others = self.ALTERNATIVES.get(field, ())
                    for other in (others,) if isinstance(others, str) else others:
                        if getattr(item, other) is None:
                            changes.append((FieldPath.parse(self.BIN_FIELDS[other]), None))
            views.append(replaced(base, changes))
        return views

    def cycle_inputs(self) -> dict[str, Any]:
        """The solver inputs of every bin, along the first axis of each, with
        ``duty_time`` and ``duty_speed`` (0 for a bin at rest)."""
        assert self.duty_cycle is not None
        written = self._as_written()
        inputs = _over_bins([view.solver_inputs() for view in _standing_in(written)])
        # a study may vary a bin's share as it varies any number: broadcast the bins'
        inputs["duty_time"] = np.stack(np.broadcast_arrays(
            *(np.asarray(item.time, dtype=float) for item in self.duty_cycle)))
        inputs["duty_speed"] = np.stack(np.broadcast_arrays(*map(_speed, written)))
        return _bins_first(inputs, _design_rank(inputs))

    def row_names(self) -> dict[str, str]:
        """Each bin's name, by the prefix of its results (``duty_1``)."""
        if not self.duty_cycle:
            return {}
        rows = zip(bin_rows(len(self.duty_cycle)), self.duty_cycle, strict=True)
        return {row: item.name or str(k) for k, (row, item) in enumerate(rows, 1)}

    def result_notes(self, results: Mapping[str, float | None],
                     tables: Sequence[ResultTable] = ()) -> list[str]:
        """The bin that does the most damage, with its shares of the time and the damage
        (of the bearings', else of the teeth's in bending)."""
        if not self.duty_cycle or len(self.duty_cycle) < 2:
            return []
        bins = next((table for table in tables if table.axis == "bin"), _NO_BINS)
        for column, what in _DAMAGE_SHARES:
            shares = [None if key is None else results.get(key) for key in bins.column(column)]
            if all(share is not None for share in shares):
                k = 1 + max(range(len(shares)), key=lambda i: shares[i])  # type: ignore[arg-type, return-value]
                return [f"bin {self.bin_label(k)} does the most {what}: "
                        f"{100 * self.duty_cycle[k - 1].time:.3g} % of the time, "
                        f"{100 * shares[k - 1]:.3g} % of the {what}"]  # type: ignore[operator]
        return []

    def rule_subjects(self) -> list[tuple[Any, Callable[[SpecFieldError, bool],
                                                        SpecFieldError]]] | None:
        """What the kind's rules check: each bin as a spec, with how its problems read
        (a field the bin sets named in the bin; one the bins share, once); None without
        a duty cycle, none for a cycle its own rules refuse."""
        if self.duty_cycle is None:
            return None
        if whole_spec_problems(self):  # type: ignore[arg-type]
            return []  # a cycle refused as a whole: its bins' own problems would be noise
        written = self._as_written()
        return [(view, self._renamer(k)) for k, view in enumerate(_standing_in(written), 1)]

    def _renamer(self, k: int) -> Callable[[SpecFieldError, bool], SpecFieldError]:
        assert self.duty_cycle is not None
        item = self.duty_cycle[k - 1]
        given = {path: field for field, path in self.BIN_FIELDS.items()
                 if getattr(item, field) is not None}

        def rename(problem: SpecFieldError, shared: bool) -> SpecFieldError:
            if problem.field in given:
                return SpecFieldError(f"duty_cycle.{k}.{given[problem.field]}",
                                      f"bin {self.bin_label(k)}: {problem.message}")
            if shared:
                return problem
            return SpecFieldError(problem.field, f"bin {self.bin_label(k)}: {problem.message}",
                                  at=problem.at or f"duty_cycle.{k}.time")
        return rename

    @whole_spec_rule
    def _cycle_given_right(self) -> SpecFieldError | None:
        bins = self.duty_cycle
        if bins is None:
            return None
        if not bins:
            return SpecFieldError("duty_cycle", "is empty: give at least one bin, like "
                                  "[{time: 100 %, radial_load: 5 kN}], or leave it out")
        if len(bins) > MAX_BINS:
            return SpecFieldError("duty_cycle", f"has {len(bins)} bins; at most {MAX_BINS}: "
                                  "bin the spectrum coarser")
        total = math.fsum(item.time for item in bins)
        if abs(total - 1.0) > SHARE_TOLERANCE:
            return SpecFieldError("duty_cycle", f"the time shares add up to {100 * total:g} %"
                                  f", not 100 % (within {100 * SHARE_TOLERANCE:g} %)")
        written = self._as_written()
        for k, view in enumerate(written, 1):
            if self.POWER_FIELD is not None and getattr(view, self.POWER_FIELD) is not None \
                    and view.turning_speed() is not None and not np.any(_speed(view) > 0):
                return SpecFieldError(f"duty_cycle.{k}.time", f"bin {self.bin_label(k)} is at "
                                      "rest, where a power gives no torque: give the bin's "
                                      "torque, like 120 N*m")
        if not _turns(written, [item.time for item in bins]):
            at_rest = all(not _turns([view], [1.0]) for view in written)
            return SpecFieldError("duty_cycle", ("every bin is at rest" if at_rest else
                                                 "every bin that turns has 0 % of the time")
                                  + ": the life needs a bin that turns for a share of the "
                                  "time above 0 (a bin at zero speed, or of 0 %, counts for "
                                  "the static safety only)")
        return None


def _turns(views: list[Any], times: list[float]) -> bool:
    """Whether a bin turns for a share of the time (or leaves its speed out: the kind's
    rules judge that)."""
    return any(time > 0 and (view.turning_speed() is None
                             or np.any(np.asarray(view.turning_speed(), dtype=float) != 0))
               for view, time in zip(views, times, strict=True))


def _standing_in(views: list[Any]) -> list[Any]:
    """The bins, each at rest turning at the fastest bin's speed instead (see
    :meth:`DutyCycleRules.bins`); a bin with no speed at all stays without, for the
    kind's rules to say so."""
    speeds = [_speed(view) for view in views]
    fastest = np.max(np.stack(np.broadcast_arrays(*speeds)), axis=0)
    return [view if view.turning_speed() is None or np.all(speed > 0)
            else view.with_turning_speed(np.where(speed > 0, speed, fastest))
            for view, speed in zip(views, speeds, strict=True)]


def _speed(view: Any) -> Any:
    """A bin's turning speed, 0 where it gives none. [rad/s]"""
    speed = view.turning_speed()
    return np.abs(np.asarray(0.0 if speed is None else speed, dtype=float))


def _over_bins(per_bin: list[Any]) -> Any:
    """Solver inputs of the bins, with each number replaced by an array of the bins'
    along a new first axis; words must agree (a bearing type)."""
    first = per_bin[0]
    if isinstance(first, dict):
        return {key: _over_bins([each[key] for each in per_bin]) for key in first}
    if isinstance(first, list):
        return [_over_bins([each[i] for each in per_bin]) for i in range(len(first))]
    if isinstance(first, str) or all(each is None for each in per_bin):
        return first
    # A field some bins give in one form and others in another (torque or power): NaN
    # where a bin gives the other, for the solver to take that.
    return np.stack(np.broadcast_arrays(*(np.asarray(np.nan if each is None else each,
                                                     dtype=float) for each in per_bin)))


def _design_rank(inputs: Any) -> int:
    """The most axes any input has after the bins' (those of a study's designs)."""
    if isinstance(inputs, dict):
        return max((_design_rank(value) for value in inputs.values()), default=0)
    if isinstance(inputs, list):
        return max((_design_rank(item) for item in inputs), default=0)
    return np.ndim(inputs) - 1 if isinstance(inputs, np.ndarray) else 0


def _bins_first(inputs: Any, rank: int) -> Any:
    """Every input with the bins on its first axis and ``rank`` design axes after them
    (length 1 where it does not vary), so that inputs broadcast bin by bin."""
    if isinstance(inputs, dict):
        return {key: _bins_first(value, rank) for key, value in inputs.items()}
    if isinstance(inputs, list):
        return [_bins_first(item, rank) for item in inputs]
    if not isinstance(inputs, np.ndarray):
        return inputs
    design = inputs.shape[1:]
    return inputs.reshape((inputs.shape[0], *(1,) * (rank - len(design)), *design))

