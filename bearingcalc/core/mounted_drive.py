"""A bevel drive as mounted (``method: iso-16281``): each shaft rigid on its bearings'
contacts (:mod:`bearingcalc.core.mounted_shaft`), each bearing's loads from them and
its ISO 281 and ISO/TS 16281 lives, each shaft's preload and stiffness at the gear's
mean pitch point, and how far the two gears move at the mesh, in Gleason's terms
(``docs/physics.md`` §12).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core import mounted_bearing as shared
from bearingcalc.core import rolling_bearing
from bearingcalc.core.common import DerivedTest
from bearingcalc.core.drive_bearings import MountedBearing
from bearingcalc.core.mounted_bearing import within_model
from bearingcalc.core.mounted_clearance import chain_warnings, mounted_clearance
from bearingcalc.core.mounted_setting import RESULTS as SETTING_RESULTS
from bearingcalc.core.mounted_setting import operating_end_play
from bearingcalc.core.mounted_shaft import (
    MountedShaft,
    gear_load,
    solve_mounted_shaft,
    takes_clearance,
)
from bearingcalc.core.shaft_statics import mean_pitch_point

#: The drive's results as mounted, of one value per design.
RESULTS: dict[str, tuple[str, str]] = {
    **{f"{shaft}_{key}": (unit, f"the {shaft} shaft's {meaning}")
       for shaft in ("pinion", "gear") for key, (unit, meaning) in {
           "preload_force": ("N", "preload: its bearings' axial load at rest"),
           "stiffness_axial": ("N/m", "stiffness along its axis at the gear's mean pitch "
                               "point"),
           "stiffness_radial": ("N/m", "stiffness along the gear's radial force at its "
                                "mean pitch point"),
           **{key: (unit, f"adjusted pair: {meaning}")
              for key, (unit, meaning) in SETTING_RESULTS.items()}}.items()},
    "mesh_offset_change": ("m", "E: the change of the offset between the axes, along "
                           "a×b from the pinion's axis to the gear's"),
    "pinion_axial_shift": ("m", "P: the pinion's shift along its axis, away from the "
                           "pitch apex, relative to where the axes cross"),
    "gear_axial_shift": ("m", "G: the gear's shift along its axis, away from the pitch "
                         "apex, relative to where the axes cross"),
    "shaft_angle_change": ("rad", "Σ: the change of the shaft angle, positive opening"),
    **{f"{key}_margin": ("1", f"1 − |{key}| / max_{key}") for key in (
        "mesh_offset_change", "pinion_axial_shift", "gear_axial_shift",
        "shaft_angle_change")},
}
#: Each bearing's results as mounted, along the member axis (declared with the drive's).
MOUNTED_COLUMNS = ("max_element_load", "reference_rating_life",
                   "modified_reference_rating_life")
#: The status codes of a shaft that finds no equilibrium on its bearings, and of a
#: bearing whose contact outgrows Hertz's theory.
NO_EQUILIBRIUM = {"pinion": 24, "gear": 25}
CRUSHED = {"pinion": 26, "gear": 27}
#: The status codes of an adjusted pair whose bearings overlap.
OVERLAPPING = {"pinion": 28, "gear": 29}
STATUS_REASONS = {
    **{code: (f"{shaft}_bearings", DerivedTest(
        f"the {shaft} shaft finds no equilibrium on its bearings, or one only at a tilt of "
        "more than 10 mrad or a shift of more than a tenth of a bearing's pitch radius: they "
        "cannot carry the gear's force (a one-way bearing loaded against its shoulder, too "
        "little thrust on an adjusted pair, a one-way bearing floating, or a shaft located "
        "by no bearing that carries thrust)")) for shaft, code in NO_EQUILIBRIUM.items()},
    **{code: (f"{shaft}_bearings", DerivedTest(
        f"a bearing of the {shaft} shaft is loaded beyond Hertz's theory (its most "
        "heavily loaded contact outgrows its rolling element): the gear's force is too "
        "large for it")) for shaft, code in CRUSHED.items()},
    **{code: (f"{shaft}_bearings.2.position", DerivedTest(
        f"the {shaft} shaft's adjusted bearings overlap: their rolling elements, c = "
        "(Dpw/2)·tanα inside their pressure centres back-to-back and outside them "
        "face-to-face, lie closer than half their widths summed (or not apart at all "
        "where a width is not given); the positions are the bearings' pressure centres"))
       for shaft, code in OVERLAPPING.items()},
}


def mounted_shaft_bearings(inputs: Mapping[str, Any], pair: Any, shaft: str, gear: str,
                           speed: NDArray, shape: tuple[int, ...],
                           mesh: tuple[NDArray, NDArray]
                           ) -> tuple[list[MountedBearing], MountedShaft, list]:
    """A shaft's bearings solved as mounted: each one's loads from its contacts, its ISO
    281 solution under them with its ISO/TS 16281 lives beside, the shaft, and the
    checks of its equilibrium and contacts."""
    def flat(value: Any) -> NDArray:
        return np.broadcast_to(np.asarray(value, dtype=float), shape).reshape(-1)

    load = gear_load({key: np.broadcast_to(value, shape) for key, value in
                      pair.results.items()}, gear, tuple(np.broadcast_to(v, shape)
                                                         for v in mesh))
    bearings = [_with_rating({**bearing, "inner_speed": speed, "outer_speed": 0.0,
                              "speed": speed}) for bearing in inputs["shafts"][shaft]]
    setting = inputs.get("settings", {}).get(shaft) or {}
    solved = solve_mounted_shaft(bearings, inputs["arrangements"][shaft], setting, load,
                                 flat)
    mounted, crushed = [], np.zeros(load.shape[0], dtype=bool)
    for i, (bearing, family, contacts, life) in enumerate(zip(
            bearings, solved.families, solved.loaded.contacts, solved.lives, strict=True)):
        crushed |= family.pressures(contacts)[2]
        loads = {"radial_load": np.hypot(contacts.force[:, 1], contacts.force[:, 2]),
                 "axial_load": np.abs(contacts.force[:, 0]),
                 "max_element_load": np.max(np.nan_to_num(contacts.element_load), axis=1)}
        loads = {key: value.reshape(shape) for key, value in loads.items()}
        member_inputs = {**bearing, "radial_load": loads["radial_load"],
                         "axial_load": loads["axial_load"], "speed": speed,
                         "inner_speed": speed, "outer_speed": 0.0, "min_rating_life": None,
                         "method": "iso-281"}
        own = rolling_bearing.evaluate(member_inputs)
        lives = shared.life_results(member_inputs, life, own.results, speed, shape,
                                    family.family)
        loads.update({key: lives[key] for key in MOUNTED_COLUMNS if key in lives})
        warned: dict[str, NDArray] = {}
        if bearing.get("mounting") is not None:
            chain = mounted_clearance(bearing)
            if takes_clearance(bearing):  # else its pair's end play says it
                loads.update({key: np.broadcast_to(chain[key], shape) for key in (
                    "operating_clearance", "operating_clearance_min",
                    "operating_clearance_max")})
            # judged under the loads the shaft gives it, as a bearing alone under its own
            warned = chain_warnings(member_inputs, chain)
        mounted.append(MountedBearing(f"{shaft}_bearing_{i + 1}", f"{shaft}_bearings.{i + 1}",
                                      f"{shaft} shaft bearings", member_inputs, loads,
                                      replace(own, results={**own.results, **lives},
                                              warnings={**own.warnings, **warned})))
    found = solved.loaded.converged & within_model(
        solved.loaded.displacement - solved.rest,
        np.min(np.stack([family.lever for family in solved.families]), axis=0))
    checks = [(NO_EQUILIBRIUM[shaft], (~found).reshape(shape)),
              (CRUSHED[shaft], crushed.reshape(shape))]
    if solved.overlapping is not None:  # said before the equilibrium it spoils
        checks.insert(0, (OVERLAPPING[shaft], solved.overlapping.reshape(shape)))
    return mounted, solved, checks


def _with_rating(bearing: dict[str, Any]) -> dict[str, Any]:
    """The bearing with its C: the catalogue's, else ISO 281's from its geometry (the
    raceway ratings of its reference life follow from it)."""
    if bearing.get("dynamic_load_rating") is not None:
        return bearing
    rated = rolling_bearing.evaluate({**bearing, "radial_load": 1.0, "axial_load": 0.0,
                                      "min_rating_life": None, "method": "iso-281"})
    return {**bearing, "dynamic_load_rating": rated.results["dynamic_load_rating"]}


def shaft_results(shaft: str, solved: MountedShaft, mesh: tuple[NDArray, NDArray],
                  shape: tuple[int, ...]) -> dict[str, NDArray]:
    r"""A shaft's preload and its stiffness at the gear's mean pitch point P: with the
    shaft's tangent stiffness K (5 × 5) and P's displacement v = J·Q,

    .. math:: J = \begin{pmatrix}1&0&0&0&r_p\\0&1&0&0&-x_p\\0&0&1&-x_p&0\end{pmatrix},
              \qquad k_d = \left(d^T J K^{-1} J^T d\right)^{-1}

    along the axis (d = e_x) and along the gear's radial force (d = −e_y); J^T d is the
    generalised load of a unit force at P along d. Source: virtual work.
    """
    x_p, r_p = (np.broadcast_to(np.asarray(v, dtype=float), shape).reshape(-1)
                for v in mesh)
    jacobian = np.zeros((x_p.size, 3, 5))
    jacobian[:, 0, 0] = jacobian[:, 1, 1] = jacobian[:, 2, 2] = 1.0
    jacobian[:, 0, 4], jacobian[:, 1, 4], jacobian[:, 2, 3] = r_p, -x_p, -x_p
    out = {f"{shaft}_preload_force": solved.preload.reshape(shape)}
    if solved.setting:
        out.update({f"{shaft}_{key}": value for key, value in
                    operating_end_play(solved.setting, shape).items()})
    for name, direction in (("axial", (1.0, 0.0, 0.0)), ("radial", (0.0, -1.0, 0.0))):
        d = np.asarray(direction)
        load = np.einsum("nij,i->nj", jacobian, d)
        with np.errstate(invalid="ignore", divide="ignore"):
            compliance = np.linalg.solve(solved.loaded.stiffness, load[..., None])[..., 0]
            out[f"{shaft}_stiffness_{name}"] = (1.0 / np.einsum("nj,nj->n", load,
                                                                compliance)).reshape(shape)
    return out


def mesh_displacements(pair: Mapping[str, NDArray], shafts: Mapping[str, MountedShaft],
                       shape: tuple[int, ...]) -> dict[str, NDArray]:
    r"""How far the gears move at the mesh from the assembly at rest: each shaft's
    displacement at the apex u and rotation ω (θy about its y, −θz about its z) in a
    common frame, the pinion's axis a = e_X, its mean pitch point in the X-Y plane at
    its pitch angle δ₁, the gear's axis b = (cos Σ, sin Σ, 0), n = a × b/|a × b|. Only
    the shafts' relative motion moves the mesh: the gear's apex relative to the
    pinion's, split along the two axes and their common normal,

    .. math:: u_g - u_p = -P\,a + G\,b + E\,n, \qquad Σ = n·(ω_g - ω_p)

    P and G each shaft's shift along its axis, away from the pitch apex, relative to
    where the axes cross; E the offset between them; Σ the shaft angle's opening; to
    first order (the axes met at the apex). A shaft left out (no gear bearings) counts
    as rigid. Source: the kinematics of two lines (Gleason's E, P, G, Σ).
    """
    sigma = np.broadcast_to(np.asarray(pair["shaft_angle"], dtype=float), shape).reshape(-1)
    delta = np.broadcast_to(np.asarray(pair["gear_a_pitch_angle"], dtype=float),
                            shape).reshape(-1)
    frames = {"pinion": np.broadcast_to(np.eye(3), (sigma.size, 3, 3)),
              "gear": _gear_frame(sigma, delta)}
    moved, turned = {}, {}
    for shaft, frame in frames.items():
        change = (shafts[shaft].loaded.displacement - shafts[shaft].rest
                  if shaft in shafts else np.zeros((sigma.size, 5)))
        moved[shaft] = np.einsum("nij,nj->ni", frame, change[:, :3])
        rotation = np.stack([np.zeros_like(sigma), change[:, 3], -change[:, 4]], axis=1)
        turned[shaft] = np.einsum("nij,nj->ni", frame, rotation)
    relative = moved["gear"] - moved["pinion"]
    gear_shift = relative[:, 1] / np.sin(sigma)
    return {key: value.reshape(shape) for key, value in {
        "mesh_offset_change": relative[:, 2],
        "pinion_axial_shift": gear_shift * np.cos(sigma) - relative[:, 0],
        "gear_axial_shift": gear_shift,
        "shaft_angle_change": turned["gear"][:, 2] - turned["pinion"][:, 2]}.items()}


def _gear_frame(sigma: NDArray, delta: NDArray) -> NDArray:
    """The gear shaft's axes in the common frame, (N, 3, 3) columns x, y, z: x = b, y
    from its axis toward the mean pitch point, z = x × y (= −e_Z: its tangential force
    opposes the pinion's)."""
    b = np.stack([np.cos(sigma), np.sin(sigma), np.zeros_like(sigma)], axis=1)
    point = np.stack([np.cos(delta), np.sin(delta), np.zeros_like(delta)], axis=1)
    radial = point - np.einsum("ni,ni->n", point, b)[:, None] * b
    radial /= np.linalg.norm(radial, axis=1)[:, None]
    return np.stack([b, radial, np.cross(b, radial)], axis=2)


def evaluate_mounted(inputs: Mapping[str, Any], pair: Any, speeds: Mapping[str, NDArray]
                     ) -> tuple[list[MountedBearing], dict[str, NDArray], list]:
    """Every shaft of the drive as mounted: its bearings (for the drive's member rows
    and system life), the drive's results as mounted, and the checks."""
    shape = _designs(inputs, pair, speeds)
    mounted: list[MountedBearing] = []
    shafts: dict[str, MountedShaft] = {}
    results: dict[str, NDArray] = {}
    checks: list = []
    for shaft, gear in (("pinion", "a"), ("gear", "b")):
        if shaft not in inputs["shafts"]:
            continue
        mesh = mean_pitch_point(pair.results["mean_cone_distance"],
                                pair.results[f"gear_{gear}_pitch_angle"])
        found, solved, own_checks = mounted_shaft_bearings(inputs, pair, shaft, gear,
                                                           speeds[shaft], shape, mesh)
        mounted += found
        shafts[shaft] = solved
        checks += own_checks
        results.update(shaft_results(shaft, solved, mesh, shape))
    results.update(mesh_displacements(pair.results, shafts, shape))
    for key in ("mesh_offset_change", "pinion_axial_shift", "gear_axial_shift",
                "shaft_angle_change"):
        limit = inputs.get(f"max_{key}")
        if limit is not None:
            results[f"{key}_margin"] = 1.0 - np.abs(results[key]) / np.asarray(limit,
                                                                              dtype=float)
    return mounted, results, checks


def _designs(inputs: Mapping[str, Any], pair: Any, speeds: Mapping[str, NDArray]
             ) -> tuple[int, ...]:
    """The designs' shape: the pair's results', the speeds' and every number of every
    bearing and setting."""
    numbers = [value for bearings in inputs["shafts"].values() for bearing in bearings
               for value in shared.numbers_in(bearing)]
    numbers += [value for setting in inputs.get("settings", {}).values() if setting
                for value in setting.values() if value is not None]
    return np.broadcast_shapes(np.shape(pair.status), *(np.shape(v) for v in numbers),
                               *(np.shape(v) for v in pair.results.values()),
                               *(np.shape(v) for v in speeds.values()))
