"""The virtual cylindrical gears of a bevel pair without offset, by ISO 10300-1:2014
Annex A (method B1): the helical pair that meshes at the mean point of the face as the
bevel pair does, in its transverse and normal sections, its contact ratios, the relative
curvature at the mean point and the middle contact line's length
(``docs/physics.md`` §8, ISO 10300).

Gear 1 is the pinion, gear 2 the wheel. Every function is pure numpy on SI arrays that
broadcast (lengths [m], angles [rad]).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: The share of the face width that carries load where the contact pattern was checked
#: (ISO 10300-1, 6.5 note: b_eff = 0.85·b).
EFFECTIVE_FACE_SHARE = 0.85


class MeanSection(NamedTuple):
    """The pair at the mean point of the face [m, rad, 1]."""

    pinion_teeth: ArrayLike
    gear_teeth: ArrayLike
    mean_pitch_diameters: tuple[ArrayLike, ArrayLike]   # d_m1, d_m2
    pitch_angles: tuple[ArrayLike, ArrayLike]           # δ1, δ2
    mean_addenda: tuple[ArrayLike, ArrayLike]           # h_am1, h_am2
    mean_dedenda: tuple[ArrayLike, ArrayLike]           # h_fm1, h_fm2
    mean_normal_module: ArrayLike                       # m_mn
    spiral_angle: ArrayLike                             # β_m
    pressure_angle: ArrayLike                           # α_n
    face_width: ArrayLike                               # b
    effective_face_share: ArrayLike = EFFECTIVE_FACE_SHARE


def virtual_gears(pair: MeanSection) -> dict[str, NDArray]:
    r"""The virtual cylindrical gears (keys as ISO 10300's symbols, SI):

    .. math:: d_v = \frac{d_m}{\cos δ}, \quad a_v = \frac{d_{v1} + d_{v2}}2, \quad
              \tan α_{vet} = \frac{\tan α_n}{\cos β_v}, \quad
              d_{vb} = d_v\cos α_{vet}, \quad d_{va} = d_v + 2h_{am}, \quad
              \sin β_{vb} = \sin β_v\cos α_n

    (β_v = β_m without offset), the transverse base pitch
    p_vet = π·m_mn·cos α_vet / cos β_v, the path of contact

    .. math:: g_{vα} = \tfrac12\left(\sqrt{d_{va1}^2 - d_{vb1}^2} - d_{v1}\sin α_{vet}\right)
              + \tfrac12\left(\sqrt{d_{va2}^2 - d_{vb2}^2} - d_{v2}\sin α_{vet}\right)

    the contact ratios ε_vα = g_vα/p_vet, ε_vβ = b_v,eff·sin β_v/(π·m_mn),
    ε_vγ = ε_vα + ε_vβ (b_v,eff = 0.85·b, b_v = b without offset), the relative
    curvature at the mean point normal to the contact line

    .. math:: \frac1{ρ_t} = \frac{\cos^2 β_m}{\sin α_n}\left(\frac1{R_m\tan δ_1}
              + \frac1{R_m\tan δ_2}\right), \quad \tan β_B = \tan β_v\sin α_n, \quad
              ρ_{rel} = ρ_t\cos^2 β_B

    the virtual spur gears of the normal section z_vn = z_v/(cos²β_vb·cos β_v),
    d_vn = z_vn·m_mn, d_van = d_vn + 2h_am, d_vbn = d_vn·cos α_n, and the middle
    contact line: the line through the zone of action's centre at β_vb to the face,
    as long as the zone lets it be, shortened by the contact pattern's ends,

    .. math:: l_{bm} = \min\left(\frac{g_{vα}}{\sin β_{vb}}, \frac{b_{v,eff}}{\cos β_{vb}}
              \right)\sqrt{b_{v,eff}/b_v}

    Source: ISO 10300-1:2014, Annex A (A.2, A.3; the middle line of A.2.7); checked
    against ISO/TR 10300-30 sample 1.
    """
    z1, z2 = (np.asarray(v, dtype=float) for v in (pair.pinion_teeth, pair.gear_teeth))
    dm1, dm2 = (np.asarray(v, dtype=float) for v in pair.mean_pitch_diameters)
    delta1, delta2 = (np.asarray(v, dtype=float) for v in pair.pitch_angles)
    ham1, ham2 = (np.asarray(v, dtype=float) for v in pair.mean_addenda)
    hfm1, hfm2 = (np.asarray(v, dtype=float) for v in pair.mean_dedenda)
    module = np.asarray(pair.mean_normal_module, dtype=float)
    beta = np.asarray(pair.spiral_angle, dtype=float)
    alpha_n = np.asarray(pair.pressure_angle, dtype=float)
    face = np.asarray(pair.face_width, dtype=float)
    dv1, dv2 = dm1 / np.cos(delta1), dm2 / np.cos(delta2)
    alpha_t = np.arctan(np.tan(alpha_n) / np.cos(beta))
    base_helix = np.arcsin(np.sin(beta) * np.cos(alpha_n))
    dva1, dva2 = dv1 + 2.0 * ham1, dv2 + 2.0 * ham2
    dvb1, dvb2 = dv1 * np.cos(alpha_t), dv2 * np.cos(alpha_t)
    pitch = np.pi * module * np.cos(alpha_t) / np.cos(beta)
    path = 0.5 * (np.sqrt(dva1**2 - dvb1**2) - dv1 * np.sin(alpha_t)
                  + np.sqrt(dva2**2 - dvb2**2) - dv2 * np.sin(alpha_t))
    effective = np.asarray(pair.effective_face_share, dtype=float) * face
    eps_alpha = path / pitch
    eps_beta = effective * np.sin(beta) / (np.pi * module)
    mean_cone = dm1 / (2.0 * np.sin(delta1))
    rho_t = np.sin(alpha_n) / (np.cos(beta) ** 2 * (
        1.0 / (mean_cone * np.tan(delta1)) + 1.0 / (mean_cone * np.tan(delta2))))
    contact_line_angle = np.arctan(np.tan(beta) * np.sin(alpha_n))
    to_normal = 1.0 / (np.cos(base_helix) ** 2 * np.cos(beta))
    zvn1, zvn2 = z1 / np.cos(delta1) * to_normal, z2 / np.cos(delta2) * to_normal
    with np.errstate(divide="ignore"):
        across = np.minimum(np.where(base_helix > 0.0, path / np.sin(base_helix), np.inf),
                            effective / np.cos(base_helix))
    return {
        "dv1": dv1, "dv2": dv2, "av": 0.5 * (dv1 + dv2), "alpha_vet": alpha_t,
        "mvt": module / np.cos(beta), "zv1": z1 / np.cos(delta1), "zv2": z2 / np.cos(delta2),
        "beta_vb": base_helix, "dva1": dva1, "dva2": dva2, "dvf1": dv1 - 2.0 * hfm1,
        "dvf2": dv2 - 2.0 * hfm2, "dvb1": dvb1, "dvb2": dvb2, "pvet": pitch,
        "gv_alpha": path, "eps_v_alpha": eps_alpha, "bv_eff": effective, "bv": face,
        "eps_v_beta": eps_beta, "eps_v_gamma": eps_alpha + eps_beta, "rho_t": rho_t,
        "beta_B": contact_line_angle, "rho_rel": rho_t * np.cos(contact_line_angle) ** 2,
        "zvn1": zvn1, "zvn2": zvn2, "dvn1": zvn1 * module, "dvn2": zvn2 * module,
        "dvan1": zvn1 * module + 2.0 * ham1, "dvan2": zvn2 * module + 2.0 * ham2,
        "dvbn1": zvn1 * module * np.cos(alpha_n), "dvbn2": zvn2 * module * np.cos(alpha_n),
        "lbm": across * np.sqrt(effective / face),
    }
