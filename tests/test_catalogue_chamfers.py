"""A catalogue's chamfers: a tapered roller bearing's cup chamfer (``cup_r_min``) is read
apart from its cone's (``r_min``), in SI; on a bearing with no cup it is refused in one
line naming the catalogue's line and column."""

from __future__ import annotations

from pathlib import Path

import pytest

from bearingcalc.catalogue.catalogue import load_catalogue

HEADER = ("designation,maker,type,bore_diameter [mm],outside_diameter [mm],width [mm],"
          "dynamic_load_rating [kN],static_load_rating [kN],e,y2,y0,r_min [mm],"
          "cup_r_min [mm],source\n")
#: HR 30211 J as NSK CAT. E1102e pp. B118-B119 prints it: cone chamfer 2 mm, cup 1.5 mm.
TAPERED = ("30211,NSK,tapered-roller,55,100,22.75,94.5,113,0.41,1.5,0.81,2,1.5,"
           "\"NSK, E1102e, pp. B118-B119\"\n")
BEARING = ("kind: rolling-bearing\ncatalogue: cat.csv\ndesignation: {designation}\n"
           "radial_load: 3 kN\naxial_load: 1 kN\nspeed: 1500 rpm\n"
           "lubrication: {{viscosity: 68 mm^2/s}}\ncontamination_factor: 0.5\n"
           "limits: {{min_rating_life: 5000 h, min_static_safety: 2}}\n")


def test_a_tapered_row_keeps_both_chamfers_apart_in_metres(tmp_path: Path):
    path = tmp_path / "cat.csv"
    path.write_text(HEADER + TAPERED.replace(",2,1.5,", ",2,1.5e0,"), encoding="utf-8")
    (row,) = load_catalogue(path).rows
    assert row.values["r_min"] == pytest.approx(2e-3, rel=1e-12)
    assert row.values["cup_r_min"] == pytest.approx(1.5e-3, rel=1e-12)


#: Rows refused for their cup_r_min before any of their numbers is used.
@pytest.mark.parametrize(("designation", "row"), [
    ("6205", "6205,SKF,deep-groove,25,52,15,14.8,7.8,,,,1,1,test input\n"),
    ("NU205", "NU205,SKF,cylindrical-roller,25,52,15,28.6,27,,,,1,0.6,test input\n"),
])
def test_a_cup_chamfer_on_a_bearing_without_a_cup_is_refused(cli, tmp_path, designation,
                                                             row):
    (tmp_path / "cat.csv").write_text(HEADER + TAPERED + row, encoding="utf-8")
    spec = tmp_path / "a.yaml"
    spec.write_text(BEARING.format(designation=designation), encoding="utf-8")
    run = cli("solve", spec)
    assert run.code == 2 and run.err.count("\n") == 1 and run.out == "", run.err
    assert "cat.csv:3: cup_r_min: " in run.err and "tapered-roller" in run.err, run.err


def test_a_tapered_row_with_its_cup_chamfer_solves(cli, tmp_path):
    (tmp_path / "cat.csv").write_text(HEADER + TAPERED, encoding="utf-8")
    spec = tmp_path / "a.yaml"
    spec.write_text(BEARING.format(designation="30211"), encoding="utf-8")
    assert cli("solve", spec).code in (0, 1)
