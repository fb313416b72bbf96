"""The most heavily loaded roller of a roller bearing: its load and its contacts with both
races, and the rollers' kinematics (``docs/physics.md`` §6 and §7).

Every function takes SI values as floats or numpy arrays, which broadcast, and returns
arrays.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.hertz import hertz_point_contact


def max_roller_load(static_equivalent_load: ArrayLike, roller_count: ArrayLike,
                    rows: ArrayLike, contact_angle: ArrayLike, thrust: bool) -> NDArray:
    r"""Load Q of the most heavily loaded roller.

    .. math:: Q = \frac{5 P_0}{i Z \cos\alpha} \ \text{(radial)}, \qquad
              Q = \frac{F_a}{i Z \sin\alpha} \ \text{(thrust)}

    Stribeck's share for radial bearings, the basis of ISO 76's C0; an equal share of
    the axial load for thrust bearings.

    Parameters
    ----------
    static_equivalent_load : P0 (radial), Fa (thrust). [N]
    roller_count, rows : Z, i. [1]
    contact_angle : α. [rad]
    thrust : a thrust bearing.

    Source: ISO 76:2006, 6.1 and its basis (Stribeck); Harris & Kotzalas, *Essential
    Concepts of Bearing Technology*, 5th ed., ch. 7.
    """
    alpha = np.asarray(contact_angle, dtype=float)
    p0 = np.asarray(static_equivalent_load, dtype=float)
    z = np.asarray(roller_count, dtype=float)
    if thrust:
        return p0 / (np.asarray(rows, dtype=float) * z * np.sin(alpha))
    return 5.0 * p0 / (np.asarray(rows, dtype=float) * z * np.cos(alpha))


def line_contact(load: ArrayLike, length: ArrayLike, reduced_radius: ArrayLike,
                 elastic_modulus: ArrayLike, poisson_ratio: ArrayLike
                 ) -> tuple[NDArray, NDArray]:
    r"""Peak pressure and half-width of a Hertz line contact of two bodies of one steel.

    .. math:: p_0 = \sqrt{\frac{Q E^*}{\pi L R'}}, \qquad b = \sqrt{\frac{4 Q R'}{\pi L E^*}},
              \qquad E^* = \frac{E}{2(1 - \nu^2)}

    Parameters
    ----------
    load : Q. [N]
    length : L, the contact length. [m]
    reduced_radius : R′ = 1/(1/R1 + 1/R2) in the rolling direction. [m]
    elastic_modulus, poisson_ratio : E [Pa], ν [1], of both bodies.

    Returns
    -------
    (p0 [Pa], b [m]).

    Source: K. L. Johnson, *Contact Mechanics*, 1985, §4.2 (eqs. 4.43 to 4.45).
    """
    e_star = np.asarray(elastic_modulus, dtype=float) / (
        2.0 * (1.0 - np.asarray(poisson_ratio, dtype=float) ** 2))
    per_length = np.asarray(load, dtype=float) / np.asarray(length, dtype=float)
    radius = np.asarray(reduced_radius, dtype=float)
    return (np.sqrt(per_length * e_star / (np.pi * radius)),
            np.sqrt(4.0 * per_length * radius / (np.pi * e_star)))


def roller_contacts(roller_diameter: ArrayLike, roller_length: ArrayLike,  # noqa: PLR0913  a numpy kernel of the laminae's array inputs
                    pitch_diameter: ArrayLike, contact_angle: ArrayLike, thrust: bool,
                    load: ArrayLike, elastic_modulus: ArrayLike, poisson_ratio: ArrayLike,
                    max_contact_pressure: ArrayLike, roller_profile_radius: ArrayLike = None,
                    raceway_radius: ArrayLike = None) -> dict[str, NDArray]:
    r"""Contacts of the most heavily loaded roller with both races.

    With γ = Dwe·cosα/Dpw, the reduced radii in the rolling direction are
    R′ = Dwe(1 − γ)/2 at the inner race and Dwe(1 + γ)/2 at the outer (a thrust bearing
    at α = 90°: Dwe/2 at both). Straight rollers take :func:`line_contact` over Lwe. A
    spherical roller with its crown radius and the raceway's across the rolling direction
    takes the point contact of :func:`bearingcalc.core.hertz.hertz_point_contact`,
    whose semi-minor axis is the half-width.

    Parameters
    ----------
    roller_diameter, roller_length, pitch_diameter : Dwe, Lwe, Dpw. [m]
    contact_angle : α. [rad]
    thrust : a thrust bearing.
    load : Q of the roller. [N]
    elastic_modulus, poisson_ratio : of rollers and races alike. [Pa], [1]
    max_contact_pressure : the limit. [Pa]
    roller_profile_radius, raceway_radius : a spherical roller's crown radius and its
        raceway's radius across the rolling direction, or None. [m]

    Returns
    -------
    dict of each contact's peak pressure [Pa] and half-width [m], the larger pressure
    [Pa] and its margin to the limit [1]; for a crowned roller also each contact
    ellipse's semi-major axis a, along the roller (``inner_contact_semi_major``). [m]

    Source: Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
    ch. 2 (curvatures) and ch. 6 (contact stress).
    """
    dwe = np.asarray(roller_diameter, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    cos_alpha = np.where(thrust & np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12),
                         0.0, np.cos(alpha))
    gamma = dwe * cos_alpha / np.asarray(pitch_diameter, dtype=float)
    out: dict[str, NDArray] = {}
    for race, sign in (("inner", -1.0), ("outer", 1.0)):
        radius = dwe * (1.0 + sign * gamma) / 2.0
        if roller_profile_radius is not None and raceway_radius is not None:
            roller = 2.0 / dwe
            contact = hertz_point_contact(
                load, roller, 1.0 / np.asarray(roller_profile_radius, dtype=float),
                1.0 / radius - roller, -1.0 / np.asarray(raceway_radius, dtype=float),
                elastic_modulus, poisson_ratio, elastic_modulus, poisson_ratio)
            pressure, half_width = contact["max_pressure"], contact["semi_minor"]
            out[f"{race}_contact_semi_major"] = contact["semi_major"]
        else:
            pressure, half_width = line_contact(load, roller_length, radius,
                                                elastic_modulus, poisson_ratio)
        out[f"{race}_contact_pressure"] = pressure
        out[f"{race}_contact_half_width"] = half_width
    peak = np.maximum(out["inner_contact_pressure"], out["outer_contact_pressure"])
    out["max_contact_pressure"] = peak
    out["contact_pressure_margin"] = 1.0 - peak / np.asarray(max_contact_pressure)
    return out


def roller_kinematics(roller_count: ArrayLike, roller_diameter: ArrayLike,
                      pitch_diameter: ArrayLike, contact_angle: ArrayLike,
                      inner_speed: ArrayLike, outer_speed: ArrayLike,
                      thrust: bool) -> dict[str, NDArray]:
    r"""Cage speed and the defect frequencies of a roller bearing in pure rolling.

    With γ = Dwe·cosα/Dpw and the rings' frequencies f_i, f_o:

    .. math:: f_c = \tfrac12\left[f_i(1-\gamma) + f_o(1+\gamma)\right], \quad
              \mathrm{BPFO} = Z|f_c - f_o|, \quad \mathrm{BPFI} = Z|f_i - f_c|, \quad
              f_R = \frac{D_{pw}}{2 D_{we}}(1 - \gamma^2)|f_i - f_o|

    f_R is the roller's spin about its own axis relative to the cage. A tapered roller
    uses its mean diameter and the mean pitch diameter.

    Parameters
    ----------
    roller_count : Z. [1]
    roller_diameter, pitch_diameter : Dwe, Dpw. [m]
    contact_angle : α. [rad]
    inner_speed, outer_speed : the rings' speeds, fixed frame. [rad/s]
    thrust : a thrust bearing (γ = 0 at α = 90°).

    Source: Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
    ch. 8; ISO 15243 (defect frequencies).
    """
    dwe = np.asarray(roller_diameter, dtype=float)
    dpw = np.asarray(pitch_diameter, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    cos_alpha = np.where(thrust & np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12),
                         0.0, np.cos(alpha))
    gamma = dwe * cos_alpha / dpw
    to_hz = 1.0 / (2.0 * np.pi)
    f_i = np.asarray(inner_speed, dtype=float) * to_hz
    f_o = np.asarray(outer_speed, dtype=float) * to_hz
    f_c = 0.5 * (f_i * (1.0 - gamma) + f_o * (1.0 + gamma))
    z = np.asarray(roller_count, dtype=float)
    return {
        "cage_frequency": f_c,
        "ball_pass_frequency_outer": z * np.abs(f_c - f_o),
        "ball_pass_frequency_inner": z * np.abs(f_i - f_c),
        "roller_spin_frequency": dpw / (2.0 * dwe) * (1.0 - gamma ** 2) * np.abs(f_i - f_o),
        "cage_speed": f_c * 2.0 * np.pi,
    }
