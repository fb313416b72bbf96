"""Dotted field names through lists and groups in `bearingcalc sweep`: every name that
leads nowhere is one line on stderr, naming the field and what is there, with exit 2."""

from __future__ import annotations

import csv
import io
import re

import pytest

from bearingcalc.evaluation import load_one_spec
from bearingcalc.models.field_path import FieldPath, FieldPathError, list_index, resolve_field
from bearingcalc.variation import field_value
from tests.conftest import ROOT

DRIVE = ROOT / "specs" / "bevel-drive.yaml"
DRIVE_TEXT = DRIVE.read_text()
#: The drive without its optional gear bearings, lubrication and contamination factor.
BARE_DRIVE = re.sub(r"gear_bearings:.*?(?=^reliability)", "", DRIVE_TEXT,
                    flags=re.DOTALL | re.MULTILINE)
BARE_DRIVE = re.sub(r"^(lubrication|contamination_factor):.*\n", "", BARE_DRIVE,
                    flags=re.MULTILINE)


def refused(cli, spec, vary):
    """The one line of a refused sweep, checked for exit 2, the usage error's form and
    the field's name."""
    run = cli("sweep", spec, "--vary", vary)
    assert run.code == 2, run.out
    assert run.err.count("\n") == 1, run.err
    assert run.err.startswith(f"root sweep: Invalid value for '--vary' / '-v': "
                              f"{vary.split('=')[0]}: "), run.err
    assert run.err.endswith(" (see 'root sweep -h')\n"), run.err
    assert "Traceback" not in run.err and "internal error" not in run.err
    return run.err


@pytest.mark.parametrize(("vary", "message"), [
    ("pinion_bearings.2=100mm:200mm:5",
     "pinion_bearings.2 is an item of pinion_bearings, not a number: vary one of its fields, "
     "like pinion_bearings.2.dynamic_load_rating; its fields are designation, maker, type, "
     "arrangement, dynamic_load_rating, "),
    ("pinion_bearings=100mm:200mm:5",
     "pinion_bearings is a list of 2 items, not a number: vary a field of one item, like "
     "pinion_bearings.1.dynamic_load_rating"),
    ("pinion_bearings.3.position=100mm:200mm:5",
     "pinion_bearings is a list of 2 items, numbered from 1 to 2: there is no item 3; name "
     "one like pinion_bearings.1.position"),
    ("pinion_bearings.0.position=100mm:200mm:5", "numbered from 1 to 2: there is no item 0;"),
    ("pinion_bearings.-1.position=100mm:200mm:5", "numbered from 1 to 2: there is no item -1;"),
    ("pinion_bearings.x.position=100mm:200mm:5",
     "pinion_bearings is a list of 2 items; name an item by its number, from 1 to 2, like "
     "pinion_bearings.1.position"),
    ("pinion_bearings..position=100mm:200mm:5", "name an item by its number, from 1 to 2, "
     "like pinion_bearings.1.position"),
    ("pinion_bearings.position=100mm:200mm:5", "like pinion_bearings.1.position"),
    ("pinion_bearings.２.position=100mm:200mm:5", "name an item by its number, from 1 to 2"),
    ("pinion_bearings.².position=100mm:200mm:5", "name an item by its number, from 1 to 2"),
    ("torque.x=1:2:3", "torque is a single value, with no fields inside; name torque itself"),
    ("pinion_bearings.1.position.x=1:2:3", "pinion_bearings.1.position is a single value"),
    ("pinion_bearings.1.=1:2:3",
     "a name is missing after pinion_bearings.1; its inputs: designation, maker, type,"),
    (".torque=1:2:3", "a name is missing before the first dot; inputs: gear_a, "),
    ("pinion_bearings.1.positon=1mm:2mm:3", "pinion_bearings.1 has no input 'positon'; inputs:"),
    ("pinion_bearings.1.load_factors.x=1:2:3", "the spec leaves pinion_bearings.1.load_factors "
     "out (it is optional and not given); give pinion_bearings.1.load_factors in the spec to "
     "sweep pinion_bearings.1.load_factors.x"),
    ("pinion_bearings.1.material=1:2:3", "pinion_bearings.1.material is a group of fields, not "
     "a number: vary one of its fields, like pinion_bearings.1.material.elastic_modulus; its "
     "fields are elastic_modulus, poisson_ratio"),
    ("pinion_bearings.1.type=1:2:3", "pinion_bearings.1.type is not a number that can be swept"),
])
def test_names_into_lists_that_lead_nowhere_are_one_line(cli, vary, message):
    assert message in refused(cli, DRIVE, vary)


@pytest.mark.parametrize(("vary", "message"), [
    ("gear_bearings.1.position=10mm:20mm:3", "the spec leaves gear_bearings out (it is "
     "optional and not given); give gear_bearings in the spec to sweep "
     "gear_bearings.1.position"),
    ("gear_bearings.x.position=10mm:20mm:3", "gear_bearings is a list; name an item by its "
     "number, from 1, like gear_bearings.1.position"),
    ("gear_bearings.0.position=10mm:20mm:3", "gear_bearings is a list, numbered from 1: "
     "there is no item 0"),
    ("lubrication.viscosity=10mm^2/s:20mm^2/s:3", "the spec leaves lubrication out"),
    ("lubrication.viscocity=10mm^2/s:20mm^2/s:3", "lubrication has no input 'viscocity'; "
     "inputs: viscosity, viscosity_40, viscosity_100, temperature"),
    ("lubrication=1:2:3", "lubrication is a group of fields, not a number"),
])
def test_names_through_optional_parts_left_out_are_one_line(cli, spec_file, vary, message):
    assert message in refused(cli, spec_file(BARE_DRIVE), vary)


def test_an_item_field_sweeps_and_its_nominal_point_is_the_spec(cli):
    run = cli("sweep", DRIVE, "--vary", "pinion_bearings.2.position=140mm:160mm:3", "-f", "csv")
    assert run.code == 0, run.err
    rows = list(csv.DictReader(io.StringIO(run.out)))
    positions = [float(r["input.pinion_bearings.2.position [m]"]) for r in rows]
    assert positions == pytest.approx([0.14, 0.15, 0.16], rel=1e-15)
    solved = cli("solve", DRIVE, "-f", "csv")
    assert solved.code == 0, solved.err
    nominal = next(csv.DictReader(io.StringIO(solved.out)))
    life = "system_modified_rating_life [s]"
    assert float(rows[1][life]) == pytest.approx(float(nominal[life]), rel=1e-9)
    assert rows[0][life] != rows[2][life]


def test_leading_zeros_name_the_same_item_as_without(cli):
    padded = cli("sweep", DRIVE, "--vary", "pinion_bearings.01.position=80mm:100mm:3", "-f",
                 "csv")
    plain = cli("sweep", DRIVE, "--vary", "pinion_bearings.1.position=80mm:100mm:3", "-f",
                "csv")
    assert padded.code == plain.code == 0 and padded.out == plain.out
    assert padded.out.startswith("input.pinion_bearings.1.position [m],")
    twice = cli("sweep", DRIVE, "--vary", "pinion_bearings.01.position=80mm:100mm:3",
                "--vary", "pinion_bearings.1.position=80mm:100mm:3")
    assert twice.code == 2 and (
        "Invalid value for '--vary' / '-v': pinion_bearings.1.position is given twice"
        in twice.err)


def test_resolve_field_names_items_from_one_and_reports_what_is_left_out(spec_file):
    _, spec, _ = load_one_spec(DRIVE)
    found = resolve_field(spec, "pinion_bearings.02.position")
    assert (found.name, found.value, found.left_out) == ("pinion_bearings.2.position", 0.15,
                                                         None)
    item = resolve_field(spec, "pinion_bearings.2")
    assert item.in_list and item.parent == "pinion_bearings" and not item.is_list
    assert resolve_field(spec, "pinion_bearings").is_list
    _, bare, _ = load_one_spec(spec_file(BARE_DRIVE))
    left_out = resolve_field(bare, "gear_bearings.1.position")
    assert (left_out.value, left_out.left_out) == (None, "gear_bearings")
    assert field_value(bare, "lubrication.viscosity") is None
    for path in ("pinion_bearings.3.position", "pinion_bearings.0", "torque.x", "nope"):
        with pytest.raises(FieldPathError):
            resolve_field(spec, path)


def test_only_ascii_digits_name_list_items():
    assert [list_index(part) for part in ("1", "02", "0", "２", "²", "-1", "x", "")] == [
        0, 1, -1, None, None, None, None, None]
    assert FieldPath.parse("pinion_bearings.2.position").parts == ("pinion_bearings", 1, "position")
    assert FieldPath.parse("pinion_bearings.².position").parts == (
        "pinion_bearings", "²", "position")
    assert str(FieldPath.parse("pinion_bearings.02.position")) == (
        "pinion_bearings.2.position")


def test_tolerance_takes_no_field_names_from_the_user(cli):
    # --result names a result, not a field: a field's name there is one line, exit 2.
    run = cli("tolerance", ROOT / "specs" / "tolerances" / "bevel-drive.yaml", "--result",
              "pinion_bearings.2", "--method", "worst-case")
    assert run.code == 2 and run.err.count("\n") == 1
    assert ("Invalid value for '--result' / '-r': 'pinion_bearings.2' is not a result of "
            "this bevel-drive spec") in run.err
