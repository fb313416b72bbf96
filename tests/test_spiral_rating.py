"""The AGMA 2003 rating of spiral bevel pairs: the standard's own sample calculation
(ANSI/AGMA 2003-D19, Annex E, Table E.1), the lengthwise curvature factor K_x computed
here from its definition, and a Zerol pair rated as the straight one."""

from __future__ import annotations

import math

import pytest

from tests.conftest import ROOT, solve_json

SPIRAL = (ROOT / "specs" / "bevel-gears-spiral.yaml").read_text()
PSI = 6894.757293168361            # Pa
KSI = 1e3 * PSI
#: Rating results that do not depend on the direction of the forces.
RATING = ("bending_stress", "contact_stress", "bending_safety", "contact_safety",
          "gear_b_bending_stress", "gear_b_bending_safety", "gear_b_contact_safety",
          "bending_power_rating", "contact_power_rating")


def _solve(cli, spec_file, text: str) -> dict:
    (record,) = solve_json(cli, spec_file(text))
    return record["results"]


def test_agma_2003_annex_e_stresses(cli, spec_file):
    """ANSI/AGMA 2003-D19, Annex E (Table E.1), the spiral bevel sample: 14/39 teeth,
    Pd 5.6, F = 1.00 in, β = 35°, r_c = 4.5 in, T = 1440 lb·in at 1750 rpm, Qv 11,
    one member straddle, crowned, I = 0.109, J = 0.222 / 0.217. Printed:
    s_c = 149 384 psi, s_t = 18 194 psi (pinion) and 18 613 psi (gear), K_x = 1.0.

    The example is worked in U.S. units; the SI form's constants are rounded
    (K_s's 0.008339 per mm for 0.2132/25.4 = 0.008394, K_v's 200·v for 196.85 ft/min
    per m/s, C_p = 190 √MPa for 2290 √psi), which moves the stresses by under 0.05 %.
    """
    results = _solve(cli, spec_file, SPIRAL)
    assert results["lengthwise_curvature_factor"] == 1.0
    assert results["contact_stress"] == pytest.approx(149_384 * PSI, rel=1e-3)
    assert results["bending_stress"] == pytest.approx(18_194 * PSI, rel=1e-3)
    assert results["gear_b_bending_stress"] == pytest.approx(18_613 * PSI, rel=1e-3)


def test_agma_2003_annex_e_safeties(cli, spec_file):
    """Annex E's permissible stresses are s_wc = 200 000 / 212 000 psi and
    s_wt = 28 200 / 28 500 psi (pinion / gear), from the U.S. allowables of carburized
    grade 1 (200 ksi, 30 ksi) and the stress-cycle factors read off its charts:
    C_L = 1.0 / 1.06 and K_L = 0.94 / 0.95 at 10⁹ / 3.59·10⁸ cycles.

    bearingcalc rates with the SI table's allowables (1380 MPa, 205 MPa) and with
    K_L = 1.683·N^−0.0323, the lower edge of the chart's band (0.862 at 10⁹ cycles, where
    the Annex reads the upper edge, 0.94). Each safety, with those two numbers put back
    to the Annex's, is the Annex's s_w/s to 0.1 %; C_L, a formula in both, rounds to the
    printed value."""
    results = _solve(cli, spec_file, SPIRAL)
    cycles = {"pinion": 1e9, "gear": 1e9 * 14 / 39}
    c_l = {member: 3.4822 * n ** -0.0602 for member, n in cycles.items()}
    k_l = {member: 1.683 * n ** -0.0323 for member, n in cycles.items()}
    assert round(c_l["pinion"], 2) == 1.0 and round(c_l["gear"], 2) == 1.06
    contact_scale, bending_scale = 200 * KSI / 1380e6, 30 * KSI / 205e6
    printed_contact = {"pinion": (200_000, 1.0), "gear": (212_000, 1.06)}
    printed_bending = {"pinion": (28_200, 0.94, 18_194), "gear": (28_500, 0.95, 18_613)}
    keys = {"pinion": ("contact_safety", "bending_safety"),
            "gear": ("gear_b_contact_safety", "gear_b_bending_safety")}
    for member, (contact_key, bending_key) in keys.items():
        permissible, chart_c_l = printed_contact[member]
        ours = results[contact_key] * contact_scale * chart_c_l / c_l[member]
        assert ours == pytest.approx(permissible / 149_384, rel=1e-3), member
        permissible, chart_k_l, stress = printed_bending[member]
        ours = results[bending_key] * bending_scale * chart_k_l / k_l[member]
        assert ours == pytest.approx(permissible / stress, rel=1e-3), member


def _curvature(spiral_deg: float, cutter: float, mean_cone: float) -> float:
    """K_x from AGMA 2003's definition, written out for one design."""
    q = 0.279 / math.log10(math.sin(math.radians(spiral_deg)))
    return min(max(0.211 * (cutter / mean_cone) ** q + 0.789, 1.0), 1.15)


@pytest.mark.parametrize(("cutter_in", "spiral_deg"), [(3.0, 35.0), (2.5, 25.0),
                                                        (3.0, 45.0), (1.0, 35.0)])
def test_a_small_cutter_strengthens_the_root_by_k_x(cli, spec_file, cutter_in, spiral_deg):
    """A cutter smaller than the mean cone distance: K_x > 1 divides the bending stresses
    of both members, and leaves the contact stress alone. At 1 in the factor is at its
    bound, 1.15."""
    text = SPIRAL.replace("spiral_angle: 35 deg", f"spiral_angle: {spiral_deg} deg")
    base = _solve(cli, spec_file, text)
    small = _solve(cli, spec_file, text.replace("cutter_radius: 4.5 in",
                                                f"cutter_radius: {cutter_in} in"))
    expected = _curvature(spiral_deg, cutter_in * 0.0254, small["mean_cone_distance"])
    assert expected > 1.0
    assert small["lengthwise_curvature_factor"] == pytest.approx(expected, rel=1e-12)
    assert base["lengthwise_curvature_factor"] == 1.0
    for key in ("bending_stress", "gear_b_bending_stress"):
        assert base[key] / small[key] == pytest.approx(expected, rel=1e-12)
    assert small["contact_stress"] == base["contact_stress"]
    if cutter_in == 1.0:
        assert small["lengthwise_curvature_factor"] == 1.15


def test_k_x_falls_to_one_as_the_spiral_vanishes(cli, spec_file):
    """With a small cutter, K_x falls toward 1 as β_m does (slowly: q ∝ 1/log10 sin β_m),
    and is 1 at β_m = 0 (Zerol)."""
    small_cutter = SPIRAL.replace("cutter_radius: 4.5 in", "cutter_radius: 2 in")
    factors = [_solve(cli, spec_file, small_cutter.replace(
        "spiral_angle: 35 deg", f"spiral_angle: {angle} deg"))["lengthwise_curvature_factor"]
        for angle in (35, 10, 1, 1e-3, 1e-6, 0)]
    assert factors == sorted(factors, reverse=True) and factors[-1] == 1.0
    assert all(1.0 < factor <= 1.15 for factor in factors[:-1]), factors


def test_a_zerol_pair_is_rated_as_the_straight_pair(cli, spec_file):
    """Zerol teeth (β = 0) are rated as straight ones (K_x = 1), with or without a cutter
    radius."""
    straight = SPIRAL.replace("spiral_angle: 35 deg", "").replace(
        "hand: left", "").replace("rotation: counterclockwise", "").replace(
        "  cutter_radius: 4.5 in", "")
    zerol = SPIRAL.replace("spiral_angle: 35 deg", "spiral_angle: 0 deg")
    straight_results = _solve(cli, spec_file, straight)
    zerol_results = _solve(cli, spec_file, zerol)
    for key in RATING:
        assert zerol_results[key] == pytest.approx(straight_results[key], rel=1e-12), key


@pytest.mark.parametrize(("old", "new", "field"), [
    ("  cutter_radius: 4.5 in", "  # no cutter radius", "rating.cutter_radius"),
    ("cutter_radius: 4.5 in", "cutter_radius: -4.5 in", "rating.cutter_radius"),
    ("cutter_radius: 4.5 in", "cutter_radius: large", "rating.cutter_radius"),
    ("spiral_angle: 35 deg", "# a straight pair", "hand"),
])
def test_bad_spiral_rating_input_is_one_line(cli, spec_file, old, new, field):
    run = cli("solve", spec_file(SPIRAL.replace(old, new)))
    assert run.code == 2 and run.err.count("\n") == 1, run.err
    assert f": {field}: " in run.err, run.err


def test_a_cutter_radius_on_a_straight_pair_is_refused(cli, spec_file):
    text = (ROOT / "specs" / "bevel-gears-sizing.yaml").read_text().replace(
        "  crowned: false", "  crowned: false\n  cutter_radius: 4.5 in")
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1, run.err
    assert ": rating.cutter_radius: " in run.err and "spiral_angle" in run.err, run.err


def test_a_rated_spiral_pair_takes_a_duty_cycle(cli, spec_file):
    """Two bins at the example's own torque are the example: the same stresses, and the
    same safeties (the whole life at one load)."""
    text = SPIRAL.replace("limits:", "duty_cycle:\n  - {time: 60 %, torque: 162.698153799768 N*m}\n"
                          "  - {time: 40 %, torque: 162.698153799768 N*m}\nlimits:")
    cycle, single = _solve(cli, spec_file, text), _solve(cli, spec_file, SPIRAL)
    for key in ("bending_safety", "contact_safety", "lengthwise_curvature_factor"):
        assert cycle[key] == pytest.approx(single[key], rel=1e-12), key
    assert cycle["duty_2_bending_stress"] == single["bending_stress"]


def test_a_spiral_angle_study_warns_that_j_and_i_stay_typed(cli, spec_file):
    run = cli("sweep", spec_file(SPIRAL), "--vary", "spiral_angle=25deg:40deg:4",
              "--format", "csv")
    assert run.code == 0, run.err
    assert "spiral_angle" in run.err and "J and I" in run.err, run.err
