"""Ball bearings: rating life (ISO 281:2007), static safety (ISO 76:2006), the Hertz
contacts of the most heavily loaded ball and the kinematics of the balls.

Deep-groove, single-row angular-contact, and thrust with α = 90°. :func:`evaluate`, the
registry's entry point, composes the standards (:mod:`bearingcalc.core.iso281`,
:mod:`bearingcalc.core.iso76`), the contacts
(:mod:`bearingcalc.core.ball_bearing_contacts`) and the kinematics
(:mod:`bearingcalc.core.ball_bearing_kinematics`). See ``docs/physics.md`` §5–§7 for
the relations, their ranges and the sources.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core import (
    mounted_ball_bearing,
    mounted_bearing,
    mounted_clearance,
    mounted_loads,
    mounted_pair,
    mounted_setting,
)
from bearingcalc.core.arrangements import (
    DOUBLE_ROW_PAIRS,
    PAIRS,
    double_row_ball_factors,
    pair_ratings_used,
)
from bearingcalc.core.ball_bearing_contacts import ball_contacts
from bearingcalc.core.ball_bearing_kinematics import ball_kinematics
from bearingcalc.core.bearing_life import operating_point, rating_life
from bearingcalc.core.bearing_types import LoadRule, traits
from bearingcalc.core.common import DerivedTest, Family, Found, balls_fit
from bearingcalc.core.iso76 import static_equivalent_load, static_load_rating, static_safety_factor
from bearingcalc.core.iso281 import dynamic_load_rating, equivalent_dynamic_load
from bearingcalc.core.solver import Solution, Solver

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import RollingBearingInputs

#: The rolling elements of every bearing this solver takes.
FAMILY: Family = "ball"

#: ISO 281:2007 Table 3, self-aligning ball bearings: X for Fa/Fr > e.
SELF_ALIGNING_X = 0.65

#: Result keys, their SI unit and meaning, in report order.
RESULTS: dict[str, tuple[str, str]] = {
    "dynamic_load_rating": ("N", "C of one bearing (a pair's life uses the pair's)"),
    "dynamic_load_rating_iso": ("N", "C from the geometry (ISO 281)"),
    "static_load_rating": ("N", "C0 of one bearing (a pair's s0 uses the pair's)"),
    "static_load_rating_iso": ("N", "C0 from the geometry (ISO 76)"),
    "pair_dynamic_load_rating": ("N", "C of the matched pair, used for the life"),
    "pair_static_load_rating": ("N", "C0 of the matched pair, used for s0"),
    "rating_factor": ("1", "fc (ISO 281 Table 2 or 4; roller bearings Table 7, thrust 10)"),
    "static_rating_factor": ("1", "f0 used"),
    "fatigue_load_limit": ("N", "Cu used"),
    "radial_factor": ("1", "X applied"),
    "axial_factor": ("1", "Y applied"),
    "axial_ratio_limit": ("1", "e"),
    "equivalent_dynamic_load": ("N", "P"),
    "load_ratio": ("1", "C/P"),
    "basic_rating_life": ("s", "L10 in time"),
    "basic_rating_life_revolutions": ("1", "L10 in revolutions"),
    "reliability_factor": ("1", "a1 (ISO 281 Table 12 formula)"),
    "reference_viscosity": ("m²/s", "ν1, the viscosity needed for separation"),
    "operating_viscosity": ("m²/s", "ν at the operating temperature"),
    "viscosity_ratio": ("1", "κ = ν/ν1 (capped at 4)"),
    "life_modification_factor": ("1", "aISO"),
    "modified_rating_life": ("s", "Lnm in time"),
    "modified_rating_life_revolutions": ("1", "Lnm in revolutions"),
    "static_equivalent_load": ("N", "P0"),
    "static_safety_factor": ("1", "s0 = C0/P0"),
    "life_margin": ("1", "modified_rating_life (as mounted: modified_reference_rating_life) "
                    "/ min_rating_life − 1"),
    "static_safety_margin": ("1", "s0 − min_static_safety"),
    "max_ball_load": ("N", "Q of the most heavily loaded ball"),
    "inner_contact_pressure": ("Pa", "Hertz peak pressure at the inner race"),
    "outer_contact_pressure": ("Pa", "Hertz peak pressure at the outer race"),
    "inner_contact_semi_major": ("m", "semi-major axis a of the inner contact ellipse"),
    "inner_contact_semi_minor": ("m", "semi-minor axis b of the inner contact ellipse"),
    "outer_contact_semi_major": ("m", "semi-major axis a of the outer contact ellipse"),
    "outer_contact_semi_minor": ("m", "semi-minor axis b of the outer contact ellipse"),
    "inner_contact_approach": ("m", "approach δ of ball and inner race"),
    "outer_contact_approach": ("m", "approach δ of ball and outer race"),
    "max_contact_pressure": ("Pa", "the larger peak pressure"),
    "contact_pressure_margin": ("1", "1 − max_contact_pressure / limit"),
    "cage_frequency": ("Hz", "cage speed f_c (FTF), signed with the rings"),
    "ball_pass_frequency_outer": ("Hz", "BPFO = Z·|f_c − f_o|"),
    "ball_pass_frequency_inner": ("Hz", "BPFI = Z·|f_i − f_c|"),
    "ball_spin_frequency": ("Hz", "BSF, the ball's turns about its axis relative to the cage"),
    "cage_speed": ("rad/s", "cage angular velocity in the fixed frame, signed"),
    "ball_speed_relative_to_cage": ("rad/s", "the ball's speed about its own axis, "
                                             "cage frame"),
    "ball_attitude_angle": ("rad", "angle β of the ball's spin axis from the bearing axis "
                                   "(its sense: docs/kinds/ball-bearing.md)"),
    "inner_spin_to_roll": ("1", "spin/roll of the inner race relative to the ball"),
    "outer_spin_to_roll": ("1", "spin/roll of the outer race relative to the ball"),
    "spin_to_roll_margin": ("1", "max_spin_to_roll − the larger |spin_to_roll|"),
    **mounted_ball_bearing.RESULTS,
    **mounted_clearance.RESULTS,
    **mounted_setting.RESULTS,
}

#: Headings of the table, each with its results.
GROUPS: dict[str, tuple[str, ...]] = {
    "ratings": ("dynamic_load_rating", "dynamic_load_rating_iso", "static_load_rating",
                "static_load_rating_iso", "pair_dynamic_load_rating",
                "pair_static_load_rating", "rating_factor", "static_rating_factor",
                "fatigue_load_limit"),
    "loads": ("radial_factor", "axial_factor", "axial_ratio_limit", "equivalent_dynamic_load",
              "load_ratio"),
    "life": ("basic_rating_life", "basic_rating_life_revolutions", "reliability_factor",
             "reference_viscosity", "operating_viscosity", "viscosity_ratio",
             "life_modification_factor", "modified_rating_life",
             "modified_rating_life_revolutions", "life_margin"),
    "static": ("static_equivalent_load", "static_safety_factor", "static_safety_margin"),
    "contact": ("max_ball_load", "inner_contact_pressure", "outer_contact_pressure",
                "inner_contact_semi_major", "inner_contact_semi_minor",
                "outer_contact_semi_major", "outer_contact_semi_minor",
                "inner_contact_approach", "outer_contact_approach", "max_contact_pressure",
                "contact_pressure_margin"),
    "kinematics": ("cage_frequency", "ball_pass_frequency_outer", "ball_pass_frequency_inner",
                   "ball_spin_frequency", "cage_speed", "ball_speed_relative_to_cage",
                   "ball_attitude_angle", "inner_spin_to_roll", "outer_spin_to_roll",
                   "spin_to_roll_margin"),
    mounted_bearing.GROUP: tuple(mounted_ball_bearing.RESULTS),
    mounted_clearance.GROUP: tuple(mounted_clearance.RESULTS),
    mounted_setting.GROUP: tuple(mounted_setting.RESULTS),
}

#: How tables show results whose SI unit alone does not say it (revolutions in millions).
DISPLAY: dict[str, tuple[str, float]] = {
    "basic_rating_life_revolutions": ("10⁶ rev", 1e-6),
    "modified_rating_life_revolutions": ("10⁶ rev", 1e-6),
    "reference_rating_life_revolutions": ("10⁶ rev", 1e-6),
}

#: Conditions the solver reports per design as warnings: flag key -> message.
WARNINGS: dict[str, str] = {
    "axial_ratio_low": "f0·Fa/C0 is below 0.172, the first row of ISO 281 Table 3: "
                             "e and Y of that row are used",
    "axial_ratio_high": "f0·Fa/C0 is above 6.89, the last row of ISO 281 Table 3: "
                              "e and Y of that row are used",
    "kappa_capped": "κ is above 4: ISO 281 takes κ = 4 for aISO",
    "aiso_capped": "aISO reached its cap of 50",
    **mounted_ball_bearing.WARNINGS,
}

FEASIBLE = 0
_CONTACT_TOO_LARGE = ("the most heavily loaded ball's contact ellipse is not small against "
                      "the ball (its semi-major axis exceeds Dw/2), so Hertz theory does not "
                      "hold: lower the load, or check the groove conformities (near 0.5 the "
                      "ellipse grows long)")
STATUS_REASONS: dict[int, tuple[str, str]] = {
    1: ("ball_diameter", "the ball must be smaller than the pitch diameter (Dw < Dpw)"),
    2: ("ball_count", DerivedTest("the balls do not fit on the pitch circle: Z·asin(Dw/Dpw) "
                                  "must be <= π")),
    3: ("ball_diameter", DerivedTest("γ = Dw·cosα/Dpw is outside ISO 281's fc table (0.01 "
                                     "to 0.40 for radial, 0.01 to 0.35 for thrust "
                                     "bearings)")),
    4: ("ball_diameter", DerivedTest("γ = Dw·cosα/Dpw is outside ISO 76's f0 table (0 to "
                                     "0.40)")),
    5: ("lubrication", "the viscosity ratio κ = ν/ν1 is below 0.1, outside ISO 281; use a "
                       "more viscous oil or give no lubrication"),
    6: ("contact_angle", "the contact angle must be from 0 deg to below 90 deg for a radial "
                         "bearing"),
    7: ("speed", "the speed must be positive"),
    8: ("radial_load", "the equivalent load is zero: give a radial or an axial load"),
    9: ("lubrication", "the viscosity at the operating temperature cannot be found from "
                       "viscosity_40 and viscosity_100 (ν40 must exceed ν100)"),
    10: ("inner_groove_conformity", "must exceed 0.5: the ball would not fit its groove"),
    11: ("outer_groove_conformity", "must exceed 0.5: the ball would not fit its groove"),
    12: ("load_factors.y", "the equivalent load P = X·Fr + Y·Fa is zero: the load factors "
                           "leave out the load the bearing carries; give the catalogue's X "
                           "and Y, above 0"),
    13: ("lubrication.temperature", "Walther's viscosity–temperature relation (ASTM D341) "
                                    "gives a viscosity above 10⁶ mm²/s here, a solid far "
                                    "below the oil's pour point: give a warmer operating "
                                    "temperature, or the viscosity itself"),
    14: ("radial_load", _CONTACT_TOO_LARGE),
    15: ("axial_load", _CONTACT_TOO_LARGE),
    **mounted_ball_bearing.STATUS_REASONS,
}


def _contact_too_large(contacts: Mapping[str, NDArray], dw: ArrayLike, fr: NDArray,
                       fa: NDArray, thrust: bool) -> list[tuple[int, NDArray]]:
    """Where a contact ellipse outgrows the ball (a semi-axis above Dw/2), named by the
    load that dominates, the one to lower: codes 15 (axial) and 14 (radial)."""
    largest = np.maximum(contacts["inner_contact_semi_major"],
                         contacts["outer_contact_semi_major"])
    too_large = ~(largest <= np.asarray(dw) / 2.0)
    axial_heavier = thrust | (np.asarray(fa) > np.asarray(fr))
    return [(15, too_large & axial_heavier), (14, too_large & ~axial_heavier)]


def evaluate(inputs: RollingBearingInputs,
             wanted: Collection[str] | None = None) -> Solution:
    """Registry entry point: results, warning flags and status codes from SI inputs.

    ``inputs`` (see :meth:`bearingcalc.models.rolling_bearing.RollingBearingSpec.solver_inputs`)
    may leave optional groups out (None): ratings given or geometry, lubrication,
    load factors, limits. Which results exist depends only on which inputs are
    given, so specs stacked into one call share their result keys.
    """
    bearing_type = str(inputs["bearing_type"])
    thrust = traits(bearing_type).thrust
    z, dw, dpw = (inputs.get(k) for k in ("ball_count", "ball_diameter", "pitch_diameter"))
    has_geometry = z is not None and dw is not None and dpw is not None
    alpha, fr, fa, speed = operating_point(inputs)
    # Checks in the order they are reported: the first that fails names the fault.
    found = Found(checks=[] if thrust else [(6, ~((alpha >= 0) & (alpha < np.pi / 2)))])
    found.checks += [(7, ~(speed > 0)), (8, ~mounted_loads.loaded(inputs, fr, fa))]
    out = found.results

    c_iso = c0_iso = f0_iso = None
    if has_geometry:
        c_iso, c0_iso, f0_iso, ratings = _ratings(z, dw, dpw, alpha, thrust)
        found.add(ratings)
    c = _given_or(inputs.get("dynamic_load_rating"), c_iso)
    c0 = _given_or(inputs.get("static_load_rating"), c0_iso)
    f0 = _given_or(inputs.get("static_factor"), f0_iso)
    arrangement = str(inputs.get("arrangement") or "single")
    double_row = arrangement in DOUBLE_ROW_PAIRS or traits(bearing_type).double_row_form
    c_used, c0_used, pair_results = pair_ratings_used(arrangement, c, c0, FAMILY)
    out.update(pair_results)
    if double_row:
        p, load = _double_row_load(inputs, bearing_type, alpha, fr, fa)
    else:
        p, load = _equivalent_dynamic_load(inputs, bearing_type, alpha, fr, fa, f0, c0)
    found.add(load)
    found.add(rating_life(inputs, thrust, speed, c_used, c0_used, p,
                          pair=arrangement in PAIRS))
    out["dynamic_load_rating"] = c
    p0, static = _static(inputs, bearing_type, alpha, fr, fa, c0, c0_used, f0, double_row)
    out.update(static)

    if has_geometry:
        out.update(ball_kinematics(z, dw, dpw, alpha, inputs["inner_speed"],
                                   inputs["outer_speed"], str(inputs["race_control"]),
                                   thrust))
        if inputs.get("max_spin_to_roll") is not None:
            out["spin_to_roll_margin"] = np.asarray(inputs["max_spin_to_roll"]) - np.maximum(
                np.abs(out["inner_spin_to_roll"]), np.abs(out["outer_spin_to_roll"]))

    if has_geometry and inputs.get("inner_groove_conformity") is not None:
        fi = np.asarray(inputs["inner_groove_conformity"], dtype=float)
        fo = np.asarray(inputs["outer_groove_conformity"], dtype=float)
        found.checks += [(10, ~(fi > 0.5)), (11, ~(fo > 0.5))]
        sets = 2.0 if arrangement in PAIRS else 1.0
        contacts = ball_contacts(np.asarray(z, dtype=float) * sets, dw, dpw, alpha, thrust,
                                 p0, fi, fo,
                                 inputs["elastic_modulus"], inputs["poisson_ratio"],
                                 inputs["max_contact_pressure"])
        out.update(contacts)
        found.checks += _contact_too_large(contacts, dw, fr, fa, thrust)

    mounted, along = mounted_bearing.as_mounted(inputs, mounted_ball_bearing.mounted_results,
                                                c, out, speed)
    return Solution(*found.add(mounted).packed(RESULTS), along=along)


def _ratings(z: ArrayLike, dw: ArrayLike, dpw: ArrayLike, alpha: NDArray, thrust: bool
             ) -> tuple[NDArray, NDArray | None, NDArray | None, Found]:
    """C from the geometry (ISO 281) and, for radial bearings, C0 and f0 (ISO 76)."""
    dw_a, dpw_a, z_a = (np.asarray(v, dtype=float) for v in (dw, dpw, z))
    c_iso, fc = dynamic_load_rating(z_a, dw_a, dpw_a, alpha, thrust, family=FAMILY)
    found = Found({"dynamic_load_rating_iso": c_iso, "rating_factor": fc},
                  checks=[(1, ~(dw_a < dpw_a)), (2, ~balls_fit(z_a, dw_a / dpw_a)),
                          (3, np.isnan(fc))])
    if thrust:  # ISO 76's thrust f0 is not implemented: C0 only from the catalogue
        return c_iso, None, None, found
    c0_iso, f0_iso = static_load_rating(z_a, dw_a, dpw_a, alpha, family=FAMILY)
    found.checks.append((4, np.isnan(f0_iso)))
    found.results["static_load_rating_iso"] = c0_iso
    return c_iso, c0_iso, f0_iso, found


def _equivalent_dynamic_load(inputs: Mapping[str, ArrayLike | str | None], bearing_type: str,
                             alpha: NDArray, fr: NDArray, fa: NDArray, f0: NDArray | None,
                             c0: NDArray | None) -> tuple[NDArray, Found]:
    """P (ISO 281), with the factors applied and the flags of Table 3's ends."""
    given = (None if inputs.get("load_x") is None
             else (inputs["load_x"], inputs["load_y"], inputs["load_e"]))
    equivalent = equivalent_dynamic_load(fr, fa, bearing_type, alpha, static_factor=f0,
                                         static_load_rating=c0, load_factors=given,
                                         family=FAMILY)
    p = equivalent.load
    if traits(bearing_type).thrust:
        return p, Found({"radial_factor": np.zeros_like(p), "axial_factor": np.ones_like(p)})
    found = Found(checks=[(12, ~(p > 0) & ((fr > 0) | (fa > 0)))])
    if equivalent.ratio_below_table is not None:
        found.flags.update(axial_ratio_low=equivalent.ratio_below_table,
                           axial_ratio_high=equivalent.ratio_above_table)
    if not np.isnan(np.asarray(equivalent.e)).all():
        found.results.update(radial_factor=np.where(equivalent.combined, equivalent.x, 1.0),
                             axial_factor=np.where(equivalent.combined, equivalent.y, 0.0),
                             axial_ratio_limit=equivalent.e)
    return p, found


def _static(inputs: Mapping[str, ArrayLike | str | None], bearing_type: str, alpha: NDArray,
            fr: NDArray, fa: NDArray, c0: NDArray | None, c0_used: NDArray | None,
            f0: NDArray | None, double_row: bool) -> tuple[NDArray, dict[str, ArrayLike]]:
    """P0 and, where C0 is known, s0 (ISO 76) with the results that report it; a pair's
    s0 from its C0."""
    if double_row:
        y0 = inputs.get("load_y0")
        if y0 is None:
            y0 = 0.0 if _self_aligning(bearing_type) else double_row_ball_factors(alpha).y0
        p0 = fr + np.asarray(y0, dtype=float) * fa
    else:
        p0 = static_equivalent_load(fr, fa, bearing_type, alpha,
                                    radial_factor=inputs.get("load_x0"),
                                    axial_factor=inputs.get("load_y0"), family=FAMILY)
    if c0_used is None:
        return p0, {}
    s0 = static_safety_factor(c0_used, p0)
    reported = {"static_load_rating": c0, "static_equivalent_load": p0,
                "static_safety_factor": s0,
                "static_safety_margin": s0 - np.asarray(inputs["min_static_safety"])}
    if f0 is not None:
        reported["static_rating_factor"] = f0
    return p0, reported


def _double_row_load(inputs: Mapping[str, ArrayLike | str | None], bearing_type: str,
                     alpha: NDArray, fr: NDArray, fa: NDArray) -> tuple[NDArray, Found]:
    """P of a double-row bearing (ISO 281 Table 3): a back-to-back or face-to-face pair
    of angular-contact bearings, or a self-aligning ball bearing: X = 1, Y = Y1 up to e;
    X2, Y2 above. The catalogue's e, Y1, X, Y2 replace the table's; a self-aligning
    bearing has X2 = 0.65 and takes its Y from the catalogue (or none: a radial load)."""
    table = double_row_ball_factors(alpha)
    given = inputs.get("load_e") is not None
    self_aligning = _self_aligning(bearing_type)
    if not given and self_aligning:
        table = table._replace(y_below=0.0, y_above=0.0, e=np.inf + 0.0 * alpha)
    e = np.asarray(inputs["load_e"], dtype=float) if given else table.e
    y_below = np.asarray(inputs["load_y1"], dtype=float) if given else table.y_below
    x_default = SELF_ALIGNING_X if self_aligning else table.x_above
    x_above = (np.asarray(inputs["load_x"], dtype=float)
               if inputs.get("load_x") is not None else x_default)
    y_above = np.asarray(inputs["load_y2"], dtype=float) if given else table.y_above
    with np.errstate(divide="ignore", invalid="ignore"):
        combined = (fa > 0) & ~(fa / fr <= e)
    x = np.where(combined, x_above, 1.0)
    y = np.where(combined, y_above, y_below)
    p = x * fr + y * fa
    found = Found({"radial_factor": x, "axial_factor": y},
                  checks=[(12, ~(p > 0) & ((fr > 0) | (fa > 0)))])
    if given or not self_aligning:
        found.results["axial_ratio_limit"] = e + 0.0 * p
    return p, found


def _self_aligning(bearing_type: str) -> bool:
    """A self-aligning ball bearing: its P is a double row's, X = 0.65 above e."""
    return traits(bearing_type).load_rule is LoadRule.SELF_ALIGNING


def _given_or(given: ArrayLike | None, computed: NDArray | None) -> NDArray | None:
    """The catalogue value where the spec gives one, else the value from the geometry."""
    if given is not None:
        return np.asarray(given, dtype=float)
    return computed


SOLVER = Solver(evaluate, RESULTS, STATUS_REASONS, WARNINGS, GROUPS, display=DISPLAY,
                along=mounted_pair.ALONG,
                inputs="RollingBearingInputs")
