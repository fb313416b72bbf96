"""A ball bearing as it is mounted (``method: iso-16281``): its operating clearance, the
rings' displacements under the loads and a tilting moment or misalignment, the load on
every ball, the reference rating life from them and the bearing's stiffness (ISO/TS
16281:2008). What every family shares is :mod:`bearingcalc.core.mounted_bearing`; here
are the balls' own results, warnings and status reasons.
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
from bearingcalc.core.iso16281_ball_contacts import (
    BallGeometry,
    ball_contacts_at,
    ball_deflections,
    ball_geometry,
    pushed_over_balls,
)
from bearingcalc.core.iso16281_balls import solve_ball_equilibrium
from bearingcalc.core.iso16281_life import (
    ball_reference_life,
    ball_spring_constant,
    largest_ball_contacts,
)
from bearingcalc.core.mounted_loads import below_minimum_load
from bearingcalc.core.mounted_pair import BearingFamily, pair_results
from bearingcalc.core.solver import Along

#: The ball bearing's results as mounted: the shared ones with its contact angles.
RESULTS = shared.results_with({
    "operating_contact_angle_min": ("rad", "the smallest contact angle of a loaded ball"),
    "operating_contact_angle_max": ("rad", "the largest contact angle of a loaded ball"),
}, after="load_zone_angle", pair=mounted_pair.RESULTS)
#: Warnings of the balls as mounted: flag -> message.
WARNINGS = {
    **shared.WARNINGS,
    "below_minimum_load": "the load on the balls is below 1 % of C, the makers' "
                          "minimum load of a ball bearing: the balls may skid",
}
#: The makers' minimum load of a ball bearing, a share of C.
MINIMUM_LOAD_SHARE = 0.01
#: by the input that loads the bearing beyond Hertz: (code, in words)
CONTACT_TOO_LARGE = {"radial_load": (26, "load"), "tilting_moment": (27, "tilting moment"),
                     "misalignment": (28, "misalignment"),
                     "operating_clearance": (34, "preload (negative clearance)"),
                     "setting.preload": (36, "preload"),
                     "setting.end_play": (37, "interference (negative end play)"),
                     "axial_load": (38, "axial load")}
#: The status code of a ring pushed over its balls (α ≥ 90°).
OVER_SHOULDER = 42
STATUS_REASONS = {
    **shared.STATUS_REASONS,
    OVER_SHOULDER: ("operating_clearance", "the clearance lets the axial load push the "
                    "ring over its balls (a contact angle of 90° or more, beyond the "
                    "groove's shoulder): no bearing has a clearance this large for its "
                    "balls; give the mounted bearing's, a few µm to a few tens of µm"),
    **mounted_pair.STATUS_REASONS,
    **{code: (field, DerivedTest(
        "the most heavily loaded ball's contact ellipse outgrows the ball (a semi-axis "
        "above Dw/2), or a pair's shaft moves beyond small displacements (a tilt above 10 "
        "mrad, a shift above a tenth of the pitch radius): the bearing's model does not "
        f"hold, and the bearing would be crushed; the {what} is too large for it"))
       for field, (code, what) in CONTACT_TOO_LARGE.items()},
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
    found.flags.update(below_minimum_load=below_minimum_load(
        inputs, found.results, iso281, c, MINIMUM_LOAD_SHARE))
    return found, along


def _family(inputs: Mapping[str, Any], flat: Any, c: NDArray
            ) -> tuple[BallGeometry, BearingFamily]:
    """The balls' groove centres, and what they give a bearing as mounted: their
    contacts, life and pressures."""
    one_way = traits(str(inputs["bearing_type"])).one_way
    z, dw, dpw, fi, fe, alpha = (flat(inputs[k]) for k in (
        "ball_count", "ball_diameter", "pitch_diameter", "inner_groove_conformity",
        "outer_groove_conformity", "contact_angle"))
    modulus, poisson = flat(inputs["elastic_modulus"]), flat(inputs["poisson_ratio"])
    nominal = alpha if one_way else np.zeros_like(alpha)
    spring = ball_spring_constant(dw, dpw, fi, fe, nominal, modulus, poisson)
    geometry = ball_geometry(z, dw, dpw, fi, fe, spring,
                             diametral_clearance=None if one_way else flat(
                                 shared.or_zero(inputs.get("operating_clearance"))),
                             free_contact_angle=alpha if one_way else None)
    rotates = flat(np.abs(inputs["inner_speed"]) >= np.abs(inputs["outer_speed"])) > 0

    def life(contacts: Any) -> Any:
        return ball_reference_life(contacts.element_load, z, dw, dpw, fi, fe, nominal,
                                   flat(c), inner_rotates=rotates)

    def pressures(contacts: Any) -> tuple[NDArray, NDArray, NDArray]:
        hertz = largest_ball_contacts(contacts.element_load, contacts.contact_angle, dw, dpw,
                                      fi, fe, modulus, poisson,
                                      quantities=("max_pressure", "semi_major"))
        return (*hertz["max_pressure"], ~(np.maximum(*hertz["semi_major"]) <= dw / 2.0))

    def deflection(q: NDArray, contacts: Any) -> NDArray:
        return ball_deflections(geometry, q, contacts.azimuth)

    offset = dpw / 2.0 * np.tan(nominal)
    return geometry, BearingFamily(
        "ball", lambda q: ball_contacts_at(geometry, q), offset, offset, np.zeros_like(z),
        dpw / 2.0, life, pressures, deflection, 3.0, CONTACT_TOO_LARGE)


def bearing_family(inputs: Mapping[str, Any], flat: Any, c: NDArray) -> BearingFamily:
    """What a ball bearing's inputs give a shaft as mounted (a pair's, a drive's)."""
    return _family(inputs, flat, c)[1]


def _single(inputs: Mapping[str, Any], geometry: BallGeometry, family: BearingFamily,
            flat: Any, shape: tuple[int, ...], iso281: Mapping[str, Any], speed: NDArray
            ) -> tuple[Found, dict[str, Along]]:
    """A single bearing's results, its balls along ``element``."""
    misalignment = inputs.get("misalignment")
    solved = solve_ball_equilibrium(geometry, shared.applied_loads(
        inputs, flat, geometry.ball_count.size), fixed_tilt=None if misalignment is None
        else flat(misalignment))
    inner, outer, crushed = family.pressures(solved)
    # only a clearance lets a deep-groove ring over its balls; an angular-contact
    # bearing's stationary point there lies beyond its shoulders, as any other refused
    over_shoulder = pushed_over_balls(geometry, solved.displacement, solved.azimuth
                                      ) & ~geometry.one_sided
    with np.errstate(invalid="ignore", all="ignore"):
        results = shared.equilibrium_results(solved, family.deflection(solved.displacement,
                                                                       solved))
        results.update(shared.contact_angle_range(solved.element_load,
                                                  solved.contact_angle))
    if misalignment is not None:
        results["tilting_moment_reaction"] = solved.reaction[:, 4]
    found = shared.completed(inputs, Found(results, checks=[
        (OVER_SHOULDER, over_shoulder),
        (shared.NO_EQUILIBRIUM, ~solved.converged & ~over_shoulder),
        (shared.crushing_code(inputs, CONTACT_TOO_LARGE), crushed)]), (inner, outer),
        family.life(solved), iso281, speed, shape, "ball")
    return found, {"element": shared.element_rows({"azimuth": solved.azimuth,
                                                   "load": solved.element_load,
                                                   "contact_angle": solved.contact_angle},
                                                  shape)}
