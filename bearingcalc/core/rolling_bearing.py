"""Rolling bearings of every type: ball bearings by :mod:`bearingcalc.core.ball_bearing`,
roller bearings by :mod:`bearingcalc.core.roller_bearing`, chosen by the bearing's type.

The kind's results, groups and status reasons are the union of the two families'; a
design has the results of its own family. See ``docs/physics.md`` §5–§7.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from typing import TYPE_CHECKING

from bearingcalc.core import ball_bearing, roller_bearing
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.duty_cycle import (
    BEARING_BINS,
    BEARING_CYCLE_RESULTS,
    rolling_bearing_cycle,
)
from bearingcalc.core.solver import DutyCycle, Solution, Solver

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import RollingBearingInputs


def _union(first: Mapping, second: Mapping) -> dict:
    """Keys of ``first`` in its order, then those only ``second`` has, in its order."""
    return {**first, **{key: value for key, value in second.items() if key not in first}}


def _merged_results() -> dict[str, tuple[str, str]]:
    """The ball bearings' results with the roller bearings' own inserted after the key
    they follow, so each group reads in the order of its family."""
    merged: dict[str, tuple[str, str]] = {}
    roller_keys = list(roller_bearing.RESULTS)
    for key, value in ball_bearing.RESULTS.items():
        merged[key] = value
    for index, key in enumerate(roller_keys):
        if key in merged:
            continue
        before = next((k for k in reversed(roller_keys[:index]) if k in merged), None)
        items = list(merged.items())
        at = 0 if before is None else [k for k, _ in items].index(before) + 1
        items.insert(at, (key, roller_bearing.RESULTS[key]))
        merged = dict(items)
    return merged


RESULTS = _merged_results()
GROUPS = {heading: tuple(key for key in RESULTS
                         if key in ball_bearing.GROUPS.get(heading, ())
                         or key in roller_bearing.GROUPS.get(heading, ()))
          for heading in _union(ball_bearing.GROUPS, roller_bearing.GROUPS)}
STATUS_REASONS = _union(ball_bearing.STATUS_REASONS, roller_bearing.STATUS_REASONS)
WARNINGS = _union(ball_bearing.WARNINGS, roller_bearing.WARNINGS)


def evaluate(inputs: RollingBearingInputs,
             wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: the family's solver for the bearing's type."""
    family = (roller_bearing if traits(str(inputs["bearing_type"])).family == "roller"
              else ball_bearing)
    return family.evaluate(inputs, wanted)


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, WARNINGS, GROUPS,
                display=ball_bearing.DISPLAY, along=ball_bearing.SOLVER.along,
                duty=DutyCycle(rolling_bearing_cycle, BEARING_CYCLE_RESULTS, BEARING_BINS),
                inputs="RollingBearingInputs")
