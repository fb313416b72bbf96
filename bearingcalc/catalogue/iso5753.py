"""ISO 5753-1 radial internal clearance: the (min, max) radial clearance of an unmounted
bearing of a clearance group at zero measuring load, by nominal bore diameter, from the
table shipped with bearingcalc (``data/iso5753_clearance.csv``).

What the table holds, and where from (every row is checked against two other sources,
entered apart, in tests/test_iso5753.py):

- ``"radial-ball"``, radial ball bearings with cylindrical bore, groups C2, CN, C3, C4, C5:
  SKF, General Catalogue (Russian edition, after ISO 5753:1991), Table 4, p. 297, bores over
  2.5 mm up to 200 mm; C4 and C5 start over 6 mm. Checked against KOYO CAT. NO. 203E-1,
  Table 2-1, p. A11, and NSK CAT. No. E1102e, Table 9.9, p. A89.
- ``"cylindrical"``, cylindrical roller bearings with cylindrical bore (a needle
  roller bearing with machined rings takes the same): NSK CAT. No. E1102e, Table 9.14,
  p. A91, up to 200 mm. Interchangeable rings: groups C2, CN, C3, C4, C5 (C5 over 10 mm),
  checked against SKF's Table 1, p. 513, and KOYO CAT. NO. 203E-1 Table 2-7 (1), p. A16.
  Non-interchangeable (matched) rings: NSK's CC1, CC2, CC, CC3, CC4, CC5, named here C1NA,
  C2NA, CNA, C3NA, C4NA, C5NA after DAS LAGER's and KOYO's names (DAS LAGER calls the
  normal one NA), bores over 10 mm,
  checked against DAS LAGER's General Technical Catalog, Table 3, p. 358, and GOST
  24810-2013 Table 7.

Where the sources differ, and what is taken:

- Deep-groove bearings of bore 2.5 to 6 mm: NSK's first row runs up to 10 mm with C4 14-29
  µm and C5 20-37 µm, and KOYO prints the same in italics, 'based on the Koyo standards';
  SKF, after the standard, gives no C4 or C5 there, and neither does this table.
- Deep-groove bearings above 200 mm: the sources part (CN over 200 up to 225 mm: SKF 28-82
  µm, NSK and KOYO 25-85 µm, GOST 24810-2013, after ISO 5753-1:2009, 30-80 µm); the table
  stops at 200 mm. KINEX and ZVL print C5 150-215 µm over 180 up to 200 mm where SKF, NSK,
  KOYO and GOST 24810 print 150-230 µm; 150-230 µm is taken.
- Cylindrical roller bearings, interchangeable, up to 10 mm: SKF prints one row up to 24 mm
  with C5 65-90 µm; NSK and KOYO split it at 10 mm and give no C5 up to 10 mm; NSK's rows
  are taken. Above 200 mm SKF, NSK and KOYO agree up to 500 mm, but one limit is kept for
  both kinds. GOST 24810-2013 Table 6 has groups of its own (1, 6, 2, 3, 4) and other values,
  and is not used.
- Cylindrical roller bearings, non-interchangeable, over 10 up to 24 mm: NSK prints one row
  (C1NA 5-15 µm, C5NA 65-75 µm); DAS LAGER splits it at 14 mm with C1NA 0-10 µm and no C5NA
  below, GOST 24810 at 18 mm with C1NA 0-10 µm below; NSK's row is taken (from 24 mm up all
  three agree).

Bores: a row holds a nominal bore over its lower bound up to and including its upper bound,
compared after rounding to 1 nm. Above 200 mm, and where a group has no value, the lookup
refuses and asks for the bearing's ``initial_clearance`` instead.

Group names are upper-cased; ``"normal"`` is CN, and NSK's names of the matched groups
(``"CC1"`` to ``"CC5"``, ``"CC"``) and DAS LAGER's ``"NA"`` are taken for C1NA to C5NA and
CNA.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

from bearingcalc.catalogue.standard_tables import UM_PER_M, note, records, size_mm

TABLE = "iso5753_clearance.csv"

#: The largest bore the table holds [mm]: above it the makers' tables disagree.
LARGEST_MM = 200.0

#: The clearance groups of each bearing kind, smallest clearance first.
GROUPS: dict[str, tuple[str, ...]] = {
    "radial-ball": ("C2", "CN", "C3", "C4", "C5"),
    "cylindrical": ("C2", "CN", "C3", "C4", "C5",
                           "C1NA", "C2NA", "CNA", "C3NA", "C4NA", "C5NA"),
}
#: Other names of the groups (upper case) -> the table's.
_ALIASES: dict[str, str] = {
    "NORMAL": "CN", "NA": "CNA", "CC": "CNA", "CC1": "C1NA", "CC2": "C2NA", "CC3": "C3NA",
    "CC4": "C4NA", "CC5": "C5NA"}


class Row(NamedTuple):
    """One row of the table: a range of nominal bores [mm] and its clearance [µm]."""

    over: float
    up_to: float
    low: float
    high: float


def radial_clearance(bore_diameter: float, group: str, *,
                     bearing_kind: str) -> tuple[float, float]:
    """The (min, max) radial internal clearance [m] of an unmounted bearing of a clearance
    group, at zero measuring load.

    Parameters
    ----------
    bore_diameter : float
        The nominal bore diameter d [m], up to 0.2.
    group : str
        The clearance group: C2, CN (``"normal"``), C3, C4, C5; of a cylindrical roller
        bearing with non-interchangeable rings C1NA, C2NA, CNA, C3NA, C4NA, C5NA (NSK's
        CC1 to CC5 and CC).
    bearing_kind : str
        ``"radial-ball"`` or ``"cylindrical"``.

    Returns
    -------
    tuple of float
        (min, max) [m]: ISO 5753-1's radial internal clearance of the group (here SKF's
        Table 4 for deep-groove bearings, NSK E1102e Table 9.14 for cylindrical roller
        bearings).

    Raises
    ------
    ValueError
        For a bearing kind the table does not hold, a group the kind does not have, a bore
        above 200 mm or one where the group has no value, in one sentence naming what would
        be right (above 200 mm: give initial_clearance).
    """
    groups = GROUPS.get(bearing_kind) if isinstance(bearing_kind, str) else None
    if groups is None:
        raise ValueError(f"ISO 5753-1 clearances are shipped for radial-ball and "
                         f"cylindrical bearings, not for {bearing_kind!r}: give the "
                         "bearing's initial_clearance.")
    name = _group_name(group, bearing_kind, groups)
    size = size_mm("bore diameter", bore_diameter)
    if size > LARGEST_MM:
        raise ValueError(f"Bore diameter {size:.10g} mm is above {LARGEST_MM:g} mm, where "
                         "the makers' clearance tables disagree: give initial_clearance.")
    rows = _rows()[(bearing_kind, name)]
    row = next((row for row in rows if row.over < size <= row.up_to), None)
    if row is None:
        raise ValueError(f"ISO 5753-1 gives {name} of {bearing_kind} bearings for bores over "
                         f"{rows[0].over:g} mm up to {rows[-1].up_to:g} mm, not {size:.10g} mm: "
                         "give initial_clearance.")
    return row.low / UM_PER_M, row.high / UM_PER_M


def _group_name(group: str, kind: str, groups: tuple[str, ...]) -> str:
    """The table's name of ``group`` for a bearing of ``kind``; ValueError for a group the
    kind does not have."""
    name = group.strip().upper() if isinstance(group, str) else ""
    name = _ALIASES.get(name, name)
    if name not in groups:
        listed = ", ".join(groups[:5])
        if len(groups) > 5:
            listed += (", or, with non-interchangeable rings, " + ", ".join(groups[5:]))
        raise ValueError(f"Clearance group {group!r} is not one of {kind} bearings in ISO "
                         f"5753-1: give {listed}.")
    return name


def _rows() -> dict[tuple[str, str], tuple[Row, ...]]:
    """The table's rows by (bearing kind, group), each in order of bore."""
    note(TABLE, "ISO 5753 table")
    return _read()


@functools.cache
def _read() -> dict[tuple[str, str], tuple[Row, ...]]:
    grouped: dict[tuple[str, str], list[Row]] = {}
    for record in records(TABLE):
        grouped.setdefault((record["bearing_kind"], record["group"]), []).append(
            Row(float(record["over_mm"]), float(record["up_to_mm"]),
                float(record["min_um"]), float(record["max_um"])))
    return {key: tuple(sorted(rows)) for key, rows in grouped.items()}
