"""Specs of one file solved together as mounted: bearings of different element counts
share one call, the smaller padded along ``element``; each spec's results equal its own
solve alone, its absent elements null in JSON and left out of its table."""

from __future__ import annotations

import json

import pytest

from tests.conftest import ROOT
from tests.mounted_specs import TAPERED_ROLLERS

BALLS = """kind: rolling-bearing
name: {name}
type: deep-groove
method: iso-16281
dynamic_load_rating: 14.8 kN
static_load_rating: 7.8 kN
ball_count: {count}
ball_diameter: 7.938 mm
pitch_diameter: 38.5 mm
inner_groove_conformity: 0.52
outer_groove_conformity: 0.53
operating_clearance: 10 µm
radial_load: 2 kN
speed: 3000 rpm
"""
ROLLERS = """kind: rolling-bearing
name: {name}
type: cylindrical-roller
method: iso-16281
dynamic_load_rating: 44 kN
static_load_rating: 36.5 kN
roller_count: {count}
roller_diameter: 7.5 mm
roller_length: 10 mm
pitch_diameter: 46 mm
operating_clearance: 15 µm
radial_load: 8 kN
speed: 3000 rpm
"""
PAIR = """kind: rolling-bearing
name: {name}
type: tapered-roller
arrangement: face-to-face
method: iso-16281
""" + TAPERED_ROLLERS.replace("roller_count: 17", "roller_count: {count}") + """\
width: 17.25 mm
setting: {{end_play: 15 µm}}
radial_load: 6 kN
axial_load: 2 kN
speed: 3000 rpm
"""


@pytest.mark.parametrize(("template", "counts"), [
    (BALLS, (8, 9)), (ROLLERS, (14, 12)), (PAIR, (15, 17))])
def test_each_spec_of_a_file_solves_as_it_would_alone(cli, spec_file, template, counts):
    assert "{count}" in template
    texts = [template.format(name=f"with {count}", count=count) for count in counts]
    together = cli("solve", spec_file("---\n".join(texts)), "--format", "json")
    assert together.code in (0, 1), together.err
    records = [json.loads(line) for line in together.out.splitlines()]
    assert len(records) == 2
    for text, record in zip(texts, records, strict=True):
        alone = cli("solve", spec_file(text), "--format", "json")
        [own] = [json.loads(line) for line in alone.out.splitlines()]
        present = {key: value for key, value in record["results"].items()
                   if value is not None}
        assert present == own["results"]
    table = cli("solve", spec_file("---\n".join(texts)))
    assert table.code in (0, 1), table.err
    smaller = min(counts)
    assert f"element_{max(counts)} " in table.out
    first_block = table.out.split(texts[1].splitlines()[1].split(": ")[1])[0]
    assert (f"element_{smaller + 1} " in first_block) == (counts[0] > smaller)


SELECTED = """kind: rolling-bearing
name: as mounted from the catalogue
type: deep-groove
method: iso-16281
designation: "{designation}"
{clearance}
radial_load: 3 kN
speed: 3000 rpm
"""


@pytest.mark.parametrize("clearance", [
    "operating_clearance: 5 µm",
    "mounting: {clearance_group: C3, shaft: k5, housing: H7}"])
def test_select_solves_each_row_with_its_own_estimated_geometry(cli, spec_file, clearance):
    """The catalogue's 6208 and 6308 (one bore, two sizes) are selected in one call; each
    row's internal geometry is estimated from its own size and ratings (and its mounting's
    classes read at its own size), so its governing value is its own solve's, not one
    estimate shared by every row."""
    catalogue = ROOT / "specs" / "catalogues" / "example.csv"
    run = cli("select", spec_file(SELECTED.format(designation="6208", clearance=clearance)),
              "--catalogue", catalogue, "-f", "json")
    assert run.code == 0, run.err
    rows = {row["designation"]: row["governing"] for row in json.loads(run.out)["qualifying"]}
    assert {"6208", "6308"} <= set(rows)
    for designation in ("6208", "6308"):
        alone = cli("solve", spec_file(SELECTED.format(designation=designation,
                                                       clearance=clearance)),
                    "--catalogue", catalogue, "-f", "json")
        results = json.loads(alone.out)["results"]
        governing = rows[designation]
        assert governing["key"] == "contact_pressure_margin"
        assert governing["value"] == pytest.approx(results["max_contact_pressure"], rel=1e-9)
