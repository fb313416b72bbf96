"""A rolling bearing's internal geometry estimated from its catalogue data (d, D, C, C0,
α), for ISO/TS 16281's load distribution where the maker publishes no more: the
rolling elements' count and size that make ISO 281's C and ISO 76's C0 of the geometry
closest to the catalogue's, among the proportions bearings are built to
(``docs/physics.md`` §12).

Balls come in the nominal sizes of ISO 3290-1's two series (whole 64ths of an inch,
half millimetres); rollers in half millimetres, each roller's effective length then
following from C0. The pitch diameter is the rings' mean, (d + D)/2.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from bearingcalc.core.bearing_types import traits
from bearingcalc.core.iso76 import static_load_rating
from bearingcalc.core.iso281 import dynamic_load_rating
from bearingcalc.core.roller_ratings import roller_dynamic_load_rating

#: The nominal ball diameters tried [m]: 1/64 in to 2 in, 0.5 mm to 60 mm.
BALL_SIZES = np.unique(np.round(np.concatenate([
    np.arange(1, 129) * 25.4e-3 / 64, np.arange(1, 121) * 0.5e-3]), 9))
#: The roller diameters tried [m]: 1 mm to 60 mm in half millimetres.
ROLLER_SIZES = np.arange(2, 121) * 0.5e-3
#: The share of the rings' section (D − d) an element's diameter takes, at least and
#: at most: the published bearings of tests/data span 0.26 to 0.32.
SECTION_SHARE = (0.2, 0.4)
#: How far ISO 76's C0 of an estimate may lie from the catalogue's (C0 is set by the
#: contact pressure, which makers rate as ISO 76 does).
TOLERANCE = 0.03
#: ISO 281's C of an estimate over the catalogue's, at least and at most: makers rate
#: modern steels up to about a tenth above ISO 281 for the same geometry (SKF's 6205:
#: 14.8 kN against ISO's 14.0 kN for its 9 balls of 5/16 in), never much below.
RATING_RATIO = (0.9, 1.03)
#: ISO 76's C0 of a radial roller bearing per (1 − γ)·Z·Lwe·Dwe·cos α: 44 N/mm² [N/m²].
ROLLER_C0_FACTOR = 44e6


class EstimatedGeometry(NamedTuple):
    """The estimate, and how near its ISO ratings come to the catalogue's."""

    count: int                 # Z [1]
    diameter: float            # Dw or Dwe [m]
    length: float | None       # Lwe [m], rollers
    pitch_diameter: float      # Dpw [m]
    rating_ratio: float        # ISO 281's C of the estimate over the catalogue's [1]
    static_ratio: float        # ISO 76's C0 of the estimate over the catalogue's [1]

    @property
    def acceptable(self) -> bool:
        """Whether its C0 lies within :data:`TOLERANCE` of the catalogue's and its C
        within :data:`RATING_RATIO` of it."""
        return (abs(self.static_ratio - 1.0) <= TOLERANCE
                and RATING_RATIO[0] <= self.rating_ratio <= RATING_RATIO[1])


# pure, and asked for again by each rule and result that reads the geometry
@functools.lru_cache(maxsize=256)
def estimate_ball_geometry(bore: float, outside: float, rating: float,
                           static_rating: float, contact_angle: float, bearing_type: str
                           ) -> EstimatedGeometry | None:
    r"""Z and Dw of a radial ball bearing that bring

    .. math:: C = b_m f_c (\cos\alpha)^{0.7} Z^{2/3} D_w^{1.8}, \qquad
              C_0 = f_0 Z D_w^2 \cos\alpha

    (ISO 281:2007 6.1; ISO 76:2006 6.1) closest to the catalogue's C0 and C (C0 first:
    a maker's C may lie above ISO 281's), among nominal ball sizes of 0.2 to 0.4 of the
    section (D − d) and counts that fill the type's share of the pitch circle (its
    trait ``fill``).
    [m, N, rad] Returns None where no candidate fits. Source: the estimate of KISSsoft
    and MESYS (balls of standard sizes, the ratings reproduced).
    """
    pitch = (bore + outside) / 2.0
    sizes = _in_section(BALL_SIZES, outside - bore)
    low, high = traits(bearing_type).fill
    counts = np.arange(3, 200, dtype=float)
    dw, z = (grid.ravel() for grid in np.meshgrid(sizes, counts))
    fill = z * dw / (np.pi * pitch)
    keep = (fill >= low) & (fill <= high)
    if not keep.any():
        return None
    dw, z = dw[keep], z[keep]
    c, _ = dynamic_load_rating(z, dw, pitch, contact_angle, family="ball")
    c0, _ = static_load_rating(z, dw, pitch, contact_angle, family="ball")
    return _best(z, dw, None, pitch, c / rating, c0 / static_rating)


# pure, and asked for again by each rule and result that reads the geometry
@functools.lru_cache(maxsize=256)
def estimate_roller_geometry(bore: float, outside: float, width: float | None,
                             rating: float, static_rating: float, contact_angle: float,
                             bearing_type: str) -> EstimatedGeometry | None:
    r"""Z, Dwe and Lwe of a radial roller bearing: for each roller size in half
    millimetres of 0.2 to 0.4 of the section and each count that fills the type's share
    of the pitch circle, the length that makes ISO 76's C0 the catalogue's,

    .. math:: L_{we} = \frac{C_0}{44\,(1 - γ)\,Z\,D_{we}\cos\alpha}, \quad
              γ = \frac{D_{we}\cos\alpha}{D_{pw}}

    kept where it lies within the type's lengths (and the width B); of those whose ISO
    281 C lies within :data:`RATING_RATIO` of the catalogue's, the one nearest the usual
    proportion Lwe/Dwe (C fixes the roller's diameter closely, but trades its count
    against its length), else the one whose C comes nearest. [m, N, rad] Returns None
    where no candidate fits. Source: ISO 76:2006 7.1; ISO 281:2007 7.1.
    """
    pitch = (bore + outside) / 2.0
    cos = np.cos(contact_angle)
    sizes = _in_section(ROLLER_SIZES, outside - bore)
    low, high = traits(bearing_type).fill
    dwe, z = (grid.ravel() for grid in np.meshgrid(sizes, np.arange(3, 300, dtype=float)))
    gamma = dwe * cos / pitch
    lwe = static_rating / (ROLLER_C0_FACTOR * (1.0 - gamma) * z * dwe * cos)
    shortest, longest, usual = traits(bearing_type).roller_proportion
    fill = z * dwe / (np.pi * pitch)
    keep = ((fill >= low) & (fill <= high) & (lwe >= shortest * dwe)
            & (lwe <= longest * dwe) & (gamma < 1.0))
    if width is not None:
        keep &= lwe <= width
    if not keep.any():
        return None
    z, dwe, lwe = z[keep], dwe[keep], lwe[keep]
    c, _ = roller_dynamic_load_rating(z, dwe, lwe, pitch, contact_angle,
                                      bearing_type=bearing_type)
    near = (RATING_RATIO[0] <= c / rating) & (c / rating <= RATING_RATIO[1])
    if near.any():
        i = int(np.argmin(np.where(near, np.abs(np.log(lwe / (usual * dwe))), np.inf)))
        return EstimatedGeometry(int(z[i]), float(dwe[i]), float(lwe[i]), pitch,
                                 float(c[i] / rating), 1.0)
    return _best(z, dwe, lwe, pitch, c / rating, np.ones_like(c))


def _in_section(sizes: NDArray, section: float) -> NDArray:
    """The ``sizes`` between the least and the largest share of the rings' section."""
    low, high = (share * section for share in SECTION_SHARE)
    return sizes[(low <= sizes) & (sizes <= high)]


def _best(count: NDArray, diameter: NDArray, length: NDArray | None, pitch: float,
          rating_ratio: NDArray, static_ratio: NDArray) -> EstimatedGeometry | None:
    """Of the acceptable candidates (else of all, for the message that refuses them),
    the one whose ratings come nearest the catalogue's: C0 first, C a quarter as much
    (a maker's C may lie above ISO's); None where none has ratings."""
    deviation = np.abs(np.log(static_ratio)) + 0.25 * np.abs(np.log(rating_ratio))
    acceptable = ((np.abs(static_ratio - 1.0) <= TOLERANCE) & (RATING_RATIO[0] <= rating_ratio)
                  & (rating_ratio <= RATING_RATIO[1]))
    if acceptable.any():
        deviation = np.where(acceptable, deviation, np.inf)
    if not np.isfinite(deviation).any():
        return None
    i = int(np.nanargmin(deviation))
    return EstimatedGeometry(int(count[i]), float(diameter[i]),
                             None if length is None else float(length[i]), pitch,
                             float(rating_ratio[i]), float(static_ratio[i]))
