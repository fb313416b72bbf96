"""ISO 76:2006, static load ratings of rolling bearings.

The static load rating C0 with its factor f0, the static equivalent load P0 and the
static safety factor s0. Every function takes SI values as floats or numpy arrays, which
broadcast, and returns arrays; the formulas are written in the standard's own units (N,
mm) inside. See ``docs/physics.md`` §5.

The standard gives ball and roller bearings formulas of their own. Functions whose
formula depends on the rolling elements take a ``family``; only "ball" is implemented.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.bearing_types import LoadRule, traits
from bearingcalc.core.common import MM, NEWTON, Family, ball_family_only, table_lookup

#: ISO 76:2006 Table 1: f0 of radial and angular-contact groove ball bearings against
#: γ = Dw·cosα/Dpw.
STATIC_F0_GAMMA = np.round(np.arange(0, 41) * 0.01, 2)
STATIC_F0 = np.array([14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5,
                      16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2,
                      14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
                      11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4])
#: ISO 76:2006 static factors of single-row deep-groove ball bearings.
DEEP_GROOVE_X0, DEEP_GROOVE_Y0 = 0.6, 0.5
#: ISO 76:2006 static factors of single-row angular-contact ball bearings: X0, and Y0
#: against α.
ANGULAR_X0 = 0.5
ANGULAR_ALPHA_DEG = np.array([20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
ANGULAR_Y0 = np.array([0.42, 0.38, 0.33, 0.29, 0.26, 0.22])


def static_load_rating(ball_count: ArrayLike, ball_diameter: ArrayLike,
                       pitch_diameter: ArrayLike, contact_angle: ArrayLike, *,
                       family: Family = "ball") -> tuple[NDArray, NDArray]:
    r"""Basic static load rating C0 of a radial ball bearing, and its f0.

    .. math:: C_0 = f_0 Z D_w^2 \cos\alpha

    with C0 in N and Dw in mm, f0 from Table 1 at γ = Dw·cosα/Dpw.

    Parameters
    ----------
    ball_count : Z. [1]
    ball_diameter, pitch_diameter : Dw, Dpw. [m]
    contact_angle : α. [rad]
    family : the rolling elements; "ball" only (radial roller bearings:
        C0 = 44·(1 − Dwe·cosα/Dpw)·i·Z·Lwe·Dwe·cosα).

    Returns
    -------
    (C0 [N], f0 [1]); NaN where γ is outside the table.

    Source: ISO 76:2006, 6.1.1 (eq. 1, Table 1).

    >>> c0, f0 = static_load_rating(9, 7.938e-3, 38.5e-3, 0.0)
    >>> round(float(f0), 3), round(float(c0))
    (13.815, 7834)
    """
    ball_family_only(family, "ISO 76's static load rating C0")
    z = np.asarray(ball_count, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float) * MM
    dpw = np.asarray(pitch_diameter, dtype=float) * MM
    cos_alpha = np.cos(np.asarray(contact_angle, dtype=float))
    f0 = table_lookup(dw * cos_alpha / dpw, STATIC_F0_GAMMA, STATIC_F0)
    return f0 * z * dw ** 2 * cos_alpha * NEWTON, f0


def static_equivalent_load(radial_load: ArrayLike, axial_load: ArrayLike, bearing_type: str,
                           contact_angle: ArrayLike, *, radial_factor: ArrayLike | None = None,
                           axial_factor: ArrayLike | None = None,
                           family: Family = "ball") -> NDArray:
    r"""Static equivalent load P0 of a ball bearing.

    .. math:: P_0 = \max(F_r,\ X_0 F_r + Y_0 F_a)

    with X0 = 0.6, Y0 = 0.5 for deep-groove bearings and X0 = 0.5, Y0 from 0.42 (20°) to
    0.22 (45°) for angular-contact bearings (NaN outside that range); thrust bearings
    (α = 90°) take P0 = Fa.

    Parameters
    ----------
    radial_load, axial_load : Fr, Fa. [N]
    bearing_type : a ball bearing's type (:mod:`bearingcalc.core.bearing_types`).
    contact_angle : α. [rad]
    radial_factor, axial_factor : the catalogue's X0 and Y0 of an angular-contact bearing,
        which replace the standard's. [1]
    family : the rolling elements; "ball" only.

    Returns
    -------
    P0. [N]

    Source: ISO 76:2006, 5.2; docs/physics.md §5.
    """
    ball_family_only(family, "ISO 76's static equivalent load P0")
    fr = np.asarray(radial_load, dtype=float)
    fa = np.asarray(axial_load, dtype=float)
    rule = traits(bearing_type).load_rule
    if rule is LoadRule.AXIAL_ONLY:
        return fa
    if rule is LoadRule.ANGLE_TABLE:
        y0 = (np.asarray(axial_factor, dtype=float) if axial_factor is not None
              else table_lookup(np.degrees(np.asarray(contact_angle, dtype=float)),
                                ANGULAR_ALPHA_DEG, ANGULAR_Y0))
        x0 = (np.asarray(radial_factor, dtype=float) if radial_factor is not None
              else ANGULAR_X0)
        return np.maximum(fr, x0 * fr + y0 * fa)
    return np.maximum(fr, DEEP_GROOVE_X0 * fr + DEEP_GROOVE_Y0 * fa)


def static_safety_factor(static_load_rating: ArrayLike, static_equivalent_load: ArrayLike
                         ) -> NDArray:
    r"""Static safety factor s0 of a bearing, ball or roller.

    .. math:: s_0 = \frac{C_0}{P_0}

    Parameters
    ----------
    static_load_rating, static_equivalent_load : C0, P0. [N]

    Returns
    -------
    s0. [1]

    Source: ISO 76:2006; docs/physics.md §5.
    """
    return np.asarray(static_load_rating, dtype=float) / np.asarray(static_equivalent_load,
                                                                    dtype=float)
