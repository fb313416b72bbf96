"""ISO 281:2007's other options: bm = 1.0 for drawn-cup needle roller bearings (Table 1;
GOST 18855-2013 Table 6) and lubricants with effective EP additives (9.3.3.3.4), each
against the standard's rule written here."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_json
from tests.test_iso281_tables import GAMMA, GOST_TABLE_7
from tests.test_roller_bearing import a_iso

NEEDLES = """kind: rolling-bearing
name: HK needle roller bearing
type: needle-roller
roller_count: 24
roller_diameter: 3 mm
roller_length: 16 mm
pitch_diameter: 41 mm
radial_load: {load}
speed: 1000 rpm
contamination_factor: {ec}
limits: {{min_rating_life: 1000 h}}
"""


def results(cli, spec_file, text: str) -> dict:
    (record,) = solve_json(cli, spec_file(text))
    return record["results"]


def needle_c(bm: float) -> float:
    """Cr = bm·fc·Lwe^(7/9)·Z^(3/4)·Dwe^(29/27), fc of Table 7 at γ = 3/41."""
    gamma = 3 / 41
    low = GAMMA.index(0.07)
    fc = GOST_TABLE_7[low] + (GOST_TABLE_7[low + 1] - GOST_TABLE_7[low]) * (gamma - 0.07) / 0.01
    return bm * fc * 16 ** (7 / 9) * 24 ** 0.75 * 3 ** (29 / 27)


@pytest.mark.parametrize(("drawn_cup", "bm"), [("", 1.1), ("drawn_cup: false\n", 1.1),
                                                ("drawn_cup: true\n", 1.0)])
def test_a_drawn_cup_needle_bearing_has_bm_one(cli, spec_file, drawn_cup, bm):
    text = NEEDLES.format(load="2 kN", ec=0.5) + "lubrication: {viscosity: 20 mm^2/s}\n" + drawn_cup
    got = results(cli, spec_file, text)
    assert got["dynamic_load_rating"] == pytest.approx(needle_c(bm), rel=1e-12)


@pytest.mark.parametrize("kind", ["cylindrical-roller", "deep-groove"])
def test_drawn_cup_on_another_type_is_one_line(cli, spec_file, kind):
    text = (NEEDLES.format(load="2 kN", ec=0.5).replace("type: needle-roller", f"type: {kind}")
            + "lubrication: {viscosity: 20 mm^2/s}\ndrawn_cup: true\n")
    if kind == "deep-groove":
        text = text.replace("roller_", "ball_").replace("ball_length: 16 mm\n", "")
    run = cli("solve", spec_file(text), "--format", "json")
    assert (run.code, run.out, run.err.count("\n")) == (2, "", 1), run.err
    assert ": drawn_cup: " in run.err and "needle-roller" in run.err


# --- EP additives ---------------------------------------------------------------------------

def ep_rule(kappa: float, ec: float, cu: float, p: float) -> float:
    """9.3.3.3.4: with κ < 1 and eC >= 0.2, κ = 1 may be used; aISO then at most 3,
    and not below the value of an ordinary lubricant at the actual κ."""
    plain = a_iso(kappa, ec, cu, p)
    if kappa < 1 and ec >= 0.2:
        return max(min(a_iso(1.0, ec, cu, p), 3.0), plain)
    return plain


@pytest.mark.parametrize(("viscosity", "ec", "load"), [
    ("5 mm^2/s", 0.5, "2 kN"),     # κ 0.22: κ = 1 gives more than 3, held at 3
    ("12 mm^2/s", 0.3, "6 kN"),    # κ 0.54: κ = 1's value, below 3
    ("5 mm^2/s", 0.2, "2 kN"),     # eC at the limit: applies
    ("5 mm^2/s", 0.1, "2 kN"),     # eC below 0.2: the ordinary value
    ("40 mm^2/s", 0.5, "2 kN"),    # κ above 1: the ordinary value
    ("21 mm^2/s", 0.8, "0.5 kN"),  # κ just below 1, a light load: the ordinary value is above 3
])
def test_ep_additives_take_kappa_one(cli, spec_file, viscosity, ec, load):
    base = NEEDLES.format(load=load, ec=ec)
    plain = results(cli, spec_file, base + f"lubrication: {{viscosity: {viscosity}}}\n")
    ep = results(cli, spec_file, base + f"lubrication: {{viscosity: {viscosity}, "
                                        "ep_additives: true}\n")
    kappa, cu, p = (ep[key] for key in ("viscosity_ratio", "fatigue_load_limit",
                                        "equivalent_dynamic_load"))
    assert plain["life_modification_factor"] == pytest.approx(a_iso(kappa, ec, cu, p),
                                                              rel=1e-12)
    assert ep["life_modification_factor"] == pytest.approx(ep_rule(kappa, ec, cu, p),
                                                           rel=1e-12)
    assert ep["viscosity_ratio"] == plain["viscosity_ratio"]  # κ itself is reported as is
    assert ep["modified_rating_life"] == pytest.approx(
        plain["modified_rating_life"] * ep["life_modification_factor"]
        / plain["life_modification_factor"], rel=1e-12)


def test_the_cases_above_reach_every_branch(cli, spec_file):
    """The parameters of the EP test do reach each branch of the rule."""
    branches = set()
    for viscosity, ec, load in (("5 mm^2/s", 0.5, "2 kN"), ("12 mm^2/s", 0.3, "6 kN"),
                                ("21 mm^2/s", 0.8, "0.5 kN")):
        got = results(cli, spec_file, NEEDLES.format(load=load, ec=ec)
                      + f"lubrication: {{viscosity: {viscosity}}}\n")
        kappa, cu, p = (got[key] for key in ("viscosity_ratio", "fatigue_load_limit",
                                             "equivalent_dynamic_load"))
        at_one, plain = a_iso(1.0, ec, cu, p), a_iso(kappa, ec, cu, p)
        assert kappa < 1
        branches.add("held at 3" if at_one > 3 and plain < 3 else
                     "ordinary above 3" if plain >= 3 else "kappa one")
    assert branches == {"held at 3", "kappa one", "ordinary above 3"}
    assert math.isfinite(a_iso(1.0, 0.5, 1e3, 2e3))
