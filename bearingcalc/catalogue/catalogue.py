"""A bearing catalogue in memory: its rows in SI units, checked against the ISO boundary
dimensions, and the lookup of a designation."""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from bearingcalc import reads
from bearingcalc.catalogue.columns import COLUMNS, NUMERIC
from bearingcalc.catalogue.designation import Designation, normal_form, parse_designation
from bearingcalc.catalogue.iso import iso_series, iso_table
from bearingcalc.catalogue.reader import RawCatalogue, read_csv
from bearingcalc.core.bearing_types import TABLE, traits
from bearingcalc.errors import SpecError
from bearingcalc.units import DIMENSIONLESS, MAX_MAGNITUDE, to_display, unit_scale

#: How far a row's dimension may be from ISO's before it contradicts it: a hundredth of a
#: millimetre, so that a catalogue in inches to four decimals (2.5 µm) agrees. [m]
DIMENSION_TOLERANCE = 1e-5
ISO_CHECKED = ("bore_diameter", "outside_diameter", "width")
#: The type whose outer ring is a cup with a chamfer of its own (``cup_r_min``).
CUPPED_TYPE = next(entry.name for entry in TABLE if entry.cupped)


class CatalogueRow:
    """One bearing of a catalogue: its text cells, and its numbers in SI."""

    __slots__ = (
        "_cells",
        "_units",
        "designation",
        "line",
        "maker",
        "parsed",
        "source",
        "type",
        "values",
    )

    def __init__(self, cells: dict[str, str], line: int, values: dict[str, float],
                 units: dict[str, str]) -> None:
        self.designation, self.maker = cells["designation"], cells["maker"]
        self.type, self.source = cells["type"], cells["source"]
        self.line = line
        #: number columns given, in SI
        self.values = values
        self.parsed: Designation | None = parse_designation(self.designation)
        self._cells = cells
        self._units = units

    @property
    def written(self) -> dict[str, str | float]:
        """The numbers as the file writes them, with the column's unit ('14.8 kN'), so
        that a spec filled from the row reads as if typed; plain numbers as numbers."""
        out: dict[str, str | float] = {}
        for name in self.values:
            text, unit = self._cells[name], self._units[name]
            out[name] = (f"{text} {unit}" if unit else
                         int(float(text)) if COLUMNS[name].whole else float(text))
        return out

    @property
    def label(self) -> str:
        return f"{self.designation} ({self.maker})"

    @property
    def cited(self) -> str:
        """The row as the results name it: designation, maker, source."""
        return f"{self.designation}, {self.maker}: {self.source}"


@dataclass
class Catalogue:
    """The rows of one catalogue file."""

    path: str
    rows: list[CatalogueRow]
    #: what the reader should know of the file (bearings ISO's table does not hold)
    warnings: list[str] = field(default_factory=list)
    _by_basic: dict[str, list[CatalogueRow]] | None = field(default=None, repr=False)

    def column(self, name: str) -> NDArray:
        """A number column over every row, NaN where a row leaves it empty. [SI]"""
        return np.array([row.values.get(name, np.nan) for row in self.rows])

    def _index(self) -> dict[str, list[CatalogueRow]]:
        """Rows by basic designation (a special bearing's by its whole designation)."""
        if self._by_basic is None:
            index: dict[str, list[CatalogueRow]] = {}
            for row in self.rows:
                key = (row.parsed.basic if row.parsed is not None
                       else normal_designation(row.designation))
                index.setdefault(key, []).append(row)
            self._by_basic = index
        return self._by_basic

    def find(self, designation: str | int, maker: str | None = None) -> CatalogueRow:
        """The row of ``designation`` (by its basic designation; its suffixes pick among
        rows that share one), of ``maker`` where given. Raises LookupError with the
        nearest designations where none or several fit."""
        wanted = parse_designation(designation)
        text = str(designation).strip()
        key = wanted.basic if wanted is not None else normal_designation(text)
        candidates = [row for row in self._index().get(key, [])
                      if (maker is None or row.maker.casefold() == maker.casefold())
                      and _same_basic(row, wanted, text)]
        exact = [row for row in candidates
                 if normal_designation(row.designation) == normal_designation(text)]
        found = exact or candidates
        if len(found) == 1:
            return found[0]
        if not found:
            names = sorted({row.designation for row in self.rows
                            if maker is None or row.maker.casefold() == maker.casefold()})
            near = difflib.get_close_matches(text, names, n=3, cutoff=0.5)
            hint = f"; the nearest: {', '.join(near)}" if near else ""
            whose = f" from {maker}" if maker else ""
            raise LookupError(f"{text!r} is not in the catalogue{whose}{hint}")
        makers = sorted({row.maker for row in found})
        if len(makers) > 1:
            raise LookupError(f"{text!r} is in the catalogue from {', '.join(makers)}: "
                              f"give the bearing's maker too, like maker: {makers[0]}")
        raise LookupError(f"{text!r} fits {', '.join(row.designation for row in found)}: "
                          "write the designation whole")


def normal_designation(text: str | int) -> str:
    """A designation as looked up: its compatibility form (:func:`normal_form`), without
    spaces, case-folded (``'6205 2rs'`` and ``'６２０５-2RS'`` are ``'62052rs'`` and
    ``'6205-2rs'``)."""
    return "".join(normal_form(text).split()).casefold()


def _same_basic(row: CatalogueRow, wanted: Designation | None, text: str) -> bool:
    if wanted is None or row.parsed is None:
        return normal_designation(row.designation) == normal_designation(text)
    return row.parsed.basic == wanted.basic


_LOADED: dict[tuple[str, float, int], Catalogue] = {}
_KEEP = 8


def load_catalogue(path: str | Path) -> Catalogue:
    """The catalogue at ``path``, read once per version of the file (however the path is
    written); raises SpecError. Every call notes the file as read by the run (even when
    its rows come from memory), so that no output of the run replaces it."""
    target = Path(path)
    reads.note(target, "catalogue")
    try:
        status = target.stat()
        key = (str(target.resolve()), status.st_mtime, status.st_size)
    except OSError:
        raise SpecError("no such catalogue file", source=str(path)) from None
    found = _LOADED.get(key)
    if found is None:
        found = build(read_csv(target))
        if len(_LOADED) >= _KEEP:
            _LOADED.pop(next(iter(_LOADED)))
        _LOADED[key] = found
    return found


def build(raw: RawCatalogue) -> Catalogue:
    """Rows in SI, each checked against ISO's dimensions for its designation; raises
    SpecError at the row's line."""
    numbers = _numbers(raw)
    units = {name: unit if COLUMNS[name].dimension is not DIMENSIONLESS else ""
             for name, (_, unit) in raw.columns.items() if name in numbers}
    names = list(numbers)
    table = zip(*(numbers[name].tolist() for name in names), strict=True)
    rows: list[CatalogueRow] = []
    seen: dict[tuple[str, str], int] = {}
    special: list[str] = []
    for raw_row, numbers_of_row in zip(raw.rows, table, strict=True):
        # a NaN is an empty cell
        values = {name: value for name, value in zip(names, numbers_of_row, strict=True)
                  if not math.isnan(value)}
        row = CatalogueRow(raw_row.cells, raw_row.line, values, units)
        key = (normal_designation(row.designation), row.maker.casefold())
        if key in seen:
            raise SpecError(f"{row.label} is given twice (first at line {seen[key]})",
                            source=raw.path, line=row.line, field="designation")
        seen[key] = row.line
        _check_cup(row, raw.path)
        if not _check_iso(row, raw.path):
            special.append(row.designation)
        rows.append(row)
    warnings = []
    if special:
        shown = ", ".join(special[:5]) + (f" and {len(special) - 5} more" if len(special) > 5
                                          else "")
        warnings.append(f"{raw.path}: {shown} {'is' if len(special) == 1 else 'are'} not in "
                        "the table of ISO boundary dimensions (series "
                        f"{', '.join(iso_series())}): the catalogue's dimensions are taken "
                        "unchecked")
    return Catalogue(raw.path, rows, warnings)


def _numbers(raw: RawCatalogue) -> dict[str, NDArray]:
    """Each number column over every row in SI (NaN where a cell is empty), converted as
    :func:`bearingcalc.units.parse_quantity` converts one number; a SpecError at the
    first cell out of range."""
    out: dict[str, NDArray] = {}
    for name, (column, unit) in raw.columns.items():
        if name not in NUMERIC:
            continue
        written = np.array([float(row.cells.get(name, "nan")) for row in raw.rows])
        if column.dimension is DIMENSIONLESS:
            values = written
        else:
            factor, divides = unit_scale(unit, column.dimension)  # type: ignore[arg-type]
            with np.errstate(over="ignore"):  # an overflow is refused below, in words
                values = written / factor if divides else written * factor
        given = ~np.isnan(values)
        allowed = (values > 0) | ((values == 0) if name == "contact_angle" else False)
        bad = given & ~(allowed & (values <= MAX_MAGNITUDE))
        if column.whole:
            bad |= given & (written != np.floor(written))
        if bad.any():
            i = int(np.argmax(bad))
            text = raw.rows[i].cells[name]
            what = ("a whole number greater than zero" if column.whole
                    else "a finite number greater than zero")
            raise SpecError(f"must be {what}, got {text}", source=raw.path,
                            line=raw.rows[i].line, field=name)
        out[name] = values
    return out


def _check_cup(row: CatalogueRow, path: str) -> None:
    """A cup chamfer belongs to a tapered roller bearing (whose ``r_min`` is the cone's);
    on any other type it is a misplaced value. Raises SpecError."""
    if "cup_r_min" in row.values and not traits(row.type).cupped:
        raise SpecError(f"{row.label} is {row.type}, which has no cup: cup_r_min is the cup's "
                        f"chamfer of a {CUPPED_TYPE} bearing; leave it empty",
                        source=path, line=row.line, field="cup_r_min")


def _check_iso(row: CatalogueRow, path: str) -> bool:
    """True where ISO's table holds the row's designation (and the row agrees with it);
    False for a bearing the table does not hold. Raises SpecError on a contradiction."""
    if row.parsed is None:
        return False
    iso = iso_table().get(row.parsed.iso_key)
    if iso is None:
        return False
    if iso.type != row.type:
        raise SpecError(f"{row.label} is {iso.type} in ISO's boundary dimensions, got "
                        f"{row.type}", source=path, line=row.line, field="type")
    for name in ISO_CHECKED:
        ours, theirs = row.values[name], getattr(iso, name)
        if abs(ours - theirs) > DIMENSION_TOLERANCE:
            shown, unit = to_display(ours, "m")
            standard, _ = to_display(theirs, "m")
            what = COLUMNS[name].name
            raise SpecError(f"{row.label}: {what} {shown:g} {unit} where ISO's boundary "
                            f"dimensions give {standard:g} {unit} for {row.parsed.iso_key}",
                            source=path, line=row.line, field=name)
    return True
