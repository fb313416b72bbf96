"""One cause, one line: a problem that follows from another is not reported, and where
an unknown key is a typo of a field, the typo's line is the one shown; problems that do
not follow from each other are all still reported."""

from __future__ import annotations

import pytest

from bearingcalc.errors import SpecError
from bearingcalc.evaluation import evaluate_documents
from bearingcalc.models.yaml_loader import load_documents

BALL = """kind: rolling-bearing
dynamic_load_rating: 50 kN
static_load_rating: 30 kN
load_factors: {x: 0.56, y: 1.6, e: 0.3}
radial_load: 6 kN
axial_load: 1 kN
speed: 1500 rpm
"""
SPHERICAL = """kind: rolling-bearing
type: spherical-roller
contact_angle: 10 deg
dynamic_load_rating: 50 kN
static_load_rating: 30 kN
load_factors: {y: 1.6, e: 0.3}
radial_load: 6 kN
axial_load: 1 kN
speed: 1500 rpm
"""


def lines(text: str) -> list[tuple[int | None, str | None]]:
    """(line, field) of every problem of the spec, which must be refused."""
    (result,) = evaluate_documents(load_documents("spec.yaml", text))
    assert isinstance(result, SpecError), "solved, not refused"
    return [(each.line, each.field) for each in (result, *result.more)]


def line_of(text: str, key: str) -> int:
    return next(i for i, row in enumerate(text.splitlines(), 1) if row.startswith(f"{key}:"))


@pytest.mark.parametrize(("text", "field"), [
    (BALL + "rows: 2\n", "rows"),
    (SPHERICAL + "arrangement: back-to-back\n", "arrangement"),
    (BALL.replace("dynamic", "type: angular-contact\ncontact_angle: 90 deg\ndynamic", 1),
     "contact_angle"),
    (BALL.replace("dynamic", "contact_angle: 90 deg\ndynamic", 1), "contact_angle"),
], ids=["rows-on-a-ball-bearing", "a-spherical-pair", "90-deg-angular-contact",
        "90-deg-deep-groove"])
def test_a_field_given_wrong_is_the_one_line(text: str, field: str) -> None:
    assert lines(text) == [(line_of(text, field), field)]


def test_problems_that_do_not_follow_from_each_other_are_all_reported() -> None:
    text = BALL.replace("speed: 1500 rpm\n", "") + "rows: 2\n"
    assert {field for _, field in lines(text)} == {"rows", "speed"}


def test_a_wrong_pair_still_reports_factors_missing_for_a_single_bearing_too() -> None:
    # {e} alone lacks y for the single bearing the spec becomes once the pair goes.
    text = SPHERICAL.replace("load_factors: {y: 1.6, e: 0.3}", "load_factors: {e: 0.3}") \
        + "arrangement: back-to-back\n"
    fields = [field for _, field in lines(text)]
    assert "arrangement" in fields and len(fields) == len(set(fields))


def test_a_typo_of_a_load_is_the_one_line() -> None:
    text = BALL.replace("radial_load: 6 kN\naxial_load: 1 kN\n", "radial_lod: 5 kN\n")
    assert lines(text) == [(line_of(text, "radial_lod"), "radial_lod")]


def test_a_typo_of_a_required_key_is_not_also_missing() -> None:
    text = "kind: bevel-drive\ninput_sped: 1500 rpm\n"
    found = lines(text)
    assert (2, "input_sped") in found
    assert "input_speed" not in {field for _, field in found}


def test_a_typo_beside_an_independent_problem_keeps_both() -> None:
    text = BALL.replace("speed: 1500 rpm\n", "sped: 1500 rpm\n") + "rows: 2\n"
    fields = {field for _, field in lines(text)}
    assert fields == {"sped", "rows"}


def test_a_drive_s_bearing_reports_one_cause_too() -> None:
    text = """kind: bevel-drive
gear_a: {teeth: 13}
gear_b: {teeth: 43}
module: 4 mm
face_width: 20 mm
torque: 60 N*m
input_speed: 1500 rpm
pinion_bearings:
  - {position: 40 mm, dynamic_load_rating: 30 kN, static_load_rating: 20 kN,
     load_factors: {x: 0.56, y: 1.6, e: 0.3}, rows: 2, locating: true}
  - {position: 120 mm, dynamic_load_rating: 30 kN, static_load_rating: 20 kN}
"""
    (result,) = evaluate_documents(load_documents("spec.yaml", text))
    if isinstance(result, SpecError):
        fields = [each.field for each in (result, *result.more)]
        assert "pinion_bearings.1.rows" in fields
        assert not any(field.startswith("pinion_bearings.1.load_factors")
                       for field in fields), fields
    else:
        pytest.fail("a ball bearing with rows: 2 was solved")
