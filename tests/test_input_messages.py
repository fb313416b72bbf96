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
        "byte-order mark) text: save the catalogue as UTF-8" in run.err, run.err


def test_binary_and_latin1_files_keep_their_messages(tmp_path, cli):
    binary = tmp_path / "binary.yaml"
    binary.write_bytes(bytes(range(256)) * 4)
    latin = tmp_path / "latin.yaml"
    latin.write_bytes("kind: thrust-bearing\nname: Lösung\n".encode("latin-1"))
    assert "binary file" in cli("solve", binary).err
    assert "not UTF-8" in cli("solve", latin).err
