"""Narrow terminals: a number is never broken across lines (at its thousands separator or
from its unit), in a table's cell or a printed verdict, and a file name is never broken,
however long its path; the JSON's numbers stay plain numbers."""

from __future__ import annotations

import io
import json
import re
import shutil

import pytest

from bearingcalc.reports import formatting
from bearingcalc.reports.formatting import console
from bearingcalc.verdicts import BEFORE_UNIT, THOUSANDS, Verdict, verdict_line
from tests.conftest import ROOT

#: A number as verdicts write it, with its unit: 20 000 h, −70 %, 1.018.
QUANTITY = re.compile(rf"[−+-]?\d[\d{THOUSANDS}]*(?:\.\d+)?(?:{BEFORE_UNIT}[^\s)]+)?")
#: A failing life: 5 981 h against 20 000 h.
SHORT_LIFE = ROOT / "specs" / "rolling-bearing.yaml"


def quantities(text: str) -> list[str]:
    """The numbers of ``text`` (a verdict) with their units, of four or more digits or
    with a unit: those a line end must not break."""
    return [q for q in QUANTITY.findall(text) if THOUSANDS in q or BEFORE_UNIT in q]


def assert_whole(lines: list[str], wanted: list[str]) -> None:
    for quantity in wanted:
        assert any(quantity in line for line in lines), (quantity, lines)


def failing_spec(tmp_path, name: str = "shaft.yaml"):
    """The example bearing with a required life above its own: a verdict of thousands."""
    text = SHORT_LIFE.read_text()
    spec = tmp_path / name
    spec.write_text(re.sub(r"min_rating_life: [\d.]+ *\w+", "min_rating_life: 25000 h", text))
    return spec


def test_verdicts_hold_their_numbers_with_no_break_spaces():
    verdict = Verdict(key="life_margin", name="modified rating life", value=5981 * 3600.0,
                      limit=20000 * 3600.0, unit="s", margin=-0.70095, at_least=True,
                      limit_word="required")
    line = verdict_line(verdict)
    assert line == (f"modified rating life 5{THOUSANDS}981{BEFORE_UNIT}h < required "
                    f"20{THOUSANDS}000{BEFORE_UNIT}h (margin −70.1{BEFORE_UNIT}%)")
    assert (THOUSANDS, BEFORE_UNIT) == ("\u202f", "\u00a0")


@pytest.mark.parametrize("width", [20, 24, 31, 40, 57])
def test_a_printed_line_and_a_table_cell_never_break_a_number(width):
    from rich.table import Table

    text = (f"modified rating life 5{THOUSANDS}981{BEFORE_UNIT}h < required "
            f"10{THOUSANDS}000{BEFORE_UNIT}h (margin −70{BEFORE_UNIT}%)")
    stream = io.StringIO()
    out = console(stream)
    out.width = width
    out.print(text)
    table = Table()
    table.add_column("spec", no_wrap=True)
    table.add_column("governing margin")
    table.add_row("a.yaml", text)
    out.print(table)
    lines = stream.getvalue().splitlines()
    assert_whole(lines, ["5\u202f981\u00a0h", "10\u202f000\u00a0h", "−70\u00a0%"])
    # and the words still wrap: no line is wider than the terminal
    assert max(len(line) for line in lines) <= width


def test_text_without_no_break_spaces_wraps_as_before():
    stream = io.StringIO()
    out = console(stream)
    out.width = 10
    out.print("one two three four")
    assert [line.rstrip() for line in stream.getvalue().splitlines()] == ["one two",
                                                                          "three four"]


@pytest.mark.parametrize("width", [40, 60, 80])
def test_check_on_a_narrow_terminal_keeps_file_names_and_numbers_whole(cli, tmp_path,
                                                                      monkeypatch, width):
    """A spec deep in long folders: its line holds the whole path, its verdict every
    number whole, whatever the width."""
    deep = tmp_path.joinpath("projects", "mechanical-design", "a-rather-long-folder-name",
                             "gearbox-for-the-conveyor-of-line-three")
    deep.mkdir(parents=True)
    spec = failing_spec(deep, "pinion-shaft-bearing-with-the-longer-life.yaml")
    shutil.copyfile(ROOT / "specs" / "thrust-bearing.yaml", deep / "thrust.yaml")
    monkeypatch.setattr(formatting, "PIPE_WIDTH", width)
    run = cli("check", deep, "--all")
    assert run.code == 1, run.err
    lines = run.out.splitlines()
    assert any(line.startswith("FAIL  ") and f" {spec} " in line for line in lines), lines
    records = [json.loads(line) for line in cli("check", deep, "-f", "json").out.splitlines()]
    for record in records:
        for verdict in record["verdicts"]:
            assert isinstance(verdict["value"], float) and isinstance(verdict["limit"], float)
    failing = [m for record in records for m in record["messages"] if "required" in m]
    assert failing and quantities(failing[0])
    assert_whole(lines, quantities(failing[0]))


@pytest.mark.parametrize("width", [50, 70])
def test_solve_and_select_verdicts_keep_their_numbers_whole(cli, tmp_path, monkeypatch, width):
    monkeypatch.setattr(formatting, "PIPE_WIDTH", width)
    spec = failing_spec(tmp_path)
    run = cli("solve", spec)
    assert run.code == 1, run.err
    lines = run.out.splitlines()
    failing = [line for line in lines if "required" in line]
    assert failing
    record = json.loads(cli("solve", spec, "-f", "json").out)
    fields = ("key", "name", "value", "limit", "unit", "margin", "at_least")
    wanted = [q for v in record["verdicts"] if not v["passed"] for q in quantities(
        verdict_line(Verdict(**{f: v[f] for f in fields}, limit_word="required")))]
    assert wanted
    assert_whole(lines, wanted)


def test_the_html_report_keeps_numbers_whole(cli, tmp_path):
    spec = failing_spec(tmp_path)
    page = tmp_path / "report.html"
    run = cli("report", spec, "-o", page)
    assert run.code == 0, run.err
    text = page.read_text()
    # the verdict's numbers joined by no-break spaces, written as the characters themselves
    assert re.search(rf"required 25{THOUSANDS}000{BEFORE_UNIT}h", text), text[:2000]


def test_the_shipped_specs_by_their_absolute_paths_get_a_whole_line_each(cli, monkeypatch):
    """The shipped specs, named by their absolute paths whatever the clone's folder: a
    line per spec, each holding its whole file name."""
    monkeypatch.setattr(formatting, "PIPE_WIDTH", 40)
    run = cli("check", ROOT / "specs", "--all")
    assert run.code == 0, run.err
    heads = [line for line in run.out.splitlines() if line.startswith("PASS  ")]
    assert len(heads) == len(list((ROOT / "specs").rglob("*.yaml")))
    for head in heads:
        assert head.split("  ")[1].startswith(str(ROOT / "specs")) and ".yaml" in head


@pytest.mark.parametrize("command", [
    ["solve"], ["sweep", "--vary", "radial_load=8kN:10kN:3"], ["select"],
    ["tolerance", "-m", "rss"]])
def test_every_report_names_a_long_spec_path_whole(cli, tmp_path, monkeypatch, command):
    """The heading that names the spec holds its whole path on one line, on a terminal
    narrower than the path (the terminal folds it; rich never breaks it)."""
    deep = tmp_path.joinpath("projects", "mechanical-design", "a-rather-long-folder-name")
    deep.mkdir(parents=True)
    shutil.copyfile(ROOT / "specs" / "catalogues" / "example.csv", deep / "bearings.csv")
    text = (ROOT / "specs" / "rolling-bearing-catalogue.yaml").read_text()
    text = re.sub(r"(?m)^catalogue: .*$", "catalogue: bearings.csv", text)
    text = re.sub(r"(?m)^radial_load: (\S+ \S+).*$", r"radial_load: \1 ± 0.5 kN", text)
    spec = deep / "pinion-shaft-bearing-of-the-conveyor-drive.yaml"
    spec.write_text(text)
    monkeypatch.setattr(formatting, "PIPE_WIDTH", 40)
    run = cli(command[0], spec, *command[1:])
    assert run.code in (0, 1), run.err
    assert len(str(spec)) > 40
    assert any(str(spec) in line for line in run.out.splitlines()), run.out
