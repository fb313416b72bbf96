"""Geometry no bearing can have is refused with one line naming the field (and the
quantity tested, with its limit); geometry that is merely unusual is solved with a warning
that says why. Each threshold is checked against a computation of its own: the fill by
counting, the widths and crowns by plane geometry, the contact ellipse by Johnson's
equations solved with scipy (not the tool's Hertz solver)."""

from __future__ import annotations

import math

import pytest
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearingcalc.errors import SpecError
from bearingcalc.evaluation import Evaluation, evaluate_documents
from bearingcalc.models.yaml_loader import load_documents

CYLINDRICAL = """kind: rolling-bearing
type: cylindrical-roller
roller_count: 13
roller_diameter: 9 mm
roller_length: 9 mm
pitch_diameter: 46 mm
radial_load: 6 kN
speed: 3000 rpm
"""
SPHERICAL = """kind: rolling-bearing
type: spherical-roller
rows: 2
roller_count: 16
roller_diameter: 9 mm
roller_length: 12 mm
pitch_diameter: 70 mm
contact_angle: 10 deg
roller_profile_radius: 40 mm
raceway_radius: 41 mm
radial_load: 15 kN
speed: 1000 rpm
"""
TAPERED = """kind: rolling-bearing
type: tapered-roller
roller_count: 17
roller_diameter: 7.4 mm
roller_length: 12 mm
pitch_diameter: 46 mm
contact_angle: 14 deg
radial_load: 6 kN
axial_load: 3 kN
speed: 1500 rpm
"""
TAPERED_CATALOGUE = """kind: rolling-bearing
type: tapered-roller
dynamic_load_rating: 50 kN
static_load_rating: 60 kN
contact_angle: 14 deg
radial_load: 6 kN
axial_load: 3 kN
speed: 1500 rpm
"""


def outcome(text: str) -> Evaluation | SpecError:
    (result,) = evaluate_documents(load_documents("spec.yaml", text))
    return result


def with_fields(base: str, **fields: str) -> str:
    """``base`` with each field replaced (or added) as written."""
    rows = [row for row in base.splitlines() if row.split(":")[0] not in fields]
    return "\n".join([*rows, *(f"{key}: {value}" for key, value in fields.items())]) + "\n"


def refused(text: str, field: str) -> str:
    """The one line that refuses ``text``, which must name ``field``."""
    result = outcome(text)
    assert isinstance(result, SpecError), "solved, not refused"
    assert result.more == [], result.lines()
    assert result.field == field, str(result)
    assert "double precision" not in result.message
    return result.message


def solved(text: str) -> Evaluation:
    result = outcome(text)
    assert isinstance(result, Evaluation), str(result)
    return result


# The rollers within the rings' width -------------------------------------------------

def test_a_roller_longer_than_the_ring_is_wide_is_refused() -> None:
    message = refused(with_fields(CYLINDRICAL, roller_length="40 mm", width="16 mm"),
                      "roller_length")
    assert "40 mm" in message and "16 mm" in message


def test_a_roller_just_within_the_width_is_taken() -> None:
    solved(with_fields(CYLINDRICAL, roller_length="15.9 mm", width="16 mm"))


@pytest.mark.parametrize(("length", "fits"), [("7.9 mm", True), ("8.1 mm", False)])
def test_two_rows_of_rollers_lie_side_by_side_in_the_width(length: str, fits: bool) -> None:
    text = with_fields(CYLINDRICAL, rows="2", roller_length=length, width="16 mm")
    if fits:
        solved(text)
    else:
        assert "2·Lwe = 16.2 mm" in refused(text, "roller_length")


def test_a_tapered_roller_is_measured_along_the_axis() -> None:
    # 12 mm at 14 deg reaches 12·cos 14° = 11.64 mm along the axis.
    along = 12 * math.cos(math.radians(14))
    solved(with_fields(TAPERED, width=f"{along * 1.001:.6f} mm"))
    message = refused(with_fields(TAPERED, width=f"{along * 0.999:.6f} mm"), "roller_length")
    assert f"{along:.4g} mm" in message


def test_a_ball_wider_than_the_ring_is_refused() -> None:
    text = """kind: rolling-bearing
ball_count: 9
ball_diameter: 7.9 mm
pitch_diameter: 38.5 mm
width: 7 mm
radial_load: 2 kN
speed: 1500 rpm
"""
    refused(text, "ball_diameter")


# A spherical roller's crown ------------------------------------------------------------

def test_a_crown_radius_below_half_the_length_is_refused() -> None:
    message = refused(with_fields(SPHERICAL, roller_profile_radius="2 mm"),
                      "roller_profile_radius")
    assert "Lwe/2 = 6 mm" in message


def test_a_crown_that_leaves_no_roller_at_its_ends_is_refused() -> None:
    # R = 6.5 mm over 12 mm drops R − √(R² − 6²) = 4 mm: below the 4.5 mm radius, so a
    # roller of 9 mm keeps its ends; one of 7.9 mm (3.95 mm) does not.
    drop = 6.5 - math.sqrt(6.5 ** 2 - 6 ** 2)
    assert drop == pytest.approx(4.0, rel=1e-12)
    fine = with_fields(SPHERICAL, roller_profile_radius="6.5 mm", raceway_radius="50 mm")
    solved(fine)
    message = refused(with_fields(fine, roller_diameter="7.9 mm"), "roller_profile_radius")
    assert "drops 4 mm" in message


# A crowned roller's contact ellipse against its length -----------------------------------

def _semi_major(load: float, across: float, rolling: float, modulus: float,
                poisson: float) -> float:
    """Johnson, *Contact Mechanics* (1985) §3.4, eqs. 3.69–3.70, solved here by brentq on
    the eccentricity: A and B are the half curvature sums along the ellipse's major and
    minor axes, A = p0·b·(K − E)/(E*·e²·a²), B = p0·b·((a/b)²E − K)/(E*·e²·a²)."""
    a_sum, b_sum = across / 2, rolling / 2
    e_star = modulus / (2 * (1 - poisson ** 2))

    def ratio(m: float) -> float:
        k, e = ellipk(m), ellipe(m)
        return (e / (1 - m) - k) / (k - e) - b_sum / a_sum

    m = brentq(ratio, 1e-12, 1 - 1e-15, xtol=1e-300, rtol=1e-15, maxiter=500)
    k, e = ellipk(m), ellipe(m)
    return (3 * load * (k - e) / (2 * math.pi * e_star * m * a_sum)) ** (1 / 3)


def _crowned(raceway: float) -> float:
    """The longer semi-major axis [m] of the two contacts of the SPHERICAL roller with
    this raceway radius [m], from its geometry alone: the most loaded roller takes
    Q = 5·Fr/(i·Z·cosα) (Stribeck, ISO 76's basis); the inner race is convex in the
    rolling direction, the outer concave."""
    dwe, dpw, alpha, crown = 9e-3, 70e-3, math.radians(10), 40e-3
    load = 5 * 15e3 / (2 * 16 * math.cos(alpha))
    inner = 2 * math.cos(alpha) / (dpw - dwe * math.cos(alpha))
    outer = -2 * math.cos(alpha) / (dpw + dwe * math.cos(alpha))
    return max(_semi_major(load, 1 / crown - 1 / raceway, 2 / dwe + race, 2.1e11, 0.3)
               for race in (inner, outer))


def _raceway_where(semi_major: float) -> float:
    return brentq(lambda r: _crowned(r) - semi_major, 40.00001e-3, 60e-3, xtol=1e-15)


def test_the_example_raceway_keeps_its_ellipse_on_the_roller() -> None:
    result = solved(SPHERICAL)
    assert _crowned(41e-3) < 6e-3
    assert not any("ellipse" in note for note in result.warnings)


def test_an_ellipse_longer_than_the_roller_is_refused() -> None:
    # A raceway radius a hair above a 40 mm crown: 40.0001 mm.
    assert _crowned(40.0001e-3) > 0.1
    message = refused(with_fields(SPHERICAL, raceway_radius="40.0001 mm"), "raceway_radius")
    assert "ellipse" in message and "got" not in message


def test_the_ellipse_thresholds_fall_where_johnson_puts_them() -> None:
    whole = _raceway_where(12e-3)    # a = Lwe: refused below this raceway radius
    half = _raceway_where(6e-3)      # a = Lwe/2: a warning below this one
    assert whole < half < 41e-3
    steel = with_fields(SPHERICAL, material="{elastic_modulus: 210 GPa, poisson_ratio: 0.3}")
    refused(with_fields(steel, raceway_radius=f"{whole * 1e3 * (1 - 1e-4):.9f} mm"),
            "raceway_radius")
    for radius, warned in ((whole * (1 + 1e-4), True), (half * (1 - 1e-4), True),
                           (half * (1 + 1e-4), False)):
        result = solved(with_fields(steel, raceway_radius=f"{radius * 1e3:.9f} mm"))
        assert any("ellipse is longer than the roller" in note
                   for note in result.warnings) is warned, radius


# Load factors a catalogue never gives ---------------------------------------------------

def test_an_e_above_every_radial_bearing_s_is_refused() -> None:
    message = refused(with_fields(TAPERED, load_factors="{e: 12, y: 1.6}"), "load_factors.e")
    assert "1.5" in message


@pytest.mark.parametrize("e", ["0.37", "1.5"])
def test_an_e_within_iso_281_s_is_taken(e: str) -> None:
    solved(with_fields(TAPERED, load_factors=f"{{e: {e}, y: 1.6}}"))


def test_an_x_of_zero_that_drops_the_radial_load_is_refused() -> None:
    text = with_fields(TAPERED_CATALOGUE, type="angular-contact", contact_angle="40 deg",
                       load_factors="{x: 0, y: 0.57, e: 1.14}")
    refused(text, "load_factors.x")


def test_a_y2_of_zero_that_drops_the_axial_load_is_refused() -> None:
    text = with_fields(TAPERED_CATALOGUE, arrangement="back-to-back",
                       load_factors="{e: 0.37, y1: 1.8, y2: 0}")
    refused(text, "load_factors.y2")


# Angles and loads that leave the formulas ----------------------------------------------

@pytest.mark.parametrize("bearing_type", ["tapered-roller", "spherical-roller"])
def test_inclined_rollers_at_zero_degrees_are_refused(bearing_type: str) -> None:
    message = refused(with_fields(TAPERED_CATALOGUE, type=bearing_type,
                                  contact_angle="0 deg"), "contact_angle")
    assert "inclined" in message


def test_a_spherical_bearing_from_its_geometry_at_zero_degrees_names_the_angle() -> None:
    refused(with_fields(SPHERICAL, contact_angle="0 deg", axial_load="2 kN"),
            "contact_angle")


def test_a_shallow_angle_is_solved_with_a_warning() -> None:
    result = solved(with_fields(TAPERED_CATALOGUE, contact_angle="2 deg"))
    note = next(note for note in result.warnings if "contact_angle 2 deg" in note)
    assert f"{0.4 / math.tan(math.radians(2)):.3g}" in note  # Y = 0.4·cotα


def test_a_straight_roller_bearing_without_radial_load_names_the_radial_load() -> None:
    message = refused(with_fields(CYLINDRICAL, radial_load="0 kN", axial_load="2 kN"),
                      "radial_load")
    assert "P = Fr" in message


# Long rollers, the fill, the size ratio ------------------------------------------------

NEEDLE = """kind: rolling-bearing
type: needle-roller
roller_count: 20
roller_diameter: 3 mm
roller_length: 20 mm
pitch_diameter: 30 mm
radial_load: 6 kN
speed: 1500 rpm
"""


def test_needles_longer_than_two_and_a_half_diameters_are_warned_of() -> None:
    notes = solved(NEEDLE).warnings
    assert any("2.5·Dwe = 7.5 mm" in note and "7.1.1" in note for note in notes), notes


@pytest.mark.parametrize("text", [with_fields(NEEDLE, roller_length="7.5 mm"),
                                  with_fields(NEEDLE, dynamic_load_rating="30 kN")])
def test_no_warning_at_two_and_a_half_or_with_the_catalogue_s_rating(text: str) -> None:
    assert not any("2.5·Dwe" in note for note in solved(text).warnings)


def test_the_fill_message_gives_the_fill_and_its_limit() -> None:
    message = refused(with_fields(CYLINDRICAL, roller_count="30"), "roller_count")
    fill = 30 * math.asin(9 / 46)
    most = max(z for z in range(1, 100) if z * math.asin(9 / 46) <= math.pi)
    assert f"= {fill:.4g}" in message and f"π = {math.pi:.4g}" in message
    assert f"at most {most} fit" in message
    assert "got 30" not in message


def test_rollers_that_just_fit_are_taken() -> None:
    most = max(z for z in range(1, 100) if z * math.asin(9 / 46) <= math.pi)
    solved(with_fields(CYLINDRICAL, roller_count=str(most)))


def test_a_roller_too_small_for_the_fc_table_is_refused_with_its_gamma() -> None:
    message = refused(with_fields(CYLINDRICAL, roller_diameter="0.3 mm"), "roller_diameter")
    assert f"{0.3 / 46:.4g}" in message and "0.01" in message


def test_the_solver_s_fit_reason_quotes_no_value_of_the_count() -> None:
    # Studies see the solver's reasons: the count alone is not what the fill tests.
    from bearingcalc.core.common import DerivedTest
    from bearingcalc.kinds import KINDS

    reasons = KINDS["rolling-bearing"].status_reasons
    fits = [why for field, why in reasons.values() if "do not fit" in why]
    assert fits and all(isinstance(why, DerivedTest) for why in fits)


@pytest.mark.parametrize(("pitch", "fits"), [("31.5 mm", False), ("39.5 mm", True),
                                              ("46 mm", True), ("52.5 mm", True),
                                              ("60.5 mm", False)])
def test_the_rollers_lie_between_the_rings(pitch: str, fits: bool) -> None:
    # 9 mm rollers in rings of 30 and 62 mm: the pitch circle from 39 to 53 mm.
    text = with_fields(CYLINDRICAL, pitch_diameter=pitch, bore_diameter="30 mm",
                       outside_diameter="62 mm")
    if fits:
        solved(text)
    else:
        assert "pitch circle lies nearer" in refused(text, "pitch_diameter")
