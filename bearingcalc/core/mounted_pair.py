"""A matched pair as mounted (``method: iso-16281``, ``arrangement: back-to-back``,
``face-to-face`` or ``tandem``): two identical angular-contact ball or tapered roller
bearings on one rigid shaft (:mod:`bearingcalc.core.iso16281_shaft`), set against each
other by an end play or a preload, their pressure centres ``pair_spacing`` apart. The
pair's results are the shaft's and the two bearings' together; each bearing's own are
along ``member`` and its elements along ``element``. ``docs/physics.md`` §12.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core import mounted_bearing as shared
from bearingcalc.core.bearing_life import ROLLER_WEIBULL_SLOPE, WEIBULL_SLOPE, system_life
from bearingcalc.core.common import DerivedTest, Family, Found
from bearingcalc.core.iso16281_shaft import (
    ShaftBearing,
    axial_deflection_for_load,
    solve_shaft,
)
from bearingcalc.core.mounted_clearance import chain_warnings, mounted_clearance
from bearingcalc.core.mounted_setting import AXIAL_SIGN, end_play_loss, operating_end_play
from bearingcalc.core.solver import Along, AxisResults

#: The pair's results besides the single bearing's.
RESULTS: dict[str, tuple[str, str]] = {
    "preload_force": ("N", "the axial load each bearing of the pair carries at rest, from "
                      "its setting (0 with end play)"),
    "pair_spacing_used": ("m", "the distance of the two pressure centres (negative: a "
                          "face-to-face pair whose pressure centres lie past each other)"),
}
#: Each bearing of the pair, a row per bearing.
MEMBER_RESULTS = AxisResults({
    "axial_load": ("N", "the axial load its contacts carry"),
    "radial_load": ("N", "the radial load its contacts carry"),
    "max_element_load": ("N", "its largest rolling-element load"),
    "reference_rating_life": ("s", "its L10r"),
}, after="pair_spacing_used", meaning="{row}: {meaning}",
    # a bearing that the loads lift off its elements lives for ever
    unbounded=("reference_rating_life",))
#: What a bearing as mounted reports along each axis: its elements, a pair's bearings.
ALONG = {"element": shared.ELEMENT_RESULTS, "member": MEMBER_RESULTS}
#: The status code of a pair whose spacing cannot be found.
NO_SPACING = 33
STATUS_REASONS = {
    NO_SPACING: ("pair_spacing", DerivedTest(
        "the pair's bearings overlap: their pressure centres and widths leave no room for "
        "both (side by side, their centres lie B + 2c apart back-to-back, B − 2c "
        "face-to-face, B in tandem, c = (Dpw/2)·tanα: spacers only part them further); "
        "give pair_spacing, the distance of the pressure centres")),
}
#: How the two bearings face each other: (bearing 1's side, bearing 2's orientation).
#: Bearing 1 carries the thrust that pushes the shaft toward +x.
_FACING = {"back-to-back": (-1.0, -1.0), "face-to-face": (1.0, -1.0), "tandem": (-1.0, 1.0)}


class BearingFamily(NamedTuple):
    """What the pair needs of its bearings' family, arrays over the flat designs."""

    family: Family
    #: q (N, 5) -> the bearing's contacts (energy, force, stiffness, element_load, azimuth)
    contacts: Callable[[NDArray], Any]
    #: its reference point (a ball bearing's ball plane) lies this far past its pressure
    #: centre, (Dpw/2)·tan α0 for balls, 0 for rollers (whose point is the centre) [m]
    centre_offset: NDArray
    #: its pressure centre lies c = (Dpw/2)·tan α from its middle, outward from its back [m]
    pressure_offset: NDArray
    #: δx at first contact, from the bearing's own axial datum [m]
    first_contact: NDArray
    #: the pitch radius, the lever of a tilt [m]
    lever: NDArray
    #: contacts -> the bearing's ReferenceLife
    life: Callable[[Any], Any]
    #: contacts -> (inner pressure, outer pressure, crushed) over its elements
    pressures: Callable[[Any], tuple[NDArray, NDArray, NDArray]]
    #: (q, contacts) -> each element's signed deflection (N, Zmax)
    deflection: Callable[[NDArray, Any], NDArray]
    #: the exponent p of L = (C/P)^p
    life_exponent: float
    #: the status codes of contacts beyond Hertz's theory, by the input that causes them
    crushing: Mapping[str, tuple[int, str]]
    #: contacts -> where a roller is edge-loaded (rollers only)
    edge_loaded: Callable[[Any], NDArray] | None = None


def pair_results(inputs: Mapping[str, Any], family: BearingFamily, flat: Any,
                 shape: tuple[int, ...], c: NDArray, iso281: Mapping[str, Any],
                 speed: NDArray) -> tuple[Found, dict[str, Along]]:
    """The pair's results, each bearing's along ``member`` and every element's along
    ``element``, from the bearing's inputs (``setting_end_play`` or
    ``setting_preload``, ``pair_spacing`` or ``width``), its family and ISO 281's
    results of the pair."""
    arrangement = str(inputs["arrangement"])
    spacing, overlap = _spacing(inputs, family, flat)
    lost = _lost_to_mounting(inputs, family, spacing, flat)
    end_play, preload = _setting(inputs, family, flat, arrangement, lost.get("loss", 0.0))
    side, orientation = _FACING[arrangement]
    bearings = []
    for sign, facing in ((side, 1.0), (-side, orientation)):
        centre = sign * spacing / 2.0
        bearings.append(ShaftBearing(family.contacts, centre + facing * family.centre_offset,
                                     facing, family.first_contact - end_play / 2.0))
    lever = np.abs(spacing) / 2.0 + family.pressure_offset + family.lever
    misalignment = inputs.get("misalignment")
    solved = solve_shaft(bearings, shared.applied_loads(inputs, flat, spacing.size), lever,
                         fixed_tilt=None if misalignment is None else flat(misalignment))
    lives = [family.life(contacts) for contacts in solved.contacts]
    inner, outer = (np.maximum(*parts) for parts in zip(
        *((p[0], p[1]) for p in (family.pressures(each) for each in solved.contacts)),
        strict=True))
    slope = WEIBULL_SLOPE if family.family == "ball" else ROLLER_WEIBULL_SLOPE
    revolutions = system_life([life.revolutions for life in lives], slope)
    pair_rating = np.asarray(iso281.get("pair_dynamic_load_rating", c), dtype=float)
    reference = shared.LifeOf(revolutions, flat(pair_rating)
                              / (revolutions / 1e6) ** (1.0 / family.life_exponent))
    found = shared.completed(
        inputs, _scalars(inputs, family, solved, (spacing, preload, overlap), flat),
        (inner, outer), reference, iso281, speed, shape, family.family)
    if lost:
        chain = mounted_clearance(inputs)
        found.results.update(_as_mounted(chain, lost, end_play, shape))
        # each ring against creep under its own load: the more heavily loaded bearing's
        radial = np.max(np.stack([np.hypot(c.force[:, 1], c.force[:, 2])
                                  for c in solved.contacts]), axis=0).reshape(shape)
        found.flags.update(chain_warnings({**inputs, "radial_load": radial}, chain))
    return found, {"member": _members(solved, lives, speed, shape),
                   "element": _elements(solved, shape)}


def _lost_to_mounting(inputs: Mapping[str, Any], family: BearingFamily, spacing: NDArray,
                      flat: Any) -> dict[str, NDArray]:
    """What the pair's mounting (both bearings on the same seats) takes of its end
    play, flat over the designs; empty without one."""
    arrangement = str(inputs["arrangement"])
    if inputs.get("mounting") is None or arrangement not in AXIAL_SIGN:
        return {}
    # the rolling elements lie c = (Dpw/2)·tan α inside their pressure centres
    # back-to-back, outside them face-to-face
    spread = spacing + AXIAL_SIGN[arrangement] * 2.0 * family.pressure_offset
    return end_play_loss([inputs, inputs], arrangement,
                         str(inputs.get("setting_stage") or "mounted"), spread, flat)


def _as_mounted(chain: Mapping[str, NDArray], lost: Mapping[str, NDArray],
                end_play: NDArray, shape: tuple[int, ...]) -> dict[str, NDArray]:
    """The setting's results, and each bearing's fits from its ``chain`` (the same
    seats for both)."""
    fits = {key: np.broadcast_to(value, shape) for key, value in chain.items()
            if key.startswith(("fit_", "effective_", "inner_ring_hoop"))}
    return {**fits, **operating_end_play({**lost, "set_end_play": end_play
                                          + lost["loss"]}, shape)}


def _spacing(inputs: Mapping[str, Any], family: BearingFamily, flat: Any
             ) -> tuple[NDArray, NDArray]:
    """The distance of the pressure centres [m] (signed: negative where a face-to-face
    pair's lie past each other) and where two bearings side by side would overlap.
    Given, it is ``pair_spacing`` (closer than side by side where the width is given:
    overlapping); else two bearings of width B side by side (:func:`_side_by_side`)."""
    given, width = inputs.get("pair_spacing"), inputs.get("width")
    twice = 2.0 * family.pressure_offset
    arrangement = str(inputs["arrangement"])
    if given is not None:
        spacing = flat(given)
        if width is None:
            return spacing, np.zeros(spacing.shape, dtype=bool)
        # two bearings side by side are as close as their centres come
        closest = _side_by_side(flat(width), twice, arrangement)
        return spacing, spacing < closest - 1e-9 * np.abs(closest)
    width = flat(width)
    return _side_by_side(width, twice, arrangement), ~(width > 0.0)


def _side_by_side(width: NDArray, twice: NDArray, arrangement: str) -> NDArray:
    """The pressure centres' distance of two bearings of width B side by side: B + 2c
    back-to-back, B − 2c face-to-face, B in tandem."""
    return width + {"back-to-back": twice, "face-to-face": -twice,
                    "tandem": 0.0 * twice}[arrangement]


def _setting(inputs: Mapping[str, Any], family: BearingFamily, flat: Any, arrangement: str,
             lost: Any = 0.0) -> tuple[NDArray, NDArray]:
    """The pair's end play e [m] (negative: preload) and the preload at rest [N], as it
    runs: from ``setting_end_play``, or the end play at which each bearing carries
    ``setting_preload`` at rest, e = −2·(δa(P) − δx at first contact), less what its
    mounting takes (``lost``)."""
    size = family.first_contact.size
    if arrangement == "tandem":
        return np.zeros(size), np.zeros(size)
    preload = inputs.get("setting_preload")
    if preload is not None:
        deflection = axial_deflection_for_load(family.contacts, flat(preload))
        end_play = -2.0 * (deflection - family.first_contact)
        if np.ndim(lost) == 0 and lost == 0.0:
            return end_play, flat(preload)
        end_play = end_play - lost
    else:
        end_play = flat(inputs["setting_end_play"]) - lost
    at_rest = np.zeros((size, 5))
    at_rest[:, 0] = np.maximum(-end_play / 2.0, 0.0) + family.first_contact
    return end_play, np.where(end_play < 0.0, family.contacts(at_rest).force[:, 0], 0.0)


def _scalars(inputs: Mapping[str, Any], family: BearingFamily, solved: Any,
             setting: tuple[NDArray, NDArray, NDArray], flat: Any) -> Found:
    """The pair's scalars over the flat designs, with the checks of its spacing, its
    equilibrium and Hertz's theory."""
    spacing, preload, overlap = setting
    loads = np.concatenate([c.element_load for c in solved.contacts], axis=1)
    loaded = np.nan_to_num(loads) > 0
    zones = [shared.load_zone_angle(family.deflection(q, c), c.azimuth)
             for q, c in zip(solved.local, solved.contacts, strict=True)]
    results = {
        "ring_displacement_radial": solved.displacement[:, 1],
        "ring_displacement_axial": solved.displacement[:, 0],
        "ring_tilt": solved.displacement[:, 4],
        "max_element_load": np.max(np.nan_to_num(loads), axis=1),
        "loaded_elements": loaded.sum(axis=1).astype(float),
        "load_zone_angle": np.maximum(*zones),
        "stiffness_radial": solved.stiffness[:, 1, 1],
        "stiffness_axial": solved.stiffness[:, 0, 0],
        "stiffness_tilt": solved.stiffness[:, 4, 4],
        "equilibrium_residual": solved.residual,
        **shared.stiffness_entries(solved.stiffness),
        "preload_force": preload, "pair_spacing_used": spacing,
    }
    if hasattr(solved.contacts[0], "contact_angle"):
        with np.errstate(invalid="ignore"):
            results.update(shared.contact_angle_range(loads, np.concatenate(
                [c.contact_angle for c in solved.contacts], axis=1)))
    if inputs.get("misalignment") is not None:
        results["tilting_moment_reaction"] = solved.force[:, 4]
    results.update(shared.rib_load(inputs, results["max_element_load"], flat))
    crushed = np.logical_or(*(family.pressures(c)[2] for c in solved.contacts))
    flags = {} if family.edge_loaded is None else {"edge_loaded": np.logical_or(
        *(family.edge_loaded(c) for c in solved.contacts))}
    crushed |= ~shared.within_model(solved.displacement, family.lever)
    return Found(results, flags, checks=[
        (NO_SPACING, overlap), (shared.NO_EQUILIBRIUM, ~solved.converged),
        (shared.crushing_code(inputs, family.crushing), crushed)])


def _members(solved: Any, lives: list[Any], speed: NDArray, shape: tuple[int, ...]
             ) -> Along:
    """Each bearing's axial and radial load, largest element load and L10r, a row each."""
    turns = np.abs(np.asarray(speed, dtype=float)) / (2.0 * np.pi)
    columns: dict[str, list[NDArray]] = {key: [] for key in MEMBER_RESULTS.columns}
    for contacts, life in zip(solved.contacts, lives, strict=True):
        columns["axial_load"].append(np.abs(contacts.force[:, 0]))
        columns["radial_load"].append(np.hypot(contacts.force[:, 1], contacts.force[:, 2]))
        columns["max_element_load"].append(np.max(np.nan_to_num(contacts.element_load),
                                                  axis=1))
        columns["reference_rating_life"].append(life.revolutions)
    values = {key: np.stack([np.reshape(v, shape) for v in rows])
              for key, rows in columns.items()}
    values["reference_rating_life"] = values["reference_rating_life"] / turns
    return Along(("bearing_1", "bearing_2"), values, ("bearings of the pair",) * 2)


def _elements(solved: Any, shape: tuple[int, ...]) -> Along:
    """Every element of both bearings along ``element``, each bearing's under its own
    heading."""
    parts = [shared.element_rows({key: getattr(c, key) for key in ("azimuth", "element_load",
                                                                  "contact_angle")
                                  if hasattr(c, key)}, shape) for c in solved.contacts]
    rows, headings, values = [], [], {}
    for number, part in enumerate(parts, start=1):
        rows += [f"bearing_{number}_{row}" for row in part.rows]
        headings += [f"bearing {number}: rolling elements as mounted"] * len(part.rows)
        for key, value in part.values.items():
            name = "load" if key == "element_load" else key
            values[name] = value if name not in values else np.concatenate([values[name],
                                                                            value])
    return Along(tuple(rows), values, tuple(headings))
