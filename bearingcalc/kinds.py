"""The registry of spec kinds: one entry per rolling system.

Adding a kind takes a solver module in ``core/`` that describes itself in a
:class:`~bearingcalc.core.solver.Solver` named ``SOLVER``, a spec model in ``models/``
derived from :class:`~bearingcalc.models.base.Spec`, a template in ``templates/``, a
page in ``docs/kinds/``, and one entry here; every command picks it up.
"""

from __future__ import annotations

import functools
import importlib
import re
from collections.abc import Collection, Iterator, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core.common import STATUS_DTYPE
from bearingcalc.core.solver import BIN_PREFIX, MAX_BINS, Members, Solution, Solver
from bearingcalc.verdicts import (
    CONTACT,
    LIFE,
    PAIR,
    SPIN_TO_ROLL,
    STATIC,
    Judged,
    smallest_bearing_safety,
)

if TYPE_CHECKING:
    from bearingcalc.models.base import Spec

#: Status of a design whose inputs are valid but whose results overflow double precision.
OUT_OF_RANGE = 99
#: The first status code of a composite's members (the composite's own and the last
#: guard come before).
MEMBER_CODES_FROM = 100
OUT_OF_RANGE_REASON = ("", "the design's numbers are out of the range of double precision; "
                       "check the magnitudes of the inputs")


@dataclass(frozen=True)
class Kind:
    """What every command needs to know of one spec kind."""

    name: str
    summary: str
    #: "module:Class" of the spec model and the solver module, imported on first use:
    #: a command that reads one kind builds only that kind's pydantic model.
    model_path: str
    solver_path: str
    margins: tuple[str, ...]   # result keys that must be >= 0 for the design to pass
    governing: tuple[str, ...]  # results a study shows first
    #: result key -> the solver input that limits it symmetrically: |result| <= limit
    limits: dict[str, str] = field(default_factory=dict)
    #: results that may legitimately be +inf (an edge that no design reaches)
    unbounded: tuple[str, ...] = ()
    #: margin key -> what it judges, for verdicts in engineering terms
    judged: Mapping[str, Judged] = field(default_factory=dict)

    @property
    def model(self) -> type[Spec]:
        """The kind's pydantic spec model."""
        module, _, name = self.model_path.partition(":")
        return getattr(importlib.import_module(module), name)  # type: ignore[no-any-return]

    @property
    def limit_fields(self) -> list[str]:
        """The fields of the spec's ``limits`` block, which set the margins (or none)."""
        from bearingcalc.models.base import nested_model

        limits = self.model.model_fields.get("limits")
        held = nested_model(limits) if limits is not None else None
        return list(held.model_fields) if held is not None else []

    @property
    def solver(self) -> Solver:
        """The kind's solver, as its module describes it (``SOLVER``)."""
        return importlib.import_module(self.solver_path).SOLVER  # type: ignore[no-any-return]

    def evaluate(self, inputs: Mapping[str, Any], wanted: Collection[str] | None = None
                 ) -> tuple[dict[str, NDArray], NDArray]:
        """Results and status codes (0 = feasible) of the solver on SI ``inputs``.

        ``wanted`` names the results the caller needs; a solver may compute only
        those (and the margins), or everything. A design the solver calls feasible
        but whose numbers are not finite (an overflow) gets ``OUT_OF_RANGE``, so no
        command ever prints or judges a non-finite number as a design's result.
        """
        results, status, _ = self.evaluate_with_warnings(inputs, wanted)
        return results, status

    def evaluate_with_warnings(self, inputs: Mapping[str, Any],
                               wanted: Collection[str] | None = None
                               ) -> tuple[dict[str, NDArray], NDArray, dict[str, NDArray]]:
        """:meth:`evaluate`, plus where each of the solver's warnings holds."""
        with np.errstate(all="ignore"):
            solution = self.solver.evaluate(inputs, wanted)
            duty = self.solver.duty
            if duty is not None and inputs.get("duty_time") is not None:
                solution = duty.combine(solution, inputs)
            status = self._with_member_failures(solution)
            for key, values in solution.results.items():
                finite = np.isfinite(values)
                if key in self.unbounded or bin_column(key) in self._unbounded_columns:
                    finite |= values == np.inf
                if not finite.all():
                    status = np.where(finite | (status != 0), status, STATUS_DTYPE(OUT_OF_RANGE))
        return solution.results, status, solution.warnings

    def _with_member_failures(self, solution: Solution) -> NDArray:
        """The solution's status, where the design itself is possible but a member is not
        given that member's code (see :meth:`status_reasons`)."""
        members = self.solver.members
        status = solution.status
        if members is None:
            return status
        for index, name in enumerate(members.names):
            codes = solution.members.get(name)
            if codes is not None and np.any(codes):
                offset = STATUS_DTYPE(self._member_offset(index))
                status = np.where((status == 0) & (codes != 0), offset + codes, status)
        return status

    def _member_offset(self, index: int) -> int:
        members = self.solver.members
        assert members is not None
        return MEMBER_CODES_FROM + index * (max(members.solver.status_reasons) + 1)

    def limit_values(self, inputs: Mapping[str, Any]) -> dict[str, float]:
        """Result key -> its symmetric limit, read from the solver ``inputs`` (a limit is
        one number, repeated along a duty cycle's bins)."""
        return {key: float(np.asarray(inputs[limit], dtype=float).flat[0])
                for key, limit in self.limits.items()}

    def within_limits(self, results: Mapping[str, NDArray], status: NDArray) -> NDArray:
        """Where a design is possible (status 0) and every margin it has is >= 0."""
        ok = status == 0
        for margin in self.margins:
            if margin in results:
                ok = ok & (results[margin] >= 0)
        return ok

    @functools.cached_property
    def results(self) -> Mapping[str, tuple[str, str]]:
        """Result key -> (SI unit, meaning), in report order; with a duty cycle also the
        cycle's own results and each bin's (``duty_3_speed``)."""
        duty = self.solver.duty
        if duty is None:
            return self.solver.results
        return ResultCatalogue({**self.solver.results, **duty.results}, duty.columns)

    @property
    def _unbounded_columns(self) -> tuple[str, ...]:
        return () if self.solver.duty is None else self.solver.duty.unbounded

    @property
    def groups(self) -> Mapping[str, tuple[str, ...]]:
        """Table heading -> its results, for kinds with many results (else empty)."""
        return self.solver.groups

    @functools.cached_property
    def matrices(self) -> Mapping[str, tuple[tuple[str, ...], tuple[str, ...]]]:
        """Table heading -> (row prefixes, column suffixes): results shown as a small
        table of their own, a row per member (``pinion_bearing_1``) or per bin of a duty
        cycle (``duty_1``) and a column per quantity (``radial_load``), whose keys are
        ``{row}_{column}``."""
        duty = self.solver.duty
        if duty is None:
            return self.solver.matrices
        bins = tuple(f"{BIN_PREFIX}{k}" for k in range(1, MAX_BINS + 1))
        return {**self.solver.matrices, "duty cycle": (bins, tuple(duty.columns))}

    @property
    def display(self) -> Mapping[str, tuple[str, float]]:
        """Result key -> (table unit, factor from SI) where the SI unit alone would not do."""
        return self.solver.display

    @property
    def labels(self) -> Mapping[str, Mapping[float, str]]:
        """Result key -> {value: text}, for results a table shows in words."""
        return self.solver.labels

    @property
    def warnings(self) -> Mapping[str, str]:
        """Warning key -> message, for conditions the solver finds per design."""
        return self.solver.warnings

    @functools.cached_property
    def status_reasons(self) -> dict[int, tuple[str, str]]:
        """Status code -> (field at fault, why): the solver's own; for a composite, each
        member's codes after ``MEMBER_CODES_FROM``, naming the member's field (or the
        composite's field that sets it); and the last guard, ``OUT_OF_RANGE``."""
        solver = self.solver
        reasons = dict(solver.status_reasons)
        if solver.members is not None:
            for index, name in enumerate(solver.members.names):
                offset = self._member_offset(index)
                for code, (field, why) in solver.members.solver.status_reasons.items():
                    where = _member_field(solver.members, name, field)
                    # The composite's own field (a drive's torque) at fault: say which
                    # member it fails.
                    reasons[offset + code] = (where, why if where.startswith(name)
                                              else type(why)(f"at {name}, {why}"))
        reasons[OUT_OF_RANGE] = OUT_OF_RANGE_REASON
        return reasons


_BIN_KEY = re.compile(rf"{BIN_PREFIX}(\d+)_(.+)")


def bin_column(key: str) -> str | None:
    """The column of a per-bin result key (``duty_3_speed`` -> ``speed``), else None."""
    found = _BIN_KEY.fullmatch(key)
    return found.group(2) if found else None


class ResultCatalogue(Mapping[str, tuple[str, str]]):
    """A kind's results, (SI unit, meaning) by key, with the per-bin results of a duty
    cycle found by their column; iterating gives the kind's own results only."""

    def __init__(self, results: Mapping[str, tuple[str, str]],
                 columns: Mapping[str, tuple[str, str]]) -> None:
        self._results = dict(results)
        self._columns = dict(columns)

    def __getitem__(self, key: str) -> tuple[str, str]:
        if key in self._results:
            return self._results[key]
        column = bin_column(key)
        if column is None or column not in self._columns:
            raise KeyError(key)
        unit, meaning = self._columns[column]
        return unit, f"bin {_BIN_KEY.fullmatch(key).group(1)}: {meaning}"  # type: ignore[union-attr]

    def __contains__(self, key: object) -> bool:
        if not isinstance(key, str):
            return False
        try:
            self[key]  # type: ignore[index]
        except KeyError:
            return False
        return True

    def __iter__(self) -> Iterator[str]:
        return iter(self._results)

    def __len__(self) -> int:
        return len(self._results)


def _member_field(members: Members, name: str, field: str) -> str:
    """The composite's name for a member's field: ``pinion_bearings.2.ball_count``, or the
    composite's own field where it sets the member's (a bearing's speed is input_speed)."""
    root, dot, rest = field.partition(".")
    if root in members.set_by_composite:
        return members.set_by_composite[root] + dot + rest
    return f"{name}.{field}"


KINDS: dict[str, Kind] = {
    kind.name: kind
    for kind in (
        Kind("thrust-bearing", "balls between a fixed race and a turning shaft",
             "bearingcalc.models.thrust_bearing:ThrustBearingSpec",
             "bearingcalc.core.thrust_bearing",
             margins=("slip_margin", "contact_pressure_margin"),
             governing=("slip_margin", "spin_to_roll"),
             limits={"spin_to_roll": "max_spin_to_roll"},
             unbounded=("pitch_radius_max",),
             judged={"slip_margin": Judged("spin-to-roll ratio", "spin_to_roll", False),
                     "contact_pressure_margin": CONTACT}),
        Kind("disk-on-circle", "a disk rolling on a fixed or turning circle, outside or inside",
             "bearingcalc.models.disk_on_circle:DiskOnCircleSpec",
             "bearingcalc.core.disk_on_circle", margins=(),
             governing=("contact_point_accel", "center_speed")),
        Kind("cone-on-plane", "a cone rolling on a plane about its fixed apex",
             "bearingcalc.models.cone_on_plane:ConeOnPlaneSpec",
             "bearingcalc.core.cone_on_plane", margins=(),
             governing=("precession_speed",)),
        Kind("bevel-gears", "a bevel pair on fixed axes, or an epicyclic one: gear A on an "
             "arm, gear B on a shaft", "bearingcalc.models.bevel_gears:BevelGearsSpec",
             "bearingcalc.core.bevel_gears",
             margins=("slip_margin", "face_width_margin", "bending_safety_margin",
                      "contact_safety_margin"),
             governing=("bending_safety_margin", "contact_safety_margin", "apex_mismatch",
                        "slip_margin"),
             limits={"apex_mismatch": "max_apex_mismatch"}, judged=PAIR),
        *(Kind(name, summary, "bearingcalc.models.rolling_bearing:RollingBearingSpec",
               "bearingcalc.core.rolling_bearing",
               margins=("life_margin", "static_safety_margin", "contact_pressure_margin",
                        "spin_to_roll_margin"),
               governing=("life_margin", "modified_rating_life", "static_safety_factor"),
               judged={"life_margin": LIFE, "static_safety_margin": STATIC,
                       "contact_pressure_margin": CONTACT,
                       "spin_to_roll_margin": SPIN_TO_ROLL})
          for name, summary in (
              ("rolling-bearing", "a ball or roller bearing, single or paired: ISO 281 "
               "rating life, ISO 76 static safety"),
              ("ball-bearing", "the same as rolling-bearing (its earlier name)"))),
        Kind("bevel-drive", "a bevel pair on two shafts, each on two rolling bearings, "
             "located or adjusted: every bearing's life",
             "bearingcalc.models.bevel_drive:BevelDriveSpec",
             "bearingcalc.core.bevel_drive",
             margins=("slip_margin", "face_width_margin", "bending_safety_margin",
                      "contact_safety_margin", "life_margin", "static_safety_margin"),
             governing=("life_margin", "system_modified_rating_life", "static_safety_margin"),
             judged={**PAIR, "life_margin": Judged("system modified rating life",
                                                   "system_modified_rating_life", True,
                                                   "ratio", "required"),
                     "static_safety_margin": Judged("smallest static safety s0",
                                                    smallest_bearing_safety, True)}),
    )
}


def unknown_kind(name: object) -> str:
    """Why ``name`` is not a kind, with the nearest kind's name and every kind's."""
    from bearingcalc.wording import did_you_mean

    return (f"unknown kind {name!r}{did_you_mean(str(name), KINDS)}; known kinds: "
            f"{', '.join(KINDS)}")
