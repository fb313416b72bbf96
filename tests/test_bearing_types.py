"""The table of bearing types (``bearingcalc.core.bearing_types``): its traits against the
standards and against what the spec models refuse, the docs' type table against it, and
no module outside it comparing a type's name.
"""

from __future__ import annotations

import ast
import math
import re
from pathlib import Path
from typing import get_args

import numpy as np
import pytest

from bearingcalc.catalogue.reader import ROW_TYPES
from bearingcalc.core import iso76, iso281, roller_ratings
from bearingcalc.core.bearing_types import (
    DRAWN_CUP_MATERIAL_FACTOR,
    SPEC_NAMES,
    TABLE,
    TYPE_NAMES,
    AngleRule,
    LoadRule,
    RatingFormula,
    StaticFormula,
    names_where,
    traits,
    type_name,
)
from bearingcalc.errors import SpecError
from bearingcalc.models.rolling_bearing import BearingType
from bearingcalc.models.yaml_loader import load_documents
from bearingcalc.parsing import parse_document

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "bearingcalc"
#: The table itself: the one module that names types to tell them apart.
TABLE_MODULE = PACKAGE / "core" / "bearing_types.py"

#: ISO 281:2007 Table 1 ("Values of bm for rolling bearings"), typed from the standard:
#: radial ball bearings 1.3 (self-aligning ones among them); angular-contact ball
#: bearings are radial ball bearings; thrust ball 1.3; radial cylindrical roller 1.1;
#: tapered 1.1; spherical 1.15; needle roller bearings with machined rings 1.1 and
#: drawn-cup 1.0; thrust cylindrical 1.0; thrust tapered 1.1; thrust spherical 1.15.
ISO_281_TABLE_1 = {
    "deep-groove": 1.3, "angular-contact": 1.3, "self-aligning-ball": 1.3,
    "thrust-ball": 1.3, "cylindrical-roller": 1.1, "needle-roller": 1.1,
    "tapered-roller": 1.1, "spherical-roller": 1.15, "thrust-cylindrical-roller": 1.0,
    "thrust-tapered-roller": 1.1, "thrust-spherical-roller": 1.15,
}
#: GOST 18855-2013 (the Russian adoption of ISO 281:2007), Table 1, typed from it
#: separately, by its own wording of the bearing kinds: шариковые радиальные и
#: радиально-упорные 1.3, шариковые упорные 1.3, роликовые радиальные с короткими
#: цилиндрическими роликами 1.1, конические 1.1, сферические 1.15, игольчатые с
#: механически обработанными кольцами 1.1, с штампованным наружным кольцом 1.0,
#: упорные цилиндрические 1.0, упорные конические 1.1, упорные сферические 1.15.
GOST_18855_TABLE_1 = {
    ("ball", "radial"): 1.3, ("ball", "thrust"): 1.3, ("cylindrical", "radial"): 1.1,
    ("tapered", "radial"): 1.1, ("spherical", "radial"): 1.15, ("needle", "radial"): 1.1,
    ("cylindrical", "thrust"): 1.0, ("tapered", "thrust"): 1.1, ("spherical", "thrust"): 1.15,
}
GOST_DRAWN_CUP = 1.0


def _gost_key(name: str) -> tuple[str, str]:
    entry = traits(name)
    shape = "ball" if entry.family == "ball" else next(
        word for word in ("cylindrical", "tapered", "spherical", "needle") if word in name)
    return shape, "thrust" if entry.thrust else "radial"


@pytest.mark.parametrize("name", TYPE_NAMES)
def test_material_factor_is_iso_281_table_1_and_gost_18855(name):
    entry = traits(name)
    assert entry.material_factor == ISO_281_TABLE_1[name]
    assert entry.material_factor == GOST_18855_TABLE_1[_gost_key(name)]


def test_drawn_cup_factor_and_the_ball_solver_agree_with_table_1():
    assert DRAWN_CUP_MATERIAL_FACTOR == GOST_DRAWN_CUP == 1.0
    assert names_where(drawn_cup=True) == ("needle-roller",)
    # the ball bearings' C is rated by iso281 with its own bm: the table's
    assert {traits(name).material_factor for name in names_where(family="ball")} == {
        iso281.MATERIAL_FACTOR}


def test_roller_rating_uses_the_tables_bm():
    """C of every radial roller type from one geometry: in the ratio of their bm, the
    rest of ISO 281 8.1's formula being the same (at α = 0 for all, by the formula)."""
    ratings = {name: float(roller_ratings.roller_dynamic_load_rating(
        14, 11e-3, 11e-3, 64e-3, 0.0, bearing_type=name)[0])
        for name in names_where(family="roller", thrust=False)}
    base = ratings["cylindrical-roller"] / ISO_281_TABLE_1["cylindrical-roller"]
    for name, rating in ratings.items():
        assert rating == pytest.approx(base * ISO_281_TABLE_1[name], rel=1e-12)
    drawn, _ = roller_ratings.roller_dynamic_load_rating(
        14, 11e-3, 11e-3, 64e-3, 0.0, bearing_type="needle-roller", drawn_cup=True)
    assert float(drawn) == pytest.approx(base * GOST_DRAWN_CUP, rel=1e-12)


def test_names_and_spellings():
    """One name inside (the catalogue's), the spec's ``thrust`` resolving to it."""
    assert type_name("thrust") == type_name("thrust-ball") == "thrust-ball"
    assert traits("thrust") is traits("thrust-ball")
    assert get_args(BearingType) == SPEC_NAMES
    assert ROW_TYPES == TYPE_NAMES == tuple(entry.name for entry in TABLE)
    assert set(SPEC_NAMES) == set(TYPE_NAMES) | {"thrust"}
    assert type_name("no-such-type") == "no-such-type"


@pytest.mark.parametrize("entry", TABLE, ids=lambda entry: entry.name)
def test_traits_hang_together(entry):
    """ISO 281 divides radial (α <= 45°) from thrust (α > 45°) bearings; a fixed or
    default angle lies on its side; only bearings that carry thrust one way pair."""
    if entry.contact_angle is not None:
        assert (entry.contact_angle > math.pi / 4) == entry.thrust
    assert (entry.angle_rule is AngleRule.GIVEN) == (entry.contact_angle is None)
    assert (entry.example_angle is not None) == (entry.angle_rule is AngleRule.GIVEN)
    assert entry.pairable == entry.one_way
    assert entry.rows == ((1,) if entry.family == "ball" or entry.thrust else (1, 2))
    thrust_formulas = {RatingFormula.THRUST_BALL, RatingFormula.THRUST_ROLLER}
    if entry.rating_formula is not RatingFormula.CATALOGUE:
        assert (entry.rating_formula in thrust_formulas) == entry.thrust
        assert entry.rating_formula.name.endswith(entry.family.upper())
    assert entry.name in entry.spec_names and entry.spec_names[-1] == entry.name
    assert entry.crowned == ("spherical" in entry.name)
    if entry.crowned:
        assert {"roller_profile_radius", "raceway_radius"} <= entry.fields


def test_load_rules_are_those_of_the_solvers():
    """P by each rule, from ISO 281's words: a thrust ball bearing P = Fa; a cylindrical
    or needle one P = Fr whatever Fa; Table 3 in α for an angular-contact bearing
    (α = 40°: X = 0.35, Y = 0.57, e = 1.14); ISO 76 P0 = Fa of a thrust ball bearing."""
    fr, fa = 1000.0, 3000.0
    for name in names_where(load_rule=LoadRule.AXIAL_ONLY):
        assert float(iso281.equivalent_dynamic_load(0.0, fa, name, math.pi / 2).load) == fa
        assert float(iso76.static_equivalent_load(0.0, fa, name, math.pi / 2)) == fa
    for name in names_where(load_rule=LoadRule.RADIAL_ONLY):
        load = roller_ratings.roller_equivalent_dynamic_load(fr, fa, 0.0, bearing_type=name,
                                                             double_row=False)
        assert float(load.load) == fr
    (angular,) = names_where(load_rule=LoadRule.ANGLE_TABLE)
    found = iso281.equivalent_dynamic_load(fr, fa, angular, math.radians(40))
    assert float(found.load) == pytest.approx(0.35 * fr + 0.57 * fa, rel=1e-12)
    assert float(np.asarray(found.e)) == pytest.approx(1.14, rel=1e-12)
    assert names_where(static_formula=StaticFormula.CATALOGUE) == (
        "self-aligning-ball", "thrust-ball")


def _problems(tmp_path: Path, fields: dict[str, object]) -> list[str]:
    """The fields the spec models blame in a rolling bearing of ``fields``."""
    lines = ["kind: rolling-bearing", "radial_load: 5 kN", "axial_load: 1 kN",
             "speed: 1000 rpm", "dynamic_load_rating: 30 kN", "static_load_rating: 25 kN"]
    lines += [f"{key}: {value}" for key, value in fields.items()]
    path = tmp_path / "bearing.yaml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    (document,) = load_documents(path)
    try:
        parse_document(document)
    except SpecError as error:
        return [problem.field for problem in error.problems]
    return []


def _spec_name(entry) -> str:
    return entry.spec_names[0]


def _angle(entry) -> dict[str, object]:
    return {} if entry.example_angle is None else {"contact_angle": entry.example_angle}


@pytest.mark.parametrize("entry", TABLE, ids=lambda entry: entry.name)
def test_pairable_is_what_the_model_pairs(tmp_path, entry):
    fields = {"type": _spec_name(entry), "arrangement": "back-to-back", **_angle(entry)}
    refused = "arrangement" in _problems(tmp_path, fields)
    assert refused == (not entry.pairable)


@pytest.mark.parametrize("entry", [entry for entry in TABLE if entry.family == "roller"],
                         ids=lambda entry: entry.name)
def test_rows_are_what_the_model_takes(tmp_path, entry):
    for rows in (1, 2):
        fields = {"type": _spec_name(entry), "rows": rows, **_angle(entry)}
        assert ("rows" in _problems(tmp_path, fields)) == (rows not in entry.rows)


@pytest.mark.parametrize("entry", TABLE, ids=lambda entry: entry.name)
def test_angle_rule_is_what_the_model_asks(tmp_path, entry):
    """A type that needs its angle is refused without one; a fixed angle is refused
    when another is given."""
    problems = _problems(tmp_path, {"type": _spec_name(entry)})
    assert ("contact_angle" in problems) == (entry.angle_rule is AngleRule.GIVEN)
    if entry.angle_rule is AngleRule.FIXED:
        other = "10 deg" if entry.contact_angle == 0 else "80 deg"
        assert "contact_angle" in _problems(tmp_path, {"type": _spec_name(entry),
                                                        "contact_angle": other})


def _docs_table() -> dict[str, dict[str, str]]:
    """docs/kinds/rolling-bearing.md's table of types: spelling -> its columns."""
    text = (ROOT / "docs" / "kinds" / "rolling-bearing.md").read_text(encoding="utf-8")
    section = text.split("## Types", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines()
            if line.startswith("| `") and not line.startswith("| `type`")]
    table = {}
    for line in rows:
        names, elements, angle, rating, notes = (cell.strip() for cell in
                                                 line.strip("|").split("|"))
        for name in re.findall(r"`([a-z-]+)`", names):
            table[name] = {"elements": elements, "angle": angle, "rating": rating,
                           "notes": notes}
    return table


def test_docs_type_table_is_the_traits_table():
    table = _docs_table()
    assert set(table) == set(SPEC_NAMES)
    for name, columns in table.items():
        entry = traits(name)
        assert columns["elements"].startswith("balls" if entry.family == "ball"
                                              else "rollers")
        assert columns["angle"].startswith("required") == (entry.angle_rule
                                                           is AngleRule.GIVEN)
        assert ("may be paired" in columns["notes"]) == entry.pairable
        assert ("no radial load" in columns["notes"]) == (
            entry.load_rule is LoadRule.AXIAL_ONLY or (
                entry.thrust and entry.angle_rule is AngleRule.FIXED))
        assert ("P = Fr" in columns["notes"]) == (entry.load_rule is LoadRule.RADIAL_ONLY)
        assert (columns["rating"] == "catalogue only") == (
            entry.rating_formula is RatingFormula.CATALOGUE)
        assert ("C0 from the catalogue only" in columns["rating"]) == (
            entry.static_formula is StaticFormula.CATALOGUE
            and entry.rating_formula is not RatingFormula.CATALOGUE)


def test_catalogue_docs_list_the_row_types():
    text = (ROOT / "docs" / "catalogues.md").read_text(encoding="utf-8")
    line = next(line for line in text.splitlines() if line.startswith("| `type` |"))
    assert tuple(re.findall(r"`([a-z-]+)`", line.split("|")[3])) == TYPE_NAMES


def _type_names_compared(tree: ast.AST) -> list[tuple[int, str]]:
    """(line, name) of each type name a comparison or membership test holds as a
    constant, or a literal list of two or more type names (a type list written out)."""
    names = set(SPEC_NAMES)
    found = []

    def constants(node: ast.AST) -> list[str]:
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return [node.value]
        if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            return [value for element in node.elts for value in constants(element)]
        if isinstance(node, ast.Dict):
            return [value for key in node.keys if key is not None
                    for value in constants(key)]
        return []

    for node in ast.walk(tree):
        if isinstance(node, ast.Compare):
            for operand in (node.left, *node.comparators):
                found += [(node.lineno, value) for value in constants(operand)
                          if value in names]
        if isinstance(node, (ast.Tuple, ast.List, ast.Set, ast.Dict)):
            listed = [value for value in constants(node) if value in names]
            if len(listed) >= 2:
                found += [(node.lineno, value) for value in listed]
    return sorted(set(found))


def test_scan_finds_what_it_looks_for():
    tree = ast.parse('if kind == "tapered-roller" or kind in ("thrust",):\n'
                     '    pass\nTYPES = ("deep-groove", "needle-roller")\n'
                     'message = f"a {kind} bearing, not tapered-roller"\n')
    assert sorted(_type_names_compared(tree)) == [
        (1, "tapered-roller"), (1, "thrust"), (3, "deep-groove"), (3, "needle-roller")]


def test_no_module_outside_the_table_compares_a_type_name():
    offenders = [f"{path.relative_to(ROOT)}:{line}: {name}"
                 for path in sorted(PACKAGE.rglob("*.py")) if path != TABLE_MODULE
                 for line, name in _type_names_compared(ast.parse(path.read_text("utf-8")))]
    assert offenders == []
