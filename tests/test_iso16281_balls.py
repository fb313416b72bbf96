"""The vectorised ISO/TS 16281 ball-bearing equilibrium against computations that do not
share its code: the scalar reference in ``tests/iso16281_reference.py`` (a residual of
its own solved by ``scipy.optimize.root``, its stiffness by central differences),
Harris's closed form for a pure axial load, and Stribeck's limit from the load-zone
integral evaluated by quadrature.

Sources: T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., Part 1: eq. 7.13
(a ball bearing under a pure axial load), eqs. 7.22-7.23 (J_r(ε)); R. Stribeck (1901)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, optimize, special

from bearingcalc.core.iso16281_ball_contacts import ball_geometry
from bearingcalc.core.iso16281_balls import solve_ball_equilibrium
from bearingcalc.core.iso16281_life import (
    ball_contact_pressures,
    ball_reference_life,
    ball_spring_constant,
)
from tests import iso16281_reference as reference
from tests.test_iso16281_reference import MINZHUN_CASES, _minzhun

#: Every design of the random set: one vectorised call, each then by the reference.
DESIGNS = 1000


def _random_bearings(seed: int = 3) -> list[tuple[reference.BallBearing, np.ndarray, bool]]:
    """Deep-groove bearings with clearance or preload and angular-contact bearings at
    their free contact angle, under radial and axial loads and a tilting moment in the
    load plane (about z); every third with the tilt imposed instead."""
    rng = np.random.default_rng(seed)
    found = []
    for i in range(DESIGNS):
        z = int(rng.integers(6, 19))
        dw = rng.uniform(4e-3, 20e-3)
        dpw = dw * rng.uniform(3.2, 7.0)
        angular = i % 2 == 1
        alpha = rng.uniform(math.radians(12), math.radians(42))
        bearing = reference.BallBearing(
            z, dw, dpw, rng.uniform(0.505, 0.54), rng.uniform(0.51, 0.56),
            diametral_clearance=0.0 if angular else rng.uniform(-8e-6, 40e-6),
            free_contact_angle=alpha if angular else None)
        # up to about ISO 76's C0 (f0·Z·Dw² with f0 ≈ 12 MPa·...), where the contacts
        # stay on their shoulders (0 < α < 90°) as a real bearing's must
        fr = rng.uniform(50.0, 0.4 * z * dw * dw * 4e7)
        fa = rng.uniform(0.0, 0.5 * fr)
        if angular:
            fa = fr * math.tan(alpha) * rng.uniform(1.3, 3.0)
        moment = rng.uniform(-1.0, 1.0) * fr * dpw * 0.03
        imposed = i % 3 == 0
        found.append((bearing, np.array([fa, fr, 0.0, 0.0, moment]), imposed))
    return found


def _geometry(bearings: list[reference.BallBearing]):
    angular = [b.free_contact_angle is not None for b in bearings]
    assert len(set(angular)) == 1
    return ball_geometry(
        [b.ball_count for b in bearings], [b.ball_diameter for b in bearings],
        [b.pitch_diameter for b in bearings], [b.inner_conformity for b in bearings],
        [b.outer_conformity for b in bearings], [b.spring_constant for b in bearings],
        diametral_clearance=None if angular[0] else [b.diametral_clearance for b in bearings],
        free_contact_angle=[b.free_contact_angle for b in bearings] if angular[0] else None)


@pytest.fixture(scope="module")
def solved():
    """Each design by the reference, and all of one family and kind of load in one call."""
    cases = _random_bearings()
    out = []
    for angular in (False, True):
        for imposed in (False, True):
            group = [(b, f, i) for b, f, i in cases
                     if (b.free_contact_angle is not None) == angular and i == imposed]
            bearings = [b for b, _, _ in group]
            loads = np.array([f for _, f, _ in group])
            tilt = None
            refs = []
            if imposed:
                tilt = np.linspace(-4e-4, 4e-4, len(group))
                loads[:, 4] = 0.0
                refs = [reference.solve_equilibrium(b, f, imposed={"z": 0, "tilt_y": 0,
                                                                   "tilt_z": t})
                        for b, f, t in zip(bearings, loads, tilt, strict=True)]
            else:
                refs = [reference.solve_equilibrium(b, f, imposed={"z": 0, "tilt_y": 0})
                        for b, f in zip(bearings, loads, strict=True)]
            mine = solve_ball_equilibrium(_geometry(bearings), loads, fixed_tilt=tilt)
            out.append((bearings, refs, mine))
    return out


def test_every_design_is_in_equilibrium(solved):
    for _, _, mine in solved:
        assert mine.converged.all()
        assert np.max(mine.residual) < 1e-9


def test_displacements_and_ball_loads_are_the_references(solved):
    for bearings, refs, mine in solved:
        for i, (bearing, ref) in enumerate(zip(bearings, refs, strict=True)):
            assert ref["residual"] < 1e-11
            scale = np.array([1, 1, 1, bearing.pitch_diameter / 2, bearing.pitch_diameter / 2])
            np.testing.assert_allclose(mine.displacement[i] * scale, ref["q"] * scale,
                                       rtol=0, atol=1e-9 * np.max(np.abs(ref["q"] * scale)))
            z = bearing.ball_count
            np.testing.assert_allclose(mine.element_load[i, :z], ref["load"], rtol=0,
                                       atol=1e-9 * ref["load"].max())
            loaded = ref["load"] > 0
            np.testing.assert_allclose(mine.contact_angle[i, :z][loaded],
                                       np.abs(ref["angle"][loaded]), rtol=1e-9, atol=1e-12)
            assert np.isnan(mine.element_load[i, z:]).all()


def test_the_reaction_of_an_imposed_tilt_is_the_references_moment(solved):
    for _, refs, mine in solved[1::2]:
        moments = np.array([ref["reaction"][4] for ref in refs])
        np.testing.assert_allclose(mine.reaction[:, 4], moments, rtol=1e-8,
                                   atol=1e-9 * np.max(np.abs(moments)))


def test_the_stiffness_is_the_central_differences_of_the_contacts(solved):
    """The analytic tangent stiffness against the reference's central differences of the
    contacts' force (steps of 10 pm) at the solved displacement, to 1e-6 of its largest
    entry in consistent units (tilts over the pitch radius). A ball's Q ∝ δ^1.5 has an
    unbounded second derivative at first contact, so a design with a ball within 10 nm
    of it is left out (a difference quotient there sees the ball, the tangent does not);
    most designs have none."""
    checked = total = 0
    for bearings, _, mine in solved:
        for i, bearing in enumerate(bearings):
            total += 1
            deflection = reference.ball_state(bearing, mine.displacement[i])["deflection"]
            if np.min(np.abs(deflection)) < 1e-8:
                continue
            checked += 1
            lever = bearing.pitch_diameter / 2
            scale = np.array([1, 1, 1, 1 / lever, 1 / lever])
            numeric = reference.stiffness_matrix(bearing, mine.displacement[i], step=1e-11)
            mine_scaled = mine.stiffness[i] * scale[:, None] * scale[None, :]
            numeric_scaled = numeric * scale[:, None] * scale[None, :]
            np.testing.assert_allclose(mine_scaled, numeric_scaled, rtol=0,
                                       atol=1e-6 * np.max(np.abs(numeric_scaled)))
            np.testing.assert_allclose(mine.stiffness[i], mine.stiffness[i].T, rtol=1e-12,
                                       atol=1e-12 * np.max(np.abs(mine.stiffness[i])))
    assert checked > 0.8 * total


def test_designs_of_different_ball_counts_in_one_call_are_each_alone():
    cases = [b for b, _, _ in _random_bearings(seed=11)
             if b.free_contact_angle is None][:6]
    loads = np.array([[0.0, 900.0, 0.0, 0.0, 0.4]] * len(cases))
    together = solve_ball_equilibrium(_geometry(cases), loads)
    for i, bearing in enumerate(cases):
        alone = solve_ball_equilibrium(_geometry([bearing]), loads[i:i + 1])
        np.testing.assert_allclose(together.displacement[i], alone.displacement[0],
                                   rtol=1e-12, atol=1e-18)


@pytest.mark.parametrize(("alpha0_deg", "force"), [(15.0, 500.0), (25.0, 3000.0),
                                                   (40.0, 20000.0)])
def test_a_pure_axial_load_is_harris_closed_form(alpha0_deg, force):
    """Every ball carries Fa/(Z·sinα), and Fa/(Z·K·A^1.5) = sinα·(cosα0/cosα − 1)^1.5
    (Harris & Kotzalas, Part 1, eq. 7.13) solved for α by brentq."""
    alpha0 = math.radians(alpha0_deg)
    bearing = reference.BallBearing(12, 9.525e-3, 46.0e-3, 0.52, 0.53,
                                    free_contact_angle=alpha0)
    mine = solve_ball_equilibrium(_geometry([bearing]), np.array([[force, 0, 0, 0, 0]]))
    a = bearing.groove_distance
    k = bearing.spring_constant
    target = force / (bearing.ball_count * k * a**1.5)
    alpha = optimize.brentq(
        lambda x: math.sin(x) * (math.cos(alpha0) / math.cos(x) - 1.0) ** 1.5 - target,
        alpha0, math.pi / 2 - 1e-9, xtol=1e-15, rtol=1e-15)
    loads = mine.element_load[0]
    np.testing.assert_allclose(loads, force / (bearing.ball_count * math.sin(alpha)),
                               rtol=1e-9)
    np.testing.assert_allclose(mine.contact_angle[0], alpha, rtol=1e-9)


def test_stribecks_limit_at_zero_clearance_and_many_balls():
    """Qmax·Z/Fr → 1/J_r(½) as Z grows, J_r(½) = (1/2π)∫ cos ψ·(cos ψ)^1.5 dψ over
    |ψ| < π/2 for point contact (= 0.2288, 4.370 = 2π/B(½, 7/4) its inverse)."""
    integral = integrate.quad(lambda psi: math.cos(psi) ** 2.5, -math.pi / 2,
                              math.pi / 2)[0] / (2 * math.pi)
    z = 400
    bearing = reference.BallBearing(z, 1e-3, 200e-3, 0.52, 0.53)
    mine = solve_ball_equilibrium(_geometry([bearing]), np.array([[0.0, 5000.0, 0, 0, 0]]))
    ratio = np.nanmax(mine.element_load[0]) * z / 5000.0
    assert ratio == pytest.approx(1 / integral, rel=2e-5)
    assert 1 / integral == pytest.approx(2 * math.pi / special.beta(0.5, 1.75), rel=1e-9)


def test_an_angular_contact_bearing_without_axial_load_has_no_equilibrium():
    bearing = reference.BallBearing(12, 9.525e-3, 46.0e-3, 0.52, 0.53,
                                    free_contact_angle=math.radians(25))
    mine = solve_ball_equilibrium(_geometry([bearing]), np.array([[0.0, 2000.0, 0, 0, 0]]))
    assert not mine.converged[0]


def test_an_angular_contact_bearing_free_to_tilt_holds_above_a_least_axial_load_only():
    """Under 2 kN radial and a growing axial load a single 25° bearing, its ring free to
    tilt, has no equilibrium on its shoulders up to some least axial load and one at every
    load above it: no stationary point with a ball pressed past its groove's bottom
    (α ≤ 0, where an angular-contact bearing's model has no contact) is taken for one.
    Each state taken is checked from the groove centres, written here again: every ball
    pressed is pressed at 0 < α < 90°, and the loads balance."""
    bearing = reference.BallBearing(9, 7.938e-3, 38.5e-3, 0.52, 0.53,
                                    free_contact_angle=math.radians(25))
    axial = np.concatenate([[1e-3, 5.0], np.linspace(20.0, 1500.0, 75)])
    loads = np.zeros((axial.size, 5))
    loads[:, 0], loads[:, 1] = axial, 2000.0
    mine = solve_ball_equilibrium(_geometry([bearing] * axial.size), loads)
    held = mine.converged
    assert held.any() and not held[0]
    least = axial[held].min()
    assert held[axial >= least].all()
    psi = 2 * np.pi * np.arange(9) / 9
    for q, reaction, load in zip(mine.displacement[held], mine.reaction[held], loads[held],
                                 strict=True):
        groove = (0.52 + 0.53 - 1) * bearing.ball_diameter
        sx = groove * math.sin(math.radians(25)) + q[0] + 38.5e-3 / 2 * q[4] * np.cos(psi)
        sr = groove * math.cos(math.radians(25)) + q[1] * np.cos(psi)
        pressed = np.hypot(sx, sr) > groove
        assert np.all((sx[pressed] > 0) & (sr[pressed] > 0))
        assert reaction == pytest.approx(load, rel=1e-9, abs=1e-9 * load[1])


# --- the reference life, contacts and the published cases ------------------------------------

def _life(bearing: reference.BallBearing, loads: np.ndarray, c: float):
    return ball_reference_life(loads, bearing.ball_count, bearing.ball_diameter,
                               bearing.pitch_diameter, bearing.inner_conformity,
                               bearing.outer_conformity, bearing.nominal_contact_angle, c)


@pytest.mark.parametrize(("clearance", "forces", "expected", "life"), MINZHUN_CASES,
                         ids=[f"example_{i + 1}" for i in range(7)])
def test_minzhun_masta_cases(clearance, forces, expected, life):
    """minzhun/ISO16281 Test_BallBearing.py (commit ade7076), its seven examples with the
    MASTA values they check against (as ``tests/test_iso16281_reference.py`` lists them),
    to 0.05 % in displacement, tilt and L10r; C = 23.4 kN."""
    bearing = _minzhun(clearance)
    mine = solve_ball_equilibrium(_geometry([bearing]), np.array([forces], dtype=float))
    assert mine.converged[0]
    q = mine.displacement[0]
    got = {"r": math.hypot(q[1], q[2]) / 1e-6, "a": q[0] / 1e-6,
           "t": math.hypot(q[3], q[4]) / 1e-3}
    for key, value in expected.items():
        assert got[key] == pytest.approx(value, rel=5e-4), key
    found = _life(bearing, mine.element_load, 23400.0)
    assert found.revolutions[0] / 1e6 == pytest.approx(life, rel=5e-4)


def test_life_and_pressures_are_the_references(solved):
    """L10r, the raceway ratings and equivalent loads, and the largest Hertz pressures
    against the reference's (its own Hertz from scipy's elliptic integrals), over the
    random designs, to 1e-9 (pressures to 1e-7: two Hertz implementations)."""
    for bearings, refs, mine in solved:
        c = np.array([2e4 + 1e3 * b.ball_count for b in bearings])
        found = ball_reference_life(
            mine.element_load, [b.ball_count for b in bearings],
            [b.ball_diameter for b in bearings], [b.pitch_diameter for b in bearings],
            [b.inner_conformity for b in bearings], [b.outer_conformity for b in bearings],
            [b.nominal_contact_angle for b in bearings], c)
        inner, outer = ball_contact_pressures(
            mine.element_load, mine.contact_angle, [b.ball_diameter for b in bearings],
            [b.pitch_diameter for b in bearings], [b.inner_conformity for b in bearings],
            [b.outer_conformity for b in bearings], 2.1e11, 0.3)
        for i, (bearing, ref) in enumerate(zip(bearings, refs, strict=True)):
            expected = reference.ball_reference_life(bearing, ref["load"], c[i])
            assert found.revolutions[i] / 1e6 == pytest.approx(expected["life_million"],
                                                               rel=1e-9)
            assert found.equivalent_load[i] == pytest.approx(expected["reference_load"],
                                                             rel=1e-9)
            ref_inner, ref_outer = reference.ball_pressures(bearing, ref["load"], ref["angle"])
            assert inner[i] == pytest.approx(ref_inner.max(), rel=1e-7)
            assert outer[i] == pytest.approx(ref_outer.max(), rel=1e-7)


def test_the_spring_constant_is_the_references_exact_hertz():
    for bearing in (_minzhun(0.0), reference.BallBearing(
            12, 9.525e-3, 46e-3, 0.515, 0.525, free_contact_angle=math.radians(30))):
        k = ball_spring_constant(bearing.ball_diameter, bearing.pitch_diameter,
                                 bearing.inner_conformity, bearing.outer_conformity,
                                 bearing.nominal_contact_angle, 2.1e11, 0.3)
        assert float(k) == pytest.approx(bearing.spring_constant, rel=1e-9)


def test_the_load_zone_of_a_radial_load_with_clearance_is_harris_closed_form():
    """A deep-groove bearing under a radial load: δ(ψ) = δr·cosψ − Pd/2, so the load zone
    ends at cosψ_l = Pd/(2δr) (Harris & Kotzalas, Part 1, ch. 7); between 360 balls the
    interpolation is within 1e-4 of it, and at zero clearance between 10 balls exact by
    symmetry (180°)."""
    from bearingcalc.core.iso16281_ball_contacts import ball_deflections
    from bearingcalc.core.mounted_bearing import load_zone_angle

    for z, clearance, expected in ((360, 12e-6, None), (10, 0.0, math.pi)):
        bearing = reference.BallBearing(z, 2e-3, 200e-3, 0.52, 0.53,
                                        diametral_clearance=clearance)
        geometry = _geometry([bearing])
        mine = solve_ball_equilibrium(geometry, np.array([[0.0, 3000.0, 0, 0, 0]]))
        zone = load_zone_angle(ball_deflections(geometry, mine.displacement, mine.azimuth),
                               mine.azimuth)[0]
        radial = mine.displacement[0, 1]
        closed = 2 * math.acos(clearance / (2 * radial)) if expected is None else expected
        assert zone == pytest.approx(closed, abs=1e-4 if expected is None else 1e-12)


def test_the_load_zone_is_whole_under_an_axial_load():
    from bearingcalc.core.iso16281_ball_contacts import ball_deflections
    from bearingcalc.core.mounted_bearing import load_zone_angle

    bearing = reference.BallBearing(12, 9.525e-3, 46e-3, 0.52, 0.53, diametral_clearance=1e-5)
    geometry = _geometry([bearing])
    mine = solve_ball_equilibrium(geometry, np.array([[2000.0, 100.0, 0, 0, 0]]))
    zone = load_zone_angle(ball_deflections(geometry, mine.displacement, mine.azimuth),
                           mine.azimuth)
    assert zone[0] == 2 * math.pi
