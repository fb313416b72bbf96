"""A value that the catalogue gives a spec and the spec refuses is said at the spec's
`catalogue:` (or the bearing's designation) with the catalogue's own file, row line and
column; a `catalogue:` written inside a drive's bearing is said to belong at the top."""

from __future__ import annotations

from tests.conftest import ROOT

EXAMPLE = (ROOT / "specs" / "catalogues" / "example.csv").read_text(encoding="utf-8")
SPEC = """kind: rolling-bearing
name: 6205 from the catalogue
{catalogue}designation: '6205'
maker: SKF
radial_load: 2 kN
speed: 1500 rpm
"""


def _catalogue_with_implausible_rating(folder) -> tuple[str, int]:
    lines = EXAMPLE.splitlines()
    row = next(i for i, line in enumerate(lines) if line.startswith("6205,SKF,"))
    cells = lines[row].split(",")
    cells[6] = "1e12"  # dynamic_load_rating [kN]
    lines[row] = ",".join(cells)
    (folder / "bearings.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    return "bearings.csv", row + 1


def test_a_refused_catalogue_value_names_the_catalogue_row_and_column(cli, tmp_path,
                                                                      spec_file):
    name, line = _catalogue_with_implausible_rating(tmp_path)
    path = spec_file(SPEC.format(catalogue=f"catalogue: {name}\n"))
    run = cli("solve", path)
    assert run.code == 2
    assert run.err == (f"{path}:3: catalogue: {tmp_path / name}:{line}: dynamic_load_rating: "
                       f"6205 (SKF): {run.err.split(': 6205 (SKF): ', 1)[1]}"), run.err
    assert "1e12 kN" in run.err and run.err.count("\n") == 1


def test_without_catalogue_key_the_designation_line_is_blamed(cli, tmp_path, spec_file):
    name, line = _catalogue_with_implausible_rating(tmp_path)
    path = spec_file(SPEC.format(catalogue=""))
    run = cli("solve", path, "--catalogue", str(tmp_path / name))
    assert run.code == 2
    assert run.err.startswith(f"{path}:3: designation: {tmp_path / name}:{line}: "
                              "dynamic_load_rating: 6205 (SKF): "), run.err


def test_catalogue_inside_a_drive_bearing_belongs_at_the_top(cli, spec_file):
    text = (ROOT / "specs" / "bevel-drive.yaml").read_text(encoding="utf-8")
    first = "gear_bearings:                 # 6206s, straddling the gear\n  - {"
    assert first in text
    spec = text.replace(first, first + "catalogue: bearings.csv, designation: '6206', ")
    run = cli("solve", spec_file(spec))
    assert run.code == 2
    assert run.err.count("\n") == 1, run.err
    assert "gear_bearings.1.catalogue: unknown key 'catalogue' here" in run.err, run.err
