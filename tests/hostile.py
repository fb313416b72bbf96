"""A generated corpus of hostile spec files: every class of bad input, on every kind.

Each case is a file name and its bytes. The good example specs are mutated one
field at a time with values that break the unit parser, the YAML reader, the
number rules, the ranges and the physics; structural attacks (aliases, nesting,
tags, encodings) are added whole. Every case is invalid: `solve`, `check`,
`tolerance` and `sweep` must each refuse it with clear lines naming the file, exit
status 2, and no traceback, no internal error and no non-finite number.
"""

from __future__ import annotations

import json
import re
import tempfile
from pathlib import Path

SPECS = Path(__file__).resolve().parent.parent / "specs"
TEMPLATES = SPECS.parent / "bearingcalc" / "templates"

#: kind -> (example spec, its quantity fields that take hostile values, a field to sweep),
#: chosen by hand for the kinds they were written for; every other registered kind gets
#: its example's first quantity fields and a sweep of the first (see ``derived_choice``).
CHOSEN = {
    "thrust-bearing": ("thrust-bearing.yaml",
                       ("ball_diameter", "contact_angle", "pitch_radius", "shaft_speed"),
                       "shaft_speed=100rpm:200rpm:3"),
    "bevel-gears": ("bevel-gears.yaml", ("module", "shaft_angle", "arm_speed", "gear_b_speed"),
                    "arm_speed=100rpm:200rpm:3"),
    "disk-on-circle": ("disk-on-circle.yaml",
                       ("disk_radius", "surface_radius", "disk_speed", "disk_accel"),
                       "disk_speed=100rpm:200rpm:3"),
    "cone-on-plane": ("cone-on-plane.yaml", ("half_angle", "spin_speed"),
                      "half_angle=10deg:20deg:3"),
    "ball-bearing": ("ball-bearing.yaml",
                     ("dynamic_load_rating", "radial_load", "speed", "pitch_diameter"),
                     "radial_load=1kN:5kN:3"),
    "bevel-drive": ("bevel-drive.yaml", ("module", "face_width", "input_speed", "torque"),
                    "torque=50N*m:70N*m:3"),
    "rolling-bearing": ("rolling-bearing-tapered-geometry.yaml",
                        ("roller_diameter", "roller_length", "contact_angle", "pitch_diameter"),
                        "radial_load=5kN:7kN:3"),
}


def derived_choice(kind: str) -> tuple[str, tuple[str, ...], str]:
    """(example spec, quantity fields, sweep) of a kind from its template
    (``bearingcalc/templates/KIND.yaml``, which every kind has) and its model: the first
    four top-level quantity fields the template writes as text, and a sweep of the first
    from 0.9 to 1.1 times its value."""
    import yaml

    from bearingcalc.kinds import KINDS as REGISTRY
    from bearingcalc.models.base import field_parser
    from bearingcalc.number_grammar import NUMBER

    example = str(TEMPLATES / f"{kind}.yaml")  # absolute: SPECS / example is the template
    data = yaml.safe_load((SPECS / example).read_text())
    fields = REGISTRY[kind].model.model_fields
    quantities = [name for name, value in data.items()
                  if name in fields and isinstance(value, str)
                  and (parser := field_parser(fields[name])) is not None
                  and parser[0] == "quantity" and re.match(NUMBER, value)]
    first = quantities[0]
    number = re.match(NUMBER, data[first])
    assert number is not None
    value, unit = float(number[0]), data[first][number.end():].strip().replace(" ", "")
    return example, tuple(quantities[:4]), f"{first}={0.9 * value:g}{unit}:{1.1 * value:g}{unit}:3"


def _kinds() -> dict[str, tuple[str, tuple[str, ...], str]]:
    from bearingcalc.kinds import KINDS as REGISTRY

    return {kind: CHOSEN.get(kind) or derived_choice(kind) for kind in REGISTRY}


KINDS = _kinds()

#: Quantity strings (written quoted) that must each be refused.
BAD_QUANTITY_TEXT = [
    "26 mm)", "1500 rpm**0", "30 deg!", "12.7 mm;", "26 mm/", "12,7 mm", "26 mm(", "2 mm{",
    "3 [mm]", "5 mm**2**3**4", "1" + "0" * 400 + " mm", "1" + "0" * 400 + " rpm", "mm", "",
    " ", "nan mm", "inf deg", "-inf rpm", "1e400 mm", "1e305 mm", "-1e305 rad", "１２ mm",
    "12 furlongz", "25 Hz", "12 N*m", "3 kg", "12.7 mm mm mm mm" + " mm" * 40, "7 mm\x00",
    "7 mm\x1b[31m", "7 mm\nkind: x", "7 m" * 300, "1e-400", "12..7 mm", "--3 mm", "3 mm ± -1 mm",
    "3 mm ± 1 mm ± 1 mm", "3 mm ± 1 kg", "3 ± mm", "0x1F mm", "1_000 mm", "∞ mm", "12 mm#x",
    # A percent sign is a unit of its own, never a factor of another.
    "20 deg%", "3 %*mm", "3 mm/%", "5 % rpm",
    # Magnitudes no machine element has: a unit slip, refused with a hint.
    "2e10 N", "3e7 rpm", "0.5 um", "500 m", "-200 m", "2e7 mm^2/s",
]
#: Raw YAML values (written unquoted) that must each be refused for a quantity field.
BAD_QUANTITY_YAML = [
    ".inf", "-.inf", ".nan", "0x1F", "014", "1:00", "2024-01-01", "true", "[1, 2]",
    "{a: 1}", "12.7", "1e-2", "1" + "0" * 400, "!!binary aGk=", "!!python/none ''",
    "{nominal: 3 mm}", "{nominal: 3 mm, tolerance: 1 mm, plus: 1 mm}",
    "{nominal: 3 mm, tolerance: 1 mm, sigma_level: 0.00001}",
    "{nominal: 3 mm, tolerance: 1 mm, distribution: weird}",
    "{nominal: 3 mm, tolerance: 1 mm, bogus: 1}", "*undefined", "&a [*a]",
]

#: Whole files: structure, encoding and size attacks.
STRUCTURAL = {
    "empty.yaml": b"",
    "only-comment.yaml": b"# nothing\n",
    "binary.yaml": b"kind: thrust-bearing\x00\x01\x02\n",
    "latin1.yaml": "kind: thrust-bearing\nname: caf\xe9\n".encode("latin-1"),
    "utf16.yaml": "kind: thrust-bearing\n".encode("utf-16"),
    "list.yaml": b"- kind: thrust-bearing\n",
    "scalar.yaml": b"just words\n",
    "tab.yaml": b"kind: thrust-bearing\n\tname: x\n",
    "unclosed.yaml": b"kind: thrust-bearing\nball_diameter: [12.7 mm\n",
    "python-tag.yaml": b"kind: !!python/object/apply:os.system [ls]\n",
    "merge-key.yaml": b"base: &b {shaft_speed: 1 rpm}\nkind: thrust-bearing\n<<: *b\n",
    "alias-bomb.yaml": (b"a: &a [x, x, x, x, x, x, x, x, x]\nb: &b [*a, *a, *a, *a, *a, *a, *a]\n"
                        b"c: &c [*b, *b, *b, *b, *b, *b, *b]\nd: &d [*c, *c, *c, *c, *c, *c]\n"
                        b"e: [*d, *d, *d, *d, *d, *d, *d, *d]\nkind: thrust-bearing\n"),
    "deep.yaml": b"kind: thrust-bearing\nx: " + b"[" * 5000 + b"]" * 5000 + b"\n",
    "deep-map.yaml": b"kind: thrust-bearing\nx: " + b"{a: " * 3000 + b"1" + b"}" * 3000 + b"\n",
    "too-large.yaml": b"kind: thrust-bearing\n# " + b"x" * (1024 * 1024 + 10) + b"\n",
    "duplicate.yaml": b"kind: thrust-bearing\nkind: thrust-bearing\n",
    "kind-missing.yaml": b"name: x\n",
    "kind-typo.yaml": b"kind: thrust-bering\n",
    "kind-number.yaml": b"kind: 12\n",
    "kind-list.yaml": b"kind: [thrust-bearing]\n",
    "key-number.yaml": b"kind: thrust-bearing\n12: x\n",
    "key-null.yaml": b"kind: thrust-bearing\n~: x\n",
    "date-name.yaml": b"kind: thrust-bearing\nname: 2024-01-01\n",
    "two-docs-bad.yaml": b"kind: thrust-bearing\n---\nkind: nonsense\n",
    "crlf.yaml": b"kind: thrust-bearing\r\nball_diameter: 12.7 mm)\r\n",
    "bom-bad.yaml": b"\xef\xbb\xbfkind: thrust-bearing\nball_diameter: 12,7 mm\n",
    "long-line.yaml": b"kind: thrust-bearing\nball_diameter: \"" + b"9" * 200_000 + b" mm\"\n",
    "long-unit.yaml": b"kind: thrust-bearing\nball_diameter: \"1 " + b"mm*" * 100_000 + b"mm\"\n",
    "control-key.yaml": b"kind: thrust-bearing\n\"\\e[31mevil\": 1\n",
    "undefined-alias.yaml": b"kind: thrust-bearing\nball_diameter: *nothing\n",
}


def _mutate(text: str, field: str, raw_value: str) -> str:
    """``text`` with the block-style line of ``field`` given ``raw_value``."""
    pattern = re.compile(rf"^(\s*){re.escape(field)}:.*$", re.MULTILINE)
    if not pattern.search(text):
        return text + f"{field}: {raw_value}\n"
    return pattern.sub(lambda m: f"{m.group(1)}{field}: {raw_value}", text, count=1)


def _physics_cases() -> dict[str, str]:
    """Valid-looking files that break a range or the physics of their kind."""
    tb = (SPECS / "thrust-bearing.yaml").read_text()
    bevel = (SPECS / "bevel-gears.yaml").read_text()
    disk = (SPECS / "disk-on-circle.yaml").read_text()
    cone = (SPECS / "cone-on-plane.yaml").read_text()
    ball = (SPECS / "ball-bearing.yaml").read_text()
    drive = (SPECS / "bevel-drive.yaml").read_text()
    sizing = (SPECS / "bevel-gears-sizing.yaml").read_text()
    geometry = (SPECS / "ball-bearing-geometry.yaml").read_text()
    loaded = (SPECS / "thrust-bearing-loaded.yaml").read_text()
    oil = "lubrication: {viscosity_40: 68 mm^2/s, viscosity_100: 8.7 mm^2/s, temperature: %s}"
    return {**_roller_cases(), **_duty_cases(), **_pair_cases(), **_catalogue_cases(), **{
        # Contradictory geometry: every size valid, together impossible.
        "ball-pitch-outside-rings.yaml": _mutate(ball, "pitch_diameter", "150 mm")
        + "bore_diameter: 45 mm\noutside_diameter: 100 mm\n",
        "ball-pitch-inside-bore.yaml": _mutate(ball, "pitch_diameter", "40 mm")
        + "bore_diameter: 45 mm\noutside_diameter: 100 mm\n",
        "ball-larger-than-section.yaml": _mutate(geometry, "ball_diameter", "14 mm")
        + "bore_diameter: 25 mm\noutside_diameter: 52 mm\n",
        "ball-rings-swapped.yaml": geometry + "bore_diameter: 52 mm\noutside_diameter: 25 mm\n",
        "drive-pitch-outside-rings.yaml": drive.replace(
            "bore_diameter: 25 mm, outside_diameter: 62 mm}",
            "bore_diameter: 25 mm, outside_diameter: 62 mm, pitch_diameter: 70 mm}", 1),
        # Quantities of the wrong order: MPa typed for GPa, and the contact it would give.
        "ball-modulus-mpa.yaml": geometry + "material: {elastic_modulus: 207.5 MPa}\n",
        "thrust-modulus-kpa.yaml": loaded.replace("207.5 GPa", "207.5 kPa"),
        "thrust-modulus-tpa.yaml": loaded.replace("207.5 GPa", "207.5 TPa"),
        "thrust-contact-too-wide.yaml": _mutate(loaded, "axial_load", "5e8 N"),
        "ball-contact-too-wide.yaml": _mutate(_mutate(geometry, "radial_load", "900 kN"),
                                              "axial_load", "0 kN"),
        "ball-viscosity-huge.yaml": _mutate(ball, "viscosity", "2e7 mm^2/s"),
        # Causes that once ended at the generic overflow status.
        "ball-load-factors-zero.yaml": ball.replace("axial_load: 0 kN", "axial_load: 1 kN")
        + "load_factors: {x: 0, y: 0, e: 0}\n",
        "ball-load-factor-y-zero.yaml": _mutate(_mutate(ball, "radial_load", "0 kN"),
                                                "axial_load", "3 kN")
        + "load_factors: {x: 0.56, y: 0, e: 0.3}\n",
        "ball-oil-frozen.yaml": re.sub(r"lubrication:\n  viscosity: .*", oil % "-200 degC", ball),
        "ball-oil-cold.yaml": re.sub(r"lubrication:\n  viscosity: .*", oil % "-150 degC", ball),
        "ball-oil-thickens.yaml": re.sub(r"lubrication:\n  viscosity: .*", oil % "80 degC", ball)
        .replace("8.7 mm^2/s", "90 mm^2/s"),
        "drive-oil-frozen.yaml": drive.replace("lubrication: {viscosity: 68 mm^2/s}",
                                               oil % "-180 degC"),
        # Several problems at once: every one is listed.
        "ball-many-problems.yaml": _mutate(_mutate(_mutate(ball, "radial_load", "10 kNx"),
                                                   "speed", "3000 rpmm"),
                                           "reliability", "120 %")
        .replace("static_factor: 13", "").replace("contamination_factor: 0.5", "")
        .replace("axial_load: 0 kN", "axial_load: 2 kN"),
        "thrust-angle-50.yaml": _mutate(tb, "contact_angle", "50 deg"),
        "thrust-angle-0.yaml": _mutate(tb, "contact_angle", "0 deg"),
        "thrust-angle-50-solved.yaml": _mutate(tb, "contact_angle", "50 deg").replace(
            "pitch_radius: 26 mm", ""),
        "thrust-radius-small.yaml": _mutate(tb, "pitch_radius", "5 mm"),
        "thrust-balls-40.yaml": _mutate(tb, "ball_count", "40"),
        "thrust-balls-huge.yaml": _mutate(tb, "ball_count", "1" + "0" * 400),
        "thrust-balls-half.yaml": _mutate(tb, "ball_count", "4.5"),
        "thrust-balls-zero.yaml": _mutate(tb, "ball_count", "0"),
        "thrust-balls-text.yaml": _mutate(tb, "ball_count", "twelve"),
        "thrust-both-sizes.yaml": tb + "ball_radius: 6.35 mm\n",
        "thrust-limit-negative.yaml": _mutate(tb, "max_spin_to_roll", "-0.1"),
        "thrust-limit-inf.yaml": _mutate(tb, "max_spin_to_roll", ".inf"),
        "thrust-limit-text.yaml": _mutate(tb, "max_spin_to_roll", "low"),
        "thrust-limit-huge.yaml": _mutate(tb, "max_spin_to_roll", "1e300"),
        "thrust-limits-scalar.yaml": _mutate(tb, "limits", "0.1").replace(
            "  max_spin_to_roll: 0.01", ""),
        "thrust-unknown-key.yaml": tb + "pich_radius: 25 mm\n",
        "thrust-missing-speed.yaml": tb.replace("shaft_speed: 1500 rpm", ""),
        "bevel-teeth-4.yaml": bevel.replace("{teeth: 24}", "{teeth: 4}"),
        "bevel-teeth-radii.yaml": bevel.replace("{teeth: 12}", "{teeth: 12, pitch_radius: 20 mm}")
        .replace("{teeth: 24}", "{teeth: 24, pitch_radius: 20 mm}").replace(
            "module: 2.5 mm", ""),
        "bevel-angle-200.yaml": _mutate(bevel, "shaft_angle", "200 deg"),
        "bevel-angle-0.yaml": _mutate(bevel, "shaft_angle", "0 deg"),
        "bevel-no-module.yaml": bevel.replace("module: 2.5 mm", ""),
        "bevel-gear-scalar.yaml": bevel.replace("{teeth: 12}", "12"),
        "bevel-mismatch-limit.yaml": _mutate(bevel, "max_apex_mismatch", "-1"),
        "disk-internal-big.yaml": _mutate(disk, "disk_radius", "90 mm"),
        "disk-contact-bad.yaml": _mutate(disk, "contact", "sideways"),
        "disk-negative.yaml": _mutate(disk, "surface_radius", "-80 mm"),
        "cone-angle-90.yaml": _mutate(cone, "half_angle", "90 deg"),
        "cone-angle-neg.yaml": _mutate(cone, "half_angle", "-10 deg"),
        "ball-thrust-radial.yaml": _mutate(ball, "type", "thrust"),
        "ball-no-loads.yaml": _mutate(ball, "radial_load", "0 kN"),
        "ball-reliability-80.yaml": _mutate(ball, "reliability", "80 %"),
        "ball-reliability-99.yaml": _mutate(ball, "reliability", "99"),
        "ball-kappa-low.yaml": _mutate(ball, "viscosity", "0.2 mm^2/s"),
        "ball-contamination.yaml": _mutate(ball, "contamination_factor", "1.5"),
        "ball-no-contamination.yaml": ball.replace("contamination_factor: 0.5", ""),
        "ball-no-rating.yaml": ball.replace("dynamic_load_rating: 55.3 kN", ""),
        "ball-temperature.yaml": _mutate(ball, "viscosity", "20 degC"),
        "drive-bearings-scalar.yaml": drive.replace("pinion_bearings:",
                                                    "pinion_bearings: 5\nx:"),
        "drive-bearings-numbers.yaml": drive.replace("gear_bearings:",
                                                     "gear_bearings: [1, 2]\nx:"),
        "drive-bearing-unknown.yaml": drive.replace("{position: 20 mm,",
                                                    "{colour: red, position: 20 mm,"),
        "drive-bearing-junk.yaml": drive.replace("{position: 20 mm,", "{position: '20 mm)',"),
        "drive-bearing-load.yaml": drive.replace("{position: 20 mm,",
                                                 "{axial_load: 1 kN, position: 20 mm,"),
        "drive-nested.yaml": drive.replace("  - {position: 150 mm,",
                                           "  - {position: 150 mm, x: [[[[1]]]],"),
        "drive-no-locating.yaml": drive.replace("locating: true", "locating: false"),
        "drive-thrust.yaml": drive.replace("{position: 20 mm, type: deep-groove",
                                           "{position: 20 mm, type: thrust"),
        "drive-same-position.yaml": drive.replace("position: 150 mm", "position: 90 mm"),
        "drive-no-torque.yaml": drive.replace("torque: 60 N*m", "torque: 0 N*m"),
        "bevel-sizing-hardness.yaml": sizing.replace("180 HB", "180 HRC"),
        "bevel-sizing-both-loads.yaml": sizing.replace("power: 7.5 kW",
                                                       "power: 7.5 kW\ntorque: 1 N*m"),
        "bevel-sizing-wide.yaml": sizing.replace("face_width: 27.94 mm", "face_width: 60 mm"),
        # Whole numbers too long for a float, where a number within a range is asked.
        "bevel-sizing-huge-quality.yaml": sizing.replace("quality_number: 7",
                                                         "quality_number: 1" + "0" * 400),
        "bevel-sizing-huge-hardness.yaml": sizing.replace("hardness: 180 HB",
                                                          "hardness: 1" + "0" * 400),
        "bevel-sizing-huge-reliability.yaml": sizing.replace("reliability: 0.99",
                                                             "reliability: 1" + "0" * 400),
    }}


def _pair_cases() -> dict[str, str]:
    """Bevel pairs whose speeds mix the fixed-axis and the epicyclic forms."""
    sizing = (SPECS / "bevel-gears-sizing.yaml").read_text()
    spiral = (SPECS / "bevel-gears-spiral.yaml").read_text()
    speed = re.compile(r"^gear_a_speed: .*$", re.MULTILINE)
    return {
        "bevel-speed-key.yaml": speed.sub("speed: 600 rpm", sizing),
        "bevel-no-speed.yaml": speed.sub("", sizing),
        "bevel-fixed-two-speeds.yaml": speed.sub("gear_a_speed: 600 rpm\ngear_b_speed: 300 rpm",
                                                 sizing),
        "bevel-arm-and-pinion.yaml": speed.sub("gear_a_speed: 600 rpm\narm_speed: 100 rpm",
                                               sizing),
        "bevel-fixed-bin-arm.yaml": sizing + "duty_cycle:\n  - {time: 100 %, arm_speed: 10 rpm}\n",
        "bevel-nitrided-grade-1.yaml": sizing.replace("  hardness: 180 HB",
                                                      "  material: nitrided"),
        "bevel-carburized-hardness.yaml": sizing.replace("  hardness: 180 HB",
                                                         "  hardness: 180 HB\n"
                                                         "  material: carburized"),
        "bevel-grade-4.yaml": sizing.replace("  hardness: 180 HB", "  hardness: 180 HB\n"
                                             "  grade: 4"),
        "bevel-material-unknown.yaml": sizing.replace("  hardness: 180 HB",
                                                      "  hardness: 180 HB\n"
                                                      "  material: cast-iron"),
        "bevel-gear-j-zero.yaml": sizing.replace("  hardness: 180 HB", "  hardness: 180 HB\n"
                                                 "  geometry_factor_bending_gear: 0"),
        "bevel-temperature-text.yaml": sizing.replace("  hardness: 180 HB",
                                                      "  hardness: 180 HB\n"
                                                      "  temperature: hot"),
        "bevel-spiral-rated.yaml": sizing + "spiral_angle: 35 deg\nhand: right\n"
        "rotation: clockwise\n",
        "bevel-spiral-no-hand.yaml": sizing.replace("rating:", "spiral_angle: 35 deg\n"
                                                    "rotation: clockwise\nrating:"),
        "bevel-spiral-hand-wrong.yaml": sizing + "spiral_angle: 35 deg\nhand: up\n"
        "rotation: clockwise\n",
        "bevel-hand-alone.yaml": sizing + "hand: left\n",
        "bevel-spiral-steep.yaml": sizing + "spiral_angle: 70 deg\nhand: left\n"
        "rotation: clockwise\n",
        "bevel-spiral-cutter-negative.yaml": spiral.replace("cutter_radius: 4.5 in",
                                                            "cutter_radius: -4.5 in"),
        "bevel-spiral-cutter-text.yaml": spiral.replace("cutter_radius: 4.5 in",
                                                        "cutter_radius: large"),
        "bevel-spiral-cutter-unit.yaml": spiral.replace("cutter_radius: 4.5 in",
                                                        "cutter_radius: 4.5 deg"),
        "bevel-straight-cutter.yaml": sizing.replace("  hardness: 180 HB",
                                                     "  hardness: 180 HB\n"
                                                     "  cutter_radius: 4.5 in"),
        "bevel-temperature-frozen.yaml": sizing.replace("  hardness: 180 HB",
                                                        "  hardness: 180 HB\n"
                                                        "  temperature: -40 degC"),
        "bevel-temperature-huge.yaml": sizing.replace("  hardness: 180 HB",
                                                      "  hardness: 180 HB\n"
                                                      "  temperature: 1e6 K"),
    }


#: Catalogue files that must each be refused, by the spec that names them.
CATALOGUE_HEADER = ("designation,maker,type,bore_diameter [mm],outside_diameter [mm],"
                    "width [mm],dynamic_load_rating [kN],static_load_rating [kN],source\n")
CATALOGUE_ROW = '6205,SKF,deep-groove,25,52,15,14.8,7.8,"SKF, catalogue, p. 306"\n'
BAD_CATALOGUES: dict[str, bytes] = {
    "empty": b"",
    "header-only": CATALOGUE_HEADER.encode(),
    "no-header": b"# a comment\n\n",
    "latin1": (CATALOGUE_HEADER + CATALOGUE_ROW.replace("catalogue", "catalogu\xe9")
               ).encode("latin-1"),
    "utf16": (CATALOGUE_HEADER + CATALOGUE_ROW).encode("utf-16"),
    "nul": (CATALOGUE_HEADER + CATALOGUE_ROW).encode().replace(b"SKF,", b"SK\x00F,", 1),
    "open-quote": (CATALOGUE_HEADER + CATALOGUE_ROW.replace('p. 306"', "p. 306")).encode(),
    "too-many-cells": (CATALOGUE_HEADER + CATALOGUE_ROW.replace("\n", ",x\n")).encode(),
    "formula-number": (CATALOGUE_HEADER + CATALOGUE_ROW.replace(",14.8,", ",=cmd|' /c'!A1,")
                       ).encode(),
    "nan-number": (CATALOGUE_HEADER + CATALOGUE_ROW.replace(",14.8,", ",nan,")).encode(),
    "huge-number": (CATALOGUE_HEADER + CATALOGUE_ROW.replace(",14.8,", ",1e400,")).encode(),
    "zero-rating": (CATALOGUE_HEADER + CATALOGUE_ROW.replace(",7.8,", ",0,")).encode(),
    "no-source": (CATALOGUE_HEADER + CATALOGUE_ROW.replace('"SKF, catalogue, p. 306"', "")
                  ).encode(),
    "bad-unit": CATALOGUE_HEADER.replace("[kN],source", "[kN/m],source").encode()
                + CATALOGUE_ROW.encode(),
    "no-unit": CATALOGUE_HEADER.replace("width [mm]", "width").encode()
               + CATALOGUE_ROW.encode(),
    "unit-on-text": CATALOGUE_HEADER.replace("maker", "maker [kN]").encode()
                    + CATALOGUE_ROW.encode(),
    "missing-column": CATALOGUE_HEADER.replace(",source", "").encode()
                      + CATALOGUE_ROW.rsplit(",", 2)[0].encode() + b"\n",
    "twice-column": CATALOGUE_HEADER.replace("maker,", "maker,maker,").encode()
                    + CATALOGUE_ROW.replace("SKF,", "SKF,SKF,", 1).encode(),
    "duplicate": (CATALOGUE_HEADER + CATALOGUE_ROW + CATALOGUE_ROW.lower()).encode(),
    "not-iso": (CATALOGUE_HEADER + CATALOGUE_ROW.replace(",52,", ",53,")).encode(),
    "wrong-type": (CATALOGUE_HEADER + CATALOGUE_ROW.replace("deep-groove", "spherical-roller")
                   ).encode(),
    "long-cell": (CATALOGUE_HEADER + CATALOGUE_ROW.replace("p. 306", "p" * 5000)).encode(),
    "control-text": (CATALOGUE_HEADER + CATALOGUE_ROW).encode().replace(
        b"SKF,", b"S\x1b[31mKF,", 1),
    "newline-in-cell": (CATALOGUE_HEADER + CATALOGUE_ROW.replace("p. 306", "p.\n306")).encode(),
}


def catalogue_folder() -> Path:
    """A folder (made once per run) holding the bad catalogues, which the catalogue
    cases name by their absolute paths."""
    folder = _CATALOGUE_FOLDER.get("path")
    if folder is None:
        folder = Path(tempfile.mkdtemp(prefix="bearingcalc-hostile-catalogues-"))
        for name, data in BAD_CATALOGUES.items():
            (folder / f"{name}.csv").write_bytes(data)
        (folder / "good.csv").write_text(CATALOGUE_HEADER + CATALOGUE_ROW)
        (folder / "a-folder.csv").mkdir()
        _CATALOGUE_FOLDER["path"] = folder
    return folder


_CATALOGUE_FOLDER: dict[str, Path] = {}


def _catalogue_cases() -> dict[str, str]:
    """Specs naming a bad catalogue, a missing one, or a designation it does not hold:
    each refused in one line that starts with the spec and names the catalogue's line.
    They name their catalogues by absolute paths, so the golden sample leaves them out."""
    folder = catalogue_folder()
    spec = ("kind: rolling-bearing\ncatalogue: {path}\ndesignation: {designation}\n"
            "static_factor: 14\nradial_load: 3 kN\naxial_load: 1 kN\nspeed: 1500 rpm\n"
            "lubrication: {{viscosity: 68 mm^2/s}}\ncontamination_factor: 0.5\n")
    cases = {f"catalogue-{name}.yaml": spec.format(path=folder / f"{name}.csv",
                                                   designation="6205")
             for name in BAD_CATALOGUES}
    good = folder / "good.csv"
    cases.update({
        "catalogue-missing.yaml": spec.format(path=folder / "nowhere.csv", designation="6205"),
        "catalogue-folder.yaml": spec.format(path=folder / "a-folder.csv", designation="6205"),
        "catalogue-not-held.yaml": spec.format(path=good, designation="6250"),
        "catalogue-designation-list.yaml": spec.format(path=good, designation="[6205]"),
        "catalogue-designation-true.yaml": spec.format(path=good, designation="true"),
        "catalogue-type-clash.yaml": spec.format(path=good, designation="6205")
        + "type: tapered-roller\n",
        "catalogue-maker-alone.yaml": spec.format(path=good, designation="6205").replace(
            "designation: 6205\n", "maker: SKF\n"),
        "catalogue-no-designation.yaml": spec.format(path=good, designation="6205").replace(
            "designation: 6205\n", "dynamic_load_rating: 14.8 kN\nstatic_load_rating: 7.8 kN\n"),
        "catalogue-nu-thrust.yaml": spec.format(path=SPECS / "catalogues" / "example.csv",
                                                designation="NU205 ECP"),
        "catalogue-catalogue-number.yaml": spec.format(path=12, designation="6205"),
    })
    return cases


def _duty_cases() -> dict[str, str]:
    """Duty cycles their rules refuse: each names the cycle, or the bin and its field."""
    duty = (SPECS / "rolling-bearing-duty-cycle.yaml").read_text()
    head, _, _ = duty.partition("duty_cycle:\n")
    tail = "limits:\n" + duty.partition("limits:\n")[2]

    def cycle(*bins: str) -> str:
        return head + "duty_cycle:\n" + "".join(f"  - {{{item}}}\n" for item in bins) + tail

    return {
        "rolling-duty-shares-90.yaml": cycle("time: 50 %, radial_load: 6 kN",
                                             "time: 40 %, radial_load: 9 kN"),
        "rolling-duty-share-negative.yaml": cycle("time: 110 %, radial_load: 6 kN",
                                                  "time: -10 %, radial_load: 9 kN"),
        "rolling-duty-share-text.yaml": cycle("time: most, radial_load: 6 kN"),
        "rolling-duty-unknown-field.yaml": cycle("time: 100 %, radial_load: 6 kN, colour: red"),
        "rolling-duty-geometry-field.yaml": cycle("time: 100 %, radial_load: 6 kN, "
                                                  "ball_diameter: 17 mm"),
        "rolling-duty-all-at-rest.yaml": cycle("time: 50 %, radial_load: 6 kN, speed: 0 rpm",
                                               "time: 50 %, radial_load: 9 kN, speed: 0 rpm"),
        "rolling-duty-empty.yaml": head + "duty_cycle: []\n" + tail,
        "rolling-duty-too-many.yaml": cycle(*["time: 0.000999, radial_load: 6 kN"] * 1001),
        "rolling-duty-bad-load.yaml": cycle("time: 100 %, radial_load: 6 kNx"),
        "rolling-duty-thrust-radial.yaml": cycle("time: 100 %, radial_load: 6 kN").replace(
            "type: deep-groove", "type: thrust").replace("static_factor: 13\n", ""),
        "rolling-duty-viscosity-with-grade.yaml": cycle("time: 100 %, radial_load: 6 kN, "
                                                        "viscosity: 30 mm^2/s"),
        "bevel-duty-not-rated.yaml": (SPECS / "bevel-gears.yaml").read_text()
        + "duty_cycle:\n  - {time: 100 %, arm_speed: 100 rpm}\n",
        "bevel-duty-face-width.yaml": (SPECS / "bevel-gears-sizing.yaml").read_text()
        + "duty_cycle:\n  - {time: 100 %, face_width: 30 mm}\n",
        "drive-duty-shares.yaml": (SPECS / "bevel-drive.yaml").read_text()
        + "duty_cycle:\n  - {time: 60 %}\n  - {time: 60 %, torque: 70 N*m}\n",
        "drive-duty-all-at-rest.yaml": (SPECS / "bevel-drive.yaml").read_text()
        + "duty_cycle:\n  - {time: 100 %, input_speed: 0 rpm}\n",
        "rolling-duty-speed-missing.yaml": cycle("time: 50 %, radial_load: 6 kN, "
                                                 "speed: 1000 rpm",
                                                 "time: 50 %, radial_load: 9 kN").replace(
            "speed: 1500 rpm                # every bin's, unless the bin gives its own\n", ""),
    }


def _roller_cases() -> dict[str, str]:
    """Roller bearings, pairs and adjusted arrangements that their rules refuse."""
    tapered = (SPECS / "rolling-bearing-tapered-geometry.yaml").read_text()
    ball = (SPECS / "ball-bearing.yaml").read_text()
    thrust = (TEMPLATES / "rolling-bearing.thrust-spherical-roller.yaml").read_text()
    drive = (SPECS / "bevel-drive-tapered.yaml").read_text()
    return {
        "rolling-no-length.yaml": re.sub(r"roller_length: .*\n", "", tapered),
        "rolling-length-zero.yaml": _mutate(tapered, "roller_length", "0 mm"),
        "rolling-length-negative.yaml": _mutate(tapered, "roller_length", "-12 mm"),
        "rolling-ball-count.yaml": tapered.replace("roller_count:", "ball_count:"),
        "rolling-conformity.yaml": tapered + "inner_groove_conformity: 0.52\n",
        "rolling-pair-deep-groove.yaml": ball + "arrangement: back-to-back\n",
        "rolling-pair-two-rows.yaml": tapered + "arrangement: tandem\nrows: 2\n",
        "rolling-three-rows.yaml": tapered + "rows: 3\n",
        "rolling-tapered-angle-50.yaml": _mutate(tapered, "contact_angle", "50 deg"),
        "rolling-cylindrical-angle.yaml": tapered.replace("tapered-roller",
                                                          "cylindrical-roller"),
        "rolling-thrust-low-axial.yaml": _mutate(thrust, "axial_load", "10 kN"),
        "rolling-thrust-angle-30.yaml": _mutate(thrust, "contact_angle", "30 deg"),
        "rolling-thrust-radial-90.yaml": thrust.replace("thrust-spherical-roller",
                                                        "thrust-cylindrical-roller")
        .replace("contact_angle: 50 deg", ""),
        "rolling-thrust-beyond-table-10.yaml": re.sub(r"(dynamic|static)_load_rating: .*\n",
                                                      "", thrust)
        + "roller_count: 6\nroller_diameter: 40 mm\nroller_length: 14 mm\n",
        "rolling-factors-single-on-pair.yaml": tapered + "arrangement: back-to-back\n"
        + "load_factors: {e: 0.37, y: 1.6}\n",
        "rolling-contact-too-wide.yaml": _mutate(tapered, "radial_load", "5e8 N"),
        "drive-adjusted-locating.yaml": drive.replace("{position: 85 mm,",
                                                      "{position: 85 mm, locating: true,"),
        "drive-adjusted-deep-groove.yaml": drive.replace(
            "pinion_arrangement: back-to-back", "pinion_arrangement: face-to-face").replace(
            "type: tapered-roller", "type: deep-groove", 1),
        "drive-pinion-pair.yaml": drive.replace("{position: 150 mm, type: tapered-roller,",
                                                "{position: 150 mm, type: tapered-roller, "
                                                "arrangement: tandem,"),
    }


def hostile_corpus() -> dict[str, bytes]:
    """File name -> bytes of every hostile case (over 300)."""
    cases: dict[str, bytes] = dict(STRUCTURAL)
    for kind, (example, fields, _) in KINDS.items():
        text = (SPECS / example).read_text()
        # Each bad value once per kind, on the kind's quantity fields in turn: every
        # field meets many classes, and the corpus stays quick to run.
        for i, value in enumerate(BAD_QUANTITY_TEXT):
            field = fields[i % len(fields)]
            cases[f"{kind}-{field}-text{i}.yaml"] = _mutate(
                text, field, json.dumps(value)).encode()
        for i, value in enumerate(BAD_QUANTITY_YAML):
            field = fields[(i + 1) % len(fields)]
            cases[f"{kind}-{field}-yaml{i}.yaml"] = _mutate(text, field, value).encode()
    for name, text in _physics_cases().items():
        cases[f"{PHYSICS_PREFIX}{name}"] = text.encode()
    return cases


#: Names of the cases whose fields are each valid but whose design is impossible: a
#: sweep may start from one (its points are gaps), every other command refuses it.
PHYSICS_PREFIX = "physics-"


def sweep_option(name: str) -> str:
    """A --vary option for the kind a case was made from (any kind will do otherwise)."""
    name = name.removeprefix(PHYSICS_PREFIX)
    for kind, (_, _, vary) in KINDS.items():
        if name.startswith(kind) or name.startswith(kind.split("-")[0]):
            return vary
    return KINDS["thrust-bearing"][2]
