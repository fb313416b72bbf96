"""The factors of ISO 10300's method B1 that follow from the virtual cylindrical gears
(:mod:`bearingcalc.core.iso10300_virtual`) in closed form: the nominal forces at the
mean point, the mid-zone and elasticity factors, the face load factor from the mounting
and the contact pattern's check, the lengthwise curvature factor for bending, and the
lubricant film factors Z_L, Z_V, Z_R (``docs/physics.md`` §8, ISO 10300).

Every function is pure numpy on SI arrays that broadcast; where the standard's
empirical formulas are written in N/mm², mm²/s, mm and µm, the conversion is inside.
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: ISO 10300-1 Table 4: K_Hβ-be by how the contact pattern was checked (rows) and how
#: the members are mounted (columns: both straddle, one cantilevered, both
#: cantilevered), from the AGMA words the rating block uses.
MOUNTINGS = ("both-straddle", "one-straddle", "neither-straddle")
PATTERN_CHECKS = ("full-load", "light-load", "estimated")
MOUNTING_FACTOR = np.array([[1.00, 1.00, 1.00],
                            [1.05, 1.10, 1.25],
                            [1.20, 1.32, 1.50]])
#: K_Hβ-C = 1.5·K_Hβ-be (ISO 10300-1, 8.3.2: a crowned contact pattern).
FACE_LOAD_SCALE = 1.5
MPA = 1e6


def nominal_forces(pinion_torque: ArrayLike, mean_pitch_diameter_pinion: ArrayLike,
                   pressure_angle: ArrayLike, spiral_angle: ArrayLike
                   ) -> tuple[NDArray, NDArray]:
    r"""The nominal tangential force at the mean point and the normal force [N]:

    .. math:: F_{mt1} = \frac{2T_1}{d_{m1}}, \qquad F_n = \frac{F_{mt1}}{\cos α_n\cos β_m}

    Source: ISO 10300-1:2014, 6.1; ISO 10300-2:2014, 6.2.
    """
    tangential = 2.0 * np.abs(np.asarray(pinion_torque, dtype=float)) / np.asarray(
        mean_pitch_diameter_pinion, dtype=float)
    return tangential, tangential / (np.cos(np.asarray(pressure_angle, dtype=float))
                                     * np.cos(np.asarray(spiral_angle, dtype=float)))


def mid_zone_factor(virtual: dict[str, NDArray]) -> NDArray:
    r"""Z_M-B [1], from the radii of curvature at the mean point's inner points of
    single contact, with the auxiliary F1, F2 by the face contact ratio ε_vβ:

    .. math:: Z_{M-B} = \frac{\tan α_{vet}}{\sqrt{\left(\sqrt{(d_{va1}/d_{vb1})^2 - 1}
              - F_1π/z_{v1}\right)\left(\sqrt{(d_{va2}/d_{vb2})^2 - 1}
              - F_2π/z_{v2}\right)}}

    F1 = 2 + (ε_vα − 2)ε_vβ, F2 = 2ε_vα − 2 + (2 − ε_vα)ε_vβ below ε_vβ = 1 (at 0:
    2 and 2(ε_vα − 1)); F1 = F2 = ε_vα from 1 on.

    Source: ISO 10300-2:2014, 6.3 and its table of F1, F2.
    """
    eps_a, eps_b = virtual["eps_v_alpha"], virtual["eps_v_beta"]
    partial = eps_b < 1.0
    first = np.where(partial, 2.0 + (eps_a - 2.0) * eps_b, eps_a)
    second = np.where(partial, 2.0 * eps_a - 2.0 + (2.0 - eps_a) * eps_b, eps_a)
    v = virtual
    pinion = np.sqrt((v["dva1"] / v["dvb1"]) ** 2 - 1.0) - first * np.pi / v["zv1"]
    gear = np.sqrt((v["dva2"] / v["dvb2"]) ** 2 - 1.0) - second * np.pi / v["zv2"]
    return np.tan(v["alpha_vet"]) / np.sqrt(pinion * gear)


def elasticity_factor(moduli: tuple[ArrayLike, ArrayLike], poissons: tuple[ArrayLike, ArrayLike]
                      ) -> NDArray:
    r"""Z_E [√Pa] of the two members' materials,

    .. math:: Z_E = \sqrt{\frac{1}{π\left(\frac{1 - ν_1^2}{E_1} + \frac{1 - ν_2^2}{E_2}\right)}}

    Source: ISO 10300-2:2014, 8.1.
    """
    compliance = sum((1.0 - np.asarray(nu, dtype=float) ** 2) / np.asarray(e, dtype=float)
                     for e, nu in zip(moduli, poissons, strict=True))
    return np.sqrt(1.0 / (np.pi * compliance))


def face_load_factor(mounting: str, pattern_check: Literal["full-load", "light-load",
                                                           "estimated"]) -> float:
    """K_Hβ-C = 1.5·K_Hβ-be [1] (ISO 10300-1, 8.3, Table 4)."""
    return FACE_LOAD_SCALE * float(MOUNTING_FACTOR[PATTERN_CHECKS.index(pattern_check),
                                                   MOUNTINGS.index(mounting)])


def lengthwise_curvature_factor(cutter_radius: ArrayLike, mean_cone_distance: ArrayLike,
                                spiral_angle: ArrayLike) -> NDArray:
    r"""K_F0 [1], a face-milled spiral's root strengthened by the lengthwise curvature,

    .. math:: K_{F0} = 0.211\left(\frac{r_{c0}}{R_m}\right)^q + 0.789, \quad
              q = \frac{0.279}{\log_{10}\sin β_m}

    from 1 to 1.15; 1 for a straight or Zerol pair (β_m = 0).

    Source: ISO 10300-1:2014, 8.4 (the same curve as AGMA 2003's K_x).
    """
    beta = np.asarray(spiral_angle, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        exponent = 0.279 / np.log10(np.sin(beta))
        value = 0.211 * (np.asarray(cutter_radius, dtype=float)
                         / np.asarray(mean_cone_distance, dtype=float)) ** exponent + 0.789
    return np.where(beta > 0.0, np.clip(value, 1.0, 1.15), 1.0)


def lubricant_film_factors(contact_limit: ArrayLike, viscosity_40: ArrayLike,
                           mean_speed: ArrayLike, flank_roughness: tuple[ArrayLike, ArrayLike],
                           relative_curvature: ArrayLike) -> tuple[NDArray, NDArray, NDArray]:
    r"""Z_L, Z_V and Z_R [1], from σ_Hlim (held within 850 to 1200 N/mm² for the
    constants), the oil's ν40 [mm²/s], the mean point's tangential speed v_mt [m/s],
    the flanks' Rz [µm] and ρ_rel [mm]:

    .. math:: C_{ZL} = 0.83 + 0.08\frac{σ_{Hlim} - 850}{350}, \quad
              Z_L = C_{ZL} + \frac{4(1 - C_{ZL})}{(1.2 + 134/ν_{40})^2}

    .. math:: C_{ZV} = C_{ZL} + 0.02, \quad Z_V = C_{ZV} + \frac{2(1 - C_{ZV})}{\sqrt{0.8
              + 32/v_{mt}}}, \quad R_{z10} = \frac{R_{z1} + R_{z2}}2\sqrt[3]{\frac{10}{ρ_{rel}}},
              \quad Z_R = \left(\frac3{R_{z10}}\right)^{0.12 + (1000 - σ_{Hlim})/5000}

    Source: ISO 10300-2:2014, 8.2 (as ISO 6336-2:2006, clause 11, method B).
    """
    limit = np.clip(np.asarray(contact_limit, dtype=float) / MPA, 850.0, 1200.0)
    c_l = 0.83 + 0.08 * (limit - 850.0) / 350.0
    viscosity = np.asarray(viscosity_40, dtype=float) * 1e6
    film = c_l + 4.0 * (1.0 - c_l) / (1.2 + 134.0 / viscosity) ** 2
    c_v = c_l + 0.02
    speed = c_v + 2.0 * (1.0 - c_v) / np.sqrt(0.8 + 32.0 / np.asarray(mean_speed, dtype=float))
    rz = 0.5 * (np.asarray(flank_roughness[0], dtype=float)
                + np.asarray(flank_roughness[1], dtype=float)) * 1e6
    rz10 = rz * np.cbrt(10.0 / (np.asarray(relative_curvature, dtype=float) * 1e3))
    roughness = (3.0 / rz10) ** (0.12 + (1000.0 - limit) / 5000.0)
    return film, speed, roughness


#: The sectors of the reference speed N = n1/n_E1 (ISO 10300-1, 7.6): subcritical up to
#: 0.75, the main resonance to 1.25, an intermediate one to 1.5, supercritical above.
SUBCRITICAL, RESONANCE, INTERMEDIATE = 0.75, 1.25, 1.5
#: Mesh stiffness per unit face width c_γ and single stiffness c′ at a load of
#: 100 N/mm and above [N/(mm·µm)], and the running-in allowance's share of f_pt (at
#: most 3 µm) of case-hardened or nitrided steel.
MESH_STIFFNESS, SINGLE_STIFFNESS, RUNNING_IN_SHARE, RUNNING_IN_MOST = 20.0, 14.0, 0.075, 3.0


def _stiffness_scale(virtual: dict[str, NDArray], tangential_force: ArrayLike,
                     application_factor: ArrayLike) -> tuple[NDArray, NDArray]:
    """F_vmt·K_A [N], and C_F: the stiffnesses fall in proportion below 100 N/mm of
    that load over b_v,eff."""
    load = np.asarray(tangential_force, dtype=float) * np.asarray(application_factor,
                                                                   dtype=float)
    return load, np.minimum(load / (virtual["bv_eff"] * 1e3) / 100.0, 1.0)


def _effective_deviation(pitch_deviation: ArrayLike) -> NDArray:
    """f_pt − y_α [µm]: the running-in allowance y_α = 0.075·f_pt, at most 3 µm."""
    deviation = np.asarray(pitch_deviation, dtype=float) * 1e6
    return deviation - np.minimum(RUNNING_IN_SHARE * deviation, RUNNING_IN_MOST)


def _coefficients(eps_gamma: NDArray) -> tuple[NDArray, NDArray, NDArray, NDArray, NDArray]:
    """c_v1 + c_v2, c_v3, c_v4, c_v5 + c_v6, c_v7 of ISO 10300-1 Table 3."""
    low = eps_gamma <= 2.0
    with np.errstate(divide="ignore", invalid="ignore"):
        cv12 = 0.32 + np.where(low, 0.34, 0.57 / (eps_gamma - 0.3))
        cv3 = np.where(low, 0.23, 0.096)
        cv4 = np.where(low, 0.90, (eps_gamma - 1.56) / (0.57 - 0.05 * eps_gamma))
        cv56 = 0.47 + np.where(low, 0.47, 0.12 / (eps_gamma - 1.74))
    cv7 = np.where(eps_gamma <= 1.5, 0.75, np.where(
        eps_gamma <= 2.5, 0.125 * np.sin(np.pi * (eps_gamma - 2.0)) + 0.875, 1.0))
    return cv12, cv3, cv4, cv56, cv7


def dynamic_factor(virtual: dict[str, NDArray], pinion_teeth: ArrayLike,
                   pinion_speed: ArrayLike, tangential_force: ArrayLike,
                   application_factor: ArrayLike, pitch_deviation: ArrayLike,
                   density: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""K_v by method B and the reference speed N [1], from the virtual cylindrical gears
    (lengths [m]), the pinion's speed n1 [rad/s], F_vmt [N], K_A, the wheel's single
    pitch deviation f_pt [m] and the steel's density ρ [kg/m³]. The members' masses per
    unit face width, referred to their base circles, and the pair's resonance:

    .. math:: m^* = \frac{π}{8}\,ρ\,\frac{d_v^2}{\cos^2 α_{vet}}, \quad
              m_{red} = \frac{m_1^* m_2^*}{m_1^* + m_2^*}, \quad
              n_{E1} = \frac{30\,000}{π z_1}\sqrt{\frac{c_γ}{m_{red}}}, \quad
              N = \frac{n_1}{n_{E1}}

    with K = (b_v,eff·f_p,eff·c′/(F_vmt·K_A))·(c_v1 + c_v2) + c_v3, f_p,eff = f_pt − y_α
    (y_α = 0.075·f_pt, at most 3 µm): K_v = N·K + 1 subcritical (N ≤ 0.75); in the main
    resonance (to 1.25) K_v = (…)(c_v1 + c_v2) + c_v4 + 1; supercritical (from 1.5)
    K_v = (…)(c_v5 + c_v6) + c_v7; between 1.25 and 1.5 linear between the two.

    Source: ISO 10300-1:2014, 7.6 (method B) and Table 3; ISO 6336-1:2006, 6.5 (the
    masses referred to the base circles). ISO/TR 10300-30 sample 1 prints K_v 1.020.
    """
    load, scale = _stiffness_scale(virtual, tangential_force, application_factor)
    width_mm = virtual["bv_eff"] * 1e3
    masses = [0.125 * np.asarray(density, dtype=float) * np.pi * virtual[key] ** 2
              / np.cos(virtual["alpha_vet"]) ** 2 for key in ("dv1", "dv2")]
    reduced = masses[0] * masses[1] / (masses[0] + masses[1])  # [kg/m]
    # the standard's n_E1 [1/min]: c_γ [N/(mm·µm)] over m_red in kg/mm
    resonance = 30000.0 / (np.pi * np.asarray(pinion_teeth, dtype=float)) * np.sqrt(
        MESH_STIFFNESS * scale / (reduced * 1e-3))
    speed = np.abs(np.asarray(pinion_speed, dtype=float)) * 30.0 / np.pi
    ratio = speed / resonance
    term = width_mm * _effective_deviation(pitch_deviation) * SINGLE_STIFFNESS * scale / load
    cv12, cv3, cv4, cv56, cv7 = _coefficients(virtual["eps_v_gamma"])
    main = term * cv12 + cv4 + 1.0
    above = term * cv56 + cv7 + 1.0
    between = above + (main - above) * (INTERMEDIATE - ratio) / (INTERMEDIATE - RESONANCE)
    value = np.where(ratio <= SUBCRITICAL, ratio * (term * cv12 + cv3) + 1.0,
                     np.where(ratio <= RESONANCE, main,
                              np.where(ratio < INTERMEDIATE, between, above)))
    return value, ratio


def transverse_load_factor(virtual: dict[str, NDArray], determinant_force: ArrayLike,
                           tangential_force: ArrayLike, application_factor: ArrayLike,
                           pitch_deviation: ArrayLike) -> NDArray:
    r"""K_Hα (= K_Fα without offset) by method B [1], from the determinant force at the
    mean point F_mtH = F_vmt·K_A·K_v·K_Hβ [N] over the face width b_v:

    .. math:: K_{Hα} = 0.9 + 0.4\,Φ\,\frac{c_γ(f_{pt} - y_α)}{F_{mtH}/b_v}, \quad
              Φ = \frac{ε_{vγ}}2 \ (ε_{vγ} \le 2), \quad
              Φ = \sqrt{\frac{2(ε_{vγ} - 1)}{ε_{vγ}}} \ (ε_{vγ} > 2)

    no less than 1. Source: ISO 10300-1:2014, 9.3 (method B). ISO/TR 10300-30 sample 1
    prints 1.161.
    """
    eps = virtual["eps_v_gamma"]
    _, scale = _stiffness_scale(virtual, tangential_force, application_factor)
    with np.errstate(invalid="ignore"):
        share = np.where(eps <= 2.0, eps / 2.0, np.sqrt(2.0 * (eps - 1.0) / eps))
    line = np.asarray(determinant_force, dtype=float) / (virtual["bv"] * 1e3)
    return np.maximum(0.9 + 0.4 * share * MESH_STIFFNESS * scale
                      * _effective_deviation(pitch_deviation) / line, 1.0)
