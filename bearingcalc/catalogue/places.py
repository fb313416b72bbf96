"""What every spec asks of the catalogue, answered without reading one: where its
bearings sit, whether any names a designation, and which catalogue a spec that names
none takes."""

from __future__ import annotations

import os
from collections.abc import Iterator
from typing import Any

#: The environment variable that names a default catalogue.
CATALOGUE_VARIABLE = "BEARINGCALC_CATALOGUE"

_default: list[str | None] = [None]


def set_default_catalogue(path: str | None) -> None:
    """The catalogue of specs that name none (a command's ``--catalogue``); None for the
    environment's (``BEARINGCALC_CATALOGUE``)."""
    _default[0] = path


def default_catalogue() -> str | None:
    return _default[0] or os.environ.get(CATALOGUE_VARIABLE) or None


def spec_bearings(data: dict[str, Any], places: tuple[str, ...]) -> Iterator[tuple[str, Any]]:
    """(place, bearing) of each bearing at ``places``: ``''`` for the spec itself, and
    ``'pinion_bearings.1'`` for each item of the list ``pinion_bearings``."""
    for place in places:
        if not place:
            yield "", data
            continue
        items = data.get(place)
        if isinstance(items, list):
            for i, item in enumerate(items, 1):
                yield f"{place}.{i}", item


def names_a_designation(data: dict[str, Any], places: tuple[str, ...]) -> bool:
    """Whether any bearing at ``places`` is given by its catalogue designation."""
    return any(isinstance(bearing, dict) and "designation" in bearing
               for _, bearing in spec_bearings(data, places))
