"""ISO 281:2007, dynamic load ratings and rating life of rolling bearings.

The basic dynamic load rating C with its factors fc and bm, the equivalent dynamic load
P (X, Y and e), the basic rating life L10, the reliability factor a1, the viscosities
of the lubrication (Walther's viscosity–temperature relation, the reference viscosity
ν1) and the life modification factor aISO. Every function takes SI values as floats or
numpy arrays, which broadcast, and returns arrays; inside, the standard's formulas are
written in its own units (N, mm, r/min, mm²/s) and converted at the edge. See
``docs/physics.md`` §5 for the relations, their ranges and the sources.

The standard gives ball and roller bearings formulas of their own. The life, Cu and
aISO take a ``family``; the roller bearings' C and P, which need the roller's length and
the number of rows, are in :mod:`bearingcalc.core.roller_ratings`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.bearing_types import LoadRule, traits
from bearingcalc.core.common import (
    MM,
    NEWTON,
    RPM,
    Family,
    ball_family_only,
    known_family,
    table_lookup,
)

#: ISO 281:2007 bm, the rating factor for contemporary, normally used material. [1]
MATERIAL_FACTOR = 1.3
#: Ball diameter above which ISO 281 uses the Dw^1.4 form of C. [mm]
LARGE_BALL_MM = 25.4

#: ISO 281:2007 Table 2: fc of single-row radial and angular-contact groove ball bearings
#: against γ = Dw·cosα/Dpw, at every hundredth from 0.01 to 0.40 as the standard prints
#: it (ISO 281:1990 printed every other row above 0.10; the line between those misses
#: the odd rows by up to 0.1).
RADIAL_FC_GAMMA = np.round(np.arange(1, 41) * 0.01, 2)
RADIAL_FC = np.array([29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
                      56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,
                      59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,
                      55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4])
#: ISO 281:2007 Table 4: fc of thrust ball bearings with α = 90° against γ = Dw/Dpw.
THRUST_FC_GAMMA = np.round(np.arange(1, 36) * 0.01, 2)
THRUST_FC = np.array([36.7, 45.2, 51.1, 55.7, 59.5, 62.9, 65.8, 68.5, 71.0, 73.3,
                      75.4, 77.4, 79.3, 81.1, 82.7, 84.4, 85.9, 87.4, 88.8, 90.2,
                      91.5, 92.8, 94.1, 95.3, 96.4, 97.6, 98.7, 99.8, 100.8, 101.9,
                      102.9, 103.9, 104.8, 105.8, 106.7])
#: ISO 281:2007 Table 3, single-row deep-groove: f0·Fa/C0 -> (e, Y), with X = 0.56.
DEEP_GROOVE_RATIO = np.array([0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89])
DEEP_GROOVE_E = np.array([0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44])
DEEP_GROOVE_Y = np.array([2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00])
DEEP_GROOVE_X = 0.56
#: ISO 281:2007 Table 3, single-row angular-contact: α -> (X, Y, e).
ANGULAR_ALPHA_DEG = np.array([20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
ANGULAR_X = np.array([0.43, 0.41, 0.39, 0.37, 0.35, 0.33])
ANGULAR_Y = np.array([1.00, 0.87, 0.76, 0.66, 0.57, 0.50])
ANGULAR_E = np.array([0.57, 0.68, 0.80, 0.95, 1.14, 1.34])
#: ISO 281:2007 aISO for radial ball bearings: (κ from, A, b) of each viscosity band.
AISO_BANDS = ((0.1, 2.2649, 0.054381), (0.4, 1.9987, 0.19087), (1.0, 1.9987, 0.071739))
#: ISO 281:2007 aISO for radial roller bearings: (κ from, A, b) of each viscosity band.
ROLLER_AISO_BANDS = ((0.1, 1.3993, 0.054381), (0.4, 1.2348, 0.19087),
                     (1.0, 1.2348, 0.071739))
#: The load-life exponent p of L10 = (C/P)^p.
LIFE_EXPONENT = {"ball": 3.0, "roller": 10.0 / 3.0}
AISO_CAP = 50.0
KAPPA_CAP = 4.0
KAPPA_MIN = 0.1
#: Kelvin of the two ASTM D341 reference temperatures.
T40, T100 = 313.15, 373.15
#: Most operating viscosity taken from Walther's equation: 10⁶ mm²/s is a solid, far
#: below an oil's pour point, where the viscosity–temperature relation no longer holds.
MAX_OPERATING_VISCOSITY = 1.0


def dynamic_load_rating(ball_count: ArrayLike, ball_diameter: ArrayLike,
                        pitch_diameter: ArrayLike, contact_angle: ArrayLike,
                        thrust: ArrayLike = False, *, family: Family = "ball"
                        ) -> tuple[NDArray, NDArray]:
    r"""Basic dynamic load rating C of a single-row ball bearing, and its fc.

    .. math:: C = b_m f_c (\cos\alpha)^{0.7} Z^{2/3} D_w^{1.8} \quad (D_w \le 25.4\,mm),
              \qquad 3.647\, b_m f_c (\cos\alpha)^{0.7} Z^{2/3} D_w^{1.4} \quad (D_w > 25.4\,mm)

    with C in N and Dw in mm, fc from Table 2 at γ = Dw·cosα/Dpw. Thrust bearings
    (α = 90°) drop the cos α factor and take fc from Table 4 at γ = Dw/Dpw.

    Parameters
    ----------
    ball_count : Z. [1]
    ball_diameter : Dw. [m]
    pitch_diameter : Dpw. [m]
    contact_angle : α (ignored for thrust). [rad]
    thrust : True for a thrust ball bearing with α = 90°.
    family : the rolling elements; "ball" only (roller bearings have a formula of their
        own, with the roller length Lwe and the number of rows i).

    Returns
    -------
    (C [N], fc [1]); NaN where γ is outside the table.

    Source: ISO 281:2007, 5.1 and 6.1 (Tables 2 and 4).

    >>> c, fc = dynamic_load_rating(8, 17.462e-3, 72.5e-3, 0.0)
    >>> round(float(fc), 2), round(float(c))
    (58.97, 52768)
    """
    ball_family_only(family, "ISO 281's dynamic load rating C")
    z = np.asarray(ball_count, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float) * MM
    dpw = np.asarray(pitch_diameter, dtype=float) * MM
    alpha = np.asarray(contact_angle, dtype=float)
    thrust = np.asarray(thrust, dtype=bool)
    cos_alpha = np.where(thrust, 1.0, np.cos(alpha))
    gamma = dw * cos_alpha / dpw
    fc = np.where(thrust, table_lookup(gamma, THRUST_FC_GAMMA, THRUST_FC),
                  table_lookup(gamma, RADIAL_FC_GAMMA, RADIAL_FC))
    base = MATERIAL_FACTOR * fc * cos_alpha ** 0.7 * z ** (2.0 / 3.0)
    rating = np.where(dw <= LARGE_BALL_MM, base * dw ** 1.8, 3.647 * base * dw ** 1.4)
    return rating * NEWTON, fc


class EquivalentLoad(NamedTuple):
    """The equivalent dynamic load and the factors it was formed with."""

    load: NDArray                      # P [N]
    combined: NDArray | None           # where P = X·Fr + Y·Fa, not Fr (radial bearings)
    x: NDArray | None                  # X of the table row, or given [1]
    y: NDArray | None                  # Y [1]
    e: NDArray | None                  # e, the limit of Fa/Fr [1]
    ratio_below_table: NDArray | None  # f0·Fa/C0 below Table 3's first row
    ratio_above_table: NDArray | None  # f0·Fa/C0 above its last row


def equivalent_dynamic_load(radial_load: ArrayLike, axial_load: ArrayLike,
                            bearing_type: str, contact_angle: ArrayLike, *,
                            static_factor: ArrayLike | None = None,
                            static_load_rating: ArrayLike | None = None,
                            load_factors: tuple[ArrayLike, ArrayLike, ArrayLike] | None = None,
                            family: Family = "ball") -> EquivalentLoad:
    r"""Equivalent dynamic load P of a ball bearing.

    .. math:: P = F_r \quad (F_a = 0 \text{ or } F_a/F_r \le e), \qquad
              P = X F_r + Y F_a \quad (F_a/F_r > e)

    Deep-groove: X = 0.56, e and Y interpolated in f0·Fa/C0 (Table 3; outside the table
    the end rows are used, and flagged). Angular-contact: X, Y and e interpolated in α
    from 20° to 45° (NaN outside). Thrust (α = 90°): P = Fa.

    Parameters
    ----------
    radial_load, axial_load : Fr, Fa. [N]
    bearing_type : a ball bearing's type (:mod:`bearingcalc.core.bearing_types`): its
        load rule, Table 3's in f0·Fa/C0 or in α, or P = Fa.
    contact_angle : α. [rad]
    static_factor, static_load_rating : f0 [1] and C0 [N], for deep-groove bearings with an
        axial load.
    load_factors : the catalogue's (X, Y, e), which replace the tables. [1]
    family : the rolling elements; "ball" only.

    Returns
    -------
    :class:`EquivalentLoad`: P, and for radial bearings where it was combined, X, Y, e and
    the flags of Table 3's ends (None where they do not apply; X, Y and e are NaN for a
    deep-groove bearing without f0 and C0, which can then carry no axial load).

    Source: ISO 281:2007, Table 3; docs/physics.md §5.
    """
    ball_family_only(family, "ISO 281's equivalent dynamic load P")
    fr = np.asarray(radial_load, dtype=float)
    fa = np.asarray(axial_load, dtype=float)
    rule = traits(bearing_type).load_rule
    if rule is LoadRule.AXIAL_ONLY:
        return EquivalentLoad(fa, None, None, None, None, None, None)
    below = above = None
    if load_factors is not None:
        x, y, e = (np.asarray(factor, dtype=float) for factor in load_factors)
    elif rule is LoadRule.ANGLE_TABLE:
        degrees = np.degrees(np.asarray(contact_angle, dtype=float))
        x, y, e = (table_lookup(degrees, ANGULAR_ALPHA_DEG, t)
                   for t in (ANGULAR_X, ANGULAR_Y, ANGULAR_E))
    elif static_factor is not None and static_load_rating is not None:
        ratio = static_factor * fa / static_load_rating
        below = (fa > 0) & (ratio < DEEP_GROOVE_RATIO[0])
        above = ratio > DEEP_GROOVE_RATIO[-1]
        clipped = np.clip(ratio, DEEP_GROOVE_RATIO[0], DEEP_GROOVE_RATIO[-1])
        e = np.interp(clipped, DEEP_GROOVE_RATIO, DEEP_GROOVE_E)
        y = np.interp(clipped, DEEP_GROOVE_RATIO, DEEP_GROOVE_Y)
        x = np.full_like(e, DEEP_GROOVE_X)
    else:  # deep-groove without f0 and C0: a radial load only (the spec model makes sure)
        x, y, e = (np.full_like(fa, np.nan) for _ in range(3))
    with np.errstate(divide="ignore", invalid="ignore"):
        combined = (fa > 0) & ~(fa / fr <= e)
    load = np.where(combined, x * fr + y * fa, fr)
    return EquivalentLoad(load, combined, x, y, e, below, above)


def basic_rating_life(dynamic_load_rating: ArrayLike, equivalent_load: ArrayLike, *,
                      family: Family = "ball") -> NDArray:
    r"""Basic rating life L10 of a ball or roller bearing, in revolutions.

    .. math:: L_{10} = \left(\frac{C}{P}\right)^p \cdot 10^6, \qquad p = 3 \ (\text{ball}),
              \ 10/3 \ (\text{roller})

    Parameters
    ----------
    dynamic_load_rating, equivalent_load : C, P. [N]
    family : the rolling elements, "ball" or "roller".

    Returns
    -------
    L10. [1] (revolutions)

    Source: ISO 281:2007, 5.3, 6.3, 7.3 and 8.3; docs/physics.md §5.

    >>> round(float(basic_rating_life(55300.0, 10000.0)) / 1e6, 1)
    169.1
    >>> round(float(basic_rating_life(2.0, 1.0, family="roller")) / 1e6, 4)
    10.0794
    """
    known_family(family)
    return (np.asarray(dynamic_load_rating, dtype=float)
            / np.asarray(equivalent_load, dtype=float)) ** LIFE_EXPONENT[family] * 1e6


def reliability_factor(reliability: ArrayLike) -> NDArray:
    r"""Life adjustment factor for reliability a1.

    .. math:: a_1 = 0.95 \left(\frac{\ln(100/R)}{\ln(100/90)}\right)^{2/3} + 0.05

    with R in percent; it reproduces ISO 281:2007 Table 12 (95 % → 0.64,
    99 % → 0.25, 99.95 % → 0.077), for ball and roller bearings alike.

    Parameters
    ----------
    reliability : R as a fraction, 0.9 <= R <= 0.9995. [1]

    >>> [round(float(reliability_factor(r)), 3) for r in (0.9, 0.95, 0.99, 0.9995)]
    [1.0, 0.638, 0.248, 0.077]
    """
    r = np.asarray(reliability, dtype=float)
    return 0.95 * (np.log(1.0 / r) / np.log(1.0 / 0.9)) ** (2.0 / 3.0) + 0.05


def reference_viscosity(speed: ArrayLike, mean_diameter: ArrayLike) -> NDArray:
    r"""Rated viscosity ν1 for adequate lubrication.

    .. math:: \nu_1 = 45000\, n^{-0.83} d_m^{-0.5} \ (n < 1000\,r/min), \qquad
              4500\, n^{-0.5} d_m^{-0.5} \ (n \ge 1000\,r/min)

    with ν1 in mm²/s, n in r/min and dm in mm; the same for ball and roller bearings.

    Parameters
    ----------
    speed : n, rotational speed. [rad/s]
    mean_diameter : dm, pitch diameter. [m]

    Returns
    -------
    ν1. [m²/s]

    Source: ISO 281:2007, Annex A; ISO/TR 1281-2 (eq. of Figure 1).
    """
    n = np.abs(np.asarray(speed, dtype=float)) * RPM
    dm = np.asarray(mean_diameter, dtype=float) * MM
    nu1 = np.where(n < 1000.0, 45000.0 * n ** -0.83, 4500.0 * n ** -0.5) * dm ** -0.5
    return nu1 * 1e-6


def walther_viscosity(viscosity_40: ArrayLike, viscosity_100: ArrayLike,
                      temperature: ArrayLike) -> NDArray:
    r"""Kinematic viscosity at a temperature from its values at 40 °C and 100 °C.

    .. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B \log_{10} T

    with ν in mm²/s and T in K, A and B fixed by the two reference points.

    Source: ASTM D341 (Walther's equation).

    >>> round(float(walther_viscosity(68e-6, 8.7e-6, 313.15)) * 1e6, 9)
    68.0
    """
    intercept, slope = _walther_line(viscosity_40, viscosity_100)
    t = np.asarray(temperature, dtype=float)
    return (10.0 ** 10.0 ** (intercept - slope * np.log10(t)) - 0.7) * 1e-6


def walther_temperature(viscosity_40: ArrayLike, viscosity_100: ArrayLike,
                        viscosity: ArrayLike) -> NDArray:
    r"""The temperature at which an oil has ``viscosity``: Walther's equation solved for T.

    .. math:: T = 10^{(A - \log_{10}\log_{10}(\nu + 0.7)) / B}

    Units: viscosities [m²/s], T [K]. Source: ASTM D341.

    >>> round(float(walther_temperature(68e-6, 8.7e-6, 8.7e-6)), 9)
    373.15
    """
    intercept, slope = _walther_line(viscosity_40, viscosity_100)
    return 10.0 ** ((intercept - _loglog(np.asarray(viscosity, dtype=float))) / slope)


def _loglog(nu: NDArray) -> NDArray:
    return np.log10(np.log10(nu * 1e6 + 0.7))


def _walther_line(viscosity_40: ArrayLike, viscosity_100: ArrayLike) -> tuple[NDArray, NDArray]:
    """(A, B) of Walther's line through the oil's two reference points."""
    v40, v100 = np.asarray(viscosity_40, dtype=float), np.asarray(viscosity_100, dtype=float)
    slope = (_loglog(v40) - _loglog(v100)) / (np.log10(T100) - np.log10(T40))
    return _loglog(v40) + slope * np.log10(T40), slope


def fatigue_load_limit(static_load_rating: ArrayLike, mean_diameter: ArrayLike, *,
                       family: Family = "ball") -> NDArray:
    r"""Fatigue load limit Cu of a bearing estimated from its static load rating.

    .. math:: C_u = \frac{C_0}{22}\left(\frac{100}{d_m}\right)^{0.5} \ (\text{ball}),
              \qquad \frac{C_0}{8.2}\left(\frac{100}{d_m}\right)^{0.3} \ (\text{roller})

    with dm in mm; the bracket is 1 up to dm = 100 mm.

    Parameters
    ----------
    static_load_rating : C0. [N]
    mean_diameter : dm. [m]
    family : the rolling elements, "ball" or "roller".

    Returns
    -------
    Cu. [N]

    Source: ISO 281:2007, Annex B.3.2.2 (simplified).
    """
    known_family(family)
    divisor, exponent = {"ball": (22.0, 0.5), "roller": (8.2, 0.3)}[family]
    dm = np.asarray(mean_diameter, dtype=float)
    return np.asarray(static_load_rating, dtype=float) / divisor * np.where(
        dm * MM <= 100.0, 1.0, (100.0 / (dm * MM)) ** exponent)


def life_modification_factor(viscosity_ratio: ArrayLike, contamination_factor: ArrayLike,
                             fatigue_load_limit: ArrayLike, equivalent_load: ArrayLike,
                             thrust: ArrayLike = False, *, family: Family = "ball"
                             ) -> NDArray:
    r"""aISO, capped at 50.

    Ball bearings (thrust: eC·Cu/(3P)):

    .. math:: a_{ISO} = 0.1\left[1 - \left(2.5671 - \frac{A}{\kappa^{b}}\right)^{0.83}
              \left(\frac{e_C C_u}{P}\right)^{1/3}\right]^{-9.3}

    with (A, b) = (2.2649, 0.054381) for 0.1 <= κ < 0.4, (1.9987, 0.19087) for
    0.4 <= κ < 1 and (1.9987, 0.071739) for 1 <= κ <= 4. Roller bearings (thrust:
    eC·Cu/(2.5P)):

    .. math:: a_{ISO} = 0.1\left[1 - \left(1.5859 - \frac{A}{\kappa^{b}}\right)
              \left(\frac{e_C C_u}{P}\right)^{0.4}\right]^{-9.185}

    with (A, b) = (1.3993, 0.054381), (1.2348, 0.19087) and (1.2348, 0.071739) in the
    same bands. A bracket <= 0 gives the cap.

    Parameters
    ----------
    viscosity_ratio : κ, 0.1 <= κ <= 4 (capped by the caller). [1]
    contamination_factor : eC, 0 to 1. [1]
    fatigue_load_limit : Cu. [N]
    equivalent_load : P. [N]
    thrust : True for thrust bearings.
    family : the rolling elements, "ball" or "roller".

    Source: ISO 281:2007, 9.3.2 (eqs. 13 to 20).
    """
    known_family(family)
    kappa = np.asarray(viscosity_ratio, dtype=float)
    bands = AISO_BANDS if family == "ball" else ROLLER_AISO_BANDS
    a_coeff = np.where(kappa < 0.4, bands[0][1], bands[1][1])
    b_coeff = np.where(kappa < 0.4, bands[0][2],
                       np.where(kappa < 1.0, bands[1][2], bands[2][2]))
    load = np.asarray(contamination_factor, dtype=float) * np.asarray(
        fatigue_load_limit, dtype=float) / np.asarray(equivalent_load, dtype=float)
    if family == "ball":
        load = np.where(np.asarray(thrust, dtype=bool), load / 3.0, load)
        bracket = 1.0 - (2.5671 - a_coeff / kappa ** b_coeff) ** 0.83 * load ** (1.0 / 3.0)
        exponent = -9.3
    else:
        load = np.where(np.asarray(thrust, dtype=bool), load / 2.5, load)
        bracket = 1.0 - (1.5859 - a_coeff / kappa ** b_coeff) * load ** 0.4
        exponent = -9.185
    with np.errstate(divide="ignore", invalid="ignore"):
        factor = 0.1 * bracket ** exponent
    return np.where(bracket > 0, np.minimum(factor, AISO_CAP), AISO_CAP)
