"""Input read as engineers write it, and refused in words that say what was written:
sweep bounds with the units their field takes, YAML keys that are no names, text in
UTF-16, catalogues written the European way, the catalogue keyword, and designations
in full-width digits."""

from __future__ import annotations

import math

import pytest

from bearingcalc.evaluation import load_one_spec
from bearingcalc.models.base import field_parser
from bearingcalc.models.field_path import FieldPathError, resolve_field
from bearingcalc.models.quantities import Measured
from bearingcalc.sweeps import SweepError, parse_axis
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
    ("rolling-bearing", "radial_load=1:2 kN:3", "has no unit"),
    ("rolling-bearing", "radial_load=1 deg:2 kN:3", "radial_load"),
    ("ball-bearing-geometry", "ball_count=8.5:12:3", "'8.5' is not a whole number"),
    ("ball-bearing-geometry", "ball_count=eight:12:3", "'eight' is not a whole number"),
    ("bevel-gears-spiral", "rating.grade=true:2:2", "not a whole number"),
])
def test_a_bound_the_field_does_not_take_says_why(spec, vary, said):
    _, parsed, _ = load_one_spec(ROOT / "specs" / f"{spec}.yaml")
    with pytest.raises(SweepError) as raised:
        parse_axis(vary, parsed)
    assert said in str(raised.value) and str(raised.value).startswith("--vary ")


def test_the_command_line_sweeps_a_reliability_in_percent(cli):
    result = cli("sweep", ROOT / "specs" / "rolling-bearing.yaml", "--vary",
                 "reliability=90%:99%:3", "--format", "csv")
    assert result.code == 0, result.err
    assert result.out.count("\n") == 4
