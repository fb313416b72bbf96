"""What the bevel-gears kind reports: its results with their units and meanings, the
table's headings, the warnings and the reasons a design is impossible
(:mod:`bearingcalc.core.bevel_gears` solves it; docs/physics.md §4 and §8).
"""

from __future__ import annotations

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
    "contact_ratio": ("1", "εα of the virtual spur pair at the mean section"),
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
    "undercut": "the pinion's virtual teeth zv1 (a spiral pinion's normal zvn1) are "
                "below 2/sin²φ (17.1 at 20°): a generated pinion undercuts unless its "
                "addendum is lengthened; check the Gleason minimum for this ratio",
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
    9: ("rating.quality_number", "the pitch-line speed is above v_t,max = [A + (Q_v − 3)]²/200 "
        "m/s, the most the AGMA dynamic factor covers at this quality number (28.7 m/s at "
        "Q_v 8; Budynas & Nisbett eq. 15-6): check the module and speed, or give a higher "
        "quality number"),
}
