"""A bevel pair on fixed axes, given by the pinion's speed alone: its speeds by the gear
ratio worked here by hand, the epicyclic-only results left out, and the two forms of
the pair kept apart in every message."""

from __future__ import annotations

import math

import pytest

from tests.conftest import ROOT, solve_json

RPM = 2 * math.pi / 60
PAIR = ("kind: bevel-gears\ngear_a: {teeth: 20}\ngear_b: {teeth: 43}\nmodule: 3 mm\n"
        "shaft_angle: 90 deg\n")
EPICYCLIC_ONLY = ("gear_a_speed_relative_to_arm", "relative_speed", "contact_point_speed")
APEX = ("apex_mismatch", "slip_margin")


def test_the_pinions_speed_alone_turns_the_pair(cli, spec_file):
    """v = r₁·ω₁ at the pitch circle, r₁ = m·z₁/2; gear A's absolute speed is the given
    one; the epicyclic pair's own results and the apex mismatch (zero by construction,
    the pitch angles being solved) are left out."""
    (record,) = solve_json(cli, spec_file(PAIR + "gear_a_speed: 1500 rpm\n"))
    results = record["results"]
    assert results["gear_a_speed"] == pytest.approx(1500 * RPM, rel=1e-12)
    assert results["pitch_line_speed"] == pytest.approx(0.003 * 20 / 2 * 1500 * RPM, rel=1e-12)
    assert not set(EPICYCLIC_ONLY + APEX) & set(results)


def test_gear_bs_speed_alone_gives_the_pinions_by_the_ratio(cli, spec_file):
    """ω₁ = ω₂·z₂/z₁ for a pair on fixed axes given gear B's speed."""
    (record,) = solve_json(cli, spec_file(PAIR + "gear_b_speed: 600 rpm\n"))
    assert record["results"]["gear_a_speed"] == pytest.approx(600 * 43 / 20 * RPM, rel=1e-12)


def test_the_same_pair_in_both_forms_agrees(cli, spec_file):
    """The fixed-axis pair is the epicyclic one with its arm at rest and gear B at
    −ω₁·z₁/z₂: every result both have is the same."""
    (fixed,) = solve_json(cli, spec_file(PAIR + "gear_a_speed: 1500 rpm\n", "fixed.yaml"))
    (epicyclic,) = solve_json(cli, spec_file(
        PAIR + f"arm_speed: 0 rpm\ngear_b_speed: {-1500 * 20 / 43!r} rpm\n", "epi.yaml"))
    assert set(epicyclic["results"]) - set(fixed["results"]) == set(EPICYCLIC_ONLY + APEX)
    for key, value in fixed["results"].items():
        assert value == pytest.approx(epicyclic["results"][key], rel=1e-12), key


def test_pitch_angles_given_by_hand_keep_the_apex_mismatch(cli, spec_file):
    text = PAIR.replace("gear_a: {teeth: 20}", "gear_a: {teeth: 20, pitch_angle: 25 deg}")
    text = text.replace("gear_b: {teeth: 43}", "gear_b: {teeth: 43, pitch_angle: 65 deg}")
    (record,) = solve_json(cli, spec_file(text.replace("shaft_angle: 90 deg\n", "")
                                          + "gear_a_speed: 1500 rpm\n"))
    assert set(APEX) <= set(record["results"])
    assert not set(EPICYCLIC_ONLY) & set(record["results"])


@pytest.mark.parametrize(("extra", "field", "words"), [
    ("speed: 1500 rpm\n", "speed", ("gear_a_speed", "arm_speed", "fixed axes", "epicyclic")),
    ("", "gear_a_speed", ("gear_a_speed", "arm_speed")),
    ("arm_speed: 100 rpm\ngear_a_speed: 1500 rpm\n", "gear_a_speed", ("epicyclic",)),
    ("gear_a_speed: 1500 rpm\ngear_b_speed: 600 rpm\n", "gear_b_speed", ("not both",)),
])
def test_the_forms_are_named_in_one_line(cli, spec_file, extra, field, words):
    """``speed`` is near names of both forms; the message names both and suggests
    neither alone, which would change the meaning."""
    run = cli("solve", spec_file(PAIR + extra))
    assert run.code == 2 and run.err.count("\n") == 1, run.err
    assert f": {field}: " in run.err and all(word in run.err for word in words), run.err
    assert "did you mean" not in run.err


def test_a_drive_is_a_pair_on_fixed_axes(cli):
    (record,) = solve_json(cli, ROOT / "specs" / "bevel-drive.yaml")
    assert not set(EPICYCLIC_ONLY + APEX) & set(record["results"])
    assert record["results"]["gear_a_speed"] == pytest.approx(1500 * RPM, rel=1e-12)


SIZING = ROOT / "specs" / "bevel-gears-sizing.yaml"


@pytest.mark.parametrize(("vary", "warned"), [
    ("module=4mm:6mm:3", True), ("face_width=25mm:30mm:3", True),
    ("power=5kW:9kW:3", False)])
def test_a_sweep_of_the_tooth_geometry_says_j_and_i_stay_typed(cli, vary, warned):
    """J and I are typed for one tooth geometry: a sweep that moves it says so, once, on
    stderr (the results may be a CSV stream); one that moves the load does not."""
    run = cli("sweep", SIZING, "--vary", vary, "--format", "csv")
    assert run.code in (0, 1), run.err
    notes = [line for line in run.err.splitlines() if "J and I" in line]
    assert len(notes) == (1 if warned else 0), run.err
    if warned:
        assert vary.split("=")[0] in notes[0]


def test_a_study_of_the_tooth_geometry_says_j_and_i_stay_typed(cli, spec_file):
    text = SIZING.read_text().replace("face_width: 27.94 mm", "face_width: 27.94 mm ± 0.5 mm")
    run = cli("tolerance", spec_file(text), "--method", "worst-case", "--format", "json")
    assert run.code in (0, 1), run.err
    import json
    (record,) = [json.loads(line) for line in run.out.splitlines()]
    assert any("J and I" in note and "face_width" in note for note in record["warnings"])
