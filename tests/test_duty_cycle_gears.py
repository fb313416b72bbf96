"""Duty cycles of kind: bevel-gears and kind: bevel-drive (AGMA 2003 stress-cycle curves
with Miner's rule, each bearing's life over the cycle): a cycle against its bins solved
one by one as single-point specs and combined here, the root of the spectrum safety, a
one-bin cycle, a sweep and a tolerance study of a bin's field, and refused cycles."""

from __future__ import annotations

import csv
import io
import json
import math
import re

import pytest

from tests import agma_miner
from tests.conftest import ROOT, solve_json, study_status

REL, HOUR = 1e-9, 3600.0
UNIT = {"N*m": 1.0, "W": 1.0, "kW": 1e3, "rpm": 2 * math.pi / 60, "%": 0.01}


def si(text: str) -> float:
    """'64 N*m', '7.5 kW', '300 rpm', '5 %' in SI units (N·m, W, rad/s, 1)."""
    number, unit = text.split()
    return float(number) * UNIT[unit]


def flow(mapping: dict[str, str]) -> str:
    return "{" + ", ".join(f"{key}: {value}" for key, value in mapping.items()) + "}"


def with_fields(text: str, fields: dict[str, str]) -> str:
    """The spec ``text`` with each top-level ``key: value`` line of ``fields`` rewritten."""
    for key, value in fields.items():
        text, count = re.subn(rf"^{key}: .*$", f"{key}: {value}", text, flags=re.M)
        assert count == 1, key
    return text


def cycle(base: str, bins: list[dict]) -> str:  # the spec with a duty cycle of bins
    return base + "duty_cycle:\n" + "".join(f"  - {flow(item)}\n" for item in bins)


def own(item: dict) -> dict:  # the operating fields a bin sets
    return {key: value for key, value in item.items() if key not in ("name", "time")}


def design_cycles(text: str) -> float:
    """The pinion's cycles over the design life: the spec's rating.cycles, 10⁷ unless
    given."""
    found = re.search(r"^  cycles: (\S+)", text, flags=re.M)
    return float(found[1]) if found else 1e7


def damage(shares: list[float], safeties: list[float], load: str,
           cycles: float) -> list[float]:
    """Uᵢ·N/Nᵢ on AGMA 2003's two-branch curves (tests/agma_miner.py): each bin's
    cycles over its cycles to failure."""
    return [agma_miner.miner_sum([u], [s], cycles, load)
            for u, s in zip(shares, safeties, strict=True)]


def solve(cli, spec_file, text: str, name: str) -> dict:
    (record,) = solve_json(cli, spec_file(text, name))
    return record["results"]


# --- 1. a pair's cycle is Miner's rule over single-point solves ----------------------------

# The sizing example in the epicyclic form (arm and gear B's shaft), which the bins vary.
SIZING = re.sub(r"^gear_a_speed: .*$", "arm_speed: 0 rpm\ngear_b_speed: -600 rpm",
                (ROOT / "specs" / "bevel-gears-sizing.yaml").read_text(), flags=re.M)
GEARS_20_43 = with_fields(SIZING, {"name": "20/43 pair", "gear_a": "{teeth: 20}",
                                   "gear_b": "{teeth: 43}"}).replace(
    "min_bending_safety: 1.0", "min_bending_safety: 1.2").replace(
    "min_contact_safety: 1.0", "min_contact_safety: 0.9")
GEAR_CASES = {
    "20/43 by power": dict(
        base=GEARS_20_43, limits={"bending": 1.2, "contact": 0.9},
        fields={"power": "7.5 kW", "arm_speed": "0 rpm", "gear_b_speed": "-600 rpm"},
        bins=[{"name": "start", "time": "10 %", "power": "3 kW", "gear_b_speed": "-150 rpm"},
              {"name": "rated", "time": "70 %"},
              {"name": "peak", "time": "20 %", "power": "9 kW", "arm_speed": "100 rpm",
               "gear_b_speed": "-500 rpm"}]),
    "miter pair by torque": dict(
        base=re.sub(r"^power: .*$", "torque: 119 N*m", SIZING, flags=re.M),
        fields={"torque": "119 N*m", "arm_speed": "0 rpm", "gear_b_speed": "-600 rpm"},
        limits={"bending": 1.0, "contact": 1.0},
        bins=[{"time": "25 %", "torque": "150 N*m", "gear_b_speed": "-300 rpm"},
              {"time": "60 %"}, {"time": "15 %", "torque": "100 N*m", "arm_speed": "200 rpm",
               "gear_b_speed": "-700 rpm"}]),
}


def gear_point(case: dict, item: dict, factor: float = 1.0) -> str:
    """A bin as a single-point spec, its torque or power times ``factor``."""
    fields = {**case["fields"], **own(item)}
    load = "power" if "power" in fields else "torque"
    fields[load] = f"{si(fields[load]) * factor!r} {'W' if load == 'power' else 'N*m'}"
    return with_fields(case["base"], fields)


def gear_shares(case: dict) -> list[float]:
    """Uᵢ = tᵢnᵢ/Σtⱼnⱼ, the pinion's speed nᵢ ∝ |ω_Z − Ω|."""
    speeds = [{**case["fields"], **own(item)} for item in case["bins"]]
    weights = [si(item["time"]) * abs(si(f["arm_speed"]) - si(f["gear_b_speed"]))
               for item, f in zip(case["bins"], speeds, strict=True)]
    return [w / sum(weights) for w in weights]


@pytest.mark.parametrize("name", list(GEAR_CASES))
def test_gear_cycle_is_miner_over_single_point_solves(cli, spec_file, name):
    """D = ΣUᵢN/Nᵢ on AGMA's two-branch curves, S by brentq on D(S) = 1 in bending and
    contact; the margins against the limits; the stresses the largest bin's; per bin its
    stresses and damage shares. The root: with every bin's stress times S (torque × S_F,
    torque × S_H²) D is 1."""
    case = GEAR_CASES[name]
    bins = case["bins"]
    n = design_cycles(case["base"])
    got = solve(cli, spec_file, cycle(case["base"], bins), "cycle.yaml")
    singles = [solve(cli, spec_file, gear_point(case, item), f"bin{k}.yaml")
               for k, item in enumerate(bins, 1)]
    u = gear_shares(case)
    expected = {}
    for load in ("bending", "contact"):
        safeties = [s[f"{load}_safety"] for s in singles]
        per_bin = damage(u, safeties, load, n)
        total = sum(per_bin)
        safety = agma_miner.spectrum_safety(u, safeties, n, load)
        expected.update({f"{load}_damage": total, f"{load}_safety": safety,
                         f"{load}_safety_margin": safety - case["limits"][load],
                         f"{load}_stress": max(s[f"{load}_stress"] for s in singles)})
        for k, (s, d) in enumerate(zip(singles, per_bin, strict=True), 1):
            expected[f"duty_{k}_{load}_stress"] = s[f"{load}_stress"]
            expected[f"duty_{k}_{load}_damage_share"] = d / total
        # the root: each bin's stress times S gives D = 1
        factor = safety if load == "bending" else safety ** 2
        scaled = [solve(cli, spec_file, gear_point(case, item, factor), f"{load}{k}.yaml")
                  for k, item in enumerate(bins, 1)]
        assert sum(damage(u, [s[f"{load}_safety"] for s in scaled], load, n)) == pytest.approx(
            1.0, rel=REL)
    for k, item in enumerate(bins, 1):
        expected[f"duty_{k}_time_share"] = si(item["time"])
    assert {key: got.get(key) for key in expected} == pytest.approx(expected, rel=REL, abs=0.0)
    assert [sum(got[f"duty_{k}_{load}_damage_share"] for k in range(1, 4)) for load in
            ("bending", "contact")] == pytest.approx([1.0, 1.0], rel=REL)


def test_gear_bin_speed_is_the_pinions(cli, spec_file):
    """duty_{k}_speed is the pinion's speed, whose turns are the load cycles counted: the
    single point's |gear_a_speed_relative_to_arm| (the shares Uᵢ do not tell, being
    proportional to |ω_Z − Ω| all the same)."""
    case = GEAR_CASES["20/43 by power"]
    got = solve(cli, spec_file, cycle(case["base"], case["bins"]), "cycle.yaml")
    for k, item in enumerate(case["bins"], 1):
        single = solve(cli, spec_file, gear_point(case, item), f"bin{k}.yaml")
        assert got[f"duty_{k}_speed"] == pytest.approx(
            abs(single["gear_a_speed_relative_to_arm"]), rel=REL)


# --- 2. a one-bin cycle is the single point ----------------------------------------------

@pytest.mark.parametrize("stem", ["bevel-gears-sizing", "bevel-drive", "bevel-drive-tapered"])
def test_one_bin_cycle_is_the_single_point(cli, spec_file, stem):
    path = ROOT / "specs" / f"{stem}.yaml"
    (single,) = solve_json(cli, path)
    text = path.read_text().rstrip("\n") + "\nduty_cycle: [{time: 100 %}]\n"
    (one,) = solve_json(cli, spec_file(text))
    differ = {key: (value, one["results"].get(key, "missing"))
              for key, value in single["results"].items()
              if one["results"].get(key, "missing") != value}
    assert not differ
    assert one["within_limits"] == single["within_limits"]


# --- 3. a drive's cycle: each bearing's life over the cycle, the system's, the pair's ----

DRIVE_BINS = [  # the bins of specs/bevel-drive-duty-cycle.yaml
    {"name": "start-up", "time": "2 %", "torque": "70 N*m", "input_speed": "300 rpm"},
    {"name": "rated", "time": "83 %", "torque": "55 N*m"},
    {"name": "peak", "time": "10 %", "torque": "64 N*m"},
    {"name": "held", "time": "5 %", "torque": "120 N*m", "input_speed": "0 rpm"}]
DUTY_SPEC = ROOT / "specs" / "bevel-drive-duty-cycle.yaml"
BALL, ROLLER = 3.0, 10 / 3
DRIVE_CASES = {  # base spec, each bearing's life exponent p, the system's slope e
    "tapered pinion, roller and ball on the gear": (
        DUTY_SPEC.read_text().split("\nduty_cycle:")[0] + "\n", (ROLLER, ROLLER, ROLLER, BALL),
        9 / 8),
    "ball bearings only": ((ROOT / "specs" / "bevel-drive.yaml").read_text(), (BALL,) * 4,
                           10 / 9)}
BEARINGS = ("pinion_bearing_1", "pinion_bearing_2", "gear_bearing_1", "gear_bearing_2")
DRIVE_FIELDS = {"torque": "60 N*m", "input_speed": "1500 rpm"}


def drive_point(base: str, item: dict) -> str:
    """A bin as a single-point spec; a bin at rest keeps the spec's speed (its static
    safety does not depend on it, and it counts for nothing else)."""
    fields = {**DRIVE_FIELDS, **own(item)}
    if si(fields["input_speed"]) == 0:
        fields["input_speed"] = DRIVE_FIELDS["input_speed"]
    return with_fields(base, fields)


def test_example_holds_the_bins_written_here():
    text = DUTY_SPEC.read_text()
    for item in DRIVE_BINS:
        assert flow(item) in text, item


@pytest.mark.parametrize("name", list(DRIVE_CASES))
def test_drive_cycle_over_single_point_solves(cli, spec_file, name):
    """Per bearing 1/L = Σtᵢ/Lᵢ over the turning bins (basic and modified; time at rest
    counts in the hours, as n_m = Σtᵢnᵢ counts it, not in the damage), P_m =
    (ΣUᵢPᵢ^p)^(1/p), s0 the smallest of every bin; the system (ΣL^(−e))^(−1/e); the
    margins; n_m = Σtᵢnᵢ; the pair by Miner's rule; per bin its share, speed, torque,
    system life (null at rest) and shares of the damage."""
    base, exponents, slope = DRIVE_CASES[name]
    got = solve(cli, spec_file, cycle(base, DRIVE_BINS), "cycle.yaml")
    singles = [solve(cli, spec_file, drive_point(base, item), f"bin{k}.yaml")
               for k, item in enumerate(DRIVE_BINS, 1)]
    t = [si(item["time"]) for item in DRIVE_BINS]
    n = [si({**DRIVE_FIELDS, **item}["input_speed"]) for item in DRIVE_BINS]
    turning = [i for i, ni in enumerate(n) if ni > 0]
    moving = [t[i] / sum(t) if i in turning else 0.0 for i in range(4)]
    mean_speed = sum(ti * ni for ti, ni in zip(t, n, strict=True))
    u = [ti * ni / mean_speed for ti, ni in zip(t, n, strict=True)]
    expected: dict[str, float] = {"mean_speed": mean_speed}
    lives: dict[str, list[float]] = {"basic": [], "modified": []}
    for bearing, p in zip(BEARINGS, exponents, strict=True):
        for life, values in lives.items():
            key = f"{bearing}_{life}_rating_life"
            expected[key] = 1 / sum(moving[i] / singles[i][key] for i in turning)
            values.append(expected[key])
        loads = [s[f"{bearing}_equivalent_dynamic_load"] for s in singles]
        expected[f"{bearing}_equivalent_dynamic_load"] = sum(
            ui * pi ** p for ui, pi in zip(u, loads, strict=True)) ** (1 / p)
        expected[f"{bearing}_static_safety_factor"] = min(
            s[f"{bearing}_static_safety_factor"] for s in singles)
    for life, values in lives.items():
        expected[f"system_{life}_rating_life"] = sum(v ** -slope for v in values) ** (-1 / slope)
    expected["life_margin"] = expected["system_modified_rating_life"] / (4000 * HOUR) - 1
    expected["static_safety_margin"] = min(s["static_safety_margin"] for s in singles)
    system = [moving[i] / singles[i]["system_modified_rating_life"] if i in turning else 0.0
              for i in range(4)]
    for load in ("bending", "contact"):
        safeties = [s[f"{load}_safety"] for s in singles]
        per_bin = damage(u, safeties, load, design_cycles(base))
        total = sum(per_bin)
        safety = agma_miner.spectrum_safety(u, safeties, design_cycles(base), load)
        expected.update({f"{load}_damage": total, f"{load}_safety": safety,
                         f"{load}_safety_margin": safety - 1.0})
        expected.update({f"duty_{k}_{load}_damage_share": d / total
                         for k, d in enumerate(per_bin, 1)})
    for k, item in enumerate(DRIVE_BINS, 1):
        expected.update({f"duty_{k}_time_share": t[k - 1], f"duty_{k}_speed": n[k - 1],
                         f"duty_{k}_torque": si({**DRIVE_FIELDS, **item}["torque"]),
                         f"duty_{k}_damage_share": system[k - 1] / sum(system)})
        life = singles[k - 1]["system_modified_rating_life"] if k - 1 in turning else None
        assert (got[f"duty_{k}_system_modified_rating_life"] is None) == (life is None)
        expected.update({f"duty_{k}_system_modified_rating_life": life} if life else {})
    assert {key: got.get(key) for key in expected} == pytest.approx(expected, rel=REL, abs=0.0)
    assert [sum(got[f"duty_{k}_{column}"] for k in range(1, 5)) for column in (
        "damage_share", "bending_damage_share", "contact_damage_share")] == pytest.approx(
        [1.0] * 3, rel=REL)


def test_held_bin_stress_does_not_move_with_another_bins_speed(cli, spec_file):
    """Adding a light, fast bin (5 N·m at 3000 rpm, 1 % of the time, taken from the rated
    bin) changes no bin's stress: the largest stress over the cycle stays, whether the
    held load counts (its stress then static, without Kv) or only the turning bins do."""
    base = DRIVE_CASES["tapered pinion, roller and ball on the gear"][0]
    bins = [dict(item) for item in DRIVE_BINS]
    bins[1]["time"] = "82 %"
    bins.append({"name": "spin", "time": "1 %", "torque": "5 N*m", "input_speed": "3000 rpm"})
    before = solve(cli, spec_file, cycle(base, DRIVE_BINS), "before.yaml")
    after = solve(cli, spec_file, cycle(base, bins), "after.yaml")
    for key in ("bending_stress", "contact_stress"):
        assert after[key] == pytest.approx(before[key], rel=REL)


# --- 4. a sweep of a bin's field is solve at each point ------------------------------------

def test_sweep_of_a_bin_torque_equals_solve_of_each_point(cli, spec_file):
    run = cli("sweep", DUTY_SPEC, "--vary", "duty_cycle.2.torque=50N*m:70N*m:3",
              "--format", "csv")
    assert run.code in (0, 1), run.err
    rows = list(csv.DictReader(io.StringIO(run.out)))
    torques = [float(row["input.duty_cycle.2.torque [N·m]"]) for row in rows]
    assert torques == pytest.approx([50.0, 60.0, 70.0], rel=1e-12)
    base = DRIVE_CASES["tapered pinion, roller and ball on the gear"][0]
    for k, (torque, row) in enumerate(zip(torques, rows, strict=True)):
        bins = [dict(item) for item in DRIVE_BINS]
        bins[1]["torque"] = f"{torque!r} N*m"
        point = solve(cli, spec_file, cycle(base, bins), f"point{k}.yaml")
        assert point["duty_2_torque"] == pytest.approx(torque, rel=REL)
        assert row.pop("reason") == ""  # no point failed
        swept = {header.split(" [")[0]: value for header, value in row.items()
                 if not header.startswith("input.")}
        assert set(swept) == set(point)
        for key, value in point.items():  # null: an empty cell
            assert (float(swept[key]) if swept[key] else None) == (
                None if value is None else pytest.approx(value, rel=1e-12, abs=0.0)), key


# --- 5. a tolerance on a bin's field --------------------------------------------------------

def test_tolerance_on_a_bin_torque_has_the_solve_as_its_nominal(cli, spec_file):
    base = DRIVE_CASES["tapered pinion, roller and ball on the gear"][0]
    bins = [dict(item) for item in DRIVE_BINS]
    bins[2]["torque"] = "64 N*m ± 4 N*m"
    run = cli("tolerance", spec_file(cycle(base, bins), "study.yaml"), "-n", "2000",
              "--seed", "7", "--format", "json")
    assert run.code in (0, 1), run.err
    record = json.loads(run.out)
    assert run.code == study_status(record)
    study = record["inputs"]["duty_cycle.3.torque"]
    assert (study["nominal"], study["low"], study["high"]) == pytest.approx((64, 60, 68))
    nominal = solve(cli, spec_file, cycle(base, DRIVE_BINS), "nominal.yaml")
    for key, value in nominal.items():  # null (the held bin's own life) stays null
        assert record["results"][key]["nominal"] == (
            None if value is None else pytest.approx(value, rel=1e-12)), key
    # the system life falls as the peak torque grows: its extremes are at the band's ends
    life = record["results"]["system_modified_rating_life"]["worst_case"]
    for end, extreme in (("60 N*m", "max"), ("68 N*m", "min")):
        bins[2]["torque"] = end
        point = solve(cli, spec_file, cycle(base, bins), f"end{extreme}.yaml")
        assert life[extreme] == pytest.approx(point["system_modified_rating_life"], rel=REL)


# --- 6. refused cycles: exit 2, one line naming the field -----------------------------------

GEARS = GEAR_CASES["20/43 by power"]
UNRATED = re.sub(r"^rating:.*?\n(?=limits)", "", GEARS_20_43, flags=re.M | re.S)
REFUSED = {  # spec, the field the line names, words it must hold
    "bevel-gears cycle without rating": (
        cycle(UNRATED, GEARS["bins"]), "duty_cycle", ("rating",)),
    "face_width in a bevel-gears bin": (
        cycle(GEARS_20_43, [GEARS["bins"][0], {"time": "70 %", "face_width": "25 mm"},
                            GEARS["bins"][2]]), "duty_cycle.2.face_width", ("face_width",)),
    "face_width in a bevel-drive bin": (
        cycle(DRIVE_CASES["ball bearings only"][0],
              [*DRIVE_BINS[:3], {**DRIVE_BINS[3], "face_width": "25 mm"}]),
        "duty_cycle.4.face_width", ("face_width",)),
    "shares add to 90 %": (
        cycle(GEARS_20_43, [GEARS["bins"][0], {"time": "60 %"}, GEARS["bins"][2]]),
        "duty_cycle", ("90 %",)),
}
LINE = re.compile(r"^\S+\.yaml:\d+: (?P<field>[\w.-]+): (?P<message>.+)$")


@pytest.mark.parametrize("case", list(REFUSED))
def test_bad_cycle_is_one_line_naming_the_field(cli, spec_file, case):
    text, field, words = REFUSED[case]
    assert "\nrating:" not in UNRATED and "geometry_factor" not in UNRATED
    run = cli("solve", spec_file(text), "--format", "json")
    assert (run.code, run.out, run.err.count("\n")) == (2, "", 1), (run.code, run.out, run.err)
    line = LINE.match(run.err.strip())
    assert line and line["field"] == field, run.err
    assert all(word in line["message"] for word in words), run.err
