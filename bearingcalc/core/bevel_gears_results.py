"""What the bevel-gears kind reports: its results with their units and meanings, the
table's headings, the warnings and the reasons a design is impossible
(:mod:`bearingcalc.core.bevel_gears` solves it; docs/physics.md §4 and §8).
"""

from __future__ import annotations

from bearingcalc.core.common import DerivedTest

#: The key of the apex-mismatch margin, max_apex_mismatch − |apex_mismatch|. It reads
#: "slip_margin" in every output, as the other rolling kinds name their margin, and stays
#: so for the tools that read it.
APEX_MISMATCH_MARGIN = "slip_margin"

RESULTS: dict[str, tuple[str, str]] = {
    "gear_a_pitch_radius": ("m", "pitch radius a of gear A"),
    "gear_b_pitch_radius": ("m", "pitch radius b of gear B"),
    "gear_a_pitch_angle": ("rad", "pitch-cone half-angle α of gear A"),
    "gear_b_pitch_angle": ("rad", "pitch-cone half-angle β of gear B"),
    "shaft_angle": ("rad", "shaft angle γ = α + β"),
    "gear_ratio": ("1", "b/a"),
    "cone_distance": ("m", "apex to pitch point, a/sinα"),
    "gear_a_speed_relative_to_arm": ("rad/s", "ω_AS = (b/a)(ω_Z − Ω)"),
    "relative_speed": ("rad/s", "|ω_A − ω_B|, gear A relative to gear B"),
    "gear_a_speed": ("rad/s", "gear A's absolute angular speed |ω_Z·k + ω_AS·n3| (its "
                              "shaft's speed on fixed axes)"),
    "contact_point_speed": ("m/s", "gear B's material point at the contact, b·|Ω|"),
    "pitch_line_speed": ("m/s", "pitch-line speed b·|ω_Z − Ω| (relative to the arm, which "
                                  "fixed axes hold at rest)"),
    "apex_mismatch": ("1", "b·sinα/(a·sinβ) − 1; 0 when the pitch cones share their apex"),
    APEX_MISMATCH_MARGIN: ("1", "max_apex_mismatch − |apex_mismatch|"),
    "outer_cone_distance": ("m", "Re, apex to the outer end of the face"),
    "mean_cone_distance": ("m", "Rm = Re − b/2"),
    "face_width_ratio": ("1", "b/Re"),
    "mean_module": ("m", "mean module m_m = m·Rm/Re"),
    "gear_a_outer_pitch_diameter": ("m", "de1 = m·z1"),
    "gear_b_outer_pitch_diameter": ("m", "de2 = m·z2"),
    "gear_a_mean_pitch_diameter": ("m", "dm1 = de1·Rm/Re"),
    "gear_b_mean_pitch_diameter": ("m", "dm2 = de2·Rm/Re"),
    "gear_a_virtual_teeth": ("1", "zv1 = z1/cosδ1 (Tredgold)"),
    "gear_b_virtual_teeth": ("1", "zv2 = z2/cosδ2"),
    "mean_normal_module": ("m", "a spiral pair's mmn = mm·cosβm"),
    "gear_a_normal_virtual_teeth": ("1", "a spiral pair's zvn1 = zv1/(cos²βvb·cosβm), "
                                         "sinβvb = sinβm·cosφn (ISO 10300-1)"),
    "gear_b_normal_virtual_teeth": ("1", "a spiral pair's zvn2 = zv2/(cos²βvb·cosβm)"),
    "gear_a_addendum": ("m", "ha1 = 2m − ha2 (Gleason)"),
    "gear_b_addendum": ("m", "ha2 (Gleason)"),
    "gear_a_dedendum": ("m", "hf1 = h − ha1, h = 2.188·m + 0.051 mm"),
    "gear_b_dedendum": ("m", "hf2 = h − ha2"),
    "gear_a_dedendum_angle": ("rad", "θf1 = atan(hf1/Re)"),
    "gear_b_dedendum_angle": ("rad", "θf2 = atan(hf2/Re)"),
    "gear_a_outside_diameter": ("m", "da1 = de1 + 2·ha1·cosδ1"),
    "gear_b_outside_diameter": ("m", "da2 = de2 + 2·ha2·cosδ2"),
    "gear_a_crown_to_apex": ("m", "pitch apex to crown X1 = Re·cosδ1 − ha1·sinδ1"),
    "gear_b_crown_to_apex": ("m", "pitch apex to crown X2 = Re·cosδ2 − ha2·sinδ2"),
    "contact_ratio": ("1", "εα of the virtual spur pair at the mean section (a spiral "
                           "or Zerol pair's: ε_vα of ISO 10300-1's virtual cylindrical "
                           "pair)"),
    **{f"{key}_{member}": (unit, f"the {member}'s {meaning}")
       for key, (unit, meaning) in {
           "pitch_angle": ("rad", "pitch angle δ"),
           "mean_pitch_diameter": ("m", "mean pitch diameter d_m = 2R_m·sinδ"),
           "mean_addendum": ("m", "mean addendum h_am = m_mn(k_hap ± x_hm1)"),
           "mean_dedendum": ("m", "mean dedendum h_fm = m_mn(k_hfp ∓ x_hm1)"),
           "addendum_angle": ("rad", "addendum angle θ_a, the mate's dedendum angle"),
           "dedendum_angle": ("rad", "dedendum angle θ_f of the taper"),
           "face_angle": ("rad", "face angle δ_a = δ + θ_a"),
           "root_angle": ("rad", "root angle δ_f = δ − θ_f"),
           "outer_addendum": ("m", "outer addendum h_ae = h_am + (b/2)·tanθ_a"),
           "outer_dedendum": ("m", "outer dedendum h_fe = h_fm + (b/2)·tanθ_f"),
           "outer_tip_diameter": ("m", "outer tip diameter d_ae = d_e + 2h_ae·cosδ"),
           "outer_root_diameter": ("m", "outer root diameter d_fe = d_e − 2h_fe·cosδ"),
           "crown_to_crossing_point": ("m", "crown to crossing point t_xo = "
                                       "R_e·cosδ − h_ae·sinδ"),
           "mean_normal_circular_thickness": ("m", "mean normal circular thickness s_mn = "
                                              "m_mn(π/2 + 2(x_sm ± x_hm1·tanα_n))"),
           "least_profile_shift": ("1", "least profile shift against undercut (its own: "
                                   "x_hm1 for the pinion, −x_hm1 for the gear)"),
           "top_land": ("m", "normal top land s_an at the mean point's tip circle"),
       }.items() for member in ("pinion", "gear")},
    "profile_shift": ("1", "x_hm1, the pinion's profile shift (given, or Gleason's "
                           "k_hap(1 − 2(0.210 + 0.290/u_a)))"),
    "tangential_force": ("N", "Wt = 2T/dm1 at the mean pitch point"),
    "gear_a_radial_force": ("N", "Wr1, toward gear A's axis (straight: Wt·tanφ·cosδ1)"),
    "gear_a_axial_force": ("N", "Wa1, away from the apex; < 0 toward it (straight: "
                                "Wt·tanφ·sinδ1)"),
    "gear_b_radial_force": ("N", "Wr2, toward gear B's axis (straight: Wt·tanφ·cosδ2)"),
    "gear_b_axial_force": ("N", "Wa2, away from the apex (straight: Wt·tanφ·sinδ2)"),
    "lengthwise_curvature_factor": ("1", "a spiral pair's K_x = 0.211(rc/Rm)^q + 0.789, "
                                         "q = 0.279/log10(sinβm), from 1 to 1.15"),
    "bending_stress": ("Pa", "AGMA 2003 s_F"),
    "contact_stress": ("Pa", "AGMA 2003 s_H"),
    "bending_safety": ("1", "S_F of gear A (the pinion)"),
    "contact_safety": ("1", "S_H of gear A (the pinion)"),
    "gear_b_bending_stress": ("Pa", "AGMA 2003 s_F of gear B"),
    "gear_b_bending_safety": ("1", "S_F of gear B, at its own cycles"),
    "gear_b_contact_safety": ("1", "S_H of gear B, with its cycles and C_H"),
    "bending_power_rating": ("W", "power at S_F = 1, same speed"),
    "contact_power_rating": ("W", "power at S_H = 1, same speed"),
    "face_width_margin": ("1", "max_face_width_ratio − b/Re"),
    "bending_safety_margin": ("1", "the smaller S_F − min_bending_safety"),
    "contact_safety_margin": ("1", "the smaller S_H − min_contact_safety"),
}

#: A spiral or Zerol pair's blank by ISO 23509 (the table's "blank" heading).
BLANK_RESULTS = ("profile_shift", *(
    f"{key}_{member}" for key in (
        "pitch_angle", "mean_pitch_diameter", "mean_addendum", "mean_dedendum",
        "addendum_angle", "dedendum_angle", "face_angle", "root_angle", "outer_addendum",
        "outer_dedendum", "outer_tip_diameter", "outer_root_diameter",
        "crown_to_crossing_point", "mean_normal_circular_thickness", "least_profile_shift",
        "top_land") for member in ("pinion", "gear")))

#: Headings of the table, each with its results.
GROUPS: dict[str, tuple[str, ...]] = {
    "kinematics": ("gear_a_pitch_radius", "gear_b_pitch_radius", "gear_a_pitch_angle",
                   "gear_b_pitch_angle", "shaft_angle", "gear_ratio", "cone_distance",
                   "gear_a_speed_relative_to_arm", "relative_speed", "gear_a_speed",
                   "contact_point_speed", "pitch_line_speed", "apex_mismatch",
                   APEX_MISMATCH_MARGIN),
    "geometry": ("outer_cone_distance", "mean_cone_distance", "face_width_ratio",
                 "mean_module", "gear_a_outer_pitch_diameter", "gear_b_outer_pitch_diameter",
                 "gear_a_mean_pitch_diameter", "gear_b_mean_pitch_diameter",
                 "gear_a_virtual_teeth", "gear_b_virtual_teeth", "mean_normal_module",
                 "gear_a_normal_virtual_teeth", "gear_b_normal_virtual_teeth",
                 "gear_a_addendum",
                 "gear_b_addendum", "gear_a_dedendum", "gear_b_dedendum",
                 "gear_a_dedendum_angle", "gear_b_dedendum_angle", "gear_a_outside_diameter",
                 "gear_b_outside_diameter", "gear_a_crown_to_apex", "gear_b_crown_to_apex",
                 "contact_ratio", "face_width_margin"),
    "blank (ISO 23509)": BLANK_RESULTS,
    "forces": ("tangential_force", "gear_a_radial_force", "gear_a_axial_force",
               "gear_b_radial_force", "gear_b_axial_force"),
    "rating": ("lengthwise_curvature_factor", "bending_stress", "contact_stress",
               "bending_safety", "contact_safety", "gear_b_bending_stress",
               "gear_b_bending_safety", "gear_b_contact_safety",
               "bending_power_rating", "contact_power_rating", "bending_safety_margin",
               "contact_safety_margin"),
}

#: Conditions reported per design as warnings: flag key -> message.
WARNINGS: dict[str, str] = {
    "undercut": "the straight pinion's virtual teeth zv1 are below 2/sin²φ (17.1 at "
                "20°): a generated pinion undercuts unless its addendum is lengthened; "
                "check the Gleason minimum for this ratio",
}

STATUS_REASONS: dict[int, tuple[str, str]] = {
    1: ("gear_a.pitch_radius", "the pitch radius of gear A must be positive"),
    2: ("gear_b.pitch_radius", "the pitch radius of gear B must be positive"),
    3: ("shaft_angle", "the shaft angle must be between 0 deg and 180 deg"),
    4: ("gear_a.pitch_angle", "the pitch angle of gear A must be between 0 deg and the "
                              "shaft angle"),
    5: ("gear_b.pitch_angle", "the pitch angle of gear B must be between 0 deg and the "
                              "shaft angle"),
    6: ("shaft_angle", "the shaft angle must equal the sum of the two pitch angles"),
    7: ("face_width", "must be less than half the outer cone distance Re (and in practice at "
                      "most Re/3)"),
    8: ("power", "gear A does not turn relative to its arm, so power gives no torque: give "
                 "torque instead"),
    **{code: ("profile_shift", DerivedTest(
        f"the {member}'s teeth would be undercut: its profile shift ({sign}x_hm1) is "
        f"below least_profile_shift_{member}, k_hfp − ρ_a0/m_mn·(1 − sinα_n) − "
        f"z_vn·sin²α_n/2: give {'a larger' if member == 'pinion' else 'a smaller'} "
        f"profile_shift, or the {member} more teeth"))
       for member, sign, code in (("pinion", "", 10), ("gear", "−", 12))},
    **{code: ("profile_shift", DerivedTest(
        f"the {member}'s teeth would be pointed (no top land at the tip circle): give "
        f"{'a smaller' if member == 'pinion' else 'a larger'} profile_shift, a smaller "
        "pressure_angle, a thicker tooth (thickness_modification) or a smaller "
        "addendum_factor"))
       for member, code in (("pinion", 11), ("gear", 13))},
    **{code: ("pressure_angle", DerivedTest(
        f"the {member}'s teeth would be pointed even unshifted: the basic rack's "
        "pressure_angle and addendum_factor leave no top land at its tip circle in the "
        "normal section: give a smaller pressure_angle or addendum_factor"))
       for member, code in (("pinion", 14), ("gear", 15))},
    16: ("cutter_radius", DerivedTest(
        "a duplex taper needs a face cutter larger than R_m·sinβ_m (the spiral's "
        "curvature at the mean point): give a larger cutter_radius, or taper: "
        "standard-depth")),
    9: ("rating.quality_number", "the pitch-line speed is above v_t,max = [A + (Q_v − 3)]²/200 "
        "m/s, the most the AGMA dynamic factor covers at this quality number (28.7 m/s at "
        "Q_v 8; Budynas & Nisbett eq. 15-6): check the module and speed, or give a higher "
        "quality number"),
}
