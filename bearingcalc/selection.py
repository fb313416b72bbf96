"""Choosing a bearing from a catalogue: every row that fits the shaft and the envelope,
solved at once, the ones that meet every limit ranked smallest first.

A ``rolling-bearing`` spec gives the loads (or a duty cycle), the speed, lubrication and
limits; its ``bore_diameter`` is the shaft and its ``outside_diameter`` and ``width``,
where given, the envelope. A ``bevel-drive`` selects one bearing position at a time with
the others as the spec gives them: the one position without ratings or a designation,
or, where every position is given, each in turn. The rows of one type are solved in one
vectorised call (:func:`bearingcalc.variation.evaluate_with`), as a sweep solves its
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

from bearingcalc.catalogue.catalogue import Catalogue, CatalogueRow, load_catalogue
from bearingcalc.catalogue.fill import CATALOGUE_VARIABLE, default_catalogue, row_fields
from bearingcalc.catalogue.reader import ROW_TYPES
from bearingcalc.errors import SpecError
from bearingcalc.evaluation import load_selected, parse_document
from bearingcalc.kinds import KINDS, Kind, unknown_kind
from bearingcalc.models.field_path import FieldPath
from bearingcalc.models.yaml_loader import Document
from bearingcalc.units import LENGTH, UnitError, parse_quantity, to_display
from bearingcalc.variation import evaluate_with
from bearingcalc.verdicts import Verdict, judge
from bearingcalc.wording import did_you_mean

#: Bearing types a drive's positions may not take (the gear forces load them radially).
THRUST_TYPES = ("thrust-ball", "thrust-cylindrical-roller", "thrust-spherical-roller",
                "thrust-tapered-roller")
#: A bearing's fields a catalogue row stands for, dropped from the spec before a row
#: fills them (the spec's shaft and envelope are read first).
ROW_OWNED = ("designation", "maker", "type", "dynamic_load_rating", "static_load_rating",
             "fatigue_load_limit", "static_factor", "contact_angle", "load_factors",
             "bore_diameter", "outside_diameter", "width", "ball_count", "ball_diameter",
             "roller_count", "roller_diameter", "roller_length", "pitch_diameter")
SHAFT_TOLERANCE = 1e-7  # [m]
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


@dataclass(frozen=True)
class Envelope:
    """What the caller allows: types, series, and the largest outside diameter and
    width [m] (None: the spec's, or no bound)."""

    types: tuple[str, ...] = ()
    series: tuple[str, ...] = ()
    max_outside_diameter: float | None = None
    max_width: float | None = None


def envelope_from_options(types: Sequence[str], series: Sequence[str],
                          max_outside_diameter: str | None, max_width: str | None
                          ) -> Envelope:
    """The envelope of ``select``'s options; ValueError naming the option at fault."""
    for name in types:
        if name not in ROW_TYPES:
            raise ValueError(f"--type {name!r}: not a bearing type{did_you_mean(name, ROW_TYPES)};"
                             f" one of {', '.join(ROW_TYPES)}")
    bounds = []
    for option, text in (("--max-outside-diameter", max_outside_diameter),
                         ("--max-width", max_width)):
        try:
            value = None if text is None else parse_quantity(text, LENGTH)
        except UnitError as error:
            raise ValueError(f"{option}: {error}") from None
        if value is not None and not value > 0:
            raise ValueError(f"{option}: must be greater than zero, like '62 mm'")
        bounds.append(value)
    return Envelope(tuple(types), tuple(s.strip() for s in series), bounds[0], bounds[1])


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
    named = data.get("catalogue")
    if isinstance(named, str) and named.strip():
        catalogue_path: str | Path = Path(document.path).parent / named.strip()
    elif named is not None:
        raise document.error("write the catalogue's path, like catalogue: bearings.csv "
                             "(relative to the spec)", field="catalogue")
    else:
        default = default_catalogue()
        if default is None:
            raise document.error("select needs a catalogue: give catalogue: bearings.csv "
                                 "(relative to the spec), --catalogue FILE, or the "
                                 f"environment variable {CATALOGUE_VARIABLE}")
        catalogue_path = default
    try:
        catalogue = load_catalogue(catalogue_path)
    except SpecError as problem:  # the catalogue's own file and line, after the spec's
        raise document.error(str(problem), field="catalogue" if named is not None
                             else None) from None
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


def _bearing(data: dict[str, Any], position: str) -> dict[str, Any]:
    found = FieldPath.parse(position).get(data) if position else data
    return found if isinstance(found, dict) else {}


def _open_positions(document: Document, positions: list[str]) -> list[str]:
    """The positions to select: the one without ratings or a designation, or every one
    where all are given."""
    if len(positions) == 1:
        return positions
    open_ = [p for p in positions if not {"designation", "dynamic_load_rating",
                                          "ball_count", "roller_count"}
             & set(_bearing(document.data, p))]
    if len(open_) > 1:
        raise document.error(f"select chooses one position at a time, the others as given: "
                             f"{', '.join(open_)} give neither ratings nor a designation; "
                             "give all but one", field=open_[1])
    return open_ or positions


def _length(document: Document, bearing: dict[str, Any], position: str, name: str
            ) -> float | None:
    text = bearing.get(name)
    if text is None:
        return None
    where = f"{position}.{name}" if position else name
    try:
        value = parse_quantity(text, LENGTH)
    except UnitError as error:
        raise document.error(str(error), field=where) from None
    if not value > 0:
        raise document.error("must be greater than zero", field=where)
    return value


def _shown(value: float) -> str:
    number, unit = to_display(value, "m")
    return f"{number:g} {unit}"


def _fitting(document: Document, catalogue: Catalogue, envelope: Envelope, position: str,
             kind: Kind) -> list[CatalogueRow]:
    """The rows that fit the position's shaft and envelope; a SpecError naming the
    limit that excluded the last of them."""
    bearing = _bearing(document.data, position)
    prefix = f"{position}." if position else ""
    bore = _length(document, bearing, position, "bore_diameter")
    if bore is None and bearing.get("designation") is not None:  # the given bearing's shaft
        maker = bearing.get("maker")
        try:
            bore = catalogue.find(bearing["designation"], maker if isinstance(maker, str)
                                  else None).values["bore_diameter"]
        except LookupError as problem:
            raise document.error(str(problem), field=f"{prefix}designation") from None
    if bore is None:
        raise document.error("select needs the shaft: give the bearing's bore_diameter, "
                             "like 25 mm", field=f"{prefix}bore_diameter",
                             key_path=FieldPath.parse(position).parts if position else ())
    given_outside = _length(document, bearing, position, "outside_diameter")
    given_width = _length(document, bearing, position, "width")
    outside = _smaller(given_outside, envelope.max_outside_diameter)
    width = _smaller(given_width, envelope.max_width)
    given_type = bearing.get("type")
    types = envelope.types or ((given_type,) if isinstance(given_type, str) else ())
    # (words, the spec's field or the option that set the bound, which rows it keeps)
    steps: list[tuple[str, str, Any]] = [
        (f"of the types {', '.join(types)}" if types else "",
         "--type" if envelope.types else f"{prefix}type",
         lambda row: not types or row.type in types),
        ("that a drive's shaft can take (no thrust bearings)" if position else "", "",
         lambda row: not position or row.type not in THRUST_TYPES),
        (f"of the series {', '.join(envelope.series)}" if envelope.series else "",
         "--series", lambda row: not envelope.series or _series(row) in envelope.series),
        (f"with the bore {_shown(bore)}",
         f"{prefix}bore_diameter" if "bore_diameter" in bearing else f"{prefix}designation",
         lambda row: abs(row.values["bore_diameter"] - bore) <= SHAFT_TOLERANCE),
        (f"with an outside diameter of at most {_shown(outside)}" if outside else "",
         f"{prefix}outside_diameter" if outside == given_outside else
         "--max-outside-diameter",
         lambda row: outside is None or row.values["outside_diameter"] <= outside
         + SHAFT_TOLERANCE),
        (f"with a width of at most {_shown(width)}" if width else "",
         f"{prefix}width" if width == given_width else "--max-width",
         lambda row: width is None or row.values["width"] <= width + SHAFT_TOLERANCE),
    ]
    rows = catalogue.rows
    said = []
    for words, source, keep in steps:
        rows = [row for row in rows if keep(row)]
        if words:
            said.append(words)
        if not rows:
            message = (f"no bearing of the catalogue {catalogue.path} fits "
                       f"{position or 'the bearing'}: none {said[-1]}"
                       + (f" among those {', '.join(said[:-1])}" if len(said) > 1 else ""))
            if source.startswith("--") or not source:
                raise SpecError(f"{source}: {message}" if source else message,
                                source=document.source)
            raise document.error(message, field=source)
    return rows


def _smaller(first: float | None, second: float | None) -> float | None:
    given = [value for value in (first, second) if value is not None]
    return min(given) if given else None


def _series(row: CatalogueRow) -> str | None:
    """The series of a row as its basic designation begins (``62``, ``NU22``, ``302``)."""
    return None if row.parsed is None else row.parsed.iso_key[:-2]


def _choose(kind: Kind, document: Document, catalogue: Catalogue, envelope: Envelope,
            position: str, top: int) -> PositionChoice:
    rows = _fitting(document, catalogue, envelope, position, kind)
    base = copy.deepcopy(document.data)
    bearing = _bearing(base, position)
    arrangement = bearing.get("arrangement", "single")
    arrangement = arrangement if isinstance(arrangement, str) else "single"
    rows_count = bearing.get("rows") if isinstance(bearing.get("rows"), int) else None
    for name in ROW_OWNED:
        bearing.pop(name, None)
    if "rows" in bearing and rows_count is None:
        bearing.pop("rows")
    base["catalogue"] = str(Path(catalogue.path).resolve())
    groups: dict[tuple[Any, ...], list[CatalogueRow]] = {}
    fields_of: dict[int, dict[str, tuple[str, float]]] = {}
    for row in rows:
        fields = row_fields(row, arrangement, rows_count)
        fields_of[id(row)] = fields
        groups.setdefault((row.type, tuple(sorted(fields))), []).append(row)
    candidates: list[Candidate] = []
    for (_, names), members in groups.items():
        candidates += _solve_group(kind, document, base, position, members, names, fields_of)
    return _ranked(kind, document, base, position, candidates, top, len(rows))


def _with_row(document: Document, base: dict[str, Any], position: str, row: CatalogueRow
              ) -> Document:
    data = copy.deepcopy(base)
    bearing = _bearing(data, position)
    bearing["designation"] = row.designation
    bearing["maker"] = row.maker
    return dataclasses.replace(document, data=data)


def _solve_group(kind: Kind, document: Document, base: dict[str, Any], position: str,
                 members: list[CatalogueRow], names: tuple[str, ...],
                 fields_of: dict[int, dict[str, tuple[str, float]]]
                 ) -> list[Candidate]:
    """The rows of one type and one set of fields, solved in one call on a spec read
    with the first of them that the spec's rules take."""
    template = None
    refused: list[Candidate] = []
    for row in members[:TEMPLATE_TRIES]:
        try:
            _, template = parse_document(_with_row(document, base, position, row))
            break
        except SpecError as error:
            refused.append(Candidate(row, False, problem=_reason(error)))
    if template is None:  # the spec's rules refuse the type itself, not a row's numbers
        reason = refused[0].problem
        return refused + [Candidate(row, False, problem=reason)
                          for row in members[len(refused):]]
    rest = members[len(refused):]
    prefix = f"{position}." if position else ""
    values = {f"{prefix}{name}": np.array([fields_of[id(row)][name][1] for row in rest])
              for name in names}
    results, status = evaluate_with(kind, template, values)
    count = len(rest)
    results = {key: np.broadcast_to(value, (count,)) for key, value in results.items()}
    status = np.broadcast_to(status, (count,))
    passed = kind.within_limits(results, status).tolist()
    codes = status.tolist()
    keys = list(results)
    margin_keys = [key for key in kind.margins if key in results]
    candidates = refused
    for row, code, ok, values in zip(rest, codes, passed, zip(
            *(results[key].tolist() for key in keys), strict=True), strict=True):
        if code:
            field_name, why = kind.status_reasons[int(code)]
            candidates.append(Candidate(row, False, problem=f"{field_name}: {why}"
                                        if field_name else why))
            continue
        scalar = dict(zip(keys, values, strict=True))
        margins = {key: scalar[key] for key in margin_keys}
        candidates.append(Candidate(row, ok, judge(kind, scalar, margins)))
    return candidates


def _reason(error: SpecError) -> str:
    return f"{error.field}: {error.message}" if error.field else error.message


def _ranked(kind: Kind, document: Document, base: dict[str, Any], position: str,
            candidates: list[Candidate], top: int, considered: int) -> PositionChoice:
    """The ``top`` smallest qualifying rows and the ``top`` failing rows nearest to
    passing, each listed row read again whole so that the spec's rules judge it."""
    qualifying = sorted((c for c in candidates if c.qualifies), key=lambda c: c.size)
    failing = sorted((c for c in candidates if not c.qualifies), key=lambda c: -c.closeness)
    listed: list[Candidate] = []
    refused = 0
    for candidate in qualifying:
        if len(listed) == top:
            break
        try:
            parse_document(_with_row(document, base, position, candidate.row))
        except SpecError as error:
            failing.insert(0, Candidate(candidate.row, False, problem=_reason(error)))
            refused += 1
            continue
        listed.append(candidate)
    return PositionChoice(position, considered, listed, failing[:top], len(qualifying) - refused)
