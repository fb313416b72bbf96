"""The vectorised ISO/TS 16281 roller-bearing equilibrium (laminae) against computations
that do not share its code: the scalar reference in ``tests/iso16281_reference.py``
(its residual solved by ``scipy.optimize.root``, its stiffness by central differences),
the classic line-contact distribution of an unprofiled, untilted bearing, and a tapered
bearing's equal roller loads under a pure axial load, both in closed form."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize

from bearingcalc.core.iso16281_life import roller_reference_life
from bearingcalc.core.iso16281_rollers import (
    CHUNK,
    LINE_CONSTANT,
    logarithmic_profile,
    roller_geometry,
    solve_roller_equilibrium,
)
from tests import iso16281_reference as reference

DESIGNS = 1000


def _random_bearings(seed: int = 5, count: int = DESIGNS):
    """Cylindrical bearings with clearance or preload and tapered ones at the cup's
    angle, ISO-profiled, under radial and axial loads and a tilting moment about z."""
    rng = np.random.default_rng(seed)
    found = []
    for i in range(count):
        z = int(rng.integers(10, 26))
        dwe = rng.uniform(5e-3, 25e-3)
        lwe = dwe * rng.uniform(0.7, 3.5)
        tapered = i % 2 == 1
        alpha = rng.uniform(math.radians(8), math.radians(28)) if tapered else 0.0
        bearing = reference.RollerBearing(
            z, dwe, lwe, dwe * rng.uniform(4.0, 9.0), contact_angle=alpha,
            diametral_clearance=0.0 if tapered else rng.uniform(-6e-6, 40e-6), laminae=30)
        fr = rng.uniform(500.0, 4e4)
        fa = fr * math.tan(alpha) * rng.uniform(1.3, 3.0) if tapered else 0.0
        found.append((bearing, np.array([fa, fr, 0.0, 0.0,
                                         rng.uniform(-1, 1) * fr * lwe * 0.02])))
    return found


def _geometry(bearings):
    return roller_geometry([b.roller_count for b in bearings],
                           [b.roller_diameter for b in bearings],
                           [b.effective_length for b in bearings],
                           [b.contact_angle for b in bearings],
                           diametral_clearance=[b.diametral_clearance for b in bearings],
                           laminae=bearings[0].laminae,
                           profile=bearings[0].profile)


@pytest.fixture(scope="module")
def solved():
    cases = _random_bearings()
    bearings = [b for b, _ in cases]
    loads = np.array([f for _, f in cases])
    refs = [reference.solve_equilibrium(b, f, imposed={"z": 0, "tilt_y": 0})
            for b, f in cases]
    return bearings, refs, solve_roller_equilibrium(_geometry(bearings), loads)


def test_every_design_is_in_equilibrium(solved):
    _, _, mine = solved
    assert mine.converged.all()
    assert np.max(mine.residual) < 1e-9


def test_displacements_and_loads_are_the_references(solved):
    for i, (bearing, ref) in enumerate(zip(*solved[:2], strict=True)):
        mine = solved[2]
        lever = bearing.effective_length / 2
        scale = np.array([1, 1, 1, lever, lever])
        assert ref["residual"] < 1e-11
        np.testing.assert_allclose(mine.displacement[i] * scale, ref["q"] * scale, rtol=0,
                                   atol=1e-9 * np.max(np.abs(ref["q"] * scale)))
        z = bearing.roller_count
        np.testing.assert_allclose(mine.lamina_load[i, :z], ref["lamina_load"], rtol=0,
                                   atol=1e-9 * ref["lamina_load"].max())
        np.testing.assert_allclose(mine.element_load[i, :z], ref["load"], rtol=0,
                                   atol=1e-9 * ref["load"].max())


def test_the_stiffness_is_the_central_differences_of_the_laminae(solved):
    """Steps of 10 pm: a lamina's law δ^(10/9) has an unbounded second derivative at
    first contact, so steps of 1 nm would misjudge the laminae that carry next to
    nothing by 1e-4 of the whole; at 10 pm the rounding is still far below 1e-6. A
    design with a lamina within 10 nm of first contact is left out: there a difference
    quotient over any step sees the lamina's h^(1/9), the tangent (its right derivative)
    none. Most designs have none."""
    bearings, _, mine = solved
    checked = 0
    for i, bearing in enumerate(bearings):
        deflection = reference.roller_state(bearing, mine.displacement[i])["deflection"]
        if np.min(np.abs(deflection)) < 1e-8:
            continue
        checked += 1
        lever = bearing.effective_length / 2
        scale = np.array([1, 1, 1, 1 / lever, 1 / lever])
        numeric = reference.stiffness_matrix(bearing, mine.displacement[i], step=1e-11)
        numeric *= scale[:, None] * scale[None, :]
        analytic = mine.stiffness[i] * scale[:, None] * scale[None, :]
        np.testing.assert_allclose(analytic, numeric, rtol=0,
                                   atol=1e-6 * np.max(np.abs(numeric)))
    assert checked > 0.8 * len(bearings)


def test_more_designs_than_a_chunk_with_different_roller_counts():
    cases = _random_bearings(seed=9, count=CHUNK + 37)
    bearings = [b for b, _ in cases]
    loads = np.array([f for _, f in cases])
    together = solve_roller_equilibrium(_geometry(bearings), loads)
    for i in (0, CHUNK - 1, CHUNK, CHUNK + 36):
        alone = solve_roller_equilibrium(_geometry([bearings[i]]), loads[i:i + 1])
        np.testing.assert_allclose(together.displacement[i], alone.displacement[0],
                                   rtol=1e-12, atol=1e-18)
        z = bearings[i].roller_count
        assert np.isnan(together.element_load[i, z:]).all()


def test_unprofiled_untilted_laminae_are_the_classic_line_contact():
    """Zero clearance, a radial load, no profile: every lamina of roller j deflects
    δr·cosψ_j, so Q_j = c_L·(δr·cosψ_j)^(10/9) with Fr = Σ Q_j·cosψ_j (Harris &
    Kotzalas, Part 1, ch. 7, line contact), δr by brentq."""
    z, dwe, lwe, fr = 16, 12e-3, 18e-3, 2.5e4
    geometry = roller_geometry(z, dwe, lwe, 0.0, laminae=40, profile="none")
    mine = solve_roller_equilibrium(geometry, np.array([[0.0, fr, 0, 0, 0]]))
    psi = 2 * math.pi * np.arange(z) / z
    c = LINE_CONSTANT * lwe ** (8 / 9)
    cos = np.clip(np.cos(psi), 0.0, None)
    radial = optimize.brentq(lambda d: c * np.sum((d * cos) ** (10 / 9) * cos) - fr,
                             1e-12, 1e-3, xtol=1e-18, rtol=1e-15)
    np.testing.assert_allclose(mine.displacement[0, 1], radial, rtol=1e-9)
    np.testing.assert_allclose(mine.element_load[0], c * (radial * cos) ** (10 / 9),
                               rtol=1e-9, atol=1e-9 * fr)


def test_a_tapered_bearing_under_a_pure_axial_load_loads_every_roller_alike():
    """Fa = Z·c_L·(δa·sinα)^(10/9)·sinα, unprofiled: δa in closed form."""
    z, dwe, lwe, alpha, fa = 18, 10e-3, 16e-3, math.radians(15), 1.2e4
    geometry = roller_geometry(z, dwe, lwe, alpha, laminae=30, profile="none")
    mine = solve_roller_equilibrium(geometry, np.array([[fa, 0.0, 0, 0, 0]]))
    c = LINE_CONSTANT * lwe ** (8 / 9)
    axial = (fa / (z * c * math.sin(alpha))) ** 0.9 / math.sin(alpha)
    np.testing.assert_allclose(mine.displacement[0, 0], axial, rtol=1e-9)
    np.testing.assert_allclose(mine.element_load[0], fa / (z * math.sin(alpha)), rtol=1e-9)


def test_the_profile_is_the_references_iso_profile():
    for dwe, lwe in ((10e-3, 12e-3), (10e-3, 40e-3)):
        bearing = reference.RollerBearing(12, dwe, lwe, 60e-3, laminae=30)
        positions = bearing.lamina_positions
        np.testing.assert_allclose(logarithmic_profile(positions, dwe, lwe),
                                   bearing.profile_drop, rtol=1e-12, atol=1e-18)


def test_the_reference_life_is_the_references(solved):
    """L10r and P_ref from every lamina's load against the reference's, to 1e-9."""
    bearings, refs, mine = solved
    c = np.array([5e4 + 2e3 * b.roller_count for b in bearings])
    found = roller_reference_life(mine.lamina_load, [b.roller_count for b in bearings],
                                  [b.roller_diameter for b in bearings],
                                  [b.pitch_diameter for b in bearings],
                                  [b.contact_angle for b in bearings], c)
    for i, (bearing, ref) in enumerate(zip(bearings, refs, strict=True)):
        expected = reference.roller_reference_life(bearing, ref["lamina_load"], c[i])
        assert found.revolutions[i] / 1e6 == pytest.approx(expected["life_million"], rel=1e-9)
        assert found.equivalent_load[i] == pytest.approx(expected["reference_load"], rel=1e-9)
