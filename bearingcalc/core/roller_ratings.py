"""ISO 281:2007 and ISO 76:2006 for roller bearings: the load ratings C and C0 from the
geometry, and the equivalent loads P and P0.

Radial roller bearings (cylindrical, needle, tapered, spherical; α <= 45°) and thrust
roller bearings (α > 45°). Every function takes SI values as floats or numpy arrays,
which broadcast, and returns arrays; the standards' formulas are written in their own
units (N, mm) inside. See ``docs/physics.md`` §5 for the relations and their sources.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.bearing_types import (
    DRAWN_CUP_MATERIAL_FACTOR,
    LoadRule,
    RatingFormula,
    traits,
)
from bearingcalc.core.common import MM, NEWTON, table_lookup

#: ISO 281:2007 Table 7: fc of radial roller bearings against γ = Dwe·cosα/Dpw, at every
#: hundredth from 0.01 to 0.30 as the standard prints it (linear between rows).
RADIAL_FC_GAMMA = np.round(np.arange(1, 31) * 0.01, 2)
RADIAL_FC = np.array([52.1, 60.8, 66.5, 70.7, 74.1, 76.9, 79.2, 81.2, 82.8, 84.2,
                      85.4, 86.4, 87.1, 87.7, 88.2, 88.5, 88.7, 88.8, 88.8, 88.7,
                      88.5, 88.2, 87.9, 87.5, 87.0, 86.4, 85.8, 85.2, 84.5, 83.8])
#: ISO 281:2007 Table 10: fc of thrust roller bearings. At α = 90° against
#: γ = Dwe/Dpw, 0.01 to 0.30; below 90° against γ = Dwe·cosα/Dpw in three columns, for
#: 45° < α < 60° (to 0.26), 60° <= α < 75° (to 0.20) and 75° <= α < 90° (to 0.15).
THRUST_FC_GAMMA = np.round(np.arange(1, 31) * 0.01, 2)
THRUST_FC = np.array([105.4, 122.9, 134.5, 143.4, 150.7, 156.9, 162.4, 167.2, 171.7, 175.7,
                      179.5, 183.0, 186.3, 189.4, 192.3, 195.1, 197.7, 200.3, 202.7, 205.0,
                      207.2, 209.4, 211.5, 213.5, 215.4, 217.3, 219.1, 220.9, 222.7, 224.3])
#: The columns below 90°: (the smallest α of the column [rad], fc from γ = 0.01 on).
THRUST_FC_ANGLED = (
    (np.radians(45.0), np.array([
        109.7, 127.8, 139.5, 148.3, 155.2, 160.9, 165.6, 169.5, 172.8, 175.5, 177.8, 179.7,
        181.1, 182.3, 183.1, 183.7, 184.0, 184.1, 184.0, 183.7, 183.2, 182.6, 181.8, 180.9,
        179.8, 178.7])),
    (np.radians(60.0), np.array([
        107.1, 124.7, 136.2, 144.7, 151.5, 157.0, 161.6, 165.5, 168.7, 171.4, 173.6, 175.4,
        176.8, 177.9, 178.8, 179.3, 179.6, 179.7, 179.6, 179.3])),
    (np.radians(75.0), np.array([
        105.6, 123.0, 134.3, 142.8, 149.4, 154.9, 159.4, 163.2, 166.4, 169.0, 171.2, 173.0,
        174.4, 175.5, 176.3])),
)

#: ISO 281's limit of Fa/Fr between the two sets of X and Y is e = 1.5·tanα.
E_PER_TAN_ALPHA = 1.5


def roller_dynamic_load_rating(roller_count: ArrayLike, roller_diameter: ArrayLike,
                               roller_length: ArrayLike, pitch_diameter: ArrayLike,
                               contact_angle: ArrayLike, rows: ArrayLike = 1, *,
                               bearing_type: str, drawn_cup: ArrayLike = False
                               ) -> tuple[NDArray, NDArray]:
    r"""Basic dynamic load rating C of a roller bearing, and its fc.

    .. math:: C_r = b_m f_c (i L_{we} \cos\alpha)^{7/9} Z^{3/4} D_{we}^{29/27}

    for radial roller bearings, with fc from Table 7 at γ = Dwe·cosα/Dpw; thrust roller
    bearings:

    .. math:: C_a = b_m f_c (L_{we}\cos\alpha)^{7/9} \tan\alpha\, Z^{3/4} D_{we}^{29/27}
              \ (\alpha \ne 90°), \qquad b_m f_c L_{we}^{7/9} Z^{3/4} D_{we}^{29/27}
              \ (\alpha = 90°)

    with fc from Table 10 (:func:`thrust_rating_factor`), C in N and lengths in mm, bm
    from Table 1. A thrust bearing of i equal rows of Z rollers (each row's own raceway
    contact) is rated by ISO 281's rule for rows,
    Ca = (Σ Zk·Lwek)·[Σ (Zk·Lwek/Cak)^(9/2)]^(−2/9), which for equal rows is
    i^(7/9)·Ca1: Lwe becomes i·Lwe in the formula, as i·Lwe in the radial one.

    Parameters
    ----------
    roller_count : Z, per row. [1]
    roller_diameter : Dwe, the mean diameter of a tapered roller. [m]
    roller_length : Lwe, the effective contact length. [m]
    pitch_diameter : Dpw. [m]
    contact_angle : α. [rad]
    rows : i, the rows of rollers (of a thrust bearing: loaded in one direction). [1]
    bearing_type : a roller bearing's type (:mod:`bearingcalc.core.bearing_types`).
    drawn_cup : a drawn-cup needle roller bearing, bm = 1.0 (Table 1). [bool]

    Returns
    -------
    (C [N], fc [1]); NaN where γ is outside the table.

    Source: ISO 281:2007, 7.1 and 8.1 (Table 1, bm; Table 7 and Table 10, fc; 8.1.2,
    rows).

    >>> c, fc = roller_dynamic_load_rating(14, 11e-3, 11e-3, 64e-3, 0.0,
    ...                                    bearing_type="cylindrical-roller")
    >>> round(float(fc), 3), round(float(c))
    (88.719, 59911)
    """
    z = np.asarray(roller_count, dtype=float)
    dwe = np.asarray(roller_diameter, dtype=float) * MM
    lwe = np.asarray(roller_length, dtype=float) * MM
    dpw = np.asarray(pitch_diameter, dtype=float) * MM
    alpha = np.asarray(contact_angle, dtype=float)
    kind = traits(bearing_type)
    bm = np.where(np.asarray(drawn_cup, dtype=bool) & kind.drawn_cup,
                  DRAWN_CUP_MATERIAL_FACTOR, kind.material_factor)
    cos_alpha = np.cos(alpha)
    common = z ** 0.75 * dwe ** (29.0 / 27.0)
    if kind.rating_formula is RatingFormula.RADIAL_ROLLER:
        fc = table_lookup(dwe * cos_alpha / dpw, RADIAL_FC_GAMMA, RADIAL_FC)
        rating = bm * fc * (np.asarray(rows, dtype=float) * lwe * cos_alpha) ** (7.0 / 9.0)
        return rating * common * NEWTON, fc
    right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    fc = thrust_rating_factor(np.where(right, dwe, dwe * cos_alpha) / dpw, alpha)
    # i equal rows of Z rollers each: ISO 281's rule for rows, Ca = i^(7/9)·Ca1
    length = np.where(right, 1.0, cos_alpha ** (7.0 / 9.0) * np.tan(alpha)) * (
        np.asarray(rows, dtype=float) * lwe) ** (7.0 / 9.0)
    return bm * fc * length * common * NEWTON, fc


def thrust_rating_factor(gamma: ArrayLike, contact_angle: ArrayLike) -> NDArray:
    r"""fc of a thrust roller bearing, ISO 281:2007 Table 10, linear between its rows.

    At α = 90° the column of γ = Dwe/Dpw (0.01 to 0.30); below, against
    γ = Dwe·cosα/Dpw, the column of 45° < α < 60° (to 0.26), of 60° <= α < 75° (to 0.20)
    or of 75° <= α < 90° (to 0.15).

    Parameters
    ----------
    gamma : γ, as above for each α. [1]
    contact_angle : α, above 45° to 90°. [rad]

    Returns
    -------
    fc [1]; NaN outside the column.

    Source: ISO 281:2007, 8.1.1, Table 10 (GOST 18855-2013, Table 10).
    """
    gamma = np.asarray(gamma, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    fc = np.full(np.broadcast_shapes(gamma.shape, alpha.shape), np.nan)
    for lowest, column in THRUST_FC_ANGLED:  # from the lowest column up
        in_column = alpha > lowest + 1e-12 if lowest <= np.pi / 4 + 1e-12 else (
            alpha >= lowest - 1e-12)
        fc = np.where(in_column, table_lookup(gamma, THRUST_FC_GAMMA[:column.size], column),
                      fc)
    right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    return np.where(right, table_lookup(gamma, THRUST_FC_GAMMA, THRUST_FC), fc)


class RollerLoad(NamedTuple):
    """The equivalent dynamic load of a roller bearing and the factors applied."""

    load: NDArray    # P [N]
    x: NDArray       # X applied [1]
    y: NDArray       # Y applied [1]
    e: NDArray       # e [1]; NaN for straight rollers (no contact angle)
    combined: NDArray  # where Fa/Fr > e


def roller_equivalent_dynamic_load(radial_load: ArrayLike, axial_load: ArrayLike,
                                   contact_angle: ArrayLike, *, bearing_type: str,
                                   double_row: ArrayLike, e: ArrayLike | None = None,
                                   y: ArrayLike | None = None, y1: ArrayLike | None = None,
                                   y2: ArrayLike | None = None, x: ArrayLike | None = None
                                   ) -> RollerLoad:
    r"""Equivalent dynamic load P of a roller bearing.

    Radial roller bearings with α = 0 (cylindrical, needle): P = Fr (an axial load is
    carried by the ribs, outside ISO 281). With α > 0 and e = 1.5·tanα:

    .. math:: P = X F_r + Y F_a

    single row: X = 1, Y = 0 for Fa/Fr <= e; X = 0.4, Y = 0.4·cotα above. Double row (or a
    pair as one double-row bearing): X = 1, Y = 0.45·cotα; above e, X = 0.67,
    Y = 0.67·cotα. Catalogue e, Y (single row, the Y above e) or Y1, Y2 (double row)
    replace the standard's. Thrust roller bearings: P = Fa at α = 90°, else
    P = tanα·Fr + Fa, valid for Fa/Fr > e only (the caller refuses the rest).

    Parameters
    ----------
    radial_load, axial_load : Fr, Fa. [N]
    contact_angle : α. [rad]
    bearing_type : the roller bearing's type.
    double_row : where the bearing has two rows (or is a back-to-back or face-to-face
        pair).
    e, y, y1, y2, x : the catalogue's factors, or None. [1]

    Returns
    -------
    :class:`RollerLoad`.

    Source: ISO 281:2007, 7.2 and 8.2 (their tables of X and Y).
    """
    fr = np.asarray(radial_load, dtype=float)
    fa = np.asarray(axial_load, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    if traits(bearing_type).load_rule is LoadRule.RADIAL_ONLY:
        ones = np.ones(np.broadcast_shapes(fr.shape, fa.shape))
        return RollerLoad(fr * ones, ones, 0.0 * ones, np.nan * ones, ones == 0)
    tan_alpha = np.tan(alpha)
    limit = E_PER_TAN_ALPHA * tan_alpha if e is None else np.asarray(e, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        combined = (fa > 0) & ~(fa / fr <= limit)
    if traits(bearing_type).thrust:
        right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
        x_applied = np.where(right, 0.0, tan_alpha)
        load = x_applied * fr + fa
        return RollerLoad(load, x_applied + 0.0 * fa, np.ones_like(load), limit + 0.0 * load,
                          combined)
    cot_alpha = 1.0 / tan_alpha
    double = np.asarray(double_row, dtype=bool)
    double_below = 0.45 * cot_alpha if y1 is None else np.asarray(y1, dtype=float)
    double_above = 0.67 * cot_alpha if y2 is None else np.asarray(y2, dtype=float)
    single_above = 0.4 * cot_alpha if y is None else np.asarray(y, dtype=float)
    x_single = 0.4 if x is None else np.asarray(x, dtype=float)
    x_double = 0.67 if x is None else np.asarray(x, dtype=float)
    x_applied = np.where(combined, np.where(double, x_double, x_single), 1.0)
    y_applied = np.where(combined, np.where(double, double_above, single_above),
                         np.where(double, double_below, 0.0))
    load = x_applied * fr + y_applied * fa
    return RollerLoad(load, x_applied, y_applied, limit + 0.0 * load, combined)


def roller_static_load_rating(roller_count: ArrayLike, roller_diameter: ArrayLike,
                              roller_length: ArrayLike, pitch_diameter: ArrayLike,
                              contact_angle: ArrayLike, rows: ArrayLike = 1, *,
                              thrust: bool) -> NDArray:
    r"""Basic static load rating C0 of a roller bearing.

    .. math:: C_{0r} = 44\left(1 - \frac{D_{we}\cos\alpha}{D_{pw}}\right)
              i Z L_{we} D_{we} \cos\alpha

    for radial roller bearings; thrust roller bearings:

    .. math:: C_{0a} = 220\left(1 - \frac{D_{we}\cos\alpha}{D_{pw}}\right)
              Z L_{we} D_{we} \sin\alpha \ (\alpha \ne 90°), \qquad 220 Z L_{we} D_{we}
              \ (\alpha = 90°)

    with C0 in N and lengths in mm; a thrust bearing of i equal rows has i·Z rollers
    (ISO 76 sums Zk·Lwek over the rows loaded in one direction).

    Parameters
    ----------
    roller_count, roller_diameter, roller_length, pitch_diameter, contact_angle, rows :
        Z [1], Dwe, Lwe, Dpw [m], α [rad], i [1].
    thrust : a thrust roller bearing.

    Returns
    -------
    C0. [N]

    Source: ISO 76:2006, the static load ratings of radial and thrust roller bearings.

    >>> round(float(roller_static_load_rating(14, 11e-3, 11e-3, 64e-3, 0.0,
    ...                                       thrust=False)))
    61725
    """
    z = np.asarray(roller_count, dtype=float)
    dwe = np.asarray(roller_diameter, dtype=float) * MM
    lwe = np.asarray(roller_length, dtype=float) * MM
    dpw = np.asarray(pitch_diameter, dtype=float) * MM
    alpha = np.asarray(contact_angle, dtype=float)
    cos_alpha = np.cos(alpha)
    if not thrust:
        return (44.0 * (1.0 - dwe * cos_alpha / dpw) * np.asarray(rows, dtype=float) * z
                * lwe * dwe * cos_alpha * NEWTON)
    right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    return 220.0 * np.where(right, 1.0, (1.0 - dwe * cos_alpha / dpw) * np.sin(alpha)) \
        * np.asarray(rows, dtype=float) * z * lwe * dwe * NEWTON


def roller_static_equivalent_load(radial_load: ArrayLike, axial_load: ArrayLike,
                                  contact_angle: ArrayLike, *, bearing_type: str,
                                  double_row: ArrayLike, x0: ArrayLike | None = None,
                                  y0: ArrayLike | None = None) -> NDArray:
    r"""Static equivalent load P0 of a roller bearing.

    Radial, α = 0: P0 = Fr. Radial, α > 0: single row P0 = max(Fr, X0·Fr + Y0·Fa) with
    X0 = 0.5, Y0 = 0.22·cotα; double row (or a back-to-back or face-to-face pair)
    P0 = Fr + 0.44·cotα·Fa. Catalogue X0, Y0 replace the standard's. Thrust:

    .. math:: P_{0a} = 2.3 F_r \tan\alpha + F_a \ (\alpha \ne 90°), \qquad F_a
              \ (\alpha = 90°)

    Parameters
    ----------
    radial_load, axial_load : Fr, Fa. [N]
    contact_angle : α. [rad]
    bearing_type : the roller bearing's type.
    double_row : where the bearing has two rows, or is a back-to-back or face-to-face
        pair.
    x0, y0 : the catalogue's static factors, or None. [1]

    Returns
    -------
    P0. [N]

    Source: ISO 76:2006, the static equivalent loads of radial and thrust roller
    bearings.
    """
    fr = np.asarray(radial_load, dtype=float)
    fa = np.asarray(axial_load, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    if traits(bearing_type).thrust:
        right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
        return np.where(right, 0.0, 2.3 * np.tan(alpha)) * fr + fa
    if traits(bearing_type).load_rule is LoadRule.RADIAL_ONLY:
        return fr + 0.0 * fa
    cot_alpha = 1.0 / np.tan(alpha)
    double = np.asarray(double_row, dtype=bool)
    x0_used = np.where(double, 1.0, 0.5) if x0 is None else np.asarray(x0, dtype=float)
    y0_used = (np.where(double, 0.44, 0.22) * cot_alpha if y0 is None
               else np.asarray(y0, dtype=float))
    return np.maximum(fr, x0_used * fr + y0_used * fa)
