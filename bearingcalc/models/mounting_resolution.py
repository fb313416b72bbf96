"""How a bearing's ``mounting`` meets the tables: each class and group turned into its
band (a toleranced value at the band's middle, uniform over it) at the bearing's
bore and outside diameter, and the chain's solver inputs design by design, a design of
another size resolved at its own (``docs/physics.md`` §13)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from bearingcalc.catalogue import iso286, iso492, iso5753
from bearingcalc.core.bearing_types import traits
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_mounting import BearingMounting
from bearingcalc.models.mounting_fields import (
    Roughness,
    SeatClass,
    band_ends,
    material_constants,
)
from bearingcalc.models.quantities import Measured, Tolerance


def _band(low: float, high: float, written_unit: str) -> Measured:
    """A band's middle, uniform over it."""
    middle = 0.5 * (low + high)
    return Measured(middle, Tolerance(middle, low, high, "uniform", unit="m",
                                      written_unit=written_unit))


class _Refusals:
    """What the tables refuse as a mounting is resolved, each at the mounting's field."""

    def __init__(self) -> None:
        self.problems: list[SpecFieldError] = []

    def band(self, field: str, lookup: Any, *args: Any, **kwargs: Any
             ) -> tuple[float, float] | None:
        try:
            return lookup(*args, **kwargs)
        except ValueError as problem:
            self.problems.append(SpecFieldError(field, str(problem).rstrip(".")))
            return None


def resolve(mounting: BearingMounting, bearing: Mapping[str, Any]) -> BearingMounting:
    """``mounting`` with every class and group turned into its band (a toleranced value
    at its middle) and the bands kept, from the bearing's ``bore_diameter``,
    ``outside_diameter`` and ``type`` (validated before the mounting). What a table
    refuses is kept for the mounting's rules to say, with the bearing's path; without
    the bearing's diameters nothing is resolved (the bearing's rules say so)."""
    bore, outside = bearing.get("bore_diameter"), bearing.get("outside_diameter")
    if bore is None or outside is None:
        return mounting
    bore, outside = float(bore), float(outside)
    refusals = _Refusals()
    updates: dict[str, Any] = {}
    written: dict[str, str] = {}
    group = mounting.clearance_group
    table = _clearance_table(bearing.get("type"))
    if isinstance(group, str) and table is not None:  # else the bearing's rules refuse it
        written["clearance_group"] = group
        band = refusals.band("clearance_group", iso5753.radial_clearance, bore, group,
                             bearing_kind=table)
        if band is not None:
            updates["clearance_group"] = _band(*band, "µm")
    for field, nominal in (("bore_deviation", bore), ("outside_deviation", outside)):
        if getattr(mounting, field) is None:
            band = refusals.band(field, getattr(iso492, field), nominal,
                                 tolerance_class=mounting.tolerance_class)
            if band is not None:
                updates[field] = _band(*band, "µm")
    for field, nominal, hole in (("shaft", bore, False), ("housing", outside, True)):
        seat = getattr(mounting, field)
        if isinstance(seat, SeatClass):
            written[field] = seat.symbol
            band = _seat_band(refusals, field, seat, nominal, hole)
            if band is not None:
                updates[field] = band
    resolved = mounting.model_copy(update=updates)
    resolved._written, resolved._refused = written, refusals.problems
    resolved._resolved_at = (bore, outside, str(bearing.get("type")))
    resolved._written_form = mounting
    if not refusals.problems and all(
            isinstance(value, float) for value in (resolved.shaft, resolved.housing,
                                                   resolved.bore_deviation,
                                                   resolved.outside_deviation)):
        resolved._bands = _bands_of(resolved, bore, outside)
    return resolved


def _clearance_table(bearing_type: Any) -> str | None:
    """Which of ISO 5753-1's tables gives the type's groups, None for none (or a type
    its own rule refuses)."""
    try:
        return traits(str(bearing_type)).clearance_table
    except (KeyError, ValueError):
        return None


def _bands_of(resolved: BearingMounting, bore: float, outside: float
              ) -> dict[str, tuple[float, float]]:
    """Each link's band [low, high] of a resolved mounting."""
    given = resolved.clearance_group if resolved.clearance_group is not None \
        else resolved.initial_clearance
    # an adjusted pair's bearing has no clearance of its own: its setting's end play
    bands = {} if isinstance(given, str) else {
        "initial_clearance": (0.0, 0.0) if given is None else band_ends(given)}
    for link, nominal, field in (("bore_diameter", bore, "bore_deviation"),
                                 ("outside_diameter", outside, "outside_deviation")):
        low, high = band_ends(getattr(resolved, field))
        bands[link] = (nominal + low, nominal + high)
    for field in ("shaft", "housing"):
        bands[f"{field}_diameter"] = band_ends(getattr(resolved, field))
    return bands


def _seat_band(refusals: _Refusals, field: str, seat: SeatClass, nominal: float,
               hole: bool) -> Measured | None:
    """A seat class's band of diameters: the nominal (the ring's, where the class names
    none) plus its ISO 286 deviations; None where it is refused."""
    ring = "bore" if field == "shaft" else "outside diameter"
    if seat.nominal is not None and not math.isclose(seat.nominal, nominal, rel_tol=1e-9):
        refusals.problems.append(SpecFieldError(
            field, f"the seat's nominal {seat.nominal * 1e3:g} mm is not the bearing's "
            f"{ring}, {nominal * 1e3:g} mm: write {seat.symbol} alone, or the ring's {ring}"))
        return None
    if seat.symbol[0].isupper() != hole:
        which, like = ("a hole's", "upper case, like H7") if hole else (
            "a shaft's", "lower case, like k5")
        refusals.problems.append(SpecFieldError(
            field, f"{seat.symbol} is not {which} class: the {field} seat takes {which} "
            f"({like})"))
        return None
    band = refusals.band(field, iso286.limit_deviations, seat.symbol, nominal)
    return None if band is None else _band(nominal + band[0], nominal + band[1], "mm")


#: The chain's toleranced links, each the mounting's field it is read from.
LINK_FIELDS = {"initial_clearance": "clearance", "shaft_diameter": "shaft",
               "bore_diameter": "bore_deviation", "housing_diameter": "housing",
               "outside_diameter": "outside_deviation"}


def _link(mounting: BearingMounting, link: str, bore: Any, outside: Any) -> Any:
    """A link's value in SI: the clearance, a seat's diameter, the ring's mean bore or
    outside (its nominal plus its deviation)."""
    if link == "initial_clearance":
        given = mounting.clearance_group if mounting.clearance_group is not None \
            else mounting.initial_clearance
        return 0.0 if given is None else given
    value = getattr(mounting, LINK_FIELDS[link])
    return value + (bore if link == "bore_diameter" else outside if link == "outside_diameter"
                    else 0.0)


#: The links that follow the bearing's bore, and those that follow its outside diameter.
BORE_LINKS = ("initial_clearance", "shaft_diameter", "bore_diameter")
OUTSIDE_LINKS = ("housing_diameter", "outside_diameter")
#: A size this close to the one the mounting was resolved at keeps its bands (a study
#: that tolerances the nominal bore itself), a share of it.
SAME_SIZE = 1e-3


def links_per_design(mounting: BearingMounting, bore: Any, outside: Any
                     ) -> tuple[dict[str, Any], dict[str, Any], dict[str, Any]]:
    """Each link's value, band low and band high (SI), design by design. A design of the
    size the mounting was resolved at takes its bands; one of another size (a sweep of
    the bore, a catalogue's row in ``select``) resolves the mounting as written at its
    own bore (for the clearance, the shaft and the ring's bore) and its own outside
    diameter (for the housing and the ring's outside), its classes and groups read from
    the tables there, a study's variation of a link kept as its offset from the band's
    middle. A size the tables refuse has NaN links, which the solver refuses."""
    bands = mounting.bands()
    at = mounting._resolved_at
    if at is None or all(np.all(np.abs(np.asarray(size, dtype=float) - nominal)
                                <= SAME_SIZE * nominal)
                         for size, nominal in ((bore, at[0]), (outside, at[1]))):
        values = {link: _link(mounting, link, bore, outside) for link in LINK_FIELDS}
        return (values, {link: low for link, (low, _) in bands.items()},
                {link: high for link, (_, high) in bands.items()})
    shape = np.broadcast_shapes(np.shape(bore), np.shape(outside))
    out: tuple[dict[str, Any], dict[str, Any], dict[str, Any]] = ({}, {}, {})
    for links, size, sized in ((BORE_LINKS, bore, lambda v: (v, at[1])),
                               (OUTSIDE_LINKS, outside, lambda v: (at[0], v))):
        values = np.broadcast_to(np.asarray(size, dtype=float), shape).ravel()
        distinct, which = np.unique(values, return_inverse=True)
        which = np.ravel(which)
        each = [(resolve(mounting._written_form, {"bore_diameter": sized(v)[0],
                                                  "outside_diameter": sized(v)[1],
                                                  "type": at[2]}), *sized(v))
                for v in distinct]
        for link in links:
            middles, lows, highs = (np.array([_of(r, link, b, d, part) for r, b, d in each]
                                             )[which].reshape(shape)
                                    for part in ("middle", "low", "high"))
            # a study's sample of the link: its offset from its band's middle, moved with
            # the band to the design's size
            low, high = bands[link]
            offset = np.asarray(_link(mounting, link, at[0], at[1]), dtype=float) - 0.5 * (
                low + high)
            out[0][link] = middles + offset
            out[1][link], out[2][link] = lows, highs
    return out


def _of(resolved: BearingMounting, link: str, bore: float, outside: float, part: str
        ) -> float:
    """A resolved mounting's link at its band's middle, low or high end; NaN where the
    tables refused it."""
    if resolved._refused or link not in resolved.bands():
        return math.nan
    low, high = resolved.bands()[link]
    if part == "low":
        return low
    if part == "high":
        return high
    return float(_link(resolved, link, bore, outside))


def chain_inputs(mounting: BearingMounting, bore: Any, outside: Any,
                 ring_modulus: Any, ring_poisson: Any) -> dict[str, Any]:
    """The chain's solver inputs (SI; arrays where a study varies a link or a sweep the
    bearing's size): see :func:`bearingcalc.core.mounted_clearance.mounted_clearance`."""
    m = mounting
    shaft, housing = (material_constants(material) for material in (m.shaft_material,
                                                                     m.housing_material))
    roughness = m.roughness or Roughness()
    inner = m.assembly_temperature if m.inner_ring_temperature is None \
        else m.inner_ring_temperature
    outer = m.assembly_temperature if m.outer_ring_temperature is None \
        else m.outer_ring_temperature
    links, low, high = links_per_design(m, bore, outside)
    return {
        **links, "band_low": low, "band_high": high, "shaft_bore": m.shaft_bore,
        "housing_outside": math.inf if m.housing_outside_diameter is None
        else m.housing_outside_diameter,
        "shaft_modulus": shaft[0], "shaft_poisson": shaft[1], "shaft_expansion": shaft[2],
        "housing_modulus": housing[0], "housing_poisson": housing[1],
        "housing_expansion": housing[2], "ring_modulus": ring_modulus,
        "ring_poisson": ring_poisson, "ring_expansion": m.ring_thermal_expansion,
        "shaft_roughness": roughness.shaft, "housing_roughness": roughness.housing,
        "assembly_temperature": m.assembly_temperature, "inner_ring_temperature": inner,
        "outer_ring_temperature": outer,
        "shaft_temperature": inner if m.shaft_temperature is None else m.shaft_temperature,
        "housing_temperature": outer if m.housing_temperature is None
        else m.housing_temperature}
