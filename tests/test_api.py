"""The Python API is the command line's code path: the same numbers as the JSON of
`solve`, `tolerance` and `sweep`, and the same one-line errors."""

from __future__ import annotations

import csv
import io
import json
import math

import pytest

import bearingcalc
from tests.conftest import ROOT

EXAMPLES = sorted((ROOT / "specs").glob("*.yaml"))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda path: path.stem)
def test_solve_gives_the_json_of_the_command_line(cli, path):
    records = [json.loads(line) for line in cli("solve", path, "--format", "json"
                                                ).out.splitlines()]
    results = bearingcalc.solve(path)
    assert len(results) == len(records)
    for result, record in zip(results, records, strict=True):
        assert (result.kind, result.name, result.within_limits) == (
            record["kind"], record["name"], record["within_limits"])
        assert result.results == record["results"] and result.units == record["units"]
        assert result.warnings == record["warnings"]
        assert [v.key for v in result.verdicts] == [v["key"] for v in record["verdicts"]]


def test_a_mapping_and_a_text_are_specs_too():
    text = (ROOT / "specs" / "thrust-bearing.yaml").read_text()
    (from_file,) = bearingcalc.solve(ROOT / "specs" / "thrust-bearing.yaml")
    (from_text,) = bearingcalc.solve(text)
    import yaml

    (from_mapping,) = bearingcalc.solve(yaml.safe_load(text))
    assert from_file.results == from_text.results == from_mapping.results


def test_bad_input_raises_the_command_lines_line(cli, tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text((ROOT / "specs" / "thrust-bearing.yaml").read_text().replace(
        "12.7 mm", "12.7 furlongz"))
    with pytest.raises(bearingcalc.SpecError) as raised:
        bearingcalc.solve(path)
    assert cli("solve", path).err.splitlines() == raised.value.lines()


def test_quantity_frame_and_notebook_table():
    (result,) = bearingcalc.solve(ROOT / "specs" / "rolling-bearing.yaml")
    life = result.quantity("modified_rating_life")
    assert math.isclose(life.to("h").magnitude, result.results["modified_rating_life"] / 3600,
                        rel_tol=1e-12)
    assert "<table>" in result._repr_html_() and "modified_rating_life" in result._repr_html_()
    pandas = pytest.importorskip("pandas")
    frame = result.to_frame()
    assert isinstance(frame, pandas.DataFrame)
    assert frame.loc["modified_rating_life", "value"] == result.results["modified_rating_life"]


def test_sweep_gives_the_points_of_the_command_line(cli, tmp_path):
    spec = ROOT / "specs" / "thrust-bearing.yaml"
    line = bearingcalc.sweep(spec, {"contact_angle": "10deg:40deg:7"})
    rows = list(csv.DictReader(io.StringIO(cli("sweep", spec, "--vary",
                                                "contact_angle=10deg:40deg:7", "--format",
                                                "csv").out)))
    ours = line.results["pitch_radius_pure_rolling"]
    assert [float(row["pitch_radius_pure_rolling [m]"]) for row in rows] == list(ours)
    frame = line.to_frame()  # the CSV's columns, number for number, and the reasons
    for header in rows[0]:
        if header != "reason" and not header.startswith("input."):
            values = [float(row[header]) if row[header] else math.nan for row in rows]
            assert frame[header].tolist() == pytest.approx(values, rel=0, nan_ok=True), header
    assert frame["reason"].tolist() == [row["reason"] for row in rows]
    assert len(repr(line)) < 200 and "7 points of contact_angle" in repr(line)
    assert line.plot(tmp_path / "line.png").stat().st_size > 1000
    assert line.plot()._repr_svg_().lstrip().startswith("<?xml")


def test_tolerance_gives_the_record_of_the_command_line(cli):
    spec = ROOT / "specs" / "tolerances" / "thrust-bearing.yaml"
    study = bearingcalc.tolerance(spec, samples=3000, seed=3)
    record = json.loads(cli("tolerance", spec, "-n", "3000", "--seed", "3", "--format",
                            "json").out)
    assert study.record["results"] == record["results"]
    assert study.within_limits is True
    frame = study.to_frame()
    for key, entry in record["results"].items():
        assert frame.loc[key, "nominal"] == entry["nominal"]
        assert frame.loc[key, "worst_case_min"] == entry["worst_case"]["min"]
        assert frame.loc[key, "monte_carlo_std"] == entry["monte_carlo"]["std"]
        assert frame.loc[key, "unit"] == record["units"][key]
    assert len(repr(study)) < 200 and "within limits" in repr(study)
