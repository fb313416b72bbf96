"""A drive's shafts hold a list of bearings: a shaft of three is a valid spec in the data
model, solved by the same loops, and refused by the shaft statics alone (which take two),
with one line naming the shaft."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import yaml

from bearingcalc.core import bevel_drive
from bearingcalc.evaluation import parse_document
from bearingcalc.kinds import KINDS
from bearingcalc.models.yaml_loader import load_documents

ROOT = Path(__file__).resolve().parents[1]
THIRD = {"position": "210 mm", "type": "deep-groove", "dynamic_load_rating": "23.4 kN",
         "static_load_rating": "11.6 kN", "static_factor": 12, "bore_diameter": "25 mm",
         "outside_diameter": "62 mm"}


def _three_bearing_drive(tmp_path: Path, shafts: tuple[str, ...]) -> Path:
    data = yaml.safe_load((ROOT / "specs" / "bevel-drive.yaml").read_text())
    for shaft in shafts:
        data[f"{shaft}_bearings"].append({**THIRD, "position": "250 mm"
                                          if shaft == "gear" else THIRD["position"]})
    path = tmp_path / "three-bearings.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def test_a_shaft_of_three_bearings_is_a_valid_spec(tmp_path):
    path = _three_bearing_drive(tmp_path, ("pinion", "gear"))
    _, spec = parse_document(load_documents(path)[0])
    inputs = spec.solver_inputs()
    assert [len(inputs["shafts"][shaft]) for shaft in ("pinion", "gear")] == [3, 3]
    # the third bearing's own fields reach the solver like the first two's
    assert inputs["shafts"]["pinion"][2]["position"] == 0.210


def test_only_the_statics_refuse_it(tmp_path):
    path = _three_bearing_drive(tmp_path, ("pinion", "gear"))
    kind, spec = parse_document(load_documents(path)[0])
    results, status = KINDS[kind.name].evaluate(spec.solver_inputs())
    assert int(status) == bevel_drive.BEARING_COUNT["pinion"]
    field, why = KINDS[kind.name].status_reasons[int(status)]
    assert field == "pinion_bearings" and "statically indeterminate" in why
    # the pair is solved all the same: only the shafts' part is refused
    assert np.isfinite(results["tangential_force"])


def test_the_refusal_is_one_line_naming_the_shaft(cli, tmp_path):
    path = _three_bearing_drive(tmp_path, ("gear",))
    run = cli("solve", path)
    assert run.code == 2
    lines = run.err.strip().splitlines()
    assert len(lines) == 1, run.err
    assert "gear_bearings" in lines[0] and "exactly 2 bearings" in lines[0]
    assert f"{path.name}:" in lines[0]  # file:line, as every refusal


def test_two_bearings_at_one_position_are_found_among_three(cli, tmp_path):
    data = yaml.safe_load((ROOT / "specs" / "bevel-drive.yaml").read_text())
    data["pinion_bearings"].append({**THIRD, "position": "90 mm"})
    path = tmp_path / "coinciding.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    run = cli("check", path)
    assert run.code == 2
    assert "pinion_bearings.3.position" in run.out + run.err
