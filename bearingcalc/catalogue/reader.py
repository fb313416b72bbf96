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
from bearingcalc.core.bearing_types import TYPE_NAMES
from bearingcalc.errors import SpecError
from bearingcalc.models.spec_files import refuse_wide_text
from bearingcalc.number_grammar import NUMBER
from bearingcalc.units import DIMENSIONLESS, UnitError, parse_quantity
from bearingcalc.wording import did_you_mean

MAX_FILE_BYTES = 32 * 1024 * 1024
MAX_ROWS = 200_000
MAX_CELL_CHARS = 1_000
MAX_COLUMNS = 64
#: The bearing types a catalogue row may have, by their own names (``thrust-ball``, not
#: the spec's other spelling ``thrust``).
ROW_TYPES = TYPE_NAMES

_HEADER_CELL = re.compile(r"^\s*(?P<name>[A-Za-z_][A-Za-z0-9_]*)\s*(?:\[(?P<unit>[^\[\]]*)\])?\s*$")
_PLAIN_NUMBER = re.compile(NUMBER)
#: Control characters (a line break inside a quoted cell among them): never in a cell.
_CONTROL = re.compile(r"[\x00-\x1f\x7f]")
#: A column's numbers joined by newlines, read in one match.
_NUMBER_LINES = re.compile(rf"(?:{NUMBER}\n)*(?:{NUMBER})?")


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
    reader = csv.reader(io.StringIO(text, newline=""), strict=True)
    header_line = 0
    names: list[str] = []
    columns: dict[str, tuple[Column, str]] = {}
    body: list[list[str]] = []
    lines: list[int] = []
    try:
        for cells in reader:
            if not names:
                if not cells or not "".join(cells).strip() or cells[0].lstrip().startswith("#"):
                    continue
                header_line = reader.line_num
                columns, names = _header(cells, source, header_line)
                continue
            stripped = [cell.strip() for cell in cells]
            if not any(stripped):
                continue
            if len(stripped) != len(names):
                split = [name for separator, name in _OTHER_SEPARATORS.items()
                         if len(stripped) < len(names)
                         and len(",".join(cells).split(separator)) >= len(names)]
                hint = (f"; the row's cells are separated by {split[0]}: write commas, and "
                        "'.' as the decimal point" if split else "")
                raise SpecError(f"{len(stripped)} cells where the header has {len(names)} "
                                f"columns{hint}", source=source, line=reader.line_num)
            if len(body) >= MAX_ROWS:
                raise SpecError(f"more than {MAX_ROWS} rows: split the catalogue",
                                source=source, line=reader.line_num)
            body.append(stripped)
            lines.append(reader.line_num)
    except csv.Error as error:
        raise SpecError(f"not a readable CSV file: {error}", source=source,
                        line=reader.line_num) from None
    if not names:
        raise SpecError("no header: the first line that is not a comment names the "
                        f"columns, like '{', '.join(_example_header())}'", source=source)
    if not body:
        raise SpecError("no rows below the header", source=source, line=header_line)
    problems = [problem for j, name in enumerate(names)
                if (problem := _column_problem(name, columns[name], [row[j] for row in body],
                                               lines, source)) is not None]
    if problems:
        raise min(problems, key=lambda problem: problem.line or 0)
    rows = [RawRow(line, {name: cell for name, cell in zip(names, row, strict=True) if cell})
            for line, row in zip(lines, body, strict=True)]
    return RawCatalogue(source, columns, rows)


def _column_problem(name: str, described: tuple[Column, str], cells: list[str],
                    lines: list[int], source: str) -> SpecError | None:
    """The first problem of one column's cells, checked all at once (a row at a time only
    to find the cell at fault)."""
    column, unit = described
    first: list[tuple[int, str]] = []
    if max(map(len, cells)) > MAX_CELL_CHARS:
        i = next(i for i, cell in enumerate(cells) if len(cell) > MAX_CELL_CHARS)
        first.append((i, f"a cell of over {MAX_CELL_CHARS} characters"))
    control = _CONTROL.search(",".join(cells))
    if control is not None:
        i = next(i for i, cell in enumerate(cells) if _CONTROL.search(cell))
        first.append((i, f"a control character ({control.group()!r}) in a cell: catalogue "
                      "cells are printable text on one line"))
    if column.required and "" in cells:
        first.append((cells.index(""), f"empty: every row gives its {name}" + (
            " (the document, edition and page, or the URL and the date read)"
            if name == "source" else "")))
    if column.dimension is not None and _NUMBER_LINES.fullmatch(
            "\n".join(cell for cell in cells if cell)) is None:
        i = next(i for i, cell in enumerate(cells)
                 if cell and _PLAIN_NUMBER.fullmatch(cell) is None)
        first.append((i, _not_a_number(cells[i], column, unit)))
    if name == "type":
        unknown = set(cells) - set(ROW_TYPES) - {""}
        if unknown:
            i = next(i for i, cell in enumerate(cells) if cell in unknown)
            first.append((i, f"unknown type {cells[i][:40]!r}"
                          f"{did_you_mean(cells[i], ROW_TYPES)}; one of {', '.join(ROW_TYPES)}"))
    if not first:
        return None
    i, message = min(first)
    return SpecError(message, source=source, line=lines[i], field=name)


#: A number written with a decimal comma ('14,8'), maybe with a unit after it.
_DECIMAL_COMMA = re.compile(r"(?P<whole>[-+]?[0-9]+),(?P<fraction>[0-9]+)(?P<rest>\s*\S.*)?")


def _not_a_number(cell: str, column: Column, unit: str) -> str:
    """Why a number column's cell is not a number, with the likely fix: a decimal point
    for a decimal comma (a thousands separator where the comma could be one), no unit."""
    want = "a whole number" if column.whole else "a number"
    units = f" (the unit, {unit}, is the column's)" if unit else ""
    comma = _DECIMAL_COMMA.fullmatch(cell)
    if comma is None:
        return f"{cell[:40]!r} is not {want}: write {want} alone{units}"
    point = f"{comma['whole']}.{comma['fraction']}"
    fix = f"write the decimal point as '.', like '{point}'"
    if len(comma["fraction"]) == 3:  # '1,500': a decimal comma, or a thousands separator
        fix += f", or leave the thousands separator out, like '{comma['whole']}{comma['fraction']}'"
    return f"{cell[:40]!r} is not {want}: {fix}{units}"


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
    refuse_wide_text(raw, source, "save the catalogue as UTF-8 (CSV UTF-8)")
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
            raise SpecError(_separator_hint(cells) or (
                f"cannot read the column heading {cell[:60]!r}: write a name and, for a "
                "number with a unit, the unit in brackets, like 'dynamic_load_rating [kN]'"),
                source=source, line=line)
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


#: Separators a spreadsheet may write in place of the comma, and their names.
_OTHER_SEPARATORS = {";": "';'", "\t": "tabs", "|": "'|'"}


def _separator_hint(cells: list[str]) -> str | None:
    """Where the header's columns are separated by another character than the comma (a
    spreadsheet set to a decimal comma writes ';'), what to do; else None."""
    for separator, name in _OTHER_SEPARATORS.items():
        parts = [part for cell in cells for part in cell.split(separator)]
        if len(parts) > len(cells) and all(_HEADER_CELL.match(part) for part in parts):
            return (f"the columns are separated by {name}: a catalogue separates them by "
                    "commas and writes the decimal point as '.' (save it as 'CSV UTF-8 "
                    "(comma delimited)' with '.' as the decimal symbol)")
    return None


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
