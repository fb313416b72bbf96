"""`bearingcalc sweep`: lines and grids for every kind, gaps, CSV round trip, plots."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from bearingcalc.evaluation import evaluate_document
from bearingcalc.models.yaml_loader import load_documents
from tests.conftest import ROOT

SPECS = ROOT / "specs"
LINES = {
    "thrust-bearing": "contact_angle=5deg:44deg:40",
    "disk-on-circle": "disk_radius=10mm:90mm:17",
    "cone-on-plane": "half_angle=5deg:95deg:19",
    "bevel-gears": "gear_a.teeth=8:30:23",
}
GRIDS = {
    "thrust-bearing": ("contact_angle=5deg:44deg:12", "pitch_radius=0.4in:1.6in:9"),
    "disk-on-circle": ("disk_speed=100rpm:900rpm:5", "surface_speed=-10rad/s:10rad/s:4"),
    "cone-on-plane": ("half_angle=10deg:80deg:8", "spin_speed=1rev/s:5rev/s:3"),
    "bevel-gears": ("shaft_angle=30deg:150deg:7", "gear_b.teeth=12:40:8"),
}


def csv_rows(text):
    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.parametrize("kind", sorted(LINES))
def test_line_sweep_of_every_kind(cli, kind):
    run = cli("sweep", SPECS / f"{kind}.yaml", "--vary", LINES[kind], "--format", "csv")
    assert run.code == 0, run.err
    rows = csv_rows(run.out)
    assert len(rows) == int(LINES[kind].rsplit(":", 1)[1])
    header = list(rows[0])
    assert header[0].startswith("input.") and header[-1] == "reason"
    assert all("[" in name for name in header[:-1])


@pytest.mark.parametrize("kind", sorted(GRIDS))
def test_grid_sweep_of_every_kind(cli, kind):
    first, second = GRIDS[kind]
    run = cli("sweep", SPECS / f"{kind}.yaml", "--vary", first, "--vary", second, "-f", "json")
    assert run.code == 0, run.err
    points = [json.loads(line) for line in run.out.splitlines()]
    n1, n2 = (int(text.rsplit(":", 1)[1]) for text in (first, second))
    assert len(points) == n1 * n2
    assert all(set(p) == {"inputs", "results", "reason"} for p in points)
    table = cli("sweep", SPECS / f"{kind}.yaml", "--vary", first, "--vary", second)
    assert table.code == 0 and "impossible design" in table.out


def test_impossible_points_are_gaps_with_a_reason(cli):
    run = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "contact_angle=40deg:50deg:11",
              "-f", "csv")
    rows = csv_rows(run.out)
    by_angle = {round(math.degrees(float(r["input.contact_angle [rad]"]))): r for r in rows}
    assert by_angle[44]["reason"] == "" and by_angle[44]["spin_to_roll [1]"] != ""
    for angle in (45, 46, 50):
        assert "pure rolling needs 0 deg < θ < 45 deg" in by_angle[angle]["reason"]
        assert by_angle[angle]["spin_to_roll [1]"] == ""
    assert "nan" not in run.out.lower()


def test_every_csv_row_equals_solve_of_the_same_point(cli, tmp_path):
    spec = (SPECS / "thrust-bearing.yaml").read_text()
    run = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "contact_angle=20deg:40deg:9",
              "--vary", "pitch_radius=20mm:30mm:7", "-f", "csv")
    rows = csv_rows(run.out)
    assert len(rows) == 63
    for row in rows[::5]:
        angle, radius = row["input.contact_angle [rad]"], row["input.pitch_radius [m]"]
        text = spec.replace("contact_angle: 30 deg", f"contact_angle: {angle} rad").replace(
            "pitch_radius: 26 mm", f"pitch_radius: {radius} m")
        path = tmp_path / "point.yaml"
        path.write_text(text)
        (document,) = load_documents(path)
        if row["reason"]:
            with pytest.raises(Exception, match=r"ball_count|contact"):
                evaluate_document(document)
            continue
        solved = evaluate_document(document).results
        for key, value in solved.items():
            column = f"{key} [{evaluate_document(document).units[key]}]"
            assert float(row[column]) == pytest.approx(value, rel=1e-14, abs=1e-300), key


def test_integer_fields_step_by_integers(cli):
    run = cli("sweep", SPECS / "bevel-gears.yaml", "--vary", "gear_a.teeth=10:20:6", "-f", "csv")
    teeth = [row["input.gear_a.teeth [1]"] for row in csv_rows(run.out)]
    assert teeth == ["10", "12", "14", "16", "18", "20"]


@pytest.mark.parametrize(("spec", "vary", "fragment"), [
    ("thrust-bearing", "contact_angle=5:40:10", "has no unit"),
    ("thrust-bearing", "contact_angle=5mm:40mm:10", "'mm' is not a unit of angle"),
    ("thrust-bearing", "contact_angle=5deg:40deg:1", "N must be at least 2"),
    ("thrust-bearing", "contact_angel=5deg:40deg:10", "has no input 'contact_angel'"),
    ("thrust-bearing", "contact_angle:5deg:40deg", "write NAME=START:STOP:N"),
    ("thrust-bearing", "ball_radius=1mm:5mm:5", "leaves ball_radius out"),
    ("bevel-gears", "gear_a.pitch_angle=10deg:20deg:3", "leaves gear_a.pitch_angle out"),
    ("bevel-gears", "gear_a=1:2:3", "gear_a is a group of fields, not a number: vary one of "
     "its fields, like gear_a.teeth; its fields are teeth, pitch_radius, pitch_angle"),
    ("thrust-bearing", "shaft_speed=25Hz:50Hz:3", "'Hz' is not a unit of angular speed (it is "
     "a frequency"),
    ("thrust-bearing", "contact_angle=5deg%:40deg%:3", "percent is a unit on its own"),
    ("bevel-gears", "gear_a.teeth=10:12:5", "only 3 distinct values"),
])
def test_bad_vary_options_are_one_line_and_exit_2(cli, spec, vary, fragment):
    run = cli("sweep", SPECS / f"{spec}.yaml", "--vary", vary)
    assert run.code == 2
    assert fragment in run.err and run.err.count("\n") == 1, run.err


@pytest.mark.parametrize("speeds", ["1000r/min:2000r/min:3", "1000 1/min:2000 1/min:3",
                                    "1000min^-1:2000 min⁻¹:3", "1000RPM:2000 rev/min:3"])
def test_speed_notations_sweep_exactly_as_rpm(cli, speeds):
    rpm = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "shaft_speed=1000rpm:2000rpm:3",
              "-f", "csv")
    other = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", f"shaft_speed={speeds}",
                "-f", "csv")
    assert other.code == rpm.code == 0, other.err
    assert other.out == rpm.out
    speeds_si = [float(r["input.shaft_speed [rad/s]"]) for r in csv_rows(other.out)]
    assert speeds_si[0] == 1000 * (2 * math.pi / 60) and speeds_si[-1] == 2000 * (2 * math.pi / 60)


def test_a_field_left_out_to_be_solved_cannot_be_swept(cli, spec_file):
    text = (SPECS / "thrust-bearing.yaml").read_text().replace("pitch_radius: 26 mm", "")
    run = cli("sweep", spec_file(text), "--vary", "pitch_radius=20mm:30mm:5")
    assert run.code == 2 and "leaves pitch_radius out (it is solved" in run.err


def test_three_axes_and_unknown_result_are_refused(cli):
    spec = SPECS / "thrust-bearing.yaml"
    run = cli("sweep", spec, "--vary", "contact_angle=5deg:40deg:3", "--vary",
              "pitch_radius=20mm:30mm:3", "--vary", "shaft_speed=1rpm:2rpm:3")
    assert run.code == 2 and ("Invalid value for '--vary' / '-v': give it once for a line or "
                              "twice for a grid") in run.err
    run = cli("sweep", spec, "--vary", "contact_angle=5deg:40deg:3", "--result", "spin")
    assert run.code == 2 and "Invalid value for '--result' / '-r': 'spin'" in run.err


def test_a_failing_run_leaves_an_existing_output_alone(cli, tmp_path):
    out = tmp_path / "sweep.csv"
    out.write_text("earlier results\n")
    run = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "nope=1:2:3", "-o", out)
    assert run.code == 2 and out.read_text() == "earlier results\n"
    run = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "contact_angle=5deg:40deg:4",
              "-o", out)
    assert run.code == 0 and len(csv_rows(out.read_text())) == 4


@pytest.mark.parametrize("suffix", [".png", ".svg"])
@pytest.mark.parametrize("grid", [False, True])
def test_plots_are_valid_images(cli, tmp_path, suffix, grid):
    path = tmp_path / f"sweep{suffix}"
    vary = ["--vary", "contact_angle=5deg:44deg:40"]
    if grid:
        vary += ["--vary", "pitch_radius=20mm:40mm:30"]
    run = cli("sweep", SPECS / "thrust-bearing.yaml", *vary, "--plot", path, "-o",
              tmp_path / "out.csv")
    assert run.code == 0, run.err
    data = path.read_bytes()
    assert len(data) > 5000
    if suffix == ".png":
        from matplotlib.image import imread

        assert data.startswith(b"\x89PNG\r\n\x1a\n")
        height, width = imread(path).shape[:2]
        assert width > 600 and height > 400
    else:
        assert b"<svg" in data[:2000]


def test_sweep_values_are_evenly_spaced_in_si(cli):
    run = cli("sweep", SPECS / "disk-on-circle.yaml", "--vary", "disk_radius=0.5in:2.5in:5",
              "-f", "csv")
    radii = [float(r["input.disk_radius [m]"]) for r in csv_rows(run.out)]
    assert np.allclose(radii, np.linspace(0.0127, 0.0635, 5), rtol=1e-15)


def test_one_document_of_a_multi_document_file_is_picked_with_a_hash(cli, spec_file):
    text = (SPECS / "thrust-bearing.yaml").read_text() + "---\n" + (
        SPECS / "cone-on-plane.yaml").read_text()
    path = spec_file(text)
    run = cli("sweep", path, "--vary", "half_angle=10deg:20deg:3")
    assert run.code == 2 and "pick one as" in run.err and "#1 .. #2" in run.err
    run = cli("sweep", f"{path}#2", "--vary", "half_angle=10deg:20deg:3", "-f", "csv")
    assert run.code == 0 and len(csv_rows(run.out)) == 3
    run = cli("tolerance", f"{path}#3")
    assert run.code == 2 and "'#3' does not pick a document" in run.err


def _reference_csv_rows(sweep) -> str:
    """The CSV body as the first implementation wrote it, line by line in Python (kept
    here to pin the block writer to it, byte for byte)."""
    import orjson

    from bearingcalc.reports import _csv_text, _integer_fields, sweep_columns

    columns = sweep_columns(sweep)
    integer_axes = [axis.integer for axis in sweep.axes]
    out = []
    for row in range(len(sweep.status)):
        block = np.array([[values[row] for _, values in columns]], dtype=float)
        line = orjson.dumps(block, option=orjson.OPT_SERIALIZE_NUMPY)[2:-2].replace(
            b"null", b"")
        if any(integer_axes):
            line = _integer_fields(line, integer_axes)
        code = int(sweep.status[row])
        reason = ("," + _csv_text(sweep.reason(code))).encode() if code else b","
        out.append(line + reason + b"\n")
    return b"".join(out).decode()


@pytest.mark.parametrize("vary", [
    ("pitch_radius=5mm:40mm:60", "contact_angle=5deg:50deg:40"),
    ("pitch_radius=5mm:40mm:30", "ball_count=1:40:40"),
    ("contact_angle=0deg:45deg:91",),
])
def test_block_csv_writer_is_byte_identical_to_the_line_writer(vary):
    import io

    from bearingcalc.evaluation import load_one_spec
    from bearingcalc.reports import write_sweep_csv
    from bearingcalc.sweeps import parse_axis, run_sweep

    kind, spec, document = load_one_spec(SPECS / "thrust-bearing.yaml")
    solved = run_sweep(kind, spec, document.source, [parse_axis(v, spec) for v in vary])
    assert (solved.status != 0).any() and (solved.status == 0).any()
    stream = io.StringIO()
    write_sweep_csv(solved, stream)
    body = stream.getvalue().split("\n", 1)[1]
    assert body == _reference_csv_rows(solved)


@pytest.mark.parametrize("angles", ["20deg:40deg:70", "20deg:50deg:70"])
def test_block_csv_writer_with_unbounded_results(spec_file, angles):
    import io

    from bearingcalc.evaluation import load_one_spec
    from bearingcalc.reports import write_sweep_csv
    from bearingcalc.sweeps import parse_axis, run_sweep

    # ρ_max above tan(45° − θ): no upper pitch-radius edge, pitch_radius_max is +inf,
    # which orjson writes as null; with every design possible, and with the last
    # ones impossible (θ > 45°).
    path = spec_file((SPECS / "thrust-bearing.yaml").read_text().replace(
        "max_spin_to_roll: 0.01", "max_spin_to_roll: 0.5"))
    kind, spec, document = load_one_spec(path)
    solved = run_sweep(kind, spec, document.source,
                       [parse_axis(f"contact_angle={angles}", spec)])
    assert np.isinf(solved.results["pitch_radius_max"]).any()
    assert (solved.status[-1] != 0) == angles.startswith("20deg:50")
    stream = io.StringIO()
    write_sweep_csv(solved, stream)
    assert stream.getvalue().split("\n", 1)[1] == _reference_csv_rows(solved)


def test_csv_block_where_a_possible_row_looks_like_an_impossible_one():
    from bearingcalc.reports import _csv_block

    # Row 1 is possible, but its results (5.0 and no number) read like code 5's row.
    block = np.array([[1.0, 5.0, np.nan], [2.0, np.nan, np.nan], [3.0, 1.5, np.inf],
                      [4.0, np.nan, np.nan]])
    codes = np.array([0, 5, 0, 7])
    reasons = {5: b",too big", 7: b",too small"}
    assert b"".join(_csv_block(block, codes, 1, reasons)) == (
        b"1.0,5.0,,\n2.0,,,too big\n3.0,1.5,,\n4.0,,,too small\n")
    assert b"".join(_csv_block(block[1:], codes[1:], 1, reasons)) == (
        b"2.0,,,too big\n3.0,1.5,,\n4.0,,,too small\n")


def test_parquet_output_holds_the_csv_columns(cli, tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "grid.parquet"
    run = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "pitch_radius=10mm:30mm:5",
              "--vary", "ball_count=4:16:5", "-o", out)
    assert run.code == 0, run.err
    table = pq.read_table(out)
    csv_run = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "pitch_radius=10mm:30mm:5",
                  "--vary", "ball_count=4:16:5", "-f", "csv")
    header = csv_run.out.splitlines()[0].split(",")
    assert table.schema.names == header and table.num_rows == 25
    assert str(table.schema.field("input.ball_count [1]").type) == "int64"


def test_parquet_without_pyarrow_names_the_extra(cli, tmp_path, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "pyarrow", None)
    out = tmp_path / "grid.parquet"
    run = cli("sweep", SPECS / "thrust-bearing.yaml", "--vary", "pitch_radius=10mm:30mm:5",
              "-o", out)
    assert run.code == 2 and "bearingcalc[parquet]" in run.err and not out.exists()
