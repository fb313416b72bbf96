"""kind: bevel-drive with a matched pair as one position of a locating-floating shaft:
rated as the pair, as ``kind: rolling-bearing`` rates the same pair under the same loads,
and against ISO 281 by hand (the pair's C = 2^(7/9)·C of one roller bearing, its P by the
catalogue's double-row factors on either side of e)."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_json

REL = 1e-9
#: A 30206-size tapered roller bearing, as the rolling-bearing template gives it: one
#: bearing's C and C0, the pair's e, Y1, Y2, Y0.
C, C0, E, Y1, Y2, Y0 = 40.2e3, 44e3, 0.37, 1.8, 2.7, 1.8
PAIR = ("type: tapered-roller, arrangement: back-to-back, dynamic_load_rating: 40.2 kN, "
        "static_load_rating: 44 kN, contact_angle: 14 deg, load_factors: {e: 0.37, y1: 1.8, "
        "y2: 2.7, y0: 1.8}, bore_diameter: 30 mm, outside_diameter: 62 mm")
CYLINDRICAL = ("type: cylindrical-roller, dynamic_load_rating: 44 kN, static_load_rating: "
               "36.5 kN, bore_diameter: 30 mm, outside_diameter: 62 mm")
TAPERED = ("type: tapered-roller, dynamic_load_rating: 32.5 kN, static_load_rating: 32.5 kN, "
           "contact_angle: 14 deg, load_factors: {e: 0.37, y: 1.6, y0: 0.9}, "
           "bore_diameter: 25 mm, outside_diameter: 52 mm")
PINION_TEETH, GEAR_TEETH, SPEED_RPM = 13, 43, 1500.0


def _drive(pinion: str, gear: str, spiral: bool = True) -> str:
    """A 13/43 drive (its pair not rated), with the shafts' bearing blocks given."""
    return f"""kind: bevel-drive
name: matched pair locating
gear_a: {{teeth: {PINION_TEETH}}}
gear_b: {{teeth: {GEAR_TEETH}}}
module: 4 mm
shaft_angle: 90 deg
face_width: 25 mm
pressure_angle: 20 deg
{"spiral_angle: 35 deg" if spiral else ""}
{"hand: left" if spiral else ""}
{"rotation: counterclockwise" if spiral else ""}
input_speed: {SPEED_RPM} rpm
torque: 120 N*m
{pinion}
{gear}
lubrication: {{viscosity: 68 mm^2/s}}
contamination_factor: 0.5
limits:
  min_rating_life: 4000 h
"""


ADJUSTED_PINION = f"""pinion_arrangement: back-to-back
pinion_bearings:
  - {{position: 85 mm, {TAPERED}}}
  - {{position: 150 mm, {TAPERED}}}"""
PAIR_LOCATING_GEAR = f"""gear_bearings:
  - {{position: 20 mm, {CYLINDRICAL}}}
  - {{position: 120 mm, locating: true, {PAIR}}}"""
PAIR_LOCATING_PINION = f"""pinion_bearings:
  - {{position: 85 mm, locating: true, {PAIR}}}
  - {{position: 150 mm, {CYLINDRICAL}}}"""


def _alone(radial: float, axial: float, speed_rpm: float) -> str:
    """The same pair as a rolling-bearing spec, with the drive's loads on it."""
    return (f"{{kind: rolling-bearing, name: the pair alone, {PAIR}, radial_load: {radial!r} N, "
            f"axial_load: {axial!r} N, speed: {speed_rpm!r} rpm, lubrication: {{viscosity: "
            "68 mm^2/s}, contamination_factor: 0.5}\n")


CASES = {
    # the gear shaft's locating pair: spiral thrust large against its radial load
    "gear pair, Fa/Fr > e": (_drive(ADJUSTED_PINION, PAIR_LOCATING_GEAR), "gear_bearing_2",
                             SPEED_RPM * PINION_TEETH / GEAR_TEETH),
    # the pinion's locating pair: a straight pinion's small thrust, Fa/Fr <= e
    "pinion pair, Fa/Fr <= e": (_drive(PAIR_LOCATING_PINION, PAIR_LOCATING_GEAR,
                                       spiral=False), "pinion_bearing_1", SPEED_RPM),
}


@pytest.mark.parametrize("case", list(CASES))
def test_a_locating_matched_pair_is_rated_as_the_same_pair_alone(case, cli, spec_file):
    text, name, speed_rpm = CASES[case]
    (drive,) = solve_json(cli, spec_file(text, "drive.yaml"))
    results = drive["results"]
    radial, axial = results[f"{name}_radial_load"], results[f"{name}_axial_load"]
    assert radial > 0 and axial > 0
    (alone,) = solve_json(cli, spec_file(_alone(radial, axial, speed_rpm), "alone.yaml"))
    for key in ("equivalent_dynamic_load", "basic_rating_life", "modified_rating_life",
                "static_safety_factor"):
        assert math.isclose(results[f"{name}_{key}"], alone["results"][key], rel_tol=REL), key

    # ISO 281 by hand: the pair as one double-row bearing (§7.1, i = 2 of the same
    # bearing: C_pair = 2^(7/9)·C), P by the catalogue's pair factors on either side of e.
    if axial / radial <= E:
        assert case.endswith("<= e")
        load = radial + Y1 * axial
    else:
        assert case.endswith("> e")
        load = 0.67 * radial + Y2 * axial
    pair_rating = 2 ** (7 / 9) * C
    life = (pair_rating / load) ** (10 / 3) * 1e6 / (speed_rpm / 60.0)
    assert math.isclose(results[f"{name}_equivalent_dynamic_load"], load, rel_tol=REL)
    assert math.isclose(results[f"{name}_basic_rating_life"], life, rel_tol=REL)
    # ISO 76: the pair's C0 is twice one bearing's, P0 = Fr + Y0·Fa
    assert math.isclose(results[f"{name}_static_safety_factor"],
                        2 * C0 / (radial + Y0 * axial), rel_tol=REL)
    # a back-to-back pair carries thrust both ways: no one-way warning for it
    assert not any("locates its shaft" in note for note in drive["warnings"])


def test_a_single_tapered_bearing_locating_still_gets_the_one_way_warning(cli, spec_file):
    single = PAIR_LOCATING_GEAR.replace("arrangement: back-to-back, ", "").replace(
        "load_factors: {e: 0.37, y1: 1.8, y2: 2.7, y0: 1.8}", "load_factors: {e: 0.37, y: 1.6, "
        "y0: 0.9}")
    (drive,) = solve_json(cli, spec_file(_drive(ADJUSTED_PINION, single), "drive.yaml"))
    assert any(note.startswith("gear_bearing_2 locates its shaft") for note in drive["warnings"])


def test_a_matched_pair_over_a_duty_cycle_is_rated_as_the_pair(cli, spec_file):
    """The pair's life over the bins, 1/L = Σ tᵢ/Lᵢ over the bins that turn, from each
    bin's own solve."""
    base = _drive(ADJUSTED_PINION, PAIR_LOCATING_GEAR)
    bins = [("60 %", "120 N*m", SPEED_RPM), ("30 %", "160 N*m", SPEED_RPM),
            ("10 %", "200 N*m", 0.0)]
    cycle = base + "duty_cycle:\n" + "".join(
        f"  - {{time: {time}, torque: {torque}, input_speed: {speed} rpm}}\n"
        for time, torque, speed in bins)
    (record,) = solve_json(cli, spec_file(cycle, "cycle.yaml"))
    damage = 0.0
    for k, (time, torque, speed) in enumerate(bins):
        if speed == 0:
            continue
        one = base.replace("torque: 120 N*m", f"torque: {torque}")
        (point,) = solve_json(cli, spec_file(one, f"bin{k}.yaml"))
        life = point["results"]["gear_bearing_2_modified_rating_life"]
        damage += float(time.split()[0]) / 100 / life
    # the bin at rest does no damage, and its time counts in the life
    assert math.isclose(record["results"]["gear_bearing_2_modified_rating_life"],
                        1.0 / damage, rel_tol=REL)


def test_a_pair_entry_on_an_adjusted_shaft_is_refused_in_one_line(cli, spec_file):
    tandem = ADJUSTED_PINION.replace("{position: 85 mm, ", "{position: 85 mm, arrangement: "
                                     "tandem, ", 1)
    path = spec_file(_drive(tandem, PAIR_LOCATING_GEAR), "drive.yaml")
    run = cli("solve", path)
    assert run.code == 2
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "pinion_bearings.1.arrangement" in lines[0]
    assert lines[0].startswith(f"{path}:") and "locating-floating" in lines[0]
