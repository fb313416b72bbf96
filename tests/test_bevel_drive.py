"""kind: bevel-drive: each shaft's statics against a 3-D force and moment balance, the
system life's bounds, and the CLI (the bearings' loads and lives from published numbers:
tests/test_bevel_drive_independent.py)."""

from __future__ import annotations

import itertools
import json
import math

import numpy as np
import pytest

from bearingcalc.core.bearing_life import system_life
from bearingcalc.core.bevel_drive import shaft_reactions
from tests.conftest import ROOT, csv_column, solve_json

DRIVE = (ROOT / "specs" / "bevel-drive.yaml").read_text()


def _three_d_balance(x1, x2, locating, xp, rp, wt, wr, wa):
    """Unknowns: the two bearings' reactions (y, z each), the locating bearing's axial
    reaction and the driving torque about the axis. Equations: force and moment balance
    of the rigid shaft as 3-D vectors, solved by numpy.linalg; nothing from the closed
    form. The shaft axis is x; the mean pitch point is at (xp, rp, 0); the gear force is
    (wa, −wr, wt): along the axis away from the apex, toward the axis, tangential."""
    point = np.array([xp, rp, 0.0])
    force = np.array([wa, -wr, wt])
    supports = [np.array([x1, 0.0, 0.0]), np.array([x2, 0.0, 0.0])]
    columns, names = [], []
    for j, where in enumerate(supports):
        for axis in (1, 2):
            unit = np.zeros(3)
            unit[axis] = 1.0
            columns.append(np.concatenate([unit, np.cross(where, unit)]))
            names.append((j, axis))
    unit_x = np.array([1.0, 0.0, 0.0])
    columns.append(np.concatenate([unit_x, np.cross(supports[locating], unit_x)]))
    columns.append(np.concatenate([np.zeros(3), unit_x]))       # the driving torque
    matrix = np.array(columns).T
    rhs = -np.concatenate([force, np.cross(point, force)])
    solution = np.linalg.solve(matrix, rhs)
    radial = [math.hypot(solution[2 * j], solution[2 * j + 1]) for j in (0, 1)]
    return radial, abs(solution[4]), abs(solution[5])


def test_shaft_statics_match_a_3d_balance_over_random_layouts():
    rng = np.random.default_rng(11)
    for _ in range(3000):
        x1, x2 = rng.uniform(-0.3, 0.3, 2)
        if abs(x2 - x1) < 0.01:
            continue
        xp, rp = rng.uniform(0.01, 0.2), rng.uniform(0.005, 0.15)
        wt, wr, wa = rng.uniform(10, 5000, 3)
        locating = int(rng.integers(2))
        radial, axial, torque = _three_d_balance(x1, x2, locating, xp, rp, wt, wr, wa)
        r1, r2 = shaft_reactions((x1, x2), xp, rp, wt, wr, wa)
        assert float(r1) == pytest.approx(radial[0], rel=1e-9, abs=1e-9 * wt)
        assert float(r2) == pytest.approx(radial[1], rel=1e-9, abs=1e-9 * wt)
        assert axial == pytest.approx(wa, rel=1e-12)
        assert torque == pytest.approx(wt * rp, rel=1e-12)


def test_straddle_and_overhung_by_hand():
    # Straddled midway with no axial force: each bearing takes half.
    r1, r2 = shaft_reactions((0.0, 0.2), 0.1, 0.05, 1000.0, 0.0, 0.0)
    assert float(r1) == pytest.approx(500.0) and float(r2) == pytest.approx(500.0)
    # Overhung: supports at 0.1 and 0.2, load at 0: the near bearing takes twice the load
    # and the far one pulls back with the load itself.
    r1, r2 = shaft_reactions((0.1, 0.2), 0.0, 0.05, 1000.0, 0.0, 0.0)
    assert float(r1) == pytest.approx(2000.0) and float(r2) == pytest.approx(1000.0)


def test_system_life_bounds():
    lives = [np.array([1000.0, 5e4]), np.array([3000.0, 5e4]), np.array([2e4, 5e4])]
    total = system_life(lives)
    assert np.all(total <= np.min(lives, axis=0))
    assert float(system_life([np.array(1234.5)])) == pytest.approx(1234.5, rel=1e-15)
    # n equal bearings: L·n^(−9/10)
    assert float(system_life([np.array(1000.0)] * 4)) == pytest.approx(1000 * 4 ** -0.9,
                                                                        rel=1e-14)


# Each bearing's loads and lives against values computed without the solver's code:
# tests/test_bevel_drive_independent.py.


def test_the_whole_chain_in_every_format(cli):
    for fmt in ("table", "json", "csv"):
        run = cli("solve", ROOT / "specs" / "bevel-drive.yaml", "-f", fmt)
        assert run.code == 0, run.err
        assert "pinion_bearing_2" in run.out and "system_modified_rating_life" in run.out
        if fmt == "table":
            assert "pinion shaft bearings" in run.out and "gear shaft bearings" in run.out
            assert "weakest bearing: pinion_bearing_1" in run.out
    (record,) = solve_json(cli, ROOT / "specs" / "bevel-drive.yaml")
    assert any(w.startswith("weakest bearing: ") for w in record["warnings"])
    assert all(isinstance(v, float) for v in record["results"].values())
    r = record["results"]
    lives = [r[f"{s}_bearing_{i}_modified_rating_life"] for s in ("pinion", "gear")
             for i in (1, 2)]
    assert r["system_modified_rating_life"] < min(lives)
    assert r["gear_speed"] == pytest.approx(1500 * 2 * math.pi / 60 * 20 / 43, rel=1e-15)


def test_check_fails_a_drive_by_its_weakest_bearing(cli, spec_file):
    run = cli("check", spec_file(DRIVE.replace("min_rating_life: 4000 h",
                                               "min_rating_life: 20000 h")), "-f", "json")
    record = json.loads(run.out)
    assert run.code == 1 and record["status"] == "fail"
    assert record["margins"]["life_margin"] < 0
    assert any("weakest bearing: pinion_bearing_1" in m for m in record["messages"])


def test_sweep_of_the_bearing_spacing(cli, tmp_path):
    plot = tmp_path / "spacing.png"
    run = cli("sweep", ROOT / "specs" / "bevel-drive.yaml", "--vary",
              "pinion_bearings.2.position=110mm:250mm:15", "-r", "system_modified_rating_life",
              "--plot", plot, "-f", "csv")
    assert run.code == 0, run.err
    assert run.out.startswith("input.pinion_bearings.2.position [m],")
    lives = csv_column(run.out, "system_modified_rating_life [s]")
    assert all(b > a for a, b in itertools.pairwise(lives))  # a wider span helps
    assert plot.read_bytes().startswith(b"\x89PNG")


def test_tolerance_gives_the_system_life_yield(cli):
    run = cli("tolerance", ROOT / "specs" / "tolerances" / "bevel-drive.yaml", "-n", "4096",
              "-r", "system_modified_rating_life", "-f", "json")
    assert run.code == 1, run.err  # the yield is below 1: some samples fail the life
    record = json.loads(run.out)
    assert 0 < record["yield"] < 1
    assert set(record["inputs"]) == {"torque", "pinion_bearings.2.position"}


BAD = [
    (("  - {position: 150 mm, type: deep-groove, dynamic_load_rating: 23.4 kN,\n"
      "     static_load_rating: 11.6 kN, static_factor: 12, bore_diameter: 25 mm, "
      "outside_diameter: 62 mm}\n"), "", "exactly two bearings, got 1"),
    (("position: 150 mm", "position: 90 mm"), None, "at the same position"),
    (("{position: 90 mm, locating: true", "{position: 90 mm, locating: false"), None,
     "exactly one bearing of a shaft is locating"),
    (("{position: 20 mm, type: deep-groove", "{position: 20 mm, locating: true, type: "
      "deep-groove"), None, "exactly one bearing of a shaft is locating"),
    (("{position: 20 mm, type: deep-groove", "{position: 20 mm, type: thrust"), None,
     "a thrust bearing takes no radial load"),
    (("{position: 20 mm, type: deep-groove", "{position: 20 mm, radial_load: 1 kN, type: "
      "deep-groove"), None, "a drive's bearing takes no"),
    (("{position: 20 mm, type: deep-groove", "{position: 20 mm, speed: 10 rpm, type: "
      "deep-groove"), None, "a drive's bearing takes no"),
    (("static_factor: 12, bore", "static_factor: 12, ball_diameter: -3 mm, bore"), None,
     "must be greater than zero"),
    (("module: 3 mm", "module: 3 mm\nface_width: 40 mm"), None, "duplicate key"),
    (("face_width: 20 mm", "face_width: 45 mm"), None, "less than half the outer cone"),
    (("torque: 60 N*m", "torque: 60 N*m\npower: 9 kW"), None, "not both"),
    (("torque: 60 N*m", ""), None, "needs a load"),
    (("input_speed: 1500 rpm", "input_speed: 0 rpm"), None, "must not be zero"),
]


@pytest.mark.parametrize(("change", "_", "fragment"), BAD, ids=[f"bad{i}" for i in range(len(BAD))])
def test_bad_drive_input_is_one_clear_line(cli, spec_file, change, _, fragment):
    text = DRIVE.replace(change, "", 1) if isinstance(change, str) else DRIVE.replace(*change, 1)
    assert text != DRIVE
    path = spec_file(text)
    run = cli("solve", path)
    assert run.code == 2 and fragment in run.err, run.err
    assert run.err.startswith(f"{path}:") and "internal error" not in run.err


def test_a_bearing_error_points_at_its_line_inside_the_list(cli, spec_file):
    text = DRIVE.replace("{position: 20 mm, type: deep-groove", "{position: 20 mm, type: thrust")
    path = spec_file(text)
    run = cli("solve", path)
    line = next(i for i, row in enumerate(text.splitlines(), 1) if "type: thrust" in row)
    assert run.err.startswith(f"{path}:{line}: gear_bearings.1.type:"), run.err
