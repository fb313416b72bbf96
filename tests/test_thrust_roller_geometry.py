"""Thrust roller bearings rated from their geometry (kind: rolling-bearing): Ca by ISO
281:2007 8.1 with fc from Table 10 and bm from Table 9 (both as printed in GOST
18855-2013, entered in tests/test_iso281_tables.py), the rule for rows (8.1.2, eq. 19)
and C0a by ISO 76:2006, each written here; through the solver and through a spec."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from bearingcalc.core import roller_bearing_contacts as rbc
from bearingcalc.core import roller_ratings as rr
from tests.conftest import ROOT, solve_json
from tests.test_iso281_tables import GAMMA, GOST_TABLE_10_ANGLED, GOST_TABLE_10_RIGHT

REL = 1e-12
#: GOST 18855-2013 Table 9 (ISO 281 Table 1, thrust roller bearings): bm.
TABLE_9 = {"thrust-cylindrical-roller": 1.00, "thrust-tapered-roller": 1.10,
           "thrust-spherical-roller": 1.15}


def fc_of_table_10(gamma: float, alpha_deg: float) -> float:
    """Linear interpolation in the printed column of α (nan outside it)."""
    if alpha_deg == 90:
        column = GOST_TABLE_10_RIGHT
    else:
        column = GOST_TABLE_10_ANGLED[50 if alpha_deg < 60 else 65 if alpha_deg < 75 else 80]
    xs = GAMMA[:len(column)]
    if not xs[0] <= gamma <= xs[-1]:
        return math.nan
    return float(np.interp(gamma, xs, column))


def ca_iso(kind: str, z: int, dwe: float, lwe: float, dpw: float, alpha_deg: float) -> float:
    """ISO 281 eqs. (17) and (18), N and mm: Ca = bm·fc·Lwe^(7/9)·Z^(3/4)·Dwe^(29/27)
    at 90°, bm·fc·(Lwe·cosα)^(7/9)·tanα·Z^(3/4)·Dwe^(29/27) below."""
    a = math.radians(alpha_deg)
    if alpha_deg == 90:
        fc = fc_of_table_10(dwe / dpw, 90)
        return TABLE_9[kind] * fc * lwe ** (7 / 9) * z ** 0.75 * dwe ** (29 / 27)
    fc = fc_of_table_10(dwe * math.cos(a) / dpw, alpha_deg)
    return (TABLE_9[kind] * fc * (lwe * math.cos(a)) ** (7 / 9) * math.tan(a) * z ** 0.75
            * dwe ** (29 / 27))


def c0a_iso(z: int, dwe: float, lwe: float, dpw: float, alpha_deg: float) -> float:
    """ISO 76: C0a = 220·(1 − Dwe·cosα/Dpw)·Z·Lwe·Dwe·sinα; 220·Z·Lwe·Dwe at 90°."""
    a = math.radians(alpha_deg)
    if alpha_deg == 90:
        return 220 * z * lwe * dwe
    return 220 * (1 - dwe * math.cos(a) / dpw) * z * lwe * dwe * math.sin(a)


GEOMETRIES = [  # (type, Z, Dwe, Lwe, Dpw [mm], α [deg])
    ("thrust-cylindrical-roller", 15, 5.0, 5.0, 43.5, 90.0),    # an 81107-size cage
    ("thrust-cylindrical-roller", 20, 8.0, 10.0, 80.0, 90.0),   # γ = 0.10, on a row
    ("thrust-cylindrical-roller", 40, 2.0, 6.0, 210.0, 90.0),   # γ just below 0.01
    ("thrust-spherical-roller", 20, 12.0, 14.0, 95.0, 50.0),
    ("thrust-spherical-roller", 16, 20.0, 18.0, 80.0, 50.0),    # γ = 0.161
    ("thrust-tapered-roller", 18, 12.0, 20.0, 95.0, 60.0),
    ("thrust-tapered-roller", 20, 9.0, 14.0, 110.0, 65.0),
    ("thrust-tapered-roller", 24, 10.0, 16.0, 120.0, 75.0),
    ("thrust-spherical-roller", 22, 14.0, 16.0, 130.0, 80.0),
]


@pytest.mark.parametrize(("kind", "z", "dwe", "lwe", "dpw", "alpha"), GEOMETRIES)
def test_ca_and_c0a_from_the_geometry(kind, z, dwe, lwe, dpw, alpha):
    expected = ca_iso(kind, z, dwe, lwe, dpw, alpha)
    c, fc = rr.roller_dynamic_load_rating(z, dwe / 1e3, lwe / 1e3, dpw / 1e3,
                                          math.radians(alpha), bearing_type=kind)
    c0 = rr.roller_static_load_rating(z, dwe / 1e3, lwe / 1e3, dpw / 1e3,
                                      math.radians(alpha), thrust=True)
    if math.isnan(expected):
        assert np.isnan(c) and np.isnan(fc)
    else:
        assert float(c) == pytest.approx(expected, rel=REL)
    assert float(c0) == pytest.approx(c0a_iso(z, dwe, lwe, dpw, alpha), rel=REL)


@pytest.mark.parametrize("alpha", [50.0, 65.0, 90.0])
def test_rows_by_iso_281_eq_19(alpha):
    """Two and three equal rows: Ca = (Σ Zk·Lwek)·[Σ (Zk·Lwek/Cak)^(9/2)]^(−2/9) with
    each Cak the one-row rating; C0a and the roller load with all the rows' rollers."""
    kind, z, dwe, lwe, dpw = "thrust-spherical-roller", 18, 10.0, 12.0, 100.0
    one = ca_iso(kind, z, dwe, lwe, dpw, alpha)
    for rows in (2, 3):
        expected = (rows * z * lwe) * (rows * (z * lwe / one) ** 4.5) ** (-2 / 9)
        c, _ = rr.roller_dynamic_load_rating(z, dwe / 1e3, lwe / 1e3, dpw / 1e3,
                                             math.radians(alpha), rows, bearing_type=kind)
        assert float(c) == pytest.approx(expected, rel=REL)
        c0 = rr.roller_static_load_rating(z, dwe / 1e3, lwe / 1e3, dpw / 1e3,
                                          math.radians(alpha), rows, thrust=True)
        assert float(c0) == pytest.approx(rows * c0a_iso(z, dwe, lwe, dpw, alpha), rel=REL)
        q = rbc.max_roller_load(9e3, z, rows, math.radians(alpha), thrust=True)
        assert float(q) == pytest.approx(9e3 / (rows * z * math.sin(math.radians(alpha))),
                                         rel=REL)


# --- through a spec -------------------------------------------------------------------------

THRUST_SPEC = (ROOT / "specs" / "rolling-bearing-thrust-spherical-roller.yaml").read_text()


def from_geometry(kind: str, z: int, dwe: float, lwe: float, dpw: float,
                  alpha: float | None) -> str:
    text = re.sub(r"(dynamic|static)_load_rating: .*\n", "", THRUST_SPEC)
    text = text.replace("type: thrust-spherical-roller", f"type: {kind}")
    text = re.sub(r"contact_angle: .*\n", "" if alpha is None else f"contact_angle: {alpha} deg\n",
                  text)
    if alpha is None:
        text = re.sub(r"radial_load: .*\n", "", text)
    return text + (f"roller_count: {z}\nroller_diameter: {dwe} mm\nroller_length: {lwe} mm\n"
                   f"pitch_diameter: {dpw} mm\n")


@pytest.mark.parametrize(("kind", "z", "dwe", "lwe", "dpw", "alpha"), [
    ("thrust-cylindrical-roller", 20, 8.0, 10.0, 95.0, None),
    ("thrust-spherical-roller", 20, 12.0, 14.0, 95.0, 50.0),
    ("thrust-tapered-roller", 20, 9.0, 14.0, 110.0, 65.0)])
def test_a_spec_rates_a_thrust_roller_bearing_from_its_geometry(cli, spec_file, kind, z, dwe,
                                                               lwe, dpw, alpha):
    """C and C0 are ISO's; L10 = (C/P)^(10/3) million revolutions, P = Fa at 90°,
    tanα·Fr + Fa below (Fr 10 kN, Fa 60 kN)."""
    (record,) = solve_json(cli, spec_file(from_geometry(kind, z, dwe, lwe, dpw, alpha)))
    got = record["results"]
    angle = 90.0 if alpha is None else alpha
    c = ca_iso(kind, z, dwe, lwe, dpw, angle) * 1.0
    c0 = c0a_iso(z, dwe, lwe, dpw, angle)
    p = 60e3 if alpha is None else math.tan(math.radians(alpha)) * 10e3 + 60e3
    assert (got["dynamic_load_rating"], got["dynamic_load_rating_iso"],
            got["static_load_rating"]) == pytest.approx((c, c, c0), rel=1e-9)
    assert got["equivalent_dynamic_load"] == pytest.approx(p, rel=1e-9)
    assert got["basic_rating_life_revolutions"] == pytest.approx((c / p) ** (10 / 3) * 1e6,
                                                                 rel=1e-9)


def test_beyond_its_column_a_thrust_bearing_is_refused_with_one_line(cli, spec_file):
    """At 65° with γ = Dwe·cos65°/Dpw = 0.222, past the column's 0.20: one line naming
    roller_diameter, exit 2."""
    text = from_geometry("thrust-spherical-roller", 5, 50.0, 30.0, 95.0, 65.0)
    run = cli("solve", spec_file(text), "--format", "json")
    assert (run.code, run.out) == (2, ""), run.err
    assert run.err.count("\n") == 1 and "roller_diameter" in run.err, run.err
