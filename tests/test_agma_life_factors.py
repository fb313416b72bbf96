"""AGMA 2003's life factors K_L and C_L on both branches and at their joins, against
Budynas & Nisbett (*Shigley's MED*, 10th ed., eqs. 15-14 and 15-15) as written in
tests/agma_miner.py; the spectrum safety against scipy's brentq on a Miner residual
written there; the low-cycle branch through a spec."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from bearingcalc.core import agma_life, bevel_rating
from tests import agma_miner
from tests.conftest import ROOT, solve_json

REL = 1e-12


@pytest.mark.parametrize("cycles", [1e3, 2.5e4, 1e5, 1e6, 2.999e6, 3e6, 1e7, 1e8, 1e9, 1e10])
def test_bending_factor_on_each_branch(cycles):
    k_l, _ = bevel_rating.life_factors(cycles)
    expected = 6.1514 * cycles ** -0.1192 if cycles < 3e6 else 1.683 * cycles ** -0.0323
    assert float(k_l) == pytest.approx(expected, rel=REL)


@pytest.mark.parametrize("cycles", [1e3, 5e3, 9999.0, 1e4, 1e5, 3e6, 1e8, 1e10])
def test_contact_factor_on_each_branch(cycles):
    _, c_l = bevel_rating.life_factors(cycles)
    expected = 2.0 if cycles < 1e4 else 3.4822 * cycles ** -0.0602
    assert float(c_l) == pytest.approx(expected, rel=REL)


def test_branches_meet_to_the_printed_digits():
    """At 3·10⁶ cycles both K_L branches give 1.040 (1.03968 and 1.03962: a relative gap
    of 6·10⁻⁵, what coefficients printed to 4 or 5 digits allow); at 10⁴ C_L's branch
    gives 2.000. Each factor just
    below a join is the lower branch's, at the join the upper's."""
    join = 3e6
    below, at = (float(bevel_rating.life_factors(n)[0]) for n in (join * (1 - 1e-12), join))
    assert below == pytest.approx(6.1514 * join ** -0.1192, rel=1e-9)
    assert at == pytest.approx(1.683 * join ** -0.0323, rel=REL)
    assert round(below, 3) == round(at, 3) == 1.040
    assert abs(below / at - 1) < 1e-4
    below, at = (float(bevel_rating.life_factors(n)[1]) for n in (1e4 * (1 - 1e-12), 1e4))
    assert below == 2.0
    assert at == pytest.approx(3.4822 * 1e4 ** -0.0602, rel=REL)
    assert round(at, 3) == 2.000


def test_at_a_thousand_cycles_the_factors_are_the_low_cycle_branches():
    """At 10³ cycles K_L = 2.70, twice what the high-cycle law gives (1.35), and
    C_L = 2, where that law gives 2.30 (15 % above)."""
    k_l, c_l = (float(f) for f in bevel_rating.life_factors(1e3))
    assert k_l == pytest.approx(2.700, abs=5e-4)
    assert k_l / (1.683 * 1e3 ** -0.0323) == pytest.approx(2.005, abs=5e-4)
    assert c_l == 2.0
    assert (3.4822 * 1e3 ** -0.0602) / c_l == pytest.approx(1.149, abs=5e-4)


def test_cycles_to_failure_inverts_the_curves():
    """N(K), the first N where the curve falls below K: on a sloped branch the inverse
    power, between K_L's two values at 3·10⁶ the join, past the flat C_L = 2 the next
    branch's crossing of 2 (at 10009 cycles), above the 10³-cycle value one cycle."""
    for load, curve in (("bending", agma_life.BENDING_LIFE_CURVE),
                        ("contact", agma_life.CONTACT_LIFE_CURVE)):
        for needed in (0.6, 0.9, 1.03965, 1.2, 1.9, 1.99999, 2.00005, 2.4, 2.69, 2.8, 3.5):
            got = float(agma_life.cycles_to_failure(needed, curve))
            expected = agma_miner.endured_cycles(needed, load)
            assert got == pytest.approx(expected, rel=1e-9), (load, needed)
    assert float(agma_life.cycles_to_failure(1.03965, agma_life.BENDING_LIFE_CURVE)) == 3e6
    flat_end = float(agma_life.cycles_to_failure(2.0, agma_life.CONTACT_LIFE_CURVE))
    assert flat_end == pytest.approx((3.4822 / 2) ** (1 / 0.0602), rel=1e-12)
    assert agma_life.cycles_to_failure(0.0, agma_life.BENDING_LIFE_CURVE) == np.inf


# --- the spectrum safety on the two-branch curves ----------------------------------------

RNG_CASES = 40


@pytest.mark.parametrize("load", ["bending", "contact"])
@pytest.mark.parametrize("cycles", [1e3, 2e4, 1e6, 1e7, 1e9])
def test_spectrum_safety_is_brentq_on_the_miner_residual(load, cycles):
    """Random spectra of 2 to 5 bins, all designs solved at once by the module; each
    against brentq on D(s) − 1 with every bin's life from brentq on the curve."""
    rng = np.random.default_rng(int(cycles) % 9973 + len(load))
    curve = (agma_life.BENDING_LIFE_CURVE if load == "bending"
             else agma_life.CONTACT_LIFE_CURVE)
    bins = 4
    shares = rng.dirichlet(np.full(bins, 0.6), size=RNG_CASES).T
    safeties = np.exp(rng.normal(0.1, 0.25, size=(bins, RNG_CASES)))
    got = agma_life.spectrum_safety(shares, safeties, cycles, curve)
    for j in range(RNG_CASES):
        u, s = shares[:, j].tolist(), safeties[:, j].tolist()
        expected = agma_miner.spectrum_safety(u, s, cycles, load)
        assert float(got[j]) == pytest.approx(expected, rel=1e-9), (u, s)
        # the largest factor whose sum is at most 1 (1 itself, or a jump past it)
        assert agma_miner.miner_sum(u, s, cycles, load, float(got[j]) * (1 - 1e-9)) <= 1.0
        assert agma_miner.miner_sum(u, s, cycles, load, float(got[j]) * (1 + 1e-9)) > 1.0


@pytest.mark.parametrize("load", ["bending", "contact"])
def test_one_bin_spectrum_is_its_own_safety(load):
    curve = (agma_life.BENDING_LIFE_CURVE if load == "bending"
             else agma_life.CONTACT_LIFE_CURVE)
    safeties = np.array([[0.7, 1.0, 1.3, 2.1]])
    got = agma_life.spectrum_safety(np.ones_like(safeties), safeties, 1e7, curve)
    np.testing.assert_allclose(got, safeties[0], rtol=1e-13)


def test_bin_at_rest_and_unstressed_bin_do_no_damage():
    shares = np.array([[0.0], [0.4], [0.6]])
    safeties = np.array([[0.5], [np.inf], [1.1]])
    got = agma_life.spectrum_safety(shares, safeties, 1e8, agma_life.BENDING_LIFE_CURVE)
    assert float(got[0]) == pytest.approx(
        agma_miner.spectrum_safety([0.6], [1.1], 1e8, "bending"), rel=1e-9)
    damage = agma_life.spectrum_damage(shares, safeties, 1e8, agma_life.BENDING_LIFE_CURVE)
    assert damage[:2, 0].tolist() == [0.0, 0.0]
    unstressed = agma_life.spectrum_safety(np.array([[1.0]]), np.array([[np.inf]]), 1e8,
                                           agma_life.BENDING_LIFE_CURVE)
    assert unstressed[0] == np.inf


def test_two_percent_peak_bin():
    """A peak bin with 2 % of 10⁷ cycles, the other bins far below it: the bin alone
    sets S, lasting 2·10⁵ cycles at the root, on the low-cycle branch. One power law
    gives S = S_p·0.02^(−0.0323); the two branches S = S_p·K_L(2·10⁵)/K_L(10⁷), which is
    1.2654 times as much: a peak bin at 0.948 on the one law is at 1.200 on AGMA's
    curve."""
    design = 1e7
    peak = 0.948 * 0.02 ** 0.0323     # S_p that the single law puts at 0.948
    shares = np.array([0.02, 0.98])
    safeties = np.array([peak, 50.0])
    got = float(agma_life.spectrum_safety(shares, safeties, design,
                                          agma_life.BENDING_LIFE_CURVE))
    expected = peak * (6.1514 * (0.02 * design) ** -0.1192) / (1.683 * design ** -0.0323)
    assert got == pytest.approx(expected, rel=1e-12)
    assert round(got, 3) == 1.200


# --- through the bevel-gears kind -----------------------------------------------------------

SPEC = (ROOT / "specs" / "bevel-gears-sizing.yaml").read_text()


def with_cycles(cycles: str) -> str:
    text, count = re.subn(r"^  cycles: \S+", f"  cycles: {cycles}", SPEC, flags=re.M)
    assert count == 1
    return text


@pytest.mark.parametrize("cycles", [1e3, 5e3, 1e5, 2e6, 3e6, 1e9])
def test_safeties_of_a_pair_scale_with_the_life_factors(cli, spec_file, cycles):
    """S_F ∝ K_L and S_H ∝ C_L at fixed stresses: the ratio to the pair at 10⁸ cycles is
    the ratio of Shigley's factors."""
    (reference,) = solve_json(cli, spec_file(with_cycles("1e8"), "reference.yaml"))
    (got,) = solve_json(cli, spec_file(with_cycles(repr(cycles)), "cycles.yaml"))
    ref, res = reference["results"], got["results"]
    assert res["bending_stress"] == pytest.approx(ref["bending_stress"], rel=REL)
    for key, factor in (("bending_safety", agma_miner.bending_factor),
                        ("contact_safety", agma_miner.contact_factor)):
        assert res[key] / ref[key] == pytest.approx(factor(cycles) / factor(1e8), rel=1e-9)
    assert math.isfinite(res["bending_safety"])
