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

from bearingcalc.core.common import MM, NEWTON, table_lookup

RADIAL_ROLLER_TYPES = ("cylindrical-roller", "needle-roller", "tapered-roller",
                       "spherical-roller")
THRUST_ROLLER_TYPES = ("thrust-cylindrical-roller", "thrust-spherical-roller",
                       "thrust-tapered-roller")
#: Roller bearings whose line contact has no contact angle: ISO 281's P is Fr alone.
STRAIGHT_ROLLER_TYPES = ("cylindrical-roller", "needle-roller")

#: ISO 281:2007 Table 1: bm, the rating factor for contemporary, normally used material.
MATERIAL_FACTOR = {
    "cylindrical-roller": 1.1, "needle-roller": 1.1, "tapered-roller": 1.1,
    "spherical-roller": 1.15, "thrust-cylindrical-roller": 1.0,
    "thrust-tapered-roller": 1.1, "thrust-spherical-roller": 1.15,
}

#: ISO 281:2007 Table 7: fc of radial roller bearings against γ = Dwe·cosα/Dpw.
RADIAL_FC_GAMMA = np.array([0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.10,
                            0.12, 0.14, 0.16, 0.18, 0.20, 0.22, 0.24, 0.26, 0.28, 0.30])
RADIAL_FC = np.array([52.1, 60.8, 66.5, 70.7, 74.1, 76.9, 79.2, 81.2, 82.8, 84.2,
                      86.4, 87.7, 88.5, 88.8, 88.7, 88.2, 87.5, 86.4, 85.2, 83.8])
#: ISO 281:2007's table of fc for thrust roller bearings, α = 90°, against γ = Dwe/Dpw;
#: None while no two sources of it agree (the ratings then come from the catalogue).
THRUST_FC_GAMMA: NDArray | None = None
THRUST_FC: NDArray | None = None

#: ISO 281's limit of Fa/Fr between the two sets of X and Y is e = 1.5·tanα.
E_PER_TAN_ALPHA = 1.5


def roller_dynamic_load_rating(roller_count: ArrayLike, roller_diameter: ArrayLike,
                               roller_length: ArrayLike, pitch_diameter: ArrayLike,
                               contact_angle: ArrayLike, rows: ArrayLike = 1, *,
                               bearing_type: str) -> tuple[NDArray, NDArray]:
    r"""Basic dynamic load rating C of a roller bearing, and its fc.

    .. math:: C_r = b_m f_c (i L_{we} \cos\alpha)^{7/9} Z^{3/4} D_{we}^{29/27}

    for radial roller bearings, with fc from Table 7 at γ = Dwe·cosα/Dpw; thrust roller
    bearings:

    .. math:: C_a = b_m f_c (L_{we}\cos\alpha)^{7/9} \tan\alpha\, Z^{3/4} D_{we}^{29/27}
              \ (\alpha \ne 90°), \qquad b_m f_c L_{we}^{7/9} Z^{3/4} D_{we}^{29/27}
              \ (\alpha = 90°)

    with C in N and lengths in mm, bm from Table 1.

    Parameters
    ----------
    roller_count : Z, per row. [1]
    roller_diameter : Dwe, the mean diameter of a tapered roller. [m]
    roller_length : Lwe, the effective contact length. [m]
    pitch_diameter : Dpw. [m]
    contact_angle : α. [rad]
    rows : i (radial bearings). [1]
    bearing_type : one of :data:`RADIAL_ROLLER_TYPES` or :data:`THRUST_ROLLER_TYPES`.

    Returns
    -------
    (C [N], fc [1]); NaN where γ is outside the table (thrust bearings: always, while
    the thrust table is not entered).

    Source: ISO 281:2007, 7.1 and 8.1 (Table 1, bm; Table 7, fc).

    >>> c, fc = roller_dynamic_load_rating(14, 11e-3, 11e-3, 64e-3, 0.0,
    ...                                    bearing_type="cylindrical-roller")
    >>> round(float(fc), 3), round(float(c))
    (88.678, 59884)
    """
    z = np.asarray(roller_count, dtype=float)
    dwe = np.asarray(roller_diameter, dtype=float) * MM
    lwe = np.asarray(roller_length, dtype=float) * MM
    dpw = np.asarray(pitch_diameter, dtype=float) * MM
    alpha = np.asarray(contact_angle, dtype=float)
    bm = MATERIAL_FACTOR[bearing_type]
    cos_alpha = np.cos(alpha)
    common = z ** 0.75 * dwe ** (29.0 / 27.0)
    if bearing_type in RADIAL_ROLLER_TYPES:
        fc = table_lookup(dwe * cos_alpha / dpw, RADIAL_FC_GAMMA, RADIAL_FC)
        rating = bm * fc * (np.asarray(rows, dtype=float) * lwe * cos_alpha) ** (7.0 / 9.0)
        return rating * common * NEWTON, fc
    right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    gamma = np.where(right, dwe, dwe * cos_alpha) / dpw
    if THRUST_FC is None or THRUST_FC_GAMMA is None:
        fc = np.full(np.shape(gamma), np.nan)
    else:
        fc = table_lookup(gamma, THRUST_FC_GAMMA, THRUST_FC)
    length = np.where(right, lwe ** (7.0 / 9.0),
                      (lwe * cos_alpha) ** (7.0 / 9.0) * np.tan(alpha))
    return bm * fc * length * common * NEWTON, fc


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
    if bearing_type in STRAIGHT_ROLLER_TYPES:
        ones = np.ones(np.broadcast_shapes(fr.shape, fa.shape))
        return RollerLoad(fr * ones, ones, 0.0 * ones, np.nan * ones, ones == 0)
    tan_alpha = np.tan(alpha)
    limit = E_PER_TAN_ALPHA * tan_alpha if e is None else np.asarray(e, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        combined = (fa > 0) & ~(fa / fr <= limit)
    if bearing_type in THRUST_ROLLER_TYPES:
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

    with C0 in N and lengths in mm.

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
        * z * lwe * dwe * NEWTON


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
    if bearing_type in THRUST_ROLLER_TYPES:
        right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
        return np.where(right, 0.0, 2.3 * np.tan(alpha)) * fr + fa
    if bearing_type in STRAIGHT_ROLLER_TYPES:
        return fr + 0.0 * fa
    cot_alpha = 1.0 / np.tan(alpha)
    double = np.asarray(double_row, dtype=bool)
    x0_used = np.where(double, 1.0, 0.5) if x0 is None else np.asarray(x0, dtype=float)
    y0_used = (np.where(double, 0.44, 0.22) * cot_alpha if y0 is None
               else np.asarray(y0, dtype=float))
    return np.maximum(fr, x0_used * fr + y0_used * fa)
