"""AGMA 2003's allowable stress numbers of bevel-gear steels, its temperature and
hardness-ratio factors, and the rating terms a pair's steels set (``docs/physics.md``
§8).

Every function takes SI values as floats or numpy arrays and returns arrays.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Heat treatments with their grades whose allowable stress numbers are fixed:
#: (material, grade) -> (s_at, s_ac) [MPa], the SI table of AGMA 2003 as Budynas &
#: Nisbett print it (Tables 15-4 and 15-6).
FIXED_ALLOWABLES: dict[tuple[str, int], tuple[float, float]] = {
    ("carburized", 1): (205.0, 1380.0),
    ("carburized", 2): (240.0, 1550.0),
    ("carburized", 3): (275.0, 1720.0),
    ("nitrided", 2): (150.0, 1000.0),            # AISI 4140, 84.5 HR15N
    ("flame-or-induction-hardened", 1): (154.0, 1210.0),  # hardened roots, 50 HRC
}
#: Through-hardened steel: grade -> (s_at slope, intercept; s_ac slope, intercept), MPa
#: against Brinell hardness (Figures 15-12 and 15-13).
THROUGH_HARDENED: dict[int, tuple[float, float, float, float]] = {
    1: (0.30, 14.48, 2.35, 162.89),
    2: (0.33, 41.24, 2.51, 203.86),
}
#: Grades each material has in the table.
GRADES: dict[str, tuple[int, ...]] = {
    "through-hardened": (1, 2), "carburized": (1, 2, 3), "nitrided": (2,),
    "flame-or-induction-hardened": (1,),
}
#: K_T = 1 up to 250 °F (121.1 °C); above, (460 + t)/710 with t in °F.
TEMPERATURE_FACTOR_FROM = (250.0 - 32.0) / 1.8 + 273.15    # K


def allowable_stresses(material: str, grade: ArrayLike, hardness: ArrayLike | None = None
                       ) -> tuple[NDArray, NDArray]:
    r"""AGMA 2003's allowable bending and contact stress numbers s_at, s_ac of a bevel
    gear steel.

    Through-hardened steel takes them from its Brinell hardness HB:
    grade 1 s_at = 0.30·HB + 14.48, s_ac = 2.35·HB + 162.89; grade 2 s_at = 0.33·HB +
    41.24, s_ac = 2.51·HB + 203.86 (MPa). The others have fixed numbers
    (:data:`FIXED_ALLOWABLES`).

    Parameters
    ----------
    material : "through-hardened", "carburized", "nitrided" or
        "flame-or-induction-hardened".
    grade : the metallurgical grade (see :data:`GRADES`), a number or an array. [1]
    hardness : HB, through-hardened steel only. [1]

    Returns
    -------
    (s_at, s_ac) [Pa]; NaN where the material has no such grade.

    Source: ANSI/AGMA 2003-B97; Budynas & Nisbett, *Shigley's Mechanical Engineering
    Design*, §15-3, Tables 15-4 and 15-6, Figures 15-12 and 15-13 (SI).
    """
    grades = np.asarray(grade, dtype=float)
    which = [grades == choice for choice in GRADES[material]]
    if material == "through-hardened":
        hb = np.asarray(hardness, dtype=float)
        lines = [THROUGH_HARDENED[choice] for choice in GRADES[material]]
        return (np.select(which, [(line[0] * hb + line[1]) * 1e6 for line in lines], np.nan),
                np.select(which, [(line[2] * hb + line[3]) * 1e6 for line in lines], np.nan))
    numbers = [FIXED_ALLOWABLES[(material, choice)] for choice in GRADES[material]]
    return (np.select(which, [s_at * 1e6 for s_at, _ in numbers], np.nan),
            np.select(which, [s_ac * 1e6 for _, s_ac in numbers], np.nan))


def temperature_factor(temperature: ArrayLike) -> NDArray:
    r"""AGMA 2003's temperature factor K_T.

    .. math:: K_T = 1 \ (t \le 250\,°F), \qquad K_T = \frac{460 + t}{710} \ (t > 250\,°F)

    with t in °F (t = 1.8·(T − 273.15) + 32 from T in kelvin).

    Parameters
    ----------
    temperature : the oil's (the gear blank's) temperature T. [K]

    Source: Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, eq. (15-18).
    """
    t = np.asarray(temperature, dtype=float)
    fahrenheit = 1.8 * (t - 273.15) + 32.0
    return np.where(t > TEMPERATURE_FACTOR_FROM, (460.0 + fahrenheit) / 710.0, 1.0)


def hardness_ratio_factor(pinion_hardness: ArrayLike, gear_hardness: ArrayLike,
                          gear_ratio: ArrayLike) -> NDArray:
    r"""AGMA 2003's hardness-ratio factor C_H of a through-hardened gear meshing with a
    harder through-hardened pinion (the pinion's C_H is 1).

    .. math:: C_H = 1 + B_1\left(\frac{N}{n} - 1\right), \qquad
              B_1 = 0.00898\,\frac{H_{BP}}{H_{BG}} - 0.00829

    with the ratio H_BP/H_BG taken from 1.2 to 1.7 (below 1.2, C_H = 1; above 1.7, as
    1.7) and N/n the gear ratio, at least 1: a softer member with fewer teeth than the
    harder one is worked less often than it, and gains nothing (C_H = 1).

    Parameters
    ----------
    pinion_hardness, gear_hardness : H_BP, H_BG, Brinell. [1]
    gear_ratio : N/n = z_gear/z_pinion. [1]

    Source: Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, eq. (15-16);
    AGMA's interpretation of 2003-B97 for ratios above 1.7.
    """
    ratio = np.asarray(pinion_hardness, dtype=float) / np.asarray(gear_hardness, dtype=float)
    b1 = np.where(ratio < 1.2, 0.0, 0.00898 * np.minimum(ratio, 1.7) - 0.00829)
    return 1.0 + b1 * (np.maximum(np.asarray(gear_ratio, dtype=float), 1.0) - 1.0)


class GearMemberTerms(NamedTuple):
    """What rating gear B as well takes beyond the pinion's terms."""

    #: J_G, gear B's bending geometry factor. [1]
    bending_geometry_factor: ArrayLike
    #: N/n = z_gear/z_pinion: gear B turns N/n times less often than the pinion. [1]
    gear_ratio: ArrayLike
    #: C_H, the hardness-ratio factor of a softer gear B. [1]
    hardness_ratio_factor: ArrayLike = 1.0
    #: (s_at,G, s_ac,G), gear B's own allowable stress numbers [Pa]; None: the pinion's.
    allowables: tuple[ArrayLike, ArrayLike] | None = None


def rating_terms(inputs: Mapping[str, ArrayLike | None]) -> dict[str, Any]:
    """The terms of :class:`bearingcalc.core.bevel_rating.PairRatingInput` that the
    steel sets: its allowable stresses, the temperature factor and gear B's own terms,
    where the inputs [SI] give them (through-hardened grade 1 at normal temperature, the
    pinion alone, otherwise)."""
    terms: dict[str, Any] = {}
    material = inputs.get("material")
    grade = None if material is None else np.asarray(inputs["grade"], dtype=float)
    if material is not None and not (material == "through-hardened" and np.all(grade == 1)):
        terms["allowables"] = allowable_stresses(str(material), grade, inputs.get("hardness"))
    if inputs.get("temperature") is not None:
        terms["temperature_factor"] = temperature_factor(inputs["temperature"])
    if inputs.get("geometry_factor_bending_gear") is not None:
        ratio = np.asarray(inputs["gear_b_teeth"], dtype=float) / np.asarray(
            inputs["gear_a_teeth"], dtype=float)
        gear_hardness = inputs.get("gear_hardness")
        if gear_hardness is None:  # gear B of the pinion's steel
            terms["gear"] = GearMemberTerms(inputs["geometry_factor_bending_gear"], ratio)
        else:  # a softer through-hardened gear B: its own allowables, and C_H
            terms["gear"] = GearMemberTerms(
                inputs["geometry_factor_bending_gear"], ratio,
                hardness_ratio_factor(inputs["hardness"], gear_hardness, ratio),
                allowable_stresses(str(material), grade, gear_hardness))
    return terms
