"""Hostile inputs for roller bearings solved as mounted (`method: iso-16281`).

Cylindrical, needle and tapered roller bearings with their operating clearance, a
tilting moment or a misalignment, a roller profile and laminae, through every command.
Each case holds the README's contract ("Bad input and output files"): no traceback, a
refusal is one line `file:line: field: ...` with exit status 2, exit 1 only for a valid
design beyond a limit, finite numbers in a solved spec, sweeps that leave impossible
points as gaps with a reason, tolerance studies that finish; and, where it can be stated
without the product's formulas, physical sanity (statics, symmetry, monotony, units).
Cases that fail because of the product are kept as strict xfails naming the defect.
"""

from __future__ import annotations

import csv
import io
import json
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from bearingcalc.cli.app import app

RUNNER = CliRunner()
LINE = re.compile(r"^(?P<file>[^:\n]+):(?P<line>\d+): (?P<field>[A-Za-z_][\w.]*): (?P<what>.+)$")
CATALOGUE = Path(__file__).resolve().parents[1] / "specs" / "catalogues" / "example.csv"
DROP = object()  # an override that removes the key

CYL = {
    "kind": "rolling-bearing",
    "type": "cylindrical-roller",
    "method": "iso-16281",
    "dynamic_load_rating": "44 kN",
    "static_load_rating": "36.5 kN",
    "roller_count": 13,
    "roller_diameter": "7.5 mm",
    "roller_length": "10 mm",
    "pitch_diameter": "46 mm",
    "operating_clearance": "15 µm",
    "radial_load": "8 kN",
    "speed": "3000 rpm",
}
TAP = {
    "kind": "rolling-bearing",
    "type": "tapered-roller",
    "method": "iso-16281",
    "dynamic_load_rating": "54 kN",
    "static_load_rating": "63 kN",
    "roller_count": 17,
    "roller_diameter": "7.5 mm",
    "roller_length": "14 mm",
    "pitch_diameter": "45 mm",
    "contact_angle": "14 deg",
    "roller_included_angle": "4 deg",
    "radial_load": "6 kN",
    "axial_load": "3 kN",
    "speed": "3000 rpm",
}
NEEDLE = {**CYL, "type": "needle-roller", "roller_diameter": "3 mm", "roller_length": "12 mm",
          "roller_count": 30}
PAIR = {**TAP, "arrangement": "back-to-back", "setting": {"end_play": "20 µm"},
        "pair_spacing": "60 mm"}
BASES = {"cyl": CYL, "tap": TAP, "needle": NEEDLE, "pair": PAIR}


@dataclass
class Run:
    code: int
    out: str
    err: str

    def lines(self) -> list[str]:
        return [line for line in self.err.splitlines() if line.strip()]


@pytest.fixture(autouse=True)
def _in_tmp(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("BEARINGCALC_CATALOGUE", raising=False)


def spec(base: dict, **over) -> dict:
    """A copy of `base` with `over` applied; DROP removes a key."""
    out = dict(base)
    for key, value in over.items():
        if value is DROP:
            out.pop(key, None)
        else:
            out[key] = value
    return out


def dump(data: dict) -> str:
    return yaml.safe_dump(data, allow_unicode=True, sort_keys=False)


def write(name: str, data: dict | str) -> str:
    Path(name).parent.mkdir(parents=True, exist_ok=True)
    Path(name).write_text(data if isinstance(data, str) else dump(data), encoding="utf-8")
    return name


def line_of(text: str, key: str) -> int | None:
    """The line of a top-level key, or of a dotted key's innermost one written."""
    found, indent = None, ""
    for part in key.split("."):
        for number, line in enumerate(text.splitlines(), start=1):
            if number > (found or 0) and line.startswith(f"{indent}{part}:"):
                found = number
                break
        else:
            return found
        indent += "  "
    return found


def cli(*args) -> Run:
    """Run bearingcalc in-process; no traceback and no uncaught exception, ever."""
    res = RUNNER.invoke(app, [str(a) for a in args], prog_name="bearingcalc")
    exc = res.exception
    assert exc is None or isinstance(exc, SystemExit), f"uncaught {exc!r}"
    both = res.stdout + res.stderr
    assert "Traceback" not in both
    assert "internal error" not in both.lower()
    return Run(res.exit_code, res.stdout, res.stderr)


def refused(run: Run, field: str, line: int | None = None) -> str:
    """Exit 2 and exactly one line `file:line: field: ...` on stderr; returns it."""
    assert run.code == 2, (run.code, run.err, run.out[:300])
    lines = run.lines()
    assert len(lines) == 1, lines
    match = LINE.match(lines[0])
    assert match, lines[0]
    assert match["field"] == field, lines[0]
    if line is not None:
        assert int(match["line"]) == line, lines[0]
    assert "\x1b" not in run.err
    return lines[0]


def finite_tree(obj, path: str = "") -> list[str]:
    """Paths of every float in a JSON tree that is not finite."""
    if isinstance(obj, float):
        return [] if math.isfinite(obj) else [path]
    if isinstance(obj, dict):
        return [p for k, v in obj.items() for p in finite_tree(v, f"{path}.{k}")]
    if isinstance(obj, list):
        return [p for i, v in enumerate(obj) for p in finite_tree(v, f"{path}[{i}]")]
    return []


def mounted_sanity(res: dict) -> None:
    """What any single bearing as mounted must show, whatever its formulas."""
    loads = [v for k, v in res.items() if re.fullmatch(r"element_\d+_load", k)]
    if not loads:
        return
    assert all(q >= 0 for q in loads)
    assert 0 < res["loaded_elements"] <= len(loads)
    assert res["loaded_elements"] == sum(q > 0 for q in loads)
    assert res["max_element_load"] == pytest.approx(max(loads), rel=1e-12)
    assert 0 < res["load_zone_angle"] <= 2 * math.pi + 1e-9
    assert res["stiffness_radial"] > 0
    assert res["stiffness_tilt"] > 0
    assert res["stiffness_axial"] >= 0
    assert res["equilibrium_residual"] < 1e-6
    assert res["reference_rating_life"] > 0
    pressures = (res["max_contact_pressure_inner"], res["max_contact_pressure_outer"])
    assert res["max_contact_pressure"] == pytest.approx(max(pressures), rel=1e-12)


def solve(data: dict | str, name: str = "s.yaml") -> tuple[dict, dict]:
    """Solve one spec to JSON: exit 0 or 1, every number finite; (results, record)."""
    run = cli("solve", write(name, data), "--format", "json")
    assert run.code in (0, 1), (run.code, run.err)
    assert run.err.strip() == ""
    record = json.loads(run.out.splitlines()[0])
    assert finite_tree(record) == []
    assert record["within_limits"] is (run.code == 0)
    mounted_sanity(record["results"])
    return record["results"], record


def elements(res: dict, z: int) -> list[tuple[float, float]]:
    return [(res[f"element_{k}_azimuth"], res[f"element_{k}_load"]) for k in range(1, z + 1)]


def sweep_rows(data: dict, *vary: str) -> list[dict]:
    args = ["sweep", write("sw.yaml", data)]
    for v in vary:
        args += ["--vary", v]
    run = cli(*args, "--format", "json")
    assert run.code == 0, run.err
    rows = [json.loads(line) for line in run.out.splitlines()]
    for row in rows:
        assert finite_tree(row) == []
        assert (not row["results"]) == (row["reason"] is not None), row["reason"]
        if row["results"]:
            mounted_sanity(row["results"])
    return rows


# --------------------------------------------------------------------------------------
# 1. Every new field, wrong in every way: one line naming the field, at its line.

BAD_FIELDS = [
    # roller_count
    ("cyl", {"roller_count": 0}, "roller_count"),
    ("cyl", {"roller_count": -3}, "roller_count"),
    ("cyl", {"roller_count": 2.5}, "roller_count"),
    ("cyl", {"roller_count": "13"}, "roller_count"),
    ("cyl", {"roller_count": True}, "roller_count"),
    ("cyl", {"roller_count": [13]}, "roller_count"),
    ("cyl", {"roller_count": float("nan")}, "roller_count"),
    ("cyl", {"roller_count": float("inf")}, "roller_count"),
    ("cyl", {"roller_count": 40}, "roller_count"),
    ("cyl", {"roller_count": 100000}, "roller_count"),
    # roller_diameter, roller_length, pitch_diameter
    ("cyl", {"roller_diameter": "0 mm"}, "roller_diameter"),
    ("cyl", {"roller_diameter": "-7.5 mm"}, "roller_diameter"),
    ("cyl", {"roller_diameter": 7.5}, "roller_diameter"),
    ("cyl", {"roller_diameter": "7.5 kg"}, "roller_diameter"),
    ("cyl", {"roller_diameter": "nan mm"}, "roller_diameter"),
    ("cyl", {"roller_diameter": "inf mm"}, "roller_diameter"),
    ("cyl", {"roller_diameter": "1e20 mm"}, "roller_diameter"),
    ("cyl", {"roller_diameter": {"a": 1}}, "roller_diameter"),
    ("cyl", {"roller_diameter": "50 mm"}, "roller_diameter"),
    ("cyl", {"roller_length": "0 mm"}, "roller_length"),
    ("cyl", {"roller_length": "-10 mm"}, "roller_length"),
    ("cyl", {"roller_length": "10 deg"}, "roller_length"),
    ("cyl", {"roller_length": None}, "roller_length"),
    ("cyl", {"pitch_diameter": "0 mm"}, "pitch_diameter"),
    ("cyl", {"pitch_diameter": "NaN mm"}, "pitch_diameter"),
    ("cyl", {"pitch_diameter": "7 mm"}, "roller_diameter"),
    # operating_clearance
    ("cyl", {"operating_clearance": 15}, "operating_clearance"),
    ("cyl", {"operating_clearance": "15 deg"}, "operating_clearance"),
    ("cyl", {"operating_clearance": "nan um"}, "operating_clearance"),
    ("cyl", {"operating_clearance": "-inf um"}, "operating_clearance"),
    ("cyl", {"operating_clearance": ["15 um"]}, "operating_clearance"),
    ("cyl", {"operating_clearance": True}, "operating_clearance"),
    ("cyl", {"operating_clearance": "15 %"}, "operating_clearance"),
    ("cyl", {"operating_clearance": "200 m"}, "operating_clearance"),
    ("cyl", {"operating_clearance": None}, "operating_clearance"),
    ("cyl", {"operating_clearance": "15 µm 3 mm"}, "operating_clearance"),
    ("cyl", {"operating_clearance": "1" * 90 + " mm"}, "operating_clearance"),
    ("cyl", {"operating_clearance": "5 mm"}, "operating_clearance"),
    ("cyl", {"operating_clearance": "-750 µm"}, "operating_clearance"),
    ("tap", {"operating_clearance": "15 um"}, "operating_clearance"),
    # misalignment
    ("cyl", {"misalignment": "0.5 mm"}, "misalignment"),
    ("cyl", {"misalignment": 0.0005}, "misalignment"),
    ("cyl", {"misalignment": "nan mrad"}, "misalignment"),
    ("cyl", {"misalignment": "1e300 mrad"}, "misalignment"),
    ("cyl", {"misalignment": "0,5 mrad"}, "misalignment"),
    ("cyl", {"misalignment": "−0.5 mrad"}, "misalignment"),
    ("cyl", {"misalignment": ""}, "misalignment"),
    ("cyl", {"misalignment": "0.5 mrad\x1b[31m"}, "misalignment"),
    ("cyl", {"misalignment": "90 deg"}, "misalignment"),
    ("cyl", {"tilting_moment": "2 N*m", "misalignment": "1 mrad"}, "misalignment"),
    # tilting_moment
    ("cyl", {"tilting_moment": "2 N"}, "tilting_moment"),
    ("cyl", {"tilting_moment": 2}, "tilting_moment"),
    ("cyl", {"tilting_moment": "inf N*m"}, "tilting_moment"),
    ("cyl", {"tilting_moment": "1e6 N*m"}, "tilting_moment"),
    ("tap", {"tilting_moment": "100 N*m"}, "axial_load"),
    # roller_profile
    ("cyl", {"roller_profile": "ISO"}, "roller_profile"),
    ("cyl", {"roller_profile": "logarithmic"}, "roller_profile"),
    ("cyl", {"roller_profile": True}, "roller_profile"),
    ("cyl", {"roller_profile": 1}, "roller_profile"),
    ("cyl", {"roller_profile": ["iso"]}, "roller_profile"),
    ("cyl", {"roller_profile": "None"}, "roller_profile"),
    ("cyl", {"roller_profile": {"crown_radius": 1}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "1 deg"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "0 m"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "-1 m"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "5 mm"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "4.9 mm"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "5.2 mm"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "80 mm"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "1e6 m"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "nan m"}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": None}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": ["1 m"]}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {}}, "roller_profile.crown_radius"),
    ("cyl", {"roller_profile": {"crown_radius": "1 m", "drop": "5 um"}}, "roller_profile.drop"),
    ("cyl", {"roller_profile": {"crown_radus": "1 m"}}, "roller_profile.crown_radus"),
    # laminae
    ("cyl", {"laminae": 9}, "laminae"),
    ("cyl", {"laminae": 201}, "laminae"),
    ("cyl", {"laminae": 0}, "laminae"),
    ("cyl", {"laminae": -30}, "laminae"),
    ("cyl", {"laminae": 30.5}, "laminae"),
    ("cyl", {"laminae": "30"}, "laminae"),
    ("cyl", {"laminae": "30 mm"}, "laminae"),
    ("cyl", {"laminae": True}, "laminae"),
    ("cyl", {"laminae": float("nan")}, "laminae"),
    ("cyl", {"laminae": float("inf")}, "laminae"),
    ("cyl", {"laminae": 10**9}, "laminae"),
    ("cyl", {"laminae": [30]}, "laminae"),
    ("cyl", {"laminae": "30 ± 2"}, "laminae"),
    # roller_included_angle
    ("tap", {"roller_included_angle": "0 deg"}, "roller_included_angle"),
    ("tap", {"roller_included_angle": "-4 deg"}, "roller_included_angle"),
    ("tap", {"roller_included_angle": "90 deg"}, "roller_included_angle"),
    ("tap", {"roller_included_angle": "360 deg"}, "roller_included_angle"),
    ("tap", {"roller_included_angle": "4 mm"}, "roller_included_angle"),
    ("tap", {"roller_included_angle": 4}, "roller_included_angle"),
    ("tap", {"roller_included_angle": "nan deg"}, "roller_included_angle"),
    ("tap", {"roller_included_angle": "4 %"}, "roller_included_angle"),
    ("tap", {"roller_included_angle": "14 deg"}, "roller_included_angle"),
    ("tap", {"contact_angle": "0.5 deg"}, "roller_included_angle"),
    ("cyl", {"roller_included_angle": "4 deg"}, "roller_included_angle"),
    # contact angle, loads, speed
    ("cyl", {"contact_angle": "14 deg"}, "contact_angle"),
    ("tap", {"contact_angle": "0 deg"}, "contact_angle"),
    ("tap", {"contact_angle": "46 deg"}, "contact_angle"),
    ("tap", {"contact_angle": DROP}, "contact_angle"),
    ("cyl", {"axial_load": "1 kN"}, "axial_load"),
    ("cyl", {"axial_load": "1 kN", "radial_load": "0 kN"}, "axial_load"),
    ("cyl", {"radial_load": "0 kN"}, "radial_load"),
    ("cyl", {"speed": "0 rpm"}, "speed"),
    ("cyl", {"speed": "50 Hz"}, "speed"),
    ("tap", {"axial_load": "0 kN"}, "axial_load"),
    ("tap", {"axial_load": "100 N"}, "axial_load"),
    ("tap", {"axial_load": "1.4 kN"}, "axial_load"),
    ("tap", {"axial_load": "-3 kN"}, "axial_load"),
    ("tap", {"contact_angle": "30 deg"}, "axial_load"),
    # method, type and what the method does not solve
    ("cyl", {"method": "ISO-16281"}, "method"),
    ("cyl", {"method": "iso16281"}, "method"),
    ("cyl", {"method": 16281}, "method"),
    ("cyl", {"method": ["iso-16281"]}, "method"),
    ("cyl", {"method": "iso-281"}, "operating_clearance"),
    ("tap", {"type": "spherical-roller"}, "type"),
    ("cyl", {"type": "thrust-cylindrical-roller"}, "type"),
    ("cyl", {"rows": 3}, "rows"),
    ("tap", {"rows": 2}, "rows"),
    ("cyl", {"duty_cycle": [{"time": "50 %", "radial_load": "4 kN"},
                            {"time": "50 %", "radial_load": "8 kN"}]}, "duty_cycle"),
    ("tap", {"duty_cycle": [{"time": "100 %"}]}, "duty_cycle"),
    ("pair", {"duty_cycle": [{"time": "100 %"}]}, "duty_cycle"),
    ("cyl", {"limits": {"max_spin_to_roll": 0.1}}, "limits.max_spin_to_roll"),
    ("cyl", {"ball_count": 9}, "ball_count"),
    ("cyl", {"inner_groove_conformity": 0.52}, "inner_groove_conformity"),
    ("cyl", {"bore_diameter": "30 mm", "outside_diameter": "62 mm", "width": "8 mm"},
     "roller_length"),
    # matched pairs as mounted
    ("pair", {"setting": {}}, "setting.end_play"),
    ("pair", {"setting": "20 um"}, "setting"),
    ("pair", {"setting": {"preload": "0 kN"}}, "setting.preload"),
    ("pair", {"setting": {"preload": "1 kN", "end_play": "10 um"}}, "setting.preload"),
    ("pair", {"pair_spacing": "-60 mm"}, "pair_spacing"),
    ("pair", {"arrangement": "tandem"}, "setting"),
]


@pytest.mark.parametrize(
    ("base", "over", "field"),
    [
        pytest.param(b, o, f, id=f"{b}-{f}-{next(iter(o.values()))!r}"[:60])
        for b, o, f in BAD_FIELDS
    ],
)
def test_bad_field_is_one_line_naming_it(base, over, field):
    text = dump(spec(BASES[base], **over))
    run = cli("solve", write("s.yaml", text), "--format", "json")
    refused(run, field, line_of(text, field))
    assert run.out.strip() == ""


# --------------------------------------------------------------------------------------
# 2. YAML oddities around the new fields.

YAML_ODDITIES = [
    ("laminae: 30\nlaminae: 40\n", "duplicate key"),
    ("method: iso-281\n", "duplicate key"),
    ("<<: {laminae: 30}\n", "merge"),
    ("laminae: !!python/object/apply:os.system ['true']\n", "tag"),
    ("roller_profile:\n\tcrown_radius: 1 m\n", "malformed"),
    ("roller_profile: {crown_radius: 1 m\n", "malformed"),
    ("? [laminae]\n: 30\n", "key"),
    ("null: 3\n", "key"),
]


@pytest.mark.parametrize(("tail", "word"), YAML_ODDITIES)
def test_yaml_oddity_is_one_line(tail, word):
    run = cli("solve", write("s.yaml", dump(CYL) + tail))
    assert run.code == 2
    assert len(run.lines()) == 1, run.lines()
    assert run.lines()[0].startswith("s.yaml:")
    assert word in run.lines()[0].lower()


@pytest.mark.parametrize(
    ("tail", "same_as"),
    [
        ("laminae: 0x28\n", {"laminae": 40}),
        ("laminae: 4e1\n", {"laminae": 40}),
        ("laminae: 040\n", {"laminae": 40}),
        ("roller_profile: ~\n", {"roller_profile": "iso"}),
        ("misalignment: 500 µrad\n", {"misalignment": "0.5 mrad"}),
        ("misalignment: +0.5 mrad\n", {"misalignment": "0.5 mrad"}),
        ("misalignment: 0.5 milliradian\n", {"misalignment": "0.5 mrad"}),
    ],
)
def test_yaml_forms_that_read_as_written(tail, same_as):
    """YAML 1.2 numbers and unit spellings read as the value they write."""
    base = spec(CYL, roller_profile={"crown_radius": "1 m"})
    written, _ = solve(dump(spec(base, **dict.fromkeys(same_as, DROP))) + tail)
    reference, _ = solve(spec(base, **same_as), name="ref.yaml")
    for key in ("max_element_load", "stiffness_tilt", "ring_tilt"):
        assert written[key] == pytest.approx(reference[key], rel=1e-12, abs=1e-15), key


# --------------------------------------------------------------------------------------
# 3. Valid hostile designs: solved, finite, physically sane.

VALID = [
    ("cyl", {"roller_count": 1}),
    ("cyl", {"roller_count": 2}),
    ("cyl", {"operating_clearance": "-15 µm"}),
    ("cyl", {"operating_clearance": "0 µm"}),
    ("cyl", {"operating_clearance": "1e-400 mm"}),
    ("cyl", {"operating_clearance": "0.7 mm"}),
    ("cyl", {"operating_clearance": "-0.7 mm"}),
    ("cyl", {"misalignment": "-0.5 mrad"}),
    ("cyl", {"misalignment": "5 mrad", "roller_profile": "none"}),
    ("cyl", {"misalignment": "2 arcmin", "roller_profile": {"crown_radius": "1 m"}}),
    ("cyl", {"tilting_moment": "-2 N*m", "laminae": 10}),
    ("cyl", {"tilting_moment": "2 J", "laminae": 200}),
    ("cyl", {"roller_profile": {"crown_radius": "100 m"}, "misalignment": "1 mrad"}),
    ("cyl", {"roller_profile": {"crown_radius": "40 in"}}),
    ("cyl", {"roller_profile": {"crown_radius": "84 mm"}}),
    ("cyl", {"roller_profile": {"crown_radius": "1 m ± 0.1 m"}}),
    ("cyl", {"pitch_diameter": DROP, "bore_diameter": "30 mm", "outside_diameter": "62 mm"}),
    ("cyl", {"dynamic_load_rating": DROP, "static_load_rating": DROP}),
    ("cyl", {"speed": DROP, "outer_speed": "3000 rpm"}),
    ("cyl", {"lubrication": {"viscosity": "20 mm^2/s"}, "contamination_factor": 0.5}),
    ("cyl", {"kind": "ball-bearing"}),
    ("needle", {"misalignment": "0.3 mrad"}),
    ("needle", {"drawn_cup": True, "tilting_moment": "1 N*m"}),
    ("tap", {"tilting_moment": "5 N*m"}),
    ("tap", {"misalignment": "1 mrad", "roller_profile": {"crown_radius": "1 m"}}),
    ("tap", {"radial_load": "0 kN"}),
    ("tap", {"roller_included_angle": DROP, "roller_profile": "none", "laminae": 200}),
    ("tap", {"contact_angle": "0.5 deg", "roller_included_angle": DROP}),
    ("pair", {}),
    ("pair", {"arrangement": "face-to-face", "misalignment": "1 mrad"}),
    ("pair", {"setting": {"preload": "1.5 kN"}, "tilting_moment": "50 N*m"}),
    ("pair", {"axial_load": "0 kN", "roller_profile": {"crown_radius": "1 m"}, "laminae": 50}),
]


@pytest.mark.parametrize(
    ("base", "over"),
    [pytest.param(b, o, id=f"{b}-{o!r}"[:70]) for b, o in VALID],
)
def test_valid_hostile_design_is_solved_finite(base, over):
    res, record = solve(spec(BASES[base], **over))
    assert all(isinstance(w, str) and "\n" not in w for w in record["warnings"])
    if "ring_tilt" in res and "misalignment" in over:
        assert res["tilting_moment_reaction"] * res["ring_tilt"] >= 0


def test_one_roller_carries_the_whole_load_with_a_warning():
    res, record = solve(spec(CYL, roller_count=1))
    assert res["loaded_elements"] == 1
    assert res["max_element_load"] == pytest.approx(8000, rel=1e-9)
    assert any("one rolling element" in w for w in record["warnings"])


@pytest.mark.parametrize("base", ["cyl", "needle"])
def test_radial_statics_hold(base):
    """The element loads' components along the radial load add up to it."""
    data = spec(BASES[base], misalignment="0.5 mrad")
    res, _ = solve(data)
    z = data["roller_count"]
    fr = sum(q * math.cos(psi) for psi, q in elements(res, z))
    assert fr == pytest.approx(8000, rel=1e-9)


def test_tapered_statics_hold_on_the_cup():
    res, _ = solve(TAP)
    loads = elements(res, 17)
    alpha = math.radians(14)
    fr = sum(q * math.cos(alpha) * math.cos(psi) for psi, q in loads)
    fa = sum(q * math.sin(alpha) for _, q in loads)
    assert fr == pytest.approx(6000, rel=1e-9)
    assert fa == pytest.approx(3000, rel=1e-9)
    assert res["max_rib_load"] == pytest.approx(
        2 * res["max_element_load"] * math.sin(math.radians(2)), rel=1e-12)


@pytest.mark.parametrize(
    ("base", "over"),
    [("cyl", {}), ("cyl", {"misalignment": "1 mrad"}), ("cyl", {"tilting_moment": "3 N*m"}),
     ("tap", {}), ("tap", {"tilting_moment": "5 N*m"}), ("needle", {})],
)
def test_element_loads_symmetric_about_azimuth_zero(base, over):
    """A radial load at azimuth 0 and a tilt in its plane: a mirror-symmetric load zone."""
    data = spec(BASES[base], **over)
    res, _ = solve(data)
    z = data["roller_count"]
    loads = [q for _, q in elements(res, z)]
    for k in range(1, z):
        assert loads[k] == pytest.approx(loads[z - k], rel=1e-9, abs=1e-9)
    assert res["element_1_azimuth"] == 0


def test_misalignment_sign_mirrors():
    plus, _ = solve(spec(CYL, misalignment="0.8 mrad"), name="p.yaml")
    minus, _ = solve(spec(CYL, misalignment="-0.8 mrad"), name="m.yaml")
    assert plus["ring_tilt"] == pytest.approx(8e-4, rel=1e-12)
    assert minus["ring_tilt"] == pytest.approx(-8e-4, rel=1e-12)
    assert plus["max_element_load"] == pytest.approx(minus["max_element_load"], rel=1e-9)
    assert plus["reference_rating_life"] == pytest.approx(minus["reference_rating_life"], rel=1e-9)
    assert plus["tilting_moment_reaction"] == pytest.approx(-minus["tilting_moment_reaction"])


@pytest.mark.parametrize(
    ("base", "moment"), [("cyl", "2 N*m"), ("cyl", "-20 N*m"), ("tap", "20 N*m")]
)
def test_moment_and_misalignment_round_trip(base, moment):
    """The tilt a moment gives, imposed, takes that moment back."""
    free, _ = solve(spec(BASES[base], tilting_moment=moment), name="free.yaml")
    tilt = free["ring_tilt"]
    held, _ = solve(spec(BASES[base], misalignment=f"{tilt!r} rad"), name="held.yaml")
    newton_metre = float(moment.split()[0])
    assert held["tilting_moment_reaction"] == pytest.approx(newton_metre, rel=1e-6)
    assert held["max_element_load"] == pytest.approx(free["max_element_load"], rel=1e-6)


def test_units_do_not_change_the_answer():
    mm, _ = solve(spec(CYL, misalignment="0.5 mrad"), name="mm.yaml")
    other, _ = solve(spec(CYL, roller_diameter="0.0075 m", roller_length="0.3937007874015748 in",
                          pitch_diameter="46000 um", operating_clearance="0.015 mm",
                          misalignment="0.028647889756541161 deg", radial_load="8000 N",
                          speed="50 rev/s"), name="other.yaml")
    for key in ("max_element_load", "reference_rating_life", "tilting_moment_reaction",
                "stiffness_radial"):
        assert other[key] == pytest.approx(mm[key], rel=1e-9), key


def test_life_relations_as_documented():
    res, _ = solve(spec(CYL, misalignment="0.5 mrad"))
    revs = (res["dynamic_load_rating"] / res["dynamic_equivalent_reference_load"]) ** (10 / 3)
    assert res["reference_rating_life_revolutions"] == pytest.approx(revs * 1e6, rel=1e-9)
    assert res["reference_rating_life"] == pytest.approx(
        res["reference_rating_life_revolutions"] / 50, rel=1e-9)
    assert res["life_ratio_to_iso281"] == pytest.approx(
        res["reference_rating_life"] / res["basic_rating_life"], rel=1e-9)


def test_laminae_converge_and_crown_tends_to_straight():
    coarse, _ = solve(spec(CYL, laminae=100, misalignment="1 mrad"), name="a.yaml")
    fine, _ = solve(spec(CYL, laminae=200, misalignment="1 mrad"), name="b.yaml")
    assert fine["max_element_load"] == pytest.approx(coarse["max_element_load"], rel=0.01)
    assert fine["reference_rating_life"] == pytest.approx(coarse["reference_rating_life"],
                                                          rel=0.03)
    crown, _ = solve(spec(CYL, roller_profile={"crown_radius": "100 m"}), name="c.yaml")
    straight, _ = solve(spec(CYL, roller_profile="none"), name="d.yaml")
    assert crown["max_element_load"] == pytest.approx(straight["max_element_load"], rel=0.01)


def test_zero_clearance_aligned_straight_rollers_load_half_the_ring():
    """Stribeck's classic: no clearance, no tilt, a load zone of 180°."""
    res, _ = solve(spec(CYL, operating_clearance="0 um", roller_profile="none"))
    assert res["load_zone_angle"] == pytest.approx(math.pi, rel=0.01)
    assert res["loaded_elements"] == 7


def test_which_ring_turns_does_not_move_the_loads():
    inner, _ = solve(CYL, name="i.yaml")
    outer, _ = solve(spec(CYL, speed=DROP, outer_speed="3000 rpm"), name="o.yaml")
    assert outer["max_element_load"] == pytest.approx(inner["max_element_load"], rel=1e-12)
    assert outer["ring_displacement_radial"] == pytest.approx(inner["ring_displacement_radial"])


@pytest.mark.parametrize(
    ("base", "vary"),
    [("cyl", "radial_load=0.5kN:30kN:25"), ("needle", "radial_load=0.5kN:10kN:15"),
     ("tap", "radial_load=0.5kN:12kN:20"),
     ("cyl_tilt", "radial_load=0.5kN:30kN:25")],
)
def test_more_radial_load_more_element_load_less_life(base, vary):
    data = spec(CYL, misalignment="1 mrad") if base == "cyl_tilt" else BASES[base]
    rows = sweep_rows(data, vary)
    res = [r["results"] for r in rows]
    assert all(res)
    mel = [r["max_element_load"] for r in res]
    life = [r["reference_rating_life"] for r in res]
    assert all(a < b for a, b in pairwise(mel))
    assert all(a > b for a, b in pairwise(life))


def test_more_clearance_fewer_loaded_rollers_and_misalignment_costs_life():
    rows = sweep_rows(CYL, "operating_clearance=0um:200um:20")
    loaded = [r["results"]["loaded_elements"] for r in rows]
    assert all(a >= b for a, b in pairwise(loaded))
    assert loaded[0] > loaded[-1]
    rows = sweep_rows(spec(CYL, misalignment="0 mrad"), "misalignment=0mrad:5mrad:20")
    life = [r["results"]["reference_rating_life"] for r in rows]
    assert all(a >= b for a, b in pairwise(life))


# --------------------------------------------------------------------------------------
# 4. Defects once recorded here as strict xfails, since fixed: what the product now does.

def test_huge_clearance_is_named_at_operating_clearance():
    """operating_clearance: 1 m is refused in one line naming operating_clearance at its
    own line: a clearance must be smaller in size than a tenth of Dwe (750 µm here)."""
    text = dump(spec(CYL, operating_clearance="1 m"))
    line = refused(cli("solve", write("s.yaml", text)), "operating_clearance",
                   line_of(text, "operating_clearance"))
    assert "750 µm" in line


def test_clearance_beyond_the_rings_is_refused():
    """operating_clearance: 100 mm on a bearing of Dpw 46 mm, Dwe 7.5 mm (above
    2·(Dpw − Dwe) = 77 mm, an inner raceway of negative diameter) is refused in one line
    naming operating_clearance at its own line, by the tenth-of-Dwe rule."""
    text = dump(spec(CYL, operating_clearance="100 mm"))
    line = refused(cli("solve", write("s.yaml", text)), "operating_clearance",
                   line_of(text, "operating_clearance"))
    assert "750 µm" in line


def test_crushing_preload_is_named_at_operating_clearance():
    """operating_clearance: -6 mm, a preload that would crush the rollers, is refused in one
    line naming operating_clearance at its own line (not radial_load): a preload too must
    be smaller in size than a tenth of Dwe."""
    text = dump(spec(CYL, operating_clearance="-6 mm"))
    line = refused(cli("solve", write("s.yaml", text)), "operating_clearance",
                   line_of(text, "operating_clearance"))
    assert "750 µm" in line


def test_sweep_into_a_crushing_preload_names_the_clearance():
    """A sweep of operating_clearance into a crushing preload (-6 mm, with a 0.5 mrad
    misalignment) is refused in one line naming operating_clearance, the swept field at
    fault, not misalignment; down to the deepest preload the clearance rule allows
    (-740 µm) every point is solved, with no gap."""
    write("sw.yaml", spec(CYL, misalignment="0.5 mrad"))
    run = cli("sweep", "sw.yaml", "--vary", "operating_clearance=-6mm:20um:4")
    assert run.code == 2
    assert len(run.lines()) == 1
    assert run.lines()[0].startswith("bearingcalc sweep:")
    assert "operating_clearance = -6mm: operating_clearance:" in run.lines()[0]
    rows = sweep_rows(spec(CYL, misalignment="0.5 mrad"), "operating_clearance=-740um:20um:4")
    assert all(r["results"] for r in rows)


@pytest.mark.parametrize(
    ("base", "laminae"),
    [("cyl", 10), ("cyl", 30), ("cyl", 100), ("tap", 30)],
    ids=["cyl-10", "cyl-30", "cyl-100", "tap-30"],
)
def test_straight_untilted_rollers_are_not_edge_loaded(base, laminae):
    """Straight rollers (roller_profile: none) with no tilt, moment or misalignment load
    their laminae alike: no 'edge-loaded' warning, whatever the laminae, cylindrical or
    tapered (a translation of the cone loads every lamina of a straight roller alike)."""
    _, record = solve(spec(BASES[base], roller_profile="none", laminae=laminae))
    assert not any("edge-loaded" in w for w in record["warnings"])


def test_tilted_straight_rollers_are_edge_loaded():
    _, record = solve(spec(CYL, roller_profile="none", misalignment="2 mrad"))
    assert any("edge-loaded" in w for w in record["warnings"])


def test_crown_that_drops_more_than_the_roller_radius_is_refused():
    """roller_profile: {crown_radius: 5.0000001 mm} on rollers of Lwe 10 mm, Dwe 7.5 mm,
    whose arc drops r − √(r² − (Lwe/2)²) ≈ 5 mm at the ends (more than Dwe/2, a roller of
    negative end radius), is refused in one line naming roller_profile.crown_radius at its
    own line: a crown must drop the ends by less than 2 % of Dwe."""
    text = dump(spec(CYL, roller_profile={"crown_radius": "5.0000001 mm"}))
    refused(cli("solve", write("s.yaml", text)), "roller_profile.crown_radius",
            line_of(text, "roller_profile") + 1)


def test_sweep_leads_with_the_life_the_limit_judges():
    """Under method: iso-16281 the limit judges modified_reference_rating_life
    (life_margin), and sweep's default table shows it."""
    write("sw.yaml", spec(CYL, misalignment="0 mrad", limits={"min_rating_life": "3000 h"}))
    run = cli("sweep", "sw.yaml", "--vary", "misalignment=0mrad:5mrad:4")
    assert run.code == 0
    assert "life_margin" in run.out
    assert "modified_reference_rating_life" in run.out


def test_tolerance_leads_with_the_life_the_limit_judges():
    """Under method: iso-16281 tolerance's default table shows
    modified_reference_rating_life, the life the limit judges."""
    write("tol.yaml", spec(CYL, misalignment="1 mrad ± 1 mrad",
                           limits={"min_rating_life": "3000 h"}))
    run = cli("tolerance", "tol.yaml", "--samples", "32", "--method", "rss,monte-carlo")
    assert run.code in (0, 1)
    assert "modified_reference_rating_life" in run.out


# --------------------------------------------------------------------------------------
# 5. Defects once kept as strict xfails, since fixed.

@pytest.mark.parametrize(("clearance", "load"), [
    ("-10 um", "10 mN"),
    ("15 um", "1 mN"),
])
def test_small_radial_load_on_a_roller_bearing_is_solved(clearance, load):
    solve(spec(CYL, operating_clearance=clearance, radial_load=load))


def test_negative_tapered_contact_angle_is_one_line():
    text = dump(spec(TAP, contact_angle="-14 deg"))
    refused(cli("solve", write("s.yaml", text)), "contact_angle", line_of(text, "contact_angle"))


def test_pair_with_two_rows_is_one_line():
    text = dump(spec(PAIR, arrangement="face-to-face", rows=2))
    refused(cli("solve", write("s.yaml", text)), "rows", line_of(text, "rows"))


@pytest.mark.parametrize("over", [{"tilting_moment": "5 N*m"},
                                  {"misalignment": "1 mrad", "operating_clearance": "-5 um"}])
def test_moment_alone_is_not_called_no_load(over):
    """A moment, or a tilt against a preload, loads the rollers with no force: ISO/TS
    16281 rates it, ISO 281's lives and ISO 76's safety are unbounded (null)."""
    run = cli("solve", write("s.yaml", spec(CYL, radial_load="0 kN", **over)), "--format",
              "json")
    assert run.code in (0, 1), run.err
    results = json.loads(run.out)["results"]
    assert results["max_element_load"] > 0 and results["reference_rating_life"] > 0
    assert results["basic_rating_life"] is None and results["static_safety_factor"] is None


def test_report_plots_the_life_the_limit_judges():
    write("r.yaml", spec(CYL, misalignment="1 mrad", limits={"min_rating_life": "3000 h"}))
    assert cli("report", "r.yaml", "--output", "r.html").code == 0
    text = re.sub(r"<[^>]+>", " ", Path("r.html").read_text(encoding="utf-8"))
    caption = next(s for s in text.split(". ") if "against the radial load" in s)
    assert "reference" in caption


def test_worst_case_across_the_equilibrium_limit_finds_the_limit():
    """The band crosses the least axial load that holds a tapered bearing's rollers,
    Fa = Fr·tanα (one roller at ψ = 0 carrying Q: Fr = Q·cosα, Fa = Q·sinα): the largest
    roller load lies at that limit, which the worst case's zoom finds."""
    run, record = _tolerance(spec(TAP, axial_load="1.6 kN ± 0.3 kN"), "--method",
                             "worst-case")
    assert run.code == 1, run.err
    assert record["impossible_in_box"]["reason"].startswith("axial_load:")
    largest = record["results"]["max_element_load"]["worst_case"]
    limit = 6000.0 * math.tan(math.radians(14.0))
    assert largest["max_inputs"]["axial_load"] == pytest.approx(limit, rel=1e-9)
    assert largest["max"] > record["results"]["max_element_load"]["nominal"]


# --------------------------------------------------------------------------------------
# 6. Every command.

def test_solve_csv_and_table_agree_with_json():
    write("c.yaml", spec(CYL, misalignment="0.5 mrad", roller_profile={"crown_radius": "1 m"}))
    res, _ = solve(Path("c.yaml").read_text(encoding="utf-8"), name="c.yaml")
    run = cli("solve", "c.yaml", "--format", "csv")
    assert run.code == 0
    values = next(csv.DictReader(io.StringIO(run.out)))
    assert float(values["max_element_load [N]"]) == pytest.approx(res["max_element_load"])
    assert all(v.lower() not in ("nan", "inf", "-inf") for v in values.values())
    table = cli("solve", "c.yaml")
    assert table.code == 0
    assert "PASS" in table.out
    assert "nan" not in table.out.lower().split()


def test_solve_good_and_bad_together_is_exit_2_and_one_line():
    write("good.yaml", TAP)
    write("bad.yaml", spec(TAP, axial_load="100 N"))
    run = cli("solve", "good.yaml", "bad.yaml", "--format", "json")
    assert run.code == 2
    assert len(run.lines()) == 1
    assert run.lines()[0].startswith("bad.yaml:")
    assert json.loads(run.out.splitlines()[0])["spec"] == "good.yaml"


def test_multi_document_file_names_the_bad_document():
    write("two.yaml", dump(CYL) + "---\n" + dump(spec(CYL, laminae=5)))
    assert cli("solve", "two.yaml#1", "--format", "json").code == 0
    run = cli("solve", "two.yaml#2")
    assert run.code == 2
    assert len(run.lines()) == 1
    assert "laminae" in run.lines()[0]


def _folder() -> None:
    write("designs/cyl.yaml", spec(CYL, misalignment="0.5 mrad"))
    write("designs/tap.yaml", TAP)
    write("designs/bad_laminae.yaml", spec(CYL, laminae=5))
    write("designs/sub/bad_axial.yaml", spec(TAP, axial_load="100 N"))
    write("designs/sub/cyl_axial.yaml", spec(CYL, axial_load="1 kN"))
    write("designs/sub/fails.yaml", spec(CYL, limits={"min_rating_life": "1e6 h"}))
    write("designs/sub/pair.yaml", PAIR)


def test_check_folder_mixing_good_and_bad():
    _folder()
    run = cli("check", "designs", "--format", "json", "--jobs", "1")
    assert run.code == 2
    status = {}
    for line in run.out.splitlines():
        rec = json.loads(line)
        status[Path(rec["spec"]).name] = rec
    assert {k: v["status"] for k, v in status.items()} == {
        "cyl.yaml": "pass", "tap.yaml": "pass", "pair.yaml": "pass", "fails.yaml": "fail",
        "bad_laminae.yaml": "invalid", "bad_axial.yaml": "invalid", "cyl_axial.yaml": "invalid",
    }
    fields = {"bad_laminae.yaml": "laminae", "bad_axial.yaml": "axial_load",
              "cyl_axial.yaml": "axial_load"}
    for name, field in fields.items():
        (message,) = status[name]["messages"]
        assert LINE.match(message)["field"] == field
    assert "life" in status["fails.yaml"]["messages"][0]


def test_check_junit_is_xml_and_table_counts():
    _folder()
    run = cli("check", "designs", "--format", "junit", "--jobs", "1")
    assert run.code == 2
    root = ET.fromstring(run.out)
    assert len(root.findall(".//testcase")) == 7
    table = cli("check", "designs", "--jobs", "1")
    assert "3 pass, 1 fail, 3 invalid" in table.out


def test_sweep_laminae_and_grid_with_misalignment_and_crown():
    data = spec(CYL, laminae=30, misalignment="0.5 mrad", roller_profile={"crown_radius": "1 m"})
    rows = sweep_rows(data, "laminae=10:200:6", "misalignment=-1mrad:1mrad:5")
    assert len(rows) == 30
    assert all(r["results"] for r in rows)
    by_point = {(r["inputs"]["laminae"], r["inputs"]["misalignment"]): r["results"] for r in rows}
    for lam in {k[0] for k in by_point}:
        assert by_point[lam, -0.001]["max_element_load"] == pytest.approx(
            by_point[lam, 0.001]["max_element_load"], rel=1e-9)


def test_sweep_crown_radius_down_to_the_smallest_crown_allowed():
    """A crown must drop the ends by less than 2 % of Dwe: for Lwe 10 mm, Dwe 7.5 mm a
    radius above (5² + 0.15²)/(2·0.15) ≈ 83.41 mm. A sweep down to just above it solves
    every point; one that starts at 5.5 mm is refused in one line naming the crown."""
    rows = sweep_rows(spec(CYL, roller_profile={"crown_radius": "1 m"}),
                      "roller_profile.crown_radius=83.5mm:50m:30")
    assert all(r["results"] for r in rows)
    run = cli("sweep", "sw.yaml", "--vary", "roller_profile.crown_radius=5.5mm:50m:30")
    assert run.code == 2
    assert len(run.lines()) == 1
    assert "roller_profile.crown_radius: drops the roller's ends" in run.lines()[0]


@pytest.mark.parametrize(
    ("data", "vary", "field"),
    [
        (spec(CYL, misalignment="0 mrad"), "misalignment=0mrad:1rad:4", "misalignment"),
        (TAP, "axial_load=0.5kN:3kN:4", "axial_load"),
        (CYL, "radial_load=1kN:10MN:4", "radial_load"),
    ],
)
def test_sweep_impossible_points_are_gaps_with_a_reason(data, vary, field):
    rows = sweep_rows(data, vary)
    gaps = [r for r in rows if not r["results"]]
    assert gaps
    assert rows[-1]["results"] or rows[0]["results"]
    assert all(r["reason"].startswith(f"{field}:") for r in gaps)


@pytest.mark.parametrize(
    "vary",
    ["laminae=5:300:4", "laminae=10.5:20:3", "roller_profile.crown_radius=1mm:2m:4",
     "operating_clearance=1:2:3", "nonsense=1:2:3"],
)
def test_sweep_bad_vary_is_one_line(vary):
    write("sw.yaml", spec(CYL, laminae=30, roller_profile={"crown_radius": "1 m"}))
    run = cli("sweep", "sw.yaml", "--vary", vary)
    assert run.code == 2
    assert len(run.lines()) == 1
    assert run.lines()[0].startswith("bearingcalc sweep:")


def test_sweep_of_an_omitted_laminae_says_so():
    write("sw.yaml", CYL)
    run = cli("sweep", "sw.yaml", "--vary", "laminae=10:200:5")
    assert run.code == 2
    assert len(run.lines()) == 1
    assert "laminae" in run.lines()[0]


def test_sweep_writes_csv_with_gaps():
    write("sw.yaml", spec(CYL, misalignment="0 mrad"))
    run = cli("sweep", "sw.yaml", "--vary", "misalignment=0mrad:1rad:4", "--output", "out.csv")
    assert run.code == 0
    lines = Path("out.csv").read_text(encoding="utf-8").splitlines()
    assert len(lines) == 5
    assert lines[0].split(",")[-1] == "reason"
    assert "nan" not in ",".join(lines).lower().split(",")


def _tolerance(data: dict, *extra: str) -> tuple[Run, dict | None]:
    write("tol.yaml", data)
    run = cli("tolerance", "tol.yaml", "--samples", "64", "--format", "json", *extra)
    record = json.loads(run.out) if run.code in (0, 1) else None
    if record is not None:
        assert finite_tree(record) == []
    return run, record


@pytest.mark.parametrize(
    "data",
    [
        # at Lwe 10.1 mm a crown must exceed 85.08 mm to drop the ends less than 2 % of Dwe
        spec(CYL, roller_length="10 mm ± 0.1 mm", roller_profile={"crown_radius": "86 mm"}),
        spec(CYL, misalignment="0 mrad ± 1 mrad", roller_profile="none"),
        spec(CYL, operating_clearance="0 µm ± 20 µm"),
        spec(TAP, roller_included_angle="4 deg ± 1 deg", contact_angle="14 deg ± 0.5 deg"),
    ],
    ids=["length-near-crown", "misalignment-across-0", "clearance-across-0", "tapered-angles"],
)
def test_tolerance_studies_finish_finite(data):
    run, record = _tolerance(data)
    assert run.code in (0, 1), run.err
    assert "max_element_load" in record["results"]


def test_tolerance_band_past_the_crown_limit_is_one_line():
    data = spec(CYL, roller_length="10 mm ± 0.5 mm", roller_profile={"crown_radius": "86 mm"})
    text = dump(data)
    run, _ = _tolerance(data)
    refused(run, "roller_length", line_of(text, "roller_length"))


def test_tolerance_box_with_impossible_designs_fails_with_the_reason():
    run, record = _tolerance(spec(CYL, misalignment="0.3 rad ± 0.2 rad"), "--method",
                             "monte-carlo")
    assert run.code == 1
    assert record["impossible_in_box"]["reason"].startswith("misalignment:")
    assert 0 < record["impossible_in_box"]["fraction"] < 1
    run, _ = _tolerance(spec(CYL, misalignment="0.5 rad ± 0.2 rad"))
    refused(run, "misalignment", line_of(dump(spec(CYL, misalignment="0")), "misalignment"))


@pytest.mark.parametrize(
    ("data", "name"),
    [(spec(CYL, misalignment="0.5 mrad", roller_profile={"crown_radius": "1 m"}), "cyl"),
     (spec(PAIR, tilting_moment="20 N*m"), "pair")],
)
def test_report_is_one_html_file_with_finite_numbers(data, name):
    write(f"{name}.yaml", data)
    run = cli("report", f"{name}.yaml", "--output", f"{name}.html")
    assert run.code == 0, run.err
    html = Path(f"{name}.html").read_text(encoding="utf-8")
    assert html.lstrip().lower().startswith("<!doctype html")
    assert not re.search(r">\s*-?(nan|inf|infinity)\s*<", html, re.IGNORECASE)
    assert "max_element_load" in html


def test_report_of_a_bad_spec_writes_nothing():
    write("bad.yaml", spec(CYL, roller_profile={"crown_radius": "4 mm"}))
    run = cli("report", "bad.yaml", "--output", "bad.html")
    refused(run, "roller_profile.crown_radius")
    assert not Path("bad.html").exists()


def test_report_never_replaces_its_spec():
    text = dump(TAP)
    write("t.yaml", text)
    run = cli("report", "t.yaml", "--output", "./t.yaml")
    assert run.code == 2
    assert len(run.lines()) == 1
    assert Path("t.yaml").read_text(encoding="utf-8") == text


def test_schema_knows_the_roller_fields():
    run = cli("schema", "--kind", "rolling-bearing")
    assert run.code == 0
    props = json.loads(run.out)["properties"]
    for key in ("method", "operating_clearance", "tilting_moment", "misalignment",
                "roller_profile", "laminae", "roller_included_angle"):
        assert key in props, key
    assert props["laminae"]["anyOf"][0]["minimum"] == 10
    assert props["laminae"]["anyOf"][0]["maximum"] == 200
    assert "iso-16281" in props["method"]["enum"]


def test_schema_accepts_the_examples():
    jsonschema = pytest.importorskip("jsonschema")
    schema = json.loads(cli("schema", "--kind", "rolling-bearing").out)
    validator = jsonschema.Draft202012Validator(schema)
    for data in (CYL, TAP, NEEDLE, PAIR, spec(CYL, roller_profile={"crown_radius": "1 m"})):
        assert list(validator.iter_errors(data)) == []
    assert list(validator.iter_errors(spec(CYL, laminae=5)))


def test_mounted_template_passes_check():
    run = cli("new", "rolling-bearing", "--method", "iso-16281")
    assert run.code == 0
    write("tpl.yaml", run.out)
    assert cli("check", "tpl.yaml", "--jobs", "1").code == 0


def test_catalogue_designation_with_the_geometry():
    data = {"kind": "rolling-bearing", "method": "iso-16281", "designation": "NU206 ECP",
            "catalogue": str(CATALOGUE), "roller_count": 13, "roller_diameter": "7.5 mm",
            "roller_length": "10 mm", "operating_clearance": "15 µm",
            "misalignment": "0.5 mrad", "radial_load": "8 kN", "speed": "3000 rpm"}
    res, _ = solve(data)
    assert res["dynamic_load_rating"] == pytest.approx(44000)
    estimated, record = solve(spec(data, roller_count=DROP, roller_diameter=DROP,
                                   roller_length=DROP), name="nogeo.yaml")
    assert any("estimated" in w for w in record["warnings"])
    assert estimated["dynamic_load_rating"] == pytest.approx(44000)
    text = dump(spec(data, roller_diameter=DROP, roller_length=DROP))
    refused(cli("solve", write("part.yaml", text)), "roller_diameter")
    text = dump(spec(data, roller_count=DROP, roller_diameter=DROP, roller_length=DROP,
                     laminae=5))
    refused(cli("solve", write("lam.yaml", text)), "laminae", line_of(text, "laminae"))
