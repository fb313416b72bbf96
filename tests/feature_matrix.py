"""Every combination of the bearing features, as specs: generated from the type table
(``BearingType``), the arrangements (``Arrangement``, ``ShaftArrangement``) and the kinds
of the registry that take bearings, so that a new type, arrangement or bearing kind
joins the matrix by itself (``tests/test_feature_matrix.py`` runs it).

A case's values come from what the type table (``bearingcalc.core.bearing_types``) says
of its type: a ball or roller bearing, radial or thrust, and the contact angle the type
takes by default, else a usual one for its family.
"""

from __future__ import annotations

import csv
import itertools
import zlib
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any, get_args

import yaml

from bearingcalc.core.bearing_types import traits
from bearingcalc.kinds import KINDS
from bearingcalc.models.bevel_drive import ShaftArrangement
from bearingcalc.models.rolling_bearing import Arrangement, BearingFields, BearingType

ROOT = Path(__file__).resolve().parent.parent
CATALOGUE = ROOT / "specs" / "catalogues" / "example.csv"

TYPES: tuple[str, ...] = get_args(BearingType)
ARRANGEMENTS: tuple[str, ...] = get_args(Arrangement)
SHAFT_ARRANGEMENTS: tuple[str, ...] = get_args(ShaftArrangement)
#: Where a bearing's ratings come from: the spec's numbers, its internal geometry, or a
#: row of the example catalogue (for the types it has rows of).
SOURCES = ("ratings", "geometry", "catalogue")
OPERATION = ("point", "cycle")
PAIRS = ("straight", "spiral")

#: A usual contact angle of a type that has no default, by family. [deg]
USUAL_ANGLE = {("ball", "radial"): 25.0, ("roller", "radial"): 15.0,
               ("ball", "thrust"): 50.0, ("roller", "thrust"): 50.0}


#: Catalogue factors of the types whose ratings alone do not give P under axial load (a
#: 1205-size self-aligning ball bearing's, SKF).
CATALOGUE_FACTORS = {"self-aligning-ball": {"e": 0.27, "y1": 2.3, "y2": 3.6, "y0": 2.5}}


def family(bearing_type: str) -> tuple[str, str]:
    """(ball or roller, radial or thrust), from the type tables."""
    own = traits(bearing_type)
    return own.family, "thrust" if own.thrust else "radial"


def catalogue_rows() -> dict[str, dict[str, str]]:
    """The first row of each type in the example catalogue."""
    lines = [line for line in CATALOGUE.read_text(encoding="utf-8").splitlines()
             if not line.startswith("#")]
    rows: dict[str, dict[str, str]] = {}
    for row in csv.DictReader(lines):
        rows.setdefault(row["type"], row)
    return rows


def bearing_fields(bearing_type: str, arrangement: str, source: str) -> dict[str, Any] | None:
    """What the bearing is (type, arrangement, ratings or geometry); None where the source
    has nothing of the type (no catalogue row)."""
    rolling, direction = family(bearing_type)
    fields: dict[str, Any] = {"type": bearing_type}
    if arrangement != "single":
        fields["arrangement"] = arrangement
    if traits(bearing_type).contact_angle is None:
        fields["contact_angle"] = f"{USUAL_ANGLE[rolling, direction]:g} deg"
    if source == "catalogue":
        row = catalogue_rows().get(bearing_type)
        if row is None:
            return None
        fields.pop("contact_angle", None)
        return {**fields, "catalogue": str(CATALOGUE), "designation": row["designation"],
                "maker": row["maker"]}
    if source == "ratings":
        radial = direction == "radial"
        fields.update(dynamic_load_rating="30 kN" if radial else "60 kN",
                      static_load_rating="25 kN" if radial else "150 kN",
                      bore_diameter="25 mm" if radial else "40 mm",
                      outside_diameter="52 mm" if radial else "80 mm")
        if rolling == "ball":
            fields["static_factor"] = 14
        if bearing_type in CATALOGUE_FACTORS:
            fields["load_factors"] = CATALOGUE_FACTORS[bearing_type]
        return fields
    if rolling == "ball":
        fields.update(ball_count=9, ball_diameter="7.938 mm", pitch_diameter="38.5 mm",
                      inner_groove_conformity=0.52, outer_groove_conformity=0.53)
        if direction == "thrust":
            fields.update(ball_count=19, ball_diameter="9.525 mm", pitch_diameter="62.5 mm")
        return fields
    fields.update(roller_count=17, roller_diameter="7.4 mm", roller_length="12 mm",
                  pitch_diameter="46 mm")
    if direction == "thrust":
        fields.update(roller_count=15, roller_diameter="8 mm", roller_length="8 mm",
                      pitch_diameter="70 mm")
    return fields


def _loads(bearing_type: str, scale: float = 1.0) -> dict[str, str]:
    if family(bearing_type)[1] == "thrust":
        return {"axial_load": f"{10 * scale:g} kN"}
    return {"radial_load": f"{5 * scale:g} kN", "axial_load": f"{1 * scale:g} kN"}


@dataclass(frozen=True)
class Case:
    """One combination: its name (the file's stem), its spec, and what a study varies."""

    name: str
    kind: str
    spec: dict[str, Any]
    #: (field, its nominal with a tolerance), for tolerance; (field, START:STOP:N) for sweep
    toleranced: tuple[str, str]
    swept: str

    def sampled(self, every: int) -> bool:
        """Whether the case is in the sample of one in ``every`` (by the CRC-32 of its
        name: the same sample on every run and machine)."""
        return zlib.crc32(self.name.encode()) % every == 0

    def text(self, tolerance: bool = False) -> str:
        """The spec as YAML; with ``tolerance``, the toleranced field in place."""
        spec = dict(self.spec)
        if tolerance:
            field, value = self.toleranced
            spec[field] = value
        return yaml.safe_dump(spec, sort_keys=False, allow_unicode=True)


def rolling_bearing_cases(kind: str) -> Iterator[Case]:
    """Every type × arrangement × source × operation of a rolling bearing."""
    for bearing_type, arrangement, source, operation in itertools.product(
            TYPES, ARRANGEMENTS, SOURCES, OPERATION):
        fields = bearing_fields(bearing_type, arrangement, source)
        if fields is None:
            continue
        spec: dict[str, Any] = {"kind": kind, "name": None, **fields,
                                **_loads(bearing_type), "speed": "1500 rpm",
                                "lubrication": {"viscosity": "68 mm^2/s"},
                                "contamination_factor": 0.5,
                                "limits": {"min_rating_life": "1000 h",
                                           "min_static_safety": 1}}
        if operation == "cycle":
            spec["duty_cycle"] = [{"name": "rated", "time": "60 %"},
                                  {"name": "peak", "time": "30 %", **_loads(bearing_type, 1.5)},
                                  {"name": "held", "time": "10 %", "speed": "0 rpm"}]
        name = f"{kind}.{bearing_type}.{arrangement}.{source}.{operation}"
        spec["name"] = name
        load = "axial_load" if family(bearing_type)[1] == "thrust" else "radial_load"
        nominal = float(spec[load].split()[0])
        yield Case(name, kind, spec, (load, f"{nominal:g} kN ± {nominal / 10:g} kN"),
                   f"{load}={0.8 * nominal:g}kN:{1.2 * nominal:g}kN:3")


#: The drive's gear pair, straight or spiral.
_PAIR = {"gear_a": {"teeth": 20}, "gear_b": {"teeth": 43}, "module": "3 mm",
         "shaft_angle": "90 deg", "face_width": "20 mm", "pressure_angle": "20 deg"}
_SPIRAL = {"spiral_angle": "35 deg", "hand": "left", "rotation": "counterclockwise"}
_RATING = {"quality_number": 8, "hardness": "300 HB", "mounting": "one-straddle",
           "geometry_factor_bending": 0.23, "geometry_factor_pitting": 0.08}
_POSITIONS = {"pinion": ("85 mm", "150 mm"), "gear": ("20 mm", "120 mm")}


def bevel_drive_cases(kind: str) -> Iterator[Case]:
    """Every type × arrangement × shaft arrangement × pair × source × operation of a
    drive whose four bearings are of the type, both shafts in the shaft arrangement."""
    for bearing_type, arrangement, shafts, pair, source, operation in itertools.product(
            TYPES, ARRANGEMENTS, SHAFT_ARRANGEMENTS, PAIRS, SOURCES, OPERATION):
        fields = bearing_fields(bearing_type, arrangement, source)
        if fields is None:
            continue
        catalogue = fields.pop("catalogue", None)
        spec: dict[str, Any] = {"kind": kind, "name": None, **_PAIR,
                                **(_SPIRAL if pair == "spiral" else {}),
                                "input_speed": "1500 rpm", "torque": "60 N*m",
                                "rating": {**_RATING, **({"cutter_radius": "4.5 in"}
                                                         if pair == "spiral" else {})}}
        if catalogue is not None:
            spec["catalogue"] = catalogue
        for shaft, positions in _POSITIONS.items():
            entries = [{"position": position, **fields} for position in positions]
            if shafts == "locating-floating":
                entries[1]["locating"] = True
            else:
                spec[f"{shaft}_arrangement"] = shafts
            spec[f"{shaft}_bearings"] = entries
        spec.update({"lubrication": {"viscosity": "68 mm^2/s"}, "contamination_factor": 0.5,
                     "limits": {"min_rating_life": "1000 h", "min_static_safety": 1}})
        if operation == "cycle":
            spec["duty_cycle"] = [{"name": "rated", "time": "60 %"},
                                  {"name": "peak", "time": "30 %", "torque": "80 N*m"},
                                  {"name": "held", "time": "10 %", "torque": "100 N*m",
                                   "input_speed": "0 rpm"}]
        name = f"{kind}.{bearing_type}.{arrangement}.{shafts}.{pair}.{source}.{operation}"
        spec["name"] = name
        yield Case(name, kind, spec, ("torque", "60 N*m ± 6 N*m"), "torque=50N*m:70N*m:3")


def _takes_bearings(model: type) -> str | None:
    """How a kind's spec holds bearings: as one (its model is a bearing), in a list of
    bearing entries (a drive), or not at all."""
    if issubclass(model, BearingFields):
        return "bearing"
    for info in model.model_fields.values():
        if any(isinstance(arg, type) and issubclass(arg, BearingFields)
               for arg in _type_args(info.annotation)):
            return "entries"
    return None


def _type_args(annotation: Any) -> Iterator[Any]:
    yield annotation
    for arg in get_args(annotation):
        yield from _type_args(arg)


#: How each way of holding bearings is built into specs.
BUILDERS = {"bearing": rolling_bearing_cases, "entries": bevel_drive_cases}


def bearing_kinds() -> dict[str, str]:
    """Each kind of the registry that takes bearings, and how (one kind per model: an
    alias such as ``ball-bearing`` is the same spec)."""
    seen: set[str] = set()
    out = {}
    for name, kind in KINDS.items():
        holds = _takes_bearings(kind.model)
        if holds is not None and kind.model_path not in seen:
            seen.add(kind.model_path)
            out[name] = holds
    return out


def cases() -> list[Case]:
    """Every case of every bearing kind."""
    return [case for name, holds in bearing_kinds().items()
            for case in BUILDERS[holds](name)]

