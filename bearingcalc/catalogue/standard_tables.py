"""What the standards' tables shipped with bearingcalc share (ISO 286, ISO 492, ISO 5753-1,
``data/iso*.csv``): reading a table's rows, noting the file it was read from, and a
nominal diameter as the tables' ranges take it."""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Iterator
from importlib import resources

from bearingcalc import reads

#: Metres -> millimetres (the tables' diameters) and -> micrometres (their deviations).
MM_PER_M, UM_PER_M = 1e3, 1e6


def note(table: str, what: str) -> None:
    """Note the shipped ``table`` as read by this run (its rows are read once and kept)."""
    path = resources.files("bearingcalc.data").joinpath(table)
    if isinstance(path, os.PathLike):  # a file of its own, not inside a zip archive
        reads.note(path, what)


def records(table: str) -> Iterator[dict[str, str]]:
    """Each row of the shipped ``table`` as column -> text, its comment lines left out."""
    text = resources.files("bearingcalc.data").joinpath(table).read_text("utf-8")
    return csv.DictReader(line for line in io.StringIO(text) if not line.startswith("#"))


def size_mm(what: str, diameter: float) -> float:
    """A nominal diameter [m] in millimetres, rounded to 1 nm; ValueError unless it is a
    positive finite number. The rounding keeps a diameter meant on a range boundary
    (0.05 m) from drifting past it by a floating-point ulp into the next range."""
    try:
        size = float(diameter) * MM_PER_M
    except (TypeError, ValueError):
        size = math.nan
    if not (math.isfinite(size) and size > 0.0):
        raise ValueError(f"The {what} must be a positive length in metres, not "
                         f"{diameter!r}.")
    return round(size, 6)
