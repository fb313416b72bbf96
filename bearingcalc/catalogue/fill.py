"""A spec's bearings filled from their catalogue rows, before the spec is validated.

A bearing with a ``designation`` takes from its catalogue row every rating and dimension
the spec does not give, written as the catalogue writes it (``'14.8 kN'``), so that the
spec reads exactly as if it had been typed. A value the spec gives wins, and a note says
so where it differs from the catalogue's. ``catalogue`` in a field's text stands for the
catalogue's value: ``dynamic_load_rating: catalogue ± 5 %`` studies the spread between
makers.
"""

from __future__ import annotations

import copy
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from bearingcalc.catalogue.catalogue import (
    Catalogue,
    CatalogueRow,
    load_catalogue,
    normal_designation,
)
from bearingcalc.catalogue.columns import COLUMNS
from bearingcalc.catalogue.places import (
    CATALOGUE_VARIABLE,
    default_catalogue,
    names_a_designation,
    spec_bearings,
)
from bearingcalc.core.bearing_types import traits, type_name
from bearingcalc.errors import SpecError
from bearingcalc.number_grammar import UNSIGNED_DECIMAL
from bearingcalc.units import DIMENSIONLESS, UnitError, parse_quantity

#: Load-factor columns -> the field of a bearing's ``load_factors``: single row, double.
FACTOR_FIELDS = {"e": ("e", "e"), "y1": (None, "y1"), "y2": ("y", "y2"), "y0": ("y0", "y0")}
#: ``catalogue`` as a field's whole value, or before a tolerance (``catalogue ± 5 %``):
#: never the word inside a longer value (a file ``catalogue.csv``, a name).
_WORD = re.compile(r"\s*catalogue\s*(?=$|±|\+/-|\+-)", re.IGNORECASE)
_PERCENT_TOLERANCE = re.compile(rf"^\s*(?:±|\+/-|\+-)\s*(?P<percent>{UNSIGNED_DECIMAL})\s*%\s*$")
#: A bearing's text fields, which the catalogue keyword never stands in for.
_TEXT_FIELDS = ("kind", "name", "catalogue", "designation", "maker")
#: Columns that fill a bearing field of the same level: column -> field.
_DIRECT = {name: column.field for name, column in COLUMNS.items()
           if column.field is not None and "." not in column.field}
#: Arrangements of two single-row bearings whose load factors are the pair's own.
PAIRS = ("back-to-back", "face-to-face")

@dataclass(frozen=True)
class FilledFrom:
    """Where the catalogue gave a spec's field: the bearing's designation field, the
    catalogue's file, its row and column."""

    designation: str
    path: str
    row: CatalogueRow
    column: str

    def said(self, message: str) -> str:
        """``message`` of the value, after the catalogue's file, line and column."""
        return f"{self.path}:{self.row.line}: {self.column}: {self.row.label}: {message}"


@dataclass
class CatalogueUse:
    """What the catalogue gave a spec: each bearing's row by its place (``''`` for a
    spec that is one bearing, ``pinion_bearings.1`` for a drive's), and the notes."""

    rows: dict[str, CatalogueRow] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    #: each field the catalogue filled (``pinion_bearings.1.dynamic_load_rating``) ->
    #: where it came from, for the message of a value the spec refuses
    filled: dict[str, FilledFrom] = field(default_factory=dict)

    def sources(self) -> dict[str, str]:
        """Result-style keys naming each row: ``catalogue_source``, or
        ``pinion_bearing_1_catalogue_source`` for a drive's bearing."""
        return {(_flat(place) + "_" if place else "") + "catalogue_source": row.cited
                for place, row in self.rows.items()}


def _flat(place: str) -> str:
    list_name, _, index = place.rpartition(".")
    return f"{list_name.removesuffix('s')}_{index}"


def fill(data: dict[str, Any], places: tuple[str, ...], spec_path: str,
         error: Any) -> tuple[dict[str, Any], CatalogueUse]:
    """``data`` with each bearing at ``places`` (``''``: the spec itself;
    ``'pinion_bearings'``: each item of that list) filled from its catalogue row.
    ``error(message, field)`` makes the SpecError of a field of the spec."""
    use = CatalogueUse()
    if not names_a_designation(data, places):
        return data, use
    data = copy.deepcopy(data)
    catalogue: Catalogue | None = None
    for place, bearing in spec_bearings(data, places):
        if not isinstance(bearing, dict) or "designation" not in bearing:
            continue
        prefix = f"{place}." if place else ""
        if catalogue is None:
            catalogue = spec_catalogue(data, spec_path, error, f"{prefix}designation")
            use.notes += catalogue.warnings
        designation = bearing["designation"]
        if isinstance(designation, bool) or not isinstance(designation, (str, int)) or (
                not str(designation).strip()):
            raise error("a designation is text, like '6205-2RS'", f"{prefix}designation")
        maker = bearing.get("maker")
        if maker is not None and (not isinstance(maker, str) or not maker.strip()):
            raise error("the maker is text, like maker: SKF", f"{prefix}maker")
        try:
            row = catalogue.find(designation, maker)
        except LookupError as problem:
            raise error(str(problem), f"{prefix}designation") from None
        if normal_designation(row.designation) != normal_designation(designation):
            use.notes.append(f"{prefix}designation: {str(designation).strip()} is taken as the "
                             f"catalogue's {row.designation} ({row.maker}), the same basic "
                             "designation: suffixes do not look a bearing up, so check that "
                             "it is the variant meant")
        _fill_bearing(bearing, row, prefix, use, error, catalogue.path)
        use.rows[place] = row
    return data, use


def spec_catalogue(data: dict[str, Any], spec_path: str, error: Any, at: str | None,
                   needed_for: str = "a designation") -> Catalogue:
    """The catalogue of a spec: its ``catalogue`` (relative to the spec), else the
    command's ``--catalogue`` or ``BEARINGCALC_CATALOGUE``. ``error(message, field)``
    makes the spec's SpecError: at ``catalogue`` where the spec names one, else at
    ``at``; a problem of the catalogue's file keeps its own file and line after it."""
    named = data.get("catalogue")
    if named is not None:
        if not isinstance(named, str) or not named.strip():
            raise error("write the catalogue's path, like catalogue: bearings.csv (relative "
                        "to the spec)", "catalogue")
        path = Path(spec_path).parent / named.strip()
    else:
        default = default_catalogue()
        if default is None:
            raise error(f"{needed_for} needs a catalogue: give catalogue: bearings.csv "
                        "(relative to the spec), --catalogue FILE, or the environment "
                        f"variable {CATALOGUE_VARIABLE}", at)
        path = Path(default)
    try:
        return load_catalogue(path)
    except SpecError as problem:
        raise error(str(problem), "catalogue" if named is not None else at) from None


def row_fields(row: CatalogueRow, arrangement: str = "single", rows: int | None = None
               ) -> dict[str, tuple[str, float]]:
    """The bearing fields a catalogue row gives (dotted within the bearing), each with
    the column it comes from and its SI value, for a bearing of ``arrangement`` and
    ``rows`` (see :func:`written_fields` for the text a spec takes).

    A roller bearing's e, Y and Y0 become its ``load_factors`` in its form (a single
    row's Y is the row's y2, the Y above e); a pair's are ISO 281's for its contact
    angle, not one bearing's. Where the row gives e but no contact angle, a tapered or
    spherical roller bearing's follows from ISO 281's e = 1.5·tanα (column ``e``).
    """
    values = row.values
    fields = {_DIRECT[name]: (name, value) for name, value in values.items()
              if name in _DIRECT}
    kind = traits(row.type)
    if not kind.catalogue_factors or "e" not in values:
        return fields
    if "contact_angle" not in fields and kind.inclined:
        fields["contact_angle"] = ("e", math.atan(values["e"] / 1.5))
    if arrangement in PAIRS:
        return fields
    double = (kind.family == "ball" and kind.double_row_form) or (
        rows if rows is not None else row_count(row)) == 2
    for column, targets in FACTOR_FIELDS.items():
        if column in values and targets[double] is not None:
            fields[f"load_factors.{targets[double]}"] = (column, values[column])
    return fields


def row_count(row: CatalogueRow) -> int:
    """The rows of rollers of a row's bearing: 2 for a spherical roller bearing, or where
    the row gives y1 (a double row's Y for Fa/Fr <= e), else 1."""
    kind = traits(row.type)
    # of two rows by its form (ISO 281 rates it as double row), or a roller bearing whose
    # row gives y1 (Y for Fa/Fr <= e), a double row's
    double = kind.family == "roller" and (kind.double_row_form or "y1" in row.values)
    return 2 if double else 1


def written_fields(row: CatalogueRow, arrangement: str = "single", rows: int | None = None
                   ) -> dict[str, tuple[str, str | float]]:
    """:func:`row_fields` as a spec writes them: the catalogue's text with its column's
    unit (``'14.8 kN'``), a derived contact angle in radians."""
    written = row.written
    return {target: (column, f"{value!r} rad" if target == "contact_angle" and column == "e"
                     else written[column])
            for target, (column, value) in row_fields(row, arrangement, rows).items()}


def _fill_bearing(bearing: dict[str, Any], row: CatalogueRow, prefix: str, use: CatalogueUse,
                  error: Any, path: str) -> None:
    given_type = bearing.get("type")
    if given_type is not None and type_name(given_type) != row.type:
        raise error(f"the catalogue's {row.label} is {row.type}, not {given_type}: leave type "
                    "out, or choose another designation", f"{prefix}type")
    bearing["type"] = row.type
    if row_count(row) == 2 and "rows" not in bearing:
        bearing["rows"] = 2
    arrangement = bearing.get("arrangement", "single")
    fields = written_fields(
        row, arrangement if isinstance(arrangement, str) else "single",
        bearing.get("rows") if isinstance(bearing.get("rows"), int) else None)
    factors_given = "load_factors" in bearing
    for target, (column, written) in fields.items():
        source = FilledFrom(f"{prefix}designation", path, row, column)
        if target.startswith("load_factors."):
            if not factors_given:
                bearing.setdefault("load_factors", {})[target.split(".")[1]] = written
                use.filled[f"{prefix}{target}"] = source
            continue
        if bearing.get(target) is None:
            use.filled[f"{prefix}{target}"] = source
        _put(bearing, target, written, row, None if column == "e" else column, prefix, use)
    if arrangement in PAIRS and "e" in row.values and traits(row.type).family == "roller" and (
            not factors_given):
        use.notes.append(f"{prefix or 'the bearing'}: a pair's load factors are ISO 281's "
                         f"for its contact angle, not {row.label}'s own e and Y (a single "
                         "bearing's)")
    for name, value in bearing.items():
        if name not in _TEXT_FIELDS and isinstance(value, str) and _WORD.match(value):
            raise error(f"the catalogue's {row.label} gives no {name}: write its value",
                        f"{prefix}{name}")


def _put(bearing: dict[str, Any], target: str, value: str | float, row: CatalogueRow,
         column: str | None, prefix: str, use: CatalogueUse) -> None:
    given = bearing.get(target)
    if given is None:
        bearing[target] = value
        return
    word = _WORD.match(given) if isinstance(given, str) else None
    if word is not None:
        bearing[target] = _with_tolerance(value, given[word.end():].strip())
        return
    if column is not None and _differs(given, row.values[column], column):
        use.notes.append(f"{prefix}{target}: the spec's {given} overrides the catalogue's "
                         f"{value} ({row.label})")


def _with_tolerance(value: str | float, tolerance: str) -> str:
    """The catalogue's value with the spec's tolerance: 'catalogue ± 5 %' is the value
    ± 5 % of it, in the catalogue's unit; 'catalogue ± 0.5 kN' as written."""
    percent = _PERCENT_TOLERANCE.match(tolerance)
    if percent is None:
        return f"{value}{tolerance}"
    number, _, unit = str(value).partition(" ")
    spread = abs(float(number)) * float(percent["percent"]) / 100.0
    return f"{number} {unit} ± {spread!r} {unit}".replace("  ", " ")


def _differs(given: Any, catalogue_value: float, column: str) -> bool:
    dimension = COLUMNS[column].dimension
    try:
        ours = (float(given) if dimension is DIMENSIONLESS
                else parse_quantity(given, dimension))  # type: ignore[arg-type]
    except (UnitError, ValueError, TypeError):
        return True  # the spec's own check says what is wrong with it
    return abs(ours - catalogue_value) > 1e-12 * max(abs(catalogue_value), 1e-300)
