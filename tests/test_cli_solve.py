"""`bearingcalc solve` as the user runs it: formats, exit codes and every bad input."""

from __future__ import annotations

import csv
import io
import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest
from numpy.testing import assert_allclose

from tests.conftest import ROOT, solve_json
from tests.independent import thrust_bearing_3d

THRUST_RESULT_KEYS = [
    "ball_radius", "contact_angle", "pitch_radius", "pitch_radius_pure_rolling",
    "pitch_radius_deviation", "shaft_contact_radius", "shaft_speed", "ball_speed", "cage_speed",
    "ball_center_speed", "shaft_contact_speed", "spin_speed", "roll_speed", "spin_to_roll",
    "slip_margin", "pitch_radius_min", "pitch_radius_max", "ball_pass_frequency_race",
    "ball_pass_frequency_shaft",
]
EXAMPLE_SPECS = sorted((ROOT / "specs").glob("*.yaml"))

TB = """kind: thrust-bearing
ball_diameter: 12.7 mm
contact_angle: 30 deg
pitch_radius: 26 mm
shaft_speed: 1500 rpm
"""


@pytest.mark.parametrize("spec", EXAMPLE_SPECS, ids=lambda p: p.name)
@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_every_example_spec_solves_in_every_format(cli, spec, fmt):
    run = cli("solve", spec, "--format", fmt)
    assert run.code == 0, run.err
    assert run.err == ""
    assert run.out.strip()
    assert "nan" not in run.out.lower().replace("nanometer", "")


def test_json_record_follows_the_contract(cli):
    (record,) = solve_json(cli, ROOT / "specs" / "thrust-bearing.yaml")
    assert list(record) == ["spec", "kind", "name", "results", "units", "within_limits",
                            "verdicts", "warnings"]
    assert record["kind"] == "thrust-bearing"
    assert record["name"] == "TB-30"
    assert list(record["results"]) == THRUST_RESULT_KEYS
    assert record["units"]["cage_speed"] == "rad/s"
    assert record["units"]["ball_pass_frequency_race"] == "Hz"
    assert record["within_limits"] is True
    (verdict,) = record["verdicts"]
    assert verdict["key"] == "slip_margin" and verdict["passed"] is True
    # the margin as a fraction of the limit: 1 − |spin_to_roll|/max_spin_to_roll
    assert verdict["limit"] == pytest.approx(0.01, rel=1e-12)
    assert verdict["margin"] == pytest.approx(
        1 - abs(record["results"]["spin_to_roll"]) / 0.01, rel=1e-12)


def test_json_speeds_match_the_3d_constraint_solve(cli, spec_file):
    (record,) = solve_json(cli, spec_file(TB))
    res = record["results"]
    ref = thrust_bearing_3d(0.00635, math.radians(30), 0.026, 1500 * 2 * math.pi / 60)
    for key in ("ball_speed", "cage_speed", "ball_center_speed", "spin_speed", "roll_speed"):
        assert_allclose(res[key], ref[key], rtol=1e-9, atol=1e-12)


def test_csv_has_si_units_in_the_header_and_one_row_per_spec(cli, spec_file):
    path = spec_file(TB + "---\n" + TB.replace("26 mm", "25 mm"))
    run = cli("solve", path, "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(run.out)))
    assert len(rows) == 2
    assert rows[0]["spec"] == f"{path}#1" and rows[1]["spec"] == f"{path}#2"
    assert "pitch_radius [m]" in rows[0] and "cage_speed [rad/s]" in rows[0]
    assert float(rows[0]["pitch_radius [m]"]) == 0.026


def test_table_reads_without_colour(cli):
    run = cli("solve", ROOT / "specs" / "thrust-bearing.yaml")
    assert "PASS" in run.out and "\x1b[" not in run.out
    assert "rpm" in run.out and "mm" in run.out


@pytest.mark.parametrize(("omit", "solved_key"), [
    ("ball_diameter", "ball_radius"), ("contact_angle", "contact_angle"),
    ("pitch_radius", "pitch_radius")])
def test_leaving_out_one_of_r_theta_b_solves_it_for_pure_rolling(cli, spec_file, omit, solved_key):
    text = "\n".join(line for line in TB.splitlines() if not line.startswith(omit)) + "\n"
    (record,) = solve_json(cli, spec_file(text))
    res = record["results"]
    assert abs(res["spin_to_roll"]) < 1e-12
    ref = thrust_bearing_3d(res["ball_radius"], res["contact_angle"], res["pitch_radius"],
                            res["shaft_speed"])
    assert abs(ref["spin_speed"]) < 1e-9 * abs(ref["roll_speed"])
    given = {"ball_radius": 0.00635, "contact_angle": math.radians(30), "pitch_radius": 0.026}
    for key, value in given.items():
        if key != solved_key:
            assert res[key] == pytest.approx(value, rel=1e-15)


@pytest.mark.parametrize("variant", [
    {"ball_diameter": "0.5 in", "contact_angle": "0.5235987755982988 rad",
     "shaft_speed": "157.07963267948966 rad/s"},
    {"ball_diameter": "12.7 mm", "contact_angle": "30 deg", "shaft_speed": "25 rev/s"},
    {"ball_diameter": "1.27 cm", "contact_angle": "30 deg", "shaft_speed": "1500 rpm"},
])
def test_units_of_every_kind_give_the_same_design(cli, spec_file, variant):
    (reference,) = solve_json(cli, spec_file(TB, "ref.yaml"))
    text = TB
    for key, value in variant.items():
        text = "\n".join(f"{key}: {value}" if line.startswith(key + ":") else line
                         for line in text.splitlines()) + "\n"
    (record,) = solve_json(cli, spec_file(text))
    for key, value in reference["results"].items():
        assert record["results"][key] == pytest.approx(value, rel=1e-12), key


def test_ball_radius_is_half_the_diameter(cli, spec_file):
    (a,) = solve_json(cli, spec_file(TB, "a.yaml"))
    (b,) = solve_json(cli, spec_file(TB.replace("ball_diameter: 12.7", "ball_radius: 6.35"),
                                     "b.yaml"))
    assert a["results"] == b["results"]


def test_a_limit_violation_exits_1_and_says_fail(cli, spec_file):
    path = spec_file(TB.replace("26 mm", "20 mm"))
    run = cli("solve", path)
    assert run.code == 1
    assert "FAIL" in run.out and "slip_margin" in run.out
    (record,) = solve_json(cli, path)
    assert record["within_limits"] is False
    assert record["results"]["slip_margin"] < 0


def test_unbounded_window_edge_is_null_with_a_warning(cli, spec_file):
    text = TB.replace("30 deg", "44.9 deg") + "limits:\n  max_spin_to_roll: 0.5\n"
    (record,) = solve_json(cli, spec_file(text))
    assert record["results"]["pitch_radius_max"] is None
    assert any("pitch_radius_max" in w for w in record["warnings"])


def test_invalid_beats_limit_violation_and_valid_specs_still_print(cli, spec_file):
    good = spec_file(TB.replace("26 mm", "20 mm"), "over.yaml")
    bad = spec_file(TB.replace("30 deg", "50 deg"), "bad.yaml")
    run = cli("solve", good, bad, "--format", "json")
    assert run.code == 2
    assert len(run.out.splitlines()) == 1
    assert run.err.count("\n") == 1


BAD = [
    # (text, expected line, expected fragment)
    ("", None, "empty file"),
    (b"kind: thrust-bearing\nname: \xff\n", None, "not UTF-8"),
    ("kind: thrust-bearing\nball_diameter: [12.7 mm\n", 3, "malformed YAML"),
    ("kind: !!python/object/apply:os.system [ls]\n", 1, "YAML tag"),
    ("- kind: thrust-bearing\n", 1, "a spec is a mapping"),
    ("just a string\n", 1, "a spec is a mapping"),
    ("name: x\n", 1, "missing key 'kind'"),
    ("kind: thrust-bering\n", 1, "did you mean 'thrust-bearing'"),
    (TB + "pich_radius: 25 mm\n", 6, "unknown key 'pich_radius' (did you mean 'pitch_radius'?)"),
    (TB.replace("shaft_speed: 1500 rpm\n", ""), 1, "missing required key 'shaft_speed', "
     "e.g. shaft_speed: 1500 rpm"),
    (TB.replace("12.7 mm", "12.7"), 2, "a bare number has no unit: write it as '12.7 mm'"),
    (TB.replace("1500 rpm", "1500"), 5, "write it as '1500 rpm'"),
    (TB.replace("12.7 mm", "12 rpm"), 2, "'rpm' is not a unit of length"),
    (TB.replace("1500 rpm", "25 Hz"), 5, "it is a frequency"),
    (TB.replace("12.7 mm", "0 mm"), 2, "must be greater than zero, got '0 mm'"),
    (TB.replace("26 mm", "-26 mm"), 4, "must be greater than zero"),
    (TB.replace("12.7 mm", "nan mm"), 2, "not a finite number"),
    (TB.replace("30 deg", "inf deg"), 3, "not a finite number"),
    (TB.replace("30 deg", ".nan"), 3, "nan is not a finite number; give an angle like"),
    (TB.replace("30 deg", "50 deg"), 3, "contact_angle: pure rolling needs 0 deg < θ < 45 deg, "
     "got 50 deg"),
    (TB.replace("30 deg", "0 deg"), 3, "pure rolling needs 0 deg < θ < 45 deg"),
    (TB.replace("26 mm", "5 mm"), 4, "shaft contact radius d = b − r·cosθ must be positive"),
    (TB + "ball_count: 40\n", 6, "ball_count: the balls do not fit"),
    (TB + "ball_count: 4.5\n", 6, "must be a whole number of balls"),
    (TB + "ball_count: 0\n", 6, "must be at least 1"),
    (TB + "ball_radius: 6.35 mm\n", 6, "give ball_diameter or ball_radius, not both"),
    (TB.replace("contact_angle: 30 deg\n", "").replace("pitch_radius: 26 mm\n", ""), None,
     "give at least two of"),
    (TB.replace("contact_angle: 30 deg\n", "").replace("26 mm", "6 mm"), 3,
     "a pure-rolling contact angle exists only for b > r"),
    (TB + "limits:\n  max_spin_to_roll: -0.1\n", 7, "must be a finite number from 0"),
    (TB + "limits:\n  max_spin_to_roll: .inf\n", 7, "must be a finite number from 0"),
    (TB + "limits: 0.1\n", 6, "must be a mapping"),
]


@pytest.mark.parametrize(("text", "line", "fragment"), BAD,
                         ids=[f"bad{i}" for i in range(len(BAD))])
def test_bad_input_gets_one_clear_line_and_exit_2(cli, spec_file, text, line, fragment):
    path = spec_file(text)
    run = cli("solve", path)
    assert run.code == 2
    assert run.exception is None or isinstance(run.exception, SystemExit)
    assert run.out == ""
    assert run.err.count("\n") == 1, run.err
    assert "Traceback" not in run.err
    prefix = f"{path}:{line}: " if line else f"{path}"
    assert run.err.startswith(prefix), run.err
    assert fragment in run.err, run.err


def test_missing_file_and_folder_exit_2(cli, tmp_path):
    run = cli("solve", tmp_path / "none.yaml")
    assert run.code == 2 and "no such file" in run.err
    run = cli("solve", tmp_path)
    assert run.code == 2 and "is a folder" in run.err


def test_python_tag_is_not_executed(cli, spec_file, tmp_path):
    marker = tmp_path / "owned"
    run = cli("solve", spec_file(f"kind: !!python/object/apply:os.system ['touch {marker}']\n"))
    assert run.code == 2 and not marker.exists()


def test_the_installed_command_and_python_m_run_without_traceback(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(TB.replace("30 deg", "50 deg"))
    for command in ([sys.executable, "-m", "bearingcalc"],):
        done = subprocess.run([*command, "solve", str(bad)], capture_output=True, text=True,
                              check=False)
        assert done.returncode == 2
        assert "Traceback" not in done.stderr and "50 deg" in done.stderr
        done = subprocess.run([*command, "solve", str(ROOT / "specs" / "thrust-bearing.yaml"),
                               "-f", "json"], capture_output=True, text=True, check=False)
        assert done.returncode == 0 and json.loads(done.stdout)["kind"] == "thrust-bearing"


def test_help_lists_every_registered_kind_with_its_summary(cli, monkeypatch):
    from dataclasses import replace

    from bearingcalc.kinds import KINDS

    # A kind registered after the command was written is listed too.
    added = replace(KINDS["disk-on-circle"], name="kind-added-by-a-test",
                    summary="a summary only this test gives")
    monkeypatch.setitem(KINDS, added.name, added)
    run = cli("solve", "--help")
    assert run.code == 0, run.err
    # Read as words, whatever the help's layout: colours, box lines and wrapping aside.
    text = re.sub(r"[\s│]+", " ", re.sub(r"\x1b\[[0-9;]*m", "", run.out))
    for name in KINDS:
        assert re.search(rf"(?<![\w-]){re.escape(name)}(?![\w-])", text), name
    assert added.summary in text


COMMANDS = ("solve", "check", "schema", "new", "report", "select", "tolerance", "sweep")


@pytest.mark.parametrize("command", ("", *COMMANDS))
def test_help_speaks_in_words(cli, command):
    """No parser types (``<bool>``, ``<list[Path]>``), no braces round the arguments:
    every value an option takes is a capitalised word, and a flag takes none."""
    run = cli(*command.split(), "--help")
    assert run.code == 0, run.err
    text = re.sub(r"\x1b\[[0-9;]*m", "", run.out)
    assert not re.search(r"<[\w|\[\], ]+>", text), text
    # click's type names, which older typer puts where a metavar repeats the name
    assert not re.search(r"\b(TEXT|INTEGER|FLOAT|BOOLEAN)\b", text), text
    assert not re.search(r"\[\S*x[<>]=", text), text  # typer's range tokens, [x>=1]
    assert "{" not in text and "list[" not in text
    usage = next(line for line in text.splitlines() if "Usage:" in line)
    assert re.search(r"\[OPTIONS\]( (SPEC|PATH)\.\.\.| SPEC| \[KIND\]| COMMAND)?", usage)
    for line in text.splitlines():
        for flag in ("--version", "--help", "--debug", "--all", "--list", "--sobol"):
            if re.search(rf"{flag}\b", line):
                after = line.split(flag, 1)[1]
                assert not re.match(r"\s+(-\w\s+)?[A-Z<]{2,}", after), line


def test_solve_usage_names_its_specs(cli):
    text = re.sub(r"\x1b\[[0-9;]*m", "", cli("solve", "--help").out)
    assert re.search(r"Usage: \S+ solve \[OPTIONS\] SPEC\.\.\.\s", text)


def test_solver_is_importable_and_takes_arrays():
    from bearingcalc import solve_thrust_bearing

    out = solve_thrust_bearing(0.005, np.radians([10.0, 20.0, 30.0]), None, 100.0)
    assert out["pitch_radius"].shape == (3,)


def test_a_limit_no_margin_can_name_is_said_as_the_plain_margin(cli, spec_file):
    """At rest and with no axial load the contact pressure is 0: its margin 1 − p/p_max
    is 1 against any limit, so no limit can be stated and the verdict names the other."""
    text = (ROOT / "specs" / "thrust-bearing-loaded.yaml").read_text()
    run = cli("solve", spec_file(text.replace("axial_load: 2 kN", "axial_load: 0 kN").replace(
        "shaft_speed: 1500 rpm", "shaft_speed: 0 rpm")))
    assert run.code == 0, run.err
    assert "PASS: spin-to-roll ratio" in run.out and "the only limit judged" in run.out


def test_a_narrow_terminal_turns_a_members_table_and_cuts_no_number(cli, monkeypatch):
    """At 80 columns a drive's bearing table has a row per quantity and a column per
    bearing; nothing in any table is cut short with an ellipsis."""
    from bearingcalc.reports import formatting

    monkeypatch.setattr(formatting, "PIPE_WIDTH", 80)
    run = cli("solve", ROOT / "specs" / "bevel-drive.yaml")
    assert run.code == 0, run.err
    assert "…" not in run.out
    assert re.search(r"│ modified rating life \[h\]\s+│\s+9793\.09 │\s+1588600 │", run.out)
    monkeypatch.setattr(formatting, "PIPE_WIDTH", 200)
    wide = cli("solve", ROOT / "specs" / "bevel-drive.yaml").out
    assert re.search(r"│ pinion_bearing_1 │\s+3\.817113 │", wide)
