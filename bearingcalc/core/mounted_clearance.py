"""A bearing's operating clearance from its ``mounting``: the chain of
:mod:`bearingcalc.core.mounting_fits` at the middle of every band (or at a study's
samples), and its extremes over the bands' ends, for a bearing as mounted
(``method: iso-16281``).
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core.mounting_fits import (
    CHAIN_RESULTS,
    Seats,
    Temperatures,
    operating_clearance,
)

#: The toleranced links of the chain, each a band [low, high] whose ends the extremes
#: are taken over: the operating clearance is monotonic in each.
BANDED = ("initial_clearance", "shaft_diameter", "bore_diameter", "housing_diameter",
          "outside_diameter")
#: The heading of the chain's results.
GROUP = "mounting (ISO 286, ISO 492, Lamé)"
#: Each result of the chain, and its extremes over the bands.
RESULTS: dict[str, tuple[str, str]] = {}
_MEANINGS = {
    "fit_interference_inner": ("m", "the shaft's fit as drawn: its seat less the ring's "
                               "mean bore, at the assembly's temperature (negative: loose)"),
    "fit_interference_outer": ("m", "the housing's fit as drawn: the ring's mean outside "
                               "less its seat (negative: loose)"),
    "effective_interference_inner": ("m", "the shaft's fit less 0.4·Rz pressed down, at "
                                     "the operating temperatures"),
    "effective_interference_outer": ("m", "the housing's fit less 0.4·Rz pressed down, at "
                                     "the operating temperatures"),
    "fit_pressure_inner": ("Pa", "the pressure between shaft and inner ring (Lamé)"),
    "fit_pressure_outer": ("Pa", "the pressure between outer ring and housing (Lamé)"),
    "inner_ring_hoop_stress": ("Pa", "the inner ring's hoop stress at its bore"),
    "clearance_reduction_fit_inner": ("m", "the inner raceway's growth from its fit"),
    "clearance_reduction_fit_outer": ("m", "the outer raceway's shrinking from its fit"),
    "clearance_change_thermal": ("m", "the clearance lost as the inner ring runs warmer "
                                 "than the outer, α·Dpw·(ΔT_i − ΔT_o)"),
    "initial_clearance": ("m", "the unmounted bearing's radial clearance (its group's)"),
    "operating_clearance": ("m", "the mounted bearing's diametral clearance at its "
                            "temperatures (negative: preload)"),
}
for _key in CHAIN_RESULTS:
    _unit, _meaning = _MEANINGS[_key]
    RESULTS[_key] = (_unit, _meaning + "; in solve at the middle of every band")
    RESULTS[f"{_key}_min"] = (_unit, f"the least {_key} over the chain's bands")
    RESULTS[f"{_key}_max"] = (_unit, f"the largest {_key} over the chain's bands")


RESULTS["operating_clearance_margin"] = ("m", "operating_clearance − "
                                         "min_operating_clearance")


#: NSK's guide against a fit that damages the inner ring: the largest interference under
#: about 7/10 000 of the shaft's diameter (Rolling Bearings, CAT. No. E1102e, 9.1.2 (5)).
LARGEST_INTERFERENCE_SHARE = 7e-4
#: NSK's interference a radial load needs against creep (CAT. No. E1102e, 9.1.2 (2)): a
#: light load's 0.08·√(d/B·Fr) µm (d, B [mm], Fr [N]), eq. (9.1); above 20 % of C0r, where
#: NSK finds (9.1) often short, at least a heavy load's 0.02·Fr/B µm, eq. (9.2), as well.
CREEP_LIGHT, CREEP_HEAVY, HEAVY_SHARE = 0.08e-6, 0.02e-6, 0.2
WARNINGS = {
    "inner_ring_creeps": "the turning inner ring's least effective interference is below "
                         "what its radial load needs against creep (NSK: 0.08·√(d/B·Fr) µm, "
                         "0.02·Fr/B µm above 20 % of C0): a tighter shaft class, or a ring "
                         "held otherwise",
    "clearance_below_limit_within_bands": "some assemblies within the bands fall below "
                                          "min_operating_clearance (operating_clearance_min): "
                                          "solve judges the bands' middles; run tolerance "
                                          "for the share of assemblies below it",
    "fit_too_tight": "the shaft's interference exceeds 7/10 000 of d, NSK's guide against "
                     "a fit that damages the ring (inner_ring_hoop_stress gives its "
                     "stress)",
}


def required_interference(bore: NDArray, width: NDArray, radial_load: NDArray,
                          static_rating: NDArray | None) -> NDArray:
    r"""The effective interference [m] a turning inner ring under the radial load Fr [N]
    needs against creep (d, B [m]):

    .. math:: Δd_F = 0.08\sqrt{\frac{d}{B}F_r}\ \text{µm}, \qquad
              Δd = 0.02\,\frac{F_r}{B}\ \text{µm}\ \ (F_r > 0.2\,C_{0r})

    with d and B in mm. Source: NSK, Rolling Bearings, CAT. No. E1102e, 9.1.2 (2), eqs.
    (9.1) and (9.2).
    """
    d_mm, b_mm = bore * 1e3, width * 1e3
    light = CREEP_LIGHT * np.sqrt(d_mm / b_mm * radial_load)
    if static_rating is None:
        return light
    heavy = CREEP_HEAVY * radial_load / b_mm
    return np.where(radial_load > HEAVY_SHARE * static_rating, np.maximum(light, heavy), light)


def chain_warnings(inputs: Mapping[str, Any], results: Mapping[str, NDArray]
                   ) -> dict[str, NDArray]:
    """The chain's warning flags: a turning inner ring whose least fit is below what its
    load needs (where the bearing's width is known), a shaft fit tighter than NSK's
    guide."""
    mounting = inputs["mounting"]
    bore = np.asarray(mounting["band_low"]["bore_diameter"], dtype=float)
    # judged at the design's own fit (the bands' middles in solve), not at the bands'
    # tightest corner, which every usual class of a tight fit passes
    flags = {"fit_too_tight": results["fit_interference_inner"]
             > LARGEST_INTERFERENCE_SHARE * bore}
    limit = inputs.get("min_operating_clearance")
    if limit is not None:
        flags["clearance_below_limit_within_bands"] = (
            results["operating_clearance_min"] < np.asarray(limit, dtype=float))
    width = inputs.get("width")
    if width is not None:
        turns = np.abs(np.asarray(inputs["inner_speed"], dtype=float)) > np.abs(
            np.asarray(inputs["outer_speed"], dtype=float))
        rating = inputs.get("static_load_rating")
        needed = required_interference(bore, np.asarray(width, dtype=float),
                                       np.asarray(inputs["radial_load"], dtype=float),
                                       None if rating is None else np.asarray(rating, float))
        flags["inner_ring_creeps"] = turns & (results["effective_interference_inner_min"]
                                              < needed)
    return flags


def raceway_diameters(inputs: Mapping[str, Any]) -> tuple[NDArray, NDArray]:
    """The inner and outer raceways' diameters F and E [m] across an element's middle:
    Dpw ∓ Dw·cos α (balls), Dpw ∓ Dwe·cos α (rollers), α the contact angle (0 for a
    radial bearing)."""
    element = inputs.get("ball_diameter")
    if element is None:
        element = inputs["roller_diameter"]
    pitch = np.asarray(inputs["pitch_diameter"], dtype=float)
    angle = inputs.get("contact_angle")
    across = np.asarray(element, dtype=float) * np.cos(np.asarray(
        0.0 if angle is None else angle, dtype=float))
    return pitch - across, pitch + across


def chain_at(mounting: Mapping[str, Any], links: Mapping[str, Any],
           inner_raceway: NDArray, outer_raceway: NDArray, pitch: NDArray
           ) -> dict[str, NDArray]:
    """The chain with the toleranced ``links`` (:data:`BANDED`) and the rest of
    ``mounting``."""
    def at(name: str) -> NDArray:
        return np.asarray(mounting[name], dtype=float)

    seats = Seats(links["shaft_diameter"], links["bore_diameter"],
                  links["housing_diameter"], links["outside_diameter"],
                  *(at(name) for name in (
                      "shaft_bore", "housing_outside", "shaft_modulus", "shaft_poisson",
                      "housing_modulus", "housing_poisson", "ring_modulus", "ring_poisson",
                      "shaft_roughness", "housing_roughness")))
    assembly = at("assembly_temperature")
    rises = [at(name) - assembly for name in ("inner_ring_temperature",
                                              "outer_ring_temperature",
                                              "shaft_temperature", "housing_temperature")]
    temperatures = Temperatures(*rises, at("ring_expansion"), at("shaft_expansion"),
                                at("housing_expansion"))
    return operating_clearance(links["initial_clearance"], seats, temperatures,
                               inner_raceway, outer_raceway, pitch)


def operating_clearance_of(inputs: Mapping[str, Any]) -> NDArray:
    """The operating clearance [m] of ``inputs['mounting']`` at its links' values alone,
    for a caller that needs no extremes (a drive's shaft building its bearings)."""
    mounting, rings = inputs["mounting"], raceways(inputs)
    return chain_at(mounting, _links(mounting), *rings)["operating_clearance"]


def raceways(inputs: Mapping[str, Any]) -> tuple[NDArray, NDArray, NDArray]:
    """F, E and Dpw [m]."""
    return (*raceway_diameters(inputs), np.asarray(inputs["pitch_diameter"], dtype=float))


def _links(mounting: Mapping[str, Any]) -> dict[str, NDArray]:
    """The chain's toleranced links at their values (the bands' middles, a study's
    samples)."""
    return {name: np.asarray(mounting[name], dtype=float) for name in BANDED}


def mounted_clearance(inputs: Mapping[str, Any]) -> dict[str, NDArray]:
    """The chain's results (:data:`RESULTS`) of ``inputs['mounting']``: at its links'
    values (the bands' middles, or a study's samples), and each result's least and
    largest over the 2⁵ corners of the bands (``mounting['band_low']`` and
    ``['band_high']``: name -> its band's end)."""
    mounting, rings = inputs["mounting"], raceways(inputs)
    results = chain_at(mounting, _links(mounting), *rings)
    # each band widened to hold its link's own value: a sweep may carry a link past its
    # band, a study's samples stay inside it
    ends = [(np.minimum(mounting["band_low"][name], mounting[name]),
             np.maximum(mounting["band_high"][name], mounting[name])) for name in BANDED]
    corners = [chain_at(mounting, dict(zip(BANDED, corner, strict=True)), *rings)
               for corner in itertools.product(*ends)]
    limit = inputs.get("min_operating_clearance")
    if limit is not None:
        results["operating_clearance_margin"] = (results["operating_clearance"]
                                                 - np.asarray(limit, dtype=float))
    shape = np.shape(results["operating_clearance"])
    for key in CHAIN_RESULTS:
        # reduced corner by corner: a study's corners are constants beside its samples,
        # and a stack of them over the samples would hold 2⁵ arrays of its size
        least = functools.reduce(np.minimum, (corner[key] for corner in corners))
        most = functools.reduce(np.maximum, (corner[key] for corner in corners))
        results[f"{key}_min"] = np.broadcast_to(least, shape)
        results[f"{key}_max"] = np.broadcast_to(most, shape)
    return results
