"""Choosing a bearing from a catalogue: every row that fits the shaft and the envelope,
solved at once, the ones that meet every limit ranked smallest first.

A ``rolling-bearing`` spec gives the loads (or a duty cycle), the speed, lubrication and
limits; its ``bore_diameter`` is the shaft and its ``outside_diameter`` and ``width``,
where given, the envelope. A ``bevel-drive`` selects one bearing position at a time with
the others as the spec gives them: the one position without ratings or a designation,
or, where every position is given, each in turn. The rows of one type are solved in one
vectorised call per form (:func:`bearingcalc.variation.evaluate_with`), as a sweep solves its
points; the rows a report lists are then read one by one as ``solve`` would read them,
so that a rule of the spec (not checked on arrays) refuses any it must.
"""

from __future__ import annotations

import copy
import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from bearingcalc.catalogue.catalogue import Catalogue, CatalogueRow
from bearingcalc.catalogue.fill import row_fields, spec_catalogue
from bearingcalc.envelope import Envelope, bearing_at, fitting_rows
from bearingcalc.errors import SpecError
from bearingcalc.evaluation import evaluate_document, load_selected, parse_document
from bearingcalc.kinds import KINDS, Kind, unknown_kind
from bearingcalc.models.yaml_loader import Document
from bearingcalc.variation import evaluate_with
from bearingcalc.verdicts import PAIR, Verdict, judge, verdict_line

#: A bearing's fields a catalogue row stands for, dropped from the spec before a row
#: fills them (the spec's shaft and envelope are read first).
#: Of those, the ones that bound the choice (the shaft, the envelope, the type).
ENVELOPE = ("designation", "maker", "type", "bore_diameter", "outside_diameter", "width")
ROW_OWNED = ("designation", "maker", "type", "dynamic_load_rating", "static_load_rating",
             "fatigue_load_limit", "static_factor", "contact_angle", "load_factors",
             "bore_diameter", "outside_diameter", "width", "ball_count", "ball_diameter",
             "roller_count", "roller_diameter", "roller_length", "pitch_diameter")
#: Rows of one type read as a whole spec before the type is taken as refused by the
#: spec's rules (rows of a type differ in their numbers only; the listed rows are read
#: again one by one).
TEMPLATE_TRIES = 3


@dataclass
class Candidate:
    """One catalogue row in one position: how it fares."""

    row: CatalogueRow
    qualifies: bool
    verdicts: list[Verdict] = field(default_factory=list)
    #: why the design is impossible or the spec refuses it, where it is or does
    problem: str | None = None
    #: the spec's refusal of this row, as read whole
    error: SpecError | None = None

    @property
    def size(self) -> tuple[float, float, float, float, str, str]:
        """What ranks the qualifying rows: outside diameter, width, mass (unknown last),
        then the larger governing margin."""
        values = self.row.values
        margin = self.verdicts[0].margin if self.verdicts else 0.0
        return (values["outside_diameter"], values["width"], values.get("mass", math.inf),
                -margin, self.row.designation, self.row.maker)

    @property
    def closeness(self) -> float:
        """How near a failing row comes to passing: its worst margin as a fraction of its
        limit (an impossible design last)."""
        return -math.inf if self.problem or not self.verdicts else self.verdicts[0].margin


@dataclass
class PositionChoice:
    """The selection for one bearing position."""

    position: str                  # '' for a rolling-bearing spec; 'pinion_bearings.1'
    considered: int                # rows that fit the shaft and envelope
    qualifying: list[Candidate]    # smallest first, at most ``top``
    failing: list[Candidate]       # the nearest to passing first, at most ``top``
    qualifying_count: int
    #: what the reader should know: spec values select leaves out, a gear pair that
    #: misses its own limits whatever the bearing
    notes: list[str] = field(default_factory=list)

    @property
    def label(self) -> str:
        return self.position or "the bearing"


@dataclass
class Selection:
    source: str
    name: str
    kind: str
    catalogue: str
    choices: list[PositionChoice]

    @property
    def found(self) -> bool:
        """A bearing qualifies in every position."""
        return all(choice.qualifying for choice in self.choices)


def select_spec(path: str | Path, envelope: Envelope, top: int = 5) -> Selection:
    """:func:`select` on the one spec of the file at ``path``, with its catalogue (the
    spec's ``catalogue``, else ``--catalogue`` or ``BEARINGCALC_CATALOGUE``)."""
    documents = load_selected(path)
    if len(documents) > 1:
        raise SpecError(f"the file holds {len(documents)} specs; pick one as {path}#1 .. "
                        f"#{len(documents)}", source=str(path))
    document = documents[0]
    data = document.data
    if not isinstance(data, dict):
        raise document.error("a spec is a mapping of keys (kind: rolling-bearing, ...)")
    kind = KINDS.get(data.get("kind")) if isinstance(data.get("kind"), str) else None
    if kind is None:
        raise document.error(unknown_kind(data.get("kind")), field="kind")

    def error(message: str, field: str | None) -> SpecError:
        if field is None:  # --catalogue or the environment's: no line of the spec
            return SpecError(message, source=document.source)
        return document.error(message, field=field)

    catalogue = spec_catalogue(data, document.path, error, None, needed_for="select")
    return select(kind, document, catalogue, envelope, top)


def select(kind: Kind, document: Document, catalogue: Catalogue, envelope: Envelope,
           top: int = 5) -> Selection:
    """The bearings of ``catalogue`` that meet every limit of the spec in ``document``,
    in each position it selects; raises SpecError where no row fits the envelope."""
    places = kind.model.CATALOGUE_PLACES
    if not places:
        raise document.error(f"select chooses rolling bearings: a {kind.name} spec has none "
                             "(use a rolling-bearing or bevel-drive spec)", field="kind")
    positions = _positions(document, places)
    choices = [_choose(kind, document, catalogue, envelope, position, top)
               for position in _open_positions(document, positions)]
    name = document.data.get("name") if isinstance(document.data.get("name"), str) else None
    return Selection(document.source, name or Path(document.path).stem, kind.name,
                     catalogue.path, choices)


def _positions(document: Document, places: Sequence[str]) -> list[str]:
    found = []
    for place in places:
        if not place:
            found.append("")
            continue
        items = document.data.get(place)
        if isinstance(items, list):
            found += [f"{place}.{i}" for i in range(1, len(items) + 1)]
    return found


def _open_positions(document: Document, positions: list[str]) -> list[str]:
    """The positions to select: the one without ratings or a designation, or every one
    where all are given."""
    if len(positions) == 1:
        return positions
    open_ = [p for p in positions if not {"designation", "dynamic_load_rating",
                                          "ball_count", "roller_count"}
             & set(bearing_at(document.data, p))]
    if len(open_) > 1:
        raise document.error(f"select chooses one position at a time, the others as given: "
                             f"{', '.join(open_)} give neither ratings nor a designation; "
                             "give all but one", field=open_[1])
    return open_ or positions


def _choose(kind: Kind, document: Document, catalogue: Catalogue, envelope: Envelope,
            position: str, top: int) -> PositionChoice:
    rows = fitting_rows(document, catalogue, envelope, position)
    base = copy.deepcopy(document.data)
    bearing = bearing_at(base, position)
    arrangement = bearing.get("arrangement", "single")
    arrangement = arrangement if isinstance(arrangement, str) else "single"
    rows_count = bearing.get("rows") if isinstance(bearing.get("rows"), int) else None
    notes = []
    dropped = [name for name in ROW_OWNED if name in bearing and name not in ENVELOPE]
    if dropped:
        notes.append(f"{position or 'the spec'}'s {', '.join(dropped)} "
                     "left out: each bearing's are its catalogue row's")
    for name in ROW_OWNED:
        bearing.pop(name, None)
    if "rows" in bearing and rows_count is None:
        bearing.pop("rows")
    base["catalogue"] = str(Path(catalogue.path).resolve())
    # The spec's own fields, read before any row is judged: a bad spec is refused, not
    # reported as every bearing failing.
    parse_document(_with_row(document, base, position, rows[0]), rules=False)
    groups: dict[tuple[Any, ...], list[CatalogueRow]] = {}
    fields_of: dict[int, dict[str, tuple[str, float]]] = {}
    for row in rows:
        fields = row_fields(row, arrangement, rows_count)
        fields_of[id(row)] = fields
        # The form (NU, NJ, ...) groups apart: a rule of the spec may judge it.
        form = row.parsed.basic.rstrip("0123456789") if row.parsed else row.designation
        groups.setdefault((row.type, form, tuple(sorted(fields))), []).append(row)
    candidates: list[Candidate] = []
    judged = _judged_margins(kind, position)
    for (_, _, names), members in groups.items():
        candidates += _solve_group(kind, document, base, position, members, names,
                                   fields_of, judged, notes)
    errors = {candidate.problem for candidate in candidates}
    if candidates[0].error is not None and len(errors) == 1:
        raise candidates[0].error  # the spec itself is at fault, whichever the bearing
    return _ranked(document, base, position, candidates, top, len(rows), notes)


def _judged_margins(kind: Kind, position: str) -> tuple[str, ...]:
    """The margins a position's bearing is chosen by: in a drive, not the gear pair's,
    which no bearing changes."""
    return tuple(key for key in kind.margins if not (position and key in PAIR))


def _with_row(document: Document, base: dict[str, Any], position: str, row: CatalogueRow
              ) -> Document:
    data = copy.deepcopy(base)
    bearing = bearing_at(data, position)
    bearing["designation"] = row.designation
    bearing["maker"] = row.maker
    return dataclasses.replace(document, data=data)


def _solve_group(kind: Kind, document: Document, base: dict[str, Any], position: str,
                 members: list[CatalogueRow], names: tuple[str, ...],
                 fields_of: dict[int, dict[str, tuple[str, float]]],
                 judged: tuple[str, ...], notes: list[str]) -> list[Candidate]:
    """The rows of one type, form and set of fields, solved in one call on a spec read
    with the first of them that the spec's rules take."""
    template = None
    refused: list[Candidate] = []
    for row in members[:TEMPLATE_TRIES]:
        try:
            _, template = parse_document(_with_row(document, base, position, row))
            break
        except SpecError as error:
            refused.append(Candidate(row, False, problem=_reason(error), error=error))
    if template is None:  # the spec's rules refuse the form itself, not a row's numbers
        first = refused[0]
        return refused + [Candidate(row, False, problem=first.problem, error=first.error)
                          for row in members[len(refused):]]
    rest = members[len(refused):]
    prefix = f"{position}." if position else ""
    values = {f"{prefix}{name}": np.array([fields_of[id(row)][name][1] for row in rest])
              for name in names}
    solved, status = evaluate_with(kind, template, values)
    count = len(rest)
    results = {key: np.broadcast_to(value, (count,)) for key, value in solved.items()}
    status = np.broadcast_to(status, (count,))
    margin_keys = [key for key in judged if key in results]
    ok = status == 0
    for key in margin_keys:
        ok = ok & (results[key] >= 0)
    passed = ok.tolist()
    codes = status.tolist()
    keys = list(results)
    candidates = refused
    _note_the_pair(kind, results, status, judged, notes)
    for row, code, ok, values in zip(rest, codes, passed, zip(
            *(results[key].tolist() for key in keys), strict=True), strict=True):
        if code:
            field_name, why = solved.reasons[int(code)]
            candidates.append(Candidate(row, False, problem=f"{field_name}: {why}"
                                        if field_name else why))
            continue
        scalar = dict(zip(keys, values, strict=True))
        margins = {key: scalar[key] for key in margin_keys}
        candidates.append(Candidate(row, ok, judge(kind.judged, kind.results,
                                                   solved.with_values(scalar), margins)))
    return candidates


def _note_the_pair(kind: Kind, results: dict[str, Any], status: Any,
                   judged: tuple[str, ...], notes: list[str]) -> None:
    """A drive's gear pair that misses its own limits misses them whatever the bearing:
    said once."""
    feasible = np.flatnonzero(status == 0)
    if feasible.size == 0:
        return
    i = int(feasible[0])
    scalar = {key: float(value[i]) for key, value in results.items()}
    margins = {key: scalar[key] for key in kind.margins
               if key in scalar and key not in judged}
    missed = [verdict_line(v) for v in judge(kind.judged, kind.results, scalar, margins)
              if not v.passed]
    note = f"the gear pair misses its own limits, whatever the bearing: {'; '.join(missed)}"
    if missed and note not in notes:  # the same pair under every type's rows
        notes.append(note)


def _reason(error: SpecError) -> str:
    return f"{error.field}: {error.message}" if error.field else error.message


def _ranked(document: Document, base: dict[str, Any], position: str,
            candidates: list[Candidate], top: int, considered: int,
            notes: list[str]) -> PositionChoice:
    """The ``top`` smallest qualifying rows and the ``top`` failing rows nearest to
    passing, each listed row read again whole so that the spec's rules judge it."""
    qualifying = sorted((c for c in candidates if c.qualifies), key=lambda c: c.size)
    failing = sorted((c for c in candidates if not c.qualifies), key=lambda c: -c.closeness)
    listed: list[Candidate] = []
    warned: dict[str, list[CatalogueRow]] = {}
    refused = 0
    for candidate in qualifying:
        if len(listed) == top:
            break
        try:
            solved = evaluate_document(_with_row(document, base, position, candidate.row))
        except SpecError as error:
            failing.insert(0, Candidate(candidate.row, False, problem=_reason(error),
                                        error=error))
            refused += 1
            continue
        for warning in solved.warnings:
            warned.setdefault(warning, []).append(candidate.row)
        listed.append(candidate)
    return PositionChoice(position, considered, listed, failing[:top],
                          len(qualifying) - refused, notes + _row_warnings(warned, listed))


def _row_warnings(warned: dict[str, list[CatalogueRow]], listed: list[Candidate]
                  ) -> list[str]:
    """The warnings ``solve`` gives each listed row: once where every listed row has it,
    else after the rows' designations."""
    every = len(listed)
    return [warning if len(rows) == every else
            f"{', '.join(row.label for row in rows)}: {warning}"
            for warning, rows in warned.items()]
