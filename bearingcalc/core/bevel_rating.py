"""The AGMA 2003 strength rating of a bevel pair: straight, Zerol and spiral teeth of
steel (``docs/physics.md`` §8).

Gear A is the pinion. Inputs are SI floats or broadcasting arrays; inside the rating,
the SI form of AGMA 2003 (Budynas & Nisbett, *Shigley's Mechanical Engineering
Design*, ch. 15; ANSI/AGMA 2003-D19's "M" equations) works in mm, N, MPa and m/s, as
that form is written.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core import agma_life
from bearingcalc.core.common import MM
from bearingcalc.core.gear_materials import THROUGH_HARDENED, GearMemberTerms

#: AGMA 2003 load-distribution base factor Kmb by mounting.
MOUNTING_FACTOR = {"both-straddle": 1.00, "one-straddle": 1.10, "neither-straddle": 1.25}
#: Elastic coefficient of steel on steel. [√MPa]
STEEL_ELASTIC_COEFFICIENT = 190.0


#: AGMA 2003's bounds on the lengthwise curvature factor K_x of spiral teeth.
CURVATURE_FACTOR_BOUNDS = (1.0, 1.15)


def lengthwise_curvature_factor(spiral_angle: ArrayLike, cutter_radius: ArrayLike,
                                mean_cone_distance: ArrayLike) -> NDArray:
    r"""AGMA 2003's lengthwise curvature factor for bending strength K_x (Y_β).

    .. math:: K_x = 0.211\left(\frac{r_c}{A_m}\right)^q + 0.789, \qquad
              q = \frac{0.279}{\log_{10}\sin\beta_m}

    held between 1 and 1.15; K_x = 1 for straight and Zerol teeth (β_m = 0). A face
    cutter smaller than the mean cone distance curves the tooth more along its length,
    which the standard credits with a stronger root (K_x > 1); a larger cutter gets no
    credit (K_x = 1), as at r_c/A_m = 1.41 in the standard's own spiral example.

    Parameters
    ----------
    spiral_angle : β_m at the mean point, 0 to 50°. [rad]
    cutter_radius : r_c, the face cutter's nominal radius. [m]
    mean_cone_distance : A_m = R_e − b/2. [m]

    Source: ANSI/AGMA 2003-D19, clause 14, eqs. (21M)–(23M) and the bounds under them;
    ISO 10300-1's K_F0 is the same curve with the same bounds.
    """
    beta = np.asarray(spiral_angle, dtype=float)
    ratio = np.asarray(cutter_radius, dtype=float) / np.asarray(mean_cone_distance, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        exponent = 0.279 / np.log10(np.sin(beta))
        factor = 0.211 * ratio ** exponent + 0.789
    return np.where(beta > 0, np.clip(factor, *CURVATURE_FACTOR_BOUNDS), 1.0)


def dynamic_factor(quality_number: ArrayLike, pitch_line_speed: ArrayLike) -> NDArray:
    r"""AGMA dynamic factor, SI form.

    .. math:: K_v = \left(\frac{A + \sqrt{200\,v_{et}}}{A}\right)^B, \quad
              B = 0.25(12 - Q_v)^{2/3}, \quad A = 50 + 56(1 - B)

    with v_et in m/s.

    Source: Budynas & Nisbett, eq. (15-5).
    """
    qv = np.asarray(quality_number, dtype=float)
    b_exp = 0.25 * (12.0 - qv) ** (2.0 / 3.0)
    a_coeff = 50.0 + 56.0 * (1.0 - b_exp)
    return ((a_coeff + np.sqrt(200.0 * np.abs(np.asarray(pitch_line_speed)))) / a_coeff) ** b_exp


def max_pitch_line_speed(quality_number: ArrayLike) -> NDArray:
    r"""The highest pitch-line speed the dynamic factor covers at a quality number.

    .. math:: v_{t,max} = \frac{[A + (Q_v - 3)]^2}{200}

    in m/s, A as in :func:`dynamic_factor`; 28.7 m/s at Q_v = 8.

    Source: Budynas & Nisbett, eq. (15-6).
    """
    qv = np.asarray(quality_number, dtype=float)
    b_exp = 0.25 * (12.0 - qv) ** (2.0 / 3.0)
    a_coeff = 50.0 + 56.0 * (1.0 - b_exp)
    return (a_coeff + (qv - 3.0)) ** 2 / 200.0


def life_factors(cycles: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""AGMA 2003's stress-cycle factors of steel bevel gears, bending and contact.

    .. math:: K_L = 6.1514\,N^{-0.1192}\ (10^3 \le N < 3\cdot10^6), \quad
              1.683\,N^{-0.0323}\ (3\cdot10^6 \le N \le 10^{10})

    .. math:: C_L = 2\ (10^3 \le N < 10^4), \quad
              3.4822\,N^{-0.0602}\ (10^4 \le N \le 10^{10})

    Parameters
    ----------
    cycles : N, load cycles of the member. [1]

    Returns
    -------
    (K_L [1], C_L [1]), bending and contact (:func:`bearingcalc.core.agma_life.life_factor`).

    Source: ANSI/AGMA 2003-B97, Figs. 18 and 19; Budynas & Nisbett, *Shigley's
    Mechanical Engineering Design*, 10th ed., eqs. (15-14) and (15-15).
    """
    return (agma_life.life_factor(cycles, agma_life.BENDING_LIFE_CURVE),
            agma_life.life_factor(cycles, agma_life.CONTACT_LIFE_CURVE))


class PairRatingInput(NamedTuple):
    """The terms of an AGMA 2003 rating of a bevel pair (SI, broadcasting arrays), in the
    order of the worked examples' positional form (:func:`agma_rating`)."""

    pinion_torque: ArrayLike  #: T. [N·m]
    pinion_speed: ArrayLike  #: n of gear A (relative to its arm). [rad/s]
    module: ArrayLike  #: m, outer. [m]
    pinion_outer_diameter: ArrayLike  #: d_e1. [m]
    face_width: ArrayLike  #: b. [m]
    quality_number: ArrayLike  #: Qv, 5 to 11. [1]
    hardness: ArrayLike  #: Brinell HB. [1]
    mounting_factor: ArrayLike  #: Kmb. [1]
    crowned: ArrayLike  #: true (1) for crowned teeth, Cxc = 1.5; else Cxc = 2.
    bending_geometry_factor: ArrayLike  #: J. [1]
    pitting_geometry_factor: ArrayLike  #: I. [1]
    overload_factor: ArrayLike  #: Ko. [1]
    cycles: ArrayLike  #: N, load cycles of the pinion. [1]
    reliability: ArrayLike  #: R, 0.9 to 0.9999. [1]
    #: (s_at, s_ac) of the steel [Pa] (:mod:`bearingcalc.core.gear_materials`); None:
    #: those of through-hardened grade 1 steel of ``hardness``.
    allowables: tuple[ArrayLike, ArrayLike] | None = None
    temperature_factor: ArrayLike = 1.0  #: K_T. [1]
    #: K_x, 1 for straight and Zerol teeth (:func:`lengthwise_curvature_factor`). [1]
    lengthwise_curvature_factor: ArrayLike = 1.0
    #: gear B's terms, to rate it as well; None: the pinion alone.
    gear: GearMemberTerms | None = None


class GearMemberRating(NamedTuple):
    """Gear B's bending stress [Pa] and its safety factors [1]."""

    bending_stress: NDArray
    bending_safety: NDArray
    contact_safety: NDArray


class PairRating(NamedTuple):
    """The AGMA 2003 rating of a pair: the pinion's stresses [Pa], safety factors [1]
    and the powers at which they reach 1 [W]; gear B's where it was rated."""

    bending_stress: NDArray
    contact_stress: NDArray
    bending_safety: NDArray
    contact_safety: NDArray
    bending_power_rating: NDArray
    contact_power_rating: NDArray
    gear_b: GearMemberRating | None = None

    def as_results(self) -> dict[str, NDArray]:
        """The rating under the kind's result keys (gear B's prefixed ``gear_b_``)."""
        out = {name: getattr(self, name) for name in (
            "bending_stress", "contact_stress", "bending_safety", "contact_safety",
            "bending_power_rating", "contact_power_rating")}
        if self.gear_b is not None:
            out.update({"gear_b_bending_stress": self.gear_b.bending_stress,
                        "gear_b_bending_safety": self.gear_b.bending_safety,
                        "gear_b_contact_safety": self.gear_b.contact_safety})
        return out


def agma_rating(*terms: Any, **named: Any) -> dict[str, NDArray]:
    """:func:`rate_pair` of ``PairRatingInput(*terms, **named)`` under the kind's result
    keys: the positional form in which the worked examples are written."""
    return rate_pair(PairRatingInput(*terms, **named)).as_results()


def rate_pair(pair: PairRatingInput) -> PairRating:
    r"""AGMA 2003 bending and contact stresses, safety factors and power ratings of a
    bevel pair (straight, Zerol or spiral teeth), by default of through-hardened grade 1
    steel, in the SI form of Budynas & Nisbett ch. 15 and AGMA 2003-D19.

    Wt = 2T/d_e1 at the outer pitch diameter, v_et its pitch-line speed;
    s_F = (Wt/b)·Ks·Km/(Kx·J)·Ko·Kv/m with Ks = 0.4867 + 0.008339·m,
    Km = Kmb + 5.6e−6·b², Kx from :func:`lengthwise_curvature_factor`;
    s_H = Cp·√(Wt·Ko·Kv·Km·Cs·Cxc/(b·d_e1·I)) with Cp = 190 √MPa,
    Cs = 0.00492·b + 0.4375, Cxc = 2 (1.5 crowned); allowables
    s_at = 0.30·HB + 14.48 and s_ac = 2.35·HB + 162.89 MPa; K_L and C_L of
    :func:`life_factors` (two branches each), K_R = 0.50 − 0.25·log10(1 − R) (R ≥ 0.99) else
    0.70 − 0.15·log10(1 − R), C_R = √K_R, K_T = C_H = 1;
    S_F = s_at·K_L/(K_T·K_R·s_F), S_H = s_ac·C_L/(K_T·C_R·s_H). The power at which
    S = 1 at the same speed is P·S_F (bending, s_F ∝ Wt) and P·S_H² (contact,
    s_H ∝ √Wt). Gear B (``pair.gear``): s_F,G = s_F·J/J_G, its cycles N/(N/n),
    S_H,G = s_ac,G·C_L,G·C_H/(K_T·C_R·s_H).

    Parameters and units: :class:`PairRatingInput`; returns :class:`PairRating`.

    Source: ANSI/AGMA 2003-B97; Budynas & Nisbett, *Shigley's Mechanical Engineering
    Design*, 10th ed., §15-1 to 15-4, eqs. (15-1)–(15-23), SI form.
    """
    torque = np.abs(np.asarray(pair.pinion_torque, dtype=float))
    speed = np.abs(np.asarray(pair.pinion_speed, dtype=float))
    bending, contact = _stresses(pair, torque, speed)  # MPa
    s_at, s_ac = _allowables(pair.allowables, pair.hardness)
    n = np.asarray(pair.cycles, dtype=float)
    r = np.asarray(pair.reliability, dtype=float)
    k_l, c_l = life_factors(n)
    k_r = np.where(r >= 0.99, 0.50 - 0.25 * np.log10(1.0 - r), 0.70 - 0.15 * np.log10(1.0 - r))
    k_t = np.asarray(pair.temperature_factor, dtype=float)
    bending_safety = s_at * k_l / (k_t * k_r * bending)
    contact_safety = s_ac * c_l / (k_t * np.sqrt(k_r) * contact)
    power = torque * speed
    gear_b = None
    if pair.gear is not None:
        member = pair.gear
        j_g, gear_ratio, c_h = (np.asarray(value, dtype=float) for value in (
            member.bending_geometry_factor, member.gear_ratio, member.hardness_ratio_factor))
        gear_s_at, gear_s_ac = ((s_at, s_ac) if member.allowables is None
                                else _allowables(member.allowables, pair.hardness))
        gear_k_l, gear_c_l = life_factors(n / gear_ratio)  # gear B turns N/n times
        gear_bending = bending * np.asarray(pair.bending_geometry_factor, dtype=float) / j_g
        gear_b = GearMemberRating(
            bending_stress=gear_bending * 1e6,
            bending_safety=gear_s_at * gear_k_l / (k_t * k_r * gear_bending),
            contact_safety=gear_s_ac * gear_c_l * c_h / (k_t * np.sqrt(k_r) * contact))
    return PairRating(bending_stress=bending * 1e6, contact_stress=contact * 1e6,
                      bending_safety=bending_safety, contact_safety=contact_safety,
                      bending_power_rating=power * bending_safety,
                      contact_power_rating=power * contact_safety ** 2, gear_b=gear_b)


def _stresses(pair: PairRatingInput, torque: NDArray, speed: NDArray
              ) -> tuple[NDArray, NDArray]:
    """The pinion's bending and contact stresses s_F and s_H [MPa] (see :func:`rate_pair`),
    in the mm, N and m/s of the SI form."""
    m = np.asarray(pair.module, dtype=float) * MM
    de1 = np.asarray(pair.pinion_outer_diameter, dtype=float) * MM
    b = np.asarray(pair.face_width, dtype=float) * MM
    wt = 2.0 * torque * MM / de1                       # N, with T in N·mm
    v = 0.5 * de1 / MM * speed                         # m/s
    kv = dynamic_factor(pair.quality_number, v)
    ks = 0.4867 + 0.008339 * m
    km = np.asarray(pair.mounting_factor, dtype=float) + 5.6e-6 * b * b
    ko = np.asarray(pair.overload_factor, dtype=float)
    bending = (wt / b * ks * km / np.asarray(pair.bending_geometry_factor, dtype=float) * ko
               * kv / m / np.asarray(pair.lengthwise_curvature_factor, dtype=float))
    cs = 0.00492 * b + 0.4375
    cxc = np.where(np.asarray(pair.crowned, dtype=bool), 1.5, 2.0)
    contact = STEEL_ELASTIC_COEFFICIENT * np.sqrt(
        wt * ko * kv * km * cs * cxc
        / (b * de1 * np.asarray(pair.pitting_geometry_factor, dtype=float)))
    return bending, contact


def _allowables(allowables: tuple[ArrayLike, ArrayLike] | None, hardness: ArrayLike
                ) -> tuple[NDArray, NDArray]:
    """The allowable bending and contact stress numbers s_at, s_ac [MPa]: those given
    [Pa], else through-hardened grade 1 steel's of the Brinell ``hardness``."""
    if allowables is not None:
        s_at, s_ac = (np.asarray(value, dtype=float) / 1e6 for value in allowables)
        return s_at, s_ac
    hb = np.asarray(hardness, dtype=float)
    bending_slope, bending_intercept, contact_slope, contact_intercept = THROUGH_HARDENED[1]
    return bending_slope * hb + bending_intercept, contact_slope * hb + contact_intercept
