"""The statics of a rigid shaft on two bearings carrying a gear force: the bearings'
radial loads, the bending moment along the shaft, and how the two bearings share the
axial force, located or adjusted against each other (``docs/physics.md`` §9).

Inputs are SI floats or broadcasting arrays; x runs along the shaft from the gear's
pitch-cone apex.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from bearingcalc.core.arrangements import (
    adjusted_axial_loads,
    induced_axial_factor_ball,
    induced_axial_factor_tapered,
    supports_positive,
)
from bearingcalc.core.bearing_types import traits

#: How a shaft's two bearings share its axial force.
ARRANGEMENTS = ("locating-floating", "back-to-back", "face-to-face")


def shaft_reactions(positions: tuple[ArrayLike, ArrayLike], mesh_position: ArrayLike,
                    mesh_radius: ArrayLike, tangential: ArrayLike, radial: ArrayLike,
                    axial: ArrayLike) -> tuple[NDArray, NDArray]:
    r"""Radial loads of the two simple supports of a rigid shaft carrying a gear force.

    x runs along the shaft from the pitch-cone apex toward the gear's back face; the
    mean pitch point is at x_p, at radius r_p from the axis. The gear force there has
    W_t across the plane of the axis and the pitch point, W_r toward the axis and W_a
    along +x (away from the apex). Moments about the first support in the two planes:

    .. math:: R_{2y} = \frac{W_r(x_p - x_1) + W_a r_p}{x_2 - x_1}, \quad
              R_{1y} = W_r - R_{2y}, \quad
              R_{2z} = \frac{W_t(x_p - x_1)}{x_2 - x_1}, \quad R_{1z} = W_t - R_{2z}

    Each bearing's radial load is |(R_y, R_z)|. Straddle (x1 < x_p < x2) and overhung
    (both supports on one side) mountings alike.

    Parameters
    ----------
    positions : (x1, x2) of the bearings. [m]
    mesh_position, mesh_radius : x_p, r_p of the mean pitch point. [m]
    tangential, radial, axial : W_t, W_r, W_a. [N]

    Source: statics of a beam on two simple supports (Budynas & Nisbett, *Shigley's
    Mechanical Engineering Design*, 10th ed., Example 13-8 sets up the same balance).
    """
    (r1y, r1z), (r2y, r2z) = _support_forces(positions, mesh_position, mesh_radius,
                                             tangential, radial, axial)
    return np.hypot(r1y, r1z), np.hypot(r2y, r2z)


def _support_forces(positions: tuple[ArrayLike, ArrayLike], mesh_position: ArrayLike,
                    mesh_radius: ArrayLike, tangential: ArrayLike, radial: ArrayLike,
                    axial: ArrayLike) -> tuple[tuple[NDArray, NDArray], tuple[NDArray, NDArray]]:
    """((R1y, R1z), (R2y, R2z)) of :func:`shaft_reactions`, in the two planes. [N]"""
    x1, x2 = (np.asarray(x, dtype=float) for x in positions)
    xp, rp = np.asarray(mesh_position, dtype=float), np.asarray(mesh_radius, dtype=float)
    wt, wr, wa = (np.asarray(w, dtype=float) for w in (tangential, radial, axial))
    span = x2 - x1
    r2y = (wr * (xp - x1) + wa * rp) / span
    r2z = wt * (xp - x1) / span
    return (wr - r2y, wt - r2z), (r2y, r2z)


def mean_pitch_point(mean_cone_distance: ArrayLike, pitch_angle: ArrayLike
                     ) -> tuple[NDArray, NDArray]:
    """(x_p, r_p) = (Rm·cosδ, Rm·sinδ): where a gear's mean pitch point lies along its
    shaft from the pitch-cone apex, and how far from the axis. [m]"""
    distance, angle = np.asarray(mean_cone_distance), np.asarray(pitch_angle)
    return distance * np.cos(angle), distance * np.sin(angle)


def shaft_bending_moments(x: ArrayLike, positions: tuple[float, float], mesh_position: float,
                          mesh_radius: float, tangential: float, radial: float,
                          axial: float) -> tuple[NDArray, NDArray]:
    r"""The bending moment along a shaft of :func:`shaft_reactions`, in its two planes.

    With the supports' reactions from the balance of the whole shaft, the moment at a
    section x is that of every force on the side nearer the apex (x' < x):

    .. math:: M_y(x) = \sum_i R_{iy}\langle x - x_i\rangle - W_r\langle x - x_p\rangle
              + W_a r_p H(x - x_p), \quad
              M_z(x) = \sum_i R_{iz}\langle x - x_i\rangle - W_t\langle x - x_p\rangle

    (⟨u⟩ = max(u, 0), H the unit step; W_a r_p is the couple of the axial force at
    the pitch point). Both vanish beyond the last force, and each slope jumps by the
    reaction at a support. [N·m] at x [m]; inputs as in :func:`shaft_reactions`.

    Source: singularity functions of a beam, Budynas & Nisbett, *Shigley's Mechanical
    Engineering Design*, 10th ed., §3-3.
    """
    x = np.asarray(x, dtype=float)
    first, second = _support_forces(positions, mesh_position, mesh_radius, tangential,
                                    radial, axial)
    reactions = ((positions[0], *first), (positions[1], *second))

    def arm(at: float) -> NDArray:
        return np.maximum(x - at, 0.0)

    moment_y = sum(ry * arm(at) for at, ry, _ in reactions) - radial * arm(mesh_position) \
        + axial * mesh_radius * (x > mesh_position)
    moment_z = sum(rz * arm(at) for at, _, rz in reactions) - tangential * arm(mesh_position)
    return np.asarray(moment_y), np.asarray(moment_z)


def shaft_bending_lines(shafts: Mapping[str, list[Mapping[str, Any]]],
                        results: Mapping[str, float], points: int = 801
                        ) -> list[tuple[str, NDArray, NDArray, tuple[float, ...], float]]:
    """Each shaft's resultant bending moment |M| = √(M_y² + M_z²) [N·m] along its axis,
    for a drawing: (shaft, x [m], |M| [N·m], its bearings' positions [m], the mean pitch
    point [m]), x from the outermost of those over ``points`` positions and at each of
    them; shafts with no bearings left out. ``shafts`` are the solver inputs' shafts,
    ``results`` one design's results (:func:`shaft_bending_moments`, §9)."""
    drawn = []
    for shaft, gear in (("pinion", "a"), ("gear", "b")):
        if shaft not in shafts:
            continue
        positions = tuple(float(bearing["position"]) for bearing in shafts[shaft])
        angle = results[f"gear_{gear}_pitch_angle"]
        mesh, radius = (float(v) for v in mean_pitch_point(results["mean_cone_distance"],
                                                             angle))
        ends = [*positions, mesh]
        x = np.linspace(min(ends), max(ends), points)
        x = np.unique(np.concatenate([x, ends]))
        moment_y, moment_z = shaft_bending_moments(
            x, positions, mesh, radius, results["tangential_force"],
            results[f"gear_{gear}_radial_force"], results[f"gear_{gear}_axial_force"])
        drawn.append((shaft, x, np.hypot(moment_y, moment_z), positions, mesh))
    return drawn


def induced_axial_factor(bearing: Mapping[str, Any]) -> NDArray:
    """R of one bearing of an adjusted pair: the spec's ``induced_axial_factor``, else
    0.5/Y for a tapered roller bearing (the catalogue's Y above e, or ISO's 0.4·cotα) and
    the makers' table against α for an angular-contact ball bearing."""
    if bearing.get("induced_axial_factor") is not None:
        return np.asarray(bearing["induced_axial_factor"], dtype=float)
    alpha = np.asarray(bearing["contact_angle"], dtype=float)
    if traits(bearing["bearing_type"]).family == "roller":  # a tapered roller bearing
        y = bearing.get("load_y")
        return induced_axial_factor_tapered(0.4 / np.tan(alpha) if y is None else y)
    return induced_axial_factor_ball(alpha)


def shaft_axial_loads(arrangement: str, bearings: list[Mapping[str, Any]],
                      radial: tuple[NDArray, NDArray], axial_force: NDArray
                      ) -> tuple[list[NDArray], dict[str, list[NDArray]]]:
    """Each bearing's axial load, and for an adjusted pair the induced forces and the
    load case of each. Locating-floating: the locating bearing takes the whole force."""
    if arrangement == "locating-floating":  # a spiral pair's force may point either way
        return [np.abs(axial_force) if bearing["locating"] == "locating"
                else np.zeros_like(axial_force) for bearing in bearings], {}
    factors = [induced_axial_factor(bearing) for bearing in bearings]
    positions = [np.asarray(bearing["position"], dtype=float) for bearing in bearings]
    # Cases 1: Ka acts in the direction the second bearing supports.
    second_positive = supports_positive(positions[1], positions[0], arrangement)
    loads = adjusted_axial_loads(radial[0], radial[1], factors[0], factors[1], axial_force,
                                 second_positive == (axial_force >= 0))
    case = loads.case
    return [loads.first, loads.second], {
        "induced_axial_load": [factors[0] * radial[0], factors[1] * radial[1]],
        "load_case": [case, case]}
