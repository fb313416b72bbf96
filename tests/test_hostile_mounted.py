"""Hostile input for ``kind: rolling-bearing`` with ``method: iso-16281`` through the CLI.

The contract under test: bad input gives exit status 2 and one line per cause on
stderr naming the field (never a traceback, a hang or nan); good input gives finite
results and exit status 0 or 1. Where the right answer is a judgement call, only the
contract is asserted.
"""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from bearingcalc.cli import app

CATALOGUE = Path(__file__).resolve().parents[1] / "specs" / "catalogues" / "example.csv"

BASE: dict = {
    "kind": "rolling-bearing",
    "name": "hostile mounted",
    "type": "deep-groove",
    "method": "iso-16281",
    "dynamic_load_rating": "14.8 kN",
    "static_load_rating": "7.8 kN",
    "ball_count": 9,
    "ball_diameter": "7.938 mm",
    "pitch_diameter": "38.5 mm",
    "inner_groove_conformity": 0.52,
    "outer_groove_conformity": 0.53,
    "operating_clearance": "10 µm",
    "tilting_moment": "2 N*m",
    "radial_load": "2 kN",
    "axial_load": "300 N",
    "speed": "3000 rpm",
    "lubrication": {"viscosity": "32 mm^2/s"},
    "contamination_factor": 0.5,
    "limits": {"min_rating_life": "1500 h"},
}

ANGULAR = {
    **{k: v for k, v in BASE.items() if k not in ("operating_clearance", "tilting_moment")},
    "type": "angular-contact",
    "contact_angle": "25 deg",
    "axial_load": "1.5 kN",
}

DROP = object()


def spec_with(base: dict, **changes) -> dict:
    spec = dict(base)
    for key, value in changes.items():
        if value is DROP:
            spec.pop(key, None)
        else:
            spec[key] = value
    return spec


def run(tmp_path: Path, spec: dict | str, *args: str):
    path = tmp_path / "spec.yaml"
    text = (
        spec if isinstance(spec, str) else yaml.safe_dump(spec, allow_unicode=True, sort_keys=False)
    )
    path.write_text(text, encoding="utf-8")
    argv = [a.replace("{spec}", str(path)).replace("{tmp}", str(tmp_path)) for a in args]
    if "{spec}" not in args:
        argv.append(str(path))
    return CliRunner().invoke(app, argv, catch_exceptions=True)


def assert_no_crash(result) -> None:
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(
        result.exception
    )
    text = result.output
    assert "Traceback" not in text
    assert "internal error" not in text.lower()


def assert_refused(result, field: str) -> None:
    """Exit 2, one line on stderr, naming the field."""
    assert_no_crash(result)
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, result.stderr
    assert field in message_after_location(lines[0]), lines[0]


def message_after_location(line: str) -> str:
    """The line without its 'path:line: ' prefix (the path holds the test's own name)."""
    return line.split("spec.yaml:", 1)[-1]


def finite_numbers(value) -> bool:
    if isinstance(value, bool):
        return True
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(finite_numbers(v) for v in value.values())
    if isinstance(value, list):
        return all(finite_numbers(v) for v in value)
    return True


def assert_solved(result) -> dict:
    """Exit 0 or 1, JSON results all finite."""
    assert_no_crash(result)
    assert result.exit_code in (0, 1), result.output
    assert "nan" not in result.stdout.lower().replace("name", "")
    data = json.loads(result.stdout)
    assert finite_numbers(data), data
    return data["results"]


def assert_contract(result) -> None:
    """Either a clean refusal (exit 2, one line) or finite results."""
    assert_no_crash(result)
    if result.exit_code == 2:
        lines = [line for line in result.stderr.splitlines() if line.strip()]
        assert lines, result.output
        assert all(line.count(":") >= 2 for line in lines), result.stderr
    else:
        assert_solved(result)


# ---------------------------------------------------------------- refused fields

REFUSED = [
    ("clearance-huge", {"operating_clearance": "1 m"}, "operating_clearance"),
    ("preload-beyond-grooves", {"operating_clearance": "-0.5 mm"}, "operating_clearance"),
    ("clearance-in-newton", {"operating_clearance": "10 N"}, "operating_clearance"),
    ("clearance-string", {"operating_clearance": "lots"}, "operating_clearance"),
    ("clearance-list", {"operating_clearance": ["10 µm", "20 µm"]}, "operating_clearance"),
    ("clearance-null", {"operating_clearance": None}, "operating_clearance"),
    ("clearance-missing-deep-groove", {"operating_clearance": DROP}, "operating_clearance"),
    ("clearance-bare-number", {"operating_clearance": 0.00001}, "operating_clearance"),
    ("clearance-nan", {"operating_clearance": ".nan mm"}, "operating_clearance"),
    ("clearance-inf", {"operating_clearance": "inf mm"}, "operating_clearance"),
    ("moment-in-mm", {"tilting_moment": "2 mm"}, "tilting_moment"),
    ("moment-in-newton", {"tilting_moment": "2 N"}, "tilting_moment"),
    ("moment-string", {"tilting_moment": "big"}, "tilting_moment"),
    ("moment-list", {"tilting_moment": [1, 2]}, "tilting_moment"),
    ("moment-nan", {"tilting_moment": "nan N*m"}, "tilting_moment"),
    ("misalignment-in-mm", {"tilting_moment": DROP, "misalignment": "1 mm"}, "misalignment"),
    ("misalignment-string", {"tilting_moment": DROP, "misalignment": "crooked"}, "misalignment"),
    ("misalignment-inf", {"tilting_moment": DROP, "misalignment": "inf rad"}, "misalignment"),
    ("moment-and-misalignment", {"misalignment": "1 mrad"}, "misalignment"),
    ("method-unknown", {"method": "iso-16282"}, "method"),
    ("method-null", {"method": None}, "method"),
    ("method-list", {"method": ["iso-16281"]}, "method"),
    ("ball-count-200", {"ball_count": 200}, "ball_count"),
    ("ball-count-zero", {"ball_count": 0}, "ball_count"),
    ("ball-count-negative", {"ball_count": -3}, "ball_count"),
    ("ball-count-fraction", {"ball_count": 8.5}, "ball_count"),
    ("ball-count-string", {"ball_count": "nine"}, "ball_count"),
    ("ball-larger-than-pitch", {"ball_diameter": "40 mm"}, "ball_diameter"),
    ("ball-diameter-zero", {"ball_diameter": "0 mm"}, "ball_diameter"),
    ("conformity-half", {"inner_groove_conformity": 0.5}, "inner_groove_conformity"),
    ("conformity-below-half", {"outer_groove_conformity": 0.49}, "outer_groove_conformity"),
    ("conformity-missing", {"outer_groove_conformity": DROP}, "outer_groove_conformity"),
    ("conformity-string", {"inner_groove_conformity": "tight"}, "inner_groove_conformity"),
    ("method-spherical-roller", {"type": "spherical-roller"}, "method"),
    ("method-thrust-ball", {"type": "thrust-ball"}, "method"),
    ("method-self-aligning-ball", {"type": "self-aligning-ball"}, "method"),
    (
        "pair-without-setting",
        {
            "arrangement": "back-to-back",
            "type": "angular-contact",
            "contact_angle": "25 deg",
            "operating_clearance": DROP,
            "tilting_moment": DROP,
            "axial_load": "1 kN",
            "width": "16 mm",
        },
        "setting",
    ),
    ("radial-load-in-mm", {"radial_load": "2 mm"}, "radial_load"),
    ("axial-load-negative", {"axial_load": "-300 N"}, "axial_load"),
]


@pytest.mark.parametrize(("changes", "field"), [pytest.param(c, f, id=i) for i, c, f in REFUSED])
def test_refused_on_solve(tmp_path, changes, field):
    assert_refused(run(tmp_path, spec_with(BASE, **changes), "solve", "--format", "json"), field)


REFUSED_ANGULAR = [
    ("ac-only-radial", {"axial_load": DROP}, "axial_load"),
    ("ac-zero-axial", {"axial_load": "0 N"}, "axial_load"),
    ("ac-with-clearance", {"operating_clearance": "10 µm"}, "operating_clearance"),
    ("ac-contact-angle-90", {"contact_angle": "90 deg"}, "contact_angle"),
    ("ac-contact-angle-in-mm", {"contact_angle": "25 mm"}, "contact_angle"),
    ("ac-moment-pulls-off", {"tilting_moment": "500 N*m"}, "axial_load"),
]


@pytest.mark.parametrize(
    ("changes", "field"), [pytest.param(c, f, id=i) for i, c, f in REFUSED_ANGULAR]
)
def test_refused_angular_contact(tmp_path, changes, field):
    assert_refused(run(tmp_path, spec_with(ANGULAR, **changes), "solve", "--format", "json"), field)


def test_refused_on_check_names_field_in_table(tmp_path):
    result = run(tmp_path, spec_with(BASE, operating_clearance="-0.5 mm"), "check")
    assert_no_crash(result)
    assert result.exit_code == 2
    assert "operating_clearance" in message_after_location(result.output)


def test_duty_cycle_with_method_refused(tmp_path):
    spec = spec_with(
        BASE,
        radial_load=DROP,
        axial_load=DROP,
        tilting_moment=DROP,
        duty_cycle=[
            {"name": "a", "time": "50 %", "radial_load": "2 kN", "axial_load": "300 N"},
            {"name": "b", "time": "50 %", "radial_load": "3 kN", "axial_load": "100 N"},
        ],
    )
    assert_refused(run(tmp_path, spec, "solve", "--format", "json"), "method")


def test_duty_cycle_bin_with_mounted_field_refused(tmp_path):
    spec = spec_with(
        BASE,
        radial_load=DROP,
        axial_load=DROP,
        duty_cycle=[
            {"name": "a", "time": "50 %", "radial_load": "2 kN", "tilting_moment": "3 N*m"},
            {"name": "b", "time": "50 %", "radial_load": "3 kN"},
        ],
    )
    result = run(tmp_path, spec, "solve", "--format", "json")
    assert_no_crash(result)
    assert result.exit_code == 2


def test_mounted_field_without_method_refused(tmp_path):
    """operating_clearance with the catalogue method would be silently ignored."""
    result = run(tmp_path, spec_with(BASE, method=DROP), "solve", "--format", "json")
    assert_refused(result, "operating_clearance")


# ---------------------------------------------------------------- solved (judgement: contract only)

CONTRACT = [
    ("clearance-zero", {"operating_clearance": "0 µm"}),
    ("preload-small", {"operating_clearance": "-5 µm"}),
    ("preload-near-groove-distance", {"operating_clearance": "-390 µm"}),
    ("clearance-near-groove-distance", {"operating_clearance": "390 µm"}),
    ("ball-count-1", {"ball_count": 1}),
    ("ball-count-2", {"ball_count": 2}),
    ("ball-count-3", {"ball_count": 3}),
    ("ball-count-15-max", {"ball_count": 15}),
    ("conformity-barely-above-half", {"inner_groove_conformity": 0.5000001}),
    ("conformity-0.99", {"inner_groove_conformity": 0.99, "outer_groove_conformity": 0.99}),
    ("zero-loads", {"radial_load": "0 N", "axial_load": "0 N", "tilting_moment": DROP}),
    (
        "zero-loads-with-preload",
        {
            "radial_load": "0 N",
            "axial_load": "0 N",
            "tilting_moment": DROP,
            "operating_clearance": "-10 µm",
        },
    ),
    ("only-axial-with-clearance", {"radial_load": "0 N", "tilting_moment": DROP}),
    ("only-axial-missing-radial", {"radial_load": DROP, "tilting_moment": DROP}),
    ("only-moment", {"radial_load": "0 N", "axial_load": "0 N"}),
    ("huge-moment", {"tilting_moment": "1e6 N*m"}),
    ("negative-moment", {"tilting_moment": "-2 N*m"}),
    ("misalignment-0.5-rad", {"tilting_moment": DROP, "misalignment": "0.5 rad"}),
    ("misalignment-small", {"tilting_moment": DROP, "misalignment": "1 mrad"}),
    ("misalignment-negative", {"tilting_moment": DROP, "misalignment": "-2 mrad"}),
    ("huge-radial-load", {"radial_load": "10 MN"}),
    ("tiny-radial-load", {"radial_load": "1 mN", "axial_load": "0 N", "tilting_moment": DROP}),
    ("inner-outer-speed", {"speed": DROP, "inner_speed": "3000 rpm", "outer_speed": "-500 rpm"}),
    ("speed-zero", {"speed": "0 rpm"}),
    (
        "method-iso-281-explicit",
        {"method": "iso-281", "operating_clearance": DROP, "tilting_moment": DROP},
    ),
]


@pytest.mark.parametrize("changes", [pytest.param(c, id=i) for i, c in CONTRACT])
def test_contract_on_solve(tmp_path, changes):
    assert_contract(run(tmp_path, spec_with(BASE, **changes), "solve", "--format", "json"))


CONTRACT_ANGULAR = [
    ("ac-contact-angle-0", {"contact_angle": "0 deg"}),
    ("ac-contact-angle-1", {"contact_angle": "1 deg"}),
    ("ac-contact-angle-89", {"contact_angle": "89 deg"}),
    ("ac-only-axial", {"radial_load": "0 N"}),
    ("ac-small-moment", {"tilting_moment": "1 N*m"}),
    ("ac-misalignment", {"misalignment": "2 mrad"}),
    ("ac-tiny-axial", {"axial_load": "1 mN"}),
]


@pytest.mark.parametrize("changes", [pytest.param(c, id=i) for i, c in CONTRACT_ANGULAR])
def test_contract_angular_contact(tmp_path, changes):
    assert_contract(run(tmp_path, spec_with(ANGULAR, **changes), "solve", "--format", "json"))


def test_example_solves_finite(tmp_path):
    results = assert_solved(run(tmp_path, BASE, "solve", "--format", "json"))
    assert results["loaded_elements"] == 9


def test_only_axial_deep_groove_loads_every_ball(tmp_path):
    """Pure axial load on a deep-groove bearing with clearance: equal balls, contact angle > 0."""
    results = assert_solved(
        run(
            tmp_path,
            spec_with(BASE, radial_load="0 N", tilting_moment=DROP),
            "solve",
            "--format",
            "json",
        )
    )
    loads = [results[f"element_{k}_load"] for k in range(1, 10)]
    assert max(loads) == pytest.approx(min(loads), rel=1e-6)
    assert results["operating_contact_angle_min"] > 0


def test_zero_load_no_nan_life(tmp_path):
    result = run(
        tmp_path,
        spec_with(BASE, radial_load="0 N", axial_load="0 N", tilting_moment=DROP),
        "solve",
        "--format",
        "json",
    )
    assert_contract(result)


def test_catalogue_designation_with_method(tmp_path):
    spec = spec_with(
        BASE,
        dynamic_load_rating=DROP,
        static_load_rating=DROP,
        catalogue=str(CATALOGUE),
        designation="6205",
        maker="SKF",
    )
    assert_solved(run(tmp_path, spec, "solve", "--format", "json"))


def test_catalogue_angular_designation_with_method(tmp_path):
    spec = spec_with(
        ANGULAR,
        dynamic_load_rating=DROP,
        static_load_rating=DROP,
        contact_angle=DROP,
        catalogue=str(CATALOGUE),
        designation="7205 BEP",
        maker="SKF",
    )
    assert_contract(run(tmp_path, spec, "solve", "--format", "json"))


def test_catalogue_roller_designation_with_ball_geometry_refused(tmp_path):
    """A cylindrical roller bearing from the catalogue is solved as mounted, but not with
    balls: each ball field, and the thrust an NU bearing cannot carry, is its own line."""
    spec = spec_with(
        BASE,
        type=DROP,
        dynamic_load_rating=DROP,
        static_load_rating=DROP,
        catalogue=str(CATALOGUE),
        designation="NU205 ECP",
    )
    result = run(tmp_path, spec, "solve", "--format", "json")
    assert_no_crash(result)
    assert result.exit_code == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    fields = [line.split(": ")[1] for line in lines]
    assert len(fields) == len(set(fields)), result.stderr
    assert {"ball_count", "ball_diameter", "axial_load"} <= set(fields), result.stderr


def test_check_example_passes(tmp_path):
    result = run(tmp_path, BASE, "check")
    assert_no_crash(result)
    assert result.exit_code in (0, 1)


# ---------------------------------------------------------------- sweeps


def sweep_rows(result) -> list[dict]:
    assert_no_crash(result)
    assert result.exit_code in (0, 1), result.output
    assert "nan" not in result.stdout.lower()
    assert "inf" not in result.stdout.lower().replace("info", "")
    return list(csv.DictReader(io.StringIO(result.stdout)))


SWEEPS = [
    ("clearance-fine", BASE, "operating_clearance=-20um:60um:9"),
    ("moment-wide", BASE, "tilting_moment=-200N*m:200N*m:9"),
    ("radial-through-zero", BASE, "radial_load=0N:5kN:6"),
    ("axial-through-zero", BASE, "axial_load=0N:3kN:7"),
    ("ball-count-fitting", BASE, "ball_count=1:15:15"),
    ("ac-axial-through-zero", ANGULAR, "axial_load=0N:2kN:5"),
    ("ac-moment-wide", {**ANGULAR, "tilting_moment": "1 N*m"}, "tilting_moment=0N*m:500N*m:6"),
    ("ac-contact-angle-in-table", ANGULAR, "contact_angle=20deg:45deg:6"),
    (
        "misalignment",
        spec_with(BASE, tilting_moment=DROP, misalignment="0 rad"),
        "misalignment=0rad:5mrad:3",
    ),
    ("ac-axial-low-end", ANGULAR, "axial_load=0N:10N:3"),
]


@pytest.mark.parametrize(("spec", "vary"), [pytest.param(s, v, id=i) for i, s, v in SWEEPS])
def test_sweep_gaps_not_nan(tmp_path, spec, vary):
    rows = sweep_rows(run(tmp_path, spec, "sweep", "--vary", vary, "-f", "csv", "{spec}"))
    assert rows


@pytest.mark.parametrize(
    ("vary", "corner", "bound"),
    [
        ("operating_clearance=-500um:500um:11", "operating_clearance = -500um", "396.9 µm"),
        ("ball_count=10:20:11", "ball_count = 20", "at most 15 fit"),
    ],
)
def test_sweep_past_a_spec_rule_names_the_corner_and_the_bound(tmp_path, vary, corner, bound):
    """A sweep crossing one of the spec's own rules (a clearance past the grooves'
    distance (fi + fo − 1)·Dw, more balls than fit on the pitch circle) is refused in one
    line that names the corner and the bound to narrow the range to."""
    result = run(tmp_path, BASE, "sweep", "--vary", vary, "-f", "csv", "{spec}")
    assert_no_crash(result)
    assert result.exit_code == 2 and not result.stdout
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and corner in lines[0] and bound in lines[0], result.stderr


def test_sweep_grid_clearance_moment(tmp_path):
    sweep_rows(
        run(
            tmp_path,
            BASE,
            "sweep",
            "--vary",
            "operating_clearance=-50um:50um:3",
            "--vary",
            "tilting_moment=0N*m:100N*m:3",
            "-f",
            "csv",
            "{spec}",
        )
    )


def test_sweep_json_lines_finite(tmp_path):
    result = run(
        tmp_path, ANGULAR, "sweep", "--vary", "axial_load=0N:2kN:5", "-f", "json", "{spec}"
    )
    assert_no_crash(result)
    assert result.exit_code in (0, 1), result.output
    for line in result.stdout.splitlines():
        if line.strip():
            assert finite_numbers(json.loads(line))


def test_sweep_bad_unit_refused(tmp_path):
    result = run(tmp_path, BASE, "sweep", "--vary", "operating_clearance=0N:10N:3", "{spec}")
    assert_no_crash(result)
    assert result.exit_code == 2
    assert "operating_clearance" in message_after_location(result.stderr)


# ---------------------------------------------------------------- tolerance


def tolerance_json(tmp_path, spec):
    result = run(tmp_path, spec, "tolerance", "-n", "2000", "--format", "json", "-j", "1", "{spec}")
    assert_no_crash(result)
    assert result.exit_code in (0, 1), result.output
    assert finite_numbers(json.loads(result.stdout))
    return result


def tolerance_contract(tmp_path, spec, field):
    """A band crossing a bound: a study (exit 0/1, finite) or one line naming the field."""
    result = run(tmp_path, spec, "tolerance", "-n", "2000", "--format", "json", "-j", "1", "{spec}")
    assert_no_crash(result)
    if result.exit_code == 2:
        lines = [line for line in result.stderr.splitlines() if line.strip()]
        assert len(lines) == 1 and field in message_after_location(lines[0]), result.stderr
    else:
        assert result.exit_code in (0, 1), result.output
        assert finite_numbers(json.loads(result.stdout))


def test_tolerance_clearance(tmp_path):
    tolerance_json(tmp_path, spec_with(BASE, operating_clearance="10 µm ± 5 µm"))


def test_tolerance_clearance_crosses_groove_edge(tmp_path):
    tolerance_contract(
        tmp_path, spec_with(BASE, operating_clearance="390 µm ± 20 µm"), "operating_clearance"
    )


def test_tolerance_clearance_crosses_zero(tmp_path):
    tolerance_json(tmp_path, spec_with(BASE, operating_clearance="0 µm ± 10 µm"))


def test_tolerance_moment_and_loads(tmp_path):
    tolerance_json(
        tmp_path, spec_with(BASE, tilting_moment="2 N*m ± 1 N*m", radial_load="2 kN ± 0.2 kN")
    )


def test_tolerance_angular_axial_crosses_zero(tmp_path):
    tolerance_contract(tmp_path, spec_with(ANGULAR, axial_load="100 N ± 200 N"), "axial_load")


def test_tolerance_angular_axial_box_crosses_equilibrium_edge(tmp_path):
    """Axial loads 0.3 to 1.7 kN under 2 kN radial: some corners have no equilibrium."""
    result = run(
        tmp_path,
        spec_with(ANGULAR, axial_load="1 kN ± 0.7 kN"),
        "tolerance",
        "-n",
        "2000",
        "--format",
        "json",
        "-j",
        "1",
        "{spec}",
    )
    assert_contract(result)


def test_tolerance_misalignment(tmp_path):
    tolerance_json(tmp_path, spec_with(BASE, tilting_moment=DROP, misalignment="1 mrad ± 0.5 mrad"))


def test_tolerance_conformity_to_half(tmp_path):
    tolerance_contract(
        tmp_path, spec_with(BASE, inner_groove_conformity="0.505 ± 0.01"), "inner_groove_conformity"
    )


# ---------------------------------------------------------------- report and json


def test_report_writes_html(tmp_path):
    out = tmp_path / "r.html"
    result = run(tmp_path, BASE, "report", "-o", str(out), "{spec}")
    assert_no_crash(result)
    assert result.exit_code in (0, 1), result.output
    html = out.read_text(encoding="utf-8")
    assert "nan" not in html.lower().replace("nanc", "")


def test_report_angular(tmp_path):
    out = tmp_path / "r.html"
    result = run(
        tmp_path, spec_with(ANGULAR, tilting_moment="1 N*m"), "report", "-o", str(out), "{spec}"
    )
    assert_no_crash(result)
    assert result.exit_code in (0, 1), result.output
    assert out.exists()


def test_report_bad_spec_leaves_no_file(tmp_path):
    out = tmp_path / "r.html"
    result = run(
        tmp_path, spec_with(BASE, operating_clearance="-1 mm"), "report", "-o", str(out), "{spec}"
    )
    assert_no_crash(result)
    assert result.exit_code == 2
    assert not out.exists()
    assert "operating_clearance" in message_after_location(result.stderr)


def test_report_one_ball(tmp_path):
    out = tmp_path / "r.html"
    result = run(tmp_path, spec_with(BASE, ball_count=1), "report", "-o", str(out), "{spec}")
    assert_no_crash(result)
    assert result.exit_code in (0, 1, 2), result.output


# ---------------------------------------------------------------- defects found (xfail until fixed)


@pytest.mark.parametrize("field", ["ball_count", "ball_diameter", "pitch_diameter"])
def test_missing_geometry_one_line(tmp_path, field):
    assert_refused(
        run(tmp_path, spec_with(BASE, **{field: DROP}), "solve", "--format", "json"), field
    )


@pytest.mark.parametrize("axial", ["1 mN", "5 N", "20 N", "100 N"])
def test_angular_contact_near_zero_axial_refused(tmp_path, axial):
    """Once solved to spurious states (balls pressed past their groove's bottom, a ring
    tilted 30 mrad with balls at 85°) while 0 N and 100 N were refused: every load below
    the least that holds the balls on their shoulders is refused alike."""
    assert_refused(
        run(tmp_path, spec_with(ANGULAR, axial_load=axial), "solve", "--format", "json"),
        "axial_load",
    )


def test_deep_groove_no_equilibrium_message_fits_type(tmp_path):
    result = run(tmp_path, spec_with(BASE, ball_count=1), "solve", "--format", "json")
    assert_no_crash(result)
    assert result.exit_code == 2
    assert "angular-contact" not in result.stderr


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"tilting_moment": "1e6 N*m"}, "tilting_moment"),
        ({"tilting_moment": DROP, "misalignment": "0.5 rad"}, "misalignment"),
    ],
)
def test_moment_beyond_hertz_refused(tmp_path, changes, field):
    assert_refused(run(tmp_path, spec_with(BASE, **changes), "solve", "--format", "json"), field)


def test_ring_pushed_over_its_balls_names_the_clearance(tmp_path):
    spec = spec_with(BASE, operating_clearance="410 µm", tilting_moment=DROP)
    assert_refused(run(tmp_path, spec, "solve", "--format", "json"), "operating_clearance")


def test_contact_angle_stays_below_right_angle(tmp_path):
    result = run(
        tmp_path, spec_with(BASE, operating_clearance="390 µm"), "solve", "--format", "json"
    )
    assert_no_crash(result)
    if result.exit_code != 2:
        assert assert_solved(result)["operating_contact_angle_max"] < math.pi / 2


def test_pure_moment_solves(tmp_path):
    assert_solved(
        run(
            tmp_path,
            spec_with(BASE, radial_load="0 N", axial_load="0 N"),
            "solve",
            "--format",
            "json",
        )
    )


def test_misalignment_beyond_a_turn_names_misalignment(tmp_path):
    spec = spec_with(BASE, tilting_moment=DROP, misalignment="7 rad")
    assert_refused(run(tmp_path, spec, "solve", "--format", "json"), "misalignment")


@pytest.mark.parametrize(
    "changes",
    [
        pytest.param({"tilting_moment": None}, id="moment-null"),
        pytest.param({"tilting_moment": DROP, "misalignment": None}, id="misalignment-null"),
        pytest.param({"operating_clearance": "0.0004 in"}, id="clearance-inch"),
        pytest.param({"tilting_moment": DROP, "misalignment": "0.1 deg"}, id="misalignment-deg"),
        pytest.param({"reliability": "95 %"}, id="reliability"),
    ],
)
def test_more_inputs_contract(tmp_path, changes):
    assert_contract(run(tmp_path, spec_with(BASE, **changes), "solve", "--format", "json"))
