"""Reading a bearing catalogue: a CSV file with a ``name [unit]`` header, as hardened as
the spec reader.

Files over ``MAX_FILE_BYTES``, rows over ``MAX_ROWS`` and cells over ``MAX_CELL_CHARS``
are refused; the text must be UTF-8 (a byte-order mark is dropped; CRLF, quoted fields
and commas inside quotes are read as the CSV rules say). Cells are text: a cell that
looks like a spreadsheet formula (``=cmd|...``) is read as the text it is, and a number
column takes nothing but a plain number. Lines starting with ``#`` before the header
are comments. Every problem is one :class:`SpecError` with the file, the line and the
column.
"""

from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass
from pathlib import Path

from bearingcalc.catalogue.columns import COLUMNS, REQUIRED, Column
from bearingcalc.errors import SpecError
from bearingcalc.number_grammar import NUMBER
from bearingcalc.units import DIMENSIONLESS, UnitError, parse_quantity
from bearingcalc.wording import did_you_mean

MAX_FILE_BYTES = 32 * 1024 * 1024
MAX_ROWS = 200_000
MAX_CELL_CHARS = 1_000
MAX_COLUMNS = 64
#: The bearing types a catalogue row may have (a rolling bearing's types).
ROW_TYPES = ("deep-groove", "angular-contact", "self-aligning-ball", "thrust-ball",
             "cylindrical-roller", "needle-roller", "tapered-roller", "spherical-roller",
             "thrust-cylindrical-roller", "thrust-spherical-roller", "thrust-tapered-roller")

_HEADER_CELL = re.compile(r"^\s*(?P<name>[A-Za-z_][A-Za-z0-9_]*)\s*(?:\[(?P<unit>[^\[\]]*)\])?\s*$")
_PLAIN_NUMBER = re.compile(rf"^{NUMBER}$")


@dataclass(frozen=True)
class RawRow:
    """A row as read: its line in the file and its cells by column name (stripped
    text; empty cells left out)."""

    line: int
    cells: dict[str, str]


@dataclass(frozen=True)
class RawCatalogue:
    """A catalogue file as read and checked cell by cell."""

    path: str
    columns: dict[str, tuple[Column, str]]    # name -> (column, unit as written)
    rows: list[RawRow]


def read_csv(path: str | Path) -> RawCatalogue:
    """The header and rows of a catalogue file, every cell checked against its column
    (a number with the column's unit, a known type, a source on every row)."""
    source = str(path)
    text = _text(Path(path), source)
    reader = csv.reader(io.StringIO(text, newline=""))
    header: list[str] | None = None
    header_line = 0
    rows: list[RawRow] = []
    columns: dict[str, tuple[Column, str]] = {}
    names: list[str] = []
    try:
        for cells in reader:
            line = reader.line_num
            if header is None:
                if not cells or not "".join(cells).strip() or cells[0].lstrip().startswith("#"):
                    continue
                header, header_line = cells, line
                columns, names = _header(cells, source, line)
                continue
            if not any(cell.strip() for cell in cells):
                continue
            if len(rows) >= MAX_ROWS:
                raise SpecError(f"more than {MAX_ROWS} rows: split the catalogue",
                                source=source, line=line)
            rows.append(_row(cells, names, columns, source, line))
    except csv.Error as error:
        raise SpecError(f"not a readable CSV file: {error}", source=source,
                        line=reader.line_num) from None
    if header is None:
        raise SpecError("no header: the first line that is not a comment names the "
                        f"columns, like '{', '.join(_example_header())}'", source=source)
    if not rows:
        raise SpecError("no rows below the header", source=source, line=header_line)
    return RawCatalogue(source, columns, rows)


def _text(path: Path, source: str) -> str:
    try:
        with path.open("rb") as handle:
            raw = handle.read(MAX_FILE_BYTES + 1)
    except FileNotFoundError:
        raise SpecError("no such catalogue file", source=source) from None
    except IsADirectoryError:
        raise SpecError("is a folder, not a catalogue file (a .csv)", source=source) from None
    except OSError as error:
        raise SpecError(f"cannot read the catalogue: {error.strerror}", source=source) from None
    if len(raw) > MAX_FILE_BYTES:
        raise SpecError(f"file too large: catalogues are at most {MAX_FILE_BYTES // 2**20} MiB",
                        source=source)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        line = raw[:error.start].count(b"\n") + 1
        raise SpecError("not UTF-8 text: save the catalogue as UTF-8 (CSV UTF-8)",
                        source=source, line=line) from None


def _example_header() -> list[str]:
    return [f"{name} [{column.dimension.display_unit}]"
            if column.dimension not in (None, DIMENSIONLESS) else name
            for name, column in COLUMNS.items() if column.required]


def _header(cells: list[str], source: str, line: int
            ) -> tuple[dict[str, tuple[Column, str]], list[str]]:
    if len(cells) > MAX_COLUMNS:
        raise SpecError(f"{len(cells)} columns is more than {MAX_COLUMNS}", source=source,
                        line=line)
    columns: dict[str, tuple[Column, str]] = {}
    names: list[str] = []
    for cell in cells:
        match = _HEADER_CELL.match(cell)
        if match is None:
            raise SpecError(f"cannot read the column heading {cell[:60]!r}: write a name and, "
                            "for a number with a unit, the unit in brackets, like "
                            "'dynamic_load_rating [kN]'", source=source, line=line)
        name, unit = match["name"], (match["unit"] or "").strip()
        column = COLUMNS.get(name)
        if column is None:
            raise SpecError(f"unknown column {name!r}{did_you_mean(name, COLUMNS)}; the "
                            f"columns are {', '.join(COLUMNS)}", source=source, line=line,
                            field=name)
        if name in columns:
            raise SpecError(f"column {name!r} is given twice", source=source, line=line,
                            field=name)
        _check_unit(column, unit, source, line)
        columns[name] = (column, unit)
        names.append(name)
    missing = [name for name in REQUIRED if name not in columns]
    if missing:
        raise SpecError(f"missing column{'s' if len(missing) > 1 else ''} "
                        f"{', '.join(missing)}: every catalogue gives "
                        f"{', '.join(REQUIRED)}", source=source, line=line, field=missing[0])
    return columns, names


def _check_unit(column: Column, unit: str, source: str, line: int) -> None:
    dimension = column.dimension
    if dimension is None or dimension is DIMENSIONLESS:
        if unit:
            raise SpecError(f"{column.name} takes no unit, got [{unit}]", source=source,
                            line=line, field=column.name)
        return
    if not unit:
        raise SpecError(f"{column.name} needs its unit in the heading, like "
                        f"'{column.name} [{dimension.display_unit}]'", source=source,
                        line=line, field=column.name)
    try:
        parse_quantity(f"1 {unit}", dimension)
    except UnitError as error:
        raise SpecError(f"[{unit}]: {error}", source=source, line=line,
                        field=column.name) from None


def _row(cells: list[str], names: list[str], columns: dict[str, tuple[Column, str]],
         source: str, line: int) -> RawRow:
    if len(cells) != len(names):
        raise SpecError(f"{len(cells)} cells where the header has {len(names)} columns",
                        source=source, line=line)
    found: dict[str, str] = {}
    for name, cell in zip(names, cells, strict=True):
        text = cell.strip()
        if len(text) > MAX_CELL_CHARS:
            raise SpecError(f"a cell of over {MAX_CELL_CHARS} characters", source=source,
                            line=line, field=name)
        if not text:
            continue
        column, unit = columns[name]
        if column.dimension is not None and not _PLAIN_NUMBER.match(text):
            want = "a whole number" if column.whole else "a number"
            units = f" (the unit, {unit}, is the column's)" if unit else ""
            raise SpecError(f"{text[:40]!r} is not {want}: write {want} alone{units}",
                            source=source, line=line, field=name)
        found[name] = text
    for name in REQUIRED:
        if name not in found:
            raise SpecError(f"empty: every row gives its {name}"
                            + (" (the document, edition and page, or the URL and the date "
                               "read)" if name == "source" else ""),
                            source=source, line=line, field=name)
    if found["type"] not in ROW_TYPES:
        raise SpecError(f"unknown type {found['type'][:40]!r}"
                        f"{did_you_mean(found['type'], ROW_TYPES)}; one of "
                        f"{', '.join(ROW_TYPES)}", source=source, line=line, field="type")
    return RawRow(line, found)
