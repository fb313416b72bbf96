"""No input of ``kind: rolling-bearing`` ends in the generic line "the design's numbers are
out of the range of double precision": every field of the model (and of its duty cycle's
bins), on every bearing type, rated from the catalogue or from its geometry, is set to
edge values (0, tiny, huge, negative, 90 deg, ...), and each outcome must be a result or
a line that names a field.

The fields and their kinds of value are read from the spec model itself, so a new field
or bearing type joins the fuzz by itself. ``python -m tests.test_no_generic_overflow``
prints every input that still reaches the generic line.
"""

from __future__ import annotations

import copy
import typing
from collections.abc import Iterator
from typing import Any

import yaml

from bearingcalc.core.roller_ratings import THRUST_FC
from bearingcalc.errors import SpecError
from bearingcalc.evaluation import evaluate_documents
from bearingcalc.kinds import OUT_OF_RANGE_REASON
from bearingcalc.models.base import field_parser, nested_model
from bearingcalc.models.rolling_bearing import BearingBin, RollingBearingSpec
from bearingcalc.models.yaml_loader import load_documents

#: The lines that name no field: the overflow guard's, an internal error's, and a NaN's.
GENERIC = (OUT_OF_RANGE_REASON[1], "internal error", "cannot be computed for this design")

#: Edge values by SI unit, as a spec writes them: zero, a magnitude no machine has, the
#: smallest and largest that one may have, and a negative value.
EDGES: dict[str, tuple[str, ...]] = {
    "m": ("0 mm", "1e-300 m", "0.001 mm", "100 m", "1e300 m", "-5 mm"),
    "N": ("0 N", "1e-300 N", "1e-6 N", "1e6 kN", "1e300 N", "-1 kN"),
    "rad": ("0 deg", "1e-12 deg", "45 deg", "89.999999 deg", "90 deg", "-10 deg",
            "180 deg"),
    "rad/s": ("0 rpm", "1e-300 rpm", "1e-9 rpm", "1e6 rpm", "1e300 rpm", "-100 rpm"),
    "Pa": ("0 MPa", "1e-300 Pa", "1 kPa", "1e6 MPa", "1e300 Pa", "-1 MPa"),
    "s": ("0 h", "1e-300 s", "1 ms", "1e9 h", "1e300 s", "-1 h"),
    "K": ("-273.15 degC", "-200 degC", "1e6 degC", "1e300 K"),
    "m²/s": ("0 mm^2/s", "1e-300 m^2/s", "1e-9 mm^2/s", "1e6 mm^2/s", "1e300 m^2/s"),
    "1": ("0", "1e-300", "1e-12", "0.5", "1", "1e12", "1e300", "-1"),
}
COUNTS = (0, 1, 2, 3, 1000, 10**9)

_SHARED = {"kind": "rolling-bearing", "radial_load": "6 kN", "axial_load": "2 kN",
           "speed": "1500 rpm", "lubrication": {"viscosity": "30 mm^2/s"},
           "contamination_factor": 0.5, "limits": {"min_rating_life": "5000 h"}}
_CATALOGUE = {"dynamic_load_rating": "50 kN", "static_load_rating": "30 kN",
              "fatigue_load_limit": "1.5 kN", "pitch_diameter": "40 mm"}
_BALLS = {"ball_count": 9, "ball_diameter": "7.9 mm", "pitch_diameter": "38.5 mm",
          "bore_diameter": "25 mm", "outside_diameter": "52 mm", "width": "15 mm"}
_ROLLERS = {"roller_count": 15, "roller_diameter": "7 mm", "roller_length": "10 mm",
            "pitch_diameter": "46 mm", "bore_diameter": "30 mm", "outside_diameter": "62 mm",
            "width": "20 mm"}
_ANGLES = {"angular-contact": "40 deg", "tapered-roller": "14 deg",
           "spherical-roller": "10 deg", "thrust-spherical-roller": "50 deg",
           "thrust-tapered-roller": "60 deg"}
_THRUST = ("thrust", "thrust-ball", "thrust-cylindrical-roller", "thrust-spherical-roller",
           "thrust-tapered-roller")
_FACTORS = {"self-aligning-ball": {"e": 0.3, "y1": 2.1, "y2": 3.3, "y0": 2.2}}


#: The spec's fields that a bin may set (its own, or the lubrication's).
_BIN_SETS = {path.split(".")[0] for path in RollingBearingSpec.BIN_FIELDS.values()}


def bearing_types() -> tuple[str, ...]:
    return typing.get_args(RollingBearingSpec.model_fields["type"].annotation)


def base_specs() -> Iterator[tuple[str, dict[str, Any]]]:
    """A valid spec of every type, from the catalogue and, where ISO rates it, from its
    geometry; each also over a duty cycle with a bin at rest."""
    for bearing_type in bearing_types():
        rollers = "roller" in bearing_type
        spec: dict[str, Any] = {**_SHARED, "type": bearing_type}
        if bearing_type in _ANGLES:
            spec["contact_angle"] = _ANGLES[bearing_type]
        if bearing_type in _THRUST:
            spec.update(radial_load="0 kN", axial_load="8 kN")
        if bearing_type in _FACTORS:
            spec["load_factors"] = _FACTORS[bearing_type]
        if bearing_type == "spherical-roller":
            spec.update(roller_profile_radius="40 mm", raceway_radius="41 mm")
        forms = [("catalogue", {**spec, **_CATALOGUE})]
        if bearing_type == "deep-groove":
            forms[0][1]["static_factor"] = 14
        if bearing_type != "self-aligning-ball":
            forms.append(("geometry", {**spec, **(_ROLLERS if rollers else _BALLS)}))
        for form, each in forms:
            if form == "geometry" and bearing_type in _THRUST:
                # ISO 76 gives no thrust ball f0 (so no Cu), ISO 281 here no thrust fc.
                each.update(fatigue_load_limit="1.5 kN") if not rollers else (
                    THRUST_FC is None and each.update(dynamic_load_rating="150 kN"))
            if bearing_type == "thrust-spherical-roller" and form == "geometry":
                each.update(roller_profile_radius="40 mm", raceway_radius="41 mm")
            yield f"{bearing_type}/{form}", each
            heavier = ({"axial_load": "12 kN"} if bearing_type in _THRUST
                       else {"radial_load": "9 kN"})
            yield f"{bearing_type}/{form}/duty", {**each, "duty_cycle": [
                {"time": "60 %"}, {"time": "30 %", **heavier},
                {"time": "10 %", "speed": "0 rpm"}]}


def _numeric_fields(model: Any, prefix: str = "") -> Iterator[tuple[str, tuple[Any, ...]]]:
    """(dotted field, its edge values) of every number of ``model`` and the groups it
    holds, read from the model's own field types."""
    for name, info in model.model_fields.items():
        held = nested_model(info)
        if held is not None:
            if name != "duty_cycle":
                yield from _numeric_fields(held, f"{prefix}{name}.")
            continue
        parser = field_parser(info)
        if parser is None:
            continue
        kind, _, unit = parser
        yield f"{prefix}{name}", COUNTS if kind == "integer" else EDGES.get(unit, EDGES["1"])


def _set(spec: dict[str, Any], path: str, value: Any) -> dict[str, Any]:
    out = copy.deepcopy(spec)
    parts = path.split(".")
    target = out
    for part in parts[:-1]:
        target = target.setdefault(part, {}) if not isinstance(target, list) else (
            target[int(part)])
    target[parts[-1]] = value
    return out


def fuzzed() -> Iterator[tuple[str, dict[str, Any]]]:
    """Every base spec with each field, and each field of its duty cycle's bins, at each
    edge value; and the bins' time shares at their edges."""
    spec_fields = list(_numeric_fields(RollingBearingSpec))
    bin_fields = [(name, values) for name, values in _numeric_fields(BearingBin)]
    for label, spec in base_specs():
        cycle = "duty_cycle" in spec
        for path, values in spec_fields:
            if cycle and path.split(".")[0] not in _BIN_SETS:
                continue  # the same as without the cycle, but for the fields bins set
            for value in values:
                yield f"{label}: {path}={value}", _set(spec, path, value)
        if not cycle:
            continue
        for path, values in bin_fields:
            for value in values:
                yield f"{label}: duty_cycle.2.{path}={value}", _set(
                    spec, f"duty_cycle.1.{path}", value)
        for times in (("100 %", "0 %", "0 %"), ("0 %", "0 %", "100 %"),
                      ("1e-12 %", "100 %", "0 %")):
            cycle = [{**item, "time": time} for item, time in zip(spec["duty_cycle"], times,
                                                                   strict=True)]
            yield f"{label}: times={times}", {**spec, "duty_cycle": cycle}


def generic_outcomes() -> list[tuple[str, str]]:
    """(label, line) of every fuzzed input that ends in the generic line or an internal
    error."""
    labels, documents = [], []
    for label, spec in fuzzed():
        labels.append(label)
        documents.extend(load_documents(f"{len(labels)}.yaml", yaml.safe_dump(
            spec, allow_unicode=True)))
    found = []
    for label, outcome in zip(labels, evaluate_documents(documents), strict=True):
        if isinstance(outcome, SpecError) and any(
                text in line for text in GENERIC for line in outcome.lines()):
            found.append((label, str(outcome)))
    return found


def test_the_fuzz_covers_every_type_and_field() -> None:
    labels = [label for label, _ in fuzzed()]
    for bearing_type in bearing_types():
        assert any(label.startswith(f"{bearing_type}/") for label in labels)
    for path in ("roller_length", "raceway_radius", "contact_angle", "load_factors.e",
                 "material.elastic_modulus", "lubrication.temperature"):
        assert any(f": {path}=" in label for label in labels)
    assert any("duty_cycle.2.speed=" in label for label in labels)


def test_every_base_spec_solves() -> None:
    labels, documents = [], []
    for label, spec in base_specs():
        labels.append(label)
        documents.extend(load_documents(f"{label}.yaml", yaml.safe_dump(spec)))
    refused = [(label, str(outcome)) for label, outcome in
               zip(labels, evaluate_documents(documents), strict=True)
               if isinstance(outcome, SpecError)]
    assert refused == []


def test_no_fuzzed_input_reaches_the_generic_line() -> None:
    assert generic_outcomes() == []


if __name__ == "__main__":
    for label, line in generic_outcomes():
        print(label, "->", line)
