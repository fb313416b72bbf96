"""Catalogues: the example catalogue against a second reading of the pages it cites; a
spec filled from a row against the same spec typed by hand; the reader's refusals, one
line each with the file and the line."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import pytest

from bearingcalc.catalogue.catalogue import load_catalogue
from bearingcalc.catalogue.designation import bore_from_code, parse_designation
from tests.conftest import ROOT

EXAMPLE = ROOT / "specs" / "catalogues" / "example.csv"
HEADER = ("designation,maker,type,bore_diameter [mm],outside_diameter [mm],width [mm],"
          "dynamic_load_rating [kN],static_load_rating [kN],source\n")
GOOD_ROW = "6205,SKF,deep-groove,25,52,15,14.8,7.8,\"SKF, catalogue, p. 306\"\n"
BEARING = ("kind: rolling-bearing\n{head}radial_load: 3 kN\naxial_load: 1 kN\nspeed: 1500 rpm\n"
           "lubrication: {{viscosity: 68 mm^2/s}}\ncontamination_factor: 0.5\n"
           "limits: {{min_rating_life: 5000 h, min_static_safety: 2}}\n")


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8") as handle:
        return list(csv.DictReader(line for line in handle if not line.startswith("#")))


def test_a_sample_of_the_example_agrees_with_a_second_reading_of_its_pages():
    """tests/data/catalogue_sample_check.csv was read from the pages the example's rows
    cite (SKF's general catalogue, NSK's CAT. No. E1102e), apart from the example."""
    ours = {(row["designation"], row["maker"]): row for row in _rows(EXAMPLE)}
    second = _rows(Path(__file__).parent / "data" / "catalogue_sample_check.csv")
    assert len(second) >= 10
    columns = ("bore_diameter [mm]", "outside_diameter [mm]", "width [mm]",
               "dynamic_load_rating [kN]", "static_load_rating [kN]")
    for row in second:
        mine = ours[(row["designation"], row["maker"])]
        assert [float(mine[c]) for c in columns] == [float(row[c]) for c in columns], row
        assert row["page"].removeprefix("B") in mine["source"], (row, mine["source"])


def test_the_example_reads_whole_and_every_row_names_its_source():
    catalogue = load_catalogue(EXAMPLE)
    assert len(catalogue.rows) >= 36
    assert all(row.source.strip() for row in catalogue.rows)
    assert catalogue.warnings == []  # every row is a designation of the ISO table
    assert {row.maker for row in catalogue.rows if row.designation == "6205"} == {"SKF", "NSK"}


@pytest.mark.parametrize(("text", "basic", "suffixes", "bore"), [
    ("6205-2RS C3", "6205", ("2RS", "C3"), 25.0),
    ("6205ZZ", "6205", ("ZZ",), 25.0),
    ("NU 206 ECP", "NU206", ("ECP",), 30.0),
    ("NJ2208", "NJ2208", (), 40.0),
    ("HR30205 J", "30205", ("J",), 25.0),
    ("7208 BECBP", "7208", ("BECBP",), 40.0),
    ("608", "608", (), 8.0),
    ("51100", "51100", (), 10.0),
])
def test_designations_read_into_their_parts(text, basic, suffixes, bore):
    parsed = parse_designation(text)
    assert (parsed.basic, parsed.suffixes, parsed.bore_diameter) == (basic, suffixes, bore)


def test_the_bore_code_rule():
    """ISO 15: 00 → 10, 01 → 12, 02 → 15, 03 → 17, then the code × 5 mm up to 96."""
    assert [bore_from_code(c) for c in (0, 1, 2, 3, 4, 20, 96, 97)] == [
        10, 12, 15, 17, 20, 100, 480, None]
    assert parse_designation("NJ205").iso_key == "NU205"
    assert parse_designation("62/22") is None


def _solve(cli, spec_file, text, name="spec.yaml"):
    path = spec_file(text, name)
    run = cli("solve", path, "--format", "json")
    assert run.code in (0, 1), run.err
    return json.loads(run.out), run


def test_a_row_fills_the_spec_as_if_typed(cli, spec_file, tmp_path):
    """30206 J2/Q (SKF): C 40.2 kN, C0 44 kN, Cu 4.8 kN, e 0.37, Y 1.6, Y0 0.9, d 30, D 62
    (example.csv) give the same numbers as the spec with those values typed, and a contact
    angle of atan(e/1.5) (ISO 281's e = 1.5·tanα)."""
    (tmp_path / "cat.csv").write_bytes(EXAMPLE.read_bytes())
    filled, _ = _solve(cli, lambda text, name: _write(tmp_path, text, name), BEARING.format(
        head="catalogue: cat.csv\ndesignation: 30206 J2/Q\n"), "filled.yaml")
    alpha = math.atan(0.37 / 1.5)
    typed, _ = _solve(cli, spec_file, BEARING.format(head=(
        "type: tapered-roller\ndynamic_load_rating: 40.2 kN\nstatic_load_rating: 44 kN\n"
        "fatigue_load_limit: 4.8 kN\nbore_diameter: 30 mm\noutside_diameter: 62 mm\n"
        f"width: 17.25 mm\ncontact_angle: {alpha!r} rad\n"
        "load_factors: {e: 0.37, y: 1.6, y0: 0.9}\n")))
    assert filled["results"] == typed["results"]
    assert filled["catalogue_source"].startswith("30206 J2/Q, SKF: SKF, General Catalogue")


def _write(folder: Path, text: str, name: str) -> Path:
    path = folder / name
    path.write_text(text)
    return path


def test_a_spec_value_wins_and_is_reported(cli, tmp_path):
    (tmp_path / "cat.csv").write_text(HEADER + GOOD_ROW)
    path = _write(tmp_path, BEARING.format(head="catalogue: cat.csv\ndesignation: 6205\n"
                                           "static_factor: 14\n"
                                           "dynamic_load_rating: 15 kN\n"), "a.yaml")
    run = cli("solve", path, "--format", "json")
    record = json.loads(run.out)
    assert record["results"]["dynamic_load_rating"] == 15000.0
    assert any("dynamic_load_rating: the spec's 15 kN overrides the catalogue's 14.8 kN"
               in warning for warning in record["warnings"]), record["warnings"]


def test_the_word_catalogue_takes_the_catalogue_value_with_a_tolerance(cli, tmp_path):
    (tmp_path / "cat.csv").write_text(HEADER + GOOD_ROW)
    path = _write(tmp_path, BEARING.format(
        head="catalogue: cat.csv\ndesignation: 6205\nstatic_factor: 14\n"
             "dynamic_load_rating: catalogue ± 5 %\n"), "a.yaml")
    run = cli("tolerance", path, "--method", "worst-case", "--format", "json")
    assert run.code in (0, 1), run.err
    report = json.loads(run.out)
    inputs = report["inputs"]
    assert inputs["dynamic_load_rating"]["nominal"] == pytest.approx(14800.0)
    assert inputs["dynamic_load_rating"]["high"] == pytest.approx(14800.0 * 1.05)


def test_the_catalogue_option_and_the_environment_give_a_default(cli, tmp_path, monkeypatch):
    (tmp_path / "cat.csv").write_text(HEADER + GOOD_ROW)
    path = _write(tmp_path, BEARING.format(head="designation: 6205\nstatic_factor: 14\n"),
                  "a.yaml")
    refused = cli("solve", path)
    assert refused.code == 2 and "BEARINGCALC_CATALOGUE" in refused.err
    assert cli("solve", path, "--catalogue", tmp_path / "cat.csv").code in (0, 1)
    monkeypatch.setenv("BEARINGCALC_CATALOGUE", str(tmp_path / "cat.csv"))
    assert cli("check", path).code in (0, 1)


#: Catalogue texts each refused in one line naming the catalogue's line and column.
BAD_CATALOGUES = {
    "missing-column": (HEADER.replace(",source", "") + GOOD_ROW.rsplit(",", 2)[0] + "\n",
                       1, "source"),
    "bad-unit": (HEADER.replace("[kN],source", "[furlong],source") + GOOD_ROW, 1,
                 "static_load_rating"),
    "unit-in-cell": (HEADER + GOOD_ROW.replace(",14.8,", ",14.8 kN,"), 2,
                     "dynamic_load_rating"),
    "formula-number": (HEADER + GOOD_ROW.replace(",14.8,", ",=1+2,"), 2,
                       "dynamic_load_rating"),
    "no-source": (HEADER + GOOD_ROW.replace('"SKF, catalogue, p. 306"', ""), 2, "source"),
    "duplicate": (HEADER + GOOD_ROW + GOOD_ROW, 3, "designation"),
    "not-iso": (HEADER + GOOD_ROW.replace(",52,", ",53,"), 2, "outside_diameter"),
    "wrong-type": (HEADER + GOOD_ROW.replace("deep-groove", "tapered-roller"), 2, "type"),
    "unknown-type": (HEADER + GOOD_ROW.replace("deep-groove", "deepgroove"), 2, "type"),
    "unknown-column": (HEADER.replace("maker", "makr") + GOOD_ROW, 1, "makr"),
    "short-row": (HEADER + "6205,SKF,deep-groove\n", 2, None),
    "negative": (HEADER + GOOD_ROW.replace(",7.8,", ",-7.8,"), 2, "static_load_rating"),
}


@pytest.mark.parametrize("case", sorted(BAD_CATALOGUES))
def test_a_bad_catalogue_is_one_line_with_its_line(cli, tmp_path, case):
    text, line, column = BAD_CATALOGUES[case]
    (tmp_path / "cat.csv").write_text(text)
    path = _write(tmp_path, BEARING.format(head="catalogue: cat.csv\ndesignation: 6205\n"),
                  "a.yaml")
    run = cli("solve", path)
    assert run.code == 2 and run.err.count("\n") == 1 and run.out == "", run.err
    assert run.err.startswith(f"{path}:2: catalogue: "), run.err
    assert f"cat.csv:{line}: " in run.err, run.err
    if column is not None:
        assert f":{line}: {column}: " in run.err, run.err


@pytest.mark.parametrize(("raw", "where"), [
    (b"\xef\xbb\xbf" + (HEADER + GOOD_ROW).encode(), None),
    ((HEADER + GOOD_ROW).replace("\n", "\r\n").encode(), None),
    ((HEADER + GOOD_ROW).encode() + b"6305,SKF,deep-groove,25,62,17,23.4,11.6,caf\xe9\n", 3),
])
def test_bom_and_crlf_are_read_and_other_encodings_refused(cli, tmp_path, raw, where):
    (tmp_path / "cat.csv").write_bytes(raw)
    path = _write(tmp_path, BEARING.format(head="catalogue: cat.csv\ndesignation: 6205\n"
                                           "static_factor: 14\n"), "a.yaml")
    run = cli("solve", path)
    if where is None:
        assert run.code in (0, 1), run.err
    else:
        assert run.code == 2 and f"cat.csv:{where}: not UTF-8" in run.err, run.err


def test_a_formula_looking_text_cell_is_text_and_never_run(cli, tmp_path):
    (tmp_path / "cat.csv").write_text(HEADER + GOOD_ROW.replace(
        '"SKF, catalogue, p. 306"', "\"=cmd|' /c calc'!A1\""))
    path = _write(tmp_path, BEARING.format(head="catalogue: cat.csv\ndesignation: 6205\n"
                                           "static_factor: 14\n"), "a.yaml")
    run = cli("solve", path, "--format", "json")
    assert run.code in (0, 1), run.err
    assert json.loads(run.out)["catalogue_source"] == "6205, SKF: =cmd|' /c calc'!A1"


def test_a_designation_not_in_the_catalogue_suggests_the_nearest(cli, tmp_path):
    (tmp_path / "cat.csv").write_text(HEADER + GOOD_ROW)
    path = _write(tmp_path, BEARING.format(head="catalogue: cat.csv\ndesignation: 6250\n"),
                  "a.yaml")
    run = cli("solve", path)
    assert run.code == 2 and run.err.count("\n") == 1, run.err
    assert ":3: designation: '6250' is not in the catalogue; the nearest: 6205" in run.err


def test_a_designation_from_two_makers_needs_the_maker(cli, tmp_path):
    path = _write(tmp_path, BEARING.format(head=f"catalogue: {EXAMPLE}\ndesignation: 6205\n"),
                  "a.yaml")
    run = cli("solve", path)
    assert run.code == 2 and "give the bearing's maker too, like maker: NSK" in run.err
    path.write_text(BEARING.format(head=f"catalogue: {EXAMPLE}\ndesignation: 6205\n"
                                   "maker: NSK\n"))
    record, _ = _solve(cli, lambda text, name: path, "", "a.yaml")
    assert record["results"]["dynamic_load_rating"] == 14000.0


def test_a_bare_number_designation_is_the_same_as_text(cli, tmp_path):
    (tmp_path / "cat.csv").write_text(HEADER + GOOD_ROW)
    numbers = [json.loads(cli("solve", _write(tmp_path, BEARING.format(
        head=f"catalogue: cat.csv\ndesignation: {written}\nstatic_factor: 14\n"), "a.yaml"),
        "--format", "json").out)["results"] for written in ("6205", '"6205"', "6205-2RS")]
    assert numbers[0] == numbers[1] == numbers[2]


def test_a_catalogue_without_a_designation_is_refused(cli, tmp_path):
    path = _write(tmp_path, (ROOT / "specs" / "rolling-bearing.yaml").read_text()
                  + "catalogue: cat.csv\n", "a.yaml")
    run = cli("solve", path)
    assert run.code == 2 and ": catalogue: no bearing names a designation" in run.err


def test_an_nu_bearing_refuses_an_axial_load(cli, tmp_path):
    path = _write(tmp_path, BEARING.format(head=f"catalogue: {EXAMPLE}\n"
                                           "designation: NU205 ECP\n"), "a.yaml")
    run = cli("solve", path)
    assert run.code == 2 and "axial_load: NU205 ECP is an NU bearing" in run.err, run.err


@pytest.mark.parametrize(("limit", "value", "words"), [
    ("MAX_FILE_BYTES", 100, "file too large"),
    ("MAX_ROWS", 1, "more than 1 rows: split the catalogue"),
    ("MAX_CELL_CHARS", 10, "a cell of over 10 characters"),
])
def test_the_reader_holds_its_limits(cli, tmp_path, monkeypatch, limit, value, words):
    from bearingcalc.catalogue import reader

    monkeypatch.setattr(reader, limit, value)
    (tmp_path / "cat.csv").write_text(HEADER + GOOD_ROW + GOOD_ROW.replace("SKF", "NSK"))
    path = _write(tmp_path, BEARING.format(head="catalogue: cat.csv\ndesignation: 6205\n"
                                           "maker: SKF\nstatic_factor: 14\n"), "a.yaml")
    run = cli("solve", path)
    assert run.code == 2 and run.err.count("\n") == 1 and words in run.err, run.err


FACTOR_HEADER = ("designation,maker,type,bore_diameter [mm],outside_diameter [mm],width [mm],"
                 "dynamic_load_rating [kN],static_load_rating [kN],e,y1,y2,y0,source\n")


def _solve_row(cli, tmp_path, row: str) -> dict:
    """BEARING (Fr 3 kN, Fa 1 kN) with its bearing the one made-up catalogue row."""
    (tmp_path / "cat.csv").write_text(FACTOR_HEADER + row + "\n")
    path = _write(tmp_path, BEARING.format(
        head=f"catalogue: cat.csv\ndesignation: {row.partition(',')[0]}\n"), "a.yaml")
    run = cli("solve", path, "--format", "json")
    assert run.code in (0, 1), run.err
    return json.loads(run.out)


def test_a_self_aligning_ball_row_gives_its_factors(cli, tmp_path):
    """1205 ETN9 (a made-up row): e 0.27, Y1 2.3, Y2 3.6, Y0 2.5 fill the double-row
    factors a self-aligning ball bearing under axial load needs: Fa/Fr = 1/3 > e gives
    P = 0.65·Fr + Y2·Fa."""
    record = _solve_row(cli, tmp_path, "1205 ETN9,X,self-aligning-ball,25,52,15,14.3,4,"
                                       "0.27,2.3,3.6,2.5,made up")
    assert (record["results"]["axial_factor"], record["results"]["radial_factor"]) == (
        3.6, 0.65)
    assert any("not in the table of ISO boundary dimensions" in w for w in record["warnings"])


def test_a_row_with_y1_is_a_double_row_bearing(cli, tmp_path):
    """A tapered row that gives y1 (made-up double-row bearing): rated as two rows, with
    P = Fr + Y1·Fa at Fa/Fr = 1/3 below e (a single row would take P = Fr)."""
    record = _solve_row(cli, tmp_path, "X352205,X,tapered-roller,25,52,36,55,70,"
                                       "0.37,1.8,2.7,1.8,made up")
    assert (record["results"]["axial_factor"], record["results"]["radial_factor"]) == (
        1.8, 1.0)


def test_another_variant_of_the_designation_is_taken_with_a_note(cli, tmp_path):
    path = _write(tmp_path, BEARING.format(head=f"catalogue: {EXAMPLE}\n"
                                           "designation: 7205 AC\nmaker: SKF\n"), "a.yaml")
    warnings = json.loads(cli("solve", path, "--format", "json").out)["warnings"]
    assert any("7205 AC is taken as the catalogue's 7205 BEP" in w for w in warnings), warnings


def test_a_catalogue_in_inches_agrees_with_iso(cli, tmp_path):
    (tmp_path / "cat.csv").write_text(
        "designation,maker,type,bore_diameter [in],outside_diameter [in],width [in],"
        "dynamic_load_rating [kN],static_load_rating [kN],static_factor,source\n"
        "6205,X,deep-groove,0.9843,2.0472,0.5906,14.8,7.8,14,made up\n")
    path = _write(tmp_path, BEARING.format(head="catalogue: cat.csv\ndesignation: 6205\n"),
                  "a.yaml")
    assert cli("solve", path).code in (0, 1)


@pytest.mark.parametrize(("head", "words"), [
    ("designation: 51105\ntype: thrust\naxial_load: 2 kN\n", None),
    ("designation: 6205\nmaker: SKF\ndynamic_load_rating: catalogues\n", "dynamic_load_rating"),
    ("designation: 6205\nmaker: NSK\nfatigue_load_limit: catalogue ± 5 %\n",
     "gives no fatigue_load_limit"),
])
def test_alias_word_and_missing_value(cli, tmp_path, head, words):
    text = BEARING.format(head=f"catalogue: {EXAMPLE}\n" + head)
    if "51105" in head:
        text = text.replace("radial_load: 3 kN\naxial_load: 1 kN\n", "")
    path = _write(tmp_path, text, "a.yaml")
    run = cli("solve", path)
    if words is None:
        assert run.code in (0, 1), run.err
    else:
        assert run.code == 2 and words in run.err, run.err
