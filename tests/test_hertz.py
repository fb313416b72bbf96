"""The Hertz point-contact solver against computations that share none of its code.

Closed forms (Johnson, Contact Mechanics, Cambridge 1985, §4.2), a brute-force
integral of the pressure, the surface displacement of the Boussinesq solution
integrated over the contact ellipse, an independent root find of the ellipticity
with elliptic integrals by quadrature, mpmath at 30 digits, and the ISO 76 basis.
"""

from __future__ import annotations

import itertools
import json
import math
import subprocess
import sys

import numpy as np
import pytest
from mpmath import ellipe as mp_ellipe
from mpmath import ellipk as mp_ellipk
from mpmath import mp, mpf
from scipy.integrate import dblquad, quad
from scipy.optimize import brentq

from bearingcalc.core import ball_bearing_contacts, iso76, thrust_bearing_contacts
from bearingcalc.core.hertz import curvature_difference, ellipse_modulus, hertz_point_contact
from tests.conftest import ROOT, csv_column, solve_json, study_status

STEEL = (210e9, 0.3, 210e9, 0.3)


def test_sphere_on_a_flat_matches_johnsons_closed_form():
    """Johnson eq. (4.22)-(4.23): a = (3QR/4E*)^(1/3), p0 = 3Q/(2πa²), δ = a²/R, with
    1/E* = 2(1 − ν²)/E. R = 6.35 mm, Q = 10 N, E = 210 GPa, ν = 0.3: p0 ≈ 861 MPa,
    a ≈ 0.0745 mm."""
    radius, load = 6.35e-3, 10.0
    e_star = 210e9 / (2 * (1 - 0.3 ** 2))
    a = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    out = hertz_point_contact(load, 1 / radius, 1 / radius, 0.0, 0.0, *STEEL)
    assert float(out["semi_major"]) == pytest.approx(a, rel=1e-13)
    assert float(out["semi_minor"]) == pytest.approx(a, rel=1e-13)
    assert float(out["max_pressure"]) == pytest.approx(3 * load / (2 * math.pi * a * a),
                                                       rel=1e-13)
    assert float(out["approach"]) == pytest.approx(a * a / radius, rel=1e-13)
    assert round(float(out["max_pressure"]) / 1e6) == 861
    assert round(float(out["semi_major"]) * 1e3, 4) == 0.0745


def test_equal_crossed_cylinders_are_a_sphere_on_a_flat():
    """Johnson §4.2: two cylinders of radius R crossed at right angles touch as a sphere
    of radius R on a flat does."""
    crossed = hertz_point_contact(50.0, 1 / 0.01, 0.0, 0.0, 1 / 0.01, *STEEL)
    sphere = hertz_point_contact(50.0, 1 / 0.01, 1 / 0.01, 0.0, 0.0, *STEEL)
    for key in ("semi_major", "semi_minor", "approach", "max_pressure"):
        assert float(crossed[key]) == pytest.approx(float(sphere[key]), rel=1e-13)


def _k_and_e(m: float) -> tuple[float, float]:
    k = quad(lambda t: 1 / math.sqrt(1 - m * math.sin(t) ** 2), 0, math.pi / 2,
             epsabs=1e-13, epsrel=1e-13, limit=200)[0]
    e = quad(lambda t: math.sqrt(1 - m * math.sin(t) ** 2), 0, math.pi / 2,
             epsabs=1e-13, epsrel=1e-13, limit=200)[0]
    return k, e


@pytest.mark.parametrize("difference", [1e-6, 1e-3, 0.05, 0.3, 0.6, 0.9, 0.97, 0.995])
def test_ellipse_modulus_agrees_with_an_independent_root_find(difference):
    def mismatch(k):
        big_k, big_e = _k_and_e(1 - 1 / k ** 2)
        return ((k * k + 1) * big_e - 2 * big_k) / ((k * k - 1) * big_e) - difference

    k = brentq(mismatch, 1 + 1e-9, 200.0, xtol=1e-15, rtol=1e-15)
    m = float(ellipse_modulus(difference))
    # The quadrature's own cancellation limits the comparison near F = 0.
    assert 1 / math.sqrt(1 - m) == pytest.approx(k, rel=1e-10)


def test_ellipse_modulus_is_exact_to_rounding_by_mpmath():
    mp.dps = 60  # the numerator cancels to order m²: 1e-20 of its terms for tiny m
    rng = np.random.default_rng(7)
    targets = np.concatenate([rng.uniform(0, 1, 300), 10.0 ** -rng.uniform(1, 12, 100),
                              1 - 10.0 ** -rng.uniform(1, 10, 100)])
    moduli = ellipse_modulus(targets)
    for f, m in zip(targets.tolist(), moduli.tolist(), strict=True):
        exact_m = mpf(m)
        value = ((2 - exact_m) * mp_ellipe(exact_m) - 2 * (1 - exact_m) * mp_ellipk(exact_m)) \
            / (exact_m * mp_ellipe(exact_m))
        assert abs(float((value - f) / f)) < 2e-14, (f, m)


def test_circle_and_impossible_contacts():
    assert float(ellipse_modulus(0.0)) == 0.0
    assert np.isnan(ellipse_modulus(1.0)) and np.isnan(ellipse_modulus(-0.1))
    out = hertz_point_contact(1.0, 1.0, 1.0, -2.0, -2.0, *STEEL)   # concave wins: Σρ < 0
    assert np.isnan(out["max_pressure"])


def test_curvature_difference_series_and_closed_form_meet():
    below, above = np.nextafter(0.3, 0), 0.3
    assert float(curvature_difference(below)) == pytest.approx(
        float(curvature_difference(above)), rel=1e-14)


@pytest.fixture(scope="module")
def elliptic_contact():
    """A ball in an inner-race groove: 6205 ball, fi = 0.52."""
    dw, gamma = 7.938e-3, 7.938 / 38.5
    curvatures = (2 / dw, 2 / dw, 2 * gamma / (dw * (1 - gamma)), -1 / (0.52 * dw))
    out = hertz_point_contact(2000.0, *curvatures, 207.5e9, 0.3, 207.5e9, 0.3)
    return curvatures, {key: float(value) for key, value in out.items()}


def test_the_pressure_integrates_to_the_load(elliptic_contact):
    _, out = elliptic_contact
    a, b, p0 = out["semi_major"], out["semi_minor"], out["max_pressure"]
    total, _ = dblquad(lambda y, x: p0 * math.sqrt(max(0.0, 1 - (x / a) ** 2 - (y / b) ** 2)),
                       -a, a, lambda x: -b * math.sqrt(1 - (x / a) ** 2),
                       lambda x: b * math.sqrt(1 - (x / a) ** 2), epsabs=1e-10, epsrel=1e-10)
    assert total == pytest.approx(2000.0, rel=1e-8)


def _boussinesq_displacement(x, y, a, b, p0, compliance):
    """Combined normal surface displacement at (x, y) under the Hertz pressure, from the
    point-load (Boussinesq) solution w = (1 − ν²)/(πE)·P/r, integrated in polar
    coordinates about (x, y): along each ray the pressure's integral is elementary."""
    def along_ray(phi):
        c, s = math.cos(phi), math.sin(phi)
        # 1 − ((x + rc)/a)² − ((y + rs)/b)² = α − 2βr − γr²
        alpha = 1 - (x / a) ** 2 - (y / b) ** 2
        beta = x * c / a ** 2 + y * s / b ** 2
        gamma = (c / a) ** 2 + (s / b) ** 2
        radius2 = alpha / gamma + (beta / gamma) ** 2
        radius = math.sqrt(radius2)
        u0 = beta / gamma
        primitive = u0 * math.sqrt(max(radius2 - u0 * u0, 0.0)) + radius2 * math.asin(
            max(-1.0, min(1.0, u0 / radius)))
        return math.sqrt(gamma) * 0.5 * (radius2 * math.pi / 2 - primitive)

    integral = quad(along_ray, 0, 2 * math.pi, epsabs=1e-15, epsrel=1e-13, limit=400)[0]
    return compliance / math.pi * p0 * integral


def test_surface_displacement_closes_the_gap_of_the_two_bodies(elliptic_contact):
    """Inside the contact, displacement + initial gap = the approach δ at every point.
    The gap is ½(ρ1a + ρ2a)·X² + ½(ρ1b + ρ2b)·Y² with X along the semi-major axis, which
    lies in the plane of the smaller curvature sum."""
    (r1a, r1b, r2a, r2b), out = elliptic_contact
    a, b, p0, approach = (out[k] for k in ("semi_major", "semi_minor", "max_pressure",
                                           "approach"))
    sums = sorted([r1a + r2a, r1b + r2b])  # smaller sum: the semi-major axis's plane
    compliance = 2 * (1 - 0.3 ** 2) / 207.5e9
    for fx, fy in ((0.0, 0.0), (0.5, 0.0), (0.0, 0.6), (0.3, -0.4), (-0.7, 0.2)):
        x, y = fx * a, fy * b
        gap = 0.5 * sums[0] * x * x + 0.5 * sums[1] * y * y
        displacement = _boussinesq_displacement(x, y, a, b, p0, compliance)
        assert displacement + gap == pytest.approx(approach, rel=1e-9), (fx, fy)


def test_scaling_laws_of_load():
    loads = np.array([1.0, 8.0, 27.0, 1000.0])
    out = hertz_point_contact(loads, 250.0, 250.0, 60.0, -240.0, *STEEL)
    assert np.allclose(out["max_pressure"] / np.cbrt(loads), out["max_pressure"][0], rtol=1e-13)
    assert np.allclose(out["approach"] / np.cbrt(loads) ** 2, out["approach"][0], rtol=1e-13)
    assert np.allclose(out["ellipticity"], out["ellipticity"][0], rtol=1e-14)


def test_iso_76_basis_through_the_bearing_contacts():
    """ISO 76:2006 6.1: at P0 = C0 the inner contact of the most heavily loaded ball sees
    4200 MPa. For a 6205 (fi = 0.52) C0 from Table 1's f0 must give that within 1 %
    (pressure ∝ load^(1/3), so within 1/3 % in pressure)."""
    c0, _ = iso76.static_load_rating(9, 7.938e-3, 38.5e-3, 0.0)
    out = ball_bearing_contacts.ball_contacts(9, 7.938e-3, 38.5e-3, 0.0, False, c0, 0.52,
                                              0.53, 207.5e9, 0.3, 4.2e9)
    assert float(out["inner_contact_pressure"]) ** 3 == pytest.approx(4.2e9 ** 3, rel=0.01)
    assert float(out["max_ball_load"]) == pytest.approx(5 * float(c0) / 9, rel=1e-15)


def test_thrust_ball_forces_balance_in_three_dimensions():
    """Each ball's forces and moments balance as vectors, and the shaft's share of all Z
    balls adds up to the axial load with no net radial force."""
    r, theta, b, z, fa = 6.35e-3, math.radians(30), 26e-3, 12, 2000.0
    cage = 52.3
    out = thrust_bearing_contacts.ball_contact_loads(r, theta, b, cage, z, fa, 207.5e9, 0.3,
                                                     7850.0, 4.2e9)
    q1, q2, q3 = (float(out[k]) for k in ("race_radial_contact_load",
                                          "race_axial_contact_load", "shaft_contact_load"))
    mass = 7850.0 * 4 / 3 * math.pi * r ** 3
    shaft_total = np.zeros(3)
    for i in range(z):
        phi = 2 * math.pi * i / z
        outward = np.array([math.cos(phi), math.sin(phi), 0.0])
        e1, e2 = -outward, np.array([0.0, 0.0, 1.0])           # e1 toward the axis
        centre = b * outward
        normal = math.cos(theta) * e1 + math.sin(theta) * e2     # toward the shaft contact
        points = [centre - r * e1, centre - r * e2, centre + r * normal]
        forces = [q1 * e1, q2 * e2, -q3 * normal]                # race wall, floor, shaft
        centrifugal = mass * b * cage ** 2 * outward
        total = sum(forces) + centrifugal
        moment = sum(np.cross(p - centre, f) for p, f in zip(points, forces, strict=True))
        assert np.allclose(total, 0.0, atol=1e-9 * fa)
        assert np.allclose(moment, 0.0, atol=1e-12 * fa)
        shaft_total += q3 * normal                               # the ball pushes the shaft
    assert shaft_total[2] == pytest.approx(fa, rel=1e-13)
    assert np.allclose(shaft_total[:2], 0.0, atol=1e-9 * fa)


# --- through the CLI ----------------------------------------------------------------

BEARING = """kind: ball-bearing
ball_count: 9
ball_diameter: 7.938 mm
pitch_diameter: 38.5 mm
inner_groove_conformity: 0.52
outer_groove_conformity: 0.53
radial_load: 4 kN
speed: 1000 rpm
"""
THRUST = (ROOT / "specs" / "thrust-bearing.yaml").read_text() + "axial_load: 2 kN\n"


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_contact_results_in_every_format(cli, spec_file, fmt):
    for text, key in ((BEARING, "inner_contact_semi_minor"),
                      (THRUST, "race_axial_contact_pressure")):
        run = cli("solve", spec_file(text), "--format", fmt)
        assert run.code == 0, run.err
        assert key in run.out


def test_without_an_axial_load_the_thrust_bearing_is_unchanged(cli):
    (record,) = solve_json(cli, ROOT / "specs" / "thrust-bearing.yaml")
    assert "max_contact_pressure" not in record["results"]


def test_a_contact_pressure_past_the_limit_fails(cli, spec_file):
    run = cli("check", spec_file(BEARING + "limits: {max_contact_pressure: 2000 MPa}\n"),
              "-f", "json")
    assert run.code == 1 and '"contact_pressure_margin"' in run.out and '"fail"' in run.out
    run = cli("check", spec_file(THRUST.replace("2 kN", "20 kN")), "-f", "json")
    assert run.code == 1 and '"fail"' in run.out


def test_conformity_tolerance_and_sweep(cli, spec_file):
    path = spec_file(BEARING.replace("0.52", "0.52 ± 0.005"))
    run = cli("tolerance", path, "-r", "inner_contact_pressure", "-n", "4096", "-f", "json")
    assert run.code == study_status(json.loads(run.out)), run.err
    assert '"inner_groove_conformity"' in run.out
    run = cli("sweep", spec_file(BEARING), "--vary", "inner_groove_conformity=0.505:0.56:12",
              "-r", "inner_contact_pressure", "-f", "csv")
    assert run.code == 0, run.err
    pressures = csv_column(run.out, "inner_contact_pressure [Pa]")
    assert all(later > earlier for earlier, later in itertools.pairwise(pressures))


@pytest.mark.parametrize(("text", "fragment"), [
    (BEARING.replace("0.52", "0.5"), "must be between 0.5 and 1"),
    (BEARING.replace("0.53", "0.45"), "must be between 0.5 and 1"),
    (BEARING + "material: {poisson_ratio: 0.5}\n", "between -1 and 0.5"),
    (BEARING + "material: {elastic_modulus: -200 GPa}\n", "must be greater than zero"),
    (BEARING.replace("outer_groove_conformity: 0.53\n", ""), "need both groove conformities"),
    (THRUST.replace("2 kN", "-2 kN"), "must not be negative"),
    (THRUST.replace("ball_count: 12", ""), "give ball_count too"),
    (THRUST + "material: {density: 0 kg/m^3}\n", "must be greater than zero"),
])
def test_bad_contact_input_is_one_clear_line(cli, spec_file, text, fragment):
    run = cli("solve", spec_file(text))
    assert run.code == 2 and run.err.count("\n") == 1 and fragment in run.err, run.err


def test_solving_the_contact_examples_loads_no_scipy():
    """K and E come from the arithmetic-geometric mean: importing scipy.special would cost a
    cold solve of a loaded thrust bearing about a third of a second."""
    code = ("import sys\n"
            "from typer.testing import CliRunner\n"
            "from bearingcalc.cli import app\n"
            "for spec in ('thrust-bearing-loaded', 'ball-bearing-geometry'):\n"
            "    run = CliRunner().invoke(app, ['solve', f'specs/{spec}.yaml'])\n"
            "    assert run.exit_code == 0, run.output\n"
            "print(sorted(name for name in sys.modules if name.split('.')[0] == 'scipy'))\n")
    run = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, check=True)
    assert run.stdout.strip() == "[]", run.stdout
