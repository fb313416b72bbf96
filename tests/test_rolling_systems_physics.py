"""Disk on a circle, cone on a plane and bevel gears against independent computations.

Disk and cone: positions written down with sympy, the rolling constraint imposed
on the velocities of material points, and everything else differentiated
symbolically (docs/physics.md, "How the tests check these relations"); bevel gears:
a 3-D constraint solve.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearingcalc.core.bevel_gears import pitch_angles, solve_bevel_gears
from bearingcalc.core.cone_on_plane import solve_cone_on_plane
from bearingcalc.core.disk_on_circle import solve_disk_on_circle
from tests.independent import bevel_pair_3d

sympy = pytest.importorskip("sympy")
RTOL = 1e-9
N = 300


@functools.lru_cache(maxsize=2)
def disk_kinematics(internal: bool):
    """Numeric functions (r, R, ω, ω̇, Ω, Ω̇, θ) -> G', G'', OG rate, contact point P''."""
    t = sympy.symbols("t")
    r, big_r = sympy.symbols("r R", positive=True)
    w, w_dot, big_w, big_w_dot, theta0 = sympy.symbols("w wd W Wd theta0", real=True)
    theta, phi, psi = (sympy.Function(n)(t) for n in ("theta", "phi", "psi"))
    side = -1 if internal else 1
    e = sympy.Matrix([sympy.cos(theta), sympy.sin(theta)])
    g = (big_r + side * r) * e
    # Material point of the disk with body angle c, and of the surface with body angle c2.
    c, c2 = sympy.symbols("c c2", real=True)
    p = g + r * sympy.Matrix([sympy.cos(phi + c), sympy.sin(phi + c)])
    q = big_r * sympy.Matrix([sympy.cos(psi + c2), sympy.sin(psi + c2)])
    # At the instant, the disk point at the contact has angle θ + π (external) or θ
    # (internal) about G; the surface point has angle θ about O.
    at_contact = {c: theta + (sympy.pi if side == 1 else 0) - phi, c2: theta - psi}
    slip = (p.diff(t) - q.diff(t)).subs(at_contact)
    theta_dot = sympy.solve(slip[0] * -sympy.sin(theta) + slip[1] * sympy.cos(theta),
                            theta.diff(t))[0]
    theta_ddot = theta_dot.diff(t)
    rates = {phi.diff(t, 2): w_dot, psi.diff(t, 2): big_w_dot}
    first = {phi.diff(t): w, psi.diff(t): big_w}

    def numeric(expr):
        expr = expr.subs(theta.diff(t, 2), theta_ddot).subs(theta.diff(t), theta_dot)
        expr = expr.subs(rates).subs(first).subs(theta, theta0)
        return sympy.lambdify((r, big_r, w, w_dot, big_w, big_w_dot, theta0), expr, "numpy")

    p_ddot = p.diff(t, 2).subs(at_contact)
    return (numeric(g.diff(t)), numeric(g.diff(t, 2)), numeric(theta_dot), numeric(p_ddot))


@pytest.mark.parametrize("internal", [False, True])
def test_disk_on_circle_matches_symbolic_differentiation_of_positions(internal):
    rng = np.random.default_rng(5)
    big_r = rng.uniform(0.01, 1.0, N)
    r = big_r * rng.uniform(0.05, 0.95, N) if internal else rng.uniform(0.001, 1.0, N)
    w, w_dot, big_w, big_w_dot = rng.uniform(-100, 100, (4, N))
    big_w[: N // 4] = 0.0  # fixed surfaces too
    out = solve_disk_on_circle(r, big_r, w, disk_accel=w_dot, surface_speed=big_w,
                               surface_accel=big_w_dot, internal=internal)
    v_fn, a_fn, rate_fn, p_fn = disk_kinematics(internal)
    theta0 = 0.7  # any orientation: the results are frame-invariant
    e = np.array([np.cos(theta0), np.sin(theta0)])
    e_t = np.array([-np.sin(theta0), np.cos(theta0)])
    for i in range(N):
        args = (r[i], big_r[i], w[i], w_dot[i], big_w[i], big_w_dot[i], theta0)
        v = np.asarray(v_fn(*args), dtype=float).ravel()
        acc = np.asarray(a_fn(*args), dtype=float).ravel()
        p_acc = np.asarray(p_fn(*args), dtype=float).ravel()
        scale_v = abs(big_r[i] * big_w[i]) + abs(r[i] * w[i])
        scale_a = np.linalg.norm(acc) + np.linalg.norm(p_acc) + abs(r[i] * w_dot[i])
        assert abs(out["center_speed"][i] - v @ e_t) <= RTOL * scale_v
        assert abs(out["center_tangential_accel"][i] - acc @ e_t) <= RTOL * scale_a
        assert abs(out["center_normal_accel"][i] - (-acc @ e)) <= RTOL * scale_a
        assert abs(out["center_accel"][i] - np.linalg.norm(acc)) <= RTOL * scale_a
        assert_allclose(out["orbit_speed"][i], float(rate_fn(*args)), rtol=RTOL,
                        atol=RTOL * scale_v / (big_r[i] + r[i]))
        assert abs(out["contact_point_accel"][i] - np.linalg.norm(p_acc)) <= RTOL * scale_a


def test_disk_on_a_fixed_circle_reproduces_the_textbook_relations():
    # Rolling on a fixed surface: v_G = rω, a_G = rω̇ e_t + r²ω²/(R + r) e_n,
    # and (docs/physics.md §2) the contact point accelerates at rω²·R/(R + r) toward G.
    out = solve_disk_on_circle(0.5, 2.0, 3.0, disk_accel=0.25)
    assert_allclose(out["center_speed"], 1.5, rtol=1e-15)
    assert_allclose(out["center_tangential_accel"], 0.125, rtol=1e-15)
    assert_allclose(out["center_normal_accel"], 0.25 * 9 / 2.5, rtol=1e-15)
    assert_allclose(out["contact_point_accel"], 0.5 * 9 * 2.0 / 2.5, rtol=1e-15)


@functools.lru_cache(maxsize=1)
def cone_kinematics():
    """Numeric functions (β, ω, ω̇, a) -> precession rate, angular acceleration, v_P, a_P.

    Orientation R(t) = Rz(φ)·Ry(−β)·Rx(ψ): the body x-axis is the cone axis, tilted
    up by β so that the lowest generator lies on the plane along n1 = (cosφ, sinφ, 0).
    The angular velocity is read off Ṙ·Rᵀ; the no-slip condition (contact line at
    rest, i.e. ω·k = 0) fixes φ̇ in terms of ψ̇.
    """
    t = sympy.symbols("t")
    beta, height = sympy.symbols("beta a", positive=True)
    w, w_dot = sympy.symbols("w wd", real=True)
    phi, psi = sympy.Function("phi")(t), sympy.Function("psi")(t)
    rot = sympy.rot_axis3(-phi) * sympy.rot_axis2(beta) * sympy.rot_axis1(-psi)
    skew = sympy.simplify(rot.diff(t) * rot.T)
    omega = sympy.Matrix([skew[2, 1], skew[0, 2], skew[1, 0]])
    phi_dot = sympy.solve(omega[2], phi.diff(t))[0]
    n1 = sympy.Matrix([sympy.cos(phi), sympy.sin(phi), 0])
    spin = sympy.simplify(omega.subs(phi.diff(t), phi_dot).dot(n1))  # ω in terms of ψ̇
    psi_dot = sympy.solve(sympy.Eq(spin, w), psi.diff(t))[0]
    subs_rate = {phi.diff(t): phi_dot}
    axis_point = rot * sympy.Matrix([height / sympy.sin(beta), 0, 0])

    def numeric(expr):
        expr = expr.subs(subs_rate)
        expr = expr.subs(phi.diff(t), phi_dot)
        expr = expr.subs(psi.diff(t, 2), sympy.diff(psi_dot, w) * w_dot)
        expr = expr.subs(psi.diff(t), psi_dot).subs({phi: 0.3, psi: 1.1})
        return sympy.lambdify((beta, w, w_dot, height), sympy.simplify(expr), "numpy")

    omega_dot = omega.diff(t).subs(phi.diff(t, 2), phi_dot.diff(t))
    accel = axis_point.diff(t, 2).subs(phi.diff(t, 2), phi_dot.diff(t))
    return (numeric(phi_dot), numeric(omega_dot), numeric(axis_point.diff(t)),
            numeric(accel))


def test_cone_on_plane_matches_symbolic_differentiation_of_a_rotation_matrix():
    rng = np.random.default_rng(6)
    beta = rng.uniform(np.radians(1), np.radians(89), N)
    w, w_dot = rng.uniform(-50, 50, (2, N))
    height = rng.uniform(0.001, 1.0, N)
    out = solve_cone_on_plane(beta, w, spin_accel=w_dot, axis_point_height=height)
    rate_fn, alpha_fn, v_fn, a_fn = cone_kinematics()
    for i in range(N):
        args = (beta[i], w[i], w_dot[i], height[i])
        alpha = np.asarray(alpha_fn(*args), dtype=float).ravel()
        v = np.asarray(v_fn(*args), dtype=float).ravel()
        acc = np.asarray(a_fn(*args), dtype=float).ravel()
        assert_allclose(out["precession_speed"][i], float(rate_fn(*args)), rtol=RTOL,
                        atol=1e-12)
        assert_allclose(out["angular_accel"][i], np.linalg.norm(alpha), rtol=RTOL)
        assert_allclose(out["axis_point_speed"][i], np.linalg.norm(v), rtol=RTOL)
        assert_allclose(out["axis_point_accel"][i], np.linalg.norm(acc), rtol=RTOL)


def test_bevel_pitch_angle_of_a_12_24_pair_at_90_degrees():
    # The pitch angle of a 12/24 pair at 90°: arctan(12/24) = 26.565°.
    alpha, beta = pitch_angles(12, 24, np.radians(90.0))
    assert_allclose(np.degrees(alpha), 26.565, atol=5e-4)
    assert_allclose(np.degrees(alpha), np.degrees(np.arctan(0.5)), rtol=1e-14)
    assert_allclose(np.degrees(beta), 90 - np.degrees(np.arctan(0.5)), rtol=1e-14)


def test_bevel_gears_match_a_3d_constraint_solve():
    rng = np.random.default_rng(7)
    for _ in range(N):
        a, b = rng.uniform(0.005, 0.2, 2)
        gamma = rng.uniform(np.radians(10), np.radians(170))
        arm, shaft = rng.uniform(-300, 300, 2)
        alpha, beta = pitch_angles(a, b, gamma)
        out = solve_bevel_gears(a, b, alpha, beta, arm, gear_b_speed=shaft)
        ref = bevel_pair_3d(a, b, gamma, arm, shaft)
        assert ref["residual"] < 1e-9 * (abs(arm) + abs(shaft)) * ref["cone_distance"]
        assert_allclose(ref["distance_from_a_axis"], a, rtol=RTOL)
        speed_scale = (abs(arm) + abs(shaft)) * (1 + b / a)
        for key in ("gear_a_pitch_angle", "gear_b_pitch_angle", "cone_distance"):
            assert_allclose(out[key], ref[key], rtol=RTOL, err_msg=key)
        for key in ("gear_a_speed_relative_to_arm", "gear_a_speed", "relative_speed"):
            assert abs(out[key] - ref[key]) <= RTOL * speed_scale, key
        for key in ("contact_point_speed", "pitch_line_speed"):
            assert abs(out[key] - ref[key]) <= RTOL * speed_scale * b, key
        assert abs(out["apex_mismatch"]) < 1e-12
        # A relative to B turns at (ω_Z − Ω)·sinγ/sinα about the contact line.
        assert abs(out["relative_speed"] - abs(arm - shaft) * np.sin(gamma) / np.sin(alpha)) \
            <= RTOL * speed_scale


def test_bevel_apex_mismatch_compares_the_two_cone_distances():
    # Pitch angles fixed at 30/60 deg but radii of a 1:2 pair: the cones' apexes sit
    # at b/sinβ and a/sinα from the pitch point; the mismatch is their ratio − 1.
    a, b = 0.01, 0.02
    alpha, beta = np.radians(30.0), np.radians(60.0)
    out = solve_bevel_gears(a, b, alpha, beta, 10.0)
    assert_allclose(out["apex_mismatch"], (b / np.sin(beta)) / (a / np.sin(alpha)) - 1,
                    rtol=1e-12)
    assert out["slip_margin"] < 0
