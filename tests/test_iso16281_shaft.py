"""The vectorised rigid shaft on several bearings (``core/iso16281_shaft.py``) against
the independent scalar shaft reference (``tests/iso16281_shaft_reference.py``: its own
maps, scipy's root on its own residual, central differences), on random matched pairs
of angular-contact ball and tapered roller bearings with end play or preload under
combined loads; and the preload's axial deflection against the reference's closed
forms (Harris's axial law of a ball bearing, the laminae's of a tapered one)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingcalc.core.iso16281_ball_contacts import ball_contacts_at, ball_geometry
from bearingcalc.core.iso16281_life import ball_spring_constant
from bearingcalc.core.iso16281_rollers import roller_contacts_at, roller_geometry
from bearingcalc.core.iso16281_shaft import (
    ShaftBearing,
    axial_deflection_for_load,
    solve_shaft,
)
from tests import iso16281_reference as reference
from tests import iso16281_shaft_reference as shaft_reference

DESIGNS = 40


def _ball_contacts(bearing: reference.BallBearing):
    """The product's contacts of the reference's angular-contact ball bearing."""
    alpha = bearing.free_contact_angle
    spring = ball_spring_constant(bearing.ball_diameter, bearing.pitch_diameter,
                                  bearing.inner_conformity, bearing.outer_conformity, alpha,
                                  bearing.elastic_modulus, bearing.poisson_ratio)
    geometry = ball_geometry(bearing.ball_count, bearing.ball_diameter,
                             bearing.pitch_diameter, bearing.inner_conformity,
                             bearing.outer_conformity, spring, free_contact_angle=alpha)
    return lambda q: ball_contacts_at(geometry, q)


def _roller_contacts(bearing: reference.RollerBearing):
    geometry = roller_geometry(bearing.roller_count, bearing.roller_diameter,
                               bearing.effective_length, bearing.contact_angle,
                               laminae=bearing.laminae, profile=bearing.profile)
    return lambda q: roller_contacts_at(geometry, q)


def _random_pairs(seed: int = 3, count: int = DESIGNS):
    """Pairs of identical bearings, back-to-back or face-to-face, pressure centres 15 to
    80 mm apart, end play from −30 µm (preload) to +30 µm, under radial, axial and
    tilting loads in the radial load's plane and out of it."""
    rng = np.random.default_rng(seed)
    found = []
    for i in range(count):
        if i % 2 == 0:
            bearing = reference.BallBearing(
                int(rng.integers(9, 17)), rng.uniform(6e-3, 14e-3), 0.0, 0.52, 0.53,
                free_contact_angle=math.radians(rng.uniform(15.0, 40.0)))
            bearing = reference.BallBearing(
                bearing.ball_count, bearing.ball_diameter,
                bearing.ball_diameter * rng.uniform(4.0, 7.0), rng.uniform(0.505, 0.53),
                rng.uniform(0.51, 0.54), free_contact_angle=bearing.free_contact_angle)
        else:
            dwe = rng.uniform(5e-3, 12e-3)
            bearing = reference.RollerBearing(
                int(rng.integers(12, 22)), dwe, dwe * rng.uniform(1.2, 2.2),
                dwe * rng.uniform(5.0, 9.0), contact_angle=math.radians(rng.uniform(10, 28)),
                laminae=20)
        spread = rng.uniform(15e-3, 80e-3)
        arrangement = ("back-to-back", "face-to-face")[int(rng.integers(2))]
        end_play = rng.uniform(-30e-6, 30e-6)
        fr = rng.uniform(500.0, 8000.0)
        load = np.array([rng.uniform(-1, 1) * fr, fr, 0.0, 0.0,
                         rng.uniform(-1, 1) * fr * spread * 0.2])
        if i % 3 == 0:
            load[2], load[3] = rng.uniform(-0.3, 0.3) * fr, rng.uniform(-0.1, 0.1) * fr * spread
        found.append((bearing, shaft_reference.matched_pair(
            bearing, (-spread / 2, spread / 2), arrangement, end_play), load))
    return found


def _solved_by_product(bearing, pair, load):
    contacts = _ball_contacts(bearing) if isinstance(bearing, reference.BallBearing) \
        else _roller_contacts(bearing)
    on_shaft = [ShaftBearing(contacts, np.array([item.position]), item.orientation,
                             np.array([item.offset])) for item in pair]
    lever = max(abs(item.position) for item in pair) + bearing.pitch_diameter / 2.0
    return solve_shaft(on_shaft, load[None, :], np.array([lever]))


@pytest.fixture(scope="module")
def solved():
    out = []
    for bearing, pair, load in _random_pairs():
        mine = _solved_by_product(bearing, pair, load)
        theirs = shaft_reference.solve_shaft(pair, load)
        out.append((bearing, pair, load, mine, theirs))
    return out


def test_every_pair_converges_to_a_relative_residual_below_1e9(solved):
    for _, _, _, mine, theirs in solved:
        assert theirs["residual"] < 1e-9
        assert mine.converged[0] and mine.residual[0] < 1e-9


def test_the_shafts_displacement_equals_the_references_to_1e9(solved):
    for _, _, _, mine, theirs in solved:
        q = theirs["Q"]
        scale = np.abs(q[:3]).max()
        np.testing.assert_allclose(mine.displacement[0, :3], q[:3], rtol=1e-9,
                                   atol=1e-9 * scale)
        tilt_scale = max(np.abs(q[3:]).max(), 1e-9 * scale / 0.05)
        np.testing.assert_allclose(mine.displacement[0, 3:], q[3:], rtol=1e-9,
                                   atol=1e-8 * tilt_scale)


def test_every_elements_load_equals_the_references(solved):
    for _, _, _, mine, theirs in solved:
        for contacts, loads in zip(mine.contacts, theirs["load"], strict=True):
            np.testing.assert_allclose(contacts.element_load[0], loads, rtol=1e-8,
                                       atol=1e-9 * max(np.max(loads), 1.0))


def test_the_shafts_stiffness_equals_central_differences_to_1e6(solved):
    """A lamina's load grows as δ^(10/9), whose slope is not smooth at first contact, so
    steps of 1 nm misjudge a lamina next to it: a design with an element or lamina within
    10 nm of first contact is left out (no difference quotient converges there)."""
    compared = 0
    for _, _, _, mine, theirs in solved:
        if any(np.min(np.abs(state["deflection"])) < 1e-8 for state in theirs["states"]):
            continue
        compared += 1
        expected = theirs["stiffness"]
        np.testing.assert_allclose(mine.stiffness[0], expected, rtol=1e-6,
                                   atol=1e-6 * np.abs(expected).max())
    assert compared >= DESIGNS // 2


@pytest.mark.parametrize("preload", [50.0, 800.0, 5000.0])
def test_the_preloads_axial_deflection_is_the_closed_forms(preload):
    """δa(P) of one bearing under its preload P, against the reference's closed forms
    (Harris's F = Z·K·δ^1.5·sin α with tan α = (A sin α0 + δa)/(A cos α0) for balls, the
    laminae's sum for a tapered bearing) through their own brentq."""
    ball = reference.BallBearing(12, 11.112e-3, 52.5e-3, 0.52, 0.53,
                                 free_contact_angle=math.radians(40.0))
    tapered = reference.RollerBearing(17, 7.5e-3, 14e-3, 60e-3,
                                      contact_angle=math.radians(15.0))
    for bearing, contacts in ((ball, _ball_contacts(ball)), (tapered, _roller_contacts(tapered))):
        deflection = axial_deflection_for_load(contacts, preload)[0]
        assert -2.0 * deflection == pytest.approx(
            shaft_reference.end_play_for_preload(bearing, preload), rel=1e-9)
