"""``method: iso-16281`` of cylindrical, needle and tapered roller bearings through the
command line: every result against the independent scalar reference
(``tests/iso16281_reference.py``: scipy's root on its own residual of the laminae, its
own line-contact pressures and reference life), a crowned profile against the same
reference with the crown's drop, the rib's load and the edge loading from their
definitions, and each bad input of the new fields one line with exit status 2."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest

from tests import iso16281_reference as reference
from tests.conftest import solve_json
from tests.mounted_specs import TAPERED_ROLLERS

#: The material a spec that names none takes: steel, E = 207.5 GPa, ν = 0.3.
STEEL = 207.5e9

CYLINDRICAL = """kind: rolling-bearing
type: {type}
method: iso-16281
dynamic_load_rating: 44 kN
static_load_rating: 36.5 kN
roller_count: 13
roller_diameter: 7.5 mm
roller_length: 10 mm
pitch_diameter: 46 mm
operating_clearance: {clearance}
radial_load: 8 kN
speed: 3000 rpm
{extra}
"""
TAPERED = """kind: rolling-bearing
type: tapered-roller
method: iso-16281
""" + TAPERED_ROLLERS + """\
radial_load: 6 kN
axial_load: {axial}
speed: 3000 rpm
{extra}
"""


@dataclasses.dataclass(frozen=True)
class CrownedRoller(reference.RollerBearing):
    """The reference's bearing with rollers crowned by one arc: p = R − √(R² − ℓ²)."""

    crown_radius: float = math.inf

    @property
    def profile_drop(self) -> np.ndarray:
        ell = self.lamina_positions
        return self.crown_radius - np.sqrt(self.crown_radius ** 2 - ell ** 2)


def _solved(cli, spec_file, text):
    [record] = solve_json(cli, spec_file(text))
    return record


def _assert_the_references(results, bearing, forces, c, imposed=None):
    """Every scalar of the command's results against the reference's solve."""
    solved = reference.solve_equilibrium(bearing, forces,
                                         imposed={"z": 0, "tilt_y": 0, **(imposed or {})})
    life = reference.roller_reference_life(bearing, solved["lamina_load"], c)
    inner, outer = reference.roller_pressures(bearing, solved["lamina_load"])
    q = solved["q"]
    scale = np.abs(q[:3]).max()
    assert results["ring_displacement_radial"] == pytest.approx(q[1], rel=1e-8)
    assert results["ring_displacement_axial"] == pytest.approx(q[0], rel=1e-8,
                                                               abs=1e-9 * scale)
    assert results["ring_tilt"] == pytest.approx(q[4], rel=1e-7, abs=1e-12)
    assert results["max_element_load"] == pytest.approx(solved["load"].max(), rel=1e-8)
    assert results["loaded_elements"] == np.count_nonzero(solved["load"] > 0)
    assert results["reference_rating_life_revolutions"] == pytest.approx(
        life["life_million"] * 1e6, rel=1e-8)
    assert results["dynamic_equivalent_reference_load"] == pytest.approx(
        life["reference_load"], rel=1e-8)
    assert results["max_contact_pressure_inner"] == pytest.approx(inner.max(), rel=1e-8)
    assert results["max_contact_pressure_outer"] == pytest.approx(outer.max(), rel=1e-8)
    stiffness = solved["stiffness"]
    assert results["stiffness_radial"] == pytest.approx(stiffness[1, 1], rel=1e-5)
    assert results["stiffness_tilt"] == pytest.approx(stiffness[4, 4], rel=1e-5)
    loads = [results[f"element_{k}_load"] for k in range(1, bearing.roller_count + 1)]
    np.testing.assert_allclose(loads, solved["load"], rtol=1e-7,
                               atol=1e-9 * solved["load"].max())
    return solved


@pytest.mark.parametrize(("kind", "clearance", "misalignment"), [
    ("cylindrical-roller", 15e-6, 0.0), ("cylindrical-roller", 0.0, 5e-4),
    ("needle-roller", -3e-6, -2e-4), ("cylindrical-roller", 40e-6, 1e-3)])
def test_a_cylindrical_bearing_is_the_references(cli, spec_file, kind, clearance,
                                                 misalignment):
    extra = f"misalignment: {misalignment * 1e3} mrad" if misalignment else ""
    record = _solved(cli, spec_file, CYLINDRICAL.format(
        type=kind, clearance=f"{clearance * 1e6} µm", extra=extra))
    bearing = reference.RollerBearing(13, 7.5e-3, 10e-3, 46e-3,
                                      diametral_clearance=clearance, elastic_modulus=STEEL)
    imposed = {"tilt_z": misalignment} if misalignment else None
    solved = _assert_the_references(record["results"], bearing, (0, 8000.0, 0, 0, 0),
                                    44000.0, imposed)
    if misalignment:
        assert record["results"]["tilting_moment_reaction"] == pytest.approx(
            solved["reaction"][4], rel=1e-6)


@pytest.mark.parametrize(("axial", "moment"), [(3000.0, 0.0), (2000.0, 15.0),
                                                (8000.0, -20.0)])
def test_a_tapered_bearing_is_the_references(cli, spec_file, axial, moment):
    extra = f"tilting_moment: {moment} N*m" if moment else ""
    record = _solved(cli, spec_file, TAPERED.format(axial=f"{axial} N", extra=extra))
    bearing = reference.RollerBearing(17, 7.5e-3, 14e-3, 45e-3,
                                      contact_angle=math.radians(14), elastic_modulus=STEEL)
    solved = _assert_the_references(record["results"], bearing, (axial, 6000.0, 0, 0, moment),
                                    54000.0)
    assert record["results"]["stiffness_axial"] == pytest.approx(solved["stiffness"][0, 0],
                                                                 rel=1e-5)


def test_a_crowned_profile_is_the_references_with_the_crowns_drop(cli, spec_file):
    record = _solved(cli, spec_file, CYLINDRICAL.format(
        type="cylindrical-roller", clearance="10 µm",
        extra="misalignment: 0.4 mrad\nroller_profile: {crown_radius: 800 mm}\nlaminae: 40"))
    bearing = CrownedRoller(13, 7.5e-3, 10e-3, 46e-3, diametral_clearance=10e-6,
                            elastic_modulus=STEEL, laminae=40, crown_radius=0.8)
    _assert_the_references(record["results"], bearing, (0, 8000.0, 0, 0, 0), 44000.0,
                           {"tilt_z": 4e-4})


def test_an_unprofiled_roller_is_the_references_straight_roller(cli, spec_file):
    record = _solved(cli, spec_file, CYLINDRICAL.format(
        type="cylindrical-roller", clearance="5 µm", extra="roller_profile: none"))
    bearing = reference.RollerBearing(13, 7.5e-3, 10e-3, 46e-3, diametral_clearance=5e-6,
                                      elastic_modulus=STEEL, profile="none")
    _assert_the_references(record["results"], bearing, (0, 8000.0, 0, 0, 0), 44000.0)


def test_the_rib_load_is_twice_the_roller_load_times_the_half_angles_sine(cli, spec_file):
    results = _solved(cli, spec_file, TAPERED.format(
        axial="3 kN", extra="roller_included_angle: 4 deg"))["results"]
    assert results["max_rib_load"] == pytest.approx(
        2.0 * results["max_element_load"] * math.sin(math.radians(2.0)), rel=1e-12)


def test_a_misaligned_roller_is_edge_loaded_and_an_aligned_one_is_not(cli, spec_file):
    aligned = _solved(cli, spec_file, CYLINDRICAL.format(
        type="cylindrical-roller", clearance="15 µm", extra=""))
    tilted = _solved(cli, spec_file, CYLINDRICAL.format(
        type="cylindrical-roller", clearance="15 µm", extra="misalignment: 3 mrad"))
    assert not any("edge-loaded" in warning for warning in aligned["warnings"])
    assert any("edge-loaded" in warning for warning in tilted["warnings"])


def test_a_light_load_on_a_roller_bearing_warns_below_two_percent_of_c(cli, spec_file):
    record = _solved(cli, spec_file, CYLINDRICAL.format(
        type="cylindrical-roller", clearance="5 µm", extra="").replace(
            "radial_load: 8 kN", "radial_load: 800 N"))
    assert any("2 % of C" in warning for warning in record["warnings"])


def test_laminae_of_several_counts_in_one_sweep_equal_their_own_solves(cli, spec_file):
    text = CYLINDRICAL.format(type="cylindrical-roller", clearance="10 µm",
                              extra="misalignment: 0.5 mrad\nlaminae: 30")
    path = spec_file(text)
    run = cli("sweep", path, "--vary", "laminae=10:40:4", "--format", "json")
    assert run.code == 0, run.err
    rows = [json.loads(line) for line in run.out.splitlines() if line.strip()]
    for row, laminae in zip(rows, (10, 20, 30, 40), strict=True):
        own = _solved(cli, spec_file, text.replace("laminae: 30", f"laminae: {laminae}"))
        assert row["inputs"]["laminae"] == laminae
        # each solved to the equilibrium's tolerance, 1e-12 of the load
        assert row["results"]["reference_rating_life"] == pytest.approx(
            own["results"]["reference_rating_life"], rel=1e-9)


@pytest.mark.parametrize(("extra", "field"), [
    ("laminae: 1", "laminae"),
    ("laminae: 300", "laminae"),
    ("laminae: 20.5", "laminae"),
    ("roller_profile: crowned", "roller_profile"),
    ("roller_profile: {crown_radius: 2 mm}", "roller_profile.crown_radius"),
    ("roller_profile: {crown_radius: 1 m, radius: 2 m}", "roller_profile.radius"),
    ("roller_included_angle: 4 deg", "roller_included_angle"),
    ("rows: 3", "rows"),
    ("axial_load: 1 kN", "axial_load"),
    ("tilting_moment: 2 N*m\nmisalignment: 1 mrad", "misalignment"),
])
def test_bad_input_of_a_roller_bearing_as_mounted_is_one_line(cli, spec_file, extra, field):
    run = cli("solve", spec_file(CYLINDRICAL.format(type="cylindrical-roller",
                                                    clearance="10 µm", extra=extra)))
    assert run.code == 2, run.out
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in run.err, run.err
    assert f": {field}: " in lines[0], lines[0]


@pytest.mark.parametrize(("text", "field"), [
    (CYLINDRICAL.format(type="cylindrical-roller", clearance="10 µm", extra="").replace(
        "operating_clearance: 10 µm\n", ""), "operating_clearance"),
    (TAPERED.format(axial="3 kN", extra="operating_clearance: 10 µm"),
     "operating_clearance"),
    (TAPERED.format(axial="3 kN", extra="roller_included_angle: 95 deg"),
     "roller_included_angle"),
    (TAPERED.format(axial="3 kN", extra="").replace("roller_length: 14 mm\n", ""),
     "roller_length"),
    (TAPERED.format(axial="3 kN", extra="").replace("method: iso-16281\n", "")
     + "laminae: 20\n", "laminae"),
])
def test_bad_input_of_the_method_fields_is_one_line(cli, spec_file, text, field):
    run = cli("solve", spec_file(text))
    assert run.code == 2, run.out
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in run.err, run.err
    assert f": {field}: " in lines[0], lines[0]


def test_a_tapered_bearing_with_too_little_thrust_finds_no_equilibrium(cli, spec_file):
    """Below Fa = Fr·tanα a single tapered bearing cannot hold its rollers on the cup:
    the spec is refused naming the axial load, not solved to a wrong number."""
    run = cli("solve", spec_file(TAPERED.format(axial="1 kN", extra="")))
    assert run.code == 2, run.out
    assert ": axial_load: " in run.err and "no equilibrium" in run.err
