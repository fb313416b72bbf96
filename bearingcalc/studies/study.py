"""A tolerance study of one spec: its toleranced inputs, the tolerance box they span,
and the evaluation of whole arrays of designs that every method calls."""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.errors import BearingcalcError
from bearingcalc.kinds import Kind
from bearingcalc.models.base import SpecModel, field_parser
from bearingcalc.models.field_path import resolve_field
from bearingcalc.models.quantities import Tolerance
from bearingcalc.models.yaml_loader import Document
from bearingcalc.result_keys import FlatResults
from bearingcalc.studies.sobol import sobol_stream
from bearingcalc.units import to_display
from bearingcalc.variation import evaluate_with, field_value, invalid_at, toleranced_fields

#: Designs in the interior of the box, besides its corners, that seed the worst-case search.
INTERIOR_POINTS = 1 << 10
MAX_CORNER_INPUTS = 14


class StudyError(BearingcalcError):
    """A tolerance study that cannot be run as asked (no tolerances, bad options):
    ``option`` names the option at fault, if one is (``--method``), and ``message`` says
    what is wrong with its value."""

    def __init__(self, message: str, option: str | None = None) -> None:
        super().__init__(f"{option}: {message}" if option else message)
        self.message = message
        self.option = option


def check_band_ends(document: Document, spec: SpecModel) -> None:
    """Validate the spec at both ends of every tolerance band, one input at a time, as
    ``solve`` would (see :func:`bearingcalc.variation.invalid_at`): a band that reaches
    past what the spec model takes (a spiral angle below 0, a length below 0) would be
    studied silently. Raises SpecError at the input's line, naming the end and the
    rule."""
    for name, tolerance in toleranced_fields(spec).items():
        info = resolve_field(spec, name).info
        parsed = None if info is None else field_parser(info)
        unit = "" if parsed is None or parsed[2] == "1" else f" {parsed[2]}"
        for end, value in (("low", tolerance.low), ("high", tolerance.high)):
            error = invalid_at(document, {name: f"{value!r}{unit}" if unit else value})
            if error is not None:
                what = (error.message if error.field in (None, name)
                        else f"{error.field}: {error.message}")
                shown, shown_unit = to_display(value, unit.strip() or "1")
                raise document.error(f"the {end} end of its tolerance band, {shown:.6g}"
                                     f"{' ' + shown_unit if shown_unit else ''}, is outside "
                                     f"what the spec takes: {what}", field=name)


@dataclass
class StudyInput:
    """One toleranced spec field."""

    name: str
    tolerance: Tolerance

    @property
    def low(self) -> float:
        return self.tolerance.low

    @property
    def high(self) -> float:
        return self.tolerance.high


@dataclass
class Study:
    """A tolerance study of one spec."""

    kind: Kind
    spec: SpecModel
    inputs: list[StudyInput] = field(init=False)
    nominal: dict[str, float] = field(init=False)
    _layout: FlatResults = field(init=False, repr=False)
    #: impossible designs met by the worst-case search of the box (see worst_case)
    box_impossible: dict[str, Any] | None = field(init=False, default=None)

    def __post_init__(self) -> None:
        self.inputs = [StudyInput(name, tol) for name, tol in toleranced_fields(self.spec).items()]
        if not self.inputs:
            raise StudyError("the spec has no tolerances: give one on any input with a unit, "
                             "like 'contact_angle: 20 deg ± 0.25 deg'")
        results, _ = evaluate_with(self.kind, self.spec, {})
        self.nominal = {key: float(value) for key, value in results.items()}
        self._layout = results

    @property
    def names(self) -> Mapping[str, tuple[str, str]]:
        """Each result's (SI unit, meaning)."""
        return self._layout.names

    def layout(self, values: Mapping[str, float]) -> FlatResults:
        """``values`` of one design with the layout of the spec's results (the tables
        along axes, which a drive's verdicts read)."""
        return self._layout.with_values(values)

    @property
    def keys(self) -> list[str]:
        """Every numeric result of the kind that this spec has."""
        return list(self.nominal)

    @property
    def limit_values(self) -> dict[str, float]:
        """Result key -> its symmetric limit value from the spec."""
        return self.kind.limit_values(self.spec.solver_inputs())  # type: ignore[attr-defined]

    @property
    def margins(self) -> list[str]:
        """The kind's margins that this spec has (a margin needs its limit)."""
        return [key for key in self.kind.margins if key in self.nominal]

    def evaluate(self, columns: NDArray, keys: Sequence[str] | None = None
                 ) -> tuple[dict[str, NDArray], NDArray]:
        """Results ``keys`` (default all; NaN where infeasible) and status codes at the
        designs in the rows of ``columns`` (n, d)."""
        keys = self.keys if keys is None else keys
        values = {item.name: columns[:, i] for i, item in enumerate(self.inputs)}
        wanted = {*keys, *self.margins}
        results, status = evaluate_with(self.kind, self.spec, values, wanted)
        bad = status != 0
        if not bad.any():  # the usual chunk: nothing to blank, no copies
            shape = np.broadcast_shapes(status.shape, *(np.shape(results[k]) for k in wanted))
            return {key: np.broadcast_to(results[key], shape) for key in wanted}, status
        return {key: np.where(bad, np.nan, results[key]) for key in wanted}, status

    def box(self) -> tuple[NDArray, NDArray]:
        """(low, width) of the tolerance box, input by input. [SI]"""
        return (np.array([item.low for item in self.inputs]),
                np.array([item.high - item.low for item in self.inputs]))

    def search_points(self) -> NDArray:
        """Where the worst case starts, in unit coordinates of the box: all 2^d corners
        (d <= MAX_CORNER_INPUTS), INTERIOR_POINTS scrambled Sobol' points, the centre."""
        d = len(self.inputs)
        if d <= MAX_CORNER_INPUTS:
            corners = np.array(list(itertools.product((0.0, 1.0), repeat=d)))
        else:
            corners = np.empty((0, d))
        interior = sobol_stream(d, 0).next(INTERIOR_POINTS)
        return np.vstack([corners, interior, np.full((1, d), 0.5)])

    def scan_box(self, unit: NDArray | None = None) -> tuple[dict[str, NDArray], NDArray]:
        """Results and status at the box's ``search_points`` (or ``unit``); records in
        ``box_impossible`` how much of the box is impossible designs."""
        low, width = self.box()
        unit = self.search_points() if unit is None else unit
        results, status = self.evaluate(low + unit * width)
        self.box_impossible = self._impossible_part(unit, status, low, width)
        return results, status

    def _impossible_part(self, unit: NDArray, status: NDArray, low: NDArray,
                         width: NDArray) -> dict[str, Any] | None:
        """How much of the worst-case search of the box hit impossible designs, and one
        of them (the first corner or point found) with the reason; None when none did."""
        bad = np.flatnonzero(status != 0)
        if bad.size == 0:
            return None
        first = int(bad[0])
        field, why = self._layout.reasons[int(status[first])]
        return {"fraction": bad.size / status.size,
                "inputs": {item.name: float(low[i] + unit[first, i] * width[i])
                           for i, item in enumerate(self.inputs)},
                "reason": f"{field}: {why}" if field else why}

    def input_summary(self) -> dict[str, dict[str, Any]]:
        """The JSON ``inputs`` object: nominal, band, distribution and std of each input."""
        return {item.name: {"nominal": float(field_value(self.spec, item.name)),
                            "low": item.low, "high": item.high,
                            "distribution": item.tolerance.distribution,
                            "std": item.tolerance.std,
                            "written_unit": item.tolerance.written_unit}
                for item in self.inputs}
