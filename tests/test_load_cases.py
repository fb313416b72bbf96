"""The axial loads of two bearings adjusted against each other
(bearingcalc.core.arrangements.adjusted_axial_loads) against the catalogue load-case
table written out here case by case, by hand, over a random grid and against a
textbook's worked example."""

from __future__ import annotations

import numpy as np
import pytest

from bearingcalc.core.arrangements import adjusted_axial_loads

REL = 1e-9


def table(fra, frb, ra, rb, ka, to_b):
    """The catalogue load-case table, case by case as printed (SKF 2018 Table 11)."""
    ia, ib = ra * fra, rb * frb
    if to_b:
        if ia >= ib:
            return ia, ia + ka, 1
        if ka >= ib - ia:
            return ia, ia + ka, 2
        return ib - ka, ib, 3
    if ia <= ib:
        return ib + ka, ib, 4
    if ka >= ia - ib:
        return ib + ka, ib, 5
    return ia, ia - ka, 6


# -- the unit function against the table ------------------------------------------------

@pytest.mark.parametrize(("fra", "frb", "to_b", "expected"), [
    (4000.0, 2000.0, True, (2000.0, 2100.0, 1)),     # 1a
    (2000.0, 4000.0, True, (1000.0, 2500.0, 2)),     # 1b (Ka 1500 >= 1000)
    (2000.0, 4000.0, True, (1500.0, 2000.0, 3)),     # 1c (Ka 500 < 1000)
    (2000.0, 4000.0, False, (2100.0, 2000.0, 4)),    # 2a
    (4000.0, 2000.0, False, (2500.0, 1000.0, 5)),    # 2b
    (4000.0, 2000.0, False, (2000.0, 1500.0, 6)),    # 2c
    (2000.0, 2000.0, True, (1000.0, 1100.0, 1)),     # tie: 1a takes equality
    (2000.0, 2000.0, False, (1100.0, 1000.0, 4)),    # tie: 2a takes equality
])
def test_each_load_case_by_hand(fra, frb, to_b, expected):
    ka = {2: 1500.0, 3: 500.0, 5: 1500.0, 6: 500.0}.get(expected[2], 100.0)
    first, second, case = adjusted_axial_loads(fra, frb, 0.5, 0.5, ka, to_b)
    assert (float(first), float(second), float(case)) == pytest.approx(expected, rel=1e-15)


def test_the_boundary_of_b_and_c_is_continuous():
    # Ka exactly R(FrB − FrA) = 1000: case 1b (2b), with the loads 1c (2c) gives there.
    for to_b, fr, expected in ((True, (2000.0, 4000.0), (1000.0, 2000.0, 2.0)),
                               (False, (4000.0, 2000.0), (2000.0, 1000.0, 5.0))):
        loads = adjusted_axial_loads(*fr, 0.5, 0.5, 1000.0, to_b)
        assert tuple(float(v) for v in loads) == expected


def test_unit_function_matches_the_table_over_a_random_grid():
    rng = np.random.default_rng(20240521)
    n = 20000
    fra, frb = rng.uniform(1.0, 1e4, n), rng.uniform(1.0, 1e4, n)
    ra, rb = rng.uniform(0.2, 1.2, n), rng.uniform(0.2, 1.2, n)
    ka = np.where(rng.random(n) < 0.1, 0.0, rng.uniform(0.0, 5e3, n))
    to_b = rng.random(n) < 0.5
    first, second, case = adjusted_axial_loads(fra, frb, ra, rb, ka, to_b)
    expected = np.array([table(*row) for row in zip(fra, frb, ra, rb, ka, to_b, strict=True)])
    assert set(expected[:, 2].astype(int)) == {1, 2, 3, 4, 5, 6}
    np.testing.assert_allclose(first, expected[:, 0], rtol=REL, atol=1e-9)
    np.testing.assert_allclose(second, expected[:, 1], rtol=REL, atol=1e-9)
    np.testing.assert_array_equal(case, expected[:, 2])
    # Each bearing carries at least its own induced force, and the axial balance holds.
    assert np.all(first >= ra * fra * (1 - REL)) and np.all(second >= rb * frb * (1 - REL))
    np.testing.assert_allclose(np.where(to_b, second - first, first - second), ka,
                               rtol=REL, atol=1e-8)


def test_shigley_11_12_tapered_pair_without_external_thrust():
    # Budynas & Nisbett 8th ed. SM 11-12 (Timken: induced 0.47·Fr/K, K = 1.5, Fae = 0):
    # 0.781 < 1.527 kN, so FaA = FaB = 1.527 kN. With Ka = 0 either direction applies.
    for to_b in (True, False):
        first, second, _ = adjusted_axial_loads(2492.0, 4873.0, 0.47 / 1.5, 0.47 / 1.5,
                                                0.0, to_b)
        assert float(first) == pytest.approx(1527.0, abs=0.5)
        assert float(second) == pytest.approx(1527.0, abs=0.5)
