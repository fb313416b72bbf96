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
from bearingcalc.core import mounted_pair
from bearingcalc.core.arrangements import PAIRS
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.common import DerivedTest, Found
from bearingcalc.core.iso16281_life import largest_roller_contacts, roller_reference_life
from bearingcalc.core.iso16281_rollers import (
    RollerGeometry,
    lamina_deflections,
    roller_contacts_at,
    roller_geometry,
    row_loads,
    solve_roller_equilibrium,
)
from bearingcalc.core.mounted_loads import below_minimum_load
from bearingcalc.core.mounted_pair import BearingFamily, pair_results
from bearingcalc.core.solver import Along

#: The roller bearing's results as mounted: the shared ones with the rib's load.
RESULTS = shared.results_with({
    "max_rib_load": ("N", "2·Q·sin(θ/2) of the most heavily loaded roller, θ its included "
                     "angle: the load on the cone's rib"),
}, after="max_contact_pressure_outer", pair=mounted_pair.RESULTS)
#: Warnings of the rollers as mounted: flag -> message.
WARNINGS = {
    **shared.WARNINGS,
    "edge_loaded": "a roller is edge-loaded: its end lamina carries more than its mean "
                   "(ISO/TS 16281): the profile does not relieve the ends at this tilt or "
                   "load",
    "below_minimum_load_roller": "the load on the rollers is below 2 % of C, the "
                                 "makers' minimum load of a roller bearing: the rollers "
                                 "may skid",
}
#: The largest drop of a crowned roller at its ends, a share of Dwe: crowns drop some
#: micrometres to tens.
CROWN_DROP_SHARE = 0.02
#: The makers' minimum load of a roller bearing, a share of C.
MINIMUM_LOAD_SHARE = 0.02
#: by the input that loads the bearing beyond Hertz: (code, in words)
CONTACT_TOO_WIDE = {"radial_load": (29, "load"), "tilting_moment": (30, "tilting moment"),
                    "misalignment": (31, "misalignment"),
                    "operating_clearance": (35, "preload (negative clearance)"),
                    "setting.preload": (39, "preload"),
                    "setting.end_play": (40, "interference (negative end play)"),
                    "axial_load": (41, "axial load")}
#: The status code of a crown whose arc is shorter than the roller.
CROWN_TOO_SMALL = 32
STATUS_REASONS = {
    **shared.STATUS_REASONS,
    **mounted_pair.STATUS_REASONS,
    **{code: (field, DerivedTest(
        "the most heavily loaded lamina's contact is not narrow against the roller (its "
        "half-width exceeds Dwe/4), or a pair's shaft moves beyond small displacements (a "
        "tilt above 10 mrad, a shift above a tenth of the pitch radius): the bearing's model "
        f"does not hold, and the bearing would be crushed; the {what} is too large for it"))
       for field, (code, what) in CONTACT_TOO_WIDE.items()},
    CROWN_TOO_SMALL: ("roller_profile.crown_radius", DerivedTest(
        "the crown drops the roller's ends by 2 % of its diameter or more (or its arc does "
        "not span the roller): a crown's radius is of the order of a metre")),
}


def mounted_results(inputs: Mapping[str, Any], c: NDArray, iso281: Mapping[str, Any],
                    speed: NDArray) -> tuple[Found, dict[str, Along]]:
    """The method's results from the bearing's inputs, C and ISO 281's results of the
    same bearing (its L10 and life factors), at the rings' relative speed [rad/s]: of a
    single bearing, or of a matched pair (:mod:`bearingcalc.core.mounted_pair`)."""
    shape, flat = shared.designs(inputs, c, speed)
    geometry, family = _family(inputs, flat, c)
    if inputs.get("arrangement") in PAIRS:
        found, along = pair_results(inputs, family, flat, shape, c, iso281, speed)
    else:
        found, along = _single(inputs, geometry, family, flat, shape, iso281, speed)
    crown = inputs.get("crown_radius")
    lwe = flat(inputs["roller_length"])
    found.checks.insert(0, (CROWN_TOO_SMALL, np.zeros(shape, bool) if crown is None
                            else ~_crown_fits(flat(crown), lwe,
                                              flat(inputs["roller_diameter"])).reshape(shape)))
    found.flags.update(below_minimum_load_roller=below_minimum_load(
        inputs, found.results, iso281, c, MINIMUM_LOAD_SHARE))
    return found, along


def _geometry(inputs: Mapping[str, Any], flat: Any) -> tuple[RollerGeometry, NDArray]:
    """Every design's laminae (their count may differ between designs) and the count of
    one row's. A double row's rows lie in the two halves of the bearing's width (their
    middles B/2 apart), or side by side (Lwe apart) where no width is given."""
    laminae = flat(inputs["laminae"]).astype(int)
    one_way = traits(str(inputs["bearing_type"])).one_way
    crown, width = inputs.get("crown_radius"), inputs.get("width")
    lwe = flat(inputs["roller_length"])
    geometry = roller_geometry(
        *(flat(inputs[key]) for key in ("roller_count", "roller_diameter", "roller_length",
                                        "contact_angle")),
        diametral_clearance=0.0 if one_way else flat(
            shared.or_zero(inputs.get("operating_clearance"))),
        laminae=laminae, profile=str(inputs["roller_profile"]),
        crown_radius=None if crown is None else flat(crown),
        row_distance=np.where(flat(inputs["rows"]) > 1, lwe if width is None else
                              np.maximum(flat(width) / 2.0, lwe), 0.0))
    return geometry, laminae


def bearing_family(inputs: Mapping[str, Any], flat: Any, c: NDArray) -> BearingFamily:
    """What a roller bearing's inputs give a shaft as mounted (a pair's, a drive's)."""
    return _family(inputs, flat, c)[1]


def _family(inputs: Mapping[str, Any], flat: Any, c: NDArray
            ) -> tuple[RollerGeometry, BearingFamily]:
    """The rollers' laminae, and what they give a bearing as mounted: their contacts,
    life, pressures."""
    geometry, laminae = _geometry(inputs, flat)
    z, dwe, lwe, dpw, alpha = (flat(inputs[key]) for key in (
        "roller_count", "roller_diameter", "roller_length", "pitch_diameter",
        "contact_angle"))
    rotates = flat(np.abs(inputs["inner_speed"]) >= np.abs(inputs["outer_speed"])) > 0
    material = (flat(inputs["elastic_modulus"]), flat(inputs["poisson_ratio"]))
    rows = flat(inputs["rows"])

    def life(contacts: Any) -> Any:
        return roller_reference_life(contacts.lamina_load, z, dwe, dpw, alpha, flat(c),
                                     rows=rows, inner_rotates=rotates, laminae=laminae,
                                     edge_stress=bool(inputs.get("edge_stress_factor")))

    def pressures(contacts: Any) -> tuple[NDArray, NDArray, NDArray]:
        found = largest_roller_contacts(contacts.lamina_load, dwe, lwe, dpw, alpha,
                                        *material, laminae=laminae)
        return (*found["max_pressure"], ~(np.maximum(*found["half_width"]) <= dwe / 4.0))

    def deflection(q: NDArray, contacts: Any) -> NDArray:
        return np.max(lamina_deflections(geometry, q, contacts.azimuth), axis=2)

    with np.errstate(invalid="ignore", divide="ignore"):
        first_contact = np.where(alpha > 0.0, np.min(geometry.gap, axis=1) / np.sin(alpha),
                                 0.0)
    def contacts(q: NDArray) -> Any:
        # a double row's element at ψ_j is its two rollers: the larger is its load
        found = roller_contacts_at(geometry, q)
        return found._replace(element_load=np.max(row_loads(found.lamina_load, row_count),
                                                  axis=2))

    row_count = int(rows.max())
    return geometry, BearingFamily(
        "roller", contacts, np.zeros_like(z), dpw / 2.0 * np.tan(alpha), first_contact,
        dpw / 2.0, life, pressures, deflection, 10.0 / 3.0, CONTACT_TOO_WIDE,
        lambda contacts: _edge_loaded(contacts.lamina_load, laminae, row_count))


def _single(inputs: Mapping[str, Any], geometry: RollerGeometry, family: BearingFamily,
            flat: Any, shape: tuple[int, ...], iso281: Mapping[str, Any], speed: NDArray
            ) -> tuple[Found, dict[str, Along]]:
    """A single bearing's results, its elements along ``element``."""
    misalignment = inputs.get("misalignment")
    solved = solve_roller_equilibrium(geometry, shared.applied_loads(
        inputs, flat, geometry.roller_count.size), fixed_tilt=None if misalignment is None
        else flat(misalignment))
    inner, outer, crushed = family.pressures(solved)
    rows = flat(inputs["rows"])
    per_roller = _per_roller(solved, rows)
    with np.errstate(invalid="ignore"):
        results = shared.equilibrium_results(solved, family.deflection(solved.displacement,
                                                                       solved))
    loads = np.nan_to_num(per_roller.element_load)
    results.update(max_element_load=np.max(loads, axis=1),
                   loaded_elements=np.sum(loads > 0, axis=1).astype(float))
    if misalignment is not None:
        results["tilting_moment_reaction"] = solved.reaction[:, 4]
    results.update(shared.rib_load(inputs, results["max_element_load"], flat))
    # rollers all round carry any radial load and moment: where such a ring finds no
    # equilibrium it was pushed past any small displacement, by a load too large
    one_way = traits(str(inputs["bearing_type"])).one_way
    runs_off = np.isinf(solved.residual) & (not one_way)
    found = shared.completed(inputs, Found(
        results, {"edge_loaded": family.edge_loaded(solved)},
        [(shared.NO_EQUILIBRIUM, ~solved.converged & ~runs_off),
         (shared.crushing_code(inputs, CONTACT_TOO_WIDE), crushed | runs_off)]),
        (inner, outer),
        family.life(solved), iso281, speed, shape, "roller")
    return found, {"element": _element_rows(per_roller, int(rows.max()), shape)}


def _per_roller(solved: Any, rows: NDArray) -> Any:
    """``solved`` with its elements the rollers of each row, the first row's Z and then
    the second's (NaN past Z, and in a second row a design does not have)."""
    row_count = int(rows.max())
    if row_count == 1:
        return solved
    double = (rows > 1)[:, None]
    per_row = row_loads(solved.lamina_load, row_count)
    return solved._replace(
        element_load=np.concatenate([per_row[:, :, 0],
                                     np.where(double, per_row[:, :, 1], np.nan)], axis=1),
        azimuth=np.concatenate([solved.azimuth, np.where(double, solved.azimuth, np.nan)],
                               axis=1))


def _element_rows(per_roller: Any, row_count: int, shape: tuple[int, ...]) -> Along:
    """Each roller's azimuth and load along ``element``; a double row's under a heading
    of each row."""
    along = shared.element_rows({"azimuth": per_roller.azimuth,
                                 "load": per_roller.element_load}, shape)
    if row_count == 1:
        return along
    z = len(along.rows) // row_count
    names = tuple(f"row_{i // z + 1}_element_{i % z + 1}" for i in range(len(along.rows)))
    headings = tuple(f"row {i // z + 1}: rolling elements as mounted"
                     for i in range(len(along.rows)))
    return Along(names, along.values, headings)


def _crown_fits(radius: NDArray, length: NDArray, diameter: NDArray) -> NDArray:
    """Where a crown of ``radius`` spans the roller and drops its ends by less than
    2 % of its diameter."""
    half = length / 2.0
    with np.errstate(invalid="ignore"):
        drop = radius - np.sqrt(radius * radius - half * half)
    return (radius > half) & (drop < CROWN_DROP_SHARE * diameter)


def _edge_loaded(lamina_load: NDArray, laminae: NDArray, rows: int = 1) -> NDArray:
    """Where a roller's end lamina (the first, or the design's last of its ``laminae``,
    of either row) carries more than the mean of its row's laminae."""
    n, z, width = lamina_load.shape
    loads = np.nan_to_num(lamina_load, nan=0.0).reshape(n, z, rows, width // rows)
    last = (laminae - 1)[:, None, None, None]
    ends = np.maximum(loads[..., 0], np.take_along_axis(
        loads, np.broadcast_to(last, (*loads.shape[:3], 1)), axis=3)[..., 0])
    mean = loads.sum(axis=3) / laminae[:, None, None]
    # a straight, untilted roller loads its laminae alike, to the rounding of their sum
    return np.any((ends > mean * (1.0 + 1e-9)) & (mean > 0), axis=(1, 2))
