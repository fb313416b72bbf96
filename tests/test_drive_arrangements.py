"""kind: bevel-drive with adjusted bearing pairs (back-to-back, face-to-face) and roller
bearings: every axial load against an own implementation of the catalogue load-case
table, every radial load against an own 3-D balance of the shaft with the tooth forces
from the textbook formulas, ISO 281 P and L10, and the system life's Weibull slope."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from tests.conftest import ROOT, solve_json, study_status
from tests.test_load_cases import table as _table

DRIVE = (ROOT / "specs" / "bevel-drive.yaml").read_text()
TOLERANCED = (ROOT / "specs" / "tolerances" / "bevel-drive.yaml").read_text()
REL = 1e-9

# Catalogue bearings: a 7208 BEP (40 deg, as specs/ball-bearing-angular-contact.yaml) and
# a 30206 tapered roller bearing (C, C0, e, Y, Y0 of a maker's catalogue; tan α ≈ e/1.5).
ANGULAR = dict(type="angular-contact", alpha=40.0, c=36.5e3, c0=26e3,
               text="type: angular-contact, contact_angle: 40 deg, dynamic_load_rating: "
                    "36.5 kN,\n     static_load_rating: 26 kN, bore_diameter: 40 mm, "
                    "outside_diameter: 80 mm")
TAPERED = dict(type="tapered-roller", alpha=14.0, c=50.1e3, c0=63e3, e=0.37, y=1.6, y0=0.9,
               text="type: tapered-roller, contact_angle: 14 deg, dynamic_load_rating: "
                    "50.1 kN,\n     static_load_rating: 63 kN, load_factors: {e: 0.37, y: 1.6, "
                    "y0: 0.9}, bore_diameter: 30 mm, outside_diameter: 62 mm")
# The same without catalogue factors: ISO 281's e = 1.5·tanα, Y = 0.4·cotα, Y0 = 0.22·cotα.
TAPERED_ISO = dict(TAPERED, e=1.5 * math.tan(math.radians(14)),
                   y=0.4 / math.tan(math.radians(14)), y0=0.22 / math.tan(math.radians(14)),
                   text=TAPERED["text"].replace(" load_factors: {e: 0.37, y: 1.6, y0: 0.9},", ""))
SPEED_RPM = {"pinion": 1500.0, "gear": 1500.0 * 20 / 43}
POSITIONS = {"pinion": (0.090, 0.150), "gear": (0.020, 0.120)}


def _drive(pinion=None, gear=None, base=DRIVE):
    """The example drive with a shaft's two bearing entries replaced: (arrangement,
    [(position text, bearing), (position text, bearing)]) per shaft."""
    text = base
    for shaft, new in (("pinion", pinion), ("gear", gear)):
        if new is None:
            continue
        start = text.index("\n", text.index(f"{shaft}_bearings:")) + 1
        second = text.index("  - {", text.index("  - {", start) + 1)
        end = text.index("\n", text.index("\n", second) + 1) + 1  # two lines an entry
        arrangement, entries = new
        body = "".join(f"  - {{position: {pos}, {b['text']}}}\n" for pos, b in entries)
        if arrangement != "locating-floating":
            body += f"{shaft}_arrangement: {arrangement}\n"
        text = text[:start] + body + text[end:]
    return text


def _tooth_forces(torque=60.0):
    """Straight bevel 20/43, m 3 mm, b 20 mm, φ 20°, shafts at 90° (Shigley Eq. 13-38):
    Wt = T/r_m at the mean pitch radius; on each gear Wr = Wt·tanφ·cosγ toward its axis,
    Wa = Wt·tanφ·sinγ along its axis away from the apex. Per shaft: (x_p, r_p, Wt, Wr, Wa)."""
    gamma_1 = math.atan2(20, 43)
    wt = torque / (0.003 * 20 / 2 - 0.010 * math.sin(gamma_1))  # r_m = d/2 − (b/2)·sinγ
    tan_phi = math.tan(math.radians(20))
    out = {}
    for shaft, z, gamma in (("pinion", 20, gamma_1), ("gear", 43, math.pi / 2 - gamma_1)):
        r_mean = 0.003 * z / 2 - 0.010 * math.sin(gamma)
        out[shaft] = (r_mean / math.tan(gamma), r_mean, wt, wt * tan_phi * math.cos(gamma),
                      wt * tan_phi * math.sin(gamma))
    return out


def _radial_3d(x1, x2, xp, rp, wt, wr, wa):
    """Radial loads of two simple supports from a 3-D force and moment balance of the rigid
    shaft (numpy.linalg; unknowns: both supports' y and z reactions, one axial reaction on
    the axis, which has no moment about it, and the driving torque)."""
    point, force = np.array([xp, rp, 0.0]), np.array([wa, -wr, wt])
    cols = []
    for x in (x1, x2):
        for k in (1, 2):
            unit = np.eye(3)[k]
            cols.append(np.concatenate([unit, np.cross([x, 0.0, 0.0], unit)]))
    cols.append(np.concatenate([np.eye(3)[0], np.zeros(3)]))
    cols.append(np.concatenate([np.zeros(3), np.eye(3)[0]]))
    sol = np.linalg.solve(np.array(cols).T, -np.concatenate([force, np.cross(point, force)]))
    return math.hypot(sol[0], sol[1]), math.hypot(sol[2], sol[3])


def _supports_plus_x(x_self, x_other, arrangement):
    """Whether a bearing resists shaft forces toward +x. Its contact line runs from its
    pressure centre on the axis out to the rolling element, and the inner ring pushes the
    element outward along it, so the element pushes the shaft back along the line toward
    the pressure centre. Back-to-back, the centres lie outside the pair: for the bearing
    at the smaller x the element is at larger x than its centre, so it pushes the shaft
    toward −x, i.e. it carries forces toward +x. Face-to-face, the centres lie between
    the bearings and everything mirrors: the bearing at the larger x carries +x."""
    smaller = x_self < x_other
    return smaller if arrangement == "back-to-back" else not smaller


def _r(bearing, alpha=None):
    """R: 0.5/Y for tapered rollers; the makers' 20/25/30/40 deg table for balls."""
    if bearing["type"] == "tapered-roller":
        return 0.5 / bearing["y"]
    return float(np.interp(bearing["alpha"] if alpha is None else alpha,
                           [20, 25, 30, 40], [0.50, 0.57, 0.66, 0.88]))


def _expected_shaft(shaft, arrangement, entries, ka):
    """(Fr, Fa, R, case) per bearing from the own statics and table."""
    xp, rp, wt, wr, wa = _tooth_forces()[shaft]
    xs = [x for x, _ in entries]
    fr = _radial_3d(*xs, xp, rp, wt, wr, wa)
    ra, rb = (_r(b) for _, b in entries)
    to_b = _supports_plus_x(xs[1], xs[0], arrangement) == (ka >= 0)
    fa_a, fa_b, case = _table(fr[0], fr[1], ra, rb, abs(ka), to_b)
    return fr, (fa_a, fa_b), (ra, rb), case


def _iso_p_and_p0(b, fr, fa):
    """ISO 281 P and ISO 76 P0, single row: 40 deg balls e 1.14, X 0.35, Y 0.57, Y0 0.26;
    tapered X 0.4 and the catalogue (or ISO) e, Y, Y0."""
    e, x, y, y0 = (1.14, 0.35, 0.57, 0.26) if b["type"] == "angular-contact" else (
        b["e"], 0.4, b["y"], b["y0"])
    p = fr if fa / fr <= e else x * fr + y * fa
    return p, max(fr, 0.5 * fr + y0 * fa)


def _check_adjusted(r, shaft, arrangement, entries):
    ka = r[f"gear_{'a' if shaft == 'pinion' else 'b'}_axial_force"]
    assert ka == pytest.approx(_tooth_forces()[shaft][4], rel=REL)
    fr, fa, factors, case = _expected_shaft(shaft, arrangement, entries, ka)
    for i, (_, b) in enumerate(entries):
        name = f"{shaft}_bearing_{i + 1}"
        assert r[f"{name}_radial_load"] == pytest.approx(fr[i], rel=REL), name
        assert r[f"{name}_axial_load"] == pytest.approx(fa[i], rel=REL), name
        assert r[f"{name}_induced_axial_load"] == pytest.approx(factors[i] * fr[i], rel=REL)
        assert r[f"{name}_load_case"] == case, name
        assert r[f"{name}_axial_load"] >= factors[i] * fr[i] * (1 - REL) > 0
        p, p0 = _iso_p_and_p0(b, fr[i], fa[i])
        power = 3.0 if b["type"] == "angular-contact" else 10.0 / 3.0
        assert r[f"{name}_equivalent_dynamic_load"] == pytest.approx(p, rel=REL), name
        assert r[f"{name}_static_safety_factor"] == pytest.approx(b["c0"] / p0, rel=REL), name
        assert r[f"{name}_basic_rating_life"] == pytest.approx(
            (b["c"] / p) ** power * 1e6 / (SPEED_RPM[shaft] / 60), rel=REL), name
    # The shaft's axial balance: the bearing Ka pushes into carries Ka more than the other.
    assert abs(fa[1] - fa[0]) == pytest.approx(abs(ka), rel=REL)
    return case


def _check_system(r, roller):
    for kind in ("basic", "modified"):
        lives = [r[f"{s}_bearing_{i}_{kind}_rating_life"] for s in ("pinion", "gear")
                 for i in (1, 2)]
        slope, other = (9 / 8, 10 / 9) if roller else (10 / 9, 9 / 8)
        total = sum(life ** -slope for life in lives) ** (-1 / slope)
        wrong = sum(life ** -other for life in lives) ** (-1 / other)
        assert r[f"system_{kind}_rating_life"] == pytest.approx(total, rel=REL)
        assert abs(wrong / total - 1) > 1e-4  # the two slopes are told apart


def _solve(cli, spec_file, text):
    (record,) = solve_json(cli, spec_file(text))
    return record["results"]


# -- whole drives ------------------------------------------------------------------------

def test_forty_degree_angular_contact_back_to_back_on_the_pinion(cli, spec_file):
    r = _solve(cli, spec_file, _drive(pinion=("back-to-back", [("90 mm", ANGULAR),
                                                                ("150 mm", ANGULAR)])))
    for i in (1, 2):
        fr = r[f"pinion_bearing_{i}_radial_load"]
        assert r[f"pinion_bearing_{i}_axial_load"] >= 0.88 * fr * (1 - REL) > 0
    _check_adjusted(r, "pinion", "back-to-back", [(0.090, ANGULAR), (0.150, ANGULAR)])
    _check_system(r, roller=False)


DRIVES = {
    "angular face-to-face": (("face-to-face", ANGULAR), None, False),
    "angular both shafts": (("face-to-face", ANGULAR), ("back-to-back", ANGULAR), False),
    "tapered back-to-back, gear face-to-face": (("back-to-back", TAPERED),
                                                ("face-to-face", TAPERED), True),
    "tapered face-to-face, gear ISO factors back-to-back": (
        ("face-to-face", TAPERED), ("back-to-back", TAPERED_ISO), True),
    "tapered back-to-back, written far bearing first": (("back-to-back", TAPERED), None, True),
}


@pytest.mark.parametrize("name", list(DRIVES))
def test_adjusted_drives_against_statics_and_table(cli, spec_file, name):
    pinion, gear, roller = DRIVES[name]
    changes, seen = {}, []
    for shaft, new in (("pinion", pinion), ("gear", gear)):
        if new is not None:
            xs = POSITIONS[shaft][::-1] if "far bearing first" in name else POSITIONS[shaft]
            changes[shaft] = (new[0], [(x, new[1]) for x in xs])
    r = _solve(cli, spec_file, _drive(**{shaft: (arr, [(f"{x * 1000:g} mm", b) for x, b in e])
                                         for shaft, (arr, e) in changes.items()}))
    for shaft, (arrangement, entries) in changes.items():
        seen.append(_check_adjusted(r, shaft, arrangement, entries))
    _check_system(r, roller)
    if "far bearing first" in name:
        # The bearing at 90 mm carries 0.5·Fr/Y whichever is written first (case 1c).
        assert seen == [3]
        assert r["pinion_bearing_2_axial_load"] == pytest.approx(
            0.5 / 1.6 * r["pinion_bearing_2_radial_load"], rel=REL)


def test_cylindrical_floating_and_deep_groove_locating(cli, spec_file):
    cylindrical = dict(text="type: cylindrical-roller, dynamic_load_rating: 44 kN,\n"
                            "     static_load_rating: 36.5 kN, bore_diameter: 30 mm, "
                            "outside_diameter: 62 mm")
    locating = dict(text="locating: true, type: deep-groove, dynamic_load_rating: 20.3 kN,\n"
                         "     static_load_rating: 11.2 kN, static_factor: 14, bore_diameter: "
                         "30 mm, outside_diameter: 62 mm")
    r = _solve(cli, spec_file, _drive(gear=("locating-floating", [("20 mm", cylindrical),
                                                                   ("120 mm", locating)])))
    for shaft, locating_index in (("pinion", 1), ("gear", 2)):
        xp, rp, wt, wr, wa = _tooth_forces()[shaft]
        fr = _radial_3d(*POSITIONS[shaft], xp, rp, wt, wr, wa)
        for i in (1, 2):
            name = f"{shaft}_bearing_{i}"
            assert r[f"{name}_radial_load"] == pytest.approx(fr[i - 1], rel=REL)
            assert r[f"{name}_axial_load"] == pytest.approx(
                wa if i == locating_index else 0.0, rel=REL, abs=0.0)
    # The cylindrical roller bearing: P = Fr, L10 = (C/P)^(10/3) revolutions.
    p = r["gear_bearing_1_radial_load"]
    assert r["gear_bearing_1_equivalent_dynamic_load"] == pytest.approx(p, rel=REL)
    assert r["gear_bearing_1_basic_rating_life"] == pytest.approx(
        (44e3 / p) ** (10 / 3) * 1e6 / (SPEED_RPM["gear"] / 60), rel=REL)
    _check_system(r, roller=True)


# -- sweep, tolerance study ---------------------------------------------------------------

@pytest.mark.parametrize("xs", [(0.090, 0.150), (0.020, 0.110)], ids=["overhung", "straddled"])
def test_sweep_of_the_contact_angle_is_continuous(cli, spec_file, xs):
    entries = [(f"{x * 1000:g} mm", ANGULAR) for x in xs]
    run = cli("sweep", spec_file(_drive(pinion=("back-to-back", entries))), "--vary",
              "pinion_bearings.1.contact_angle=20 deg:40 deg:81", "--format", "csv")
    assert run.code in (0, 1), run.err
    rows = list(csv.DictReader(io.StringIO(run.out)))
    assert len(rows) == 81
    alpha = np.degrees([float(row["input.pinion_bearings.1.contact_angle [rad]"])
                        for row in rows])
    col = {key: np.array([float(row[f"pinion_bearing_{key} [{unit}]"]) for row in rows])
           for key, unit in (("1_axial_load", "N"), ("2_axial_load", "N"), ("1_radial_load", "N"),
                             ("2_radial_load", "N"), ("1_load_case", "1"))}
    xp, rp, wt, wr, wa = _tooth_forces()["pinion"]
    fr = _radial_3d(*xs, xp, rp, wt, wr, wa)  # pressure centres fixed: Fr does not vary
    np.testing.assert_allclose(col["1_radial_load"], fr[0], rtol=REL)
    np.testing.assert_allclose(col["2_radial_load"], fr[1], rtol=REL)
    to_b = _supports_plus_x(xs[1], xs[0], "back-to-back")  # Wa acts toward +x
    expected = np.array([_table(*fr, _r(ANGULAR, a), 0.88, wa, to_b) for a in alpha])
    np.testing.assert_allclose(col["1_axial_load"], expected[:, 0], rtol=REL)
    np.testing.assert_allclose(col["2_axial_load"], expected[:, 1], rtol=REL)
    np.testing.assert_array_equal(col["1_load_case"], expected[:, 2])
    if xs[0] == 0.020:
        assert len(set(col["1_load_case"])) >= 2  # the sweep crosses a case boundary
    # Continuity: no step exceeds the steepest R slope (0.022 per degree) times Fr_A.
    step = alpha[1] - alpha[0]
    bound = 0.022 * step * fr[0] * (1 + 1e-6)
    nodes = {25.0, 30.0}  # kinks of the makers' R table
    for key in ("1_axial_load", "2_axial_load"):
        values = col[key]
        assert np.max(np.abs(np.diff(values))) <= bound, key
        second = values[:-2] - 2 * values[1:-1] + values[2:]
        for i in np.flatnonzero(np.abs(second) > 1e-6 * values.max()):
            window = col["1_load_case"][i:i + 3]
            at_node = any(abs(alpha[i + 1] - node) < 1e-9 for node in nodes)
            assert at_node or len(set(window)) > 1, (key, alpha[i + 1])


def test_tolerance_study_of_a_tapered_drive(cli, spec_file):
    text = _drive(pinion=("back-to-back", [("90 mm", TAPERED), ("150 mm ± 0.5 mm", TAPERED)]),
                  base=TOLERANCED)
    run = cli("tolerance", spec_file(text), "-n", "2000", "--seed", "7", "-f", "json")
    assert run.code in (0, 1), run.err
    record = json.loads(run.out)
    assert run.code == study_status(record)
    _, fa, _, case = _expected_shaft("pinion", "back-to-back",
                                      [(0.090, TAPERED), (0.150, TAPERED)],
                                      _tooth_forces()["pinion"][4])
    for i in (1, 2):
        entry = record["results"][f"pinion_bearing_{i}_axial_load"]
        assert entry["nominal"] == pytest.approx(fa[i - 1], rel=REL)
        # Every force scales with the torque, and ±0.5 mm barely moves the margin: one case.
        cases = record["results"][f"pinion_bearing_{i}_load_case"]["monte_carlo"]
        assert cases["min"] == cases["max"] == case


# -- refusals -----------------------------------------------------------------------------

ANGULAR_15 = dict(text="type: angular-contact, contact_angle: 15 deg, dynamic_load_rating: "
                       "36.5 kN,\n     static_load_rating: 26 kN, load_factors: {e: 0.5, x: 0.44, "
                       "y: 1.12, x0: 0.5, y0: 0.46}, bore_diameter: 40 mm, outside_diameter: "
                       "80 mm")
DEEP_GROOVE = dict(text="type: deep-groove, dynamic_load_rating: 23.4 kN,\n     "
                        "static_load_rating: 11.6 kN, static_factor: 12, bore_diameter: 25 mm, "
                        "outside_diameter: 62 mm")
REFUSED = {
    "locating given": (dict(text="locating: true, " + ANGULAR["text"]),
                       "pinion_bearings.1.locating"),
    "locating false given": (dict(text="locating: false, " + ANGULAR["text"]),
                             "pinion_bearings.1.locating"),
    "deep-groove": (DEEP_GROOVE, "pinion_bearings.1.type"),
    "15 deg without R": (ANGULAR_15, "pinion_bearings.1.induced_axial_factor"),
}


@pytest.mark.parametrize("name", list(REFUSED))
def test_adjusted_arrangement_refusals(cli, spec_file, name):
    first, field = REFUSED[name]
    path = spec_file(_drive(pinion=("back-to-back", [("90 mm", first), ("150 mm", ANGULAR)])))
    run = cli("solve", path)
    assert run.code == 2, run.out
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and field in lines[0], run.err
    assert lines[0].startswith(f"{path}:") and "internal error" not in run.err


def test_induced_axial_factor_overrides_the_table(cli, spec_file):
    given = dict(text=ANGULAR_15["text"].replace("contact_angle", "induced_axial_factor: 0.4, "
                                                 "contact_angle"))
    r = _solve(cli, spec_file, _drive(pinion=("back-to-back", [("90 mm", given),
                                                                ("150 mm", ANGULAR)])))
    fr = r["pinion_bearing_1_radial_load"]
    assert r["pinion_bearing_1_induced_axial_load"] == pytest.approx(0.4 * fr, rel=REL)
    ka = r["gear_a_axial_force"]
    fa, _, case = _table(fr, r["pinion_bearing_2_radial_load"], 0.4, 0.88, ka,
                         _supports_plus_x(0.150, 0.090, "back-to-back") == (ka >= 0))
    assert r["pinion_bearing_1_axial_load"] == pytest.approx(fa, rel=REL)
    assert r["pinion_bearing_1_load_case"] == case
