"""Hostile tests of matched pairs solved as mounted (ISO/TS 16281), written from the docs.

Every case builds a spec of `kind: rolling-bearing`, `method: iso-16281` from one of two
bases (a back-to-back pair of 40° angular-contact ball bearings preloaded to 300 N and a
face-to-face pair of tapered roller bearings set with 15 µm of end play, after the two
example specs) and runs the CLI on it. Bad input must give one line per problem,
`file:line: field: ...`, exit status 2 and no traceback; a valid design must give finite
results that obey statics and symmetry, which need none of the product's formulas:

- the two bearings' axial loads differ by the applied axial load (bearing 1 carries the
  thrust of a positive one) and their radial loads add up to the applied radial load when
  no moment acts;
- each bearing's loads are the sums of its balls' load components;
- with no axial load the pair is symmetric, and a moment's mirror image swaps the bearings;
- more preload makes the pair stiffer axially, and the pair outlives neither bearing;
- an end play and the preload it gives are one and the same setting.

Cases that fail because the product is wrong are kept as strict xfails naming the defect.
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import math
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from bearingcalc.cli.app import app

RUNNER = CliRunner()
CATALOGUE = Path(__file__).resolve().parents[1] / "specs" / "catalogues" / "example.csv"

BALL = {
    "kind": "rolling-bearing",
    "name": "hostile ball pair",
    "type": "angular-contact",
    "arrangement": "back-to-back",
    "method": "iso-16281",
    "contact_angle": "40 deg",
    "dynamic_load_rating": "24 kN",
    "static_load_rating": "15.6 kN",
    "ball_count": "12",
    "ball_diameter": "9.525 mm",
    "pitch_diameter": "46 mm",
    "inner_groove_conformity": "0.52",
    "outer_groove_conformity": "0.53",
    "width": "16 mm",
    "setting": "{preload: 300 N}",
    "radial_load": "3 kN",
    "axial_load": "1.5 kN",
    "speed": "3000 rpm",
    "lubrication": "{viscosity: 32 mm^2/s}",
    "contamination_factor": "0.5",
    "limits": "{min_rating_life: 10000 h}",
}

TAPERED = {
    "kind": "rolling-bearing",
    "name": "hostile tapered pair",
    "type": "tapered-roller",
    "arrangement": "face-to-face",
    "method": "iso-16281",
    "contact_angle": "14 deg",
    "dynamic_load_rating": "54 kN",
    "static_load_rating": "63 kN",
    "roller_count": "17",
    "roller_diameter": "7.5 mm",
    "roller_length": "14 mm",
    "pitch_diameter": "45 mm",
    "roller_included_angle": "4 deg",
    "width": "17.25 mm",
    "setting": "{end_play: 15 µm}",
    "radial_load": "6 kN",
    "axial_load": "2 kN",
    "speed": "1500 rpm",
    "lubrication": "{viscosity: 68 mm^2/s}",
    "contamination_factor": "0.5",
    "limits": "{min_rating_life: 20000 h}",
}

BASES = {"ball": BALL, "tapered": TAPERED}
DROP = None  # a change that leaves the key out
ERROR_LINE = re.compile(r"^(?P<file>.+?):(?P<line>\d+): (?P<field>[^\s:]+): \S.*$")


def build(base: dict[str, str], **changes: str | None) -> tuple[str, dict[str, int]]:
    """The spec's text with `changes` (None drops a key, a new key goes last) and each
    top-level key's line."""
    fields = dict(base)
    for key, value in changes.items():
        if value is None:
            fields.pop(key, None)
        else:
            fields[key] = value
    lines = {key: number for number, key in enumerate(fields, start=1)}
    text = "".join(f"{key}: {value}\n" for key, value in fields.items())
    return text, lines


def write(tmp_path: Path, text: str, name: str = "spec.yaml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def invoke(*args: str):
    result = RUNNER.invoke(app, [str(arg) for arg in args], prog_name="bearingcalc")
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"internal error: {result.exception!r}\n{result.output}")
    assert "Traceback" not in result.output
    return result


def solve(tmp_path: Path, base: dict[str, str], **changes: str | None):
    text, lines = build(base, **changes)
    path = write(tmp_path, text)
    return invoke("solve", path, "--format", "json"), path, lines


def results_of(result) -> dict[str, float | None]:
    assert result.exit_code in (0, 1), result.stderr
    assert result.stderr.strip() == ""
    return json.loads(result.stdout)["results"]


def solved(tmp_path: Path, base: dict[str, str], **changes: str | None):
    result, _, _ = solve(tmp_path, base, **changes)
    return results_of(result)


def error_lines(result, named: bool = True) -> list[str]:
    assert result.exit_code == 2, (result.exit_code, result.stdout[-400:], result.stderr)
    assert result.stdout.strip() == ""
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert lines, "exit status 2 without a message"
    for line in lines:
        assert ERROR_LINE.match(line) if named else re.match(r"^.+?:\d+: \S", line), line
        assert "nan" not in line.split(": ", 2)[-1].split()
    return lines


def one_error(result, path: Path, line: int | None, field: str) -> str:
    """The one line of a refused spec, checked for its file, line and field."""
    lines = error_lines(result)
    assert len(lines) == 1, lines
    match = ERROR_LINE.match(lines[0])
    assert match["file"] == str(path)
    if field.endswith("*"):  # the field or one of its keys
        assert match["field"].startswith(field[:-1]), lines[0]
    else:
        assert match["field"] == field, lines[0]
    if line is not None:
        assert int(match["line"]) == line, lines[0]
    return lines[0]


def assert_finite(results: dict[str, float | None], unbounded: tuple[str, ...] = ()) -> None:
    for key, value in results.items():
        if value is None and key in unbounded:
            continue
        assert isinstance(value, int | float), (key, value)
        assert math.isfinite(value), (key, value)


def close(a: float, b: float, rel: float = 1e-6, abs_: float = 1e-6) -> bool:
    return math.isclose(a, b, rel_tol=rel, abs_tol=abs_)


# --------------------------------------------------------------------------------------
# Every new field: wrong types, units, signs, zero, huge values, YAML oddities
# --------------------------------------------------------------------------------------

REFUSED_SETTINGS = {
    "preload zero": ("{preload: 0 N}", "setting.preload"),
    "preload negative": ("{preload: -300 N}", "setting.preload"),
    "preload bare number": ("{preload: 300}", "setting.preload"),
    "preload a length": ('{preload: "300 mm"}', "setting.preload"),
    "preload a torque": ("{preload: 300 N*m}", "setting.preload"),
    "preload a mass": ("{preload: 30 kg}", "setting.preload"),
    "preload nan": ("{preload: nan N}", "setting.preload"),
    "preload inf": ("{preload: inf N}", "setting.preload"),
    "preload beyond 1e6 kN": ("{preload: 1e9 kN}", "setting.preload"),
    "preload below 1 µN": ("{preload: 1e-12 N}", "setting.preload"),
    "preload band crosses zero": ("{preload: 300 N ± 400 N}", "setting.preload"),
    "end play bare number": ("{end_play: 20}", "setting.end_play"),
    "end play a force": ("{end_play: 20 N}", "setting.end_play"),
    "end play trailing junk": ("{end_play: 20 µm!}", "setting.end_play"),
    "end play decimal comma": ('{end_play: "0,02 mm"}', "setting.end_play"),
    "typo of end_play": ("{endplay: 20 µm}", "setting.endplay"),
    "unknown key": ("{preload: 300 N, tolerance: 3 N}", "setting.tolerance"),
    "both end play and preload": ("{end_play: 20 µm, preload: 300 N}", "setting.preload"),
    "empty mapping": ("{}", "setting.end_play"),
    "null": ("null", "setting"),
    "a scalar": ("300 N", "setting"),
    "a list": ("[300 N]", "setting"),
    "a boolean": ("yes", "setting"),
}


@pytest.mark.parametrize("value, field", REFUSED_SETTINGS.values(), ids=REFUSED_SETTINGS)
def test_bad_setting_is_one_line_at_its_line(tmp_path, value, field):
    result, path, lines = solve(tmp_path, BALL, setting=value)
    one_error(result, path, lines["setting"], field)


REFUSED_SPACINGS = {
    "zero": "0 mm",
    "negative": "-10 mm",
    "beyond 100 m": "200 m",
    "below 1 µm": "1 nm",
    "bare number": "60",
    "a force": "60 N",
    "empty string": '""',
    "a list": "[1, 2]",
    "band crosses zero": "60 mm ± 100 mm",
    "nan": "nan mm",
}


@pytest.mark.parametrize("value", REFUSED_SPACINGS.values(), ids=REFUSED_SPACINGS)
def test_bad_pair_spacing_is_one_line_at_its_line(tmp_path, value):
    result, path, lines = solve(tmp_path, BALL, pair_spacing=value)
    one_error(result, path, lines["pair_spacing"], "pair_spacing")


REFUSED_TILTS = {
    "moment in N": ({"tilting_moment": "10 N"}, "tilting_moment"),
    "moment bare": ({"tilting_moment": "10"}, "tilting_moment"),
    "misalignment bare": ({"misalignment": "0.05"}, "misalignment"),
    "misalignment a length": ({"misalignment": "0.05 mm"}, "misalignment"),
    "misalignment past the groove": ({"misalignment": "5 deg"}, "misalignment"),
    "misalignment a right angle": ({"misalignment": "90 deg"}, "misalignment"),
    "moment that crushes the balls": ({"tilting_moment": "10 kN*m"}, "tilting_moment"),
}


@pytest.mark.parametrize("changes, field", REFUSED_TILTS.values(), ids=REFUSED_TILTS)
def test_bad_tilt_is_one_line(tmp_path, changes, field):
    result, path, lines = solve(tmp_path, BALL, **changes)
    one_error(result, path, lines[field], field)


def test_moment_and_misalignment_together_is_one_line(tmp_path):
    result, path, _ = solve(tmp_path, BALL, misalignment="0.05 deg", tilting_moment="5 N*m")
    line = one_error(result, path, None, "misalignment")
    assert "tilting_moment" in line


REFUSED_ROLLER_FIELDS = {
    "laminae 9": ({"laminae": "9"}, "laminae"),
    "laminae 201": ({"laminae": "201"}, "laminae"),
    "laminae zero": ({"laminae": "0"}, "laminae"),
    "laminae negative": ({"laminae": "-5"}, "laminae"),
    "laminae fractional": ({"laminae": "30.5"}, "laminae"),
    "laminae a string": ({"laminae": '"30"'}, "laminae"),
    "laminae a boolean": ({"laminae": "true"}, "laminae"),
    "profile upper case": ({"roller_profile": "ISO"}, "roller_profile"),
    "profile unknown word": ({"roller_profile": "crowned"}, "roller_profile"),
    "profile a length": ({"roller_profile": "1 m"}, "roller_profile"),
    "profile typo key": ({"roller_profile": "{radius: 1 m}"}, "roller_profile.radius"),
    "crown zero": ({"roller_profile": "{crown_radius: 0 m}"}, "roller_profile.crown_radius"),
    "crown negative": ({"roller_profile": "{crown_radius: -1 m}"}, "roller_profile.crown_radius"),
    "crown bare": ({"roller_profile": "{crown_radius: 1}"}, "roller_profile.crown_radius"),
    "crown = Lwe/2": ({"roller_profile": "{crown_radius: 7 mm}"}, "roller_profile.crown_radius"),
    "included angle zero": ({"roller_included_angle": "0 deg"}, "roller_included_angle"),
    "included angle negative": ({"roller_included_angle": "-4 deg"}, "roller_included_angle"),
    "included angle 90": ({"roller_included_angle": "90 deg"}, "roller_included_angle"),
    "included angle a length": ({"roller_included_angle": "4 mm"}, "roller_included_angle"),
    "included angle bare": ({"roller_included_angle": "4"}, "roller_included_angle"),
}


@pytest.mark.parametrize(
    "changes, field", REFUSED_ROLLER_FIELDS.values(), ids=REFUSED_ROLLER_FIELDS
)
def test_bad_roller_field_is_one_line(tmp_path, changes, field):
    result, path, lines = solve(tmp_path, TAPERED, **changes)
    one_error(result, path, lines[field.split(".")[0]], field)


@pytest.mark.parametrize(
    "field, value",
    [
        ("laminae", "30"),
        ("roller_profile", "none"),
        ("roller_included_angle", "4 deg"),
        ("operating_clearance", "10 µm"),
    ],
)
def test_roller_field_or_clearance_on_a_ball_pair_is_one_line(tmp_path, field, value):
    result, path, lines = solve(tmp_path, BALL, **{field: value})
    one_error(result, path, lines[field], field)


@pytest.mark.parametrize(
    "field, value",
    [
        ("arrangement", "Back-To-Back"),
        ("arrangement", "back_to_back"),
        ("arrangement", "[back-to-back]"),
        ("method", "ISO-16281"),
        ("method", "16281"),
    ],
)
def test_near_miss_choices_are_one_line_with_a_suggestion(tmp_path, field, value):
    result, path, lines = solve(tmp_path, BALL, **{field: value})
    line = one_error(result, path, lines[field], field)
    assert "did you mean" in line


@pytest.mark.parametrize(
    "setting",
    [
        "{preload: 300 N, preload: 400 N}",
        "{end_play: 15 µm, end_play: 20 µm}",
        "{preload: !!python/object:os.system ls}",
        "{<<: {preload: 300 N}}",
    ],
)
def test_yaml_oddities_in_setting_are_one_line(tmp_path, setting):
    result, path, lines = solve(tmp_path, BALL, setting=setting)
    assert len(error_lines(result, named=False)) == 1
    assert result.stderr.startswith(f"{path}:{lines['setting']}: ")


def test_setting_given_twice_is_one_line(tmp_path):
    text, lines = build(BALL)
    path = write(tmp_path, text + "setting: {preload: 400 N}\n")
    result = invoke("solve", path)
    assert len(error_lines(result, named=False)) == 1
    assert f"{path}:{len(lines) + 1}: " in result.stderr


@pytest.mark.parametrize(
    "setting",
    [
        "{end_play: 15 um}",
        "{end_play: 15 micron}",
        "{end_play: 15 μm}",
        "{end_play: .015 mm}",
        "{end_play: 0.0006 in}",
        "{end_play: -0 µm}",
        "{preload: !!str 300 N}",
        "{preload: {nominal: 300 N, plus: 50 N, minus: 20 N}}",
        "{preload: 0.3 kN ± 0.1 kN}",
    ],
)
def test_settings_written_as_engineers_write_them_are_read(tmp_path, setting):
    assert_finite(solved(tmp_path, BALL, setting=setting))


def test_preload_in_lbf_is_the_same_force_in_newtons(tmp_path):
    in_lbf = solved(tmp_path, BALL, setting="{preload: 100 lbf}")
    in_newton = solved(tmp_path, BALL, setting="{preload: 444.8221615260500 N}")
    assert close(in_lbf["preload_force"], 444.82216152605)
    assert close(in_lbf["bearing_1_axial_load"], in_newton["bearing_1_axial_load"], rel=1e-9)


# --------------------------------------------------------------------------------------
# Combinations the docs refuse
# --------------------------------------------------------------------------------------

REFUSED_COMBINATIONS = {
    "setting on a tandem pair": ({"arrangement": "tandem"}, "setting", "setting"),
    "setting on a single bearing": ({"arrangement": "single"}, "setting", "setting"),
    "setting without arrangement": ({"arrangement": DROP}, "setting", "setting"),
    "setting under iso-281": ({"method": "iso-281"}, "setting", "setting"),
    "pair_spacing under iso-281": (
        {"method": "iso-281", "setting": DROP, "pair_spacing": "60 mm"},
        "pair_spacing",
        "pair_spacing",
    ),
    "opposed pair without setting": ({"setting": DROP}, None, "setting"),
    "no width and no spacing": ({"width": DROP}, None, "pair_spacing"),
    "negative axial load": ({"axial_load": "-1.5 kN"}, "axial_load", "axial_load"),
    "both loads zero and an end play": (
        {"radial_load": "0 kN", "axial_load": "0 kN", "setting": "{end_play: 20 µm}"},
        None,
        "radial_load",
    ),
    "axial load beyond 1e6 kN": ({"axial_load": "2e6 kN"}, "axial_load", "axial_load"),
    "spherical roller pair": (
        {
            "type": "spherical-roller",
            "ball_count": DROP,
            "ball_diameter": DROP,
            "inner_groove_conformity": DROP,
            "outer_groove_conformity": DROP,
        },
        "type",
        "type",
    ),
    "duty cycle as mounted": (
        {"duty_cycle": "[{time: 50 %, radial_load: 3 kN}, {time: 50 %, radial_load: 2 kN}]"},
        "duty_cycle",
        "duty_cycle",
    ),
}


@pytest.mark.parametrize(
    "changes, line_key, field", REFUSED_COMBINATIONS.values(), ids=REFUSED_COMBINATIONS
)
def test_refused_combination_is_one_line(tmp_path, changes, line_key, field):
    result, path, lines = solve(tmp_path, BALL, **changes)
    one_error(result, path, lines[line_key] if line_key else None, field)


def test_tapered_pair_with_negative_axial_load_is_one_line(tmp_path):
    result, path, lines = solve(tmp_path, TAPERED, axial_load="-2 kN")
    one_error(result, path, lines["axial_load"], "axial_load")


@pytest.mark.parametrize(
    "pair_type, changes",
    [
        ("deep-groove", {}),
        ("cylindrical-roller", {"contact_angle": DROP, "roller_included_angle": DROP}),
    ],
)
def test_a_type_that_does_not_pair_is_refused_at_arrangement_first(tmp_path, pair_type, changes):
    base = BALL if pair_type == "deep-groove" else TAPERED
    result, path, lines = solve(tmp_path, base, type=pair_type, **changes)
    first = error_lines(result)[0]
    assert first.startswith(f"{path}:{lines['arrangement']}: arrangement: ")
    assert pair_type in first


def test_rows_two_on_a_tapered_pair_is_one_line(tmp_path):
    result, path, lines = solve(tmp_path, TAPERED, rows="2")
    one_error(result, path, lines["rows"], "rows")


# --------------------------------------------------------------------------------------
# Statics and symmetry of valid designs
# --------------------------------------------------------------------------------------

VALID_VARIANTS = {
    "ball preload": (BALL, {}),
    "ball end play": (BALL, {"setting": "{end_play: 20 µm}"}),
    "ball interference": (BALL, {"setting": "{end_play: -10 µm}"}),
    "ball face-to-face": (BALL, {"arrangement": "face-to-face"}),
    "ball far apart": (BALL, {"pair_spacing": "10 m"}),
    "ball with moment": (BALL, {"tilting_moment": "10 N*m"}),
    "ball misaligned": (BALL, {"misalignment": "0.05 deg"}),
    "ball misaligned, preloaded to 2 kN": (
        BALL,
        {"misalignment": "-0.05 deg", "setting": "{preload: 2 kN}"},
    ),
    "ball heavy thrust, bearing 2 lifts off": (BALL, {"axial_load": "5 kN"}),
    "ball pure thrust": (BALL, {"radial_load": "0 kN"}),
    "tapered end play": (TAPERED, {}),
    "tapered back-to-back preload": (
        TAPERED,
        {"arrangement": "back-to-back", "setting": "{preload: 1 kN}"},
    ),
    "tapered straight rollers": (TAPERED, {"roller_profile": "none", "laminae": "10"}),
    "tapered crowned misaligned": (
        TAPERED,
        {"roller_profile": "{crown_radius: 1 m}", "misalignment": "1 mrad"},
    ),
    "tapered lift-off": (TAPERED, {"axial_load": "10 kN"}),
}


@pytest.mark.parametrize("base, changes", VALID_VARIANTS.values(), ids=VALID_VARIANTS)
def test_axial_loads_differ_by_the_applied_axial_load(tmp_path, base, changes):
    results = solved(tmp_path, base, **changes)
    applied = {"5 kN": 5e3, "10 kN": 1e4}.get(changes.get("axial_load"))
    applied = applied if applied is not None else (1.5e3 if base is BALL else 2e3)
    assert results["bearing_1_axial_load"] >= results["bearing_2_axial_load"] >= 0
    difference = results["bearing_1_axial_load"] - results["bearing_2_axial_load"]
    assert close(difference, applied, rel=1e-6)
    assert_finite(results, unbounded=("bearing_2_reference_rating_life",))


@pytest.mark.parametrize("base, changes", VALID_VARIANTS.values(), ids=VALID_VARIANTS)
def test_the_pair_outlives_neither_bearing(tmp_path, base, changes):
    results = solved(tmp_path, base, **changes)
    pair = results["reference_rating_life"]
    for i in (1, 2):
        own = results[f"bearing_{i}_reference_rating_life"]
        assert own is None or pair <= own * (1 + 1e-12)
    lives = [results[f"bearing_{i}_reference_rating_life"] for i in (1, 2)]
    e = 10 / 9 if base is BALL else 9 / 8  # the Weibull slope docs/kinds gives
    weibull = sum(life**-e for life in lives if life is not None) ** (-1 / e)
    assert close(pair, weibull, rel=1e-9)


@pytest.mark.parametrize(
    "base, arrangement",
    [
        (BALL, "back-to-back"),
        (BALL, "face-to-face"),
        (TAPERED, "back-to-back"),
        (TAPERED, "face-to-face"),
        (TAPERED, "tandem"),
    ],
)
def test_radial_loads_add_up_to_the_applied_radial_load(tmp_path, base, arrangement):
    changes = {"arrangement": arrangement}
    if arrangement == "tandem":
        changes.update(setting=DROP, axial_load="3 kN")
    results = solved(tmp_path, base, **changes)
    applied = 3e3 if base is BALL else 6e3
    total = results["bearing_1_radial_load"] + results["bearing_2_radial_load"]
    assert close(total, applied, rel=1e-6)


def test_a_tandem_pair_shares_the_thrust_in_one_direction(tmp_path):
    results = solved(tmp_path, BALL, arrangement="tandem", setting=DROP, axial_load="5 kN")
    total = results["bearing_1_axial_load"] + results["bearing_2_axial_load"]
    assert close(total, 5e3, rel=1e-6)
    assert results["preload_force"] == 0
    assert close(results["pair_spacing_used"], 0.016)


def test_each_bearings_loads_are_the_sums_of_its_ball_loads(tmp_path):
    results = solved(tmp_path, BALL, tilting_moment="5 N*m")
    for i in (1, 2):
        axial = radial = 0.0
        for k in range(1, 13):
            load = results[f"bearing_{i}_element_{k}_load"]
            angle = results[f"bearing_{i}_element_{k}_contact_angle"]
            azimuth = results[f"bearing_{i}_element_{k}_azimuth"]
            axial += load * math.sin(angle)
            radial += load * math.cos(angle) * math.cos(azimuth)
        assert close(axial, results[f"bearing_{i}_axial_load"], rel=1e-9)
        assert close(abs(radial), results[f"bearing_{i}_radial_load"], rel=1e-9)


@pytest.mark.parametrize("base", [BALL, TAPERED], ids=["ball", "tapered"])
def test_without_axial_load_the_two_bearings_are_alike(tmp_path, base):
    results = solved(tmp_path, base, axial_load="0 kN")
    for column in ("axial_load", "radial_load", "max_element_load", "reference_rating_life"):
        one, two = results[f"bearing_1_{column}"], results[f"bearing_2_{column}"]
        assert close(one, two, rel=1e-9), column


@pytest.mark.parametrize("base", [BALL, TAPERED], ids=["ball", "tapered"])
def test_a_mirrored_moment_swaps_the_bearings(tmp_path, base):
    plus = solved(tmp_path, base, axial_load="0 kN", tilting_moment="20 N*m")
    minus = solved(tmp_path, base, axial_load="0 kN", tilting_moment="-20 N*m")
    for column in ("axial_load", "radial_load", "max_element_load", "reference_rating_life"):
        assert close(plus[f"bearing_1_{column}"], minus[f"bearing_2_{column}"], rel=1e-6)
        assert close(plus[f"bearing_2_{column}"], minus[f"bearing_1_{column}"], rel=1e-6)
    assert close(plus["ring_tilt"], -minus["ring_tilt"], rel=1e-6)
    assert close(plus["reference_rating_life"], minus["reference_rating_life"], rel=1e-6)


@pytest.mark.parametrize("base", [BALL, TAPERED], ids=["ball", "tapered"])
def test_more_preload_stiffens_the_pair_axially(tmp_path, base):
    stiffness = [
        solved(tmp_path, base, setting=f"{{preload: {value} N}}")["stiffness_axial"]
        for value in (100, 300, 1000, 3000)
    ]
    assert stiffness == sorted(stiffness)
    assert stiffness[-1] > 1.2 * stiffness[0]


def _preload_it_gives(results):
    preload = results["preload_force"]
    assert preload > 0
    return {"setting": f"{{preload: {preload!r} N}}"}


def _back_to_back_at_its_distance(results):
    spacing = results["pair_spacing_used"]
    assert spacing < 0  # 16 mm wide, c = 23 mm·tan 40° > 8 mm: the centres cross
    # no width: 16 mm wide bearings back-to-back could not come this close
    return {"pair_spacing": f"{-spacing * 1e3!r} mm", "width": None}


def _moment_it_takes(results):
    return {"tilting_moment": f"{results['tilting_moment_reaction']!r} N*m"}


SETTING_KEYS = (
    "bearing_1_axial_load",
    "bearing_2_axial_load",
    "stiffness_axial",
    "stiffness_radial",
    "reference_rating_life",
)
SPACING_KEYS = (
    "bearing_1_axial_load",
    "bearing_1_radial_load",
    "stiffness_tilt",
    "stiffness_radial",
    "ring_tilt",
    "reference_rating_life",
)

#: One state written two ways: (base, the first way, the second way from the first's
#: results, results both must share, the second's results against fixed values).
ONE_STATE_TWO_WAYS = {
    "ball interference and its preload": (
        BALL,
        {"setting": "{end_play: -10 µm}"},
        _preload_it_gives,
        SETTING_KEYS,
        {},
    ),
    "tapered interference and its preload": (
        TAPERED,
        {"setting": "{end_play: -10 µm}"},
        _preload_it_gives,
        SETTING_KEYS,
        {},
    ),
    "tapered deep interference and its preload": (
        TAPERED,
        {"setting": "{end_play: -0.5 mm}"},
        _preload_it_gives,
        SETTING_KEYS,
        {},
    ),
    "crossed face-to-face and back-to-back at the same distance": (
        BALL,
        {"arrangement": "face-to-face"},
        _back_to_back_at_its_distance,
        SPACING_KEYS,
        {},
    ),
    "misalignment and the moment it takes": (
        BALL,
        {"misalignment": "0.05 deg"},
        _moment_it_takes,
        ("bearing_1_radial_load",),
        {"ring_tilt": math.radians(0.05)},
    ),
}


@pytest.mark.parametrize(
    "base, first, second, shared, fixed", ONE_STATE_TWO_WAYS.values(), ids=ONE_STATE_TWO_WAYS
)
def test_one_state_written_two_ways_solves_alike(tmp_path, base, first, second, shared, fixed):
    one = solved(tmp_path, base, **first)
    other = solved(tmp_path, base, **second(one))
    for key, value in fixed.items():
        assert close(other[key], value, rel=1e-6), key
    for key in shared:
        assert close(one[key], other[key], rel=1e-6), key


def test_preload_force_and_spacing_are_reported_as_given(tmp_path):
    results = solved(tmp_path, BALL, setting="{preload: 750 N}", pair_spacing="70 mm")
    assert results["preload_force"] == pytest.approx(750)
    assert results["pair_spacing_used"] == pytest.approx(0.07)
    assert results["equilibrium_residual"] < 1e-9


def test_side_by_side_spacing_follows_the_width(tmp_path):
    back = solved(tmp_path, TAPERED, arrangement="back-to-back")["pair_spacing_used"]
    face = solved(tmp_path, TAPERED)["pair_spacing_used"]
    assert close(back + face, 2 * 17.25e-3, rel=1e-9)  # (B + 2c) + (B − 2c)
    assert back > 17.25e-3 > face > 0


def test_a_huge_crown_radius_tends_to_a_straight_roller(tmp_path):
    straight = solved(tmp_path, TAPERED, roller_profile="none")
    crowned = solved(tmp_path, TAPERED, roller_profile="{crown_radius: 99 m}")
    assert close(crowned["reference_rating_life"], straight["reference_rating_life"], rel=0.05)
    assert close(crowned["bearing_1_axial_load"], straight["bearing_1_axial_load"], rel=0.01)


def test_zero_radial_load_with_preload_carries_the_thrust_alone(tmp_path):
    results = solved(tmp_path, BALL, radial_load="0 kN", axial_load="0.5 kN")
    assert abs(results["bearing_1_radial_load"]) < 1e-6
    assert abs(results["bearing_2_radial_load"]) < 1e-6
    assert results["bearing_2_axial_load"] > 0  # still preloaded below lift-off
    assert_finite(results)


def test_when_bearing_2_lifts_off_the_pair_lives_as_bearing_1(tmp_path):
    results = solved(tmp_path, TAPERED, axial_load="10 kN")
    assert results["bearing_2_axial_load"] == 0
    assert results["bearing_2_reference_rating_life"] is None  # unbounded, null in JSON
    assert close(
        results["reference_rating_life"], results["bearing_1_reference_rating_life"], rel=1e-9
    )


def test_an_axial_load_far_above_one_bearing_fails_or_is_refused_cleanly(tmp_path):
    result, path, lines = solve(tmp_path, BALL, axial_load="100 kN")
    if result.exit_code == 2:
        one_error(result, path, lines["axial_load"], "axial_load")
    else:
        assert result.exit_code == 1
        results = results_of(result)
        assert close(results["bearing_1_axial_load"], 1e5, rel=1e-6)


def test_a_preload_that_crushes_the_balls_fails_or_is_refused(tmp_path):
    result, _, _ = solve(tmp_path, BALL, setting="{preload: 300 kN}")
    assert result.exit_code in (1, 2)
    if result.exit_code == 1:
        results = results_of(result)
        assert results["contact_pressure_margin"] < 0
        assert_finite(results)


@pytest.mark.parametrize("end_play", ["0.3 mm", "3 mm"])
def test_millimetres_of_end_play_solve_or_are_refused_cleanly(tmp_path, end_play):
    result, _, _ = solve(tmp_path, BALL, setting=f"{{end_play: {end_play}}}")
    if result.exit_code == 2:
        assert len(error_lines(result)) == 1
    else:
        results = results_of(result)
        assert_finite(results, unbounded=("bearing_2_reference_rating_life",))
        assert close(results["bearing_1_axial_load"] - results["bearing_2_axial_load"], 1500)


@pytest.mark.parametrize("preload", ["400 kN", "900 kN"])
def test_a_huge_tapered_preload_is_carried_or_refused(tmp_path, preload):
    """A tapered pair preloaded to hundreds of kN with no axial load is refused at
    setting.preload or carries the preload as given: each bearing's axial load is
    preload_force (not a value that saturates near 314 kN)."""
    result, path, lines = solve(
        tmp_path, TAPERED, setting=f"{{preload: {preload}}}", axial_load="0 kN", radial_load="1 N"
    )
    if result.exit_code == 2:
        one_error(result, path, lines["setting"], "setting.preload")
        return
    results = results_of(result)
    assert close(results["bearing_1_axial_load"], results["preload_force"], rel=0.01)


def test_a_preload_that_crushes_is_refused_at_setting(tmp_path):
    """A preload of 500 kN on the ball pair (radial load 1 N) is refused in one line naming
    setting.preload, the field at fault, at the line of setting."""
    result, path, lines = solve(tmp_path, BALL, setting="{preload: 500 kN}", radial_load="1 N")
    one_error(result, path, lines["setting"], "setting.preload")


def test_an_interference_that_crushes_is_refused_at_setting(tmp_path):
    """An interference of 1 mm (setting: {end_play: -1 mm}) with radial_load 0 kN is refused
    in one line naming setting.end_play, the field at fault, at the line of setting."""
    result, path, lines = solve(tmp_path, BALL, setting="{end_play: -1 mm}", radial_load="0 kN")
    one_error(result, path, lines["setting"], "setting.end_play")


def test_an_axial_load_that_crushes_is_refused_at_axial_load(tmp_path):
    result, path, lines = solve(tmp_path, BALL, axial_load="1e6 kN")
    one_error(result, path, lines["axial_load"], "axial_load")


@pytest.mark.parametrize("radius", ["7.5 mm", "10 mm"])
def test_a_crown_that_drops_millimetres_is_refused(tmp_path, radius):
    # r − √(r² − (Lwe/2)²) at the ends of a 14 mm roller: 4.8 mm and 2.9 mm, against a
    # roller radius of 3.75 mm
    result, path, lines = solve(tmp_path, TAPERED, roller_profile=f"{{crown_radius: {radius}}}")
    one_error(result, path, lines["roller_profile"], "roller_profile.crown_radius")


@pytest.mark.parametrize("angle", ["45 deg", "14 deg"])
def test_an_included_angle_above_the_cup_angle_is_refused(tmp_path, angle):
    """roller_included_angle at or above the cup's contact angle (14 deg) is refused in one
    line naming roller_included_angle at its line: the cone's raceway lies at their
    difference (14° − 45° = −31°, no tapered bearing)."""
    result, path, lines = solve(tmp_path, TAPERED, roller_included_angle=angle)
    one_error(result, path, lines["roller_included_angle"], "roller_included_angle")


@pytest.mark.parametrize(("spacing", "refused"), [("1 mm", True), ("54.5 mm", True),
                                                  ("54.7 mm", False)])
def test_a_back_to_back_spacing_below_side_by_side_is_refused(tmp_path, spacing, refused):
    """Back-to-back, two 16 mm wide 40° bearings side by side have their pressure centres
    B + 2c = 16 mm + 46 mm·tan 40° = 54.60 mm apart; spacers only part them further."""
    assert 16.0 + 46.0 * math.tan(math.radians(40.0)) == pytest.approx(54.60, abs=0.01)
    result, path, lines = solve(tmp_path, BALL, pair_spacing=spacing)
    if refused:
        one_error(result, path, lines["pair_spacing"], "pair_spacing")
    else:
        assert result.exit_code in (0, 1), result.stderr


def test_a_catalogue_designation_fills_a_ball_pair(tmp_path):
    changes = {
        "dynamic_load_rating": DROP,
        "static_load_rating": DROP,
        "width": DROP,
        "contact_angle": DROP,
        "type": DROP,
        "catalogue": str(CATALOGUE),
        "designation": '"7206 BEP"',
    }
    results = solved(tmp_path, BALL, **changes)
    assert results["dynamic_load_rating"] == pytest.approx(22.5e3)
    c = 0.023 * math.tan(math.radians(40))
    assert results["pair_spacing_used"] == pytest.approx(0.016 + 2 * c, rel=1e-6)


def test_a_catalogue_designation_fills_a_tapered_pair(tmp_path):
    changes = {
        "dynamic_load_rating": DROP,
        "static_load_rating": DROP,
        "width": DROP,
        "type": DROP,
        "catalogue": str(CATALOGUE),
        "designation": '"30206 J2/Q"',
    }
    results = solved(tmp_path, TAPERED, **changes)
    assert results["dynamic_load_rating"] == pytest.approx(40.2e3)
    assert close(results["bearing_1_axial_load"] - results["bearing_2_axial_load"], 2e3)


def test_an_unknown_designation_is_one_line(tmp_path):
    result, path, lines = solve(tmp_path, BALL, catalogue=str(CATALOGUE), designation='"7299 XYZ"')
    one_error(result, path, lines["designation"], "designation")


# --------------------------------------------------------------------------------------
# Every command
# --------------------------------------------------------------------------------------


def test_solve_table_shows_the_pair_and_its_verdict(tmp_path):
    path = write(tmp_path, build(BALL)[0])
    result = invoke("solve", path)
    assert result.exit_code == 0
    assert "bearings of the pair" in result.stdout
    assert "bearing 2: rolling elements as mounted" in result.stdout
    assert "PASS" in result.stdout
    assert "nan" not in result.stdout.lower().split()


def test_solve_csv_has_every_bearing_column_and_an_empty_unbounded_life(tmp_path):
    path = write(tmp_path, build(TAPERED, axial_load="10 kN")[0])
    result = invoke("solve", path, "--format", "csv")
    assert result.exit_code in (0, 1)
    header, row = list(csv.reader(io.StringIO(result.stdout)))
    cells = dict(zip(header, row, strict=True))
    assert float(cells["bearing_1_axial_load [N]"]) == pytest.approx(1e4)
    assert cells["bearing_2_reference_rating_life [s]"] == ""
    assert not any(cell.lower() in ("nan", "inf", "-inf") for cell in row)


def test_check_mixes_good_bad_and_failing_pairs(tmp_path):
    folder = tmp_path / "designs"
    folder.mkdir()
    write(folder, build(BALL)[0], "good.yaml")
    write(folder, build(TAPERED)[0], "good_tapered.yaml")
    write(folder, build(TAPERED, limits="{min_rating_life: 1e8 h}")[0], "short.yaml")
    write(folder, build(BALL, setting="{preload: -3 N}")[0], "bad_preload.yaml")
    write(folder, build(BALL, arrangement="tandem")[0], "bad_tandem.yaml")
    result = invoke("check", folder, "--format", "json", "--jobs", "1")
    assert result.exit_code == 2
    rows = {Path(row["spec"]).name: row for row in map(json.loads, result.stdout.splitlines())}
    assert {name: row["status"] for name, row in rows.items()} == {
        "good.yaml": "pass",
        "good_tapered.yaml": "pass",
        "short.yaml": "fail",
        "bad_preload.yaml": "invalid",
        "bad_tandem.yaml": "invalid",
    }
    assert rows["bad_preload.yaml"]["messages"][0].endswith(
        "setting.preload: must be greater than zero, got '-3 N'"
    )
    assert len(rows["bad_tandem.yaml"]["messages"]) == 1
    assert "setting" in rows["bad_tandem.yaml"]["messages"][0]


def test_check_without_invalid_specs_exits_1_on_a_failing_pair(tmp_path):
    folder = tmp_path / "designs"
    folder.mkdir()
    write(folder, build(BALL)[0], "good.yaml")
    write(folder, build(TAPERED, limits="{min_rating_life: 1e8 h}")[0], "short.yaml")
    result = invoke("check", folder, "--jobs", "1")
    assert result.exit_code == 1


def sweep(tmp_path: Path, text: str, *vary: str) -> list[dict]:
    path = write(tmp_path, text)
    args = ["sweep", path, "--format", "json"]
    for item in vary:
        args += ["--vary", item]
    result = invoke(*args)
    assert result.exit_code == 0, result.stderr
    return [json.loads(line) for line in result.stdout.splitlines()]


def test_sweep_over_end_play_is_continuous_through_zero(tmp_path):
    points = sweep(tmp_path, build(TAPERED)[0], "setting.end_play=-20um:40um:61")
    assert all(point["reason"] is None for point in points)
    for key in ("bearing_1_axial_load", "stiffness_axial", "reference_rating_life"):
        values = [point["results"][key] for point in points]
        jumps = [abs(b - a) / abs(a) for a, b in itertools.pairwise(values)]
        assert max(jumps) < 0.05, key
    stiffness = [point["results"]["stiffness_axial"] for point in points]
    assert stiffness == sorted(stiffness, reverse=True)  # more end play, softer


def test_sweep_over_preload_stiffens_monotonically(tmp_path):
    points = sweep(tmp_path, build(BALL)[0], "setting.preload=100N:3kN:30")
    stiffness = [point["results"]["stiffness_axial"] for point in points]
    assert stiffness == sorted(stiffness)


def test_sweep_over_axial_load_through_lift_off_keeps_the_statics(tmp_path):
    points = sweep(tmp_path, build(TAPERED)[0], "axial_load=0kN:12kN:25")
    for point in points:
        assert point["reason"] is None, point["reason"]
        results = point["results"]
        applied = point["inputs"]["axial_load"]
        difference = results["bearing_1_axial_load"] - results["bearing_2_axial_load"]
        assert close(difference, applied, rel=1e-6, abs_=1e-6)
    lives = [point["results"]["reference_rating_life"] for point in points]
    assert lives == sorted(lives, reverse=True)


def test_sweep_over_pair_spacing_solves_every_point(tmp_path):
    text = build(BALL, pair_spacing="60 mm")[0]
    points = sweep(tmp_path, text, "pair_spacing=55mm:500mm:25")
    tilt = [point["results"]["stiffness_tilt"] for point in points]
    assert all(point["reason"] is None for point in points)
    assert tilt == sorted(tilt)  # the farther apart, the stiffer against tilt


def test_sweep_into_impossible_end_play_leaves_gaps_with_reasons(tmp_path):
    points = sweep(
        tmp_path, build(BALL, setting="{end_play: 10 µm}")[0], "setting.end_play=0um:700um:36"
    )
    for point in points:
        if point["reason"] is None:
            assert_finite(point["results"], unbounded=("bearing_2_reference_rating_life",))
        else:
            assert point["reason"].strip()
            assert all(value is None for value in point["results"].values())
    assert points[0]["reason"] is None


@pytest.mark.parametrize(
    "vary",
    [
        "setting.preload=0N:1kN:5",
        "pair_spacing=-1mm:100mm:5",
        "axial_load=-1kN:1kN:5",
        "setting.end_play=0um:10um:5",
        "laminae=10:20:3",
    ],
)
def test_sweep_of_a_bad_range_or_absent_field_is_one_line(tmp_path, vary):
    path = write(tmp_path, build(BALL, pair_spacing="60 mm")[0])
    result = invoke("sweep", path, "--vary", vary)
    assert result.exit_code == 2
    assert len([line for line in result.stderr.splitlines() if line.strip()]) == 1
    assert result.stderr.startswith("bearingcalc sweep: ")


def tolerance(tmp_path: Path, text: str, *options: str) -> tuple[int, dict]:
    path = write(tmp_path, text)
    result = invoke("tolerance", path, "--format", "json", *options)
    assert result.exit_code in (0, 1), result.stderr
    return result.exit_code, json.loads(result.stdout)


def test_tolerance_on_end_play_brackets_the_nominal(tmp_path):
    text = build(TAPERED, setting="{end_play: 15 µm ± 10 µm}")[0]
    status, study = tolerance(tmp_path, text, "--method", "worst-case")
    assert status == 0
    life = study["results"]["reference_rating_life"]
    assert life["worst_case"]["min"] <= life["nominal"] <= life["worst_case"]["max"]
    assert life["worst_case"]["min_inputs"]["setting.end_play"] == pytest.approx(25e-6)
    preload = study["results"]["preload_force"]["worst_case"]
    assert preload["min"] == 0 and preload["max"] == 0


def test_tolerance_on_preload_spacing_and_loads_finishes(tmp_path):
    text = build(
        BALL,
        setting="{preload: 300 N ± 100 N}",
        pair_spacing="56 mm ± 1 mm",
        radial_load="3 kN ± 0.5 kN",
        axial_load="1.5 kN ± 0.5 kN",
    )[0]
    status, study = tolerance(tmp_path, text, "--method", "rss,monte-carlo", "--samples", "64")
    assert status == 0
    assert set(study["inputs"]) == {"setting.preload", "pair_spacing", "radial_load", "axial_load"}
    stiffness = study["results"]["stiffness_axial"]["rss"]["sensitivities"]
    assert stiffness["setting.preload"] > 0  # more preload, stiffer
    assert 0 < study["yield"] <= 1


def test_tolerance_band_into_lift_off_is_studied(tmp_path):
    text = build(TAPERED, axial_load="4 kN ± 1.5 kN")[0]
    status, study = tolerance(tmp_path, text, "--method", "monte-carlo", "--samples", "64")
    assert status == 0
    assert study["infeasible_samples"] == 0
    assert study["results"]["bearing_2_axial_load"]["monte_carlo"]["min"] == 0


def test_tolerance_band_into_no_equilibrium_fails_with_a_reason(tmp_path):
    text = build(BALL, setting="{end_play: 0.35 mm ± 0.1 mm}")[0]
    status, study = tolerance(tmp_path, text, "--method", "monte-carlo", "--samples", "64")
    assert status == 1
    assert study["infeasible_samples"] > 0
    assert study["impossible_in_box"]["reason"].startswith("axial_load: ")


def test_worst_case_over_a_partly_impossible_band_names_what_is_impossible(tmp_path):
    """Part of the end play's band leaves the pair without an equilibrium: the study
    fails with the reason, and its extremes lie inside the band."""
    text = build(BALL, setting="{end_play: 0.35 mm ± 0.1 mm}")[0]
    status, study = tolerance(tmp_path, text, "--method", "worst-case")
    assert status == 1
    assert study["impossible_in_box"]["reason"]
    life = study["results"]["reference_rating_life"]["worst_case"]
    assert 0.25e-3 <= life["min_inputs"]["setting.end_play"] <= 0.45e-3
    assert 0.0 < life["min"] <= study["results"]["reference_rating_life"]["nominal"]


def test_tolerance_band_of_preload_across_zero_is_one_line(tmp_path):
    path = write(tmp_path, build(BALL, setting="{preload: 300 N ± 400 N}")[0])
    result = invoke("tolerance", path)
    one_error(result, path, build(BALL)[1]["setting"], "setting.preload")


def test_report_of_a_pair_is_written_with_both_bearings(tmp_path):
    path = write(tmp_path, build(TAPERED, axial_load="10 kN")[0])
    output = tmp_path / "report.html"
    result = invoke("report", path, "--output", output)
    assert result.exit_code == 0, result.stderr
    html = output.read_text(encoding="utf-8")
    for key in (
        "bearing_1_axial_load",
        "bearing_2_reference_rating_life",
        "pair_spacing_used",
        "preload_force",
    ):
        assert key in html
    assert not re.search(r">\s*(nan|inf|-inf)\s*<", html, re.IGNORECASE)


def test_report_of_a_bad_pair_writes_nothing(tmp_path):
    path = write(tmp_path, build(BALL, setting="{preload: 0 N}")[0])
    output = tmp_path / "report.html"
    result = invoke("report", path, "--output", output)
    one_error(result, path, build(BALL)[1]["setting"], "setting.preload")
    assert not output.exists()


def test_schema_describes_the_new_fields():
    result = invoke("schema", "--kind", "rolling-bearing")
    assert result.exit_code == 0
    schema = json.loads(result.stdout)
    properties = schema["properties"]
    for field in (
        "setting",
        "pair_spacing",
        "tilting_moment",
        "misalignment",
        "roller_profile",
        "laminae",
        "roller_included_angle",
    ):
        assert field in properties, field
    assert set(properties["arrangement"]["enum"]) == {
        "single",
        "back-to-back",
        "face-to-face",
        "tandem",
    }
    setting = schema["$defs"]["PairSetting"]
    assert set(setting["properties"]) == {"end_play", "preload", "stage"}
    assert setting["additionalProperties"] is False
    laminae = next(
        option for option in properties["laminae"]["anyOf"] if option.get("type") == "integer"
    )
    assert (laminae["minimum"], laminae["maximum"]) == (10, 200)


def test_a_preload_alone_loads_the_pair(tmp_path):
    """No external load: the preload loads both bearings alike, each carrying it; ISO
    281's lives, which rate forces, are unbounded (null)."""
    results = solved(tmp_path, BALL, radial_load="0 kN", axial_load="0 kN")
    for i in (1, 2):
        assert close(results[f"bearing_{i}_axial_load"], 300.0, rel=1e-9)
    assert close(results["bearing_1_max_element_load"],
                 results["bearing_2_max_element_load"], rel=1e-9)
    assert results["reference_rating_life"] > 0 and results["basic_rating_life"] is None
