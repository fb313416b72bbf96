"""From the drawing to the operating clearance: a bearing's rings pressed onto their seats
(Lamé's thick-walled cylinders), the interference lost as the surfaces' roughness is
pressed down, and the rings and seats warmed from the assembly's temperature to their
own (``docs/physics.md``, the mounting chain).

Every function is pure numpy on SI arrays that broadcast: diameters and interferences
[m], moduli and pressures [Pa], temperatures [K], expansion coefficients [1/K]. An
interference is diametral, positive where the inner part is the larger (a press fit),
negative where the fit is loose.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: DIN 7190-1:2017: the interference lost as the two surfaces' roughness is pressed
#: down, a share of the sum of their Rz (the 2001 edition had 0.8).
SMOOTHING_SHARE = 0.4


def _wall(inner: ArrayLike, outer: ArrayLike) -> NDArray:
    """(D_o² + D_i²)/(D_o² − D_i²) of a cylinder's wall, 1 for an unbounded outer body
    (D_o = ∞) and for a solid inner body (D_i = 0)."""
    inner, outer = np.asarray(inner, dtype=float), np.asarray(outer, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(np.isinf(outer), 0.0, (inner / outer) ** 2)
    return (1.0 + ratio) / (1.0 - ratio)


def fit_pressure(interference: ArrayLike, diameter: ArrayLike, *, inner_bore: ArrayLike,
                 outer_diameter: ArrayLike, inner_modulus: ArrayLike,
                 inner_poisson: ArrayLike, outer_modulus: ArrayLike,
                 outer_poisson: ArrayLike) -> NDArray:
    r"""The contact pressure p [Pa] of a press fit of diametral interference I [m] at the
    joint's diameter d between an inner cylinder (bore d_i, 0 for a solid shaft) and an
    outer one (outside diameter d_o, ``inf`` for an unbounded body), 0 where the fit is
    loose (I <= 0):

    .. math:: I = p\,d\left[\frac{1}{E_o}\left(\frac{d_o^2 + d^2}{d_o^2 - d^2}
              + ν_o\right) + \frac{1}{E_i}\left(\frac{d^2 + d_i^2}{d^2 - d_i^2}
              - ν_i\right)\right]

    Source: Lamé's thick-walled cylinders under plane stress, as in Roark's Formulas for
    Stress and Strain (8th ed.), Table 13.5 case 1 and the shrink fit of §13.4; DIN
    7190-1:2017, 6.
    """
    compliance = (
        (_wall(diameter, outer_diameter) + np.asarray(outer_poisson, dtype=float))
        / np.asarray(outer_modulus, dtype=float)
        + (_wall(inner_bore, diameter) - np.asarray(inner_poisson, dtype=float))
        / np.asarray(inner_modulus, dtype=float))
    return np.maximum(np.asarray(interference, dtype=float), 0.0) / (
        np.asarray(diameter, dtype=float) * compliance)


def bore_pressed_expansion(pressure: ArrayLike, bore: ArrayLike, raceway: ArrayLike,
                           modulus: ArrayLike) -> NDArray:
    r"""How much an inner ring's raceway diameter F grows [m] when its bore d is pressed
    outward by p (a cylinder under internal pressure, its outer surface free):

    .. math:: ΔF = \frac{2\,p\,d^2\,F}{E\,(F^2 - d^2)}

    For a thin ring on a solid shaft of its own material ΔF → I·d/F. Source: Lamé;
    Roark (8th ed.), Table 13.5 case 1c.
    """
    p, d, f = (np.asarray(v, dtype=float) for v in (pressure, bore, raceway))
    return 2.0 * p * d * d * f / (np.asarray(modulus, dtype=float) * (f * f - d * d))


def outside_pressed_contraction(pressure: ArrayLike, raceway: ArrayLike,
                                outside: ArrayLike, modulus: ArrayLike) -> NDArray:
    r"""How much an outer ring's raceway diameter E shrinks [m] when its outside D is
    pressed inward by p (a cylinder under external pressure, its bore free):

    .. math:: ΔE = \frac{2\,p\,D^2\,E}{E_m\,(D^2 - E^2)}

    Source: Lamé; Roark (8th ed.), Table 13.5 case 1d.
    """
    p, e, outer = (np.asarray(v, dtype=float) for v in (pressure, raceway, outside))
    return 2.0 * p * outer * outer * e / (np.asarray(modulus, dtype=float)
                                          * (outer * outer - e * e))


def bore_hoop_stress(pressure: ArrayLike, bore: ArrayLike, raceway: ArrayLike) -> NDArray:
    r"""The inner ring's tangential (hoop) stress at its bore [Pa], the largest in the
    ring, under the fit's pressure p:

    .. math:: σ_t = p\,\frac{F^2 + d^2}{F^2 - d^2}

    Source: Lamé; Roark (8th ed.), Table 13.5 case 1c.
    """
    return np.asarray(pressure, dtype=float) * _wall(bore, raceway)


class Temperatures(NamedTuple):
    """The rise of each part over the assembly's temperature [K], and the expansion
    coefficients of the rings (and rolling elements) and of the seats [1/K]."""

    inner_ring: NDArray
    outer_ring: NDArray
    shaft: NDArray
    housing: NDArray
    ring_expansion: NDArray
    shaft_expansion: NDArray
    housing_expansion: NDArray


def thermal_interference_change(temperatures: Temperatures, bore: ArrayLike,
                                outside: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""How much each fit's interference grows [m] as the parts warm from the assembly's
    temperature, (inner fit, outer fit): each seat and ring grows by α·ΔT times its
    diameter,

    .. math:: ΔI_i = d\,(α_s ΔT_s - α_r ΔT_i), \qquad ΔI_o = D\,(α_r ΔT_o - α_h ΔT_h)

    (an aluminium housing, its α twice steel's, loosens its fit as it warms).
    """
    t = temperatures
    inner = np.asarray(bore, dtype=float) * (t.shaft_expansion * t.shaft
                                            - t.ring_expansion * t.inner_ring)
    outer = np.asarray(outside, dtype=float) * (t.ring_expansion * t.outer_ring
                                               - t.housing_expansion * t.housing)
    return inner, outer


def thermal_clearance_reduction(temperatures: Temperatures, pitch_diameter: ArrayLike
                                ) -> NDArray:
    r"""How much the diametral clearance shrinks [m] as the rings warm unequally, the
    rolling elements at the mean of the two rings' temperatures. With the raceways'
    diameters Dpw ∓ Dw and the elements' 2·Dw across the line of the clearance,

    .. math:: ΔP_d = α\left[(D_{pw} - D_w)ΔT_i + 2D_w\frac{ΔT_i + ΔT_o}{2}
              - (D_{pw} + D_w)ΔT_o\right] = α\,D_{pw}\,(ΔT_i - ΔT_o)

    the same for rollers (Dwe for Dw): the elements' size drops out.
    """
    t = temperatures
    return t.ring_expansion * np.asarray(pitch_diameter, dtype=float) * (
        t.inner_ring - t.outer_ring)


class Seats(NamedTuple):
    """The two fits as drawn and made, arrays over designs [m, Pa, 1]: each part's actual
    diameter (its nominal plus its deviation), the bodies around them and their
    materials, and the Rz sums pressed down in each joint."""

    shaft_diameter: NDArray       # the shaft seat's diameter
    bore_diameter: NDArray        # the inner ring's (mean) bore
    housing_diameter: NDArray     # the housing seat's bore
    outside_diameter: NDArray     # the outer ring's (mean) outside diameter
    shaft_bore: NDArray           # a hollow shaft's bore, 0 for a solid one
    housing_outside: NDArray      # the housing's wall, inf for an unbounded body
    shaft_modulus: NDArray
    shaft_poisson: NDArray
    housing_modulus: NDArray
    housing_poisson: NDArray
    ring_modulus: NDArray
    ring_poisson: NDArray
    shaft_roughness: NDArray      # Rz of the shaft seat and the ring's bore, summed
    housing_roughness: NDArray    # Rz of the housing seat and the ring's outside, summed


#: The results of :func:`operating_clearance`, in their order.
CHAIN_RESULTS = (
    "fit_interference_inner", "fit_interference_outer", "effective_interference_inner",
    "effective_interference_outer", "fit_pressure_inner", "fit_pressure_outer",
    "inner_ring_hoop_stress", "clearance_reduction_fit_inner",
    "clearance_reduction_fit_outer", "clearance_change_thermal", "initial_clearance",
    "operating_clearance")


def operating_clearance(initial_clearance: ArrayLike, seats: Seats,
                        temperatures: Temperatures, inner_raceway: ArrayLike,
                        outer_raceway: ArrayLike, pitch_diameter: ArrayLike
                        ) -> dict[str, NDArray]:
    r"""The mounted bearing's diametral operating clearance [m] and the chain to it:

    .. math:: P_{d,op} = P_{d,0} - ΔF_{fit} - ΔE_{fit} - ΔP_{d,T}

    each fit's interference as drawn (at the assembly's temperature), less
    0.4·ΣRz pressed down (DIN 7190-1:2017), plus its change as the parts warm, sets its
    pressure (:func:`fit_pressure`: the inner ring a cylinder from its bore to its raceway
    F on the shaft, the outer ring one from its raceway E to D in the housing), which
    widens the inner raceway and narrows the outer one; the rings' unequal warming
    narrows the clearance by α·Dpw·(ΔT_i − ΔT_o). Keys :data:`CHAIN_RESULTS`.
    """
    s, t = seats, temperatures
    drawn_inner = s.shaft_diameter - s.bore_diameter
    drawn_outer = s.outside_diameter - s.housing_diameter
    warm_inner, warm_outer = thermal_interference_change(t, s.bore_diameter,
                                                         s.outside_diameter)
    effective_inner = drawn_inner - SMOOTHING_SHARE * s.shaft_roughness + warm_inner
    effective_outer = drawn_outer - SMOOTHING_SHARE * s.housing_roughness + warm_outer
    pressure_inner = fit_pressure(
        effective_inner, s.bore_diameter, inner_bore=s.shaft_bore,
        outer_diameter=inner_raceway, inner_modulus=s.shaft_modulus,
        inner_poisson=s.shaft_poisson, outer_modulus=s.ring_modulus,
        outer_poisson=s.ring_poisson)
    pressure_outer = fit_pressure(
        effective_outer, s.outside_diameter, inner_bore=outer_raceway,
        outer_diameter=s.housing_outside, inner_modulus=s.ring_modulus,
        inner_poisson=s.ring_poisson, outer_modulus=s.housing_modulus,
        outer_poisson=s.housing_poisson)
    reduction_inner = bore_pressed_expansion(pressure_inner, s.bore_diameter, inner_raceway,
                                             s.ring_modulus)
    reduction_outer = outside_pressed_contraction(pressure_outer, outer_raceway,
                                                  s.outside_diameter, s.ring_modulus)
    thermal = thermal_clearance_reduction(t, pitch_diameter)
    initial = np.asarray(initial_clearance, dtype=float)
    values = (drawn_inner, drawn_outer, effective_inner, effective_outer, pressure_inner,
              pressure_outer, bore_hoop_stress(pressure_inner, s.bore_diameter,
                                               inner_raceway),
              reduction_inner, reduction_outer, thermal, initial,
              initial - reduction_inner - reduction_outer - thermal)
    return dict(zip(CHAIN_RESULTS, np.broadcast_arrays(*values), strict=True))
