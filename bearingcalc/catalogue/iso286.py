"""ISO 286 limits and fits: the limit deviations of a shaft or housing seat of a tolerance
class (``k5``, ``js6``, ``H7``, ``JS7``, ``P7``) at a nominal diameter, from the tables
shipped with bearingcalc.

- ``data/iso286_grades.csv``: the standard tolerance grades IT3 to IT12 (ISO 286-1:2010
  Table 1);
- ``data/iso286_deviations.csv``: the fundamental deviations of the shaft letters
  f g h j k m n p r (Table 2) and the hole letters F G H J K M N P (Table 3), and Δ for
  grades 4 to 8 (Table 3).

A class is a letter and a grade; lower case is a shaft (external feature), upper case a
hole (internal feature), as ISO 286-1 writes them. Grades 4 to 8 are held, and of them
only what ISO 286-1 defines: j5, j6, j7 (j8 only up to 3 mm) and J6, J7, J8.

Nominal sizes: ISO 286's ranges run "over a up to and including b", so a size on a
boundary belongs to the range it ends (30 mm takes the 18 to 30 mm values). The lookup
takes 3 mm to 500 mm. A size of exactly 3 mm belongs to the standard's "up to and
including 3 mm" range, which both tables keep for that one size; below 3 mm is refused.
Sizes are compared after rounding to 1 nm, so that 0.03 m given in floating point lands
where 30 mm does.

js and JS are ±IT/2 unrounded (js7 over 18 up to 30 mm is ±10.5 µm), as ISO 286-2:2010
(in its adoption GB/T 1800.2-2020) and the SKF and NSK catalogues tabulate them: ISO
286-1:1988 Table 2 only permitted ("may") rounding an odd IT7 to IT11 down to the even
value below, and tables that took it (Koyo CAT. No. 203E-1, 1997: js7 ±10 µm) differ by
0.5 µm.
"""

from __future__ import annotations

import functools
import re

from bearingcalc.catalogue.standard_tables import UM_PER_M, note, records, size_mm

GRADES_TABLE = "iso286_grades.csv"
DEVIATIONS_TABLE = "iso286_deviations.csv"

#: The nominal sizes the lookup takes [mm].
SMALLEST_MM = 3.0
LARGEST_MM = 500.0

SHAFT_LETTERS: tuple[str, ...] = ("f", "g", "h", "j", "js", "k", "m", "n", "p", "r")
HOLE_LETTERS: tuple[str, ...] = ("F", "G", "H", "J", "JS", "K", "M", "N", "P")
#: The grades each letter has in the tables (j8 further only up to 3 mm).
_GRADES: dict[str, tuple[int, ...]] = {
    **{letter: (4, 5, 6, 7, 8) for letter in SHAFT_LETTERS + HOLE_LETTERS},
    "j": (5, 6, 7, 8), "J": (6, 7, 8),
}
_CLASS = re.compile(r"([A-Za-z]{1,2})(\d{1,2})")

Row = tuple[float, float, dict[str, float | None]]


def is_hole(tolerance_class: str) -> bool:
    """True for a hole's class (upper case, ``H7``), False for a shaft's (``k5``).

    Raises ValueError for a class the tables do not hold (as :func:`limit_deviations`)."""
    letter, _ = _parse(tolerance_class)
    return letter.isupper()


def standard_tolerance(grade: int, nominal_diameter: float) -> float:
    """The standard tolerance ITn [m] of grade ``grade`` (3 to 12) at a nominal size.

    Parameters
    ----------
    grade : int
        The standard tolerance grade n of ITn, 3 to 12.
    nominal_diameter : float
        The nominal size D [m], 0.003 to 0.5.

    Returns
    -------
    float
        ITn [m], ISO 286-1:2010 Table 1. The table derives from the tolerance unit
        i = 0.45·∛D + 0.001·D [µm], D [mm] the geometric mean of the range, times the
        grade's factor (7, 10, 16, 25, 40, 64, 100, 160 for IT5 to IT12) and rounded; the
        table, not the formula, is authoritative.
    """
    if not (isinstance(grade, int) and 3 <= grade <= 12):
        raise ValueError(f"Standard tolerance grade {grade!r} is outside the table, which "
                         "holds IT3 to IT12.")
    size = _size_mm(nominal_diameter)
    return _cell(_row(_grades(), size)[2], f"IT{grade}") / UM_PER_M


def limit_deviations(tolerance_class: str, nominal_diameter: float) -> tuple[float, float]:
    """The (lower, upper) limit deviations [m] of a seat of ``tolerance_class``.

    Parameters
    ----------
    tolerance_class : str
        A letter and a grade, ``k5``, ``js6``, ``H7``, ``JS7``: lower case a shaft, upper
        case a hole; letters f g h j js k m n p r and F G H J JS K M N P, grades 4 to 8
        (j 5 to 7, and 8 up to 3 mm; J 6 to 8).
    nominal_diameter : float
        The nominal size D [m], 0.003 to 0.5.

    Returns
    -------
    tuple of float
        (lower, upper) [m]: a shaft's ei, es, a hole's EI, ES, the seat's size limits
        minus D. One of them is the letter's fundamental deviation (ISO 286-1:2010 Tables
        2 and 3), the other follows with the grade's ITn (Table 1):

        - shafts: ei = es − ITn (f g h, es tabulated); es = ei + ITn (j k m n p r, ei
          tabulated; k's ei applies to grades 4 to 7, 0 otherwise; j's by grade);
        - holes: ES = EI + ITn (F G H, EI tabulated); EI = ES − ITn with ES tabulated (J,
          by grade), ES = −x + Δ (K M N, grades up to 8), ES = −x + Δ up to grade 7 and −x
          above (P), Δ = ITn − IT(n−1) as Table 3 lists it; M6 over 250 up to 315 mm has
          ES = −9 µm, the special case of Table 3;
        - js and JS: ±ITn/2 (Tables 2 and 3), unrounded as ISO 286-2:2010 tabulates them.

    Raises
    ------
    ValueError
        For an unknown letter, a grade the letter does not have, or a nominal size outside
        3 mm to 500 mm, in one sentence naming what would be right.
    """
    letter, grade = _parse(tolerance_class)
    size = _size_mm(nominal_diameter)
    if letter == "j" and grade == 8 and size > SMALLEST_MM:
        raise ValueError(f"Tolerance class {tolerance_class!r} exists only up to 3 mm, not "
                         f"at {size:.10g} mm: ISO 286-1 gives j5, j6 and j7 above 3 mm "
                         "(or use js8).")
    it = _cell(_row(_grades(), size)[2], f"IT{grade}")
    lower, upper = _limits_um(letter, grade, size, it, _row(_deviations(), size)[2])
    return lower / UM_PER_M, upper / UM_PER_M


def _limits_um(letter: str, grade: int, size: float, it: float,
               row: dict[str, float | None]) -> tuple[float, float]:
    """(lower, upper) [µm] of ``letter`` in grade ``grade`` with ITn = ``it`` [µm], from
    the deviation row of nominal size ``size`` [mm]."""
    if letter in ("js", "JS"):
        return -it / 2.0, it / 2.0
    if letter in ("f", "g", "h"):
        upper = _cell(row, f"es_{letter}")
        return upper - it, upper
    if letter in ("F", "G", "H"):
        lower = _cell(row, f"EI_{letter}")
        return lower, lower + it
    if letter in ("j", "k", "m", "n", "p", "r"):
        lower = _shaft_lower(letter, grade, row)
        return lower, lower + it
    upper = _hole_upper(letter, grade, size, row)
    return upper - it, upper


def _shaft_lower(letter: str, grade: int, row: dict[str, float | None]) -> float:
    """ei [µm] of the shaft letters j k m n p r (ISO 286-1:2010 Table 2)."""
    if letter == "j":
        return _cell(row, {5: "ei_j5_j6", 6: "ei_j5_j6", 7: "ei_j7", 8: "ei_j8"}[grade])
    if letter == "k":
        # Table 2 gives k its deviation in grades 4 to 7 only; any other grade sits on zero.
        return _cell(row, "ei_k") if 4 <= grade <= 7 else 0.0
    return _cell(row, f"ei_{letter}")


def _hole_upper(letter: str, grade: int, size: float, row: dict[str, float | None]) -> float:
    """ES [µm] of the hole letters J K M N P (ISO 286-1:2010 Table 3)."""
    if letter == "J":
        return _cell(row, f"ES_J{grade}")
    if letter == "M" and grade == 6 and 250.0 < size <= 315.0:
        return -9.0  # Table 3's special case, in place of -20 + Δ6 = -11 µm
    base = _cell(row, f"ES_{letter}")
    # Δ raises K, M and N up to grade 8 and P up to grade 7 (Table 3, grades held: 4 to 8).
    if letter == "P" and grade > 7:
        return base
    return base + _cell(row, f"delta_{grade}")


def _cell(row: dict[str, float | None], column: str) -> float:
    """A table cell [µm]; an empty one is a value the standard does not define there."""
    value = row[column]
    if value is None:
        raise ValueError(f"Column {column} of the ISO 286 tables is empty in this range.")
    return value


def _parse(tolerance_class: str) -> tuple[str, int]:
    """(letter, grade) of a class such as ``k5`` or ``JS7``; ValueError otherwise."""
    match = _CLASS.fullmatch(tolerance_class.strip()) if isinstance(tolerance_class, str) \
        else None
    if match is None:
        raise ValueError(f"Tolerance class {tolerance_class!r} is not a fundamental-deviation "
                         "letter followed by a grade number, such as k5, js6, H7 or JS7.")
    letter, grade = match.group(1), int(match.group(2))
    if letter not in _GRADES:
        raise ValueError(
            f"Tolerance class {tolerance_class!r} has letter {letter!r}, which the ISO 286 "
            f"tables do not hold: shafts take {', '.join(SHAFT_LETTERS)} (lower case) and "
            f"holes {', '.join(HOLE_LETTERS)} (upper case).")
    if grade not in _GRADES[letter]:
        grades = _GRADES[letter]
        extra = " (j8 only up to 3 mm)" if letter == "j" else ""
        raise ValueError(f"Tolerance class {tolerance_class!r} has grade {grade}, which "
                         f"{letter} does not have in the ISO 286 tables: {letter} exists in "
                         f"grades {grades[0]} to {grades[-1]}{extra}.")
    return letter, grade


def _size_mm(nominal_diameter: float) -> float:
    """The nominal size [mm], rounded to 1 nm; ValueError outside 3 mm to 500 mm."""
    size = size_mm("nominal diameter", nominal_diameter)
    if not SMALLEST_MM <= size <= LARGEST_MM:
        raise ValueError(f"Nominal diameter {size:.10g} mm is outside the ISO 286 tables shipped "
                         "with bearingcalc, which cover 3 mm to 500 mm.")
    return size


def _row(rows: tuple[Row, ...], size: float) -> Row:
    """The row whose range 'over a up to and including b' holds ``size`` [mm]."""
    for row in rows:
        if row[0] < size <= row[1]:
            return row
    raise ValueError(f"No row of the ISO 286 tables holds {size:.10g} mm.")


def _grades() -> tuple[Row, ...]:
    note(GRADES_TABLE, "ISO 286 table")
    return _read(GRADES_TABLE)


def _deviations() -> tuple[Row, ...]:
    note(DEVIATIONS_TABLE, "ISO 286 table")
    return _read(DEVIATIONS_TABLE)


@functools.cache
def _read(table: str) -> tuple[Row, ...]:
    """A table's rows: (over [mm], up to [mm], column -> value [µm] or None where empty)."""
    rows: list[Row] = []
    for record in records(table):
        over, up_to = float(record.pop("over_mm")), float(record.pop("up_to_mm"))
        rows.append((over, up_to, {name: float(cell) if cell.strip() else None
                                   for name, cell in record.items()}))
    return tuple(rows)
