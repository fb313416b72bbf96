"""Roller bearings: rating life (ISO 281:2007), static safety (ISO 76:2006), the contacts
of the most heavily loaded roller and the rollers' kinematics.

Radial (cylindrical, needle, tapered, spherical) and thrust (cylindrical, tapered,
spherical) roller bearings, single, double-row or as a matched pair. :func:`evaluate`
composes the ratings (:mod:`bearingcalc.core.roller_ratings`), the life
(:mod:`bearingcalc.core.iso281`), the pairs (:mod:`bearingcalc.core.arrangements`) and
the contacts and kinematics (:mod:`bearingcalc.core.roller_bearing_contacts`). See
``docs/physics.md`` §5–§7.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core import (
    ball_bearing,
    mounted_bearing,
    mounted_clearance,
    mounted_loads,
    mounted_pair,
    mounted_roller_bearing,
    mounted_setting,
)
from bearingcalc.core.arrangements import DOUBLE_ROW_PAIRS, PAIRS, pair_ratings_used
from bearingcalc.core.bearing_life import operating_point, rating_life
from bearingcalc.core.bearing_types import LoadRule, traits
from bearingcalc.core.common import DerivedTest, Family, Found, balls_fit
from bearingcalc.core.iso76 import static_safety_factor
from bearingcalc.core.roller_bearing_contacts import (
    max_roller_load,
    roller_contacts,
    roller_kinematics,
)
from bearingcalc.core.roller_ratings import (
    roller_dynamic_load_rating,
    roller_equivalent_dynamic_load,
    roller_static_equivalent_load,
    roller_static_load_rating,
)
from bearingcalc.core.solver import Solution, Solver

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import RollingBearingInputs

FAMILY: Family = "roller"

_BALL = ball_bearing.RESULTS
#: Result keys, their SI unit and meaning, in report order.
RESULTS: dict[str, tuple[str, str]] = {
    **{key: _BALL[key] for key in ("dynamic_load_rating", "dynamic_load_rating_iso",
                                   "static_load_rating", "static_load_rating_iso",
                                   "pair_dynamic_load_rating", "pair_static_load_rating",
                                   "rating_factor", "fatigue_load_limit", "radial_factor",
                                   "axial_factor", "axial_ratio_limit",
                                   "equivalent_dynamic_load", "load_ratio",
                                   "basic_rating_life", "basic_rating_life_revolutions",
                                   "reliability_factor", "reference_viscosity",
                                   "operating_viscosity", "viscosity_ratio",
                                   "life_modification_factor", "modified_rating_life",
                                   "modified_rating_life_revolutions",
                                   "static_equivalent_load", "static_safety_factor",
                                   "life_margin", "static_safety_margin")},
    "max_roller_load": ("N", "Q of the most heavily loaded roller"),
    "inner_contact_pressure": _BALL["inner_contact_pressure"],
    "outer_contact_pressure": _BALL["outer_contact_pressure"],
    "inner_contact_half_width": ("m", "half-width b of the inner contact"),
    "outer_contact_half_width": ("m", "half-width b of the outer contact"),
    "max_contact_pressure": ("Pa", "the larger peak pressure"),
    "contact_pressure_margin": ("1", "1 − max_contact_pressure / limit"),
    "cage_frequency": _BALL["cage_frequency"],
    "ball_pass_frequency_outer": ("Hz", "BPFO = Z·|f_c − f_o|, the rollers' pass"),
    "ball_pass_frequency_inner": ("Hz", "BPFI = Z·|f_i − f_c|, the rollers' pass"),
    "roller_spin_frequency": ("Hz", "the roller's turns about its axis relative to the "
                                    "cage"),
    "cage_speed": _BALL["cage_speed"],
    **mounted_roller_bearing.RESULTS,
    **mounted_clearance.RESULTS,
    **mounted_setting.RESULTS,
}

GROUPS: dict[str, tuple[str, ...]] = {
    "ratings": ("dynamic_load_rating", "dynamic_load_rating_iso", "static_load_rating",
                "static_load_rating_iso", "pair_dynamic_load_rating",
                "pair_static_load_rating", "rating_factor", "fatigue_load_limit"),
    "loads": ball_bearing.GROUPS["loads"],
    "life": ball_bearing.GROUPS["life"],
    "static": ball_bearing.GROUPS["static"],
    "contact": ("max_roller_load", "inner_contact_pressure", "outer_contact_pressure",
                "inner_contact_half_width", "outer_contact_half_width",
                "max_contact_pressure", "contact_pressure_margin"),
    "kinematics": ("cage_frequency", "ball_pass_frequency_outer", "ball_pass_frequency_inner",
                   "roller_spin_frequency", "cage_speed"),
    mounted_bearing.GROUP: tuple(mounted_roller_bearing.RESULTS),
    mounted_clearance.GROUP: tuple(mounted_clearance.RESULTS),
    mounted_setting.GROUP: tuple(mounted_setting.RESULTS),
}

WARNINGS: dict[str, str] = {
    **{key: ball_bearing.WARNINGS[key] for key in ("kappa_capped", "aiso_capped")},
    "contact_ellipse_truncated": "the most heavily loaded roller's contact ellipse is longer "
                                 "than the roller (its semi-major axis exceeds Lwe/2): the "
                                 "contact reaches the roller's ends, where Hertz's point "
                                 "contact understates the pressure; check raceway_radius "
                                 "against roller_profile_radius",
    **mounted_roller_bearing.WARNINGS,
}

_CONTACT_TOO_WIDE = ("the most heavily loaded roller's contact is not narrow against the "
                     "roller (its half-width exceeds Dwe/4), so Hertz theory does not hold: "
                     "lower the load")
#: Status codes: those the ball bearings share keep their numbers (one reason per code
#: across both families); the roller bearings' own follow the ball bearings'.
STATUS_REASONS: dict[int, tuple[str, str]] = {
    **{code: ball_bearing.STATUS_REASONS[code] for code in (5, 7, 8, 9, 12, 13)},
    16: ("roller_diameter", "the roller must be smaller than the pitch diameter "
                            "(Dwe < Dpw)"),
    17: ("roller_count", DerivedTest("the rollers do not fit on the pitch circle: "
                                     "Z·asin(Dwe/Dpw) must be <= π")),
    18: ("roller_diameter", DerivedTest(
        "γ = Dwe·cosα/Dpw (Dwe/Dpw at α = 90°) is outside ISO 281's fc table of roller "
        "bearings (Table 7: 0.01 to 0.30; Table 10 of thrust bearings: to 0.30 at 90°, "
        "0.26, 0.20 or 0.15 below): give dynamic_load_rating from the catalogue")),
    19: ("contact_angle", "must be from 0 deg to 45 deg for a radial roller bearing, and "
                          "above 45 deg up to 90 deg for a thrust roller bearing"),
    20: ("axial_load", "a thrust roller bearing with α < 90° needs Fa/Fr > e = 1.5·tanα "
                       "(ISO 281 8.2): raise the axial load or lower the radial load"),
    21: ("radial_load", "a thrust roller bearing with α = 90° carries no radial load"),
    22: ("radial_load", _CONTACT_TOO_WIDE),
    23: ("axial_load", _CONTACT_TOO_WIDE),
    24: ("raceway_radius", DerivedTest(
        "the most heavily loaded roller's contact ellipse is more than twice the roller's "
        "length (its semi-major axis exceeds Lwe), so the crowned point contact of Hertz "
        "does not hold: raceway_radius is too close to roller_profile_radius (a spherical roller "
        "bearing's raceway radius is a few per cent larger), or the load too high")),
    **mounted_roller_bearing.STATUS_REASONS,
}


def evaluate(inputs: RollingBearingInputs,
             wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: results, warning flags and status codes from SI inputs
    (see :meth:`bearingcalc.models.rolling_bearing.RollingBearingSpec.solver_inputs`)."""
    bearing_type = str(inputs["bearing_type"])
    thrust = traits(bearing_type).thrust
    arrangement = str(inputs.get("arrangement") or "single")
    rows = np.asarray(1.0 if inputs.get("rows") is None else inputs["rows"], dtype=float)
    double_row = (rows > 1) | (arrangement in DOUBLE_ROW_PAIRS)
    z, dwe, lwe, dpw = (inputs.get(k) for k in ("roller_count", "roller_diameter",
                                                 "roller_length", "pitch_diameter"))
    has_geometry = all(value is not None for value in (z, dwe, lwe, dpw))
    alpha, fr, fa, speed = operating_point(inputs)
    angle_ok = ((alpha > np.pi / 4) & (alpha <= np.pi / 2) if thrust
                else (alpha >= 0) & (alpha <= np.pi / 4))
    # Checks in the order they are reported: the first that fails names the fault.
    found = Found(checks=[(19, ~angle_ok), (7, ~(speed > 0)),
                          (8, ~mounted_loads.loaded(inputs, fr, fa))])
    out = found.results
    c = _given(inputs.get("dynamic_load_rating"))
    c0 = _given(inputs.get("static_load_rating"))
    if has_geometry:
        z_a, dwe_a, lwe_a, dpw_a = (np.asarray(v, dtype=float) for v in (z, dwe, lwe, dpw))
        found.checks += [(16, ~(dwe_a < dpw_a)), (17, ~balls_fit(z_a, dwe_a / dpw_a))]
        drawn_cup = inputs.get("drawn_cup")
        c_iso, fc = roller_dynamic_load_rating(z_a, dwe_a, lwe_a, dpw_a, alpha, rows,
                                               bearing_type=bearing_type,
                                               drawn_cup=drawn_cup is not None and drawn_cup)
        c0_iso = roller_static_load_rating(z_a, dwe_a, lwe_a, dpw_a, alpha, rows,
                                           thrust=thrust)
        if c is None:
            found.checks.append((18, np.isnan(fc)))
        out.update(static_load_rating_iso=c0_iso, dynamic_load_rating_iso=c_iso,
                   rating_factor=fc)
        c = c_iso if c is None else c
        c0 = c0_iso if c0 is None else c0
    out["dynamic_load_rating"] = c
    c_used, c0_used, pair_results = pair_ratings_used(arrangement, c, c0, FAMILY)
    out.update(pair_results)
    p, load = _equivalent_dynamic_load(inputs, bearing_type, thrust, double_row, alpha, fr, fa)
    found.add(load)
    found.add(rating_life(inputs, thrust, speed, c_used, c0_used, p, family=FAMILY,
                          pair=arrangement in PAIRS))
    out["dynamic_load_rating"] = c
    p0 = roller_static_equivalent_load(fr, fa, alpha, bearing_type=bearing_type,
                                       double_row=double_row, x0=inputs.get("load_x0"),
                                       y0=inputs.get("load_y0"))
    if c0_used is not None:
        s0 = static_safety_factor(c0_used, p0)
        out.update(static_load_rating=c0, static_equivalent_load=p0,
                   static_safety_factor=s0,
                   static_safety_margin=s0 - np.asarray(inputs["min_static_safety"]))
    if has_geometry:
        found.add(_contacts(inputs, bearing_type, thrust, arrangement, rows, alpha, fa, p0))
        out.update(roller_kinematics(z, dwe, dpw, alpha, inputs["inner_speed"],
                                     inputs["outer_speed"], thrust))
    mounted, along = mounted_bearing.as_mounted(
        inputs, mounted_roller_bearing.mounted_results, c, out, speed)
    return Solution(*found.add(mounted).packed(RESULTS), along=along)


def _equivalent_dynamic_load(inputs: Mapping[str, ArrayLike | str | None], bearing_type: str,
                             thrust: bool, double_row: NDArray, alpha: NDArray, fr: NDArray,
                             fa: NDArray) -> tuple[NDArray, Found]:
    """P (ISO 281) and the factors applied; the thrust bearings' limits of Fa/Fr."""
    equivalent = roller_equivalent_dynamic_load(
        fr, fa, alpha, bearing_type=bearing_type, double_row=double_row,
        e=inputs.get("load_e"), y=inputs.get("load_y"), y1=inputs.get("load_y1"),
        y2=inputs.get("load_y2"), x=inputs.get("load_x"))
    found = Found({"radial_factor": equivalent.x, "axial_factor": equivalent.y})
    if thrust:
        right = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
        found.checks += [(21, right & (fr > 0)), (20, ~right & ~equivalent.combined)]
    else:
        found.checks.append((12, ~(equivalent.load > 0) & ((fr > 0) | (fa > 0))))
    if traits(bearing_type).load_rule is not LoadRule.RADIAL_ONLY:
        found.results["axial_ratio_limit"] = equivalent.e
    return equivalent.load, found


def _contacts(inputs: Mapping[str, ArrayLike | str | None], bearing_type: str, thrust: bool,
              arrangement: str, rows: NDArray, alpha: NDArray, fa: NDArray, p0: NDArray
              ) -> Found:
    """The most heavily loaded roller's line (or, crowned, point) contacts; a crowned
    roller's ellipse on its length: refused past 2·Lwe, a warning past Lwe."""
    sets = rows * (2.0 if arrangement in PAIRS else 1.0)
    load = max_roller_load(fa if thrust else p0, inputs["roller_count"], sets, alpha, thrust)
    spherical = traits(bearing_type).crowned
    contacts = roller_contacts(
        inputs["roller_diameter"], inputs["roller_length"], inputs["pitch_diameter"], alpha,
        thrust, load, inputs["elastic_modulus"], inputs["poisson_ratio"],
        inputs["max_contact_pressure"],
        inputs.get("roller_profile_radius") if spherical else None,
        inputs.get("raceway_radius") if spherical else None)
    widest = np.maximum(contacts["inner_contact_half_width"],
                        contacts["outer_contact_half_width"])
    found = Found({"max_roller_load": load, **contacts}, checks=[(
        23 if thrust else 22,
        ~(widest <= np.asarray(inputs["roller_diameter"], dtype=float) / 4.0))])
    if "inner_contact_semi_major" in contacts:  # a crowned roller's ellipse on its length
        longest = np.maximum(contacts["inner_contact_semi_major"],
                             contacts["outer_contact_semi_major"])
        length = np.asarray(inputs["roller_length"], dtype=float)
        found.checks.append((24, ~(longest <= length)))
        found.flags["contact_ellipse_truncated"] = longest > length / 2.0
    return found


def _given(value: ArrayLike | None) -> NDArray | None:
    return None if value is None else np.asarray(value, dtype=float)


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, WARNINGS, GROUPS,
                display=ball_bearing.DISPLAY, along=mounted_pair.ALONG,
                inputs="RollingBearingInputs")
