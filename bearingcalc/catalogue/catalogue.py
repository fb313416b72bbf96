"""A bearing catalogue in memory: its rows in SI units, checked against the ISO boundary
dimensions, and the lookup of a designation."""

from __future__ import annotations

import difflib
import functools
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from bearingcalc.catalogue.columns import COLUMNS, NUMERIC
from bearingcalc.catalogue.designation import Designation, parse_designation
from bearingcalc.catalogue.iso import iso_series, iso_table
from bearingcalc.catalogue.reader import RawCatalogue, RawRow, read_csv
from bearingcalc.errors import SpecError
from bearingcalc.units import DIMENSIONLESS, MAX_MAGNITUDE, to_display, unit_scale

#: How far a row's dimension may be from ISO's before it contradicts it. [m]
DIMENSION_TOLERANCE = 1e-7
ISO_CHECKED = ("bore_diameter", "outside_diameter", "width")


@dataclass(frozen=True)
class CatalogueRow:
    """One bearing of a catalogue."""

    designation: str
    maker: str
    type: str
    source: str
    line: int
    #: number columns given, in SI
    values: dict[str, float]
    #: the same as the file writes them, with the column's unit ('14.8 kN'), for specs
    written: dict[str, str | float]
    parsed: Designation | None

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

    def column(self, name: str) -> NDArray:
        """A number column over every row, NaN where a row leaves it empty. [SI]"""
        return np.array([row.values.get(name, np.nan) for row in self.rows])

    def find(self, designation: str | int, maker: str | None = None) -> CatalogueRow:
        """The row of ``designation`` (by its basic designation; its suffixes pick among
        rows that share one), of ``maker`` where given. Raises LookupError with the
        nearest designations where none or several fit."""
        wanted = parse_designation(designation)
        text = str(designation).strip()
        candidates = [row for row in self.rows
                      if (maker is None or row.maker.casefold() == maker.casefold())
                      and _same_basic(row, wanted, text)]
        exact = [row for row in candidates if _normal(row.designation) == _normal(text)]
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


def _normal(text: str) -> str:
    return "".join(text.split()).casefold()


def _same_basic(row: CatalogueRow, wanted: Designation | None, text: str) -> bool:
    if wanted is None or row.parsed is None:
        return _normal(row.designation) == _normal(text)
    return row.parsed.basic == wanted.basic


@functools.lru_cache(maxsize=8)
def _cached(path: str, modified: float, size: int) -> Catalogue:
    return build(read_csv(path))


def load_catalogue(path: str | Path) -> Catalogue:
    """The catalogue at ``path``, read once per version of the file; raises SpecError."""
    target = Path(path)
    try:
        status = target.stat()
    except OSError:
        raise SpecError("no such catalogue file", source=str(path)) from None
    return _cached(str(target), status.st_mtime, status.st_size)


def build(raw: RawCatalogue) -> Catalogue:
    """Rows in SI, each checked against ISO's dimensions for its designation; raises
    SpecError at the row's line."""
    rows: list[CatalogueRow] = []
    seen: dict[tuple[str, str], int] = {}
    special: list[str] = []
    scales = _scales(raw)
    for raw_row in raw.rows:
        row = _row(raw, raw_row, scales)
        key = (_normal(row.designation), row.maker.casefold())
        if key in seen:
            raise SpecError(f"{row.label} is given twice (first at line {seen[key]})",
                            source=raw.path, line=row.line, field="designation")
        seen[key] = row.line
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


def _scales(raw: RawCatalogue) -> dict[str, tuple[float, bool] | None]:
    """Each number column's conversion to SI (None: a plain number)."""
    return {name: None if column.dimension is DIMENSIONLESS
            else unit_scale(unit, column.dimension)  # type: ignore[arg-type]
            for name, (column, unit) in raw.columns.items() if name in NUMERIC}


def _row(raw: RawCatalogue, raw_row: RawRow, scales: dict[str, tuple[float, bool] | None]
         ) -> CatalogueRow:
    values: dict[str, float] = {}
    written: dict[str, str | float] = {}
    for name, text in raw_row.cells.items():
        if name not in scales:
            continue
        number = float(text)
        scale = scales[name]
        column, unit = raw.columns[name]
        if scale is None:
            if column.whole and not number.is_integer():
                raise SpecError(f"{text!r} is not a whole number", source=raw.path,
                                line=raw_row.line, field=name)
            value = number
            written[name] = int(number) if column.whole else number
        else:
            value = number / scale[0] if scale[1] else number * scale[0]
            written[name] = f"{text} {unit}"
        if not (math.isfinite(value) and abs(value) <= MAX_MAGNITUDE) or (
                value <= 0 and name != "contact_angle"):
            raise SpecError(f"must be a finite number greater than zero, got {text}",
                            source=raw.path, line=raw_row.line, field=name)
        values[name] = value
    cells = raw_row.cells
    return CatalogueRow(cells["designation"], cells["maker"], cells["type"], cells["source"],
                        raw_row.line, values, written, parse_designation(cells["designation"]))


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
