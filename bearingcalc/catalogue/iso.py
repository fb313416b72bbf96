"""The ISO boundary dimensions shipped with bearingcalc (``data/iso_boundary_dimensions.csv``:
ISO 15 radial, ISO 355 tapered and ISO 104 thrust bearings of the common series, d 10
to 100 mm), by basic designation."""

from __future__ import annotations

import csv
import functools
import io
import os
from dataclasses import dataclass
from importlib import resources

from bearingcalc import reads
from bearingcalc.core.common import MM

TABLE = "iso_boundary_dimensions.csv"


@dataclass(frozen=True)
class IsoDimensions:
    """One designation's boundary dimensions [m]: width is B (radial), T (tapered) or
    H (thrust); r_min the chamfer r_s min, of a tapered roller bearing the cone's (the
    inner ring's, the makers' r); cup_r_min a tapered roller bearing's cup (outer ring)
    chamfer r_1s min (the makers' r1), None for every other type."""

    designation: str
    type: str
    bore_diameter: float
    outside_diameter: float
    width: float
    r_min: float | None
    iso355_series: str | None
    cup_r_min: float | None


def iso_table() -> dict[str, IsoDimensions]:
    """Basic designation -> its ISO boundary dimensions."""
    table = resources.files("bearingcalc.data").joinpath(TABLE)
    if isinstance(table, os.PathLike):  # a file of its own, not inside a zip archive
        reads.note(table, "ISO table")
    return _iso_table()


@functools.cache
def _iso_table() -> dict[str, IsoDimensions]:
    text = resources.files("bearingcalc.data").joinpath(TABLE).read_text("utf-8")
    lines = (line for line in io.StringIO(text) if not line.startswith("#"))
    table: dict[str, IsoDimensions] = {}
    for row in csv.DictReader(lines):
        table[row["designation"]] = IsoDimensions(
            row["designation"], row["type"], float(row["bore_diameter [mm]"]) / MM,
            float(row["outside_diameter [mm]"]) / MM, float(row["width [mm]"]) / MM,
            _optional_length(row["r_min [mm]"]), row["iso355_series"].strip() or None,
            _optional_length(row["cup_r_min [mm]"]))
    return table


def _optional_length(cell: str) -> float | None:
    """A cell in millimetres [m], None where it is empty."""
    return float(cell) / MM if cell.strip() else None


def iso_series() -> list[str]:
    """The series the table holds, as their designations begin (``62``, ``NU22``,
    ``302``), in the table's order."""
    seen: dict[str, None] = {}
    for designation in iso_table():
        seen.setdefault(designation[:-2], None)
    return list(seen)
