"""The blank of a straight, Zerol or face-milled spiral bevel pair without offset, by ISO
23509:2016: pitch cones, the mean section's addenda and dedenda from the profile shift
x_hm1, the tooth taper (the dedendum angle system), face and root cones, the outer
and inner sections, the mean normal circular thickness, and the virtual spur gears of
the normal section the profile checks need (``docs/physics.md`` §8, the ISO 23509
blank).

Gear 1 is the pinion, gear 2 the wheel; the wheel's profile shift is −x_hm1. Every
function is pure numpy on SI arrays that broadcast (lengths [m], angles [rad]).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: The tooth taper's systems: the root and face lines through the pitch apex
#: (standard depth), parallel to the pitch line (uniform depth), or the constant slot
#: width of a face-milled duplex cut (the sum of the dedendum angles from the cutter).
TAPERS = ("standard-depth", "uniform-depth", "duplex")
#: Gleason's mean addendum factor of the wheel, c_ham = 0.210 + 0.290/u_a.
C_HAM_BASE, C_HAM_RATIO = 0.210, 0.290
#: The tool's edge radius where none is given, a share of m_mn.
EDGE_RADIUS_SHARE = 0.2


class BlankInputs(NamedTuple):
    """The pair as ISO 23509's data type I gives it [m, rad, 1]."""

    pinion_teeth: ArrayLike
    gear_teeth: ArrayLike
    shaft_angle: ArrayLike
    outer_pitch_diameter_gear: ArrayLike   # de2
    face_width: ArrayLike                  # b, centred on the mean point
    spiral_angle: ArrayLike                # β_m, 0 for straight and Zerol
    pressure_angle: ArrayLike              # α_n, the normal one at the mean point
    cutter_radius: ArrayLike               # r_c0 (constant slot width only)
    profile_shift: ArrayLike               # x_hm1; the wheel's is −x_hm1
    thickness_modification_pinion: ArrayLike  # x_sm1
    thickness_modification_gear: ArrayLike    # x_sm2
    addendum_factor: ArrayLike = 1.0       # k_hap
    dedendum_factor: ArrayLike = 1.25      # k_hfp
    taper: str = "standard-depth"  # one of TAPERS
    #: δ1, δ2 where the pair gives them (else from the teeth and the shaft angle)
    pitch_angles: tuple[ArrayLike, ArrayLike] | None = None


def pitch_cones(z1: ArrayLike, z2: ArrayLike, shaft_angle: ArrayLike
                ) -> tuple[NDArray, NDArray]:
    r"""The pitch angles δ1, δ2 [rad] of a pair without offset,

    .. math:: \tan δ_1 = \frac{\sin Σ}{u + \cos Σ}, \quad δ_2 = Σ - δ_1, \quad u = z_2/z_1

    Source: ISO 23509:2016, 6.2 (method 0).
    """
    u = np.asarray(z2, dtype=float) / np.asarray(z1, dtype=float)
    sigma = np.asarray(shaft_angle, dtype=float)
    delta1 = np.arctan2(np.sin(sigma), u + np.cos(sigma))
    return delta1, sigma - delta1


def gleason_profile_shift(z1: ArrayLike, z2: ArrayLike, delta1: ArrayLike,
                          delta2: ArrayLike, addendum_factor: ArrayLike = 1.0) -> NDArray:
    r"""The pinion's profile shift x_hm1 [1] of Gleason's spiral bevel proportions: the
    wheel's mean addendum is c_ham of the working depth 2·k_hap·m_mn,

    .. math:: c_{ham} = 0.210 + \frac{0.290}{u_a}, \quad
              u_a = \frac{z_2\cos δ_1}{z_1\cos δ_2}, \quad
              x_{hm1} = k_{hap}(1 - 2c_{ham})

    Source: ISO 23509:2016 Annex (Gleason's mean addendum factor); its sample F.2's
    c_ham 0.24737 is this at z 14/39.
    """
    ratio = (np.asarray(z2, dtype=float) * np.cos(np.asarray(delta1, dtype=float))
             / (np.asarray(z1, dtype=float) * np.cos(np.asarray(delta2, dtype=float))))
    return np.asarray(addendum_factor, dtype=float) * (
        1.0 - 2.0 * (C_HAM_BASE + C_HAM_RATIO / ratio))


def dedendum_angles(taper: str, mean_dedenda: tuple[NDArray, NDArray],
                    cones: tuple[NDArray, NDArray], outer_module: NDArray,
                    spiral_angle: NDArray, pressure_angle: NDArray, cutter_radius: NDArray,
                    addendum_share_gear: NDArray) -> tuple[NDArray, NDArray]:
    r"""The dedendum angles θ_f1, θ_f2 [rad] of a taper system, with the cone distances
    ``cones`` = (R_e, R_m):

    - standard depth, the root line through the pitch apex: θ_f = atan(h_fm/R_m);
    - uniform depth: θ_f = 0;
    - duplex, a constant slot width (face-milled, completing): the slot's width is the cutter's
      point width along the face, which fixes the sum

      .. math:: Σθ_f = \frac{π\,m_{et2}}{2R_e\tan α_n\cos β_m}
                \left(1 - \frac{R_m\sin β_m}{r_{c0}}\right)

      shared as the addenda are, θ_f1 = Σθ_f·h_am2/h_mw, θ_f2 = Σθ_f − θ_f1 (each
      member's dedendum angle is the other's addendum angle, so the clearance is
      constant along the face).

    Source: ISO 23509:2016, 6.3 (tooth depth and taper); Gleason Works, the duplex
    taper of face-milled completing cuts (the standard's sample F.2 gives θ_f1 2.1342°
    and θ_f2 6.4934°, the sum this yields shared so).
    """
    hfm1, hfm2 = mean_dedenda
    outer, mean = cones
    if taper == "standard-depth":
        return np.arctan(hfm1 / mean), np.arctan(hfm2 / mean)
    if taper == "uniform-depth":
        zero = np.zeros(np.broadcast_shapes(np.shape(hfm1), np.shape(hfm2)))
        return zero, zero.copy()
    total = (np.pi * outer_module / (2.0 * outer * np.tan(pressure_angle)
                                     * np.cos(spiral_angle))
             * (1.0 - mean * np.sin(spiral_angle) / cutter_radius))
    return total * addendum_share_gear, total * (1.0 - addendum_share_gear)


def blank(pair: BlankInputs) -> dict[str, NDArray]:
    r"""The pair's blank (keys named as the results: ``…_pinion``, ``…_gear``):

    .. math:: R_e = \frac{d_{e2}}{2\sin δ_2}, \quad R_m = R_e - \frac b2, \quad
              d_m = 2R_m\sin δ, \quad m_{mn} = \frac{d_{m2}\cos β_m}{z_2}

    .. math:: h_{am1} = m_{mn}(k_{hap} + x_{hm1}), \quad h_{fm1} = m_{mn}(k_{hfp} - x_{hm1}),
              \quad h_{am2} = m_{mn}(k_{hap} - x_{hm1}), \quad
              h_{fm2} = m_{mn}(k_{hfp} + x_{hm1})

    face and root angles δ_a = δ + θ_a, δ_f = δ − θ_f with θ_a1 = θ_f2, θ_a2 = θ_f1;
    outer addendum h_ae = h_am + (b/2)·tan θ_a and dedendum h_fe = h_fm + (b/2)·tan θ_f;
    outer tip and root diameters d_ae = d_e + 2h_ae·cos δ, d_fe = d_e − 2h_fe·cos δ; the
    crown to the crossing point t_xo = R_e·cos δ − h_ae·sin δ; the mean normal circular
    thickness s_mn = m_mn·(π/2 + 2(x_sm + x_hm·tan α_n)).

    Source: ISO 23509:2016, clause 6 and Annex F (sample F.2).
    """
    z1, z2 = (np.asarray(v, dtype=float) for v in (pair.pinion_teeth, pair.gear_teeth))
    delta1, delta2 = (pitch_cones(z1, z2, pair.shaft_angle) if pair.pitch_angles is None
                      else (np.asarray(v, dtype=float) for v in pair.pitch_angles))
    b = np.asarray(pair.face_width, dtype=float)
    beta = np.asarray(pair.spiral_angle, dtype=float)
    alpha = np.asarray(pair.pressure_angle, dtype=float)
    x = np.asarray(pair.profile_shift, dtype=float)
    k_a, k_f = (np.asarray(v, dtype=float) for v in (pair.addendum_factor,
                                                      pair.dedendum_factor))
    outer = np.asarray(pair.outer_pitch_diameter_gear, dtype=float) / (2.0 * np.sin(delta2))
    mean = outer - 0.5 * b
    module = 2.0 * mean * np.sin(delta2) * np.cos(beta) / z2
    addenda = (module * (k_a + x), module * (k_a - x))
    dedenda = (module * (k_f - x), module * (k_f + x))
    theta_f = dedendum_angles(pair.taper, dedenda, (outer, mean),
                              2.0 * outer * np.sin(delta2) / z2, beta, alpha,
                              np.asarray(pair.cutter_radius, dtype=float),
                              addenda[1] / (addenda[0] + addenda[1]))
    theta_a = (theta_f[1], theta_f[0])
    thickness = (pair.thickness_modification_pinion, pair.thickness_modification_gear)
    out: dict[str, NDArray] = {"outer_cone_distance": outer, "mean_cone_distance": mean,
                               "mean_normal_module": module}
    for i, (member, delta, shift) in enumerate((("pinion", delta1, x), ("gear", delta2, -x))):
        de = 2.0 * outer * np.sin(delta)
        hae = addenda[i] + 0.5 * b * np.tan(theta_a[i])
        hfe = dedenda[i] + 0.5 * b * np.tan(theta_f[i])
        out.update({
            f"pitch_angle_{member}": delta,
            f"outer_pitch_diameter_{member}": de,
            f"mean_pitch_diameter_{member}": 2.0 * mean * np.sin(delta),
            f"mean_addendum_{member}": addenda[i],
            f"mean_dedendum_{member}": dedenda[i],
            f"addendum_angle_{member}": theta_a[i],
            f"dedendum_angle_{member}": theta_f[i],
            f"face_angle_{member}": delta + theta_a[i],
            f"root_angle_{member}": delta - theta_f[i],
            f"outer_addendum_{member}": hae,
            f"outer_dedendum_{member}": hfe,
            f"outer_tip_diameter_{member}": de + 2.0 * hae * np.cos(delta),
            f"outer_root_diameter_{member}": de - 2.0 * hfe * np.cos(delta),
            f"crown_to_crossing_point_{member}": outer * np.cos(delta) - hae * np.sin(delta),
            f"mean_normal_circular_thickness_{member}": module * (
                0.5 * np.pi + 2.0 * (np.asarray(thickness[i], dtype=float)
                                     + shift * np.tan(alpha))),
        })
    return out


def _involute(angle: NDArray) -> NDArray:
    return np.tan(angle) - angle


def tooth_limits(out: dict[str, NDArray], normal_teeth: tuple[ArrayLike, ArrayLike],
                 pressure_angle: ArrayLike, rack: tuple[ArrayLike, ArrayLike],
                 edge_radii: tuple[ArrayLike, ArrayLike]) -> dict[str, NDArray]:
    r"""Each member's least profile shift against undercut and its top land, in the
    virtual spur gear of the normal section of ``normal_teeth`` z_vn (ISO 10300-1 Annex
    A: :func:`bearingcalc.core.iso10300_virtual.virtual_gears`): the tool's straight
    flank, reaching k_hfp·m_mn less its edge's ρ_a0·(1 − sin α_n), stays out of the base
    circle where

    .. math:: x_{hm} \ge k_{hfp} - \frac{ρ_{a0}}{m_{mn}}(1 - \sin α_n)
              - \frac{z_{vn}}2\sin^2 α_n

    and the tooth's normal thickness at the tip circle d_van = d_vn + 2h_am,

    .. math:: s_{an} = d_{van}\left(\frac{s_{mn}}{d_{vn}} + \operatorname{inv}α_n
              - \operatorname{inv}α_{an}\right), \quad \cos α_{an} = \frac{d_{vn}\cos α_n}{d_{van}}

    is above zero where the tooth is not pointed. Keys ``least_profile_shift_{member}``
    (the pinion's own bound on x_hm1; the wheel's, on −x_hm1), ``top_land_{member}``
    and ``rack_top_land_{member}``, the unshifted tooth's (x_hm = x_sm = 0) of the basic
    rack ``rack`` = (k_hap, k_hfp).

    Source: the generating rack's undercut limit and the involute tooth's thickness
    (ISO 21771:2007, 5.4; ISO 23509:2016, the undercut check of its Annex).
    """
    module = out["mean_normal_module"]
    alpha = np.asarray(pressure_angle, dtype=float)
    addendum_factor, dedendum_factor = (np.asarray(v, dtype=float) for v in rack)
    limits: dict[str, NDArray] = {}
    for member, teeth, edge in (("pinion", normal_teeth[0], edge_radii[0]),
                                ("gear", normal_teeth[1], edge_radii[1])):
        radius = (EDGE_RADIUS_SHARE * module if edge is None
                  else np.asarray(edge, dtype=float))
        limits[f"least_profile_shift_{member}"] = (
            dedendum_factor - radius / module * (1.0 - np.sin(alpha))
            - 0.5 * np.asarray(teeth, dtype=float) * np.sin(alpha) ** 2)
        pitch = np.asarray(teeth, dtype=float) * module
        limits[f"top_land_{member}"] = _top_land(
            pitch, out[f"mean_addendum_{member}"],
            out[f"mean_normal_circular_thickness_{member}"], alpha)
        limits[f"rack_top_land_{member}"] = _top_land(
            pitch, addendum_factor * module, 0.5 * np.pi * module, alpha)
    return limits


def _top_land(pitch: NDArray, addendum: ArrayLike, thickness: ArrayLike, alpha: NDArray
              ) -> NDArray:
    """s_an at the tip circle of a spur gear of pitch diameter d, its addendum and its
    thickness s at d, pressure angle α (see :func:`tooth_limits`) [m]."""
    tip = pitch + 2.0 * np.asarray(addendum, dtype=float)
    at_tip = np.arccos(np.clip(pitch * np.cos(alpha) / tip, -1.0, 1.0))
    return tip * (np.asarray(thickness, dtype=float) / pitch + _involute(alpha)
                  - _involute(at_tip))
