"""The reports of ``sweep`` other than its CSV: a table (a line's every point, or a
grid's first chosen result on a compact grid), JSON Lines and Parquet."""

from __future__ import annotations

from collections.abc import Sequence
from typing import IO, TYPE_CHECKING, Any

import numpy as np

from bearingcalc.reports.formatting import console, print_whole
from bearingcalc.reports.sweep_csv import BLOCK_ROWS, sweep_columns
from bearingcalc.units import to_display
from bearingcalc.wording import printable

if TYPE_CHECKING:  # the report type only; its module loads with the command
    from bearingcalc.sweeps import Sweep


def write_sweep_json_lines(sweep: Sweep, stream: IO[str]) -> None:
    """JSON Lines, one object per point: {"inputs", "results", "reason"} (SI units, as
    in the CSV header; docs/commands.md)."""
    import orjson

    names = [axis.name for axis in sweep.axes]
    integer = {axis.name: axis.integer for axis in sweep.axes}
    keys = list(sweep.results)
    for start in range(0, len(sweep.status), BLOCK_ROWS):
        stop = min(start + BLOCK_ROWS, len(sweep.status))
        inputs = {name: sweep.inputs[name][start:stop].tolist() for name in names}
        results = {key: sweep.results[key][start:stop].tolist() for key in keys}
        lines = []
        for row, code in enumerate(sweep.status[start:stop].tolist()):
            point = {name: (int(inputs[name][row]) if integer[name] else inputs[name][row])
                     for name in names}
            solved = {} if code else {key: results[key][row] for key in keys}
            lines.append(orjson.dumps({"inputs": point, "results": solved,
                                       "reason": sweep.reason(code) if code else None}))
        stream.write(b"\n".join(lines).decode() + "\n")


def write_sweep_parquet(sweep: Sweep, path: Any) -> None:
    """The CSV's columns as a Parquet table (pyarrow, the optional extra
    ``bearingcalc[parquet]``): float64 columns named as the CSV's headers, integer axes
    as int64, and ``reason`` (null for possible designs)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    arrays, names = [], []
    integer = {f"input.{axis.name} [{axis.unit}]": axis.integer for axis in sweep.axes}
    for name, values in sweep_columns(sweep):
        # from_pandas: NaN (an impossible design's result) becomes null, as in the CSV.
        arrays.append(pa.array(values.astype(np.int64) if integer.get(name)
                               else values.astype(float), from_pandas=True))
        names.append(name)
    reasons = {code: sweep.reason(code) for code in np.unique(sweep.status).tolist() if code}
    arrays.append(pa.array([reasons.get(code) for code in sweep.status.tolist()],
                           type=pa.string()))
    names.append("reason")
    pq.write_table(pa.Table.from_arrays(arrays, names=names), path)


def print_sweep_table(sweep: Sweep, keys: Sequence[str], stream: IO[str] | None = None,
                      grid_rows: int = 12, grid_columns: int = 8) -> None:
    """All points of a line with the chosen results; for a grid, the first chosen result
    on a compact grid (every n-th value of each axis)."""
    from rich.markup import escape
    from rich.table import Table

    out = console(stream)
    units = sweep.units

    def shown(value: float, si_unit: str, digits: int = 7) -> str:
        if not np.isfinite(value):
            return "—"
        return f"{to_display(value, si_unit)[0]:.{digits}g}"

    def result(key: str, value: float, digits: int = 7) -> str:
        """A result as the solve table shows it: in words where the kind labels it."""
        text = shown(value, units[key], digits)
        return sweep.kind.labels.get(key, {}).get(value, text)

    def label(name: str, si_unit: str) -> str:
        unit = to_display(0.0, si_unit)[1]
        return escape(f"{name} [{unit}]") if unit else name

    # The heading names the spec's file: whole, above the table (see print_whole).
    print_whole(out, escape(printable(f"{sweep.name} ({sweep.kind.name}, {sweep.source})")))
    if len(sweep.axes) == 1:
        axis = sweep.axes[0]
        table = Table()
        for header in (label(axis.name, axis.unit), *(label(k, units[k]) for k in keys)):
            table.add_column(header, justify="right")
        gaps = bool(np.any(sweep.status != 0))
        if gaps:  # an empty column only takes room
            table.add_column("impossible because")
        for i, value in enumerate(sweep.inputs[axis.name].tolist()):
            code = int(sweep.status[i])
            table.add_row(shown(value, axis.unit),
                          *(result(k, sweep.results[k][i]) for k in keys),
                          *([sweep.reason(code) if code else ""] if gaps else []))
        out.print(table)
        return
    first, second = sweep.axes
    key = keys[0]
    values = sweep.results[key].reshape(sweep.shape)
    rows = np.unique(np.linspace(0, len(first.values) - 1, grid_rows).round().astype(int))
    cols = np.unique(np.linspace(0, len(second.values) - 1, grid_columns).round().astype(int))
    table = Table(title=f"{label(key, units[key])} by "
                  f"{label(first.name, first.unit)} (rows) and {label(second.name, second.unit)}"
                  " (columns); —: impossible design", title_justify="left")
    table.add_column("")
    for j in cols:
        table.add_column(shown(second.values[j], second.unit, 4), justify="right")
    for i in rows:
        table.add_row(shown(first.values[i], first.unit, 4),
                      *(result(key, values[i, j], 4) for j in cols))
    out.print(table)
    if len(rows) < len(first.values) or len(cols) < len(second.values):
        out.print(f"(every point of the {len(first.values)} × {len(second.values)} grid is "
                  "in --format csv or json)")
