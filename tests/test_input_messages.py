"""Input read as engineers write it, and refused in words that say what was written:
sweep bounds with the units their field takes, YAML keys that are no names, text in
UTF-16, catalogues written the European way, the catalogue keyword, and designations
in full-width digits."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from bearingcalc.errors import SpecError
from bearingcalc.evaluation import load_one_spec
from bearingcalc.models.base import field_parser
from bearingcalc.models.field_path import FieldPathError, resolve_field
from bearingcalc.models.quantities import Measured
from bearingcalc.models.yaml_loader import load_documents
from bearingcalc.sweeps import parse_axis
from tests.conftest import ROOT

EXAMPLES = sorted((ROOT / "specs").glob("*.yaml"))


# --- sweep bounds take the units their field takes ----------------------------------


def _leaves(data, prefix=""):
    """(dotted field, value as written) of every scalar of a spec's data (list items
    from 1)."""
    items = data.items() if isinstance(data, dict) else enumerate(data, 1)
    for key, value in items:
        name = f"{prefix}{key}"
        if isinstance(value, (dict, list)):
            yield from _leaves(value, f"{name}.")
        else:
            yield name, value


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda path: path.stem)
def test_every_swept_field_reads_a_bound_as_the_spec_reads_its_value(path):
    """Each number the example writes, given back as a sweep's bound, is the number the
    spec took: quantities in their units, percentages, counts, choices."""
    _, spec, document = load_one_spec(path)
    checked = 0
    for name, written in _leaves(document.data):
        try:
            found = resolve_field(spec, name)
        except FieldPathError:
            continue
        parser = field_parser(found.info) if found.info is not None else None
        if parser is None or found.value is None or isinstance(found.value, Measured):
            continue
        if isinstance(written, bool):
            continue
        _, read, _ = parser
        assert read(str(written)) == pytest.approx(float(found.value), rel=1e-12), name
        checked += 1
    assert checked


@pytest.mark.parametrize(("spec", "vary", "values"), [
    ("rolling-bearing", "reliability=90%:99%:3", [0.9, 0.945, 0.99]),
    ("rolling-bearing", "reliability=90 %:0.99:2", [0.9, 0.99]),
    ("rolling-bearing", "reliability=0.9:99 %:2", [0.9, 0.99]),
    ("rolling-bearing", "radial_load=1kN:2000 N:3", [1000.0, 1500.0, 2000.0]),
    ("rolling-bearing", "radial_load=1 kN:2 kN:2", [1000.0, 2000.0]),
    ("rolling-bearing", "speed=1500 rpm:1800 min^-1:2", [50 * math.pi, 60 * math.pi]),
    ("rolling-bearing", "contamination_factor=0.2:0.8:3", [0.2, 0.5, 0.8]),
    ("ball-bearing-geometry", "ball_count=8:12:5", [8, 9, 10, 11, 12]),
    ("ball-bearing-geometry", "ball_count=8.0:10:3", [8, 9, 10]),
    ("bevel-gears-spiral", "rating.grade=1:2:2", [1, 2]),
    ("bevel-drive", "rating.hardness=250HB:300 HB:2", [250.0, 300.0]),
])
def test_a_bound_takes_the_units_and_forms_its_field_takes(spec, vary, values):
    _, parsed, _ = load_one_spec(ROOT / "specs" / f"{spec}.yaml")
    axis = parse_axis(vary, parsed)
    assert axis.values.tolist() == pytest.approx(values, rel=1e-12)


@pytest.mark.parametrize(("spec", "vary", "said"), [
    ("rolling-bearing", "reliability=90:99:3", "for percent write '90 %'"),
    ("rolling-bearing", "reliability=abc:99%:3", "got 'abc'"),
    ("rolling-bearing", "reliability=.nan:99%:3", "not a finite number"),
    ("rolling-bearing", "reliability=50%:99%:3", "from 90 % to"),
    ("rolling-bearing", "reliability=0.5:99%:3", "from 90 % to"),
    ("rolling-bearing", "radial_load=1:2 kN:3", "has no unit"),
    ("rolling-bearing", "radial_load=1 deg:2 kN:3", "radial_load"),
    ("ball-bearing-geometry", "ball_count=8.5:12:3", "'8.5' is not a whole number"),
    ("ball-bearing-geometry", "ball_count=eight:12:3", "'eight' is not a whole number"),
    ("bevel-gears-spiral", "rating.grade=true:2:2", "not a whole number"),
])
def test_a_bound_the_field_does_not_take_says_why(spec, vary, said, cli):
    run = cli("sweep", ROOT / "specs" / f"{spec}.yaml", "--vary", vary)
    field = vary.split("=")[0]
    assert run.code == 2 and said in run.err and "--vary" in run.err and field in run.err


def test_the_command_line_sweeps_a_reliability_in_percent(cli):
    result = cli("sweep", ROOT / "specs" / "rolling-bearing.yaml", "--vary",
                 "reliability=90%:99%:3", "--format", "csv")
    assert result.code == 0, result.err
    assert result.out.count("\n") == 4


# --- YAML keys that are no names, and text in UTF-16 or UTF-32 ----------------------


@pytest.mark.parametrize(("text", "line", "shown"), [
    ("? [speed, rpm]\n: 1500\n", 1, "the key '[speed, rpm]' is a list"),
    ("? - speed\n  - rpm\n: 1500\n", 1, "the key '[speed, rpm]' is a list"),
    ("kind: x\n? {speed: 1500,\n   unit: rpm}\n: 1\n", 2,
     "the key '{speed: 1500, unit: rpm}' is a mapping"),
    ("kind: x\nlimits: {[a, b]: 3}\n", 2, "the key '[a, b]' is a list"),
    ("x: &a [1]\n*a : 2\n", 2, "the key '*a' is a list"),
    ("~: 5\n", 1, "the key '~' is null"),
    ("null: 5\n", 1, "the key 'null' is null"),
    ("{? : 1}\n", 1, "the key is empty"),
    ("kind: x\n1500: rpm\n", 2, "the key '1500' is a number"),
    ("1.5e3: rpm\n", 1, "the key '1.5e3' is a number"),
    ("0x10: rpm\n", 1, "the key '0x10' is a number"),
    ("True: 1\n", 1, "the key 'True' is true or false"),
    ("kind: x\nb:\n  ? [é, ü]\n  : 1\n", 3, "the key '[é, ü]' is a list"),
])
def test_a_key_that_is_no_name_is_shown_as_written(text, line, shown):
    with pytest.raises(SpecError) as raised:
        load_documents("spec.yaml", text)
    error = raised.value
    assert error.line == line and error.message.startswith("a key must be a plain name")
    assert shown in error.message


def test_a_quoted_key_that_reads_as_a_number_is_a_name():
    (document,) = load_documents("spec.yaml", "'1500': rpm\n'true': 1\n")
    assert document.data == {"1500": "rpm", "true": 1}


SPEC_TEXT = (ROOT / "specs" / "thrust-bearing.yaml").read_text(encoding="utf-8") + "# Lösung\n"


@pytest.mark.parametrize(("codec", "said"), [
    ("utf-16", "UTF-16 (little-endian, with a byte-order mark)"),
    ("utf-16-le", "UTF-16 (little-endian)"),
    ("utf-16-be", "UTF-16 (big-endian)"),
    ("utf-32", "UTF-32 (little-endian, with a byte-order mark)"),
    ("utf-32-le", "UTF-32 (little-endian)"),
    ("utf-32-be", "UTF-32 (big-endian)"),
])
def test_a_spec_in_utf16_or_utf32_is_named_so(codec, said, tmp_path, cli):
    path = tmp_path / "spec.yaml"
    path.write_bytes(SPEC_TEXT.encode(codec))
    run = cli("solve", path)
    assert run.code == 2
    assert run.err.strip() == f"{path}: the file is {said} text; save it as UTF-8"


CATALOGUE_SPEC = ROOT / "specs" / "rolling-bearing-catalogue.yaml"
EXAMPLE_CATALOGUE = ROOT / "specs" / "catalogues" / "example.csv"


def catalogue_spec(folder: Path, catalogue: str | bytes, name: str = "bearings.csv",
                   designation: str = "30206 J2/Q") -> Path:
    """A copy of the example catalogue spec that names ``catalogue`` (written to
    ``folder/name``) and takes ``designation`` from it."""
    path = folder / name
    path.write_bytes(catalogue if isinstance(catalogue, bytes) else catalogue.encode())
    spec = folder / "spec.yaml"
    spec.write_text(CATALOGUE_SPEC.read_text(encoding="utf-8").replace(
        "catalogue: catalogues/example.csv", f"catalogue: {name}").replace(
        "designation: 30206 J2/Q", f"designation: {designation}"), encoding="utf-8")
    return spec


def test_a_utf16_catalogue_is_named_so(tmp_path, cli):
    text = EXAMPLE_CATALOGUE.read_text(encoding="utf-8")
    run = cli("solve", catalogue_spec(tmp_path, text.encode("utf-16")))
    assert run.code == 2 and "bearings.csv: the file is UTF-16 (little-endian, with a " \
        "byte-order mark) text; save the catalogue as UTF-8" in run.err, run.err


def test_binary_and_latin1_files_keep_their_messages(tmp_path, cli):
    binary = tmp_path / "binary.yaml"
    binary.write_bytes(bytes(range(256)) * 4)
    latin = tmp_path / "latin.yaml"
    latin.write_bytes("kind: thrust-bearing\nname: Lösung\n".encode("latin-1"))
    assert "binary file" in cli("solve", binary).err
    assert "not UTF-8" in cli("solve", latin).err


# --- catalogues written the European way ---------------------------------------------


def _example_rows(separator: str = ",", decimal: str = ".") -> str:
    """The example catalogue without its comments, with ``separator`` between cells and
    ``decimal`` as the decimal point of its numbers."""
    import csv
    import io

    rows = [row for row in csv.reader(io.StringIO(EXAMPLE_CATALOGUE.read_text(
        encoding="utf-8"))) if row and not row[0].startswith("#")]
    out = io.StringIO()
    writer = csv.writer(out, delimiter=separator, lineterminator="\n")
    for row in rows:
        writer.writerow([cell.replace(".", decimal) if cell.replace(".", "", 1).isdigit()
                         else cell for cell in row])
    return out.getvalue()


@pytest.mark.parametrize(("separator", "named"), [(";", "';'"), ("\t", "tabs")])
def test_a_catalogue_separated_by_semicolons_or_tabs_gets_a_hint(separator, named, tmp_path,
                                                                  cli):
    run = cli("solve", catalogue_spec(tmp_path, _example_rows(separator, ",")))
    assert run.code == 2 and len(run.err.splitlines()) == 1
    assert f"bearings.csv:1: the columns are separated by {named}: a catalogue separates " \
           "them by commas and writes the decimal point as '.'" in run.err


def test_a_row_separated_by_semicolons_under_a_comma_header_gets_a_hint(tmp_path, cli):
    header, first, *rest = _example_rows().splitlines()
    text = "\n".join([header, first.replace(",", ";"), *rest]) + "\n"
    run = cli("solve", catalogue_spec(tmp_path, text))
    assert run.code == 2 and "bearings.csv:2: " in run.err
    assert "the row's cells are separated by ';': write commas" in run.err


def test_a_decimal_comma_gets_the_decimal_point_hint(tmp_path, cli):
    run = cli("solve", catalogue_spec(tmp_path, _example_rows(",", ",")))
    assert run.code == 2
    assert "bearings.csv:2: dynamic_load_rating: '13,5' is not a number: write the decimal " \
           "point as '.', like '13.5' (the unit, kN, is the column's)" in run.err


def test_a_comma_before_three_digits_may_be_a_thousands_separator(tmp_path, cli):
    text = _example_rows().replace(",32000,20000,", ',"32,000",20000,', 1)
    run = cli("solve", catalogue_spec(tmp_path, text))
    assert run.code == 2 and "reference_speed: '32,000' is not a number: write the decimal " \
        "point as '.', like '32.000', or leave the thousands separator out, like '32000'" \
        in run.err


# --- the catalogue keyword is a whole value --------------------------------------------


def test_a_catalogue_file_named_catalogue_is_a_path(tmp_path, cli):
    spec = catalogue_spec(tmp_path, EXAMPLE_CATALOGUE.read_bytes(), name="catalogue.csv")
    assert cli("solve", spec).code == 0
    shaft = tmp_path / "shaft.yaml"
    shaft.write_text("kind: rolling-bearing\nname: catalogue check\ncatalogue: catalogue.csv\n"
                     "bore_diameter: 25 mm\nradial_load: 3 kN\naxial_load: 0.5 kN\n"
                     "speed: 1500 rpm\nlubrication: {viscosity: 68 mm^2/s}\n"
                     "contamination_factor: 0.5\nlimits: {min_rating_life: 2000 h}\n")
    run = cli("select", shaft)
    assert run.code == 0, run.err


@pytest.mark.parametrize("written", ["catalogue", "Catalogue", "catalogue ± 5 %",
                                     "catalogue +/- 5 %", "catalogue +- 5 %",
                                     "catalogue ± 0.5 kN"])
def test_the_keyword_stands_for_the_catalogues_value(written, tmp_path, cli):
    spec = catalogue_spec(tmp_path, EXAMPLE_CATALOGUE.read_bytes())
    spec.write_text(spec.read_text().replace("radial_load", f"dynamic_load_rating: {written}\n"
                                             "radial_load", 1))
    run = cli("solve", spec, "--format", "json")
    assert run.code == 0, run.err
    assert "overrides" not in run.out


@pytest.mark.parametrize(("field", "written", "said"), [
    ("pitch_diameter", "catalogue", "gives no pitch_diameter: write its value"),
    ("pitch_diameter", "catalogue ± 1 mm", "gives no pitch_diameter: write its value"),
])
def test_a_keyword_the_row_cannot_fill_is_refused(field, written, said, tmp_path, cli):
    spec = catalogue_spec(tmp_path, EXAMPLE_CATALOGUE.read_bytes())
    spec.write_text(spec.read_text().replace("radial_load", f"{field}: {written}\nradial_load",
                                             1))
    run = cli("solve", spec)
    assert run.code == 2 and f"{field}: the catalogue's" in run.err and said in run.err


@pytest.mark.parametrize("written", ["catalogue.csv", "catalogued", "catalogue_2024",
                                     "catalogue-2024 kN", "my catalogue"])
def test_the_word_inside_a_longer_value_is_not_the_keyword(written, tmp_path, cli):
    spec = catalogue_spec(tmp_path, EXAMPLE_CATALOGUE.read_bytes())
    spec.write_text(spec.read_text().replace("radial_load", f"pitch_diameter: {written}\n"
                                             "radial_load", 1))
    run = cli("solve", spec)
    assert run.code == 2 and "gives no pitch_diameter" not in run.err
    assert "pitch_diameter:" in run.err  # refused as the length it is not
    named = catalogue_spec(tmp_path, EXAMPLE_CATALOGUE.read_bytes())
    named.write_text(named.read_text().replace("name: 30206 on the pinion shaft",
                                               f"name: {written}"))
    assert cli("solve", named).code == 0


def test_an_unreadable_number_says_not_finite_only_where_the_number_stands(cli, tmp_path):
    from bearingcalc.units import LENGTH, UnitError, parse_quantity

    for text, finite in [("nan mm", False), ("-inf mm", False), ("Infinity", False),
                         ("bearing inf", True), ("info mm", True)]:
        with pytest.raises(UnitError) as raised:
            parse_quantity(text, LENGTH)
        assert ("not a finite number" not in str(raised.value)) == finite, text


# --- designations in full-width digits, and select's warnings ---------------------------


FULL_WIDTH = "６３０５"


def test_a_full_width_designation_is_the_bearing_it_reads_as(tmp_path, cli):
    spec = catalogue_spec(tmp_path, EXAMPLE_CATALOGUE.read_bytes(), designation=FULL_WIDTH)
    run = cli("solve", spec, "--format", "json")
    assert run.code in (0, 1), run.err  # solved; its limits are the 30206's
    assert '"catalogue_source": "6305, SKF' in run.out


def test_a_full_width_row_is_checked_against_iso(tmp_path, cli):
    header = _example_rows().splitlines()[0]
    row = next(line for line in _example_rows().splitlines() if line.startswith("6305,SKF"))
    wrong = row.replace("6305,SKF", f"{FULL_WIDTH},ACME").replace(",62,17,", ",63,17,")
    run = cli("solve", catalogue_spec(tmp_path, f"{header}\n{wrong}\n", designation="6305"))
    assert run.code == 2
    assert "outside_diameter 63 mm where ISO's boundary dimensions give 62 mm" in run.err
    both = f"{header}\n{row}\n{row.replace('6305,SKF', f'{FULL_WIDTH},SKF')}\n"
    run = cli("solve", catalogue_spec(tmp_path, both))
    assert run.code == 2 and f"{FULL_WIDTH} (SKF) is given twice" in run.err


def test_select_gives_the_warnings_solve_gives_for_the_rows_it_lists(tmp_path, cli):
    import json

    header, *rows = _example_rows().splitlines()
    special = next(line for line in rows if line.startswith("6305,SKF")).replace(
        "6305,SKF", "X6305,ACME")
    spec = catalogue_spec(tmp_path, "\n".join([header, *rows, special]) + "\n",
                          designation="X6305")
    spec.write_text(spec.read_text().replace("maker: SKF", "maker: ACME"))
    solved = json.loads(cli("solve", spec, "--format", "json").out)
    (unchecked,) = [w for w in solved["warnings"] if "taken unchecked" in w]
    assert "X6305" in unchecked
    shaft = tmp_path / "shaft.yaml"
    shaft.write_text("kind: rolling-bearing\nname: idler\ncatalogue: bearings.csv\n"
                     "bore_diameter: 25 mm\nradial_load: 3 kN\naxial_load: 0.5 kN\n"
                     "speed: 1500 rpm\nlubrication: {viscosity: 68 mm^2/s}\n"
                     "contamination_factor: 0.5\nlimits: {min_rating_life: 2000 h}\n")
    run = cli("select", shaft, "--top", "20", "--format", "json")
    selection = json.loads(run.out)
    assert "X6305" in [row["designation"] for row in selection["qualifying"]]
    assert unchecked in selection["notes"]
    table = " ".join(cli("select", shaft, "--top", "20").out.split())
    assert " ".join(f"note: {unchecked}".split()) in table


def test_a_full_width_series_selects_the_series_it_reads_as(cli):
    ascii_run = cli("select", CATALOGUE_SPEC, "--series", "62", "--format", "json")
    wide_run = cli("select", CATALOGUE_SPEC, "--series", "６２", "--format", "json")
    assert ascii_run.code == wide_run.code and '"6206"' in ascii_run.out
    assert ascii_run.out == wide_run.out
