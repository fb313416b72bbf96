"""Which catalogue rows fit a bearing position: its shaft, the envelope, and the types
and series allowed (``select``'s options and the spec's own bounds)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from bearingcalc.catalogue.catalogue import Catalogue, CatalogueRow
from bearingcalc.catalogue.designation import normal_form
from bearingcalc.catalogue.reader import ROW_TYPES
from bearingcalc.core.bearing_types import traits, type_name
from bearingcalc.errors import OptionError, SpecError
from bearingcalc.models.field_path import FieldPath
from bearingcalc.models.yaml_loader import Document
from bearingcalc.units import LENGTH, UnitError, parse_quantity, to_display
from bearingcalc.wording import did_you_mean

#: How far a row's bore may be from the shaft, or its size beyond the envelope: a
#: hundredth of a millimetre (a catalogue in inches to four decimals is within it). [m]
SHAFT_TOLERANCE = 1e-5


@dataclass(frozen=True)
class Envelope:
    """What the caller allows: types, series, and the largest outside diameter and
    width [m] (None: the spec's, or no bound)."""

    types: tuple[str, ...] = ()
    series: tuple[str, ...] = ()
    max_outside_diameter: float | None = None
    max_width: float | None = None


def envelope_from_options(types: Sequence[str], series: Sequence[str],
                          max_outside_diameter: str | None, max_width: str | None
                          ) -> Envelope:
    """The envelope of ``select``'s options; an OptionError naming the option at fault."""
    for name in types:
        if type_name(name) not in ROW_TYPES:
            raise OptionError("--type", f"{name!r}: not a bearing type"
                              f"{did_you_mean(name, ROW_TYPES)}; one of {', '.join(ROW_TYPES)}")
    bounds = []
    for option, text in (("--max-outside-diameter", max_outside_diameter),
                         ("--max-width", max_width)):
        try:
            value = None if text is None else parse_quantity(text, LENGTH)
        except UnitError as error:
            raise OptionError(option, str(error)) from None
        if value is not None and not value > 0:
            raise OptionError(option, f"{text!r} must be greater than zero, like '62 mm'")
        bounds.append(value)
    return Envelope(tuple(types), tuple(s.strip() for s in series), bounds[0], bounds[1])


def bearing_at(data: dict[str, Any], position: str) -> dict[str, Any]:
    found = FieldPath.parse(position).get(data) if position else data
    return found if isinstance(found, dict) else {}


def _length(document: Document, bearing: dict[str, Any], position: str, name: str
            ) -> float | None:
    text = bearing.get(name)
    if text is None:
        return None
    where = f"{position}.{name}" if position else name
    try:
        value = parse_quantity(text, LENGTH)
    except UnitError as error:
        raise document.error(str(error), field=where) from None
    if not value > 0:
        raise document.error("must be greater than zero", field=where)
    return value


def _shown(value: float) -> str:
    number, unit = to_display(value, "m")
    return f"{number:g} {unit}"


def fitting_rows(document: Document, catalogue: Catalogue, envelope: Envelope,
                 position: str) -> list[CatalogueRow]:
    """The rows that fit the position's shaft and envelope; a SpecError naming the
    limit that excluded the last of them."""
    bearing = bearing_at(document.data, position)
    prefix = f"{position}." if position else ""
    bore = _length(document, bearing, position, "bore_diameter")
    if bore is None and bearing.get("designation") is not None:  # the given bearing's shaft
        maker = bearing.get("maker")
        try:
            bore = catalogue.find(bearing["designation"], maker if isinstance(maker, str)
                                  else None).values["bore_diameter"]
        except LookupError as problem:
            raise document.error(str(problem), field=f"{prefix}designation") from None
    if bore is None:
        raise document.error("select needs the shaft: give the bearing's bore_diameter, "
                             "like 25 mm", field=f"{prefix}bore_diameter",
                             key_path=FieldPath.parse(position).parts if position else ())
    given_outside = _length(document, bearing, position, "outside_diameter")
    given_width = _length(document, bearing, position, "width")
    outside = _smaller(given_outside, envelope.max_outside_diameter)
    width = _smaller(given_width, envelope.max_width)
    given_type = bearing.get("type")
    types = tuple(type_name(name) for name in (
        envelope.types or ((given_type,) if isinstance(given_type, str) else ())))
    # (words, the spec's field or the option that set the bound, which rows it keeps)
    steps: list[tuple[str, str, Any]] = [
        (f"of the types {', '.join(types)}" if types else "",
         "--type" if envelope.types else f"{prefix}type",
         lambda row: not types or row.type in types),
        ("that a drive's shaft can take (no thrust bearings)" if position else "", "",
         lambda row: not position or not traits(row.type).thrust),
        (f"of the series {', '.join(envelope.series)}" if envelope.series else "",
         "--series", lambda row: not envelope.series or _in_series(row, envelope.series)),
        (f"with the bore {_shown(bore)}",
         f"{prefix}bore_diameter" if "bore_diameter" in bearing else f"{prefix}designation",
         lambda row: abs(row.values["bore_diameter"] - bore) <= SHAFT_TOLERANCE),
        (f"with an outside diameter of at most {_shown(outside)}" if outside else "",
         f"{prefix}outside_diameter" if outside == given_outside else
         "--max-outside-diameter",
         lambda row: outside is None or row.values["outside_diameter"] <= outside
         + SHAFT_TOLERANCE),
        (f"with a width of at most {_shown(width)}" if width else "",
         f"{prefix}width" if width == given_width else "--max-width",
         lambda row: width is None or row.values["width"] <= width + SHAFT_TOLERANCE),
    ]
    rows = catalogue.rows
    said = []
    for words, source, keep in steps:
        rows = [row for row in rows if keep(row)]
        if words:
            said.append(words)
        if not rows:
            message = (f"no bearing of the catalogue {catalogue.path} fits "
                       f"{position or 'the bearing'}: none {said[-1]}"
                       + (f" among those {', '.join(said[:-1])}" if len(said) > 1 else ""))
            if source.startswith("--") or not source:
                raise SpecError(f"{source}: {message}" if source else message,
                                source=document.source)
            raise document.error(message, field=source)
    return rows


def _smaller(first: float | None, second: float | None) -> float | None:
    given = [value for value in (first, second) if value is not None]
    return min(given) if given else None


def _in_series(row: CatalogueRow, series: Sequence[str]) -> bool:
    """Whether a row's basic designation begins with one of ``series`` (``62``, ``NJ22``,
    ``302``); ``NU22`` takes the NU series' N, NJ, NUP and NF forms too."""
    if row.parsed is None:
        return False
    own, filed = row.parsed.basic[:-2].upper(), row.parsed.iso_key[:-2].upper()
    return any(normal_form(name).upper() in (own, filed) for name in series)
