"""Hostile inputs for a bearing's ``mounting`` (docs/kinds/rolling-bearing.md, physics.md
§13), alone and with other features; the bands are ISO 286-2, ISO 492 and ISO 5753-1 values
for a 6208 entered by hand. Where the product is wrong the right behaviour is a strict xfail."""
from __future__ import annotations

import csv
import io
import json
import math
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
FITS = (ROOT / "specs" / "rolling-bearing-mounted-fits.yaml").read_text(encoding="utf-8")
PAIR = (ROOT / "specs" / "rolling-bearing-mounted-pair.yaml").read_text(encoding="utf-8")
DRIVE = (ROOT / "specs" / "bevel-drive-mounted.yaml").read_text(encoding="utf-8")
BLOCK = re.compile(r"^mounting:\n(?:  .*\n)+", re.M)
DEFAULT = {"clearance_group": "C3", "shaft": "k5", "housing": "H7",
           "inner_ring_temperature": "70 degC", "outer_ring_temperature": "60 degC"}
UM = 1e-6


def mounted(extra: str = "", **fields: str | None) -> str:
    """The 6208 spec with its mounting's fields changed (None drops one), plus ``extra``."""
    body = "".join(f"  {k}: {v}\n" for k, v in {**DEFAULT, **fields}.items() if v is not None)
    return BLOCK.sub(lambda _: "mounting:\n" + body, FITS, count=1) + extra


def ball(d: float, big_d: float, mounting: str) -> str:
    """A deep-groove bearing of bore d and outside D [mm] with its geometry given."""
    dpw, dw = (d + big_d) / 2, 0.3 * (big_d - d)
    return (f"kind: rolling-bearing\nname: edge\ntype: deep-groove\nmethod: iso-16281\n"
            f"bore_diameter: {d} mm\noutside_diameter: {big_d} mm\n"
            f"ball_count: {max(6, int(math.pi * dpw * 0.55 / dw))}\n"
            f"ball_diameter: {dw:.4g} mm\npitch_diameter: {dpw:.6g} mm\n"
            "inner_groove_conformity: 0.52\nouter_groove_conformity: 0.53\n"
            f"mounting: {{{mounting}}}\nradial_load: {0.02 * dpw * dw:.4g} kN\n"
            "speed: 3000 rpm\nlubrication: {viscosity: 100 mm^2/s}\n"
            "contamination_factor: 0.5\n")


def clean(run) -> None:
    """No traceback, no internal error."""
    assert run.exception is None or isinstance(run.exception, SystemExit), run.exception
    assert "Traceback" not in run.err + run.out and "internal error" not in run.err, run.err


def results(cli, spec_file, text: str) -> dict:
    """The solved results of a spec that must solve: exit 0 or 1, every number finite."""
    run = cli("solve", spec_file(text), "--format", "json")
    clean(run)
    assert run.code in (0, 1), run.err
    record = json.loads(run.out.splitlines()[0])
    assert run.code == (0 if record["within_limits"] else 1)
    bad = [k for k, v in record["results"].items()
           if isinstance(v, float) and not math.isfinite(v)]
    assert not bad, bad
    return record["results"]


def refused(run, field: str) -> str:
    """A refusal: exit 2, one line on stderr, naming ``field``."""
    clean(run)
    assert run.code == 2, (run.code, run.err)
    lines = [line for line in run.err.splitlines() if line.strip()]
    assert len(lines) == 1, run.err
    assert field in lines[0], run.err
    return lines[0]


def solve(cli, spec_file, text: str):
    return cli("solve", spec_file(text), "--format", "json")


# --- good drawings: the ISO bands, in µm, of fit interference and initial clearance ---

@pytest.mark.parametrize("field,value,key,low,high", [
    *(("shaft", v, "fit_interference_inner", lo, hi) for v, lo, hi in [
        ("k5", 2, 25), ("js6", -8, 20), ("j5", -5, 18), ("n6", 17, 45), ("p6", 26, 54),
        ("r6", 34, 62), ("40 mm k5", 2, 25), ("'k5 '", 2, 25),
        ("40.008 mm ± 0.004 mm", 4, 24), ("40.008 mm", 8, 20)]),
    *(("housing", v, "fit_interference_outer", lo, hi) for v, lo, hi in [
        ("M7", -13, 30), ("N7", -4, 39), ("P7", 8, 51), ("K6", -17, 15), ("JS7", -28, 15),
        ("F7", -73, -30), ("H4", -21, 0), ("80 mm H7", -43, 0)]),
    *(("clearance_group", v, "initial_clearance", lo, hi) for v, lo, hi in [
        ("C2", 1, 11), ("CN", 6, 20), ("'C3 '", 15, 33), ("C4", 28, 46), ("C5", 40, 64)]),
    ("tolerance_class", "'6'", "fit_interference_inner", 2, 23),
    ("tolerance_class", "'5'", "fit_interference_outer", -39, 0),
    ("initial_clearance", "15 µm ± 20 µm", "initial_clearance", -5, 35),
    ("bore_deviation", "-20 µm ± 1 µm", "fit_interference_inner", 21, 34),
])
def test_drawing_gives_the_iso_bands(cli, spec_file, field, value, key, low, high):
    extra = {"clearance_group": None} if field == "initial_clearance" else {}
    res = results(cli, spec_file, mounted(**{**extra, field: value}))
    assert res[f"{key}_min"] == pytest.approx(low * UM, abs=1e-9)
    assert res[f"{key}_max"] == pytest.approx(high * UM, abs=1e-9)
    assert res[f"{key}_min"] <= res[key] <= res[f"{key}_max"]


@pytest.mark.parametrize("value", ["5", "6"])
def test_tolerance_class_as_a_plain_number(cli, spec_file, value):
    res = results(cli, spec_file, mounted(tolerance_class=value))
    assert res["fit_interference_outer_min"] < -38 * UM


@pytest.mark.parametrize("d,big_d,fields,key,low,high", [
    (3, 10, "initial_clearance: 10 µm ± 5 µm, shaft: k5, housing: H7",
     "fit_interference_inner", 0, 12),
    (200, 280, "clearance_group: C3, shaft: k5, housing: H7", "initial_clearance", 63, 117),
    (200, 280, "clearance_group: C3, shaft: k5, housing: H7", "fit_interference_outer", -87, 0),
])
def test_diameters_at_the_tables_edges(cli, spec_file, d, big_d, fields, key, low, high):
    res = results(cli, spec_file, ball(d, big_d, fields))
    assert (res[f"{key}_min"], res[f"{key}_max"]) == pytest.approx((low * UM, high * UM),
                                                                    abs=1e-9)


def test_roughness_above_the_interference_leaves_the_fit_loose(cli, spec_file):
    res = results(cli, spec_file, mounted(roughness="{shaft: 100 µm}"))
    assert res["fit_pressure_inner_max"] == 0 and res["clearance_reduction_fit_inner_max"] == 0
    assert res["operating_clearance"] == pytest.approx(
        res["initial_clearance"] - res["clearance_change_thermal"])


def test_heavy_preload_from_the_drawing_fails_its_limit_and_shortens_life(cli, spec_file):
    loose = results(cli, spec_file, mounted())
    tight = results(cli, spec_file, mounted(clearance_group="C2", shaft="p6", housing="P7",
                                            inner_ring_temperature="120 degC"))
    assert tight["operating_clearance_max"] < 0 < tight["inner_ring_hoop_stress_min"]
    assert tight["max_element_load"] > loose["max_element_load"]
    assert tight["modified_reference_rating_life"] < loose["modified_reference_rating_life"]


# --- bad drawings: one line naming the field, exit 2 ---

@pytest.mark.parametrize("fields,field", [
    *(({"shaft": v}, "mounting.shaft") for v in ("K5", "JS7", "h13", "s6", "41 k5", "40")),
    *(({"housing": v}, "mounting.housing") for v in ("k5", "js7", "H12", "79 H7", None)),
    *(({"clearance_group": v}, "mounting.clearance_group")
      for v in ("C1", "C6", "C1NA", "CNA", None)),
    ({"initial_clearance": "15 µm"}, "mounting.initial_clearance"),
    ({"initial_clearance": "nan µm", "clearance_group": None}, "mounting.initial_clearance"),
    *(({"tolerance_class": v}, "mounting.tolerance_class") for v in ("P5", "Normal", "'7'")),
    *(({"housing_outside_diameter": v}, "mounting.housing_outside_diameter")
      for v in ("80 mm", "79 mm", "80 mm ± 1 mm")),
    *(({"shaft_bore": v}, "mounting.shaft_bore") for v in ("-5 mm", "40 mm", "50 mm")),
    ({"roughness": "{shaft: -2 µm}"}, "mounting.roughness.shaft"),
    ({"roughness": "{bore: 1 µm}"}, "mounting.roughness.bore"),
    ({"inner_ring_temperature": "-300 degC"}, "mounting.inner_ring_temperature"),
    ({"outer_ring_temperature": "0 K"}, "mounting.outer_ring_temperature"),
    ({"assembly_temperature": "-274 degC"}, "mounting.assembly_temperature"),
    ({"inner_ring_temperature": "70 C"}, "mounting.inner_ring_temperature"),
    *(({"ring_thermal_expansion": v}, "mounting.ring_thermal_expansion")
      for v in ("-11.5e-6 1/K", "1 1/K", "11.5e-6")),
    ({"shaft_material": "titanium"}, "mounting.shaft_material"),
    ({"housing_material": "{elastic_modulus: 70 GPa, poisson_ratio: 0.5, thermal_expansion: "
      "23e-6 1/K}"}, "mounting.housing_material.poisson_ratio"),
    ({"shaft_material": "{elastic_modulus: -110 GPa, poisson_ratio: 0.3, thermal_expansion: "
      "9e-6 1/K}"}, "mounting.shaft_material.elastic_modulus"),
    ({"shaft_material": "{elastic_modulus: 110 GPa, poisson_ratio: 0.3}"},
     "mounting.shaft_material.thermal_expansion"),
    ({"bogus": "1 mm"}, "mounting.bogus"),
])
def test_bad_drawing_is_refused_naming_its_field(cli, spec_file, fields, field):
    refused(solve(cli, spec_file, mounted(**fields)), field)


@pytest.mark.parametrize("d,big_d,fields,field", [
    (2.99, 10, "initial_clearance: 10 µm, shaft: k5, housing: H7", "mounting.shaft"),
    (200.0001, 280, "clearance_group: C3, shaft: k5, housing: H7", "mounting.clearance_group"),
    (500, 620, "initial_clearance: 10 µm, shaft: k5, housing: H7", "mounting.housing"),
])
def test_diameters_outside_the_tables_are_refused(cli, spec_file, d, big_d, fields, field):
    refused(solve(cli, spec_file, ball(d, big_d, fields)), field)


@pytest.mark.parametrize("fields,must_say", [
    pytest.param({"roughness": "2.5 µm"}, "shaft", id="roughness-not-a-mapping"),
    pytest.param({"clearance_group": "C9"}, "C2, CN, C3", id="unknown-group"),
])
def test_near_miss_messages_say_what_would_be_right(cli, spec_file, fields, must_say):
    assert must_say in refused(solve(cli, spec_file, mounted(**fields)), "mounting.")


@pytest.mark.parametrize("fields,meant", [
    pytest.param({"clearance_group": "cn"}, {"clearance_group": "CN"}, id="group-lower-case"),
    pytest.param({"clearance_group": "N"}, {"clearance_group": "CN"},
                 id="group-N-as-ISO-names-it"),
    pytest.param({"shaft": "'k 5'"}, {"shaft": "k5"}, id="class-with-a-space"),
])
def test_near_misses_are_read_as_meant(cli, spec_file, fields, meant):
    """Forms an engineer writes for a group or class (lower case, ISO 5753-1's own N, a
    space in the class) solve as the canonical spelling does."""
    near, canonical = (solve(cli, spec_file, mounted(**values)) for values in (fields, meant))
    assert near.code == canonical.code and near.code in (0, 1), near.err
    assert json.loads(near.out)["results"] == json.loads(canonical.out)["results"]


@pytest.mark.parametrize("d,big_d,fields,field,good,bad", [
    pytest.param(200.0001, 280, "clearance_group: C3, shaft: k5, housing: H7",
                 "mounting.clearance_group", "200.0001", "200 mm is above 200", id="200.0001"),
    pytest.param(2.99, 10, "initial_clearance: 10 µm, shaft: k5, housing: H7",
                 "mounting.shaft", "2.99 mm", "in metres", id="2.99mm-in-metres"),
])
def test_bore_range_messages_state_the_bore(cli, spec_file, d, big_d, fields, field, good,
                                            bad):
    line = refused(solve(cli, spec_file, ball(d, big_d, fields)), field)
    assert good in line and bad not in line


def test_empty_mounting_names_every_missing_field(cli, spec_file):
    run = solve(cli, spec_file, BLOCK.sub("mounting: {}\n", FITS, count=1))
    assert run.code == 2 and "clearance_group" in run.err, run.err




@pytest.mark.parametrize("fields,field", [
    pytest.param({"clearance_group": None, "initial_clearance": "2 mm"},
                 "mounting.initial_clearance", id="initial-clearance-2mm"),
    pytest.param({"bore_deviation": "-1 mm"}, "mounting.bore_deviation", id="bore-dev"),
    pytest.param({"outside_deviation": "1 m"}, "mounting.outside_deviation",
                 id="outside-dev"),
    pytest.param({"shaft": "41 mm"}, "mounting.shaft", id="shaft-1mm-over"),
    pytest.param({"inner_ring_temperature": "5000 degC"}, "mounting.inner_ring_temperature",
                 id="inner-ring-5000C"),
    pytest.param({"housing_temperature": "1e5 degC"}, "mounting.housing_temperature",
                 id="housing-100000C"),
    pytest.param({"roughness": "{shaft: 10 m}"}, "mounting.roughness.shaft", id="Rz-10m"),
])
def test_absurd_mounting_values_are_refused_naming_the_mounting_field(cli, spec_file,
                                                                      fields, field):
    refused(solve(cli, spec_file, mounted(**fields)), field)


@pytest.mark.parametrize("shaft_bore", ["39.995 mm", "39.999 mm"])
def test_thin_hollow_shaft_never_gives_a_negative_fit_pressure(cli, spec_file, shaft_bore):
    run = solve(cli, spec_file, mounted(shaft="p6", shaft_bore=shaft_bore))
    if run.code == 2:
        refused(run, "mounting.shaft_bore")
        return
    res = json.loads(run.out.splitlines()[0])["results"]
    assert min(v for k, v in res.items() if k.startswith(("fit_pressure", "inner_ring_hoop"))
               ) >= 0


# --- YAML oddities and combinations with other features ---

@pytest.mark.parametrize("value", ["[]", "C3", "''", "5 µm", "[C3, k5, H7]", "yes"])
def test_mounting_that_is_not_a_mapping(cli, spec_file, value):
    refused(solve(cli, spec_file, BLOCK.sub(f"mounting: {value}\n", FITS, count=1)),
            "mounting")


@pytest.mark.parametrize("text,field", [
    (mounted("operating_clearance: 10 µm\n"), "operating_clearance"),
    (BLOCK.sub("mounting: null\n", FITS, count=1), "operating_clearance"),
    (mounted().replace("method: iso-16281\n", ""), "mounting"),
    (mounted().replace("min_operating_clearance: 0 µm", "min_operating_clearance: 0 deg"),
     "limits.min_operating_clearance"),
    (BLOCK.sub("operating_clearance: 10 µm\n", FITS, count=1),
     "limits.min_operating_clearance"),
    (mounted("arrangement: back-to-back\ncontact_angle: 40 deg\nsetting: {preload: 300 N}\n",
             clearance_group=None, initial_clearance="10 µm")
     .replace("type: deep-groove", "type: angular-contact"), "mounting.initial_clearance"),
    (mounted("duty_cycle:\n  - {time: 50 %, radial_load: 3 kN}\n  - {time: 50 %, "
             "radial_load: 1 kN}\n").replace("radial_load: 3 kN\n", ""), "duty_cycle"),
])
def test_mounting_with_features_it_excludes(cli, spec_file, text, field):
    run = solve(cli, spec_file, text)
    clean(run)
    assert run.code == 2 and re.search(rf":\d+: {re.escape(field)}:", run.err), run.err


def test_check_lists_a_mounted_spec_and_a_bad_one(cli, spec_file):
    run = cli("check", spec_file(FITS, name="a.yaml"),
              spec_file(mounted(shaft="K5"), name="b.yaml"), "-j", "1")
    clean(run)
    assert run.code == 2 and "mounting.shaft" in run.out + run.err


PAIR_MOUNTED = (PAIR.replace("width: 16 mm", "width: 16 mm\nbore_diameter: 35 mm\n"
                             "outside_diameter: 62 mm")
                + "mounting: {clearance_group: C3, shaft: k5, housing: H7}\n")


def test_group_on_an_angular_contact_pair_says_its_setting_is_where_the_chain_starts(
        cli, spec_file):
    line = refused(solve(cli, spec_file, PAIR_MOUNTED), "mounting.clearance_group")
    assert "end_play" in line and "leave it out" in line


def test_a_tandem_pair_takes_no_mounting(cli, spec_file):
    text = PAIR_MOUNTED.replace("clearance_group: C3, ", "").replace(
        "arrangement: back-to-back", "arrangement: tandem")
    text = re.sub(r"^setting:.*\n(?:  .*\n)*", "", text, flags=re.M)
    line = refused(solve(cli, spec_file, text), "mounting")
    assert "leave mounting out" in line


# --- sweep, tolerance, report ---

def test_sweep_over_the_inner_ring_temperature(cli, spec_file):
    run = cli("sweep", spec_file(FITS), "--vary", "mounting.inner_ring_temperature="
              "20degC:150degC:5", "-r", "operating_clearance", "-f", "csv")
    clean(run)
    assert run.code == 0, run.err
    rows = list(csv.DictReader(io.StringIO(run.out)))
    values = [float(r["operating_clearance [m]"]) for r in rows]
    assert len(values) == 5 and all(math.isfinite(v) for v in values)
    assert values == sorted(values, reverse=True) and values[0] > 0 > values[-1]


@pytest.mark.parametrize("vary", ["shaft=k5:p6:3", "clearance_group=C2:C4:3",
                                  "shaft_bore=0mm:45mm:3", "bogus=1mm:2mm:3",
                                  "assembly_temperature=-300degC:20degC:3"])
def test_sweep_refuses_what_cannot_be_swept_and_keeps_the_output(cli, spec_file, tmp_path,
                                                                 vary):
    out = tmp_path / "keep.csv"
    out.write_text("keep")
    refused(cli("sweep", spec_file(FITS), "--vary", f"mounting.{vary}", "-o", out),
            "mounting." + vary.split("=")[0])
    assert out.read_text() == "keep"


def test_sweep_of_a_named_materials_property(cli, spec_file):
    spec = spec_file(mounted(shaft_material="steel"))
    refused(cli("sweep", spec, "--vary", "mounting.shaft_material.elastic_modulus="
                "70GPa:210GPa:3"), "mounting.shaft_material")


@pytest.mark.parametrize("methods", ["worst-case", "rss", "monte-carlo",
                                     "worst-case,rss,monte-carlo"])
def test_tolerance_study_of_the_five_bands(cli, spec_file, methods):
    run = cli("tolerance", spec_file(FITS), "-m", methods, "-n", "1000",
              "-r", "operating_clearance", "-f", "json")
    clean(run)
    # some assemblies are preloaded, below the 0 µm limit; RSS alone judges no margin
    assert run.code == (0 if methods == "rss" else 1), run.err
    record = json.loads(run.out.splitlines()[0])
    assert set(record["inputs"]) == {f"mounting.{n}" for n in (
        "clearance_group", "shaft", "housing", "bore_deviation", "outside_deviation")}
    study = record["results"]["operating_clearance"]
    solved = json.loads(cli("solve", spec_file(FITS), "-f", "json").out.splitlines()[0])
    if "worst_case" in study:  # the study's search finds the chain's corners
        assert study["worst_case"]["min"] == pytest.approx(
            solved["results"]["operating_clearance_min"], abs=1e-10)
        assert study["worst_case"]["max"] == pytest.approx(
            solved["results"]["operating_clearance_max"], abs=1e-10)
    if "rss" in study and "monte_carlo" in study:  # a linear chain: both give one σ
        assert study["rss"]["std"] == pytest.approx(study["monte_carlo"]["std"], rel=0.03)
    if "monte_carlo" in study:
        assert -12.9e-6 <= study["monte_carlo"]["min"] < 0 < study["monte_carlo"]["max"]
        assert 0.7 < record["yield"] < 0.9


def test_report_of_a_mounted_bearing(cli, spec_file, tmp_path):
    out = tmp_path / "out.html"
    run = cli("report", spec_file(FITS), "-o", out)
    clean(run)
    assert run.code == 0, run.err
    page = out.read_text(encoding="utf-8")
    assert "operating_clearance_min" in page and "k5" in page
    assert not re.search(r">\s*(nan|inf)\s*<", page)


def test_failing_report_leaves_output_and_spec_alone(cli, spec_file, tmp_path):
    out = tmp_path / "out.html"
    out.write_text("keep")
    refused(cli("report", spec_file(mounted(shaft="K5")), "-o", out), "mounting.shaft")
    assert out.read_text() == "keep"
    spec = spec_file(FITS, name="fits.yaml")
    run = cli("report", spec, "-o", spec)
    assert run.code == 2 and spec.read_text(encoding="utf-8") == FITS


# --- a bevel drive whose locating deep-groove bearing is given by its drawing ---

def drive(mounting: str) -> str:
    assert DRIVE.count("operating_clearance: 10 µm}") == 1
    return DRIVE.replace("operating_clearance: 10 µm}", f"mounting: {{{mounting}}}}}")


def test_drive_bearing_from_its_drawing(cli, spec_file):
    loose = results(cli, spec_file, drive("clearance_group: C3, shaft: k5, housing: H7"))
    tight = results(cli, spec_file, drive("clearance_group: C2, shaft: p6, housing: P7, "
                                          "inner_ring_temperature: 120 degC"))
    assert (tight["gear_bearing_2_reference_rating_life"]
            < loose["gear_bearing_2_reference_rating_life"])


@pytest.mark.parametrize("mounting", [f"clearance_group: {g}, shaft: {s}, housing: H7"
                                      for g, s in (("C3", "K5"), ("C3", "h13"), ("C1", "k5"))])
def test_drive_bearing_bad_class_names_the_bearing(cli, spec_file, mounting):
    refused(solve(cli, spec_file, drive(mounting)), "gear_bearings.2.mounting.")


def test_drive_bearing_with_both_clearance_and_mounting(cli, spec_file):
    text = DRIVE.replace("operating_clearance: 10 µm}", "operating_clearance: 10 µm, "
                         "mounting: {clearance_group: C3, shaft: k5, housing: H7}}")
    refused(solve(cli, spec_file, text), "gear_bearings.2.operating_clearance")


def test_drive_bearing_reports_its_operating_clearance(cli, spec_file):
    res = results(cli, spec_file, drive("clearance_group: C2, shaft: p6, housing: P7, "
                                        "inner_ring_temperature: 120 degC"))
    low, mid, high = (res[f"gear_bearing_2_operating_clearance{s}"] for s in ("_min", "", "_max"))
    assert low <= mid <= high < 0  # the tight drawing preloads it in every assembly
