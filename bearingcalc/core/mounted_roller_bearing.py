"""A roller bearing as it is mounted (``method: iso-16281``): cylindrical and needle
roller bearings with their operating clearance, tapered roller bearings at the cup's
contact angle, every roller cut into laminae (ISO/TS 16281:2008, 7). The rings'
displacements, every roller's load, the reference rating life from every lamina's load,
the pressures over every lamina, the edge loading and the stiffness. What every family
shares is :mod:`bearingcalc.core.mounted_bearing`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core import mounted_bearing as shared
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.common import DerivedTest, Found
from bearingcalc.core.iso16281_life import largest_roller_contacts, roller_reference_life
from bearingcalc.core.iso16281_rollers import (
    RollerEquilibrium,
    lamina_deflections,
    roller_geometry,
    solve_roller_equilibrium,
)
from bearingcalc.core.solver import Along

#: The roller bearing's results as mounted: the shared ones with the rib's load.
RESULTS = shared.results_with({
    "max_rib_load": ("N", "2·Q·sin(θ/2) of the most heavily loaded roller, θ its included "
                     "angle: the load on the cone's rib"),
}, after="max_contact_pressure_outer")
#: Warnings of the rollers as mounted: flag -> message.
WARNINGS = {
    **shared.WARNINGS,
    "edge_loaded": "a roller is edge-loaded: its end lamina carries more than its mean "
                   "(ISO/TS 16281): the profile does not relieve the ends at this tilt or "
                   "load",
    "below_minimum_load_roller": "the equivalent load is below 2 % of C, the makers' minimum "
                                 "load of a roller bearing: the rollers may skid",
}
#: The makers' minimum load of a roller bearing, a share of C.
MINIMUM_LOAD_SHARE = 0.02
#: by the input that loads the bearing beyond Hertz: (code, in words)
CONTACT_TOO_WIDE = {"radial_load": (29, "load"), "tilting_moment": (30, "tilting moment"),
                    "misalignment": (31, "misalignment")}
#: The status code of a crown whose arc is shorter than the roller.
CROWN_TOO_SMALL = 32
STATUS_REASONS = {
    **shared.STATUS_REASONS,
    **{code: (field, DerivedTest(
        "the most heavily loaded lamina's contact is not narrow against the roller (its "
        "half-width exceeds Dwe/4): Hertz's theory does not hold, and the bearing would be "
        f"crushed; the {what} is too large for it"))
       for field, (code, what) in CONTACT_TOO_WIDE.items()},
    CROWN_TOO_SMALL: ("roller_profile.crown_radius", DerivedTest(
        "the crown's arc does not span the roller: its radius must be larger than half the "
        "roller's length, Lwe/2")),
}

#: The numeric inputs the method reads, any of which a study or sweep may vary.
_NUMBERS = ("roller_count", "roller_diameter", "roller_length", "pitch_diameter",
            "radial_load", "axial_load", "contact_angle", "elastic_modulus", "poisson_ratio",
            "inner_speed", "outer_speed", "operating_clearance", "tilting_moment",
            "misalignment", "reliability", "contamination_factor", "min_rating_life",
            "max_contact_pressure", "laminae", "crown_radius", "roller_included_angle")


def mounted_results(inputs: Mapping[str, Any], c: NDArray, iso281: Mapping[str, Any],
                    speed: NDArray) -> tuple[Found, Along]:
    """The method's results from the bearing's inputs, C and ISO 281's results of the
    same bearing (its L10 and life factors), at the rings' relative speed [rad/s]."""
    shape, flat = shared.designs(inputs, _NUMBERS, c, speed)
    z, dwe, lwe, dpw, alpha = (flat(inputs[key]) for key in (
        "roller_count", "roller_diameter", "roller_length", "pitch_diameter",
        "contact_angle"))
    laminae = flat(inputs["laminae"]).astype(int)
    solved, lamina_load, deflection = _equilibrium(inputs, flat, laminae)
    life = roller_reference_life(lamina_load, z, dwe, dpw, alpha, flat(c),
                                 inner_rotates=flat(np.abs(inputs["inner_speed"])
                                                    >= np.abs(inputs["outer_speed"])) > 0,
                                 laminae=laminae)
    contacts = largest_roller_contacts(lamina_load, dwe, lwe, dpw, alpha,
                                       flat(inputs["elastic_modulus"]),
                                       flat(inputs["poisson_ratio"]), laminae=laminae)
    with np.errstate(invalid="ignore"):
        results = shared.equilibrium_results(solved, np.max(deflection, axis=2))
    if inputs.get("misalignment") is not None:
        results["tilting_moment_reaction"] = solved.reaction[:, 4]
    if inputs.get("roller_included_angle") is not None:
        results["max_rib_load"] = 2.0 * results["max_element_load"] * np.sin(
            flat(inputs["roller_included_angle"]) / 2.0)
    crushed = ~(np.maximum(*contacts["half_width"]) <= dwe / 4.0)
    crown = inputs.get("crown_radius")
    found = shared.reshaped(Found(results, {"edge_loaded": _edge_loaded(lamina_load)}, [
        (CROWN_TOO_SMALL, np.zeros(z.size, bool) if crown is None
         else ~(flat(crown) > lwe / 2.0)),
        (shared.NO_EQUILIBRIUM, ~solved.converged),
        (shared.crushing_code(inputs, CONTACT_TOO_WIDE), crushed)]), shape)
    found.results.update(shared.pressure_results(inputs, *contacts["max_pressure"], shape))
    found.results.update(shared.life_results(inputs, life, iso281, speed, shape, "roller"))
    found.flags.update(shared.warning_flags(found.results),
                       below_minimum_load_roller=shared.below_minimum_load(
                           iso281, c, MINIMUM_LOAD_SHARE))
    return found, shared.element_rows({"azimuth": solved.azimuth,
                                       "load": solved.element_load}, shape)


def _equilibrium(inputs: Mapping[str, Any], flat: Any, laminae: NDArray
                 ) -> tuple[RollerEquilibrium, NDArray, NDArray]:
    """The equilibrium of every design, the laminae's loads and deflections (N, Zmax,
    n_s) padded with NaN to the largest count of ``laminae``: designs of one count of
    laminae are solved together."""
    size = laminae.size
    one_way = traits(str(inputs["bearing_type"])).one_way
    clearance = 0.0 if one_way else flat(shared.or_zero(inputs.get("operating_clearance")))
    crown = inputs.get("crown_radius")
    loads = shared.applied_loads(inputs, flat, size)
    misalignment = inputs.get("misalignment")
    tilt = None if misalignment is None else flat(misalignment)
    geometry_inputs = [flat(inputs[key]) for key in (
        "roller_count", "roller_diameter", "roller_length", "contact_angle")]
    parts = []
    for count in np.unique(laminae):
        rows = laminae == count
        geometry = roller_geometry(
            *(value[rows] for value in geometry_inputs),
            diametral_clearance=np.broadcast_to(clearance, (size,))[rows],
            laminae=int(count), profile=str(inputs["roller_profile"]),
            crown_radius=None if crown is None else flat(crown)[rows])
        solved = solve_roller_equilibrium(geometry, loads[rows], fixed_tilt=None
                                          if tilt is None else tilt[rows])
        parts.append((rows, solved, lamina_deflections(geometry, solved.displacement,
                                                       solved.azimuth)))
    return _joined(parts, size, int(laminae.max()))


def _joined(parts: list[tuple[NDArray, RollerEquilibrium, NDArray]], size: int,
            laminae: int) -> tuple[RollerEquilibrium, NDArray, NDArray]:
    """The groups' equilibria put back in the designs' order, the laminae padded."""
    if len(parts) == 1:
        _, solved, deflection = parts[0]
        return solved, solved.lamina_load, deflection
    zmax = max(solved.element_load.shape[1] for _, solved, _ in parts)

    def placed(values: list[tuple[NDArray, NDArray]], tail: tuple[int, ...]) -> NDArray:
        out = np.full((size, *tail), np.nan)
        for rows, value in values:
            index = tuple(slice(0, n) for n in value.shape[1:])
            out[(rows, *index)] = value
        return out

    fields = {}
    for index, name in enumerate(RollerEquilibrium._fields):
        values = [(rows, solved[index]) for rows, solved, _ in parts]
        tail = values[0][1].shape[1:]
        if name in ("azimuth", "element_load"):
            tail = (zmax,)
        elif name == "lamina_load":
            tail = (zmax, laminae)
        fields[name] = placed(values, tail)
    fields["converged"] = fields["converged"] > 0.5
    deflection = placed([(rows, value) for rows, _, value in parts], (zmax, laminae))
    solved = RollerEquilibrium(**fields)
    return solved, solved.lamina_load, deflection


def _edge_loaded(lamina_load: NDArray) -> NDArray:
    """Where a roller's end lamina carries more than the mean of its laminae."""
    loads = np.nan_to_num(lamina_load, nan=0.0)
    counted = ~np.isnan(lamina_load)
    laminae = np.maximum(counted.sum(axis=2), 1)
    last = np.maximum(laminae - 1, 0)[..., None]
    ends = np.maximum(loads[..., 0], np.take_along_axis(loads, last, axis=2)[..., 0])
    mean = loads.sum(axis=2) / laminae
    return np.any((ends > mean) & (mean > 0), axis=1)
