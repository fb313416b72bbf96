"""What a bearing's load distribution gives (ISO/TS 16281:2008, 8): the reference rating
life from every element's load, the contacts' spring constant and pressures by exact
Hertz. Vectorised over designs; element arrays (N, Zmax) padded with NaN past Z.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.ball_bearing_contacts import raceway_curvatures
from bearingcalc.core.hertz import hertz_point_contact
from bearingcalc.core.roller_bearing_contacts import line_contact

#: Lundberg–Palmgren's constants of a ball bearing's C from its raceway ratings: the
#: load-zone means of the rotating ring (cubic, J1) and the stationary one (10/3, J2)
#: at a half-filled load zone, as ISO 281 rounds them.
ROTATING_MEAN = 0.407
STATIONARY_MEAN = 0.389
#: ISO 281's ratio of the inner to the outer raceway rating's constant.
RACEWAY_RATIO = 1.044


class ReferenceLife(NamedTuple):
    """A ball bearing's ISO/TS 16281 reference life and what it is formed from."""

    revolutions: NDArray         # L10r [revolutions]
    equivalent_load: NDArray     # the load P_ref with L10r = (C/P_ref)³·10⁶ [N]
    inner_rating: NDArray        # Q_ci [N]
    outer_rating: NDArray        # Q_ce [N]
    inner_equivalent: NDArray    # Q_ei [N]
    outer_equivalent: NDArray    # Q_ee [N]


def _contact(load: ArrayLike, ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
             conformity: ArrayLike, contact_angle: ArrayLike, modulus: ArrayLike,
             poisson: ArrayLike, inner: bool) -> dict[str, NDArray]:
    dw = np.asarray(ball_diameter, dtype=float)
    gamma = dw * np.cos(np.asarray(contact_angle, dtype=float)) / np.asarray(
        pitch_diameter, dtype=float)
    return hertz_point_contact(load, *raceway_curvatures(dw, gamma, conformity, inner),
                               modulus, poisson, modulus, poisson)


def ball_spring_constant(ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
                         inner_conformity: ArrayLike, outer_conformity: ArrayLike,
                         contact_angle: ArrayLike, elastic_modulus: ArrayLike,
                         poisson_ratio: ArrayLike) -> NDArray:
    r"""K of a ball between both rings, Q = K·δ^(3/2) with δ the sum of the two contacts'
    approaches (in series), each by exact Hertz at the nominal contact angle:

    .. math:: K = \left(c_i + c_e\right)^{-3/2}, \qquad δ_{i,e} = c_{i,e}\,Q^{2/3}

    [N/m^1.5]. Source: ISO/TS 16281:2008, 6.2 (eq. 10 with the exact Hertz constant in
    place of its rounded one).
    """
    compliance = sum(_contact(1.0, ball_diameter, pitch_diameter, conformity, contact_angle,
                              elastic_modulus, poisson_ratio, inner)["approach"]
                     for conformity, inner in ((inner_conformity, True),
                                               (outer_conformity, False)))
    return compliance ** -1.5


def largest_ball_contacts(element_load: NDArray, contact_angle: NDArray,
                          ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
                          inner_conformity: ArrayLike, outer_conformity: ArrayLike,
                          elastic_modulus: ArrayLike, poisson_ratio: ArrayLike,
                          quantities: tuple[str, ...] = ("max_pressure",)
                          ) -> dict[str, tuple[NDArray, NDArray]]:
    """Of each of ``quantities`` (of :data:`bearingcalc.core.hertz.CONTACT_KEYS`: the
    peak pressure [Pa], the semi-major axis [m] …), its largest over the loaded balls at
    the inner and at the outer ring, each ball's contact with the curvatures at its
    operating contact angle; one Hertz solution per contact for all of them."""
    def column(value: ArrayLike) -> NDArray:
        return np.asarray(value, dtype=float).reshape(-1, 1)

    load = np.nan_to_num(element_load, nan=0.0)
    angle = np.nan_to_num(contact_angle, nan=0.0)
    rings = [_contact(load, column(ball_diameter), column(pitch_diameter), column(conformity),
                      angle, column(elastic_modulus), column(poisson_ratio), inner)
             for conformity, inner in ((inner_conformity, True), (outer_conformity, False))]
    return {key: tuple(np.max(np.where(load > 0, ring[key], 0.0), axis=1)  # type: ignore[misc]
                       for ring in rings) for key in quantities}


def ball_contact_pressures(element_load: NDArray, contact_angle: NDArray,
                           ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
                           inner_conformity: ArrayLike, outer_conformity: ArrayLike,
                           elastic_modulus: ArrayLike, poisson_ratio: ArrayLike
                           ) -> tuple[NDArray, NDArray]:
    """The largest Hertz pressure at the inner and at the outer ring over the balls [Pa]
    (see :func:`largest_ball_contacts`)."""
    return largest_ball_contacts(element_load, contact_angle, ball_diameter, pitch_diameter,
                                 inner_conformity, outer_conformity, elastic_modulus,
                                 poisson_ratio)["max_pressure"]


def ball_reference_life(element_load: NDArray, ball_count: ArrayLike, ball_diameter: ArrayLike,
                        pitch_diameter: ArrayLike, inner_conformity: ArrayLike,
                        outer_conformity: ArrayLike, contact_angle: ArrayLike,
                        dynamic_load_rating: ArrayLike, *, rows: ArrayLike = 1,
                        inner_rotates: ArrayLike = True) -> ReferenceLife:
    r"""ISO/TS 16281's reference rating life of a ball bearing from each ball's load.

    The raceway ratings follow from C (Lundberg–Palmgren, with cos α to the first power
    and X the raceways' ratio of conformity and γ, α the nominal contact angle):

    .. math:: Q_{ci} = \frac{C}{0.407\,Z\,i^{0.7}\cos\alpha}\left[1 + (1.044X)^{10/3}
              \right]^{0.3}, \quad Q_{ce} = \frac{C}{0.389\,Z\,i^{0.7}\cos\alpha}\left[1 +
              (1.044X)^{-10/3}\right]^{0.3},

    .. math:: X = \left(\frac{1-γ}{1+γ}\right)^{1.72}\left(\frac{f_i(2f_e - 1)}
              {f_e(2f_i - 1)}\right)^{0.41}

    The rotating ring's equivalent ball load is the cubic mean over all Z balls, the
    stationary ring's the 10/3 mean, and

    .. math:: L_{10r} = \left[(Q_{ci}/Q_{ei})^{-10/3} + (Q_{ce}/Q_{ee})^{-10/3}
              \right]^{-9/10} \cdot 10^6

    revolutions. Source: ISO/TS 16281:2008, 8.2 (eqs. 19 to 29).
    """
    count = np.asarray(ball_count, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float)
    fi = np.asarray(inner_conformity, dtype=float)
    fe = np.asarray(outer_conformity, dtype=float)
    gamma = dw * np.cos(alpha) / np.asarray(pitch_diameter, dtype=float)
    ratio = RACEWAY_RATIO * ((1 - gamma) / (1 + gamma)) ** 1.72 * (
        fi * (2 * fe - 1) / (fe * (2 * fi - 1))) ** 0.41
    base = np.asarray(dynamic_load_rating, dtype=float) / (
        count * np.asarray(rows, dtype=float) ** 0.7 * np.cos(alpha))
    inner_rating = base / ROTATING_MEAN * (1 + ratio ** (10 / 3)) ** 0.3
    outer_rating = base / STATIONARY_MEAN * (1 + ratio ** (-10 / 3)) ** 0.3
    loads = np.nan_to_num(element_load, nan=0.0)
    cubic = (np.sum(loads ** 3, axis=1) / count) ** (1 / 3)
    tenth = (np.sum(loads ** (10 / 3), axis=1) / count) ** 0.3
    rotates = np.asarray(inner_rotates, dtype=bool)
    inner_load = np.where(rotates, cubic, tenth)
    outer_load = np.where(rotates, tenth, cubic)
    with np.errstate(divide="ignore"):
        millions = ((inner_rating / inner_load) ** (-10 / 3)
                    + (outer_rating / outer_load) ** (-10 / 3)) ** -0.9
    return ReferenceLife(millions * 1e6,
                         np.asarray(dynamic_load_rating, dtype=float) / millions ** (1 / 3),
                         inner_rating, outer_rating, inner_load, outer_load)


#: ISO 281's reduction factor λ·ν of roller bearings (edge stresses and misalignment in
#: the catalogue rating), and the load-zone means of the rotating and stationary rings
#: of line contact.
ROLLER_REDUCTION = 0.83
ROLLER_ROTATING_MEAN = 0.378
ROLLER_STATIONARY_MEAN = 0.364
#: ISO 281's ratio of a roller bearing's raceway ratings' constants.
ROLLER_RACEWAY_RATIO = 1.038


def edge_stress_factors(laminae: ArrayLike, width: int | None = None) -> NDArray:
    r"""ISO/TS 16281's edge-stress factor f_k of lamina k = 1 … n_s of a roller, which
    raises the load of the laminae towards the roller's ends in the life:

    .. math:: f_k = 1 - \frac{0.01}{\ln\left(1.985\left|\frac{2k - n_s - 1}{2n_s - 2}
              \right|\right)}

    1 at the roller's middle, 1 + 0.01/ln(1/0.9925) = 2.33 at its end laminae.
    ``laminae``: each design's n_s; the result is (N, ``width``), 1 past a design's own
    laminae (``width`` defaults to the largest n_s). Source: ISO/TS 16281:2008, 8.3
    (eq. 60).
    """
    count = np.atleast_1d(np.asarray(laminae, dtype=float))[:, None]
    k = np.arange(1, int(count.max() if width is None else width) + 1, dtype=float)
    share = np.abs((2.0 * k - count - 1.0) / (2.0 * count - 2.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        # the middle lamina of an odd count sits at share 0: ln → −∞ and f → 1
        factor = 1.0 - 0.01 / np.log(1.985 * share)
    # one lamina is the whole roller: it has no edge of its own to raise
    return np.where((k <= count) & (count > 1), factor, 1.0)


def roller_reference_life(lamina_load: NDArray, roller_count: ArrayLike,
                          roller_diameter: ArrayLike, pitch_diameter: ArrayLike,
                          contact_angle: ArrayLike, dynamic_load_rating: ArrayLike, *,
                          rows: ArrayLike = 1, inner_rotates: ArrayLike = True,
                          laminae: ArrayLike | None = None,
                          edge_stress: ArrayLike = False) -> ReferenceLife:
    r"""ISO/TS 16281's reference rating life of a roller bearing from every lamina's
    load, ``lamina_load`` (N, Zmax, n_s), NaN past Z.

    .. math:: Q_{ci} = \frac{C}{λν\,0.378\,Z\,i^{7/9}\cos\alpha}\left[1 + X^{9/2}
              \right]^{2/9}, \quad Q_{ce} = \frac{C}{λν\,0.364\,Z\,i^{7/9}\cos\alpha}
              \left[1 + X^{-9/2}\right]^{2/9}, \quad X = 1.038\left(\frac{1-γ}{1+γ}
              \right)^{143/108}

    with λν = 0.83; a lamina's rating is q_c = Q_c·n_s^(−7/9). Per lamina the rotating
    ring's equivalent load is the mean of exponent 4 over the Z rollers, the stationary
    ring's of exponent 4.5, and

    .. math:: L_{10r} = \left[\sum_k (q_{ei,k}/q_{ci})^{9/2} + (q_{ee,k}/q_{ce})^{9/2}
              \right]^{-8/9} \cdot 10^6

    revolutions; P_ref with L10r = (C/P_ref)^(10/3)·10⁶, the sum over the laminae of
    every row. ``laminae``: each design's n_s of one row where some are padded with NaN
    (default: every one of a row's in ``lamina_load``, whose last axis holds the rows one
    after the other, as :func:`~bearingcalc.core.iso16281_rollers.roller_geometry` lays
    them out). Where ``edge_stress`` holds, each lamina's load enters the equivalent
    loads as f_k·q_k (:func:`edge_stress_factors`, each row's own). Source: ISO/TS
    16281:2008, 8.3 (eqs. 47 to 65).
    """
    count = np.asarray(roller_count, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    c = np.asarray(dynamic_load_rating, dtype=float)
    gamma = np.asarray(roller_diameter, dtype=float) * np.cos(alpha) / np.asarray(
        pitch_diameter, dtype=float)
    ratio = ROLLER_RACEWAY_RATIO * ((1 - gamma) / (1 + gamma)) ** (143 / 108)
    base = c / (ROLLER_REDUCTION * count * np.asarray(rows, dtype=float) ** (7 / 9)
                * np.cos(alpha))
    row_count = int(np.max(rows))
    width = lamina_load.shape[2] // row_count
    if width * row_count != lamina_load.shape[2]:
        raise ValueError(f"{lamina_load.shape[2]} laminae do not lay out {row_count} rows")
    slices = np.broadcast_to(width if laminae is None else laminae, count.shape)
    share = np.asarray(slices, dtype=float) ** (-7 / 9)
    inner_rating = base / ROLLER_ROTATING_MEAN * (1 + ratio ** 4.5) ** (2 / 9) * share
    outer_rating = base / ROLLER_STATIONARY_MEAN * (1 + ratio ** -4.5) ** (2 / 9) * share
    loads = np.nan_to_num(lamina_load, nan=0.0)
    factors = np.where(np.asarray(edge_stress, dtype=bool)[..., None],
                       np.tile(edge_stress_factors(slices, width), row_count), 1.0)
    loads = loads * factors[:, None, :]
    fourth = (np.sum(loads ** 4, axis=1) / count[:, None]) ** 0.25
    four_and_half = (np.sum(loads ** 4.5, axis=1) / count[:, None]) ** (1 / 4.5)
    rotates = np.asarray(inner_rotates, dtype=bool)[..., None]
    inner_load = np.where(rotates, fourth, four_and_half)
    outer_load = np.where(rotates, four_and_half, fourth)
    with np.errstate(divide="ignore"):
        millions = np.sum((inner_load / inner_rating[:, None]) ** 4.5
                          + (outer_load / outer_rating[:, None]) ** 4.5, axis=1) ** (-8 / 9)
    return ReferenceLife(millions * 1e6, c / millions ** 0.3, inner_rating, outer_rating,
                         inner_load.max(axis=1), outer_load.max(axis=1))


def largest_roller_contacts(lamina_load: NDArray, roller_diameter: ArrayLike,
                            effective_length: ArrayLike, pitch_diameter: ArrayLike,
                            contact_angle: ArrayLike, elastic_modulus: ArrayLike,
                            poisson_ratio: ArrayLike, laminae: ArrayLike | None = None
                            ) -> dict[str, tuple[NDArray, NDArray]]:
    r"""The largest Hertz line-contact pressure [Pa] and half-width [m] over every lamina
    of every roller, at the inner and at the outer ring, each lamina a line contact of
    length Lwe/n_s under its load q:

    .. math:: p_0 = \sqrt{\frac{q E^*}{\pi (L_{we}/n_s) R'}}, \qquad R'_{i,e} =
              \frac{D_{we}(1 \mp γ)}{2}, \qquad γ = \frac{D_{we}\cos α}{D_{pw}}

    ``lamina_load`` (N, Zmax, n_s), NaN past Z (and past each design's ``laminae``,
    default all); the end laminae are included, so a profile's edge loading shows.
    Source: ISO/TS 16281:2008, 7.3; K. L. Johnson, *Contact Mechanics*, 1985, §4.2.
    """
    def column(value: ArrayLike) -> NDArray:
        return np.asarray(value, dtype=float).reshape(-1, 1)

    count = column(lamina_load.shape[2] if laminae is None else laminae)
    largest = np.max(np.nan_to_num(lamina_load, nan=0.0), axis=(1, 2)).reshape(-1, 1)
    dwe = column(roller_diameter)
    gamma = dwe * np.cos(column(contact_angle)) / column(pitch_diameter)
    found: dict[str, list[NDArray]] = {"max_pressure": [], "half_width": []}
    for sign in (-1.0, 1.0):
        pressure, half_width = line_contact(largest, column(effective_length) / count,
                                            dwe * (1.0 + sign * gamma) / 2.0,
                                            column(elastic_modulus), column(poisson_ratio))
        found["max_pressure"].append(pressure[:, 0])
        found["half_width"].append(half_width[:, 0])
    return {key: (inner, outer) for key, (inner, outer) in found.items()}
