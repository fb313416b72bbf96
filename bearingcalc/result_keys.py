"""The output edge of a solution: results along axes made into the flat keys users read.

A solver returns its results of one value per design by key, and those along an axis
(a drive's bearings, a duty cycle's bins) as arrays with that axis first
(:class:`~bearingcalc.core.solver.Along`). JSON, CSV, tables and studies speak flat keys:
``{row}_{column}`` (``pinion_bearing_2_axial_load``, ``duty_3_speed``). :func:`flatten`
makes every one of them, with its unit and meaning and the small tables a report shows
them in, from the declarations alone; nothing reads a key back into its parts.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any, NamedTuple

from numpy.typing import NDArray

from bearingcalc.core.solver import Along, AxisResults


class ResultTable(NamedTuple):
    """Results along an axis shown as a table of their own: a row per position (a
    bearing, a bin), a column per quantity, and the flat key of every cell (None where
    the row has no such value)."""

    heading: str
    axis: str
    #: each row's stem (``pinion_bearing_1``, ``duty_2``) and its position along the axis
    rows: tuple[str, ...]
    positions: tuple[int, ...]
    columns: tuple[str, ...]
    cells: tuple[tuple[str | None, ...], ...]

    @property
    def keys(self) -> tuple[str, ...]:
        """Every flat key the table shows, row by row."""
        return tuple(key for row in self.cells for key in row if key is not None)

    def column(self, column: str) -> list[str | None]:
        """The flat key of ``column`` in each row (None where the row has none)."""
        if column not in self.columns:
            return [None] * len(self.rows)
        index = self.columns.index(column)
        return [row[index] for row in self.cells]


class FlatResults(dict[str, NDArray]):
    """Flat key -> values [SI], in report order, with each key's (SI unit, meaning) in
    ``names``, the tables along axes in ``tables``, and what each status code of the
    solve means in ``reasons``: (field at fault, why)."""

    def __init__(self, values: Mapping[str, NDArray] | None = None,
                 names: Mapping[str, tuple[str, str]] | None = None,
                 tables: tuple[ResultTable, ...] = ()) -> None:
        super().__init__(values or {})
        self.names: dict[str, tuple[str, str]] = dict(names or {})
        self.tables = tables
        self.reasons: dict[int, tuple[str, str]] = {}

    def with_values(self, values: Mapping[str, Any]) -> FlatResults:
        """Other values (one design's, a sweep's) with this solve's layout."""
        flat = FlatResults(values, self.names, self.tables)
        flat.reasons = self.reasons
        return flat


@dataclass(frozen=True)
class _Block:
    axis: str
    declared: AxisResults
    along: Along
    keys: list[tuple[str, int, str]] = field(default_factory=list)  # (key, row, column)


def flatten(results: Mapping[str, NDArray], along: Mapping[str, Along],
            scalars: Mapping[str, tuple[str, str]], declared: Mapping[str, AxisResults],
            headings: Mapping[str, str]) -> FlatResults:
    """Every result of a solution by its flat key, in report order.

    ``results`` are the values of one per design (named in ``scalars``); each axis's
    block of ``along`` follows the result its declaration names (or comes last), row by
    row or column by column as declared. ``headings`` gives an axis's table heading
    where its rows do not carry their own.
    """
    blocks = [_block(axis, declared[axis], values) for axis, values in along.items()]
    flat = FlatResults()
    for key, values in results.items():
        flat[key] = values
        flat.names[key] = scalars[key]
        for block in blocks:
            if block.declared.after == key:
                _add(flat, block)
    for block in blocks:
        if block.declared.after not in results:
            _add(flat, block)
    tables = tuple(table for block in blocks
                   for table in _tables(block, headings.get(block.axis, block.axis)))
    return FlatResults(flat, flat.names, tables)


def _block(axis: str, declared: AxisResults, along: Along) -> _Block:
    block = _Block(axis, declared, along)
    columns = [column for column in declared.columns if column in along.values]
    pairs = ([(row, column) for row in range(len(along.rows)) for column in columns]
             if declared.by_row else
             [(row, column) for column in columns for row in range(len(along.rows))])
    block.keys.extend((f"{along.rows[row]}_{column}", row, column)
                      for row, column in pairs if along.has(column, row))
    return block


def _add(flat: FlatResults, block: _Block) -> None:
    for key, row, column in block.keys:
        unit, meaning = block.declared.columns[column]
        flat[key] = block.along.values[column][row]
        flat.names[key] = (unit, block.declared.meaning.format(
            meaning=meaning, position=row + 1, row=block.along.rows[row].replace("_", " ")))


def _tables(block: _Block, default: str) -> Iterator[ResultTable]:
    """A table per heading the block's rows are shown under, in the rows' order."""
    along = block.along
    headings = along.headings or (default,) * len(along.rows)
    found = {(row, column): key for key, row, column in block.keys}
    for heading in dict.fromkeys(headings):
        positions = tuple(i for i, own in enumerate(headings) if own == heading)
        columns = tuple(column for column in block.declared.columns
                        if any((row, column) in found for row in positions))
        yield ResultTable(heading, block.axis, tuple(along.rows[i] for i in positions),
                          positions, columns,
                          tuple(tuple(found.get((row, column)) for column in columns)
                                for row in positions))
