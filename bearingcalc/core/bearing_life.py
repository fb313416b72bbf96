"""The rating life of a rolling bearing, ball or roller: ISO 281:2007's L10, a1 and,
with the lubrication, κ, Cu and aISO, composed into Lnm (``docs/physics.md`` §5); the
operating point both families' solvers read; and the system life of several bearings."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.common import Family, Found
from bearingcalc.core.iso281 import (
    AISO_CAP,
    KAPPA_CAP,
    KAPPA_MIN,
    MAX_OPERATING_VISCOSITY,
    basic_rating_life,
    fatigue_load_limit,
    life_modification_factor,
    reference_viscosity,
    reliability_factor,
    walther_viscosity,
)


def life_margin(life: ArrayLike, required: ArrayLike) -> NDArray:
    """L/L_req − 1: the share by which a life exceeds its requirement (below 0 where it
    falls short). [1] of lives in the same unit."""
    return np.asarray(life, dtype=float) / np.asarray(required, dtype=float) - 1.0


def operating_point(inputs: Mapping[str, ArrayLike | str | None]
                    ) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """(α [rad], Fr [N], Fa [N], n [rad/s]) of a bearing's solver inputs, as arrays."""
    return tuple(np.asarray(inputs[key], dtype=float)  # type: ignore[return-value]
                 for key in ("contact_angle", "radial_load", "axial_load", "speed"))


#: The largest aISO that κ = 1 may give a lubricant with EP additives (ISO 281 9.3.3.3.4).
EP_ADDITIVES_AISO_CAP = 3.0
#: The least eC at which the EP additives' κ = 1 may be taken.
EP_ADDITIVES_MIN_CONTAMINATION = 0.2


def with_ep_additives(a_iso: NDArray, ep_additives: ArrayLike, kappa: NDArray,
                      contamination_factor: ArrayLike, fatigue_load_limit: ArrayLike,
                      equivalent_load: ArrayLike, thrust: bool, family: Family) -> NDArray:
    r"""aISO of a lubricant with proven effective EP additives.

    Where κ < 1 and eC >= 0.2, κ = 1 may be used; aISO is then limited to 3, but not
    below the value with the actual κ:

    .. math:: a_{ISO,EP} = \max\left(\min\left(a_{ISO}(\kappa = 1), 3\right),
              a_{ISO}(\kappa)\right)

    elsewhere aISO(κ).

    Parameters
    ----------
    a_iso : aISO at the actual κ. [1]
    ep_additives : where the lubricant has them. [bool]
    kappa : κ, capped. [1]
    contamination_factor, fatigue_load_limit, equivalent_load : eC [1], Cu, P [N].
    thrust, family : as :func:`bearingcalc.core.iso281.life_modification_factor`.

    Source: ISO 281:2007, 9.3.3.3.4 (GOST 18855-2013, the same clause).
    """
    e_c = np.asarray(contamination_factor, dtype=float)
    applies = (np.asarray(ep_additives, dtype=bool) & (kappa < 1.0)
               & (e_c >= EP_ADDITIVES_MIN_CONTAMINATION))
    at_one = life_modification_factor(np.ones_like(kappa), e_c, fatigue_load_limit,
                                      equivalent_load, thrust, family=family)
    return np.where(applies, np.maximum(np.minimum(at_one, EP_ADDITIVES_AISO_CAP), a_iso),
                    a_iso)


def rating_life(inputs: Mapping[str, ArrayLike | str | None], thrust: bool, speed: NDArray,
                c: NDArray | None, c0: NDArray | None, p: NDArray, *,
                family: Family = "ball", pair: bool = False) -> Found:
    r"""The modified rating life, with its warnings and the status checks it adds.

    .. math:: L_{nm} = a_1 a_{ISO} L_{10}, \qquad L_{10} = (C/P)^p

    in revolutions and, at the speed n [rad/s], in seconds. With lubrication data, κ =
    ν/ν1 (capped at 4) and Cu (the catalogue's, or estimated from C0) give aISO; without,
    aISO = 1. A pair's C and C0 are the pair's, and a catalogue Cu (of one bearing)
    counts twice.

    Source: ISO 281:2007, 9.1 to 9.3 (eqs. 13 to 20, Annex B).
    """
    found = Found()
    revolutions_per_second = speed / (2.0 * np.pi)
    l10 = basic_rating_life(c, p, family=family)
    a1 = reliability_factor(inputs["reliability"])
    a_iso = np.ones_like(l10)
    if inputs.get("contamination_factor") is not None:
        mean_diameter = np.asarray(inputs["mean_diameter"], dtype=float)
        nu = inputs.get("viscosity")
        if nu is None:
            nu = walther_viscosity(inputs["viscosity_40"], inputs["viscosity_100"],
                                   inputs["temperature"])
            found.checks.append((9, ~(np.asarray(inputs["viscosity_40"], dtype=float)
                                      > np.asarray(inputs["viscosity_100"], dtype=float))))
            found.checks.append((13, ~(nu <= MAX_OPERATING_VISCOSITY)))
        nu = np.asarray(nu, dtype=float)
        nu1 = reference_viscosity(speed, mean_diameter)
        kappa_raw = nu / nu1
        found.checks.append((5, ~(kappa_raw >= KAPPA_MIN)))
        found.flags["kappa_capped"] = kappa_raw > KAPPA_CAP
        kappa = np.minimum(kappa_raw, KAPPA_CAP)
        cu = inputs.get("fatigue_load_limit")
        if cu is None:
            cu = fatigue_load_limit(c0, mean_diameter, family=family)
        elif pair:
            cu = 2.0 * np.asarray(cu, dtype=float)
        a_iso = life_modification_factor(kappa, inputs["contamination_factor"], cu, p, thrust,
                                         family=family)
        if inputs.get("ep_additives") is not None:
            a_iso = with_ep_additives(a_iso, inputs["ep_additives"], kappa,
                                      inputs["contamination_factor"], cu, p, thrust, family)
        found.flags["aiso_capped"] = a_iso >= AISO_CAP
        found.results.update({"fatigue_load_limit": cu, "reference_viscosity": nu1,
                              "operating_viscosity": nu, "viscosity_ratio": kappa})
    lnm = a1 * a_iso * l10
    found.results.update({
        "equivalent_dynamic_load": p, "load_ratio": c / p,
        "basic_rating_life": l10 / revolutions_per_second,
        "basic_rating_life_revolutions": l10, "reliability_factor": a1,
        "life_modification_factor": a_iso,
        "modified_rating_life": lnm / revolutions_per_second,
        "modified_rating_life_revolutions": lnm,
    })
    min_life = inputs.get("min_rating_life")
    if min_life is not None:
        found.results["life_margin"] = life_margin(lnm / revolutions_per_second, min_life)
    return found


#: The Weibull slope of bearing makers' system-life formula: 10/9 when every bearing is a
#: ball bearing, 9/8 when any is a roller bearing.
WEIBULL_SLOPE = 10.0 / 9.0
ROLLER_WEIBULL_SLOPE = 9.0 / 8.0


def system_life(lives: list[NDArray], slope: float = WEIBULL_SLOPE) -> NDArray:
    r"""L_sys = (Σ L_i^(−e))^(−1/e), e the Weibull slope: 10/9 for ball bearings, 9/8
    when any bearing is a roller bearing.

    Source: Lundberg & Palmgren; the system-life formula of bearing makers' catalogues
    (e.g. SKF, *Rolling bearings*, "System life").
    """
    stacked = np.stack(np.broadcast_arrays(*(np.asarray(life, dtype=float) for life in lives)))
    return np.sum(stacked ** -slope, axis=0) ** (-1.0 / slope)
