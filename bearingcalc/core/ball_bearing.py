"""Rolling-bearing sizing: ISO 281:2007 rating life and ISO 76:2006 static safety.

Ball bearings only (deep-groove, single-row angular-contact, thrust with α = 90°).
Every function takes SI values as floats or numpy arrays, which broadcast, and
returns arrays; inside, the standards' formulas are written in their own units
(N, mm, r/min, mm²/s) and converted at the edge. See ``docs/physics.md`` §5 for
the relations, their ranges and the sources.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.common import first_failure
from bearingcalc.core.hertz import hertz_point_contact

#: ISO 281:2007 bm, the rating factor for contemporary, normally used material. [1]
MATERIAL_FACTOR = 1.3
#: Ball diameter above which ISO 281 uses the Dw^1.4 form of C. [mm]
LARGE_BALL_MM = 25.4
MM, NEWTON = 1e3, 1.0  # SI -> the standards' units
RPM = 60.0 / (2.0 * np.pi)

#: ISO 281:2007 Table 2: fc of single-row radial and angular-contact groove ball bearings
#: against γ = Dw·cosα/Dpw.
RADIAL_FC_GAMMA = np.array([0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.10,
                            0.12, 0.14, 0.16, 0.18, 0.20, 0.22, 0.24, 0.26, 0.28, 0.30,
                            0.32, 0.34, 0.36, 0.38, 0.40])
RADIAL_FC = np.array([29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
                      57.5, 58.8, 59.6, 59.9, 59.9, 59.6, 59.0, 58.2, 57.1, 56.0,
                      54.6, 53.2, 51.7, 50.0, 48.4])
#: ISO 281:2007 Table 4: fc of thrust ball bearings with α = 90° against γ = Dw/Dpw.
THRUST_FC_GAMMA = np.round(np.arange(1, 36) * 0.01, 2)
THRUST_FC = np.array([36.7, 45.2, 51.1, 55.7, 59.5, 62.9, 65.8, 68.5, 71.0, 73.3,
                      75.4, 77.4, 79.3, 81.1, 82.7, 84.4, 85.9, 87.4, 88.8, 90.2,
                      91.5, 92.8, 94.1, 95.3, 96.4, 97.6, 98.7, 99.8, 100.8, 101.9,
                      102.9, 103.9, 104.8, 105.8, 106.7])
#: ISO 76:2006 Table 1: f0 of radial and angular-contact groove ball bearings against γ.
STATIC_F0_GAMMA = np.round(np.arange(0, 41) * 0.01, 2)
STATIC_F0 = np.array([14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5,
                      16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2,
                      14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
                      11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4])
#: ISO 281:2007 Table 3, single-row deep-groove: f0·Fa/C0 -> (e, Y), with X = 0.56.
DEEP_GROOVE_RATIO = np.array([0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89])
DEEP_GROOVE_E = np.array([0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44])
DEEP_GROOVE_Y = np.array([2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00])
DEEP_GROOVE_X = 0.56
#: ISO 281:2007 Table 3, single-row angular-contact: α -> (X, Y, e).
ANGULAR_ALPHA_DEG = np.array([20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
ANGULAR_X = np.array([0.43, 0.41, 0.39, 0.37, 0.35, 0.33])
ANGULAR_Y = np.array([1.00, 0.87, 0.76, 0.66, 0.57, 0.50])
ANGULAR_E = np.array([0.57, 0.68, 0.80, 0.95, 1.14, 1.34])
#: ISO 76:2006 static factors: deep-groove X0, Y0; angular-contact X0 and Y0 by α.
DEEP_GROOVE_X0, DEEP_GROOVE_Y0 = 0.6, 0.5
ANGULAR_X0 = 0.5
ANGULAR_Y0 = np.array([0.42, 0.38, 0.33, 0.29, 0.26, 0.22])
#: ISO 281:2007 aISO for radial ball bearings: (κ from, A, b) of each viscosity band.
AISO_BANDS = ((0.1, 2.2649, 0.054381), (0.4, 1.9987, 0.19087), (1.0, 1.9987, 0.071739))
AISO_CAP = 50.0
KAPPA_CAP = 4.0
KAPPA_MIN = 0.1
#: Kelvin of the two ASTM D341 reference temperatures.
T40, T100 = 313.15, 373.15
#: Most operating viscosity taken from Walther's equation: 10⁶ mm²/s is a solid, far
#: below an oil's pour point, where the viscosity–temperature relation no longer holds.
MAX_OPERATING_VISCOSITY = 1.0

#: Bearing types, as the spec names them, and their codes in solver inputs.
TYPES = ("deep-groove", "angular-contact", "thrust")

#: Result keys, their SI unit and meaning, in report order.
RESULTS: dict[str, tuple[str, str]] = {
    "dynamic_load_rating": ("N", "C used for the life"),
    "dynamic_load_rating_iso": ("N", "C from the geometry (ISO 281)"),
    "static_load_rating": ("N", "C0 used"),
    "static_load_rating_iso": ("N", "C0 from the geometry (ISO 76)"),
    "rating_factor": ("1", "fc (ISO 281 Table 2 or 4)"),
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
    "life_margin": ("1", "modified_rating_life / min_rating_life − 1"),
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
                                   "(README: its sense)"),
    "inner_spin_to_roll": ("1", "spin/roll of the inner race relative to the ball"),
    "outer_spin_to_roll": ("1", "spin/roll of the outer race relative to the ball"),
    "spin_to_roll_margin": ("1", "max_spin_to_roll − the larger |spin_to_roll|"),
}

#: Headings of the table, each with its results.
GROUPS: dict[str, tuple[str, ...]] = {
    "ratings": ("dynamic_load_rating", "dynamic_load_rating_iso", "static_load_rating",
                "static_load_rating_iso", "rating_factor", "static_rating_factor",
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
}

#: How tables show results whose SI unit alone does not say it (revolutions in millions).
DISPLAY: dict[str, tuple[str, float]] = {
    "basic_rating_life_revolutions": ("10⁶ rev", 1e-6),
    "modified_rating_life_revolutions": ("10⁶ rev", 1e-6),
}

#: Conditions the solver reports per design as warnings: flag key -> message.
WARNINGS: dict[str, str] = {
    "_warn_axial_ratio_low": "f0·Fa/C0 is below 0.172, the first row of ISO 281 Table 3: "
                             "e and Y of that row are used",
    "_warn_axial_ratio_high": "f0·Fa/C0 is above 6.89, the last row of ISO 281 Table 3: "
                              "e and Y of that row are used",
    "_warn_kappa_capped": "κ is above 4: ISO 281 takes κ = 4 for aISO",
    "_warn_aiso_capped": "aISO reached its cap of 50",
}

FEASIBLE = 0
_CONTACT_TOO_LARGE = ("the most heavily loaded ball's contact ellipse is not small against "
                      "the ball (its semi-major axis exceeds Dw/2), so Hertz theory does not "
                      "hold: lower the load, or check the groove conformities (near 0.5 the "
                      "ellipse grows long)")
STATUS_REASONS: dict[int, tuple[str, str]] = {
    1: ("ball_diameter", "the ball must be smaller than the pitch diameter (Dw < Dpw)"),
    2: ("ball_count", "the balls do not fit on the pitch circle: Z·asin(Dw/Dpw) must be "
                      "<= π"),
    3: ("ball_diameter", "γ = Dw·cosα/Dpw is outside ISO 281's fc table (0.01 to 0.40 for "
                         "radial, 0.01 to 0.35 for thrust bearings)"),
    4: ("ball_diameter", "γ = Dw·cosα/Dpw is outside ISO 76's f0 table (0 to 0.40)"),
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
}


def table_lookup(x: ArrayLike, xs: NDArray, ys: NDArray) -> NDArray:
    """Linear interpolation in a table; NaN outside its range (no extrapolation)."""
    x = np.asarray(x, dtype=float)
    inside = (x >= xs[0]) & (x <= xs[-1])
    return np.where(inside, np.interp(x, xs, ys), np.nan)


def dynamic_load_rating(ball_count: ArrayLike, ball_diameter: ArrayLike,
                        pitch_diameter: ArrayLike, contact_angle: ArrayLike,
                        thrust: ArrayLike = False) -> tuple[NDArray, NDArray]:
    r"""Basic dynamic load rating C of a single-row ball bearing, and its fc.

    .. math:: C = b_m f_c (\cos\alpha)^{0.7} Z^{2/3} D_w^{1.8} \quad (D_w \le 25.4\,mm),
              \qquad 3.647\, b_m f_c (\cos\alpha)^{0.7} Z^{2/3} D_w^{1.4} \quad (D_w > 25.4\,mm)

    with C in N and Dw in mm, fc from Table 2 at γ = Dw·cosα/Dpw. Thrust bearings
    (α = 90°) drop the cos α factor and take fc from Table 4 at γ = Dw/Dpw.

    Parameters
    ----------
    ball_count : Z. [1]
    ball_diameter : Dw. [m]
    pitch_diameter : Dpw. [m]
    contact_angle : α (ignored for thrust). [rad]
    thrust : True for a thrust ball bearing with α = 90°.

    Returns
    -------
    (C [N], fc [1]); NaN where γ is outside the table.

    Source: ISO 281:2007, 6.1.1 and 6.2.1 (eqs. 2, 3; Tables 2 and 4).

    >>> c, fc = dynamic_load_rating(8, 17.462e-3, 72.5e-3, 0.0)
    >>> round(float(fc), 2), round(float(c))
    (58.97, 52768)
    """
    z = np.asarray(ball_count, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float) * MM
    dpw = np.asarray(pitch_diameter, dtype=float) * MM
    alpha = np.asarray(contact_angle, dtype=float)
    thrust = np.asarray(thrust, dtype=bool)
    cos_alpha = np.where(thrust, 1.0, np.cos(alpha))
    gamma = dw * cos_alpha / dpw
    fc = np.where(thrust, table_lookup(gamma, THRUST_FC_GAMMA, THRUST_FC),
                  table_lookup(gamma, RADIAL_FC_GAMMA, RADIAL_FC))
    base = MATERIAL_FACTOR * fc * cos_alpha ** 0.7 * z ** (2.0 / 3.0)
    rating = np.where(dw <= LARGE_BALL_MM, base * dw ** 1.8, 3.647 * base * dw ** 1.4)
    return rating * NEWTON, fc


def static_load_rating(ball_count: ArrayLike, ball_diameter: ArrayLike,
                       pitch_diameter: ArrayLike, contact_angle: ArrayLike
                       ) -> tuple[NDArray, NDArray]:
    r"""Basic static load rating C0 of a radial ball bearing, and its f0.

    .. math:: C_0 = f_0 Z D_w^2 \cos\alpha

    with C0 in N and Dw in mm, f0 from Table 1 at γ = Dw·cosα/Dpw.

    Source: ISO 76:2006, 6.1.1 (eq. 1, Table 1).

    >>> c0, f0 = static_load_rating(9, 7.938e-3, 38.5e-3, 0.0)
    >>> round(float(f0), 3), round(float(c0))
    (13.815, 7834)
    """
    z = np.asarray(ball_count, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float) * MM
    dpw = np.asarray(pitch_diameter, dtype=float) * MM
    cos_alpha = np.cos(np.asarray(contact_angle, dtype=float))
    f0 = table_lookup(dw * cos_alpha / dpw, STATIC_F0_GAMMA, STATIC_F0)
    return f0 * z * dw ** 2 * cos_alpha * NEWTON, f0


def reliability_factor(reliability: ArrayLike) -> NDArray:
    r"""Life adjustment factor for reliability a1.

    .. math:: a_1 = 0.95 \left(\frac{\ln(100/R)}{\ln(100/90)}\right)^{2/3} + 0.05

    with R in percent; it reproduces ISO 281:2007 Table 12 (95 % → 0.64,
    99 % → 0.25, 99.95 % → 0.077).

    Parameters
    ----------
    reliability : R as a fraction, 0.9 <= R <= 0.9995. [1]

    >>> [round(float(reliability_factor(r)), 3) for r in (0.9, 0.95, 0.99, 0.9995)]
    [1.0, 0.638, 0.248, 0.077]
    """
    r = np.asarray(reliability, dtype=float)
    return 0.95 * (np.log(1.0 / r) / np.log(1.0 / 0.9)) ** (2.0 / 3.0) + 0.05


def reference_viscosity(speed: ArrayLike, mean_diameter: ArrayLike) -> NDArray:
    r"""Rated viscosity ν1 for adequate lubrication.

    .. math:: \nu_1 = 45000\, n^{-0.83} d_m^{-0.5} \ (n < 1000\,r/min), \qquad
              4500\, n^{-0.5} d_m^{-0.5} \ (n \ge 1000\,r/min)

    with ν1 in mm²/s, n in r/min and dm in mm.

    Parameters
    ----------
    speed : n, rotational speed. [rad/s]
    mean_diameter : dm, pitch diameter. [m]

    Returns
    -------
    ν1. [m²/s]

    Source: ISO 281:2007, Annex A; ISO/TR 1281-2 (eq. of Figure 1).
    """
    n = np.abs(np.asarray(speed, dtype=float)) * RPM
    dm = np.asarray(mean_diameter, dtype=float) * MM
    nu1 = np.where(n < 1000.0, 45000.0 * n ** -0.83, 4500.0 * n ** -0.5) * dm ** -0.5
    return nu1 * 1e-6


def walther_viscosity(viscosity_40: ArrayLike, viscosity_100: ArrayLike,
                      temperature: ArrayLike) -> NDArray:
    r"""Kinematic viscosity at a temperature from its values at 40 °C and 100 °C.

    .. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B \log_{10} T

    with ν in mm²/s and T in K, A and B fixed by the two reference points.

    Source: ASTM D341 (Walther's equation).

    >>> round(float(walther_viscosity(68e-6, 8.7e-6, 313.15)) * 1e6, 9)
    68.0
    """
    intercept, slope = _walther_line(viscosity_40, viscosity_100)
    t = np.asarray(temperature, dtype=float)
    return (10.0 ** 10.0 ** (intercept - slope * np.log10(t)) - 0.7) * 1e-6


def walther_temperature(viscosity_40: ArrayLike, viscosity_100: ArrayLike,
                        viscosity: ArrayLike) -> NDArray:
    r"""The temperature at which an oil has ``viscosity``: Walther's equation solved for T.

    .. math:: T = 10^{(A - \log_{10}\log_{10}(\nu + 0.7)) / B}

    Units: viscosities [m²/s], T [K]. Source: ASTM D341.

    >>> round(float(walther_temperature(68e-6, 8.7e-6, 8.7e-6)), 9)
    373.15
    """
    intercept, slope = _walther_line(viscosity_40, viscosity_100)
    return 10.0 ** ((intercept - _loglog(np.asarray(viscosity, dtype=float))) / slope)


def _loglog(nu: NDArray) -> NDArray:
    return np.log10(np.log10(nu * 1e6 + 0.7))


def _walther_line(viscosity_40: ArrayLike, viscosity_100: ArrayLike) -> tuple[NDArray, NDArray]:
    """(A, B) of Walther's line through the oil's two reference points."""
    v40, v100 = np.asarray(viscosity_40, dtype=float), np.asarray(viscosity_100, dtype=float)
    slope = (_loglog(v40) - _loglog(v100)) / (np.log10(T100) - np.log10(T40))
    return _loglog(v40) + slope * np.log10(T40), slope


def life_modification_factor(viscosity_ratio: ArrayLike, contamination_factor: ArrayLike,
                             fatigue_load_limit: ArrayLike, equivalent_load: ArrayLike,
                             thrust: ArrayLike = False) -> NDArray:
    r"""aISO for ball bearings, capped at 50.

    .. math:: a_{ISO} = 0.1\left[1 - \left(2.5671 - \frac{A}{\kappa^{b}}\right)^{0.83}
              \left(\frac{e_C C_u}{P}\right)^{1/3}\right]^{-9.3}

    with (A, b) = (2.2649, 0.054381) for 0.1 <= κ < 0.4, (1.9987, 0.19087) for
    0.4 <= κ < 1 and (1.9987, 0.071739) for 1 <= κ <= 4; thrust ball bearings use
    eC·Cu/(3P). A bracket <= 0 gives the cap.

    Parameters
    ----------
    viscosity_ratio : κ, 0.1 <= κ <= 4 (capped by the caller). [1]
    contamination_factor : eC, 0 to 1. [1]
    fatigue_load_limit : Cu. [N]
    equivalent_load : P. [N]
    thrust : True for thrust ball bearings.

    Source: ISO 281:2007, 9.3.2 (eqs. 13 and 17).
    """
    kappa = np.asarray(viscosity_ratio, dtype=float)
    a_coeff = np.where(kappa < 0.4, AISO_BANDS[0][1], AISO_BANDS[1][1])
    b_coeff = np.where(kappa < 0.4, AISO_BANDS[0][2],
                       np.where(kappa < 1.0, AISO_BANDS[1][2], AISO_BANDS[2][2]))
    load = np.asarray(contamination_factor, dtype=float) * np.asarray(
        fatigue_load_limit, dtype=float) / np.asarray(equivalent_load, dtype=float)
    load = np.where(np.asarray(thrust, dtype=bool), load / 3.0, load)
    bracket = 1.0 - (2.5671 - a_coeff / kappa ** b_coeff) ** 0.83 * load ** (1.0 / 3.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        factor = 0.1 * bracket ** -9.3
    return np.where(bracket > 0, np.minimum(factor, AISO_CAP), AISO_CAP)


def evaluate(inputs: Mapping[str, ArrayLike | str | None],
             wanted: Collection[str] | None = None) -> tuple[dict[str, NDArray], NDArray]:
    """Registry entry point: results, warning flags and status codes from SI inputs.

    ``inputs`` (see :meth:`bearingcalc.models.ball_bearing.BallBearingSpec.solver_inputs`)
    may leave optional groups out (None): ratings given or geometry, lubrication,
    load factors, limits. Which results exist depends only on which inputs are
    given, so specs stacked into one call share their result keys.
    """
    kind = str(inputs["bearing_type"])
    thrust = kind == "thrust"
    z, dw, dpw = (inputs.get(k) for k in ("ball_count", "ball_diameter", "pitch_diameter"))
    has_geometry = z is not None and dw is not None and dpw is not None
    alpha = np.asarray(inputs["contact_angle"], dtype=float)
    fr = np.asarray(inputs["radial_load"], dtype=float)
    fa = np.asarray(inputs["axial_load"], dtype=float)
    speed = np.asarray(inputs["speed"], dtype=float)
    out: dict[str, ArrayLike] = {}
    bad_checks: list[tuple[int, ArrayLike]] = [(7, ~(speed > 0)), (8, ~((fr > 0) | (fa > 0)))]
    if not thrust:
        bad_checks.insert(0, (6, ~((alpha >= 0) & (alpha < np.pi / 2))))

    # --- ratings
    c_iso = c0_iso = f0_iso = None
    if has_geometry:
        dw_a, dpw_a, z_a = (np.asarray(v, dtype=float) for v in (dw, dpw, z))
        bad_checks += [(1, ~(dw_a < dpw_a)),
                       (2, ~(z_a * np.arcsin(np.minimum(dw_a / dpw_a, 1.0))
                             <= np.pi * (1.0 + 8 * np.finfo(float).eps)))]
        c_iso, fc = dynamic_load_rating(z_a, dw_a, dpw_a, alpha, thrust)
        bad_checks.append((3, np.isnan(fc)))
        out["dynamic_load_rating_iso"] = c_iso
        out["rating_factor"] = fc
        if not thrust:
            c0_iso, f0_iso = static_load_rating(z_a, dw_a, dpw_a, alpha)
            bad_checks.append((4, np.isnan(f0_iso)))
            out["static_load_rating_iso"] = c0_iso
    c = _given_or(inputs.get("dynamic_load_rating"), c_iso)
    c0 = _given_or(inputs.get("static_load_rating"), c0_iso)
    f0 = _given_or(inputs.get("static_factor"), f0_iso)

    # --- equivalent dynamic load
    flags: dict[str, ArrayLike] = {}
    given_factors = inputs.get("load_x") is not None
    if thrust:
        p = fa
    else:
        if given_factors:
            x, y, e = (np.asarray(inputs[k], dtype=float) for k in ("load_x", "load_y",
                                                                     "load_e"))
        elif kind == "angular-contact":
            degrees = np.degrees(alpha)
            x, y, e = (table_lookup(degrees, ANGULAR_ALPHA_DEG, t)
                       for t in (ANGULAR_X, ANGULAR_Y, ANGULAR_E))
        elif f0 is not None and c0 is not None:
            ratio = f0 * fa / c0
            flags["_warn_axial_ratio_low"] = (fa > 0) & (ratio < DEEP_GROOVE_RATIO[0])
            flags["_warn_axial_ratio_high"] = ratio > DEEP_GROOVE_RATIO[-1]
            clipped = np.clip(ratio, DEEP_GROOVE_RATIO[0], DEEP_GROOVE_RATIO[-1])
            e = np.interp(clipped, DEEP_GROOVE_RATIO, DEEP_GROOVE_E)
            y = np.interp(clipped, DEEP_GROOVE_RATIO, DEEP_GROOVE_Y)
            x = np.full_like(e, DEEP_GROOVE_X)
        else:  # deep-groove, radial load only (the spec model makes sure)
            x, y, e = (np.full_like(fa, np.nan) for _ in range(3))
        with np.errstate(divide="ignore", invalid="ignore"):
            combined = (fa > 0) & ~(fa / fr <= e)
        p = np.where(combined, x * fr + y * fa, fr)
        bad_checks.append((12, ~(p > 0) & ((fr > 0) | (fa > 0))))
        if not np.isnan(np.asarray(e)).all():
            out["radial_factor"] = np.where(combined, x, 1.0)
            out["axial_factor"] = np.where(combined, y, 0.0)
            out["axial_ratio_limit"] = e
    if thrust:
        out["radial_factor"], out["axial_factor"] = np.zeros_like(p), np.ones_like(p)

    # --- basic and modified life
    revolutions_per_second = speed / (2.0 * np.pi)
    l10 = (c / p) ** 3 * 1e6
    a1 = reliability_factor(inputs["reliability"])
    a_iso = np.ones_like(l10)
    if inputs.get("contamination_factor") is not None:
        mean_diameter = np.asarray(inputs["mean_diameter"], dtype=float)
        nu = inputs.get("viscosity")
        if nu is None:
            nu = walther_viscosity(inputs["viscosity_40"], inputs["viscosity_100"],
                                   inputs["temperature"])
            bad_checks.append((9, ~(np.asarray(inputs["viscosity_40"], dtype=float)
                                    > np.asarray(inputs["viscosity_100"], dtype=float))))
            bad_checks.append((13, ~(nu <= MAX_OPERATING_VISCOSITY)))
        nu = np.asarray(nu, dtype=float)
        nu1 = reference_viscosity(speed, mean_diameter)
        kappa_raw = nu / nu1
        bad_checks.append((5, ~(kappa_raw >= KAPPA_MIN)))
        flags["_warn_kappa_capped"] = kappa_raw > KAPPA_CAP
        kappa = np.minimum(kappa_raw, KAPPA_CAP)
        cu = inputs.get("fatigue_load_limit")
        if cu is None:
            # ISO 281 Annex B.3.2.2, ball bearings: Cu from C0 and the pitch diameter.
            cu = c0 / 22.0 * np.where(mean_diameter * MM <= 100.0, 1.0,
                                      (100.0 / (mean_diameter * MM)) ** 0.5)
        a_iso = life_modification_factor(kappa, inputs["contamination_factor"], cu, p, thrust)
        flags["_warn_aiso_capped"] = a_iso >= AISO_CAP
        out.update({"fatigue_load_limit": cu, "reference_viscosity": nu1,
                    "operating_viscosity": nu, "viscosity_ratio": kappa})
    lnm = a1 * a_iso * l10
    out.update({
        "dynamic_load_rating": c, "equivalent_dynamic_load": p, "load_ratio": c / p,
        "basic_rating_life": l10 / revolutions_per_second,
        "basic_rating_life_revolutions": l10, "reliability_factor": a1,
        "life_modification_factor": a_iso,
        "modified_rating_life": lnm / revolutions_per_second,
        "modified_rating_life_revolutions": lnm,
    })
    min_life = inputs.get("min_rating_life")
    if min_life is not None:
        out["life_margin"] = lnm / revolutions_per_second / np.asarray(min_life) - 1.0

    # --- static
    if thrust:
        p0 = fa
    elif kind == "angular-contact":
        y0 = (np.asarray(inputs["load_y0"], dtype=float)
              if inputs.get("load_y0") is not None
              else table_lookup(np.degrees(alpha), ANGULAR_ALPHA_DEG, ANGULAR_Y0))
        x0 = (np.asarray(inputs["load_x0"], dtype=float)
              if inputs.get("load_x0") is not None else ANGULAR_X0)
        p0 = np.maximum(fr, x0 * fr + y0 * fa)
    else:
        p0 = np.maximum(fr, DEEP_GROOVE_X0 * fr + DEEP_GROOVE_Y0 * fa)
    if c0 is not None:
        s0 = c0 / p0
        out.update({"static_load_rating": c0, "static_equivalent_load": p0,
                    "static_safety_factor": s0,
                    "static_safety_margin": s0 - np.asarray(inputs["min_static_safety"])})
        if f0 is not None:
            out["static_rating_factor"] = f0

    # --- kinematics: defect frequencies and race control
    if has_geometry:
        out.update(ball_kinematics(z, dw, dpw, alpha, inputs["inner_speed"],
                                   inputs["outer_speed"], str(inputs["race_control"]),
                                   thrust))
        if inputs.get("max_spin_to_roll") is not None:
            out["spin_to_roll_margin"] = np.asarray(inputs["max_spin_to_roll"]) - np.maximum(
                np.abs(out["inner_spin_to_roll"]), np.abs(out["outer_spin_to_roll"]))

    # --- contact stress of the most heavily loaded ball
    if has_geometry and inputs.get("inner_groove_conformity") is not None:
        fi = np.asarray(inputs["inner_groove_conformity"], dtype=float)
        fo = np.asarray(inputs["outer_groove_conformity"], dtype=float)
        bad_checks += [(10, ~(fi > 0.5)), (11, ~(fo > 0.5))]
        contacts = ball_contacts(z, dw, dpw, alpha, thrust, p0, fi, fo,
                                 inputs["elastic_modulus"], inputs["poisson_ratio"],
                                 inputs["max_contact_pressure"])
        out.update(contacts)
        largest = np.maximum(contacts["inner_contact_semi_major"],
                             contacts["outer_contact_semi_major"])
        bad_checks.append((15 if thrust else 14, ~(largest <= np.asarray(dw) / 2.0)))

    shape = np.broadcast_shapes(*(np.shape(v) for v in (*out.values(), *flags.values())))
    status = first_failure(bad_checks, shape)
    ordered = {key: np.broadcast_to(np.asarray(out[key], dtype=float), shape)
               for key in RESULTS if key in out}
    for key, flag in flags.items():
        ordered[key] = np.broadcast_to(np.asarray(flag, dtype=float), shape)
    return ordered, status


def ball_kinematics(ball_count: ArrayLike, ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
                    contact_angle: ArrayLike, inner_speed: ArrayLike, outer_speed: ArrayLike,
                    race_control: str = "outer", thrust: bool = False) -> dict[str, NDArray]:
    r"""Defect frequencies, cage and ball speeds and the spin of a ball bearing.

    Rolling without slip at both contact centres (both at the angle α, no centrifugal
    shift) fixes the cage: with γ = Dw·cosα/Dpw and ring speeds f_i, f_o,

    .. math:: f_c = 	frac12[f_i(1 - \gamma) + f_o(1 + \gamma)], \quad
              BPFO = Z|f_c - f_o|, \quad BPFI = Z|f_i - f_c|, \quad
              BSF = rac{D_{pw}}{2D_w}(1 - \gamma^2)|f_i - f_o|

    Race control (Jones): in the cage frame the ball turns in the meridian plane, and
    at the controlling race it does not spin. With R = Dpw/2, r = Dw/2, e_x the bearing
    axis, e_r from the axis to the ball centre and ω'_j the rings' speeds in the cage
    frame, the ball's angular velocity relative to the cage is

    .. math:: \omega_b = \omega'_o\left[\left(1 + 	frac{R}{r}\coslpha
ight)e_x
              - 	frac{R}{r}\sinlpha\, e_r
ight] \ 	ext{(outer control)}, \quad
              \omega'_i\left[\left(1 - 	frac{R}{r}\coslpha
ight)e_x
              + 	frac{R}{r}\sinlpha\, e_r
ight] \ 	ext{(inner control)}

    so the attitude β (ω_b ∥ cosβ·e_x − sinβ·e_r) has tanβ = sinα/(cosα ± r/R), as in
    Harris. At each race the race relative to the ball turns at ω'_j·e_x − ω_b: spin
    is its component along the contact normal (from the ball centre to the contact,
    ±(cosα·e_r + sinα·e_x)) and roll its component along t = cosα·e_x − sinα·e_r.

    Parameters
    ----------
    ball_count : Z. [1]
    ball_diameter, pitch_diameter : Dw, Dpw. [m]
    contact_angle : α (π/2 for a thrust bearing). [rad]
    inner_speed, outer_speed : ring speeds in the fixed frame. [rad/s]
    race_control : "outer" or "inner".
    thrust : a thrust bearing (γ = 0: cos α taken as 0).

    Source: Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
    ch. 8 (kinematics, race control); docs/physics.md §7.

    >>> k = ball_kinematics(9, 0.3126, 1.537, 0.0, 2 * np.pi, 0.0)
    >>> [round(float(k[key]), 4) for key in ("ball_pass_frequency_inner",
    ...  "ball_pass_frequency_outer", "cage_frequency")]
    [5.4152, 3.5848, 0.3983]
    """
    z = np.asarray(ball_count, dtype=float)
    big_r = 0.5 * np.asarray(pitch_diameter, dtype=float)
    r = 0.5 * np.asarray(ball_diameter, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    cos_alpha = np.zeros_like(alpha) if thrust else np.cos(alpha)
    sin_alpha = np.ones_like(alpha) if thrust else np.sin(alpha)
    gamma = r * cos_alpha / big_r
    w_i, w_o = np.asarray(inner_speed, dtype=float), np.asarray(outer_speed, dtype=float)
    cage = 0.5 * (w_i * (1.0 - gamma) + w_o * (1.0 + gamma))
    rel_i, rel_o = w_i - cage, w_o - cage
    ratio = big_r / r
    if race_control == "inner":
        ball_x, ball_r = rel_i * (1.0 - ratio * cos_alpha), rel_i * ratio * sin_alpha
    else:
        ball_x, ball_r = rel_o * (1.0 + ratio * cos_alpha), -rel_o * ratio * sin_alpha
    normal_x, normal_r = sin_alpha, cos_alpha      # n, toward the outer contact
    tangent_x, tangent_r = cos_alpha, -sin_alpha   # t

    def spin_to_roll(ring: NDArray, side: float) -> NDArray:
        rel_x, rel_r = ring - ball_x, -ball_r
        spin = side * (rel_x * normal_x + rel_r * normal_r)
        roll = rel_x * tangent_x + rel_r * tangent_r
        return spin / roll

    hz = 1.0 / (2.0 * np.pi)
    # The axis line's angle in (−90°, 90°]: an axis has no sense of its own.
    attitude = np.arctan2(-ball_r, ball_x)
    attitude = np.where(attitude > np.pi / 2, attitude - np.pi,
                        np.where(attitude <= -np.pi / 2, attitude + np.pi, attitude))
    return {
        "cage_frequency": cage * hz,
        "ball_pass_frequency_outer": z * np.abs(cage - w_o) * hz,
        "ball_pass_frequency_inner": z * np.abs(w_i - cage) * hz,
        "ball_spin_frequency": ratio * (1.0 - gamma ** 2) * np.abs(w_i - w_o) * hz / 2.0,
        "cage_speed": cage,
        "ball_speed_relative_to_cage": np.hypot(ball_x, ball_r),
        "ball_attitude_angle": attitude,
        # The controlling race does not spin by construction: exactly 0, not rounding dust.
        "inner_spin_to_roll": spin_to_roll(rel_i, -1.0) * (race_control != "inner"),
        "outer_spin_to_roll": spin_to_roll(rel_o, 1.0) * (race_control == "inner"),
    }


def ball_contacts(ball_count: ArrayLike, ball_diameter: ArrayLike, pitch_diameter: ArrayLike,
                  contact_angle: ArrayLike, thrust: bool, static_equivalent_load: ArrayLike,
                  inner_conformity: ArrayLike, outer_conformity: ArrayLike,
                  elastic_modulus: ArrayLike, poisson_ratio: ArrayLike,
                  max_contact_pressure: ArrayLike) -> dict[str, NDArray]:
    r"""Hertz contacts of the most heavily loaded ball with both races.

    The ball carries Q = 5·P0/(Z·cosα) in a radial bearing (Stribeck's load sharing, the
    basis of ISO 76's C0) and Q = Fa/(Z·sinα) in a thrust bearing. With γ = Dw·cosα/Dpw
    the principal curvatures are 2/Dw (ball, both planes); 2γ/(Dw(1 − γ)) and
    −1/(fi·Dw) at the inner race; −2γ/(Dw(1 + γ)) and −1/(fo·Dw) at the outer race
    (rolling plane, then across the groove).

    Parameters
    ----------
    ball_count : Z. [1]
    ball_diameter, pitch_diameter : Dw, Dpw. [m]
    contact_angle : α. [rad]
    thrust : a thrust bearing (α = 90°).
    static_equivalent_load : P0 (Fa for thrust). [N]
    inner_conformity, outer_conformity : fi, fo > 0.5. [1]
    elastic_modulus, poisson_ratio : of ball and races alike. [Pa], [1]
    max_contact_pressure : the limit. [Pa]

    Source: ISO 76:2006 6.1 and its basis; Harris & Kotzalas, *Essential Concepts of
    Bearing Technology*, 5th ed., ch. 2 (curvatures) and ch. 6 (Hertz).
    """
    z = np.asarray(ball_count, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    cos_alpha = np.where(thrust, 0.0, np.cos(alpha))
    gamma = dw * cos_alpha / np.asarray(pitch_diameter, dtype=float)
    load = (np.asarray(static_equivalent_load, dtype=float) / z
            / (np.sin(alpha) if thrust else cos_alpha / 5.0))
    ball = 2.0 / dw
    e, nu = elastic_modulus, poisson_ratio
    inner = hertz_point_contact(load, ball, ball, 2.0 * gamma / (dw * (1.0 - gamma)),
                                -1.0 / (np.asarray(inner_conformity) * dw), e, nu, e, nu)
    outer = hertz_point_contact(load, ball, ball, -2.0 * gamma / (dw * (1.0 + gamma)),
                                -1.0 / (np.asarray(outer_conformity) * dw), e, nu, e, nu)
    peak = np.maximum(inner["max_pressure"], outer["max_pressure"])
    return {
        "max_ball_load": load,
        "inner_contact_pressure": inner["max_pressure"],
        "outer_contact_pressure": outer["max_pressure"],
        "inner_contact_semi_major": inner["semi_major"],
        "inner_contact_semi_minor": inner["semi_minor"],
        "outer_contact_semi_major": outer["semi_major"],
        "outer_contact_semi_minor": outer["semi_minor"],
        "inner_contact_approach": inner["approach"],
        "outer_contact_approach": outer["approach"],
        "max_contact_pressure": peak,
        "contact_pressure_margin": 1.0 - peak / np.asarray(max_contact_pressure),
    }


def _given_or(given: ArrayLike | None, computed: NDArray | None) -> NDArray | None:
    """The catalogue value where the spec gives one, else the value from the geometry."""
    if given is not None:
        return np.asarray(given, dtype=float)
    return computed
