"""Matched pairs as mounted (``method: iso-16281`` with ``arrangement: back-to-back``,
``face-to-face`` or ``tandem``) through the command line: the shaft's displacement,
each bearing's loads and every element's load against the independent shaft reference
(``tests/iso16281_shaft_reference.py``: its own maps, scipy's root), the preload at
rest against the closed forms, the pair's life as the Weibull product of the two
bearings' (written here from its definition), and each bad setting one line."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from tests import iso16281_reference as reference
from tests import iso16281_shaft_reference as shaft
from tests.conftest import solve_json
from tests.mounted_specs import TAPERED_ROLLERS

STEEL = 207.5e9

BALL_PAIR = """kind: rolling-bearing
type: angular-contact
arrangement: {arrangement}
method: iso-16281
contact_angle: 40 deg
dynamic_load_rating: 24 kN
static_load_rating: 15.6 kN
ball_count: 12
ball_diameter: 9.525 mm
pitch_diameter: 46 mm
inner_groove_conformity: 0.52
outer_groove_conformity: 0.53
width: 16 mm
{setting}
radial_load: 3 kN
axial_load: {axial}
speed: 3000 rpm
{extra}
"""
TAPERED_PAIR = """kind: rolling-bearing
type: tapered-roller
arrangement: {arrangement}
method: iso-16281
""" + TAPERED_ROLLERS + """\
width: 17.25 mm
{setting}
radial_load: 6 kN
axial_load: {axial}
speed: 3000 rpm
{extra}
"""
BALL = reference.BallBearing(12, 9.525e-3, 46e-3, 0.52, 0.53,
                             free_contact_angle=math.radians(40), elastic_modulus=STEEL)
TAPERED = reference.RollerBearing(17, 7.5e-3, 14e-3, 45e-3, contact_angle=math.radians(14),
                                  elastic_modulus=STEEL)


def _spacing(bearing, arrangement, width):
    """Two bearings side by side: their pressure centres lie c = (Dpw/2)·tan α past
    their middles, outward back-to-back, inward face-to-face."""
    angle = (bearing.free_contact_angle if isinstance(bearing, reference.BallBearing)
             else bearing.contact_angle)
    c = bearing.pitch_diameter / 2.0 * math.tan(angle)
    return {"back-to-back": width + 2 * c, "face-to-face": width - 2 * c,
            "tandem": width}[arrangement]


def _reference_pair(bearing, arrangement, spacing, end_play):
    """The reference's pair, bearing 1 (carrying +x thrust) first; its end play counted
    from first contact, so a tapered bearing's offset includes its first contact."""
    if arrangement == "tandem":
        pair = [shaft.ShaftBearing(bearing, shaft.origin_for_pressure_centre(
            bearing, x, 1), 1, shaft.first_contact(bearing)) for x in (-spacing / 2,
                                                                       spacing / 2)]
        return pair
    low, high = -spacing / 2, spacing / 2
    placed = ((low, 1), (high, -1)) if arrangement == "back-to-back" else ((high, 1),
                                                                           (low, -1))
    return [shaft.ShaftBearing(bearing, shaft.origin_for_pressure_centre(bearing, x, s), s,
                               shaft.first_contact(bearing) - end_play / 2)
            for x, s in placed]


def _system_life(lives, slope):
    return sum(life ** -slope for life in lives) ** (-1 / slope)


CASES = [
    (BALL_PAIR, BALL, "back-to-back", {"end_play": -20e-6}, 1500.0, ""),
    (BALL_PAIR, BALL, "face-to-face", {"end_play": 10e-6}, 2500.0, ""),
    (BALL_PAIR, BALL, "back-to-back", {"preload": 300.0}, 1500.0, "tilting_moment: 20 N*m"),
    (BALL_PAIR, BALL, "tandem", None, 4000.0, "pair_spacing: 30 mm"),
    (TAPERED_PAIR, TAPERED, "back-to-back", {"end_play": 15e-6}, 2000.0, ""),
    (TAPERED_PAIR, TAPERED, "face-to-face", {"preload": 2000.0}, 1000.0, ""),
    (TAPERED_PAIR, TAPERED, "back-to-back", {"end_play": -10e-6}, 0.0,
     "pair_spacing: 80 mm"),
]


def _setting_text(setting):
    if setting is None:
        return ""
    (key, value), = setting.items()
    return f"setting: {{{key}: {value * 1e6} µm}}" if key == "end_play" else \
        f"setting: {{preload: {value} N}}"


@pytest.mark.parametrize(("template", "bearing", "arrangement", "setting", "axial", "extra"),
                         CASES)
def test_a_pair_is_the_references(cli, spec_file, template, bearing, arrangement, setting,
                                  axial, extra):
    text = template.format(arrangement=arrangement, setting=_setting_text(setting),
                           axial=f"{axial} N", extra=extra)
    [record] = solve_json(cli, spec_file(text))
    results = record["results"]
    width = 16e-3 if bearing is BALL else 17.25e-3
    spacing = (float(extra.split(": ")[1].split()[0]) * 1e-3 if "pair_spacing" in extra
               else _spacing(bearing, arrangement, width))
    if setting is None:
        end_play = 0.0
    elif "preload" in setting:
        end_play = shaft.end_play_for_preload(bearing, setting["preload"]) + \
            2 * shaft.first_contact(bearing)
    else:
        end_play = setting["end_play"]
    pair = _reference_pair(bearing, arrangement, spacing, end_play)
    moment = float(extra.split(": ")[1].split()[0]) if "tilting_moment" in extra else 0.0
    fr = 3000.0 if bearing is BALL else 6000.0
    solved = shaft.solve_shaft(pair, (axial, fr, 0.0, 0.0, moment))
    q = solved["Q"]
    assert results["pair_spacing_used"] == pytest.approx(spacing, rel=1e-12)
    assert results["ring_displacement_radial"] == pytest.approx(q[1], rel=1e-8)
    assert results["ring_displacement_axial"] == pytest.approx(q[0], rel=1e-7,
                                                               abs=1e-9 * abs(q[1]))
    assert results["ring_tilt"] == pytest.approx(q[4], rel=1e-7, abs=1e-12)
    for number, (axial_load, loads) in enumerate(zip(solved["axial_load"], solved["load"],
                                                     strict=True), start=1):
        assert results[f"bearing_{number}_axial_load"] == pytest.approx(
            axial_load, rel=1e-7, abs=1e-6 * fr)
        assert results[f"bearing_{number}_max_element_load"] == pytest.approx(
            loads.max(), rel=1e-7, abs=1e-9 * fr)
        mine = [results[f"bearing_{number}_element_{k}_load"] for k in range(1, loads.size + 1)]
        np.testing.assert_allclose(mine, loads, rtol=1e-7, atol=1e-8 * fr)
    c = 24000.0 if bearing is BALL else 54000.0
    if bearing is BALL:
        lives = [reference.ball_reference_life(bearing, loads, c)["life_million"]
                 for loads in solved["load"]]
        slope = 10 / 9
    else:
        lives = [reference.roller_reference_life(bearing, laminae, c)["life_million"]
                 for laminae in solved["lamina_load"]]
        slope = 9 / 8
    assert results["reference_rating_life_revolutions"] == pytest.approx(
        _system_life(lives, slope) * 1e6, rel=1e-7)
    assert results["stiffness_radial"] == pytest.approx(solved["stiffness"][1, 1], rel=1e-5)


@pytest.mark.parametrize(("template", "bearing"), [(BALL_PAIR, BALL),
                                                   (TAPERED_PAIR, TAPERED)])
def test_the_preload_at_rest_is_the_closed_forms(cli, spec_file, template, bearing):
    """An end play of −24 µm leaves each bearing pushed 12 µm past first contact at rest:
    its axial load is the closed form's (Harris's for balls, the laminae's sum for
    rollers) at that deflection."""
    text = template.format(arrangement="back-to-back", setting="setting: {end_play: -24 µm}",
                           axial="0 N", extra="")
    [record] = solve_json(cli, spec_file(text))
    expected = shaft.axial_load(bearing, 12e-6 + shaft.first_contact(bearing))
    assert record["results"]["preload_force"] == pytest.approx(expected, rel=1e-9)


def test_a_preload_gives_each_bearing_that_axial_load_at_rest(cli, spec_file):
    text = BALL_PAIR.format(arrangement="face-to-face", setting="setting: {preload: 1.2 kN}",
                            axial="0 N", extra="").replace("radial_load: 3 kN", "radial_load: 1 mN")
    [record] = solve_json(cli, spec_file(text))
    results = record["results"]
    for number in (1, 2):
        assert results[f"bearing_{number}_axial_load"] == pytest.approx(1200.0, rel=1e-6)


@pytest.mark.parametrize(("preload", "radial", "skids"), [
    ("1.2 kN", "1 mN", False), ("50 N", "1 mN", True), ("50 N", "3 kN", False)])
def test_the_minimum_load_is_judged_on_the_load_the_balls_carry(cli, spec_file, preload,
                                                                radial, skids):
    """The makers' minimum load, 1 % of the pair's C, judged against the
    equivalent reference load: a preload that loads the balls (the makers' cure for
    skidding) clears it with no external load, a light preload does not, and a radial
    load does."""
    text = BALL_PAIR.format(arrangement="face-to-face", setting=f"setting: {{preload: {preload}}}",
                            axial="0 N", extra="").replace("radial_load: 3 kN",
                                                           f"radial_load: {radial}")
    [record] = solve_json(cli, spec_file(text))
    load = record["results"]["dynamic_equivalent_reference_load"]
    rating = record["results"]["dynamic_load_rating"]
    assert (load < 0.01 * rating) == skids
    assert any("balls may skid" in w for w in record["warnings"]) == skids


@pytest.mark.parametrize(("arrangement", "setting", "extra", "field"), [
    ("single", "setting: {end_play: 10 µm}", "", "setting"),
    ("tandem", "setting: {end_play: 10 µm}", "", "setting"),
    ("back-to-back", "", "", "setting"),
    ("back-to-back", "setting: {end_play: 10 µm, preload: 1 kN}", "", "setting.preload"),
    ("back-to-back", "setting: {}", "", "setting.end_play"),
    ("back-to-back", "setting: {preload: -1 kN}", "", "setting.preload"),
    ("back-to-back", "setting: {preload: 0 N}", "", "setting.preload"),
    ("back-to-back", "setting: {end_play: 10 mN}", "", "setting.end_play"),
    ("single", "", "pair_spacing: 50 mm", "pair_spacing"),
    ("back-to-back", "setting: {end_play: 10 µm}", "pair_spacing: -5 mm", "pair_spacing"),
])
def test_bad_input_of_a_pair_is_one_line(cli, spec_file, arrangement, setting, extra, field):
    text = BALL_PAIR.format(arrangement=arrangement, setting=setting, axial="1 kN",
                            extra=extra)
    run = cli("solve", spec_file(text))
    assert run.code == 2, run.out
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in run.err, run.err
    assert f": {field}: " in lines[0], lines[0]


@pytest.mark.parametrize(("change", "field"), [
    (("width: 16 mm\n", ""), "pair_spacing"),
    (("method: iso-16281\n", ""), "setting"),
])
def test_a_pair_missing_its_spacing_or_method_is_one_line(cli, spec_file, change, field):
    """No width and no pair_spacing: the spacing is unknown; a setting under the
    catalogue method: the method takes none."""
    text = BALL_PAIR.format(arrangement="back-to-back", setting="setting: {end_play: 5 µm}",
                            axial="1 kN", extra="").replace(*change)
    run = cli("solve", spec_file(text))
    assert run.code == 2
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and f": {field}: " in lines[0], run.err


def test_a_sweep_over_the_end_play_equals_each_points_own_solve(cli, spec_file, tmp_path):
    """Every number of the pair is swept in one vectorised call; the life has its optimum
    at a slight preload, as the classic curve of life against end play has it."""
    text = TAPERED_PAIR.format(arrangement="back-to-back", setting="setting: {end_play: 0 µm}",
                               axial="2 kN", extra="")
    run = cli("sweep", spec_file(text), "--vary", "setting.end_play=-40um:40um:5",
              "--format", "json")
    assert run.code == 0, run.err
    rows = [json.loads(line) for line in run.out.splitlines() if line.strip()]
    lives = []
    for row in rows:
        end_play = row["inputs"]["setting.end_play"]
        own = solve_json(cli, spec_file(text.replace(
            "end_play: 0 µm", f"end_play: {end_play * 1e6} µm"), name="own.yaml"))[0]
        for key in ("reference_rating_life", "bearing_2_axial_load", "stiffness_axial"):
            assert row["results"][key] == pytest.approx(own["results"][key], rel=1e-9)
        lives.append(row["results"]["reference_rating_life"])
    best = int(np.argmax(lives))
    assert rows[best]["inputs"]["setting.end_play"] < 0.0


def test_a_toleranced_pair_runs_every_study_and_its_report(cli, spec_file, tmp_path):
    text = BALL_PAIR.format(arrangement="back-to-back",
                            setting="setting: {end_play: -10 µm ± 5 µm}", axial="1.5 kN",
                            extra="pair_spacing: 60 mm ± 0.5 mm")
    path = spec_file(text)
    run = cli("tolerance", path, "--samples", "500", "--format", "json")
    assert run.code in (0, 1), run.err
    record = json.loads(run.out)
    assert "Traceback" not in run.err and record
    report = tmp_path / "pair.html"
    run = cli("report", path, "--output", report)
    assert run.code == 0, run.err
    html = report.read_text(encoding="utf-8")
    assert "bearing_2_axial_load" in html and "bearing 1: rolling elements" in html
