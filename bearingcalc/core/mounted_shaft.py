"""A drive's shaft on its bearings as mounted (``method: iso-16281`` of ``kind:
bevel-drive``): the rigid shaft under the gear's force at its mean pitch point rests on
every bearing's contacts (:mod:`bearingcalc.core.iso16281_shaft`); a floating
bearing's outer ring slides, so it carries no axial force; an adjusted pair is set by
its end play or preload. Each bearing's loads, contacts and reference life, and the
shaft's displacement, at rest and loaded. ``docs/physics.md`` §12.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core import mounted_ball_bearing, mounted_roller_bearing
from bearingcalc.core.bearing_types import traits
from bearingcalc.core.iso16281_newton import bracketed_newton
from bearingcalc.core.iso16281_shaft import (
    ShaftBearing,
    ShaftEquilibrium,
    axial_deflection_for_load,
    solve_shaft,
)
from bearingcalc.core.mounted_clearance import operating_clearance_of
from bearingcalc.core.mounted_pair import BearingFamily
from bearingcalc.core.mounted_setting import AXIAL_SIGN, end_play_loss

#: How far a floating bearing's own axial coordinate is searched [m]: its outer ring
#: slides within this of its centred place.
FLOATING_RANGE = 2e-3
#: Steps of a floating bearing's search: bisection alone halves 4 mm to 3.5 fm in 60.
_FLOATING_ITERATIONS = 60


class MountedShaft(NamedTuple):
    """A shaft solved as mounted: its equilibria loaded and at rest, its bearings'
    families and lives, and each bearing's axial load at rest (its preload)."""

    loaded: ShaftEquilibrium
    rest: NDArray              # (N, 5) the shaft's displacement at rest [m, rad]
    families: list[BearingFamily]
    lives: list[Any]
    preload: NDArray
    #: an adjusted pair's end play lost to its bearings' mountings [m], flat over the
    #: designs, and its end play as set (keys of
    #: :func:`~bearingcalc.core.mounted_setting.end_play_loss`, and ``set_end_play``);
    #: empty without them
    setting: dict[str, NDArray] | None = None
    #: where an adjusted pair's bearings overlap (their rolling elements' spread below
    #: half their widths summed, or not above zero)
    overlapping: NDArray | None = None


def gear_load(pair: Mapping[str, NDArray], gear: str, mesh: tuple[NDArray, NDArray]
              ) -> NDArray:
    r"""The gear's force on its shaft as the shaft's generalised load at the apex,
    (N, 5) = (Fx, Fy, Fz, My, −Mz) [N, N·m]: the mean pitch point at (x_p, r_p, 0), its
    radial force W_r toward the axis (−y), the tangential W_t along +z, the axial W_a
    along +x (away from the apex), and their moment about the apex,

    .. math:: M = (x_p, r_p, 0) \times (W_a, -W_r, W_t)
              = (r_p W_t,\ -x_p W_t,\ -x_p W_r - r_p W_a)

    (its x part, the torque, turns the shaft); θz turns the other way from z, so its
    load is −Mz. Source: the statics of :mod:`bearingcalc.core.shaft_statics`.
    """
    x_p, r_p = (np.asarray(v, dtype=float) for v in mesh)
    w_t = np.asarray(pair["tangential_force"], dtype=float)
    w_r = np.asarray(pair[f"gear_{gear}_radial_force"], dtype=float)
    w_a = np.asarray(pair[f"gear_{gear}_axial_force"], dtype=float)
    parts = np.broadcast_arrays(w_a, -w_r, w_t, -x_p * w_t, x_p * w_r + r_p * w_a)
    return np.stack([np.reshape(part, -1) for part in parts], axis=1)


def bearing_family(inputs: Mapping[str, Any], flat: Any) -> BearingFamily:
    """The family adapter of a drive's bearing (its C the catalogue's or ISO's)."""
    module = (mounted_roller_bearing if traits(str(inputs["bearing_type"])).family
              == "roller" else mounted_ball_bearing)
    c = inputs.get("dynamic_load_rating")
    if takes_clearance(inputs):  # its clearance follows from the drawing
        inputs = {**inputs, "operating_clearance": operating_clearance_of(inputs)}
    return module.bearing_family(inputs, flat, np.nan if c is None else c)


def takes_clearance(inputs: Mapping[str, Any]) -> bool:
    """Whether a bearing's mounting sets its own operating clearance: a bearing with a
    radial clearance; a one-way bearing of an adjusted pair gives its pair's end play."""
    return (inputs.get("mounting") is not None
            and not traits(str(inputs["bearing_type"])).one_way)


def floating(contacts: Callable[[NDArray], Any]) -> Callable[[NDArray], Any]:
    r"""A floating bearing's contacts: its outer ring slides until its elements carry no
    axial force, so at every q [m, rad] the bearing's own δx is the root of
    F_x(δx) = 0 [N] (:func:`~bearingcalc.core.iso16281_newton.bracketed_newton`; F_x
    grows with δx), and its stiffness is condensed,

    .. math:: K_c = K - K_{\cdot x} K_{x \cdot} / K_{xx}

    the minimum of its energy over δx, convex in the rest of q as the energy is. Source:
    static condensation (Guyan reduction) of the bearing's own axial coordinate.
    """
    def condensed(q: NDArray) -> Any:
        trial = np.array(q, dtype=float)

        def axial(x: NDArray) -> tuple[NDArray, NDArray, NDArray]:
            trial[:, 0] = x
            state = contacts(trial)
            return (state.force[:, 0], state.stiffness[:, 0, 0],
                    1e-13 * np.max(np.abs(state.force[:, 1:3]), axis=1))

        size = trial.shape[0]
        trial[:, 0] = bracketed_newton(axial, np.zeros(size), np.full(size, -FLOATING_RANGE),
                                       np.full(size, FLOATING_RANGE), _FLOATING_ITERATIONS)
        state = contacts(trial)
        stiffness = state.stiffness
        k_xx = stiffness[:, 0:1, 0:1]
        with np.errstate(divide="ignore", invalid="ignore"):
            coupling = np.where(k_xx > 0.0, stiffness[:, :, 0:1] * stiffness[:, 0:1, :]
                                / k_xx, 0.0)
        force = state.force.copy()
        force[:, 0] = 0.0
        return state._replace(force=force, stiffness=stiffness - coupling)

    return condensed


def solve_mounted_shaft(bearings: list[Mapping[str, Any]], arrangement: str,
                        setting: Mapping[str, Any], load: NDArray, flat: Any
                        ) -> MountedShaft:
    """A drive's shaft on ``bearings`` (each a rolling bearing's inputs with its
    ``position`` and ``locating``) under the gear's generalised ``load`` (N, 5), in
    its ``arrangement``, an adjusted pair set by ``setting`` (``end_play`` or
    ``preload``): loaded and at rest."""
    families = [bearing_family(bearing, flat) for bearing in bearings]
    positions = [flat(bearing["position"]) for bearing in bearings]
    spread, overlapping = _spread(bearings, arrangement, families, positions, flat)
    lost = _lost_to_mountings(bearings, arrangement, setting, spread, families, flat)
    on_shaft = []
    thrust = np.sign(load[:, 0]) + (load[:, 0] == 0.0)
    for i, (bearing, family) in enumerate(zip(bearings, families, strict=True)):
        if arrangement == "locating-floating":
            orientation = thrust if traits(str(bearing["bearing_type"])).one_way else 1.0
            offset = family.first_contact
            contacts = family.contacts
            if bearing.get("locating") != "locating":
                contacts = floating(family.contacts)
        else:
            other = positions[1 - i]
            first = positions[i] < other
            orientation = np.where(first == (arrangement == "back-to-back"), 1.0, -1.0)
            offset = _setting_offset(setting, family, flat) + lost.get("loss", 0.0) / 2.0
            contacts = family.contacts
        on_shaft.append(ShaftBearing(contacts, positions[i] + orientation
                                     * family.centre_offset, orientation, offset))
    lever = np.max(np.abs(np.stack(positions)), axis=0) + families[0].lever
    loaded = solve_shaft(on_shaft, load, lever)
    # at rest only a preload holds the shaft in one place; with play it rests at Q = 0,
    # the datum its displacements count from
    preloaded = _preloaded(setting, arrangement, flat, load.shape[0])
    if lost:  # as it runs: a mounting may turn a preload into play and play into preload
        preloaded = lost["set_end_play"] - lost["loss"] < 0.0
    rest = np.zeros_like(load)
    preload = np.zeros(load.shape[0])
    if preloaded.any():
        at_rest = solve_shaft(on_shaft, rest, lever)
        rest = np.where(preloaded[:, None], at_rest.displacement, 0.0)
        preload = np.where(preloaded, np.max(np.stack(
            [np.abs(c.force[:, 0]) for c in at_rest.contacts]), axis=0), 0.0)
    lives = [family.life(contacts) for family, contacts in zip(families, loaded.contacts,
                                                               strict=True)]
    return MountedShaft(loaded, rest, families, lives, preload, lost, overlapping)


def _preloaded(setting: Mapping[str, Any], arrangement: str, flat: Any, size: int
               ) -> NDArray:
    """Where an adjusted shaft is set with a preload (or a negative end play)."""
    if arrangement == "locating-floating":
        return np.zeros(size, dtype=bool)
    if setting.get("preload") is not None:
        return np.ones(size, dtype=bool)
    return flat(setting["end_play"]) < 0.0


def _spread(bearings: list[Mapping[str, Any]], arrangement: str,
            families: list[BearingFamily], positions: list[NDArray], flat: Any
            ) -> tuple[NDArray | None, NDArray | None]:
    """An adjusted pair's spread between its rolling elements [m], flat over the
    designs, and where the two bearings overlap: the elements lie c = (Dpw/2)·tan α
    inside their pressure centres back-to-back, outside them face-to-face, and two
    bearings side by side have their elements half their widths summed apart (more
    than none where a width is not given). (None, None) on a locating-floating shaft."""
    if arrangement == "locating-floating":
        return None, None
    spread = np.abs(positions[1] - positions[0]) + AXIAL_SIGN[arrangement] * (
        families[0].pressure_offset + families[1].pressure_offset)
    widths = [bearing.get("width") for bearing in bearings]
    if any(width is None for width in widths):
        return spread, ~(spread > 0.0)
    closest = 0.5 * (flat(widths[0]) + flat(widths[1]))
    return spread, spread < closest * (1.0 - 1e-9)


def _lost_to_mountings(bearings: list[Mapping[str, Any]], arrangement: str,
                       setting: Mapping[str, Any], spread: NDArray | None,
                       families: list[BearingFamily], flat: Any) -> dict[str, NDArray]:
    """What an adjusted pair's mountings take of its end play over the ``spread``, flat
    over the designs, with its end play as set (a preload's: each bearing's deflection
    under it short of first contact); empty on a locating-floating shaft or without
    mountings."""
    if spread is None or not all(
            bearing.get("mounting") is not None
            and traits(str(bearing["bearing_type"])).one_way for bearing in bearings):
        return {}
    lost = end_play_loss(bearings, arrangement, str(setting.get("stage") or "mounted"),
                         spread, flat)
    if setting.get("preload") is not None:
        # each bearing's offset o = δa(P) = δx at first contact − e/2: e its share
        lost["set_end_play"] = sum(family.first_contact - axial_deflection_for_load(
            family.contacts, flat(setting["preload"])) for family in families)
    else:
        lost["set_end_play"] = flat(setting["end_play"])
    return lost


def _setting_offset(setting: Mapping[str, Any], family: BearingFamily, flat: Any) -> NDArray:
    """An adjusted bearing's axial offset o from its datum: e/2 short of first contact
    for an end play e, its own deflection under the preload P for a preload."""
    if setting.get("preload") is not None:
        return axial_deflection_for_load(family.contacts, flat(setting["preload"]))
    return family.first_contact - flat(setting["end_play"]) / 2.0
