"""The limits a plot draws: a result's own, 0 of a margin, or the limit of the result a
margin judges (a life's required life), in the result's own unit."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from bearingcalc.kinds import Kind
    from bearingcalc.result_keys import ResultTable
    from bearingcalc.studies import StudyReport
    from bearingcalc.sweeps import Sweep


def sweep_limits(sweep: Sweep, key: str) -> list[tuple[float, str]]:
    """The limits of a result in a sweep, each with its words (see :func:`limit_levels`),
    read at the first point where the result and the margin are known."""
    def at_a_point(margin: str) -> Mapping[str, float] | None:
        if margin not in sweep.results:
            return None
        good = np.flatnonzero(np.isfinite(sweep.results[key])
                              & np.isfinite(sweep.results[margin]))
        if not good.size:
            return None
        return {name: float(values[good[0]]) for name, values in sweep.results.items()}

    return limit_levels(sweep.kind, sweep.limits, sweep.kind.margins, key, at_a_point,
                        sweep.results.tables)


def study_limits(report: StudyReport, key: str) -> list[tuple[float, str]]:
    """The limits of a result in a tolerance study (see :func:`limit_levels`), read at the
    nominal design."""
    from bearingcalc.kinds import KINDS

    results = report.record["results"]

    def nominal(margin: str) -> Mapping[str, float] | None:
        if margin not in report.margins or results[key]["nominal"] is None:
            return None
        return {name: entry["nominal"] for name, entry in results.items()
                if entry["nominal"] is not None}

    return limit_levels(KINDS[report.record["kind"]], report.limits, report.margins, key, nominal,
                        report.tables)


#: A value no result has exactly, to ask a margin whether it judges a result.
_PROBE = 1.2345678


def limit_levels(kind: Kind, limits: Mapping[str, float], margins: Iterable[str], key: str,
                 known: Callable[[str], Mapping[str, float] | None],
                 tables: tuple[ResultTable, ...] = ()) -> list[tuple[float, str]]:
    """The limits of a result, each with its words: its own symmetric limit, 0 of a
    margin, or the limit of a result a margin judges (a life's required life; the min
    bending safety of either gear), from the results ``known`` gives at one design
    (``tables``: the results along axes, which a drive's smallest s0 reads)."""
    from bearingcalc.result_keys import FlatResults

    if key in limits:
        return [(-limits[key], "limit"), (limits[key], "limit")]
    if key in margins:
        return [(0.0, "limit")]
    for margin, judged in kind.judged.items():
        if judged.value(FlatResults({key: _PROBE}, tables=tables)) != _PROBE:
            continue  # it judges other results
        point = known(margin)
        value = None if point is None else judged.value(FlatResults(point, tables=tables))
        if point is None or value is None:
            continue
        limit = judged.limit(value, point[margin])
        if np.isfinite(limit):
            return [(limit, judged.limit_named())]
    return []


def judged_quantity(sweep: Sweep, margin: str) -> str | None:
    judged = sweep.kind.judged.get(margin)
    return judged.key(sweep.results) if judged is not None else None
