"""The cells of every CSV bearingcalc writes (solve, select, sweep): text that a
spreadsheet shows and never runs, numbers that stay numbers.

A text cell that starts with ``=``, ``+``, ``-``, ``@``, a tab or a return would be
read by a spreadsheet as a formula (``=HYPERLINK(...)`` in a spec's name, a spec file
named ``=1+2.yaml``); it gets a leading ``'``, as catalogue text does
(:func:`bearingcalc.wording.spreadsheet_text`). A number is never text: a negative
one is written as the number it is.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable, Sequence
from numbers import Integral, Real
from typing import IO

from bearingcalc.wording import spreadsheet_text

#: What a cell holds: text, a number, a yes/no, or nothing (an empty cell).
Cell = str | float | int | bool | None


def csv_cell(value: Cell) -> str:
    """The text of one cell: a number in its shortest round-trip form, a boolean as
    ``true`` or ``false``, None as an empty cell, and text guarded against formulas.

    >>> [csv_cell(v) for v in ("=1+2", "-3 dB", -3.5, 2, True, None)]
    ["'=1+2", "'-3 dB", '-3.5', '2', 'true', '']
    """
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, Integral):
        return str(int(value))
    if isinstance(value, Real):
        return repr(float(value))
    return spreadsheet_text(value)


def write_csv_rows(stream: IO[str], rows: Iterable[Sequence[Cell]]) -> None:
    """Rows of cells (:func:`csv_cell`) as CSV lines (quoted as CSV needs) on ``stream``."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerows([csv_cell(value) for value in row] for row in rows)
    stream.write(buffer.getvalue())


def csv_text_field(text: str) -> str:
    """A text cell as one CSV field, for lines built without the csv module: guarded as
    :func:`csv_cell` guards it, then quoted (its quotes doubled) where CSV needs it."""
    shown = spreadsheet_text(text)
    return '"' + shown.replace('"', '""') + '"' if any(c in shown for c in ',"\n\r') else shown
