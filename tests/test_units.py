"""Quantity parsing: the fast unit table agrees with pint, and bad quantities are refused."""

from __future__ import annotations

import math

import pytest

from bearingcalc.units import (
    ANGLE,
    ANGULAR_SPEED,
    COMMON_UNITS,
    DENSITY,
    DIMENSIONS,
    DISPLAY_UNITS,
    FORCE,
    KINEMATIC_VISCOSITY,
    LENGTH,
    POWER,
    STRESS,
    TEMPERATURE,
    TIME,
    TORQUE,
    UnitError,
    make_registry,
    parse_quantity,
)

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
