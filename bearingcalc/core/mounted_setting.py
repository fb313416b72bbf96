"""An adjusted pair's end play as mounted: two angular-contact ball or tapered roller
bearings set against each other, each with its ``mounting``. The fits that press the
rings onto their seats and the temperatures they run at move each bearing's raceways
radially, which takes up end play along the contact line, and grow the shaft and the
housing along the axis over the pair's spread, which adds or takes end play by the
arrangement (``docs/physics.md`` §13, a pair's end play).

Every function is pure numpy on SI arrays that broadcast.
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core.mounted_clearance import chain_at, raceways

#: Where an adjusted pair's end play was set: on the bench, before the rings were
#: pressed on (a matched pair's, a spacer's), or in place after they were, at the
#: assembly's temperature (shims, a nut).
STAGES = ("mounted", "bench")
#: The toleranced links of a bearing of a pair: its seats and its ring's diameters.
PAIR_LINKS = ("shaft_diameter", "bore_diameter", "housing_diameter", "outside_diameter")
#: The heading of a pair's setting results.
GROUP = "setting as mounted (fits, temperatures)"
_PARTS = {
    "end_play_reduction_fit": "the end play the fits take up as the rings are pressed on "
                              "(0 for a pair set in place, after them)",
    "end_play_change_thermal": "the end play lost from the assembly's temperature to the "
                               "operating ones: the raceways' radial change and the shaft's "
                               "and housing's growth over the pair's spread",
    "operating_end_play": "the pair's end play at its operating temperatures (negative: "
                          "preload)",
}
#: The setting's results, each with its least and largest over the chain's bands.
RESULTS: dict[str, tuple[str, str]] = {}
for _key, _meaning in _PARTS.items():
    RESULTS[_key] = ("m", _meaning + "; in solve at the middle of every band")
    RESULTS[f"{_key}_min"] = ("m", f"the least {_key} over the chain's bands")
    RESULTS[f"{_key}_max"] = ("m", f"the largest {_key} over the chain's bands")
#: How the shaft's growth along its axis, relative to the housing's, moves the end play:
#: face-to-face (pressure centres between the bearings) it pushes each cone into its cup
#: and takes end play; back-to-back (pressure centres outside them) it pulls them out.
AXIAL_SIGN = {"back-to-back": -1.0, "face-to-face": 1.0}


def _at_assembly(mounting: Mapping[str, Any]) -> dict[str, Any]:
    """The mounting with every part at the assembly's temperature."""
    assembly = mounting["assembly_temperature"]
    return {**mounting, **{name: assembly for name in (
        "inner_ring_temperature", "outer_ring_temperature", "shaft_temperature",
        "housing_temperature")}}


def clearance_losses(inputs: Mapping[str, Any], links: Mapping[str, Any], stage: str
                     ) -> tuple[NDArray, NDArray]:
    r"""A bearing's radial clearance taken up [m, diametral], (by its fits, by the
    temperatures), with its toleranced ``links`` at these values: the mounting chain
    (:func:`~bearingcalc.core.mounted_clearance.chain_at`) with no initial clearance,
    once at the assembly's temperature and once at the operating ones,

    .. math:: ΔP_{d,fit} = \left(ΔF_{fit} + ΔE_{fit}\right)\big|_{T_0}, \qquad
              ΔP_{d,T} = \left(ΔF_{fit} + ΔE_{fit} + ΔP_{d,T}\right)\big|_{T}
              - \left(ΔF_{fit} + ΔE_{fit}\right)\big|_{T_0}

    the temperatures' share whatever the stage; the fits' share only for a pair set on
    the bench (one set in place has it in its setting already: 0 here).
    """
    mounting, rings = inputs["mounting"], raceways(inputs)
    every = {"initial_clearance": 0.0, **links}
    at_operating = -chain_at(mounting, every, *rings)["operating_clearance"]
    at_assembly = -chain_at(_at_assembly(mounting), every, *rings)["operating_clearance"]
    fit = at_assembly if stage == "bench" else np.zeros_like(at_assembly)
    return fit, at_operating - at_assembly


def axial_share(inputs: Mapping[str, Any]) -> NDArray:
    r"""The end play [m] a bearing's diametral clearance change of 1 m takes up along its
    contact line, at its contact angle α (the cup's, for tapered rollers):

    .. math:: Δe = \frac{ΔP_d}{2}\cot α

    Source: the geometry of a cone in its cup; Timken's K/0.39 (K = 0.389·cot α) in its
    Engineering Manual (order no. 10424), tapered roller bearings' setting.
    """
    return 0.5 / np.tan(np.asarray(inputs["contact_angle"], dtype=float))


def axial_growth(bearings: Sequence[Mapping[str, Any]], arrangement: str,
                 spread: NDArray, flat: Any) -> NDArray:
    r"""The end play [m] the shaft's growth along its axis takes, relative to the
    housing's, over the spread L between the two bearings' rolling elements, the shaft
    and the housing at the means of the two seats' temperatures:

    .. math:: Δe_{ax} = ±(α_s ΔT_s - α_h ΔT_h)\,L

    plus face-to-face, minus back-to-back. With the radial shares this is Timken's
    setting loss α·ΔT·(K₁D₀₁/0.78 + K₂D₀₂/0.78 ± L) where shaft and housing are one
    material (Engineering Manual, tapered roller bearings' setting); a back-to-back pair
    whose cups' apexes meet keeps its setting as the shaft warms.
    """
    def mean(name: str) -> NDArray:
        # each bearing's value may be a study's array or a plain number
        values = [np.asarray(b["mounting"][name], dtype=float) for b in bearings]
        return sum(values) / len(values)

    assembly = mean("assembly_temperature")
    growth = (mean("shaft_expansion") * (mean("shaft_temperature") - assembly)
              - mean("housing_expansion") * (mean("housing_temperature") - assembly))
    return AXIAL_SIGN[arrangement] * flat(growth) * spread


def _widened(mounting: Mapping[str, Any], name: str) -> tuple[NDArray, NDArray]:
    """A link's band, widened to hold its own value (a sweep may carry it past)."""
    value = np.asarray(mounting[name], dtype=float)
    return (np.minimum(mounting["band_low"][name], value),
            np.maximum(mounting["band_high"][name], value))


def end_play_loss(bearings: Sequence[Mapping[str, Any]], arrangement: str, stage: str,
                  spread: NDArray, flat: Any) -> dict[str, NDArray]:
    """The end play a pair's fits and temperatures take up [m], flat over the designs
    (``flat`` lays a value of the designs out so, as ``spread`` is): the fits' share and the
    temperatures' (``end_play_reduction_fit``, ``end_play_change_thermal``) at the links'
    values, each with its least and largest over their bands, and the whole loss's
    (``loss``, ``loss_min``, ``loss_max``). Each bearing's links move its own share
    alone, so the extremes are each bearing's over its 2⁴ corners, summed."""
    axial = axial_growth(bearings, arrangement, spread, flat)
    parts: dict[str, Any] = {"fit": [], "thermal": [], "loss": []}
    for bearing in bearings:
        mounting, share = bearing["mounting"], axial_share(bearing)
        value = {link: np.asarray(mounting[link], dtype=float) for link in PAIR_LINKS}
        corners = [dict(zip(PAIR_LINKS, corner, strict=True)) for corner in
                   itertools.product(*(_widened(mounting, link) for link in PAIR_LINKS))]
        own = [clearance_losses(bearing, links, stage) for links in (value, *corners)]
        for key, of in (("fit", lambda f, t: f), ("thermal", lambda f, t: t),
                        ("loss", lambda f, t: f + t)):
            shares = [flat(share * of(*each)) for each in own]
            parts[key].append((shares[0],
                               functools.reduce(np.minimum, shares[1:]),
                               functools.reduce(np.maximum, shares[1:])))
    out = {}
    for key, name, extra in (("fit", "end_play_reduction_fit", 0.0),
                             ("thermal", "end_play_change_thermal", axial),
                             ("loss", "loss", axial)):
        middle, least, most = (sum(each[i] for each in parts[key]) + extra for i in range(3))
        out[name], out[f"{name}_min"], out[f"{name}_max"] = middle, least, most
    return out


def operating_end_play(loss: Mapping[str, NDArray], shape: tuple[int, ...]
                       ) -> dict[str, NDArray]:
    """The setting's results (:data:`RESULTS`) in the designs' ``shape``, from the flat
    ``loss`` with ``set_end_play``: the end play as set less what the fits and
    temperatures take up, its least where they take the most."""
    out = {key: loss[key] for key in RESULTS if not key.startswith("operating")}
    out["operating_end_play"] = loss["set_end_play"] - loss["loss"]
    out["operating_end_play_min"] = loss["set_end_play"] - loss["loss_max"]
    out["operating_end_play_max"] = loss["set_end_play"] - loss["loss_min"]
    return {key: value.reshape(shape) for key, value in out.items()}
