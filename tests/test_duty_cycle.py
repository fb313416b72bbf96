"""Duty cycles of kind: rolling-bearing (ISO 281 with the Palmgren–Miner rule): a cycle
against its bins solved one by one as single-point specs and combined by the arithmetic
written here, a one-bin cycle against the single point, published load-spectrum examples,
a sweep of a bin's field, and the inputs a cycle refuses."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from bearingcalc.core.duty_cycle import mean_load, miner_life, revolution_shares
from tests.conftest import ROOT, csv_column, solve_json

REL = 1e-9
LBF = 4.4482216152605  # N
UNIT = {"N": 1.0, "kN": 1e3, "lbf": LBF, "rpm": 2 * math.pi / 60, "%": 0.01}
HOUR = 3600.0


def si(text: str) -> float:
    """'12 kN', '300 rpm', '5 %' in SI units (N, rad/s, 1)."""
    number, unit = text.split()
    return float(number) * UNIT[unit]


def flow(mapping: dict[str, str]) -> str:
    return "{" + ", ".join(f"{key}: {value}" for key, value in mapping.items()) + "}"


def spec(case: dict, bins: list[dict] | None = None, fields: dict | None = None,
         lubrication: dict | None = None) -> str:
    """The spec of a case: its fixed lines, its operating fields, its lubrication and,
    when given, a duty cycle of ``bins``."""
    fields = case["fields"] if fields is None else fields
    lubrication = case["lubrication"] if lubrication is None else lubrication
    text = case["common"] + "".join(f"{key}: {value}\n" for key, value in fields.items())
    if lubrication:
        text += f"lubrication: {flow(lubrication)}\n"
    if bins == []:
        text += "duty_cycle: []\n"
    elif bins is not None:
        text += "duty_cycle:\n" + "".join(f"  - {flow(item)}\n" for item in bins)
    return text


def single_point(case: dict, item: dict) -> str:
    """The bin written by hand as a spec of its own: the case's spec with the bin's
    fields in place of its own. A bin at rest keeps the spec's speed (a single point
    must turn), which changes neither its P nor its static safety nor its contacts."""
    fields = dict(case["fields"])
    for key in ("radial_load", "axial_load", "speed"):
        if key in item and not (key == "speed" and si(item[key]) == 0):
            fields[key] = item[key]
    lubrication = dict(case["lubrication"])
    for key in ("temperature", "viscosity"):
        if key in item:
            lubrication[key] = item[key]
    return spec(case, fields=fields, lubrication=lubrication)


# The 6309 of the feature's example, a 30206 pair rated from the catalogue (a roller, with
# a parked bin carrying the largest load), a 6205 from its geometry (Hertz contacts) and an
# NU 206 from its geometry (a roller with line contacts).
CASES = {
    "6309 ball, the example": dict(
        common="kind: rolling-bearing\nname: 6309 under a duty cycle\ntype: deep-groove\n"
               "dynamic_load_rating: 55.3 kN\nstatic_load_rating: 31.5 kN\nstatic_factor: 13\n"
               "pitch_diameter: 72.5 mm\ncontamination_factor: 0.5\n"
               "limits: {min_rating_life: 5000 h}\n",
        fields={"radial_load": "6 kN", "speed": "1500 rpm"},
        lubrication={"viscosity_40": "68 mm^2/s", "viscosity_100": "8.7 mm^2/s",
                     "temperature": "60 degC"},
        bins=[{"name": "start-up", "time": "5 %", "radial_load": "12 kN", "axial_load": "2 kN",
               "speed": "300 rpm", "temperature": "20 degC"},
              {"name": "rated", "time": "80 %", "radial_load": "6 kN", "axial_load": "1 kN"},
              {"name": "overload", "time": "15 %", "radial_load": "9 kN",
               "axial_load": "1.5 kN"}],
        life=5000 * HOUR, exponent=3.0),
    "30206 tapered pair, parked bin": dict(
        common="kind: rolling-bearing\nname: 30206 pair under a duty cycle\n"
               "type: tapered-roller\narrangement: back-to-back\ndynamic_load_rating: 40.2 kN\n"
               "static_load_rating: 44 kN\nfatigue_load_limit: 4.8 kN\ncontact_angle: 14 deg\n"
               "load_factors: {e: 0.37, y1: 1.8, y2: 2.7, y0: 1.8}\npitch_diameter: 46 mm\n"
               "contamination_factor: 0.5\nlimits: {min_rating_life: 6000 h, "
               "min_static_safety: 2}\n",
        fields={"radial_load": "9 kN", "axial_load": "2.5 kN", "speed": "1500 rpm"},
        lubrication={"viscosity": "68 mm^2/s"},
        bins=[{"name": "parked", "time": "10 %", "radial_load": "30 kN", "axial_load": "6 kN",
               "speed": "0 rpm"},
              {"name": "rated", "time": "70 %", "viscosity": "40 mm^2/s"},
              {"name": "peak", "time": "20 %", "radial_load": "14 kN", "axial_load": "5 kN",
               "speed": "750 rpm", "viscosity": "100 mm^2/s"}],
        life=6000 * HOUR, exponent=10 / 3),
    "6205 ball from geometry, parked bin": dict(
        common="kind: rolling-bearing\nname: 6205 under a duty cycle\ntype: deep-groove\n"
               "ball_count: 9\nball_diameter: 7.938 mm\npitch_diameter: 38.5 mm\n"
               "inner_groove_conformity: 0.52\nouter_groove_conformity: 0.53\n"
               "reliability: 99 %\ncontamination_factor: 0.5\n"
               "limits: {min_rating_life: 10000 h}\n",
        fields={"radial_load": "1.5 kN", "axial_load": "0.4 kN", "speed": "1450 rpm"},
        lubrication={"viscosity": "32 mm^2/s"},
        bins=[{"name": "parked", "time": "20 %", "radial_load": "4 kN", "axial_load": "1 kN",
               "speed": "0 rpm"},
              {"name": "rated", "time": "60 %"},
              {"name": "peak", "time": "20 %", "radial_load": "2.5 kN", "speed": "2900 rpm",
               "viscosity": "20 mm^2/s"}],
        life=10000 * HOUR, exponent=3.0),
    "NU 206 cylindrical from geometry, parked bin": dict(
        common="kind: rolling-bearing\nname: NU 206 under a duty cycle\n"
               "type: cylindrical-roller\nroller_count: 13\nroller_diameter: 9 mm\n"
               "roller_length: 9 mm\npitch_diameter: 46 mm\ncontamination_factor: 0.5\n"
               "limits: {min_rating_life: 5000 h, min_static_safety: 2}\n",
        fields={"radial_load": "6 kN", "speed": "3000 rpm"},
        lubrication={"viscosity": "32 mm^2/s"},
        bins=[{"name": "parked", "time": "10 %", "radial_load": "20 kN", "speed": "0 rpm"},
              {"name": "rated", "time": "70 %", "viscosity": "40 mm^2/s"},
              {"name": "peak", "time": "20 %", "radial_load": "10 kN", "speed": "1500 rpm",
               "viscosity": "20 mm^2/s"}],
        life=5000 * HOUR, exponent=10 / 3),
}
# The worst over the bins: the smallest, and the largest (static safety, contacts).
SMALLEST = ("static_safety_factor", "static_safety_margin", "contact_pressure_margin")
LARGEST = ("static_equivalent_load", "max_ball_load", "max_roller_load",
           "inner_contact_pressure", "outer_contact_pressure", "max_contact_pressure")


# --- 1. a cycle is the Palmgren–Miner sum of its bins solved one by one --------------------

@pytest.mark.parametrize("name", list(CASES))
def test_cycle_is_miner_over_single_point_solves(cli, spec_file, name):
    """Uᵢ = tᵢnᵢ/Σtⱼnⱼ, n_m = Σtᵢnᵢ, P_m = (ΣUᵢPᵢ^p)^(1/p), 1/L10 = ΣUᵢ/L10ᵢ = 1/(C/P_m)^p,
    1/Lnm = ΣUᵢ/Lnmᵢ (each bin's own κ and aISO), times at n_m; static safety and contacts
    the worst bin's; a parked bin counts for the static safety only."""
    case = CASES[name]
    bins = case["bins"]
    (cycle,) = solve_json(cli, spec_file(spec(case, bins), "cycle.yaml"))
    got = cycle["results"]
    singles = [solve_json(cli, spec_file(single_point(case, item), f"bin{k}.yaml"))[0]["results"]
               for k, item in enumerate(bins, 1)]
    t = [si(item["time"]) for item in bins]
    n = [si(item.get("speed", case["fields"]["speed"])) for item in bins]
    n_m = sum(ti * ni for ti, ni in zip(t, n, strict=True))
    u = [ti * ni / n_m for ti, ni in zip(t, n, strict=True)]
    turning = [i for i, ni in enumerate(n) if ni > 0]
    p = case["exponent"]
    loads = [s["equivalent_dynamic_load"] for s in singles]
    p_m = sum(ui * pi ** p for ui, pi in zip(u, loads, strict=True)) ** (1 / p)
    l10 = 1 / sum(u[i] / singles[i]["basic_rating_life_revolutions"] for i in turning)
    lnm = 1 / sum(u[i] / singles[i]["modified_rating_life_revolutions"] for i in turning)
    rating = singles[0].get("pair_dynamic_load_rating", singles[0]["dynamic_load_rating"])
    assert l10 == pytest.approx(1e6 * (rating / p_m) ** p, rel=REL)  # the two forms agree
    per_second = n_m / (2 * math.pi)
    expected = {"mean_speed": n_m, "mean_equivalent_load": p_m, "equivalent_dynamic_load": p_m,
                "load_ratio": rating / p_m, "basic_rating_life_revolutions": l10,
                "basic_rating_life": l10 / per_second, "modified_rating_life_revolutions": lnm,
                "modified_rating_life": lnm / per_second,
                "life_margin": lnm / per_second / case["life"] - 1}
    expected.update({key: min(s[key] for s in singles) for key in SMALLEST if key in singles[0]})
    expected.update({key: max(s[key] for s in singles) for key in LARGEST if key in singles[0]})
    damage = [u[i] * lnm / singles[i]["modified_rating_life_revolutions"] if i in turning
              else 0.0 for i in range(len(bins))]
    assert sum(damage) == pytest.approx(1.0, rel=REL)
    unbounded = []
    for k, (item, s) in enumerate(zip(bins, singles, strict=True), 1):
        fields = {**case["fields"], **item}
        expected.update({f"duty_{k}_time_share": t[k - 1], f"duty_{k}_speed": n[k - 1],
                         f"duty_{k}_radial_load": si(fields["radial_load"]),
                         f"duty_{k}_axial_load": si(fields.get("axial_load", "0 N")),
                         f"duty_{k}_equivalent_dynamic_load": s["equivalent_dynamic_load"],
                         f"duty_{k}_damage_share": damage[k - 1]})
        if k - 1 in turning:
            expected[f"duty_{k}_modified_rating_life"] = s["modified_rating_life"]
        else:
            unbounded.append(k)
    assert {key: got.get(key) for key in expected} == pytest.approx(expected, rel=REL, abs=0.0)
    for k in unbounded:  # a parked bin: no share of the revolutions, no life of its own
        assert got[f"duty_{k}_modified_rating_life"] is None
        assert any(f"duty_{k}_modified_rating_life" in w and "unbounded" in w
                   for w in cycle["warnings"]), cycle["warnings"]
        # the parked bin is the one with the smallest static safety
        assert min(range(len(bins)), key=lambda i: singles[i]["static_safety_factor"]) == k - 1
    worst = max(range(len(bins)), key=lambda i: damage[i])
    item = bins[worst]
    assert (f"bin {worst + 1} ({item['name']}) does the most damage: "
            f"{100 * t[worst]:g} % of the time, {100 * damage[worst]:.3g} % of the damage"
            in cycle["warnings"]), cycle["warnings"]


def test_example_names_the_overload_bin(cli, spec_file):
    """The wording of the example: the overload bin, 15 % of the time, about half the
    damage (49.9 % from the sum in the test above)."""
    case = CASES["6309 ball, the example"]
    (cycle,) = solve_json(cli, spec_file(spec(case, case["bins"])))
    assert ("bin 3 (overload) does the most damage: 15 % of the time, 49.9 % of the damage"
            in cycle["warnings"])


# --- 2. a one-bin cycle is the single point ----------------------------------------------

SINGLE_POINT = sorted(path for pattern in ("ball-bearing*.yaml", "rolling-bearing*.yaml")
                      for path in (ROOT / "specs").glob(pattern)
                      if "duty_cycle" not in path.read_text()
                      # solved as mounted: one operating point, no cycle
                      and "method: iso-16281" not in path.read_text())


def test_single_point_examples_are_found():
    assert len(SINGLE_POINT) >= 10


@pytest.mark.parametrize("path", SINGLE_POINT, ids=lambda path: path.stem)
def test_one_bin_cycle_is_the_single_point(cli, spec_file, path):
    """duty_cycle: [{time: 100 %}] changes no result: every key of the single point has
    the same float (==)."""
    (single,) = solve_json(cli, path)
    text = path.read_text().rstrip("\n") + "\nduty_cycle: [{time: 100 %}]\n"
    # the copy is elsewhere: its catalogue by an absolute path
    text = text.replace("catalogue: catalogues/", f"catalogue: {ROOT / 'specs' / 'catalogues'}/")
    (cycle,) = solve_json(cli, spec_file(text))
    differ = {key: (value, cycle["results"].get(key, "missing"))
              for key, value in single["results"].items()
              if cycle["results"].get(key, "missing") != value}
    assert not differ
    assert cycle["within_limits"] == single["within_limits"]


# --- 3. published worked examples ----------------------------------------------------------

def test_mott_example_14_6_mean_effective_load(cli, spec_file):
    """R. L. Mott, *Machine Elements in Mechanical Design*, 4th ed., Pearson, 2004, §14-9,
    Example Problem 14-6 (p. 626): a 6308 deep-groove ball bearing at 600 rpm, a 60 min
    cycle of 650 lb for 30 min, 750 lb for 10 min and 250 lb for 20 min; Eq. (14-11)
    Fm = [Σ Fᵢ³Nᵢ / N]^(1/3) = 597 lb (printed to the pound). The rating is the spec's
    own (Fm does not depend on it)."""
    case = dict(common="kind: rolling-bearing\nname: Mott 14-6\ntype: deep-groove\n"
                       "dynamic_load_rating: 41 kN\nstatic_load_rating: 24 kN\n",
                fields={"radial_load": "650 lbf", "speed": "600 rpm"}, lubrication={})
    bins = [{"time": 30 / 60}, {"time": 10 / 60, "radial_load": "750 lbf"},
            {"time": 20 / 60, "radial_load": "250 lbf"}]
    (cycle,) = solve_json(cli, spec_file(spec(case, bins)))
    got = cycle["results"]
    assert got["mean_equivalent_load"] / LBF == pytest.approx(597, abs=0.5)
    assert got["mean_speed"] == pytest.approx(600 * 2 * math.pi / 60, rel=REL)
    # the core function on the same numbers
    shares, speed = revolution_shares(np.array([30, 10, 20]) / 60, np.full(3, 600.0))
    assert float(speed) == pytest.approx(600.0, rel=REL)
    fm = mean_load(shares, np.array([650.0, 750.0, 250.0]), 3.0, np.int64(1))
    assert float(fm) == pytest.approx(597, abs=0.5)


def test_reliability_package_palmgren_miner_example():
    """M. Reid, *reliability* (Python package) documentation, "Palmgren-Miner linear
    damage model" (docs/Palmgren-Miner linear damage model.rst of MatthewReid854/
    reliability): ball bearings failing after 50000 h, 6500 h and 1000 h at 1, 2 and
    4 kN, a cycle of 40, 15 and 5 min at those loads (one speed); printed: service life
    7400.37951 cycles of one hour, damage fractions 9.86717 %, 28.463 %, 61.66983 %."""
    shares, _ = revolution_shares(np.array([40, 15, 5]) / 60, np.full(3, 1500.0))
    lives = np.array([50000.0, 6500.0, 1000.0])
    life = float(miner_life(shares, lives, np.int64(2)))
    assert life == pytest.approx(7400.37951, abs=0.6e-5)
    damage = 100 * shares * life / lives
    assert damage.tolist() == pytest.approx([9.86717, 28.463, 61.66983], abs=0.6e-5)
    # the governing bin is only a reference: any choice gives the same life
    assert float(miner_life(shares, lives, np.int64(0))) == pytest.approx(life, rel=1e-12)


# --- 4. a sweep of a bin's field is solve at each point ------------------------------------

def test_sweep_of_a_bin_field_equals_solve_of_that_point(cli, spec_file):
    case = CASES["6309 ball, the example"]
    run = cli("sweep", spec_file(spec(case, case["bins"]), "cycle.yaml"), "--vary",
              "duty_cycle.3.radial_load=5kN:15kN:3", "--format", "csv")
    assert run.code in (0, 1), run.err
    loads = csv_column(run.out, "input.duty_cycle.3.radial_load [N]")
    assert loads == pytest.approx([5000.0, 10000.0, 15000.0], rel=1e-12)
    lives = csv_column(run.out, "modified_rating_life [s]")
    assert len(lives) == 3
    for k, (load, life) in enumerate(zip(loads, lives, strict=True)):
        bins = [dict(item) for item in case["bins"]]
        bins[2]["radial_load"] = f"{load!r} N"
        (point,) = solve_json(cli, spec_file(spec(case, bins), f"point{k}.yaml"))
        assert life == pytest.approx(point["results"]["modified_rating_life"], rel=1e-12)
        assert point["results"]["duty_3_radial_load"] == load


# --- 5. refused cycles: exit 2, one line naming the field -----------------------------------

EXAMPLE = CASES["6309 ball, the example"]
BY_VISCOSITY = CASES["6205 ball from geometry, parked bin"]
HALVES = [{"time": "50 %"}, {"time": "50 %"}]
REFUSED = {  # spec, the field the line names, words it must hold
    "shares add to 90 %": (spec(EXAMPLE, [{"time": "50 %"}, {"time": "40 %"}]),
                           "duty_cycle", ("90 %",)),
    "negative share": (spec(EXAMPLE, [{"time": "-5 %"}, {"time": "50 %"}, {"time": "55 %"}]),
                       "duty_cycle.1.time", ("-5 %",)),
    "unknown bin field": (spec(EXAMPLE, [HALVES[0], {"time": "50 %", "colour": "red"}]),
                          "duty_cycle.2.colour", ("colour",)),
    "geometry field in a bin": (spec(EXAMPLE, [HALVES[0], {"time": "50 %",
                                                           "ball_diameter": "5 mm"}]),
                                "duty_cycle.2.ball_diameter", ("ball_diameter",)),
    "every bin at rest": (spec(EXAMPLE, [{"time": "50 %", "speed": "0 rpm"}] * 2),
                          "duty_cycle", ("rest",)),
    "empty list": (spec(EXAMPLE, []), "duty_cycle", ("empty",)),
    "1001 bins": (spec(EXAMPLE, [{"time": "0.1 %"}] * 1000 + [{"time": "0 %"}]),
                  "duty_cycle", ("1001", "1000")),
    "bin temperature, lubrication by viscosity": (
        spec(BY_VISCOSITY, [HALVES[0], {"time": "50 %", "temperature": "40 degC"}]),
        "duty_cycle.2.temperature", ("viscosity_40",)),
}
LINE = re.compile(r"^\S+\.yaml:\d+: (?P<field>[\w.-]+): (?P<message>.+)$")


def refused(cli, spec_file, text):
    run = cli("solve", spec_file(text), "--format", "json")
    assert run.code == 2, (run.code, run.out, run.err)
    assert run.out == ""
    assert run.err.count("\n") == 1, run.err
    line = LINE.match(run.err.strip())
    assert line, run.err
    return line["field"], line["message"]


@pytest.mark.parametrize("case", list(REFUSED))
def test_bad_cycle_is_one_line_naming_the_field(cli, spec_file, case):
    text, field, words = REFUSED[case]
    named, message = refused(cli, spec_file, text)
    assert named == field, message
    assert all(word in message for word in words), message


def test_speed_missing_in_spec_and_bin_2_is_refused_naming_bin_2(cli, spec_file):
    fields = {key: value for key, value in EXAMPLE["fields"].items() if key != "speed"}
    text = spec(EXAMPLE, [{"time": "30 %", "speed": "1000 rpm"}, {"time": "40 %"},
                          {"time": "30 %", "speed": "500 rpm"}], fields=fields)
    named, message = refused(cli, spec_file, text)
    assert named.startswith("duty_cycle.2") or "bin 2" in message, (named, message)
    assert "speed" in named + message
