"""Sizing a bevel pair: blank geometry, the spiral pair's normal section and the tooth
forces of straight, Zerol and spiral teeth (``docs/physics.md`` §8). The strength
rating is :mod:`bearingcalc.core.bevel_rating`.

Gear A is the pinion (z1 teeth, pitch angle δ1), gear B the gear (z2, δ2). Inputs
are SI floats or broadcasting arrays.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Gleason whole depth: h = 2.188·m + 0.051 mm. [m]
WHOLE_DEPTH_FACTOR, WHOLE_DEPTH_EXTRA = 2.188, 0.051e-3


def blank_geometry(pinion_teeth: ArrayLike, gear_teeth: ArrayLike, module: ArrayLike,
                   pinion_pitch_angle: ArrayLike, gear_pitch_angle: ArrayLike,
                   face_width: ArrayLike, pressure_angle: ArrayLike) -> dict[str, NDArray]:
    r"""Blank dimensions of a straight bevel pair (Gleason proportions, no offset).

    With the outer transverse module m at the large end:

    .. math:: d_e = m z, \quad R_e = \frac{d_e}{2\sin\delta}, \quad R_m = R_e - \frac b2,
              \quad m_m = m\frac{R_m}{R_e}, \quad d_m = d_e\frac{R_m}{R_e},
              \quad z_v = \frac{z}{\cos\delta}

    h_a2 = 0.54·m + 0.46·m / (z2·cosδ1/(z1·cosδ2)), h_a1 = 2m − h_a2,
    h = 2.188·m + 0.051 mm, h_f = h − h_a, θ_f = atan(h_f/R_e),
    d_a = d_e + 2·h_a·cosδ, and the pitch apex to crown X = R_e·cosδ − h_a·sinδ.
    The transverse contact ratio is the virtual spur pair's at the mean section
    (virtual pitch radii d_m/(2cosδ), addenda h_a·R_m/R_e, base pitch π·m_m·cosφ).

    Parameters
    ----------
    pinion_teeth, gear_teeth : z1, z2. [1]
    module : m, outer transverse. [m]
    pinion_pitch_angle, gear_pitch_angle : δ1, δ2. [rad]
    face_width : b. [m]
    pressure_angle : φ. [rad]

    Returns
    -------
    dict keyed as the sizing results (outer_cone_distance, …). [SI]

    Source: ISO 23509:2016 (cone geometry); Gleason Works, *Straight Bevel Gear Design*
    (addendum and whole depth), as tabulated in the KHK Gear Technical Reference,
    "Bevel gear calculations"; Dudley, *Handbook of Practical Gear Design*, ch. 3.

    >>> g = blank_geometry(20, 40, 3e-3, np.arctan(0.5), np.arctan(2.0), 20e-3,
    ...                    np.radians(20))
    >>> [round(float(g[k]) * 1e3, 4) for k in ("gear_a_outside_diameter",
    ...                                        "gear_b_crown_to_apex")]
    [67.218, 28.2425]
    """
    z1, z2 = np.asarray(pinion_teeth, dtype=float), np.asarray(gear_teeth, dtype=float)
    m = np.asarray(module, dtype=float)
    d1, d2 = (np.asarray(x, dtype=float) for x in (pinion_pitch_angle, gear_pitch_angle))
    b = np.asarray(face_width, dtype=float)
    phi = np.asarray(pressure_angle, dtype=float)
    de1, de2 = m * z1, m * z2
    cone = de1 / (2.0 * np.sin(d1))
    mean_cone = cone - 0.5 * b
    scale = mean_cone / cone
    ha2 = 0.54 * m + 0.46 * m / (z2 * np.cos(d1) / (z1 * np.cos(d2)))
    ha1 = 2.0 * m - ha2
    depth = WHOLE_DEPTH_FACTOR * m + WHOLE_DEPTH_EXTRA
    hf1, hf2 = depth - ha1, depth - ha2
    dm1, dm2 = de1 * scale, de2 * scale
    out = {
        "outer_cone_distance": cone, "mean_cone_distance": mean_cone,
        "face_width_ratio": b / cone, "mean_module": m * scale,
        "gear_a_outer_pitch_diameter": de1, "gear_b_outer_pitch_diameter": de2,
        "gear_a_mean_pitch_diameter": dm1, "gear_b_mean_pitch_diameter": dm2,
        "gear_a_virtual_teeth": z1 / np.cos(d1), "gear_b_virtual_teeth": z2 / np.cos(d2),
        "gear_a_addendum": ha1, "gear_b_addendum": ha2,
        "gear_a_dedendum": hf1, "gear_b_dedendum": hf2,
        "gear_a_dedendum_angle": np.arctan(hf1 / cone),
        "gear_b_dedendum_angle": np.arctan(hf2 / cone),
        "gear_a_outside_diameter": de1 + 2.0 * ha1 * np.cos(d1),
        "gear_b_outside_diameter": de2 + 2.0 * ha2 * np.cos(d2),
        "gear_a_crown_to_apex": cone * np.cos(d1) - ha1 * np.sin(d1),
        "gear_b_crown_to_apex": cone * np.cos(d2) - ha2 * np.sin(d2),
    }
    out["contact_ratio"] = virtual_contact_ratio(dm1 / (2.0 * np.cos(d1)),
                                                 dm2 / (2.0 * np.cos(d2)),
                                                 ha1 * scale, ha2 * scale, m * scale, phi)
    return out


def spiral_normal_section(mean_module: ArrayLike, virtual_teeth_1: ArrayLike,
                          virtual_teeth_2: ArrayLike, spiral_angle: ArrayLike,
                          normal_pressure_angle: ArrayLike) -> dict[str, NDArray]:
    r"""The virtual cylindrical gears of a spiral bevel pair in the normal section at the
    mean point of the face.

    .. math:: m_{mn} = m_m\cos\beta_m, \qquad \sin\beta_{vb} = \sin\beta_m\cos\alpha_n,
              \qquad z_{vn} = \frac{z_v}{\cos^2\beta_{vb}\,\cos\beta_m}

    z_vn is the number of teeth of the spur gear whose flank, in the normal section,
    has the curvature of the virtual helical gear's at the pitch point; β_vb is the
    virtual gear's base helix angle.

    Parameters
    ----------
    mean_module : m_m, the mean transverse module. [m]
    virtual_teeth_1, virtual_teeth_2 : z_v = z/cosδ of each gear. [1]
    spiral_angle : β_m. [rad]
    normal_pressure_angle : α_n. [rad]

    Returns
    -------
    mean_normal_module [m], gear_a_normal_virtual_teeth and
    gear_b_normal_virtual_teeth [1].

    Source: ISO 10300-1:2014, the virtual cylindrical gears in the normal section.
    """
    beta = np.asarray(spiral_angle, dtype=float)
    sin_base_helix = np.sin(beta) * np.cos(np.asarray(normal_pressure_angle, dtype=float))
    to_normal = 1.0 / ((1.0 - sin_base_helix**2) * np.cos(beta))
    return {"mean_normal_module": np.asarray(mean_module, dtype=float) * np.cos(beta),
            "gear_a_normal_virtual_teeth": np.asarray(virtual_teeth_1, dtype=float) * to_normal,
            "gear_b_normal_virtual_teeth": np.asarray(virtual_teeth_2, dtype=float) * to_normal}


def virtual_contact_ratio(pitch_radius_1: ArrayLike, pitch_radius_2: ArrayLike,
                          addendum_1: ArrayLike, addendum_2: ArrayLike, module: ArrayLike,
                          pressure_angle: ArrayLike) -> NDArray:
    r"""Transverse contact ratio of a spur pair (the virtual pair of a bevel set).

    .. math:: \varepsilon_\alpha = \frac{\sqrt{r_{a1}^2 - r_{b1}^2}
              + \sqrt{r_{a2}^2 - r_{b2}^2} - (r_1 + r_2)\sin\varphi}{\pi m\cos\varphi}

    with r_a = r + h_a and r_b = r·cosφ. [1]

    Source: ISO 6336-1 / Budynas & Nisbett ch. 13 (length of action over base pitch).
    """
    r1, r2 = (np.asarray(x, dtype=float) for x in (pitch_radius_1, pitch_radius_2))
    phi = np.asarray(pressure_angle, dtype=float)
    cos, sin = np.cos(phi), np.sin(phi)
    ra1 = r1 + np.asarray(addendum_1, dtype=float)
    ra2 = r2 + np.asarray(addendum_2, dtype=float)
    action = (np.sqrt(ra1 ** 2 - (r1 * cos) ** 2) + np.sqrt(ra2 ** 2 - (r2 * cos) ** 2)
              - (r1 + r2) * sin)
    return action / (np.pi * np.asarray(module, dtype=float) * cos)


def tooth_forces(pinion_torque: ArrayLike, pinion_mean_diameter: ArrayLike,
                 pressure_angle: ArrayLike, pinion_pitch_angle: ArrayLike,
                 gear_pitch_angle: ArrayLike) -> dict[str, NDArray]:
    r"""Tooth forces of a straight bevel pair at the mean pitch point.

    .. math:: W_t = \frac{2T}{d_{m1}}, \quad W_{r1} = W_t\tan\varphi\cos\delta_1,
              \quad W_{a1} = W_t\tan\varphi\sin\delta_1, \quad
              W_{r2} = W_t\tan\varphi\cos\delta_2, \quad
              W_{a2} = W_t\tan\varphi\sin\delta_2

    The separating force W_t·tanφ lies in the plane of the axes, square to the pitch
    cones' common element, so each gear's share along and across its own axis follows
    from its own pitch angle; at a shaft angle of 90° (δ1 + δ2 = 90°) the gear's forces
    are the pinion's exchanged, W_r2 = W_a1 and W_a2 = W_r1.

    Parameters
    ----------
    pinion_torque : T on gear A. [N·m]
    pinion_mean_diameter : d_m1. [m]
    pressure_angle : φ. [rad]
    pinion_pitch_angle, gear_pitch_angle : δ1, δ2. [rad]

    Source: Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed.,
    §13-15, eq. (13-38).
    """
    torque = np.abs(np.asarray(pinion_torque, dtype=float))
    tangential = 2.0 * torque / np.asarray(pinion_mean_diameter, dtype=float)
    separating = tangential * np.tan(np.asarray(pressure_angle, dtype=float))
    d1, d2 = (np.asarray(x, dtype=float) for x in (pinion_pitch_angle, gear_pitch_angle))
    return {"tangential_force": tangential,
            "gear_a_radial_force": separating * np.cos(d1),
            "gear_a_axial_force": separating * np.sin(d1),
            "gear_b_radial_force": separating * np.cos(d2),
            "gear_b_axial_force": separating * np.sin(d2)}


def spiral_tooth_forces(pinion_torque: ArrayLike, pinion_mean_diameter: ArrayLike,
                        normal_pressure_angle: ArrayLike, spiral_angle: ArrayLike,
                        pinion_pitch_angle: ArrayLike, gear_pitch_angle: ArrayLike,
                        thrust_sign: ArrayLike) -> dict[str, NDArray]:
    r"""Tooth forces of a spiral (or Zerol) bevel pair driven by its pinion, at the mean
    pitch point, with the signs the hand and rotation give.

    .. math:: W_{a1} = \frac{W_t}{\cos\beta}(\tan\varphi_n\sin\delta_1
              - s\sin\beta\cos\delta_1), \quad
              W_{r1} = \frac{W_t}{\cos\beta}(\tan\varphi_n\cos\delta_1
              + s\sin\beta\sin\delta_1)

    and for the driven gear, of the opposite hand, the same with δ2 and −s. W_a is
    positive away from the pitch-cone apex, W_r toward the member's own axis (a
    negative W_a pulls the member toward the apex, into mesh). s = +1 for a driving
    pinion of right hand turning clockwise, or left hand turning counterclockwise,
    viewed from its back (the large end) toward the apex; s = −1 for the other two.
    At β = 0 (straight, Zerol) the forces are :func:`tooth_forces`'.

    Parameters
    ----------
    pinion_torque : T on the pinion, the driver. [N·m]
    pinion_mean_diameter : d_m1. [m]
    normal_pressure_angle : φ_n. [rad]
    spiral_angle : β at the mean point. [rad]
    pinion_pitch_angle, gear_pitch_angle : δ1, δ2. [rad]
    thrust_sign : s. [1]

    Source: the spiral-bevel force formulas of bearing and gear makers' handbooks (NTN,
    *Ball and Roller Bearings*, gear loads; Arrow Gear, stock gear bearing loads), the
    Gleason form; ``docs/physics.md`` §8.
    """
    torque = np.abs(np.asarray(pinion_torque, dtype=float))
    tangential = 2.0 * torque / np.asarray(pinion_mean_diameter, dtype=float)
    beta = np.asarray(spiral_angle, dtype=float)
    tan_phi = np.tan(np.asarray(normal_pressure_angle, dtype=float))
    sign = np.asarray(thrust_sign, dtype=float)
    scale = tangential / np.cos(beta)
    d1, d2 = (np.asarray(x, dtype=float) for x in (pinion_pitch_angle, gear_pitch_angle))
    sin_beta = np.sin(beta)
    return {"tangential_force": tangential,
            "gear_a_radial_force": scale * (tan_phi * np.cos(d1) + sign * sin_beta * np.sin(d1)),
            "gear_a_axial_force": scale * (tan_phi * np.sin(d1) - sign * sin_beta * np.cos(d1)),
            "gear_b_radial_force": scale * (tan_phi * np.cos(d2) - sign * sin_beta * np.sin(d2)),
            "gear_b_axial_force": scale * (tan_phi * np.sin(d2) + sign * sin_beta * np.cos(d2))}

