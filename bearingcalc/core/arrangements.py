"""Bearing arrangements: matched pairs rated as one bearing, and two single-row angular
bearings adjusted against each other with the axial forces a radial load induces in them.

Every function takes SI values as floats or numpy arrays, which broadcast, and returns
arrays. See ``docs/physics.md`` §5 (pairs) and §9 (adjusted arrangements).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.common import Family, table_lookup

#: Matched pairs of single-row angular-contact ball or tapered roller bearings.
PAIRS = ("back-to-back", "face-to-face", "tandem")
#: Pairs rated and loaded as one double-row bearing (tandem pairs keep the single-row
#: factors).
DOUBLE_ROW_PAIRS = ("back-to-back", "face-to-face")
#: The exponent of the number of bearings in a pair's C: i^0.7 (ball), i^(7/9) (roller).
PAIR_RATING_EXPONENT = {"ball": 0.7, "roller": 7.0 / 9.0}

#: ISO 281:2007 Table 3, double-row angular-contact ball bearings: α -> (Y for
#: Fa/Fr <= e with X = 1, X and Y above e, e).
DOUBLE_ANGULAR_ALPHA_DEG = np.array([20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
DOUBLE_ANGULAR_Y1 = np.array([1.09, 0.92, 0.78, 0.66, 0.55, 0.47])
DOUBLE_ANGULAR_X2 = np.array([0.70, 0.67, 0.63, 0.60, 0.57, 0.54])
DOUBLE_ANGULAR_Y2 = np.array([1.63, 1.41, 1.24, 1.07, 0.93, 0.81])
DOUBLE_ANGULAR_E = np.array([0.57, 0.68, 0.80, 0.95, 1.14, 1.34])
#: ISO 76:2006 double-row angular-contact ball bearings: X0 = 1, Y0 against α (twice
#: the single row's).
DOUBLE_ANGULAR_Y0 = np.array([0.84, 0.76, 0.66, 0.58, 0.52, 0.44])

#: Induced axial force of an angular-contact ball bearing adjusted to zero clearance,
#: F = R·Fr, with R against α, as bearing makers' catalogues tabulate it (linear between).
INDUCED_BALL_ALPHA_DEG = np.array([20.0, 25.0, 30.0, 40.0])
INDUCED_BALL_FACTOR = np.array([0.50, 0.57, 0.66, 0.88])
#: Induced axial force of a tapered roller bearing: F = 0.5·Fr/Y.
INDUCED_TAPERED_NUMERATOR = 0.5


def pair_ratings(dynamic_load_rating: ArrayLike, static_load_rating: ArrayLike | None,
                 family: Family) -> tuple[NDArray, NDArray | None]:
    r"""C and C0 of a matched pair of two similar single-row bearings.

    .. math:: C_{pair} = 2^{0.7} C \ (\text{ball}), \quad 2^{7/9} C \ (\text{roller}),
              \qquad C_{0,pair} = 2 C_0

    Source: ISO 281:2007, 5.1 and 7.1 (bearing combinations); ISO 76:2006 (bearing
    combinations).
    """
    c = np.asarray(dynamic_load_rating, dtype=float) * 2.0 ** PAIR_RATING_EXPONENT[family]
    c0 = None if static_load_rating is None else 2.0 * np.asarray(static_load_rating,
                                                                  dtype=float)
    return c, c0


def pair_ratings_used(arrangement: str, dynamic_load_rating: ArrayLike,
                      static_load_rating: ArrayLike | None, family: Family
                      ) -> tuple[ArrayLike, ArrayLike | None, dict[str, ArrayLike]]:
    """The C and C0 a bearing's life and static safety use: a pair's, else the bearing's
    own; and the results that report a pair's (``pair_dynamic_load_rating`` and
    ``pair_static_load_rating``)."""
    if arrangement not in PAIRS:
        return dynamic_load_rating, static_load_rating, {}
    c, c0 = pair_ratings(dynamic_load_rating, static_load_rating, family)
    reported = {"pair_dynamic_load_rating": c}
    if c0 is not None:
        reported["pair_static_load_rating"] = c0
    return c, c0, reported


class DoubleRowFactors(NamedTuple):
    """ISO 281's X and Y of a double-row angular-contact ball bearing, and ISO 76's Y0."""

    y_below: NDArray   # Y for Fa/Fr <= e (X = 1) [1]
    x_above: NDArray   # X for Fa/Fr > e [1]
    y_above: NDArray   # Y for Fa/Fr > e [1]
    e: NDArray         # [1]
    y0: NDArray        # Y0 (X0 = 1) [1]


def double_row_ball_factors(contact_angle: ArrayLike) -> DoubleRowFactors:
    """X, Y, e and Y0 of a double-row angular-contact ball bearing (or a back-to-back or
    face-to-face pair), interpolated in α from 20° to 45°; NaN outside.

    Source: ISO 281:2007, Table 3 (double row); ISO 76:2006, Table 2.
    """
    degrees = np.degrees(np.asarray(contact_angle, dtype=float))
    return DoubleRowFactors(*(table_lookup(degrees, DOUBLE_ANGULAR_ALPHA_DEG, table)
                              for table in (DOUBLE_ANGULAR_Y1, DOUBLE_ANGULAR_X2,
                                            DOUBLE_ANGULAR_Y2, DOUBLE_ANGULAR_E,
                                            DOUBLE_ANGULAR_Y0)))


def induced_axial_factor_ball(contact_angle: ArrayLike) -> NDArray:
    """R of an angular-contact ball bearing adjusted against another to zero clearance,
    F = R·Fr: 0.50 at 20°, 0.57 at 25°, 0.66 at 30°, 0.88 at 40°, linear between; NaN
    outside 20° to 40°.

    Source: bearing makers' catalogues (SKF, *Rolling bearings*, 2018, "Determining the
    axial load for bearings mounted singly or paired in tandem", factor R).
    """
    return table_lookup(np.degrees(np.asarray(contact_angle, dtype=float)),
                        INDUCED_BALL_ALPHA_DEG, INDUCED_BALL_FACTOR)


def induced_axial_factor_tapered(axial_factor: ArrayLike) -> NDArray:
    """R = 0.5/Y of a tapered roller bearing, Y its axial factor above e.

    Source: ISO 281:2007 background; the load cases of bearing makers' catalogues (SKF,
    *Rolling bearings*, 2018, "Tapered roller bearings: axial load").
    """
    return INDUCED_TAPERED_NUMERATOR / np.asarray(axial_factor, dtype=float)


class AdjustedLoads(NamedTuple):
    """The axial loads of two bearings adjusted against each other."""

    first: NDArray    # Fa of bearing A (the first of the shaft) [N]
    second: NDArray   # Fa of bearing B [N]
    case: NDArray     # the load case, 1 to 6 (1a, 1b, 1c, 2a, 2b, 2c) [1]


def adjusted_axial_loads(radial_first: ArrayLike, radial_second: ArrayLike,
                         factor_first: ArrayLike, factor_second: ArrayLike,
                         external: ArrayLike, second_takes_external: ArrayLike
                         ) -> AdjustedLoads:
    r"""Axial loads of bearings A and B, adjusted against each other to practically zero
    clearance, under radial loads FrA, FrB and an external axial force Ka.

    Each bearing's radial load induces F = R·Fr. With Ka acting in the direction B
    supports (cases 1; cases 2 swap A and B):

    .. math:: R_A F_{rA} + K_a \ge R_B F_{rB}: \quad F_{aA} = R_A F_{rA},\
              F_{aB} = F_{aA} + K_a; \qquad \text{else}\ F_{aB} = R_B F_{rB},\
              F_{aA} = F_{aB} - K_a

    Case a: R_A·FrA >= R_B·FrB; b: below that but the first branch; c: the second.

    Parameters
    ----------
    radial_first, radial_second : FrA, FrB. [N]
    factor_first, factor_second : R_A, R_B. [1]
    external : |Ka|, the size of the external axial force. [N]
    second_takes_external : where Ka acts in the direction bearing B supports.

    Returns
    -------
    :class:`AdjustedLoads`.

    Source: the load cases of bearing makers' catalogues (SKF, *Rolling bearings*, 2018,
    tables "Axial loading of paired single row angular contact ball bearings" and of
    tapered roller bearings; Timken, *Engineering Manual*, "Axial load calculation").
    """
    induced_a = np.asarray(factor_first, dtype=float) * np.asarray(radial_first, dtype=float)
    induced_b = np.asarray(factor_second, dtype=float) * np.asarray(radial_second, dtype=float)
    ka = np.abs(np.asarray(external, dtype=float))
    to_b = np.asarray(second_takes_external, dtype=bool)
    # Name the bearings by the roles of the table: "taking" is the one Ka pushes into.
    other = np.where(to_b, induced_a, induced_b)
    taking = np.where(to_b, induced_b, induced_a)
    first_branch = other + ka >= taking
    other_load = np.where(first_branch, other, taking - ka)
    taking_load = np.where(first_branch, other + ka, taking)
    letter = np.where(other >= taking, 0, np.where(first_branch, 1, 2))
    case = np.where(to_b, 1, 4) + letter
    return AdjustedLoads(np.where(to_b, other_load, taking_load),
                         np.where(to_b, taking_load, other_load), case.astype(float))


def supports_positive(position: ArrayLike, partner_position: ArrayLike,
                      arrangement: str) -> NDArray:
    """Whether a bearing of an adjusted pair carries the shaft's axial force in +x.

    Back-to-back: the pressure centres lie apart, outside the pair, and each bearing's
    contact line runs from its pressure centre on the axis inward to the outer ring: the
    bearing nearer −x carries forces toward +x. Face-to-face is the mirror image.
    """
    nearer_negative = np.asarray(position, dtype=float) < np.asarray(partner_position,
                                                                     dtype=float)
    return nearer_negative if arrangement == "back-to-back" else ~nearer_negative
