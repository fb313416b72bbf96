"""The thrust-bearing solver against independent computations (docs/physics.md §1)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearingcalc import (
    pitch_radius_window,
    pure_rolling_ball_radius,
    pure_rolling_contact_angle,
    pure_rolling_pitch_radius,
    solve_thrust_bearing,
    spin_to_roll_ratio,
)
from bearingcalc.core.thrust_bearing import evaluate, thrust_bearing_status
from tests.independent import thrust_bearing_3d

RTOL = 1e-9


def random_geometries(n: int, seed: int = 1) -> tuple[np.ndarray, ...]:
    """n designs with 0 < θ < 45° and d > 0, spanning pitch radii around b*."""
    rng = np.random.default_rng(seed)
    r = rng.uniform(0.5e-3, 50e-3, n)
    theta = rng.uniform(np.radians(0.5), np.radians(44.5), n)
    b_low = r * np.cos(theta) * 1.01
    b = b_low + rng.uniform(0.0, 1.0, n) ** 2 * 20 * r
    omega = rng.uniform(-1000.0, 1000.0, n)
    return r, theta, b, omega


def test_every_speed_matches_a_3d_constraint_solve_over_2000_geometries():
    r, theta, b, omega = random_geometries(2000)
    out = solve_thrust_bearing(r, theta, b, omega)  # one vectorised call
    keys = ["ball_speed", "ball_center_speed", "cage_speed", "shaft_contact_speed",
            "shaft_contact_radius", "spin_speed", "roll_speed"]
    for i in range(len(r)):
        ref = thrust_bearing_3d(r[i], theta[i], b[i], omega[i])
        assert ref["residual"] < 1e-9 * max(1.0, abs(omega[i]) * b[i])
        assert abs(ref["rel_e3"]) < 1e-9 * abs(omega[i]) + 1e-300
        scale = abs(omega[i])  # speeds near zero are compared against the shaft speed
        for key in keys:
            unit_scale = scale * (b[i] if key.endswith(("center_speed", "contact_speed")) else 1.0)
            if key == "shaft_contact_radius":
                unit_scale = b[i]
            assert abs(out[key][i] - ref[key]) <= RTOL * unit_scale, key
        assert_allclose(out["spin_to_roll"][i], ref["spin_speed"] / ref["roll_speed"],
                        rtol=RTOL, atol=1e-12)


def test_ball_angular_velocity_lies_on_the_race_contact_line():
    # docs/physics.md §1: both race contacts at rest put ω_B on C1C2, i.e. along e1 − e2.
    ref = thrust_bearing_3d(0.01, np.radians(25.0), 0.03, 100.0)
    w = ref["ball_angular_velocity"]
    assert abs(w[2]) < 1e-12 and abs(w[0] + w[1]) < 1e-12


def test_hand_checked_values_of_physics_md():
    # docs/physics.md "How the tests check these relations": θ = 20°, r = 1.
    theta = np.radians(20.0)
    out = solve_thrust_bearing(1.0, theta, None, 1.0)
    assert_allclose(out["pitch_radius"], 2.24541, atol=5e-6)
    assert_allclose(out["shaft_contact_radius"], 1.30572, atol=5e-6)
    assert_allclose(out["shaft_speed"] / out["ball_speed"], 1.23565, atol=5e-6)
    assert_allclose(out["cage_speed"] / out["shaft_speed"], 0.254855, atol=5e-7)
    larger = solve_thrust_bearing(1.0, theta, 1.01 * out["pitch_radius"], 1.0)
    assert_allclose(larger["spin_to_roll"], -0.003489, atol=5e-7)


def test_kane_levinson_exercise_3_10_pitch_radius_at_30_degrees():
    # Kane & Levinson, Dynamics: Theory and Applications (1985), exercise 3.10:
    # b/r = 4.0981 at θ = 30° (reproduced by the PyDy examples).
    assert_allclose(pure_rolling_pitch_radius(1.0, np.radians(30.0)), 4.0981, atol=5e-5)


def test_pure_rolling_pitch_radius_has_zero_spin_in_the_3d_solve():
    r, theta, _, omega = random_geometries(500, seed=2)
    b_star = pure_rolling_pitch_radius(r, theta)
    for i in range(len(r)):
        ref = thrust_bearing_3d(r[i], theta[i], b_star[i], omega[i])
        assert abs(ref["spin_speed"]) <= 1e-9 * abs(ref["roll_speed"])


def test_each_unknown_solved_in_turn_gives_the_inputs_back():
    r, theta, b, _ = random_geometries(1000, seed=3)
    b_star = pure_rolling_pitch_radius(r, theta)
    assert_allclose(pure_rolling_contact_angle(r, b_star), theta, rtol=RTOL)
    assert_allclose(pure_rolling_ball_radius(theta, b_star), r, rtol=RTOL)
    # And the closed form for θ satisfies the defining relation b·cosθ − (b + r)·sinθ = r.
    rb, bb = r[b > r], b[b > r]
    solved = pure_rolling_contact_angle(rb, bb)
    assert_allclose(bb * np.cos(solved) - (bb + rb) * np.sin(solved), rb, rtol=RTOL)


def test_pure_rolling_condition_agrees_with_sympy():
    sympy = pytest.importorskip("sympy")
    r, th, b, w_b = sympy.symbols("r theta b omega_B", positive=True)
    e1, e2, e3 = sympy.Matrix([1, 0, 0]), sympy.Matrix([0, 1, 0]), sympy.Matrix([0, 0, 1])
    w_ball = w_b * (e1 - e2) / sympy.sqrt(2)
    c1 = -r * e1                                  # from G
    c3 = r * (sympy.cos(th) * e1 + sympy.sin(th) * e2)
    # C1 at rest: v_G = −w × (C1 − G); ball point at C3: v_G + w × (C3 − G).
    v_g = -w_ball.cross(c1)
    v_c3 = v_g + w_ball.cross(c3)
    w_s = sympy.simplify(v_c3.dot(e3) / (b - r * sympy.cos(th)))
    rel = w_s * e2 - w_ball
    spin = rel.dot(sympy.cos(th) * e1 + sympy.sin(th) * e2)
    b_solution = sympy.solve(sympy.Eq(sympy.simplify(spin), 0), b)
    assert len(b_solution) == 1
    f = sympy.lambdify((r, th), b_solution[0], "numpy")
    rr, tt, _, _ = random_geometries(200, seed=4)
    assert_allclose(pure_rolling_pitch_radius(rr, tt), f(rr, tt), rtol=RTOL)


@settings(max_examples=200, deadline=None)
@given(r=st.floats(1e-4, 1.0), theta=st.floats(0.01, np.pi / 4 - 0.01),
       factor_a=st.floats(0.3, 5.0), factor_b=st.floats(0.3, 5.0))
def test_spin_to_roll_is_zero_at_b_star_and_falls_as_b_grows(r, theta, factor_a, factor_b):
    b_star = pure_rolling_pitch_radius(r, theta)
    assert abs(spin_to_roll_ratio(r, theta, b_star)) < 1e-12
    low = r * np.cos(theta)
    b1, b2 = sorted([low + factor_a * (b_star - low), low + factor_b * (b_star - low)])
    if b2 - b1 > 1e-9 * b2:
        assert spin_to_roll_ratio(r, theta, b1) > spin_to_roll_ratio(r, theta, b2)


@settings(max_examples=200, deadline=None)
@given(r=st.floats(1e-4, 1.0), theta=st.floats(0.01, np.pi / 4 - 0.01),
       rho_max=st.floats(1e-4, 0.5))
def test_window_edges_hit_the_limit_exactly_in_the_3d_solve(r, theta, rho_max):
    b_min, b_max = pitch_radius_window(r, theta, rho_max)
    if rho_max < np.tan(theta):
        ref = thrust_bearing_3d(r, theta, float(b_min), 1.0)
        # The 3-D least-squares solve resolves spin to about 1e-12 of the roll.
        assert_allclose(ref["spin_speed"] / ref["roll_speed"], rho_max, rtol=1e-8, atol=1e-11)
    else:
        assert_allclose(b_min, r * np.cos(theta), rtol=RTOL)
    if rho_max < np.tan(np.pi / 4 - theta):
        ref = thrust_bearing_3d(r, theta, float(b_max), 1.0)
        assert_allclose(ref["spin_speed"] / ref["roll_speed"], -rho_max, rtol=1e-8, atol=1e-11)
    else:
        assert np.isinf(b_max)


def test_ball_pass_frequencies_count_balls_passing_race_and_shaft():
    out = solve_thrust_bearing(0.005, np.radians(30.0), None, 100.0, ball_count=10)
    cage = out["cage_speed"]
    assert_allclose(out["ball_pass_frequency_race"], 10 * cage / (2 * np.pi), rtol=RTOL)
    assert_allclose(out["ball_pass_frequency_shaft"], 10 * (100.0 - cage) / (2 * np.pi),
                    rtol=RTOL)


def test_solver_broadcasts_arrays_and_marks_impossible_points_nan():
    theta = np.radians([10.0, 30.0, 50.0])
    out = solve_thrust_bearing(0.01, theta, 0.03, np.array([[1.0], [2.0]]))
    assert out["spin_to_roll"].shape == (2, 3)
    assert np.isnan(out["spin_to_roll"][:, 2]).all()
    assert np.isfinite(out["spin_to_roll"][:, :2]).all()


def test_status_codes_name_the_reason():
    r = np.array([0.01, 0.01, 0.01, -0.01, 0.01])
    theta = np.radians([20.0, 50.0, 20.0, 20.0, 20.0])
    b = np.array([0.03, 0.03, 0.005, 0.03, 0.021])
    z = np.array([3, 3, 3, 3, 40])
    assert thrust_bearing_status(r, theta, b, z).tolist() == [0, 3, 4, 1, 5]
    solution = evaluate({"ball_radius": 0.01, "contact_angle": None, "pitch_radius": 0.009,
                         "shaft_speed": 1.0, "ball_count": None, "max_spin_to_roll": 0.01})
    assert int(solution.status) == 6


def test_more_than_one_unknown_is_refused():
    with pytest.raises(ValueError, match="at most one"):
        solve_thrust_bearing(None, None, 0.02, 1.0)
