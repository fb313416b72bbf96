"""The rigid-shaft reference (tests/iso16281_shaft_reference.py) against the single-bearing
reference, its own mirror and transfer maps, and the closed forms of a matched pair, each
test naming what it checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests import iso16281_reference as ref
from tests import iso16281_shaft_reference as shaft

MM = 1e-3
UM = 1e-6

#: 40° angular-contact ball bearing: Z = 12, Dw = 11.112 mm, Dpw = 52.5 mm, fi = 0.52,
#: fe = 0.53 (steel of the reference: E = 210 GPa, ν = 0.3).
BALL = ref.BallBearing(12, 11.112 * MM, 52.5 * MM, 0.52, 0.53,
                       free_contact_angle=math.radians(40.0))
#: Tapered roller bearing: Z = 17, Dwe = 7.5 mm, Lwe = 14 mm, Dpw = 60 mm, cup angle 15°,
#: ISO's logarithmic profile on 30 laminae.
TAPERED = ref.RollerBearing(17, 7.5 * MM, 14.0 * MM, 60.0 * MM,
                            contact_angle=math.radians(15.0), profile="iso", laminae=30)
#: A combined load on one ring [N, N, N, N·m, N·m].
COMBINED = np.array([2000.0, 1500.0, 300.0, 5.0, 10.0])
END_PLAY = -20 * UM
ONE_SIDED = pytest.mark.parametrize("bearing", [BALL, TAPERED], ids=["ball", "tapered"])


def _pair(bearing, arrangement="back-to-back", centre=40 * MM, end_play=END_PLAY):
    """Identical bearings with pressure centres at ±centre, [s = +1, s = −1]."""
    return shaft.matched_pair(bearing, (-centre, centre), arrangement, end_play)


def _parallel_axis(pair, solved):
    """Σ (S_i T_i)ᵀ·K_i·(S_i T_i), K_i the reference's stiffness_matrix at each solved q_i."""
    return sum(item.matrix.T @ ref.stiffness_matrix(item.bearing, q) @ item.matrix
               for item, q in zip(pair, solved["q"], strict=True))


# ---------------------------------------------------------------- one bearing
@ONE_SIDED
def test_single_bearing_at_the_origin_equals_solve_equilibrium(bearing):
    """x = 0, s = +1, o = 0: T = S = identity, so Q = q and the loads are
    iso16281_reference.solve_equilibrium's (same residual, same scaling), to 1e-9."""
    single = ref.solve_equilibrium(bearing, COMBINED)
    solved = shaft.solve_shaft([shaft.ShaftBearing(bearing)], COMBINED)
    assert solved["residual"] < 1e-10
    assert solved["Q"] == pytest.approx(single["q"], rel=1e-9, abs=1e-9 * np.abs(single["q"]).max())
    assert solved["load"][0] == pytest.approx(single["load"], rel=1e-9,
                                              abs=1e-9 * single["load"].max())
    assert solved["stiffness"] == pytest.approx(single["stiffness"], rel=1e-6,
                                                abs=1e-6 * np.abs(single["stiffness"]).max())


@ONE_SIDED
def test_mirrored_bearing_under_reversed_thrust_equals_the_unmirrored_one(bearing):
    """The mirror S = diag(−1, 1, 1, −1, −1): a bearing with s = −1 under (−Fx, Fy, Fz, −My,
    −Mz) is the bearing with s = +1 under (Fx, Fy, Fz, My, Mz): the same element loads, and
    Q mirrored (δx and the tilts change sign, so |δx| is the same)."""
    flip = np.array([-1.0, 1.0, 1.0, -1.0, -1.0])
    plain = shaft.solve_shaft([shaft.ShaftBearing(bearing)], COMBINED)
    mirrored = shaft.solve_shaft([shaft.ShaftBearing(bearing, orientation=-1)], flip * COMBINED)
    assert mirrored["load"][0] == pytest.approx(plain["load"][0], rel=1e-9,
                                                abs=1e-9 * plain["load"][0].max())
    assert mirrored["Q"] == pytest.approx(flip * plain["Q"], rel=1e-9,
                                          abs=1e-9 * np.abs(plain["Q"]).max())
    assert mirrored["axial_load"][0] == pytest.approx(COMBINED[0], rel=1e-9)
    # pure thrust: the mirror carries −Fx as the plain bearing carries +Fx
    push = shaft.solve_shaft([shaft.ShaftBearing(bearing, orientation=-1)], (-1500.0, 0, 0, 0, 0))
    pull = shaft.solve_shaft([shaft.ShaftBearing(bearing)], (1500.0, 0, 0, 0, 0))
    assert abs(push["Q"][0]) == pytest.approx(abs(pull["Q"][0]), rel=1e-9)
    assert push["Q"][0] < 0 < pull["Q"][0]
    assert push["load"][0] == pytest.approx(pull["load"][0], rel=1e-9)


@pytest.mark.parametrize("orientation", [1, -1])
def test_bearing_away_from_the_origin_sees_the_load_moved_to_its_plane(orientation):
    """T_iᵀ f = (fx, fy, fz, My − x_i·fz, Mz − x_i·fy): a ring at x_i = 30 mm that must
    carry f = COMBINED in its own axes is loaded at x = 0 by (S T)ᵀ f, and then its own q
    is solve_equilibrium's under f, and Q = (S T)⁻¹ q (q_i = S_i T_i Q)."""
    item = shaft.ShaftBearing(BALL, position=30 * MM, orientation=orientation)
    applied = item.matrix.T @ COMBINED
    assert applied[3:] == pytest.approx(
        [orientation * COMBINED[3] - 30 * MM * COMBINED[2],
         orientation * COMBINED[4] - 30 * MM * COMBINED[1]], rel=1e-12)
    single = ref.solve_equilibrium(BALL, COMBINED)
    solved = shaft.solve_shaft([item], applied)
    assert solved["q"][0] == pytest.approx(single["q"], rel=1e-9,
                                           abs=1e-9 * np.abs(single["q"]).max())
    assert solved["Q"] == pytest.approx(np.linalg.solve(item.matrix, single["q"]), rel=1e-8)


# ---------------------------------------------------------------- closed forms
@ONE_SIDED
def test_closed_form_equals_the_reference_contacts_under_pure_axial_displacement(bearing):
    """Harris & Kotzalas Part 1 eq. 7.33 (balls: α from the groove centres) and ISO/TS
    16281:2008 eqs. 38-41 (laminae with gap (Pd/2)cos α + 2p_k): Fa(δa) equals the axial
    force of ball_state/roller_state at q = (δa, 0, 0, 0, 0), to 1e-12."""
    for delta_a in (2 * UM, 10 * UM, 20 * UM, 60 * UM):
        force = shaft.shaft_force([shaft.ShaftBearing(bearing)], (delta_a, 0, 0, 0, 0))
        assert shaft.axial_load(bearing, delta_a) == pytest.approx(force[0], rel=1e-12)
    assert shaft.axial_load(bearing, -1 * UM) == 0.0


@ONE_SIDED
def test_preloaded_pair_at_rest_carries_the_closed_form_preload(bearing):
    """End play −20 µm, o_i = +10 µm: at Q = 0 each bearing stands δa = 10 µm past first
    contact, the two thrusts cancel, so Q = 0 and each carries Fa(10 µm) (Harris & Kotzalas
    eq. 7.33 for balls, ISO/TS 16281 eqs. 38-41 for the tapered laminae), to 1e-9."""
    pair = _pair(bearing)
    solved = shaft.solve_shaft(pair, (0.0, 0.0, 0.0, 0.0, 0.0))
    preload = shaft.preload_from_end_play(bearing, END_PLAY)
    assert preload == pytest.approx(shaft.axial_load(bearing, 10 * UM), rel=1e-15)
    assert preload > 100.0
    assert solved["axial_load"] == pytest.approx([preload, preload], rel=1e-9)
    assert np.abs(solved["Q"]).max() < 1e-15
    assert solved["q"][0][0] == pytest.approx(10 * UM, rel=1e-12)


@ONE_SIDED
def test_pair_lifts_off_at_the_closed_form_thrust(bearing):
    """The shaft pushed toward +x by δx loads bearing 1 to δa = 10 µm + δx and relieves
    bearing 2 to 10 µm − δx: bearing 2 lifts off at its first contact δa0 (0 for balls),
    where Fx = Fa(20 µm − δa0) (closed forms as above). There bearing 1 carries all of it and
    bearing 2 nothing; 0.1 % above, bearing 2 is unloaded, 0.1 % below it still carries
    load and Fa1 − Fa2 = Fx."""
    pair = _pair(bearing)
    lift_off = shaft.lift_off_thrust(bearing, END_PLAY)
    at = shaft.solve_shaft(pair, (lift_off, 0.0, 0.0, 0.0, 0.0))
    assert at["residual"] < 1e-10
    assert at["Q"][0] == pytest.approx(10 * UM - shaft.first_contact(bearing), rel=1e-9)
    assert at["axial_load"][0] == pytest.approx(lift_off, rel=1e-9)
    assert at["axial_load"][1] < 1e-9 * lift_off
    above = shaft.solve_shaft(pair, (1.001 * lift_off, 0.0, 0.0, 0.0, 0.0))
    assert above["axial_load"][1] == 0.0
    assert np.all(above["load"][1] == 0.0)
    assert above["axial_load"][0] == pytest.approx(1.001 * lift_off, rel=1e-9)
    below = shaft.solve_shaft(pair, (0.999 * lift_off, 0.0, 0.0, 0.0, 0.0))
    assert below["axial_load"][1] > 1e-6 * lift_off
    assert below["axial_load"][0] - below["axial_load"][1] == pytest.approx(
        0.999 * lift_off, rel=1e-9)


def test_lift_off_thrust_of_balls_is_fa_at_twice_the_interference_and_of_tapered_just_less():
    """Angular-contact balls touch at δa = 0, so lift-off is at exactly Fa(20 µm) (Harris &
    Kotzalas eq. 7.33). The ISO profile (ISO/TS 16281:2008 eqs. 42-44) leaves the central
    laminae of the tapered bearing 2·p(Lwe/60) = 5.8 nm short of the unprofiled line, so it
    touches 22.6 nm after its datum and lifts off 0.17 % below Fa(20 µm)."""
    assert shaft.first_contact(BALL) == 0.0
    assert shaft.lift_off_thrust(BALL, END_PLAY) == shaft.axial_load(BALL, 20 * UM)
    drop = 2 * 0.00035 * 7.5 * MM * math.log(1 / (1 - (1 / 30) ** 2))
    assert shaft.first_contact(TAPERED) == pytest.approx(drop / math.sin(math.radians(15.0)),
                                                         rel=1e-12)
    assert shaft.first_contact(TAPERED) == pytest.approx(22.55 * 1e-9, rel=1e-3)
    ratio = shaft.axial_load(TAPERED, 20 * UM) / shaft.lift_off_thrust(TAPERED, END_PLAY)
    assert ratio == pytest.approx(1.0017, abs=1e-4)
    at_20 = shaft.solve_shaft(_pair(TAPERED), (shaft.axial_load(TAPERED, 20 * UM), 0, 0, 0, 0))
    assert at_20["axial_load"][1] == 0.0


@ONE_SIDED
def test_end_play_for_preload_round_trips(bearing):
    """end_play_for_preload inverts preload_from_end_play (brentq on the closed form), and
    the shaft set to that end play carries the preload in both bearings."""
    assert shaft.end_play_for_preload(bearing, shaft.preload_from_end_play(
        bearing, END_PLAY)) == pytest.approx(END_PLAY, rel=1e-9)
    for preload in (200.0, 1000.0, 3000.0):
        end_play = shaft.end_play_for_preload(bearing, preload)
        assert end_play < 0
        assert shaft.preload_from_end_play(bearing, end_play) == pytest.approx(preload, rel=1e-12)
    solved = shaft.solve_shaft(_pair(bearing, end_play=end_play), (0.0, 0.0, 0.0, 0.0, 0.0))
    assert solved["axial_load"] == pytest.approx([3000.0, 3000.0], rel=1e-9)
    assert shaft.preload_from_end_play(bearing, 5 * UM) == 0.0


# ---------------------------------------------------------------- stiffness
def _tilt(bearing, arrangement, centre):
    """The pair with end play −20 µm under Fy = 3000 N at x = 0: solved state."""
    pair = _pair(bearing, arrangement, centre)
    return pair, shaft.solve_shaft(pair, (0.0, 3000.0, 0.0, 0.0, 0.0))


@ONE_SIDED
def test_tilt_stiffness_back_to_back_exceeds_face_to_face_and_is_the_parallel_axis_sum(bearing):
    """The shaft's ∂F/∂Q (central differences of Σ T_iᵀ S_i f_i) equals the parallel-axis
    sum Σ (S_i T_i)ᵀ K_i (S_i T_i) of the rings' own stiffness at their solved states, to
    1e-6; its Mz/θz entry is Σ (x_i²·k_yy − 2 s_i x_i·k_y,θz + k_θzθz). Pressure centres at
    ±40 mm back-to-back give a larger tilt stiffness than at ±10 mm face-to-face."""
    tilts = {}
    for arrangement, centre in (("back-to-back", 40 * MM), ("face-to-face", 10 * MM)):
        pair, solved = _tilt(bearing, arrangement, centre)
        k, summed = solved["stiffness"], _parallel_axis(pair, solved)
        assert k == pytest.approx(summed, rel=1e-6, abs=1e-6 * np.abs(k).max())
        own = [ref.stiffness_matrix(item.bearing, q) for item, q in zip(pair, solved["q"],
                                                                           strict=True)]
        entry = sum(item.position**2 * m[1, 1] - 2 * item.orientation * item.position * m[1, 4]
                    + m[4, 4] for item, m in zip(pair, own, strict=True))
        assert k[4, 4] == pytest.approx(entry, rel=1e-6)
        tilts[arrangement] = k[4, 4]
    assert tilts["back-to-back"] > 2.0 * tilts["face-to-face"]


def test_tapered_pair_tilt_stiffness_is_the_plain_parallel_axis_sum():
    """A tapered bearing's origin is its pressure centre; untilted (the symmetric pair under
    a central radial load) its laminae load symmetrically in ±ℓ_k, so k_y,θz = 0 and the
    pair's tilt stiffness is Σ k_radial,i·x_i² + Σ k_tilt,i, to 1e-6."""
    for arrangement, centre in (("back-to-back", 40 * MM), ("face-to-face", 10 * MM)):
        pair, solved = _tilt(TAPERED, arrangement, centre)
        own = [ref.stiffness_matrix(TAPERED, q) for q in solved["q"]]
        plain = sum(item.position**2 * m[1, 1] + m[4, 4] for item, m in zip(pair, own,
                                                                                strict=True))
        assert [item.position for item in pair] == pytest.approx(
            [-centre, centre] if arrangement == "back-to-back" else [centre, -centre])
        assert solved["stiffness"][4, 4] == pytest.approx(plain, rel=1e-6)


def test_ball_pair_needs_the_radial_tilt_coupling_about_the_centre_planes():
    """A ball bearing's origin is its centre plane, (Dpw/2)·tan 40° = 22 mm from its
    pressure centre: there k_y,θz ≈ (Dpw/2)·tan α·k_yy, and Σ k_yy·x_i² + Σ k_θθ without
    the coupling misses the shaft's tilt stiffness by tens of per cent (the coupled sum is
    the test above)."""
    pair, solved = _tilt(BALL, "back-to-back", 40 * MM)
    assert [item.position for item in pair] == pytest.approx(
        [-40 * MM + 26.25 * MM * math.tan(math.radians(40.0)),
         40 * MM - 26.25 * MM * math.tan(math.radians(40.0))], rel=1e-12)
    own = [ref.stiffness_matrix(BALL, q) for q in solved["q"]]
    plain = sum(item.position**2 * m[1, 1] + m[4, 4] for item, m in zip(pair, own, strict=True))
    assert abs(plain / solved["stiffness"][4, 4] - 1) > 0.1


@ONE_SIDED
def test_stiffness_is_symmetric_and_positive_definite_when_preloaded(bearing):
    """At the preloaded state at rest (end play −20 µm) the shaft's central-difference
    stiffness is symmetric (it is the Hessian of the contacts' energy) to 1e-6 of its
    largest entry, and its symmetric part has only positive eigenvalues."""
    for arrangement, centre in (("back-to-back", 40 * MM), ("face-to-face", 10 * MM)):
        solved = shaft.solve_shaft(_pair(bearing, arrangement, centre), (0, 0, 0, 0, 0))
        k = solved["stiffness"]
        assert k == pytest.approx(k.T, rel=1e-6, abs=1e-6 * np.abs(k).max())
        assert np.linalg.eigvalsh(0.5 * (k + k.T)).min() > 0.0
