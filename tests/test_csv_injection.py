"""Every CSV bearingcalc writes (solve, select, sweep) shows spec and catalogue text as
text: a cell that would start a spreadsheet formula (=, +, -, @, a tab, a return) gets
a leading ', and numbers stay numbers (a negative one unquoted)."""

from __future__ import annotations

import csv
import io
import json
import math
import shutil

import numpy as np
import pytest

from bearingcalc import sweeps
from bearingcalc.reports import csv_cells, write_sweep_csv
from bearingcalc.reports.csv_cells import csv_cell, csv_text_field
from tests.conftest import ROOT

FORMULAS = ['=HYPERLINK("http://x.example","open")', "+1+2", "-2+3", "@SUM(A1:A9)",
            "\tcmd", "\rcmd"]
SPEC = ROOT / "specs" / "rolling-bearing.yaml"
CATALOGUE = ROOT / "specs" / "catalogues" / "example.csv"


def rows(text: str) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(text)))


def named(text: str, name: str) -> str:
    """The spec ``text`` with ``name`` as its name (YAML-quoted, so any text goes)."""
    return "name: " + json.dumps(name) + "\n" + "".join(
        line + "\n" for line in text.splitlines() if not line.startswith("name:"))


@pytest.mark.parametrize("formula", FORMULAS)
def test_a_formula_cell_is_marked_as_text(formula):
    assert csv_cell(formula).startswith("'")
    assert csv_text_field(formula).lstrip('"').startswith("'")


@pytest.mark.parametrize("text", ["6205", "SKF", "spec.yaml", "a=b", "1-2", " =1", ""])
def test_other_text_is_left_as_it_is(text):
    assert csv_cell(text) == text


@pytest.mark.parametrize(("value", "written"), [
    (-3.5, "-3.5"), (-0.0, "-0.0"), (1e-300, "1e-300"), (-2, "-2"), (np.float64(-1.25), "-1.25"),
    (np.int64(-7), "-7"), (True, "true"), (False, "false"), (None, "")])
def test_numbers_stay_numbers(value, written):
    assert csv_cell(value) == written


@pytest.mark.parametrize("formula", FORMULAS)
def test_solve_guards_the_name(cli, tmp_path, formula):
    spec = tmp_path / "spec.yaml"
    spec.write_text(named(SPEC.read_text(), formula))
    run = cli("solve", spec, "--format", "csv")
    assert run.code in (0, 1), run.err
    (row,) = rows(run.out)
    assert row["name"].startswith("'"), row["name"]
    assert row["name"][1:2] == formula[:1] or formula[0] in "\t\r"


@pytest.mark.parametrize("file_name", ["=1+2.yaml", "+1.yaml", "@A1.yaml"])
def test_solve_guards_the_spec_file_name(cli, tmp_path, monkeypatch, file_name):
    monkeypatch.chdir(tmp_path)
    shutil.copyfile(SPEC, tmp_path / file_name)
    run = cli("solve", file_name, "--format", "csv")
    assert run.code in (0, 1), run.err
    assert rows(run.out)[0]["spec"] == "'" + file_name


def test_solve_writes_each_number_as_the_json_gives_it(cli, tmp_path):
    """The CSV's numeric columns are the numbers of the JSON record, none of them text
    (a negative one included: the thrust bearing's pitch-radius deviation)."""
    spec = ROOT / "specs" / "thrust-bearing.yaml"
    (row,) = rows(cli("solve", spec, "--format", "csv").out)
    (record,) = [json.loads(line) for line in cli("solve", spec, "--format", "json").out
                 .splitlines()]
    negatives = 0
    for key, value in record["results"].items():
        cell = row[f"{key} [{record['units'][key]}]"]
        if value is None:
            assert cell == ""
            continue
        assert float(cell) == value and not cell.startswith("'")
        negatives += value < 0
    assert negatives, "no negative number to check"


def test_select_guards_the_spec_and_every_catalogue_cell(cli, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    text = CATALOGUE.read_text().replace("SKF,", "@SKF,")
    (tmp_path / "cat.csv").write_text(text)
    shaft = ("kind: rolling-bearing\nname: idler\ncatalogue: cat.csv\nbore_diameter: 25 mm\n"
             "radial_load: 3 kN\naxial_load: 0.5 kN\nspeed: 1500 rpm\n"
             "lubrication: {viscosity: 68 mm^2/s}\ncontamination_factor: 0.5\n"
             "limits: {min_rating_life: 2000 h, min_static_safety: 2}\n")
    (tmp_path / "=shaft.yaml").write_text(shaft)
    run = cli("select", "=shaft.yaml", "--format", "csv", "--top", "100")
    assert run.code == 0, run.err
    table = rows(run.out)
    assert table and all(row["spec"] == "'=shaft.yaml" for row in table)
    makers = {row["maker"] for row in table}
    assert "'@SKF" in makers and "@SKF" not in makers
    for row in table:
        for column in ("bore_diameter [m]", "outside_diameter [m]", "width [m]"):
            assert math.isfinite(float(row[column]))
        assert row["governing_margin"] == "" or float(row["governing_margin"]) == float(
            row["governing_margin"])


def test_the_sweep_guards_its_header_and_its_reasons(monkeypatch):
    """The sweep's own writer (not the csv module) guards its text cells too."""
    from bearingcalc.evaluation import load_one_spec

    kind, spec, document = load_one_spec(ROOT / "specs" / "thrust-bearing.yaml")
    solved = sweeps.sweep_spec(kind, spec, document, ["contact_angle=10deg:40deg:3"])
    code = next(iter(kind.status_reasons))
    solved.status[1] = code
    for values in solved.results.values():
        values[1] = np.nan
    monkeypatch.setattr(sweeps.Sweep, "reason", lambda self, status: "-1: =cmd, a reason")
    first = next(iter(solved.results))
    solved.results = {"=" + key if key == first else key: values
                      for key, values in solved.results.items()}
    monkeypatch.setattr(sweeps.Sweep, "units", property(lambda self: dict.fromkeys(
        self.results, "m")))
    stream = io.StringIO()
    write_sweep_csv(solved, stream)
    table = list(csv.reader(io.StringIO(stream.getvalue())))
    assert table[0][1] == f"'={first} [m]"
    assert table[2][-1] == "'-1: =cmd, a reason"
    assert table[1][-1] == "" and float(table[1][0]) > 0


def test_every_csv_writer_uses_the_one_guard():
    """solve's, select's and the sweep's writers all go through csv_cells."""
    import inspect

    from bearingcalc.reports import select, solve, sweep_csv

    for module in (solve, select, sweep_csv):
        source = inspect.getsource(module)
        assert "csv_cells" in source and "csv.writer" not in source, module.__name__
    assert "csv.writer" in inspect.getsource(csv_cells)
