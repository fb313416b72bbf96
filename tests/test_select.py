"""bearingcalc select: what the vectorised selection finds against every fitting row of
the example catalogue solved one by one with ``solve``; the envelope, the exit status,
the drive's positions and the formats."""

from __future__ import annotations

import csv
import io
import json

import pytest

from bearingcalc.catalogue.catalogue import load_catalogue
from tests.conftest import ROOT

EXAMPLE = ROOT / "specs" / "catalogues" / "example.csv"
SHAFT = ("kind: rolling-bearing\nname: idler\ncatalogue: {catalogue}\nbore_diameter: 25 mm\n"
         "radial_load: 3 kN\naxial_load: 0.5 kN\nspeed: 1500 rpm\n"
         "lubrication: {{viscosity: 68 mm^2/s}}\ncontamination_factor: 0.5\n"
         "limits: {{min_rating_life: {life}, min_static_safety: 2}}\n")


def _spec(tmp_path, text, name="shaft.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def _one_by_one(cli, tmp_path, text, bore_mm):
    """Every row of the example with the bore, solved alone: designation -> passes,
    or None where the spec's rules refuse it."""
    outcome = {}
    for row in load_catalogue(EXAMPLE).rows:
        if abs(row.values["bore_diameter"] - bore_mm / 1e3) > 1e-9:
            continue
        spec = text.replace("bore_diameter: 25 mm\n", f"designation: {row.designation}\n"
                            f"maker: {row.maker}\n")
        run = cli("solve", _spec(tmp_path, spec, "alone.yaml"), "--format", "json")
        outcome[(row.designation, row.maker)] = (
            None if run.code == 2 else json.loads(run.out)["within_limits"], row)
    return outcome


@pytest.mark.parametrize("duty", ["", "duty_cycle:\n  - {time: 70 %}\n"
                                      "  - {time: 30 %, radial_load: 4 kN, speed: 900 rpm}\n"])
def test_the_selection_is_every_row_solved_alone(cli, tmp_path, duty):
    text = SHAFT.format(catalogue=EXAMPLE, life="20000 h") + duty
    run = cli("select", _spec(tmp_path, text), "--format", "json", "--top", "100")
    assert run.code == 0, run.err
    (record,) = [json.loads(line) for line in run.out.splitlines()]
    alone = _one_by_one(cli, tmp_path, text, 25)
    passing = sorted((row for ok, row in alone.values() if ok),
                     key=lambda r: (r.values["outside_diameter"], r.values["width"],
                                    r.values.get("mass", float("inf"))))
    assert [(c["designation"], c["maker"]) for c in record["qualifying"]] == [
        (r.designation, r.maker) for r in passing]
    assert record["considered"] == len(alone)
    assert record["qualifying_count"] == len(passing) >= 2
    listed_failing = {(c["designation"], c["maker"]) for c in record["failing"]}
    assert listed_failing == {key for key, (ok, _) in alone.items() if not ok}


def test_the_exit_status_says_whether_one_qualifies(cli, tmp_path):
    none = SHAFT.format(catalogue=EXAMPLE, life="1e9 h")
    run = cli("select", _spec(tmp_path, none))
    assert run.code == 1 and "NONE of the catalogue's bearings" in run.out
    assert cli("select", _spec(tmp_path, SHAFT.format(catalogue=EXAMPLE, life="2000 h"))
               ).code == 0


@pytest.mark.parametrize(("options", "words"), [
    (["--max-outside-diameter", "40 mm"],
     "none with an outside diameter of at most 40 mm among those with the bore 25 mm"),
    (["--type", "thrust-ball", "--max-width", "5 mm"],
     "fits the bearing: none with a width of at most 5 mm among those of the types "
     "thrust-ball, with the bore 25 mm"),
    (["--type", "thrust-ball", "--series", "513"],
     "none of the series 513 among those of the types thrust-ball"),
    (["--series", "99"], "none of the series 99"),
])
def test_an_envelope_no_row_fits_names_the_limit(cli, tmp_path, options, words):
    run = cli("select", _spec(tmp_path, SHAFT.format(catalogue=EXAMPLE, life="2000 h")),
              *options)
    assert run.code == 2 and run.err.count("\n") == 1 and run.out == "", run.err
    assert words in run.err, run.err


def test_the_envelope_and_the_types_narrow_the_choice(cli, tmp_path):
    path = _spec(tmp_path, SHAFT.format(catalogue=EXAMPLE, life="2000 h"))
    run = cli("select", path, "--format", "json", "--top", "100",
              "--max-outside-diameter", "55 mm", "--type", "tapered-roller",
              "--type", "deep-groove")
    (record,) = [json.loads(line) for line in run.out.splitlines()]
    listed = record["qualifying"] + record["failing"]
    assert listed and all(c["outside_diameter"] <= 0.055 for c in listed)
    assert {c["type"] for c in listed} <= {"tapered-roller", "deep-groove"}


@pytest.mark.parametrize(("options", "words"), [
    (["--type", "tapered"], "Invalid value for '--type' / '-t': 'tapered': not a bearing "
     "type (did you mean"),
    (["--max-width", "17 kg"], "Invalid value for '--max-width': 'kg' is not a unit of length"),
])
def test_bad_options_are_one_line(cli, tmp_path, options, words):
    run = cli("select", _spec(tmp_path, SHAFT.format(catalogue=EXAMPLE, life="2000 h")),
              *options)
    assert run.code == 2 and run.err.count("\n") == 1 and words in run.err, run.err


def test_a_spec_that_is_not_of_a_rolling_bearing_is_refused(cli):
    run = cli("select", ROOT / "specs" / "bevel-gears.yaml", "--catalogue", EXAMPLE)
    assert run.code == 2 and "select chooses rolling bearings" in run.err, run.err


def test_a_drive_selects_its_open_position(cli, tmp_path):
    """The example drive with its locating pinion bearing left open (only its shaft):
    select lists that position, and each qualifying row, written into the drive, passes
    solve."""
    drive = (ROOT / "specs" / "bevel-drive.yaml").read_text()
    old = drive[drive.index("  - {position: 90 mm"):drive.index("  - {position: 150 mm")]
    opened = drive.replace(old, "  - {position: 90 mm, locating: true, bore_diameter: 25 mm}\n"
                           ) + f"catalogue: {EXAMPLE}\n"
    run = cli("select", _spec(tmp_path, opened, "drive.yaml"), "--format", "json")
    assert run.code in (0, 1), run.err
    (record,) = [json.loads(line) for line in run.out.splitlines()]
    assert record["position"] == "pinion_bearings.1" and record["considered"] >= 5
    for candidate in record["qualifying"]:
        chosen = opened.replace("{position: 90 mm, locating: true, bore_diameter: 25 mm}",
                                f"{{position: 90 mm, locating: true, designation: "
                                f"'{candidate['designation']}', maker: {candidate['maker']}}}")
        solved = cli("solve", _spec(tmp_path, chosen, "chosen.yaml"), "--format", "json")
        assert json.loads(solved.out)["within_limits"], candidate["designation"]


def test_the_csv_is_flat_and_never_a_spreadsheet_formula(cli, tmp_path):
    text = EXAMPLE.read_text().replace("6205,NSK,", "6205,=HYPERLINK(1),")
    (tmp_path / "cat.csv").write_text(text)
    run = cli("select", _spec(tmp_path, SHAFT.format(catalogue="cat.csv", life="2000 h")),
              "--format", "csv", "--top", "100")
    rows = list(csv.DictReader(io.StringIO(run.out)))
    assert rows and set(rows[0]) >= {"designation", "maker", "outside_diameter [m]",
                                     "governing_margin", "catalogue_source"}
    assert "'=HYPERLINK(1)" in {row["maker"] for row in rows}


def _drive_with_designations() -> str:
    """The example drive with its four bearings taken from the example catalogue: 6305
    (SKF) on the pinion shaft, 6206 (SKF) on the gear's."""
    drive = (ROOT / "specs" / "bevel-drive.yaml").read_text()
    lines = drive.splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if line.startswith("pinion_bearings:"))
    end = next(i for i, line in enumerate(lines) if line.startswith("reliability:"))
    bearings = (
        "pinion_bearings:\n"
        "  - {position: 90 mm, locating: true, designation: 6305, maker: SKF}\n"
        "  - {position: 150 mm, designation: 6305, maker: SKF}\n"
        "gear_bearings:\n"
        "  - {position: 20 mm, designation: 6206, maker: SKF}\n"
        "  - {position: 120 mm, locating: true, designation: 6206, maker: SKF}\n")
    return "".join(lines[:start]) + bearings + "".join(lines[end:]) + f"catalogue: {EXAMPLE}\n"


def test_a_drive_takes_its_bearings_by_designation(cli, tmp_path):
    """The four rows fill the drive as the example's typed ratings do (6305: 23.4 kN,
    11.6 kN; 6206: 20.3 kN, 11.2 kN), and each bearing names its row."""
    run = cli("solve", _spec(tmp_path, _drive_with_designations(), "drive.yaml"),
              "--format", "json")
    assert run.code in (0, 1), run.err
    record = json.loads(run.out)
    assert record["pinion_bearing_1_catalogue_source"].startswith("6305, SKF: ")
    assert record["gear_bearing_2_catalogue_source"].startswith("6206, SKF: ")
    typed = json.loads(cli("solve", ROOT / "specs" / "bevel-drive.yaml", "--format",
                           "json").out)
    # the example's f0 of the 6305 is 12 and the catalogue's too: the loads agree
    for key in ("pinion_bearing_1_radial_load", "pinion_bearing_1_axial_load",
                "gear_bearing_1_radial_load"):
        assert record["results"][key] == typed["results"][key], key


def test_a_drive_with_every_bearing_given_selects_each_position_in_turn(cli, tmp_path):
    text = _drive_with_designations()
    run = cli("select", _spec(tmp_path, text, "drive.yaml"), "--format", "json")
    records = [json.loads(line) for line in run.out.splitlines()]
    assert [r["position"] for r in records] == ["pinion_bearings.1", "pinion_bearings.2",
                                                "gear_bearings.1", "gear_bearings.2"]
    assert run.code == (0 if all(r["qualifying"] for r in records) else 1)
    for record in records:
        if not record["qualifying"]:
            continue
        best = record["qualifying"][0]
        place, index = record["position"].split(".")
        nth = int(index)
        lines = text.splitlines(keepends=True)
        heading = next(i for i, line in enumerate(lines) if line.startswith(f"{place}:"))
        row = heading + nth
        lines[row] = lines[row].split("designation:")[0] + (
            f"designation: '{best['designation']}', maker: {best['maker']}}}\n")
        chosen = "".join(lines)
        solved = cli("solve", _spec(tmp_path, chosen, "chosen.yaml"), "--format", "json")
        assert json.loads(solved.out)["within_limits"], (record["position"], best)


CYLINDRICAL = ("designation,maker,type,bore_diameter [mm],outside_diameter [mm],width [mm],"
               "dynamic_load_rating [kN],static_load_rating [kN],source\n"
               "NU205 ECP,X,cylindrical-roller,25,52,15,28.6,27,made up\n"
               "NU2205 ECP,X,cylindrical-roller,25,52,18,34.1,34,made up\n"
               "NU305 ECP,X,cylindrical-roller,25,62,17,46.5,36.5,made up\n"
               "NJ205 ECP,X,cylindrical-roller,25,52,15,28.6,27,made up\n"
               "NUP2205 ECP,X,cylindrical-roller,25,52,18,34.1,34,made up\n")


def test_an_nj_bearing_is_not_refused_for_the_nu_bearings_before_it(cli, tmp_path):
    """The NU rule judges a row's form, so the NU rows are refused and the NJ and NUP
    rows (ribs on both rings) are solved, and counted, as any others."""
    (tmp_path / "cyl.csv").write_text(CYLINDRICAL)
    text = SHAFT.format(catalogue="cyl.csv", life="2000 h")
    run = cli("select", _spec(tmp_path, text), "--format", "json", "--top", "10")
    assert run.code == 0, run.err
    (record,) = [json.loads(line) for line in run.out.splitlines()]
    assert [c["designation"] for c in record["qualifying"]] == ["NJ205 ECP", "NUP2205 ECP"]
    assert record["qualifying_count"] == 2
    assert all("an NU bearing" in c["problem"] for c in record["failing"])
    series = cli("select", _spec(tmp_path, text), "--series", "NJ2", "--format", "json")
    (record,) = [json.loads(line) for line in series.out.splitlines()]
    assert [c["designation"] for c in record["qualifying"]] == ["NJ205 ECP"]


@pytest.mark.parametrize(("change", "field"), [
    (("contamination_factor: 0.5", "contamination_factor: 2"), "contamination_factor"),
    (("limits: {", "limits: {min_static_safty: 3, "), "limits.min_static_safty"),
])
def test_a_bad_spec_is_refused_not_reported_as_every_bearing_failing(cli, tmp_path, change,
                                                                      field):
    text = SHAFT.format(catalogue=EXAMPLE, life="2000 h").replace(*change)
    run = cli("select", _spec(tmp_path, text))
    assert run.code == 2 and run.err.count("\n") == 1 and run.out == "", run.err
    assert f": {field}: " in run.err, run.err


def test_a_drive_whose_gear_misses_its_limits_still_chooses_bearings(cli, tmp_path):
    drive = (ROOT / "specs" / "bevel-drive.yaml").read_text().replace(
        "limits:\n", "limits:\n  min_bending_safety: 1.2\n")
    old = drive[drive.index("  - {position: 90 mm"):drive.index("  - {position: 150 mm")]
    opened = drive.replace(old, "  - {position: 90 mm, locating: true, bore_diameter: 25 mm}\n"
                           ) + f"catalogue: {EXAMPLE}\n"
    assert "min_bending_safety: 1.2" in opened
    run = cli("select", _spec(tmp_path, opened, "drive.yaml"), "--format", "json")
    (record,) = [json.loads(line) for line in run.out.splitlines()]
    assert record["qualifying"], record
    assert any(note.startswith("the gear pair misses its own limits") and "bending safety"
               in note for note in record["notes"]), record["notes"]
