"""An adjusted pair's end play as mounted (a pair's or a drive's shaft's ``mounting``):
the temperatures' share against the closed form written here from the geometry of a
cone in its cup (Timken, Engineering Manual, tapered roller bearings' setting), the
apex rule (a back-to-back pair whose apexes meet keeps its setting as the shaft warms),
the fits' share against Lamé's closed forms for rings on a solid seat and in an
unbounded housing of their own material (the raceway moves by the interference times
d/F, E/D), the solver's loads equal to the same pair set directly at the operating end
play, a tolerance study of the drive's pinion pair with the three methods, and each
bad combination one line."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from tests.conftest import ROOT, solve_json
from tests.mounted_specs import TAPERED_ROLLERS, refused_lines

#: The tapered bearing of TAPERED_ROLLERS: pitch diameter, roller diameter, cup angle.
DPW, DWE, ALPHA = 45e-3, 7.5e-3, math.radians(14.0)
BORE, OUTSIDE = 30e-3, 62e-3


def pair(arrangement: str, mounting: str, setting: str = "end_play: 40 µm",
         spacing: str = "pair_spacing: 80 mm") -> str:
    return f"""kind: rolling-bearing
type: tapered-roller
arrangement: {arrangement}
method: iso-16281
{TAPERED_ROLLERS}width: 17.25 mm
{spacing}
bore_diameter: 30 mm
outside_diameter: 62 mm
setting: {{{setting}}}
mounting:
{mounting}
radial_load: 6 kN
axial_load: 2 kN
speed: 1500 rpm
"""


def results(cli, spec_file, text: str) -> dict:
    return solve_json(cli, spec_file(text))[0]["results"]


def material(modulus: float, poisson: float, expansion: float) -> str:
    return (f"{{elastic_modulus: {modulus / 1e9:g} GPa, poisson_ratio: {poisson:g}, "
            f"thermal_expansion: {expansion:g} 1/K}}")


@pytest.mark.parametrize("arrangement,sign", [("back-to-back", -1.0),
                                              ("face-to-face", 1.0)])
def test_the_temperatures_take_the_closed_form_end_play(cli, spec_file, arrangement, sign):
    """Loose fits (f6 on the shaft, G7 in the housing, loose at every temperature here):
    only the rings' and seats' growth moves the setting. Each bearing's raceways part
    radially by α_r·Dpw·(ΔT_i − ΔT_o), which closes the cone in its cup along the axis
    by that over 2·tan α; the shaft grows α_s·ΔT_s·L against the housing's α_h·ΔT_h·L
    between the rollers, L the pressure centres' distance less (back-to-back) or plus
    (face-to-face) 2·(Dpw/2)·tan α. Face-to-face the shaft's growth pushes the cones into
    their cups, back-to-back it draws them out."""
    ring, shaft, housing = 11e-6, 12e-6, 23e-6
    t0, t_inner, t_outer, t_shaft, t_housing = 20.0, 80.0, 60.0, 85.0, 50.0
    mounting = (f"  shaft: f6\n  housing: G7\n  shaft_material: {material(210e9, 0.3, shaft)}"
                f"\n  housing_material: {material(70e9, 0.33, housing)}\n"
                f"  ring_thermal_expansion: {ring} 1/K\n  assembly_temperature: {t0} degC\n"
                f"  inner_ring_temperature: {t_inner} degC\n"
                f"  outer_ring_temperature: {t_outer} degC\n"
                f"  shaft_temperature: {t_shaft} degC\n"
                f"  housing_temperature: {t_housing} degC")
    found = results(cli, spec_file, pair(arrangement, mounting))
    assert found["fit_pressure_inner_max"] == 0.0 and found["fit_pressure_outer_max"] == 0.0
    radial = ring * DPW * ((t_inner - t0) - (t_outer - t0)) / (2.0 * math.tan(ALPHA))
    spread = 80e-3 + sign * 2.0 * (DPW / 2.0) * math.tan(ALPHA)
    axial = sign * (shaft * (t_shaft - t0) - housing * (t_housing - t0)) * spread
    expected = 2.0 * radial + axial
    assert found["end_play_change_thermal"] == pytest.approx(expected, rel=1e-12)
    assert found["end_play_reduction_fit"] == 0.0
    assert found["operating_end_play"] == pytest.approx(40e-6 - expected, rel=1e-12)


def test_a_back_to_back_pair_whose_apexes_meet_keeps_its_setting(cli, spec_file):
    """One material throughout, each ring at its seat's temperature: the shaft 70 K
    warmer than the housing scales the inner parts about the apex they share, and the
    setting does not move (Timken's apex rule), though each term alone is some 60 µm."""
    apexes_meet = DPW / math.tan(ALPHA) + DPW * math.tan(ALPHA)
    mounting = ("  shaft: k5\n  housing: M7\n  inner_ring_temperature: 90 degC\n"
                "  outer_ring_temperature: 20 degC\n  ring_thermal_expansion: 11.5e-6 1/K")
    text = pair("back-to-back", mounting, spacing=f"pair_spacing: {apexes_meet * 1e3!r} mm")
    found = results(cli, spec_file, text)
    assert abs(found["end_play_change_thermal"]) < 1e-9 * 60e-6
    moved = results(cli, spec_file, text.replace(f"{apexes_meet * 1e3!r} mm", "100 mm"))
    assert abs(moved["end_play_change_thermal"]) > 1e-6


def test_the_fits_take_lames_closed_form_from_a_bench_setting(cli, spec_file):
    """Seats of the rings' own steel, a solid shaft and an unbounded housing: the inner
    raceway F grows by the interference times d/F and the outer E shrinks by the
    interference times E/D (Lamé, plane stress), F and E = Dpw ∓ Dwe·cos α; each
    bearing's cone moves that over 2·tan α into its cup."""
    steel = material(207.5e9, 0.3, 11.5e-6)
    mounting = (f"  shaft: 30.020 mm\n  housing: 61.980 mm\n  bore_deviation: -6 µm\n"
                f"  outside_deviation: -5 µm\n  shaft_material: {steel}\n"
                f"  housing_material: {steel}")
    found = results(cli, spec_file, pair("face-to-face", mounting,
                                         "end_play: 100 µm, stage: bench"))
    inner, outer = 30.020e-3 - (BORE - 6e-6), (OUTSIDE - 5e-6) - 61.980e-3
    f, e = DPW - DWE * math.cos(ALPHA), DPW + DWE * math.cos(ALPHA)
    per_bearing = (inner * (BORE - 6e-6) / f + outer * e / (OUTSIDE - 5e-6)) / (
        2.0 * math.tan(ALPHA))
    assert found["end_play_reduction_fit"] == pytest.approx(2.0 * per_bearing, rel=1e-12)
    assert found["end_play_change_thermal"] == 0.0
    mounted = results(cli, spec_file, pair("face-to-face", mounting))
    assert mounted["end_play_reduction_fit"] == 0.0


BENCH_FITS = ("  shaft: m5\n  housing: N7\n  inner_ring_temperature: 70 degC\n"
              "  outer_ring_temperature: 55 degC")


@pytest.mark.parametrize("setting", ["end_play: 60 µm, stage: bench", "preload: 1 kN"])
def test_the_pair_is_solved_at_its_operating_end_play(cli, spec_file, setting):
    """The pair with its mounting carries the loads of the same pair set directly at the
    operating end play the chain gives."""
    mounted = results(cli, spec_file, pair("back-to-back", BENCH_FITS, setting))
    direct = results(cli, spec_file, pair("back-to-back", "  {}", "end_play: "
                                          f"{mounted['operating_end_play'] * 1e6!r} µm")
                     .replace("mounting:\n  {}\n", ""))
    for key in ("preload_force", "max_element_load", "ring_displacement_axial",
                "reference_rating_life"):
        assert mounted[key] == pytest.approx(direct[key], rel=1e-9, abs=1e-15), key
    assert mounted["operating_end_play_min"] <= mounted["operating_end_play"] \
        <= mounted["operating_end_play_max"]


DRIVE = (ROOT / "specs" / "bevel-drive-mounted.yaml").read_text(encoding="utf-8")


def drive(setting: str = "{end_play: 60 µm, stage: bench}",
          first: str = BENCH_FITS, second: str = BENCH_FITS) -> str:
    text = DRIVE.replace("pinion_setting: {preload: 1 kN}", f"pinion_setting: {setting}")
    parts = text.split("width: 17.25 mm}", 2)
    fits = [", mounting: {" + ", ".join(line.strip() for line in m.splitlines()) + "}"
            if m else "" for m in (first, second)]
    return (parts[0] + f"width: 17.25 mm{fits[0]}}}" + parts[1]
            + f"width: 17.25 mm{fits[1]}}}" + parts[2])


def test_a_tolerance_study_of_the_drives_pinion_pair_ranks_the_chain(cli, spec_file):
    """Worst case, RSS and Monte Carlo over both pinion bearings' fits and tolerances:
    the worst case is solve's extremes over the bands, the Monte Carlo stays inside it,
    and RSS ranks every link of both bearings, the housing's N7 (30 µm wide) first."""
    path = spec_file(drive())
    solved = solve_json(cli, path)[0]["results"]
    run = cli("tolerance", path, "-r", "pinion_operating_end_play", "-n", "256",
              "--format", "json")
    assert run.code in (0, 1), run.err
    study = json.loads(run.out)["results"]["pinion_operating_end_play"]
    worst = study["worst_case"]
    assert worst["min"] == pytest.approx(solved["pinion_operating_end_play_min"], rel=1e-9)
    assert worst["max"] == pytest.approx(solved["pinion_operating_end_play_max"], rel=1e-9)
    carlo = study["monte_carlo"]
    assert worst["min"] <= carlo["min"] < carlo["max"] <= worst["max"]
    shares = study["rss"]["contributions"]
    links = {f"pinion_bearings.{i}.mounting.{field}" for i in (1, 2) for field in (
        "shaft", "housing", "bore_deviation", "outside_deviation")}
    assert set(shares) == links
    assert max(shares, key=shares.get).endswith("mounting.housing")
    assert sum(shares.values()) == pytest.approx(1.0, rel=1e-9)


@pytest.mark.parametrize("text,field", [
    (drive(second=""), "pinion_bearings.2.mounting"),
    (drive(second=BENCH_FITS + "\n  housing_material: aluminium"),
     "pinion_bearings.2.mounting.housing_material"),
    (drive(first="", second=""), "pinion_setting.stage"),
    (drive(first=BENCH_FITS + "\n  clearance_group: C3"),
     "pinion_bearings.1.mounting.clearance_group"),
    (pair("back-to-back", "  initial_clearance: 10 µm\n  shaft: k5\n  housing: M7"),
     "mounting.initial_clearance"),
    (pair("back-to-back", "  {}", "end_play: 10 µm, stage: bench")
     .replace("mounting:\n  {}\n", ""), "setting.stage"),
    (pair("back-to-back", "  shaft: k5\n  housing: M7", "end_play: 10 µm, stage: shop"),
     "setting.stage"),
])
def test_a_pairs_mounting_refused_in_one_line(cli, spec_file, text, field):
    lines = refused_lines(cli, spec_file, text)
    assert len(lines) == 1 and f": {field}:" in lines[0], lines


def test_the_example_spec_of_a_pinion_pair_as_mounted(cli):
    """The shipped example solves, its setting's results in its record."""
    path = Path(ROOT / "specs" / "bevel-drive-mounted-fits.yaml")
    found = solve_json(cli, path)[0]["results"]
    assert found["pinion_operating_end_play"] < 60e-6
    assert found["pinion_end_play_reduction_fit"] > 0


def test_a_sweep_of_one_bearings_temperature_moves_the_pairs_end_play(cli, spec_file):
    """One bearing's ring warmer, the other's as written: the shaft's mean temperature
    follows, and the end play falls as the cone grows."""
    run = cli("sweep", spec_file(drive()), "--vary",
              "pinion_bearings.1.mounting.inner_ring_temperature=20degC:120degC:3",
              "-f", "json")
    assert run.code in (0, 1), run.err
    rows = [json.loads(line) for line in run.out.splitlines()]
    end_play = [row["results"]["pinion_operating_end_play"] for row in rows]
    assert len(end_play) == 3 and end_play[0] > end_play[1] > end_play[2]


@pytest.mark.parametrize("text,field", [
    (pair("back-to-back", BENCH_FITS) + "limits: {min_operating_clearance: 0 µm}\n",
     "limits.min_operating_clearance"),
    (pair("face-to-face", BENCH_FITS, spacing="pair_spacing: 1 mm"), "pair_spacing"),
    (drive().replace("position: 150 mm", "position: 82 mm"), "pinion_bearings.2.position"),
])
def test_a_limit_or_a_spacing_a_pair_cannot_take_is_one_line(cli, spec_file, text, field):
    """A pair has no radial clearance to judge; two bearings closer than side by side
    overlap (face-to-face B − 2c, here 6 mm; a drive's back-to-back pair 17.25 mm plus
    2c between its pressure centres)."""
    lines = refused_lines(cli, spec_file, text)
    assert len(lines) == 1 and f": {field}:" in lines[0], lines
