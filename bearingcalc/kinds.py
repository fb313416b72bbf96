"""The registry of spec kinds: one entry per rolling system.

Adding a kind takes a solver module in ``core/`` that describes itself in a
:class:`~bearingcalc.core.solver.Solver` named ``SOLVER``, a spec model in ``models/``
derived from :class:`~bearingcalc.models.base.Spec`, a template in ``templates/``, a
page in ``docs/kinds/``, and one entry here; every command picks it up.
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core.solver import AxisResults, Members, Solution, Solver
from bearingcalc.result_keys import FlatResults, flatten
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
#: The heading of the table of an axis's results, where its rows carry none of their own.
#: The gears' displacements at the mesh a drive as mounted may limit, in words.
MESH_DISPLACEMENTS = {"mesh_offset_change": "offset change E",
                      "pinion_axial_shift": "pinion axial shift P",
                      "gear_axial_shift": "gear axial shift G",
                      "shaft_angle_change": "shaft angle change Σ"}
TABLE_HEADINGS = {"bin": "duty cycle", "element": "rolling elements as mounted"}
OUT_OF_RANGE_REASON = ("", "the design's numbers are out of the range of double precision; "
                       "check the magnitudes of the inputs")


class Plot(NamedTuple):
    """A drawing of the kind's calculation report: its name among the report's drawings
    (:data:`bearingcalc.plots.report.DRAWINGS`) and, for a drawing that evaluates more
    than the results, the solver function it calls ("module:function", imported on
    first use), so that the drawings reach the solvers through the registry only."""

    name: str
    solver_function: str = ""

    @property
    def function(self) -> Callable[..., Any]:
        """The solver function the drawing calls."""
        module, _, name = self.solver_function.partition(":")
        return getattr(importlib.import_module(module), name)  # type: ignore[no-any-return]


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
    #: results a study shows first; a tuple among them: the first of it a solve has
    #: (a bearing as mounted shows its reference life before ISO 281's)
    governing: tuple[str | tuple[str, ...], ...]
    #: result key -> the solver input that limits it symmetrically: |result| <= limit
    limits: dict[str, str] = field(default_factory=dict)
    #: results that may legitimately be +inf (an edge that no design reaches)
    unbounded: tuple[str, ...] = ()
    #: why they are, in the warning that says so
    unbounded_reason: str = "the limit holds however far it goes"
    #: margin key -> what it judges, for verdicts in engineering terms
    judged: Mapping[str, Judged] = field(default_factory=dict)
    #: the drawings of its calculation report, in the report's order
    plots: tuple[Plot, ...] = ()
    #: the standards and methods the kind applies, with their sections, as its report
    #: cites them
    standards: tuple[str, ...] = ()

    def governing_of(self, present: Collection[str]) -> list[str]:
        """The governing results among those ``present``, each alternative resolved to
        the first of it present."""
        found = []
        for entry in self.governing:
            choices = (entry,) if isinstance(entry, str) else entry
            found += [key for key in choices if key in present][:1]
        return found

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
                 ) -> tuple[FlatResults, NDArray]:
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
                               ) -> tuple[FlatResults, NDArray, dict[str, NDArray]]:
        """:meth:`evaluate`, plus where each of the solver's warnings holds. The results
        carry each flat key's unit and meaning and the tables along axes
        (:class:`~bearingcalc.result_keys.FlatResults`)."""
        with np.errstate(all="ignore"):
            solution = self.solver.evaluate(inputs, wanted)
            duty = self.solver.duty
            if duty is not None and inputs.get("duty_time") is not None:
                solution = duty.combine(solution, inputs)
            status, reasons = self._statuses(solution)
            status = self._out_of_range(solution, status)
            flat = flatten(solution.results, solution.along, self.results, self.along,
                           TABLE_HEADINGS)
        flat.reasons = reasons
        return flat, status, solution.warnings

    def _out_of_range(self, solution: Solution, status: NDArray) -> NDArray:
        """``OUT_OF_RANGE`` where the solver calls a design feasible but one of its
        results, of one value or along an axis, is not finite (and may not be +inf)."""
        checks = [(values, key in self.unbounded, False)
                  for key, values in solution.results.items()]
        for axis, along in solution.along.items():
            declared = self.along[axis]
            checks += [(np.asarray(values)[[along.has(column, row)
                                            for row in range(len(along.rows))]],
                        column in declared.unbounded, declared.sparse)
                       for column, values in along.values.items()]
        for values, unbounded, sparse in checks:
            finite = np.isfinite(values)
            if unbounded:
                finite |= values == np.inf
            if sparse:
                finite |= np.isnan(values)
            if finite.shape != np.shape(status):  # rows along an axis: every one counts
                finite = finite.all(axis=0) if finite.ndim > np.ndim(status) else finite
            if not finite.all():
                status = np.where(finite | (status != 0), status, np.int32(OUT_OF_RANGE))
        return status

    def _statuses(self, solution: Solution) -> tuple[NDArray, dict[int, tuple[str, str]]]:
        """Each design's status and what each code means, for this solution.

        A design the solver finds possible but one of whose members (a drive's bearing)
        the member's solver refuses gets a code of that member's reason: the codes
        enumerate the solver's own reasons, the last guard (``OUT_OF_RANGE``), then each
        member of the solution in turn with each of its solver's reasons, so the table
        follows the members the spec has, however many.
        """
        reasons = {**self.solver.status_reasons, OUT_OF_RANGE: OUT_OF_RANGE_REASON}
        status = np.asarray(solution.status).astype(np.int32)
        members = self.solver.members
        if members is None:
            return status, reasons
        own = members.solver.status_reasons
        for name, member_status in solution.members.items():
            table = np.zeros(max(own) + 1, dtype=np.int32)
            for code, (blamed, why) in own.items():
                table[code] = composite = max(reasons) + 1
                reasons[composite] = _member_reason(members, name, blamed, why)
            codes = np.asarray(member_status)
            status = np.where((status == 0) & (codes != 0), table[codes], status)
        return status, reasons

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
        """Result key -> (SI unit, meaning) of the results of one value per design, in
        report order; with a duty cycle also the cycle's own. Results along an axis are
        named by :func:`~bearingcalc.result_keys.flatten`, per solution."""
        duty = self.solver.duty
        if duty is None:
            return self.solver.results
        return {**self.solver.results, **duty.results}

    @functools.cached_property
    def along(self) -> Mapping[str, AxisResults]:
        """Axis -> the results the kind's solver declares along it, a duty cycle's bins
        among them."""
        duty = self.solver.duty
        return {**self.solver.along, **({} if duty is None else {"bin": duty.bins})}

    @property
    def groups(self) -> Mapping[str, tuple[str, ...]]:
        """Table heading -> its results, for kinds with many results (else empty)."""
        return self.solver.groups

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
        """Status code -> (field at fault, why) of the kind's own solver and the last
        guard, ``OUT_OF_RANGE``; a composite's members' codes come with each solution
        (``FlatResults.reasons``)."""
        return {**self.solver.status_reasons, OUT_OF_RANGE: OUT_OF_RANGE_REASON}


def _member_reason(members: Members, name: str, field: str, why: str) -> tuple[str, str]:
    """A member's reason in the composite's words: its field named in the composite
    (``pinion_bearings.2.ball_count``), or the composite's own field that sets it (a
    bearing's speed is the drive's input_speed), saying which member it fails."""
    root, dot, rest = field.partition(".")
    if root in members.set_by_composite:
        return members.set_by_composite[root] + dot + rest, type(why)(f"at {name}, {why}")
    return f"{name}.{field}", why


#: The standards and methods each kind applies, with their sections, for its report.
THRUST_BEARING_STANDARDS = ("Pure rolling of a ball between a turning shaft and a fixed race, "
    "b = r(1 + sinθ)/(cosθ − sinθ), and the spin-to-roll ratio at the "
    "shaft contact: docs/physics.md §1",
    "Hertz point contact, with the complete elliptic integrals by the "
    "arithmetic-geometric mean: docs/physics.md §6")
DISK_ON_CIRCLE_STANDARDS = ("A disk rolling without slipping on a fixed or turning circle: "
    "docs/physics.md §2",)
CONE_ON_PLANE_STANDARDS = ("A cone rolling on a plane about its fixed apex: docs/physics.md §3",)
BEVEL_GEARS_STANDARDS = ("The epicyclic bevel pair, ω_AS = (b/a)(ω_Z − Ω): docs/physics.md §4",
    "Blank geometry (ISO 23509 cone geometry, Gleason proportions), tooth "
    "forces and the ANSI/AGMA 2003-B97 bending and pitting rating in the SI "
    "form of Budynas & Nisbett, Shigley's Mechanical Engineering Design, "
    "10th ed., §15-1 to 15-4 (eqs. 15-1 to 15-23), with ANSI/AGMA "
    "2003-D19's lengthwise curvature factor K_x of spiral teeth: "
    "docs/physics.md §8")
ROLLING_BEARING_STANDARDS = ("ISO 281:2007 basic dynamic load rating, dynamic equivalent load, "
    "basic and modified rating life (a_ISO from e_C and κ), and ISO "
    "76:2006 basic static load rating, static equivalent load and static "
    "safety: docs/physics.md §5",
    "Hertz contact of balls and rollers: docs/physics.md §6; bearing "
    "kinematics: §7; duty cycles (Palmgren–Miner): §11")
BEVEL_DRIVE_STANDARDS = ("The pair's geometry, forces and ANSI/AGMA 2003-B97 rating (Budynas & "
    "Nisbett, 10th ed., §15-1 to 15-4): docs/physics.md §8",
    "Each shaft's statics on two bearings, the induced axial forces and load "
    "cases of an adjusted pair, ISO 281:2007 lives and the system's life: "
    "docs/physics.md §9; duty cycles: §11")


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
                     "contact_pressure_margin": CONTACT},
             standards=THRUST_BEARING_STANDARDS),
        Kind("disk-on-circle", "a disk rolling on a fixed or turning circle, outside or inside",
             "bearingcalc.models.disk_on_circle:DiskOnCircleSpec",
             "bearingcalc.core.disk_on_circle", margins=(),
             governing=("contact_point_accel", "center_speed"),
             standards=DISK_ON_CIRCLE_STANDARDS),
        Kind("cone-on-plane", "a cone rolling on a plane about its fixed apex",
             "bearingcalc.models.cone_on_plane:ConeOnPlaneSpec",
             "bearingcalc.core.cone_on_plane", margins=(),
             governing=("precession_speed",), standards=CONE_ON_PLANE_STANDARDS),
        Kind("bevel-gears", "a bevel pair on fixed axes, or an epicyclic one: gear A on an "
             "arm, gear B on a shaft", "bearingcalc.models.bevel_gears:BevelGearsSpec",
             "bearingcalc.core.bevel_gears",
             margins=("slip_margin", "face_width_margin", "bending_safety_margin",
                      "contact_safety_margin"),
             governing=("bending_safety_margin", "contact_safety_margin", "apex_mismatch",
                        "slip_margin"),
             limits={"apex_mismatch": "max_apex_mismatch"}, judged=PAIR,
             standards=BEVEL_GEARS_STANDARDS),
        *(Kind(name, summary, "bearingcalc.models.rolling_bearing:RollingBearingSpec",
               "bearingcalc.core.rolling_bearing",
               margins=("life_margin", "static_safety_margin", "contact_pressure_margin",
                        "spin_to_roll_margin", "stiffness_radial_margin",
                        "stiffness_axial_margin", "operating_clearance_margin"),
               governing=("life_margin", ("modified_reference_rating_life",
                                          "modified_rating_life"), "static_safety_factor"),
               judged={"life_margin": LIFE, "static_safety_margin": STATIC,
                       "contact_pressure_margin": CONTACT,
                       "spin_to_roll_margin": SPIN_TO_ROLL,
                       **{f"stiffness_{direction}_margin": Judged(
                           f"{direction} stiffness", f"stiffness_{direction}", True, "ratio")
                          for direction in ("radial", "axial")},
                       "operating_clearance_margin": Judged("operating clearance",
                                                            "operating_clearance", True)},
               plots=(Plot("duty-damage"), Plot("life-against-load")),
               # as mounted a tilting moment alone loads the elements at P = 0
               unbounded=("load_ratio", "basic_rating_life", "basic_rating_life_revolutions",
                          "modified_rating_life", "modified_rating_life_revolutions",
                          "static_safety_factor", "static_safety_margin"),
               unbounded_reason="no force loads the bearing (ISO 281 and ISO 76 rate "
               "forces; a tilt alone loads its elements, and ISO/TS 16281's results rate it)",
               standards=ROLLING_BEARING_STANDARDS)
          for name, summary in (
              ("rolling-bearing", "a ball or roller bearing, single or paired: ISO 281 "
               "rating life, ISO 76 static safety"),
              ("ball-bearing", "the same as rolling-bearing (its earlier name)"))),
        Kind("bevel-drive", "a bevel pair on two shafts, each on two rolling bearings, "
             "located or adjusted: every bearing's life",
             "bearingcalc.models.bevel_drive:BevelDriveSpec",
             "bearingcalc.core.bevel_drive",
             margins=("slip_margin", "face_width_margin", "bending_safety_margin",
                      "contact_safety_margin", "life_margin", "static_safety_margin",
                      *(f"{key}_margin" for key in MESH_DISPLACEMENTS)),
             governing=("life_margin", "system_modified_rating_life", "static_safety_margin"),
             judged={**PAIR, "life_margin": Judged("system modified rating life",
                                                   "system_modified_rating_life", True,
                                                   "ratio", "required"),
                     "static_safety_margin": Judged("smallest static safety s0",
                                                    smallest_bearing_safety, True,
                                                    limit_of="static safety s0"),
                     **{f"{key}_margin": Judged(name, key, False, "fraction")
                        for key, name in MESH_DISPLACEMENTS.items()}},
             plots=(Plot("duty-damage"), Plot("bearing-lives"),
                    Plot("shaft-bending", "bearingcalc.core.bevel_drive:shaft_bending_lines")),
             standards=BEVEL_DRIVE_STANDARDS),
    )
}


def unknown_kind(name: object) -> str:
    """Why ``name`` is not a kind, with the nearest kind's name and every kind's."""
    from bearingcalc.wording import did_you_mean

    return (f"unknown kind {name!r}{did_you_mean(str(name), KINDS)}; known kinds: "
            f"{', '.join(KINDS)}")
