"""ISO 492 tolerances of radial bearings: the deviation of the mean bore diameter in a single
plane, Δdmp, and of the mean outside diameter in a single plane, ΔDmp, of a tolerance class
at a nominal diameter, from the tables shipped with bearingcalc
(``data/iso492_bore.csv``, ``data/iso492_outside.csv``; upper deviation 0, lower negative).

What the tables hold, and where from (every row is checked against two other sources,
entered apart, in tests/test_iso492.py):

- radial bearings but tapered roller bearings, classes Normal, 6 and 5: NSK, *Rolling
  Bearings*, CAT. No. E1102e, Tables 8.2.1 and 8.2.2, pp. A60-A63; bores 0.6 mm to 2000 mm
  (Normal), 630 mm (6), 400 mm (5), outside diameters 2.5 mm to 2500 mm, 1000 mm, 800 mm;
  checked against SKF's General Catalogue (Russian edition), Tables 3 to 5, pp. 125-127, and
  GOST 520-2011 Tables 1 to 6;
- metric tapered roller bearings, classes Normal and 5: GOST 520-2011 (interstate standard
  harmonised with ISO 492:2002, marked NEQ: a document of its own that adds classes of its
  own, 0 and T), Tables 16, 17, 23 and 24; bores 10 mm to 500 mm (Normal)
  and 400 mm (5), outside diameters 18 mm to 1600 mm and 630 mm; checked against SKF's
  Tables 6 to 8, pp. 128-130, and FBJ's catalogue, Tables 3.4.1 and 3.4.2, p. 17. Class 6X
  has the Normal class's Δdmp and ΔDmp (GOST 520 6.3.4; SKF's CLN, its 6X, prints the same);
  ISO 492 has no class 6 for tapered roller bearings.

Where the sources differ, and what is taken:

- SKF prints classes 6 and 5 of radial bearings further (bores to 2000 mm, outside
  diameters to 2500 mm) than NSK and GOST 520, which stop where the tables stop: those rows
  rest on one maker and are left out, so class 5 refuses bores over 400 mm.
- GOST 520 Table 1 splits the Normal class's bores at 1200 mm (1000-1200, 1200-1600) where
  NSK and SKF split at 1250 mm: over 1200 up to 1250 mm it gives -160 µm, the makers -125 µm;
  the makers' value is taken.
- NSK's Table 8.3 for tapered roller bearings follows NSK's own standard (its remark 2):
  Normal Δdmp -8 µm for bores 10 to 18 mm where SKF, FBJ and GOST 520 print ISO 492's
  -12 µm, class 5 likewise; it is not used.
- Tapered roller bearings' Normal Δdmp over 500 up to 630 mm is -60 µm in GOST 520 and
  -50 µm in FBJ's and NSK's tables, so that table stops at 500 mm. GOST 520's rows that no
  maker's table here confirms, class 5 above 400 mm bore and 630 mm outside diameter and
  the Normal class above 1600 mm outside diameter, are left out.

Diameters: a row holds a nominal diameter over its lower bound up to and including its
upper bound, and each class's lowest row also holds its lower bound itself (NSK's notes:
0.6 mm and 2.5 mm are included in the group; GOST 520 gives tapered roller bearings of bore
up to 10 mm and outside diameter up to 18 mm the deviations of the next row). Sizes are
compared after rounding to 1 nm, so that 0.03 m given in floating point lands where 30 mm
does.

Class names: ``"normal"`` (also ``"PN"``, DIN 620's, and ``"P0"``, its older name), ``"6"``
(``"P6"``), ``"5"`` (``"P5"``) and, for tapered roller bearings, ``"6X"`` (``"P6X"``); case
is ignored. GOST's bare ``"0"`` is not taken: GOST 520's class 0 of tapered roller bearings
is a class of its own beside the Normal class.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

from bearingcalc.catalogue.standard_tables import UM_PER_M, note, records, size_mm

BORE_TABLE = "iso492_bore.csv"
OUTSIDE_TABLE = "iso492_outside.csv"


#: A class's name as written (lower case) -> its name in the tables.
_CLASS_NAMES: dict[str, str] = {
    "normal": "normal", "pn": "normal", "p0": "normal", "6": "6", "p6": "6", "5": "5",
    "p5": "5", "6x": "6X", "p6x": "6X"}
#: The classes each kind takes, as the messages list them.
_KIND_CLASSES = {"radial": "normal, 6 and 5", "tapered": "normal, 6X and 5"}


class Row(NamedTuple):
    """One row of a table: a range of nominal diameters [mm] and its deviations [µm]."""

    over: float
    up_to: float
    upper: float
    lower: float


def bore_deviation(bore_diameter: float, *, tolerance_class: str = "normal",
                   tapered: bool = False) -> tuple[float, float]:
    """The (lower, upper) deviation Δdmp [m] of a ring's mean bore diameter in a single
    plane from its nominal bore diameter.

    Parameters
    ----------
    bore_diameter : float
        The nominal bore diameter d [m].
    tolerance_class : str
        ``"normal"`` (``"PN"``, ``"P0"``), ``"6"`` (``"P6"``), ``"5"`` (``"P5"``), or
        ``"6X"`` (``"P6X"``) for a tapered roller bearing.
    tapered : bool
        True for a metric tapered roller bearing's cone (inner ring), False for any other
        radial bearing.

    Returns
    -------
    tuple of float
        (lower, upper) [m]: Δdmp's lower deviation (negative) and upper (0); ISO 492's
        Normal, 6 and 5 tables of the inner ring (here NSK E1102e Table 8.2.1 and GOST
        520-2011 Tables 16 and 23).

    Raises
    ------
    ValueError
        For a class the tables do not hold for the bearing, or a bore diameter outside the
        class's table, in one sentence naming what would be right.
    """
    return _deviation(BORE_TABLE, "bore diameter", bore_diameter, tolerance_class, tapered)


def outside_deviation(outside_diameter: float, *, tolerance_class: str = "normal",
                      tapered: bool = False) -> tuple[float, float]:
    """The (lower, upper) deviation ΔDmp [m] of a ring's mean outside diameter in a single
    plane from its nominal outside diameter.

    Parameters
    ----------
    outside_diameter : float
        The nominal outside diameter D [m].
    tolerance_class : str
        As :func:`bore_deviation`.
    tapered : bool
        True for a metric tapered roller bearing's cup (outer ring), False for any other
        radial bearing.

    Returns
    -------
    tuple of float
        (lower, upper) [m]: ΔDmp's lower deviation (negative) and upper (0); ISO 492's
        Normal, 6 and 5 tables of the outer ring (here NSK E1102e Table 8.2.2 and GOST
        520-2011 Tables 17 and 24). A ball bearing's shields or seals and a snap ring do not
        change ΔDmp, only the variations these tables leave out.

    Raises
    ------
    ValueError
        As :func:`bore_deviation`.
    """
    return _deviation(OUTSIDE_TABLE, "outside diameter", outside_diameter, tolerance_class,
                      tapered)


def _deviation(table: str, what: str, diameter: float, tolerance_class: str,
               tapered: bool) -> tuple[float, float]:
    """(lower, upper) [m] of ``table`` for ``diameter`` [m] in ``tolerance_class``."""
    kind = "tapered" if tapered else "radial"
    name = _class_name(tolerance_class, kind)
    rows = _rows(table)[(kind, name)]
    size = size_mm(what, diameter)
    row = _row(rows, size)
    if row is None:
        label = "tapered roller bearings" if tapered else "radial bearings"
        raise ValueError(
            f"{what.capitalize()} {size:.10g} mm is outside ISO 492's class "
            f"{tolerance_class.strip()} table of {label} shipped with bearingcalc, which "
            f"covers {rows[0].over:g} mm to {rows[-1].up_to:g} mm.")
    return row.lower / UM_PER_M, row.upper / UM_PER_M


def _class_name(tolerance_class: str, kind: str) -> str:
    """The tables' name of ``tolerance_class`` for a bearing of ``kind``; 6X is the Normal
    class's rows. ValueError for a class the kind does not have."""
    name = _CLASS_NAMES.get(tolerance_class.strip().lower()) \
        if isinstance(tolerance_class, str) else None
    if name is None:
        raise ValueError(f"Tolerance class {tolerance_class!r} is not in the ISO 492 tables "
                         "shipped with bearingcalc: give normal (or PN, P0), 6 (P6), 5 (P5), "
                         "or 6X (P6X) for a tapered roller bearing.")
    if name == "6X" and kind == "radial":
        raise ValueError(f"Tolerance class {tolerance_class!r} is ISO 492's class of tapered "
                         "roller bearings only: other radial bearings take normal, 6 and 5.")
    if name == "6" and kind == "tapered":
        raise ValueError(f"ISO 492 has no class {tolerance_class!r} for tapered roller "
                         f"bearings: they take {_KIND_CLASSES['tapered']}.")
    return "normal" if name == "6X" else name


def _row(rows: tuple[Row, ...], size: float) -> Row | None:
    """The row holding ``size`` [mm]: over its lower bound up to and including its upper,
    or the lowest row's lower bound itself; None outside the table."""
    if size == rows[0].over:
        return rows[0]
    return next((row for row in rows if row.over < size <= row.up_to), None)


def _rows(table: str) -> dict[tuple[str, str], tuple[Row, ...]]:
    """``table``'s rows by (bearing kind, class), each in order of diameter."""
    note(table, "ISO 492 table")
    return _read(table)


@functools.cache
def _read(table: str) -> dict[tuple[str, str], tuple[Row, ...]]:
    grouped: dict[tuple[str, str], list[Row]] = {}
    for record in records(table):
        grouped.setdefault((record["bearing_kind"], record["tolerance_class"]), []).append(
            Row(float(record["over_mm"]), float(record["up_to_mm"]),
                float(record["upper_um"]), float(record["lower_um"])))
    return {key: tuple(sorted(rows)) for key, rows in grouped.items()}
