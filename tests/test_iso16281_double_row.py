"""A double-row cylindrical or needle roller bearing as mounted (``rows: 2``, ``method:
iso-16281``) through the command line, against a reference for two rows written here.

The reference shares no formula with ``bearingcalc.core``: it is written from ISO/TS
16281:2008 and borrows from ``tests/iso16281_reference.py`` (itself written from the
standard) only the logarithmic profile (eqs. 42-44), the line spring's unit conversion
and the raceway ratings (eqs. 47-57 with i = 2 rows). The two rows' laminae, their
equilibrium, the tangent stiffness and the life sum are here.

Model (rigid rings, laminae): ISO/TS 16281:2008, the laminae's deflections, profile and
equilibrium (eqs. 38-46 as tests/iso16281_reference.py numbers them; the standard's own
text was not at hand) and clause 8.3, the reference rating life of roller bearings (eqs.
47-65); Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., Part 2 (Advanced Concepts),
ch. 1, for the sliced line contact q = (c_L/ns)·δ^(10/9), c_L = 35 948·Lwe^(8/9)
N/mm^(10/9), and a misaligned or moment-loaded roller's laminae:

* x along the axis, y along the radial load, roller j of each row at ψ_j = 2πj/Z on the
  same azimuths in both rows; δx = 0 (a cylindrical bearing carries no axial load).
* Lamina k at ℓ_k = (k − ns/2 + 0.5)·Lwe/ns from its roller's middle; row 1's middle at
  x = −d/2, row 2's at +d/2, d = max(B/2, Lwe), or Lwe without a width.
* δ_jk = (δy − x_k·θz)·cos ψ_j − Pd/2 − 2·p(ℓ_k); Fr = Σ q_jk·cos ψ_j; Mz = −Σ q_jk·x_k·cos ψ_j.
* Q_ci, Q_ce with λν = 0.83, i = 2, Z per row; q_c = Q_c·ns^(−7/9); per raceway lamina
  (2·ns of them) q_ei the mean of exponent 4, q_ee of exponent 4.5 over the Z rollers
  (inner ring rotating); L10r = [Σ (q_ei/q_ci)^4.5 + (q_ee/q_ce)^4.5]^(−8/9) 10^6 rev.

Sign convention, read off the output and pinned by the tests: ``tilting_moment_reaction``
and ``tilting_moment`` are both Mz = −Σ q·x·cos ψ, the moment on the inner ring that the
contacts balance (work-conjugate to θz as Fr is to δy), positive with a positive θz, which
loads row 1 (at −x) more at ψ = 0.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy import optimize

from tests import iso16281_reference as reference
from tests.conftest import solve_json

SPEC = """kind: rolling-bearing
type: {type}
method: iso-16281
rows: {rows}
dynamic_load_rating: 53 kN
static_load_rating: 80 kN
roller_count: {z}
roller_diameter: {dwe} mm
roller_length: {lwe} mm
pitch_diameter: 65 mm
operating_clearance: 5 µm
laminae: {ns}
radial_load: {fr} N
speed: 1500 rpm
{extra}
"""
C = 53e3
SPEED = 1500.0 / 60.0  # rev/s


@dataclasses.dataclass(frozen=True)
class DoubleRow:
    """Two rows of Z rollers [m]; ``profile`` "none", "iso" or a crown radius [m]."""

    z: int
    dwe: float
    lwe: float
    spacing: float
    clearance: float = 5e-6
    ns: int = 30
    profile: str | float = "iso"
    dpw: float = 65e-3

    def row(self, rows: int = 2) -> reference.RollerBearing:
        """One row as the scalar reference's bearing (for its profile and ratings)."""
        return reference.RollerBearing(
            self.z, self.dwe, self.lwe, self.dpw, diametral_clearance=self.clearance,
            laminae=self.ns, profile="none" if isinstance(self.profile, float) else self.profile,
            rows=rows)

    @property
    def ell(self) -> np.ndarray:
        return (np.arange(self.ns) - self.ns / 2 + 0.5) * self.lwe / self.ns

    @property
    def x(self) -> np.ndarray:
        """Axial positions x_k [m] of the laminae, shape (2, ns): row 1 then row 2."""
        return np.stack([-self.spacing / 2 + self.ell, self.spacing / 2 + self.ell])

    @property
    def drop(self) -> np.ndarray:
        """p(ℓ_k) [m]: the scalar reference's ISO/none profile, or a crown's R − √(R² − ℓ²)."""
        if isinstance(self.profile, float):
            return self.profile - np.sqrt(self.profile**2 - self.ell**2)
        return self.row().profile_drop

    @property
    def cos(self) -> np.ndarray:
        return np.cos(2 * math.pi * np.arange(self.z) / self.z)

    def deflection(self, dy: float, tz: float) -> np.ndarray:
        """δ_rjk [m], shape (2, Z, ns)."""
        return ((dy - self.x[:, None, :] * tz) * self.cos[None, :, None]
                - self.clearance / 2 - 2 * self.drop[None, None, :])

    @property
    def lamina_spring(self) -> float:
        """c_L/ns [N/m^(10/9)]: 35 948 N/mm^(10/9)·(Lwe/mm)^(8/9) in SI, shared by ns."""
        return reference.LINE_SPRING_SI * self.lwe ** (8 / 9) / self.ns

    def loads(self, dy: float, tz: float) -> np.ndarray:
        """q_rjk [N]."""
        return self.lamina_spring * np.maximum(self.deflection(dy, tz), 0.0) ** (10 / 9)

    def forces(self, dy: float, tz: float) -> tuple[float, float]:
        """(Fr, Mz) [N, N·m] the contacts carry."""
        q = self.loads(dy, tz) * self.cos[None, :, None]
        return float(q.sum()), float(-(q * self.x[:, None, :]).sum())

    def tangent(self, dy: float, tz: float) -> np.ndarray:
        """K_ab = Σ k_rjk·g_a·g_b [SI] over q = (x, y, z, θy, θz), with the lamina's
        tangent k = (10/9)(c_L/ns)·δ^(1/9) and g = ∂δ/∂q = (0, cos ψ, sin ψ,
        −x sin ψ, −x cos ψ) (θy the same tilt turned by 90°)."""
        k = 10 / 9 * self.lamina_spring * np.maximum(self.deflection(dy, tz), 0.0) ** (1 / 9)
        psi = 2 * math.pi * np.arange(self.z) / self.z
        c, s = np.cos(psi)[None, :, None], np.sin(psi)[None, :, None]
        x = self.x[:, None, :]
        g = [0 * c * x, c + 0 * x, s + 0 * x, -x * s, -x * c]
        return np.array([[np.sum(k * ga * gb) for gb in g] for ga in g])

    def radial(self, fr: float, tz: float) -> float:
        """δy [m] with Fr(δy, θz) = fr at a given θz: Fr is increasing in δy."""
        return optimize.brentq(lambda dy: self.forces(dy, tz)[0] - fr, -1e-3, 1e-3,
                               xtol=1e-22, rtol=4 * np.finfo(float).eps, maxiter=500)

    def with_moment(self, fr: float, mz: float) -> tuple[float, float]:
        """(δy, θz) with Fr = fr and Mz = mz: brentq on θz over δy's own brentq."""
        def excess(tz):
            return self.forces(self.radial(fr, tz), tz)[1] - mz
        tz = optimize.brentq(excess, -5e-3, 5e-3, xtol=1e-22,
                             rtol=4 * np.finfo(float).eps, maxiter=500)
        return self.radial(fr, tz), tz

    def life_million(self, dy: float, tz: float) -> float:
        """L10r [10^6 rev], inner ring rotating, over both rows' 2·ns raceway laminae."""
        _, _, qc_i, qc_e = reference.roller_raceway_ratings(self.row(rows=2), C)
        q = self.loads(dy, tz)
        q = np.concatenate([q[0], q[1]], axis=1)  # (Z, 2·ns): a lamina per column
        q_ei = np.mean(q**4, axis=0) ** (1 / 4)
        q_ee = np.mean(q**4.5, axis=0) ** (1 / 4.5)
        return float(np.sum((q_ei / qc_i) ** 4.5 + (q_ee / qc_e) ** 4.5) ** (-8 / 9))


def _spec(kind, z, dwe, lwe, fr, extra, ns=30, rows=2):
    return SPEC.format(type=kind, rows=rows, z=z, dwe=dwe, lwe=lwe, fr=fr, ns=ns,
                       extra=extra)


def _results(cli, spec_file, text) -> dict:
    [record] = solve_json(cli, spec_file(text))
    return record["results"]


def _assert_equals_reference(results, bearing: DoubleRow, dy, tz):
    """Every in-plane result of the double row against the reference's state (dy, tz)."""
    assert results["ring_displacement_radial"] == pytest.approx(dy, rel=1e-9)
    assert results["ring_tilt"] == pytest.approx(tz, rel=1e-9, abs=1e-15)
    assert results["ring_displacement_axial"] == 0.0
    roller = bearing.loads(dy, tz).sum(axis=2)  # (2, Z)
    # a roller that touches carries well above rounding: "loaded" is not a coin toss
    assert np.all((roller == 0) | (roller > 1e-6 * roller.max()))
    assert results["max_element_load"] == pytest.approx(roller.max(), rel=1e-9)
    assert results["loaded_elements"] == np.count_nonzero(roller > 0)
    for r in (1, 2):
        got = [results[f"row_{r}_element_{m}_load"] for m in range(1, bearing.z + 1)]
        np.testing.assert_allclose(got, roller[r - 1], rtol=1e-9, atol=1e-9 * roller.max())
        azimuths = [results[f"row_{r}_element_{m}_azimuth"] for m in range(1, bearing.z + 1)]
        np.testing.assert_allclose(azimuths, 2 * np.pi * np.arange(bearing.z) / bearing.z,
                                   rtol=1e-15, atol=1e-15)
    life = bearing.life_million(dy, tz)
    assert results["reference_rating_life_revolutions"] == pytest.approx(life * 1e6, rel=1e-9)
    assert results["reference_rating_life"] == pytest.approx(life * 1e6 / SPEED, rel=1e-9)
    _assert_stiffness(results, bearing, dy, tz)


def _assert_stiffness(results, bearing: DoubleRow, dy, tz):
    """The tangent matrix against Σ k·g·gᵀ, and its tilt entry against central
    differences of the reference's Mz at fixed δy (not the stiffness condensed on δy)."""
    names = reference.DOF_NAMES
    k = bearing.tangent(dy, tz)
    for a in range(5):
        for b in range(a, 5):
            # entries zero by symmetry are rounding noise on the scale of the diagonal
            scale = math.sqrt(abs(k[a, a] * k[b, b]))
            assert results[f"stiffness_matrix_{names[a]}_{names[b]}"] == pytest.approx(
                k[a, b], rel=1e-9, abs=1e-12 * scale), (names[a], names[b])
    assert results["stiffness_radial"] == pytest.approx(k[1, 1], rel=1e-9)
    assert results["stiffness_tilt"] == pytest.approx(k[4, 4], rel=1e-9)
    # Central differences: 1e-6 only, the truncation error h²·M''' of a step of 1e-8 rad
    # (M''' grows as δ^(−8/9) at the laminae just touching) and rounding (1e-16·M/h).
    h = 1e-8
    central = (bearing.forces(dy, tz + h)[1] - bearing.forces(dy, tz - h)[1]) / (2 * h)
    assert results["stiffness_tilt"] == pytest.approx(central, rel=1e-6)


def test_a_straight_roller_under_misalignment_is_the_two_row_reference(cli, spec_file):
    bearing = DoubleRow(23, 6.5e-3, 7e-3, spacing=13e-3, profile="none")
    results = _results(cli, spec_file, _spec(
        "cylindrical-roller", 23, 6.5, 7, 10e3,
        "width: 26 mm\nroller_profile: none\nmisalignment: 0.5 mrad"))
    dy = bearing.radial(10e3, 5e-4)
    _assert_equals_reference(results, bearing, dy, 5e-4)
    fr, mz = bearing.forces(dy, 5e-4)
    assert fr == pytest.approx(10e3, rel=1e-12)
    # The sign: the reaction is Mz = −Σ q·x·cos ψ, positive for θz > 0 (row 1 loaded more).
    assert mz > 0
    assert results["tilting_moment_reaction"] == pytest.approx(mz, rel=1e-9)
    assert results["row_1_element_1_load"] > results["row_2_element_1_load"]


@pytest.mark.parametrize("moment", [20.0, -35.0])
def test_an_iso_profile_under_a_tilting_moment_finds_the_reference_tilt(cli, spec_file,
                                                                        moment):
    bearing = DoubleRow(23, 6.5e-3, 7e-3, spacing=13e-3, profile="iso")
    results = _results(cli, spec_file, _spec(
        "cylindrical-roller", 23, 6.5, 7, 10e3, f"width: 26 mm\ntilting_moment: {moment} N*m"))
    dy, tz = bearing.with_moment(10e3, moment)
    assert math.copysign(1.0, tz) == math.copysign(1.0, moment)
    assert bearing.forces(dy, tz) == pytest.approx((10e3, moment), rel=1e-12)
    _assert_equals_reference(results, bearing, dy, tz)


def test_without_a_width_the_rows_lie_one_roller_length_apart(cli, spec_file):
    bearing = DoubleRow(23, 6.5e-3, 7e-3, spacing=7e-3, ns=40, profile=1.0)
    results = _results(cli, spec_file, _spec(
        "cylindrical-roller", 23, 6.5, 7, 12e3,
        "roller_profile: {crown_radius: 1 m}\nmisalignment: -0.8 mrad", ns=40))
    dy = bearing.radial(12e3, -8e-4)
    _assert_equals_reference(results, bearing, dy, -8e-4)
    assert results["tilting_moment_reaction"] == pytest.approx(bearing.forces(dy, -8e-4)[1],
                                                               rel=1e-9)
    # The product refuses B ≤ 2·Lwe ("rows' rollers lie side by side within the rings'
    # width"), so with a width max(B/2, Lwe) is B/2: just above, the rows are B/2 apart.
    wider = dataclasses.replace(bearing, spacing=7.1e-3)
    results = _results(cli, spec_file, _spec(
        "cylindrical-roller", 23, 6.5, 7, 12e3,
        "width: 14.2 mm\nroller_profile: {crown_radius: 1 m}\nmisalignment: -0.8 mrad", ns=40))
    _assert_equals_reference(results, wider, wider.radial(12e3, -8e-4), -8e-4)


@pytest.mark.parametrize("extra", ["misalignment: 0.5 mrad", "tilting_moment: 40 N*m"])
def test_a_double_row_needle_bearing_is_the_two_row_reference(cli, spec_file, extra):
    # Lwe = 12 mm > 2.5·Dwe = 7.5 mm: ISO's profile is flat in the middle (eq. 44's branch)
    bearing = DoubleRow(40, 3e-3, 12e-3, spacing=13e-3, profile="iso")
    assert bearing.drop[bearing.ns // 2] == 0.0 and bearing.drop[0] > 0
    results = _results(cli, spec_file, _spec("needle-roller", 40, 3, 12, 10e3,
                                             f"width: 26 mm\n{extra}"))
    if extra.startswith("misalignment"):
        dy, tz = bearing.radial(10e3, 5e-4), 5e-4
    else:
        dy, tz = bearing.with_moment(10e3, 40.0)
    _assert_equals_reference(results, bearing, dy, tz)


@pytest.mark.parametrize(("kind", "z", "dwe", "lwe", "profile"), [
    ("cylindrical-roller", 23, 6.5, 7, "iso"), ("needle-roller", 40, 3, 12, "none")])
def test_untilted_rows_each_are_a_single_row_at_half_the_load(cli, spec_file, kind, z,
                                                              dwe, lwe, profile):
    """Without tilt both rows deflect alike, so each carries Fr/2: a row's roller loads and
    δy are a single row's (same rollers, same C, i = 1) at Fr/2, not half of it at Fr (the
    law is δ^(10/9)). In the life, q_c of i = 2 is 2^(−7/9) of i = 1's, which raises each
    term by 2^(7/9·4.5) = 2^3.5, and the laminae double: the sum is 2^4.5 times the single
    row's and L10r = L10r,single(Fr/2)/2^(4.5·8/9) = L10r,single(Fr/2)/16 exactly."""
    extra = f"roller_profile: {profile}\n"
    double = _results(cli, spec_file, _spec(kind, z, dwe, lwe, 10e3,
                                            extra + "width: 26 mm\nmisalignment: 0 mrad"))
    single = _results(cli, spec_file, _spec(kind, z, dwe, lwe, 5e3, extra, rows=1))
    bearing = DoubleRow(z, dwe * 1e-3, lwe * 1e-3, spacing=13e-3, profile=profile)
    dy = bearing.radial(10e3, 0.0)
    _assert_equals_reference(double, bearing, dy, 0.0)
    assert double["tilting_moment_reaction"] == pytest.approx(
        0.0, abs=1e-12 * 10e3 * bearing.spacing)
    assert double["ring_displacement_radial"] == pytest.approx(
        single["ring_displacement_radial"], rel=1e-9)
    lone = [single[f"element_{m}_load"] for m in range(1, z + 1)]
    for r in (1, 2):
        got = [double[f"row_{r}_element_{m}_load"] for m in range(1, z + 1)]
        np.testing.assert_allclose(got, lone, rtol=1e-9, atol=1e-9 * max(lone))
    assert double["max_element_load"] == pytest.approx(single["max_element_load"], rel=1e-9)
    assert double["loaded_elements"] == 2 * single["loaded_elements"]
    assert double["reference_rating_life_revolutions"] == pytest.approx(
        single["reference_rating_life_revolutions"] / 16, rel=1e-9)
