"""The mounting chain's Lamé fits against computations that do not share their closed
forms: the general solution of a thick-walled cylinder, u(r) = A·r + B/r, with its
boundary conditions solved as a linear system for both bodies at once (plane stress,
S. Timoshenko and J. N. Goodier, Theory of Elasticity, 3rd ed., §33); the thin-ring
limit on a solid shaft (the raceway grows by I·d/F, SKF's rule of a clearance reduction
"about 80 % of the interference" for d/F ≈ 0.8); and the thermal chain summed part by
part."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingcalc.core import mounting_fits as fits

STEEL, STEEL_NU = 208e9, 0.3
ALUMINIUM, ALUMINIUM_NU = 70e9, 0.33


def _lame_system(interference, inner_bore, diameter, outer_diameter, inner, outer):
    """p, and the radial displacements of the inner body's bore and the outer body's
    outside, from u = A·r + B/r in each body, σ_r = E/(1 − ν²)·((1 + ν)A − (1 − ν)B/r²):
    free (σ_r = 0) at the inner body's bore (B = 0 where solid) and at the outer body's
    outside (A = 0 where unbounded), σ_r = −p on both sides of the joint, and the joint's
    radial displacements apart by I/2. Unknowns (A_i, B_i, A_o, B_o, p)."""
    (e_i, nu_i), (e_o, nu_o) = inner, outer
    b = diameter / 2

    def stress_row(e, nu, r, first):
        k = e / (1 - nu * nu)
        row = np.zeros(5)
        row[first], row[first + 1] = k * (1 + nu), -k * (1 - nu) / (r * r)
        return row

    rows, rhs = [], []
    if inner_bore > 0:
        rows.append(stress_row(e_i, nu_i, inner_bore / 2, 0))
    else:
        rows.append(np.eye(5)[1])
    rhs.append(0.0)
    for e, nu, first in ((e_i, nu_i, 0), (e_o, nu_o, 2)):
        row = stress_row(e, nu, b, first)
        row[4] = 1.0  # σ_r(b) + p = 0
        rows.append(row)
        rhs.append(0.0)
    if math.isinf(outer_diameter):
        rows.append(np.eye(5)[2])
    else:
        rows.append(stress_row(e_o, nu_o, outer_diameter / 2, 2))
    rhs.append(0.0)
    joint = np.array([-b, -1 / b, b, 1 / b, 0.0])  # u_o(b) − u_i(b)
    rows.append(joint)
    rhs.append(interference / 2)
    a_i, b_i, a_o, b_o, p = np.linalg.solve(np.array(rows), np.array(rhs))
    outside = None if math.isinf(outer_diameter) else (
        a_o * outer_diameter / 2 + b_o / (outer_diameter / 2))
    bore = a_i * inner_bore / 2 + (b_i / (inner_bore / 2) if inner_bore > 0 else 0.0)
    return p, bore, outside


CASES = [  # (I, inner bore, joint d, outer diameter, inner material, outer material)
    (20e-6, 0.0, 40e-3, 48e-3, (STEEL, STEEL_NU), (STEEL, STEEL_NU)),
    (35e-6, 20e-3, 40e-3, 47e-3, (STEEL, STEEL_NU), (STEEL, STEEL_NU)),
    (12e-6, 0.0, 80e-3, 92e-3, (ALUMINIUM, ALUMINIUM_NU), (STEEL, STEEL_NU)),
    (18e-6, 72e-3, 80e-3, math.inf, (STEEL, STEEL_NU), (ALUMINIUM, ALUMINIUM_NU)),
    (25e-6, 72e-3, 80e-3, 110e-3, (STEEL, STEEL_NU), (ALUMINIUM, ALUMINIUM_NU)),
    (25e-6, 28e-3, 30e-3, 60e-3, (STEEL, STEEL_NU), (200e9, 0.28)),
]


@pytest.mark.parametrize("case", CASES)
def test_the_fit_pressure_is_the_two_bodies_solved_together(case):
    interference, bore, d, outer, inner_material, outer_material = case
    expected, _, _ = _lame_system(*case)
    got = fits.fit_pressure(interference, d, inner_bore=bore, outer_diameter=outer,
                            inner_modulus=inner_material[0], inner_poisson=inner_material[1],
                            outer_modulus=outer_material[0], outer_poisson=outer_material[1])
    assert got == pytest.approx(expected, rel=1e-10)


@pytest.mark.parametrize("case", [c for c in CASES if not math.isinf(c[3])])
def test_an_inner_rings_raceway_grows_as_the_system_says(case):
    """The outer body as an inner ring on its shaft: its outside (the raceway) grows by
    twice the solved displacement there."""
    _, _, d, outer, _, outer_material = case
    pressure, _, outside = _lame_system(*case)
    got = fits.bore_pressed_expansion(pressure, d, outer, outer_material[0])
    assert got == pytest.approx(2 * outside, rel=1e-10)


@pytest.mark.parametrize("case", [c for c in CASES if c[1] > 0])
def test_an_outer_rings_raceway_shrinks_as_the_system_says(case):
    """The inner body as an outer ring in its housing: its bore (the raceway) shrinks by
    twice the solved displacement there."""
    _, bore, d, _, inner_material, _ = case
    pressure, bore_moves, _ = _lame_system(*case)
    got = fits.outside_pressed_contraction(pressure, bore, d, inner_material[0])
    assert got == pytest.approx(-2 * bore_moves, rel=1e-10)


@pytest.mark.parametrize("ratio", [0.6, 0.8, 0.9, 0.99])
def test_a_ring_on_a_solid_shaft_of_its_steel_grows_by_the_interference_times_d_over_f(ratio):
    d, interference = 50e-3, 30e-6
    raceway = d / ratio
    pressure = fits.fit_pressure(interference, d, inner_bore=0.0, outer_diameter=raceway,
                                 inner_modulus=STEEL, inner_poisson=STEEL_NU,
                                 outer_modulus=STEEL, outer_poisson=STEEL_NU)
    assert fits.bore_pressed_expansion(pressure, d, raceway, STEEL) == pytest.approx(
        interference * ratio, rel=1e-12)


def test_a_loose_fit_presses_nothing():
    pressure = fits.fit_pressure(np.array([-5e-6, 0.0]), 40e-3, inner_bore=0.0,
                                 outer_diameter=48e-3, inner_modulus=STEEL,
                                 inner_poisson=STEEL_NU, outer_modulus=STEEL,
                                 outer_poisson=STEEL_NU)
    assert np.all(pressure == 0.0)


def test_the_hoop_stress_at_the_bore_is_the_system_s():
    interference, bore, d, outer = 30e-6, 0.0, 40e-3, 48e-3
    pressure, _, _ = _lame_system(interference, bore, d, outer, (STEEL, STEEL_NU),
                                  (STEEL, STEEL_NU))
    # the ring's hoop stress at r = d/2 from its own A and B: σ_t = k((1+ν)A + (1−ν)B/r²)
    # with σ_r(d/2) = −p and σ_r(F/2) = 0: σ_t(d/2) − σ_r(d/2) = 2kB(1−ν)/r², written out
    ring_b = pressure * (d / 2) ** 2 * (outer / 2) ** 2 / ((outer / 2) ** 2 - (d / 2) ** 2)
    expected = -pressure + 2 * ring_b / (d / 2) ** 2
    assert fits.bore_hoop_stress(pressure, d, outer) == pytest.approx(expected, rel=1e-12)


def test_the_thermal_chain_sums_every_parts_expansion():
    """Each raceway and each element grows by α·ΔT times its own diameter, the elements at
    the mean of the rings' temperatures; the clearance across one line through an element
    is the outer raceway less the inner less two elements."""
    alpha, dpw, dw = 11.5e-6, 60e-3, 12e-3
    rise_inner, rise_outer = 50.0, 40.0
    t = fits.Temperatures(np.array(rise_inner), np.array(rise_outer), np.array(55.0),
                          np.array(35.0), np.array(alpha), np.array(12e-6),
                          np.array(23e-6))
    grows = (alpha * (dpw + dw) * rise_outer - alpha * (dpw - dw) * rise_inner
             - 2 * alpha * dw * (rise_inner + rise_outer) / 2)
    assert fits.thermal_clearance_reduction(t, dpw) == pytest.approx(-grows, rel=1e-12)
    inner, outer = fits.thermal_interference_change(t, 40e-3, 90e-3)
    assert inner == pytest.approx(40e-3 * (12e-6 * 55.0 - alpha * rise_inner), rel=1e-12)
    assert outer == pytest.approx(90e-3 * (alpha * rise_outer - 23e-6 * 35.0), rel=1e-12)
    assert outer < 0  # the aluminium housing loosens its fit as it warms
