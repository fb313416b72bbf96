"""Quantity parsing: the fast unit table agrees with pint, and bad quantities are refused."""

from __future__ import annotations

import json
import math

import pytest

from bearingcalc.units import (
    ANGLE,
    ANGULAR_ACCEL,
    ANGULAR_SPEED,
    COMMON_UNITS,
    DENSITY,
    DIMENSIONS,
    DISPLAY_UNITS,
    FORCE,
    KINEMATIC_VISCOSITY,
    LENGTH,
    POWER,
    RPM_NOTATIONS,
    STRESS,
    TEMPERATURE,
    TIME,
    TORQUE,
    UnitError,
    make_registry,
    parse_quantity,
)
from tests.conftest import ROOT

UREG = make_registry()


@pytest.mark.parametrize("unit", sorted(COMMON_UNITS))
def test_every_fast_path_unit_equals_pints_own_conversion(unit):
    root, _ = COMMON_UNITS[unit]
    factor, pint_root = UREG.get_root_units(UREG.parse_units(
        unit.replace("²", "**2").replace("^", "**")))
    assert str(pint_root) == root
    dimension = next(d for d in DIMENSIONS.values() if d.root == root)
    assert math.isclose(parse_quantity(f"7.25 {unit}", dimension),
                        7.25 * factor * dimension.si_per_root, rel_tol=1e-15)


EXAMPLES = sorted([*ROOT.glob("specs/*.yaml"), *ROOT.glob("specs/tolerances/*.yaml"),
                   *ROOT.glob("bearingcalc/templates/*.yaml")])


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda path: str(path.relative_to(ROOT)))
def test_every_example_and_template_reads_its_units_from_the_table(path, monkeypatch):
    """A unit outside ``COMMON_UNITS`` loads pint's registry, which costs a cold solve
    about as much again as the rest of it."""
    from bearingcalc import units
    from bearingcalc.evaluation import load_one_spec

    def pint_lookup(unit):
        raise AssertionError(f"{path.name}: '{unit}' is not in COMMON_UNITS")

    monkeypatch.setattr(units, "_pint_unit", pint_lookup)
    load_one_spec(path)


@pytest.mark.parametrize("notation", sorted(RPM_NOTATIONS))
def test_every_rpm_notation_is_pints_revolution_per_minute(notation):
    # Checked against pint's own rpm, not against the table: pint knows neither r nor
    # RPM, and reads 1/min as a frequency.
    factor, root = UREG.get_root_units(UREG.parse_units("revolution / minute"))
    assert str(root) == ANGULAR_SPEED.root
    assert UREG.get_root_units(UREG.parse_units("rpm")) == (factor, root)
    value = parse_quantity(f"7.25 {notation}", ANGULAR_SPEED)
    assert math.isclose(value, 7.25 * factor, rel_tol=1e-15)
    assert value == parse_quantity("7.25 rpm", ANGULAR_SPEED)


RPM_1500 = 1500 * (2 * math.pi / 60)


@pytest.mark.parametrize("text", [
    "1500 rpm", "1500rpm", "1500 RPM", "1500 r/min", "1500r/min", "1500 r / min",
    "1500 rev/min", "1500 1/min", "1500 1 / min", "1500 min^-1", "1500min^-1",
    "1500 min ^ -1", "1500 min**-1", "1500 min⁻¹", "1500min⁻¹",
])
def test_speed_notations_give_exactly_the_value_of_rpm(text):
    assert parse_quantity(text, ANGULAR_SPEED) == RPM_1500


@pytest.mark.parametrize("text", ["1500 r/min ± 5 r/min", "1500 rpm ± 5 1/min",
                                  "1500 ± 5 min⁻¹", "1500 RPM +/- 5 min^-1",
                                  {"nominal": "1500 1/min", "tolerance": "5 r/min"}])
def test_speed_notations_in_tolerance_bands(text):
    from pydantic import TypeAdapter

    from bearingcalc.models.quantities import AngularSpeed

    value = TypeAdapter(AngularSpeed).validate_python(text)
    assert value == RPM_1500
    assert value.tolerance.low == parse_quantity("1500 rpm", ANGULAR_SPEED) - parse_quantity(
        "5 rpm", ANGULAR_SPEED)
    assert value.tolerance.high == RPM_1500 + parse_quantity("5 rpm", ANGULAR_SPEED)


@pytest.mark.parametrize(("text", "dimension", "message"), [
    # rpm only where an angular speed is expected: elsewhere 1/min is a frequency.
    ("20 1/min", TIME, "'1/min' is not a unit of time (it is a frequency"),
    ("20 min^-1", TIME, "'min^-1' is not a unit of time (it is a frequency"),
    ("20 min⁻¹", ANGULAR_ACCEL, "'min⁻¹' is not a unit of angular acceleration"),
    ("20 r/min", LENGTH, "'r/min' is not a unit of length (it is an angular speed)"),
    ("20 RPM", TIME, "'RPM' is not a unit of time (it is an angular speed)"),
    ("1500 1/s", ANGULAR_SPEED, "it is a frequency; for a speed of rotation write rpm"),
    ("1500 s⁻¹", ANGULAR_SPEED, "it is a frequency; for a speed of rotation write rpm"),
    ("15001/min", ANGULAR_SPEED, "put a space between the number and '1/min', like "
                                 "'1500 1/min'"),
    ("1500 /min", ANGULAR_SPEED, "cannot read '/min'"),
])
def test_speed_look_alikes_are_refused(text, dimension, message):
    with pytest.raises(UnitError) as info:
        parse_quantity(text, dimension)
    assert message in str(info.value)


@pytest.mark.parametrize(("text", "dimension"), [
    ("20 deg%", ANGLE), ("20 %deg", ANGLE), ("20 %*deg", ANGLE), ("20 % deg", ANGLE),
    ("20 deg*percent", ANGLE), ("20 mm/%", LENGTH), ("90 %*mm", LENGTH), ("90 % mm", LENGTH),
    ("90 %^2", LENGTH), ("1500 rpm%", ANGULAR_SPEED), ("80 degC%", TEMPERATURE),
])
def test_percent_is_never_a_factor_of_another_unit(text, dimension):
    with pytest.raises(UnitError) as info:
        parse_quantity(text, dimension)
    message = str(info.value)
    assert "percent is a unit on its own" in message
    assert f"like '{dimension.example}'" in message


def test_percent_alone_is_a_plain_ratio_not_a_length():
    with pytest.raises(UnitError, match=r"'%' is not a unit of length \(it is dimensionless\)"):
        parse_quantity("90 %", LENGTH)


def test_display_factors_are_pints():
    for si_unit, (shown, factor) in DISPLAY_UNITS.items():
        if si_unit in ("1",):
            continue
        def pint_name(unit):
            return unit.replace("²", "**2").replace("³", "**3").replace("·", "*")

        expected = UREG.Quantity(1.0, pint_name(si_unit)).to(pint_name(shown)).magnitude
        assert math.isclose(factor, expected, rel_tol=1e-15), si_unit


@pytest.mark.parametrize(("text", "dimension", "expected"), [
    ("12.7 mm", LENGTH, 0.0127),
    ("0.5 in", LENGTH, 0.0127),
    ("0.5in", LENGTH, 0.0127),
    ("1.2e1 millimeter", LENGTH, 0.012),  # not in the table: pint's registry
    ("20 deg", ANGLE, math.radians(20)),
    ("0.35 rad", ANGLE, 0.35),
    ("1500 rpm", ANGULAR_SPEED, 1500 * 2 * math.pi / 60),
    ("157 rad/s", ANGULAR_SPEED, 157.0),
    ("-90 revolution / minute", ANGULAR_SPEED, -3 * math.pi),
    ("10 kN", FORCE, 10000.0),
    ("2248.089 lbf", FORCE, 2248.089 * 4.4482216152605),  # pint's registry, SI via grams
    ("20000 h", TIME, 7.2e7),
    ("20 mm^2/s", KINEMATIC_VISCOSITY, 2e-5),
    ("68 cSt", KINEMATIC_VISCOSITY, 6.8e-5),
    ("4200 MPa", STRESS, 4.2e9),
    ("80 degC", TEMPERATURE, 353.15),
    ("176 degF", TEMPERATURE, 353.15),
    ("353.15 K", TEMPERATURE, 353.15),
    ("7850 kg/m^3", DENSITY, 7850.0),
    ("9.4 kW", POWER, 9400.0),
    ("150 N*m", TORQUE, 150.0),
])
def test_quantities_convert_to_si(text, dimension, expected):
    assert math.isclose(parse_quantity(text, dimension), expected, rel_tol=1e-12)


def test_decimal_sub_units_give_the_value_as_typed():
    assert parse_quantity("26 mm", LENGTH) == 0.026


@pytest.mark.parametrize(("text", "dimension", "message"), [
    (12.7, LENGTH, "bare number has no unit: write it as '12.7 mm'"),
    ("12.7", LENGTH, "has no unit"),
    ("12 rpm", LENGTH, "'rpm' is not a unit of length (it is an angular speed)"),
    ("25 Hz", ANGULAR_SPEED, "it is a frequency; for a speed of rotation write rpm"),
    ("3 mm", ANGLE, "not a unit of angle"),
    ("nan mm", LENGTH, "not a finite number"),
    ("inf rpm", ANGULAR_SPEED, "not a finite number"),
    ("1e400 mm", LENGTH, "out of range"),
    ("12 furlongz", LENGTH, "unknown unit 'furlongz'"),
    ("mm", LENGTH, "cannot read 'mm'"),
    (True, LENGTH, "expected a length"),
    (None, LENGTH, "expected a length"),
])
def test_bad_quantities_say_how_to_write_them(text, dimension, message):
    with pytest.raises(UnitError) as info:
        parse_quantity(text, dimension)
    assert message in str(info.value)


THRUST = (ROOT / "specs" / "thrust-bearing.yaml").read_text()


def test_a_spec_with_a_percent_factor_is_refused_on_one_line_naming_the_field(cli, spec_file):
    run = cli("solve", spec_file(THRUST.replace("contact_angle: 30 deg", "contact_angle: 30 deg%")))
    assert run.code == 2
    assert run.err.count("\n") == 1 and ":7: contact_angle: " in run.err
    assert "percent is a unit on its own" in run.err


@pytest.mark.parametrize("speed", ["1500 r/min", "1500 min⁻¹", "1500 1/min",
                                   "1500 rpm ± 5 r/min"])
def test_a_spec_solves_the_same_with_any_speed_notation(cli, spec_file, speed):
    rpm = cli("solve", spec_file(THRUST, "rpm.yaml"), "-f", "json")
    other = cli("solve", spec_file(THRUST.replace("1500 rpm", speed)), "-f", "json")
    assert other.code == rpm.code == 0, other.err
    assert json.loads(other.out)["results"] == json.loads(rpm.out)["results"]


def test_a_hertz_speed_in_a_spec_is_refused_with_its_explanation(cli, spec_file):
    run = cli("solve", spec_file(THRUST.replace("1500 rpm", "25 Hz")))
    assert run.code == 2 and run.err.count("\n") == 1
    assert "shaft_speed: 'Hz' is not a unit of angular speed (it is a frequency" in run.err
