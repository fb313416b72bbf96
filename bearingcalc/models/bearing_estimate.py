"""A bearing as mounted whose internal geometry the spec leaves out: estimated from its
catalogue data (:mod:`bearingcalc.core.internal_geometry`), said in a warning naming
every estimated value, and refused in one line where no estimate reproduces the
catalogue's ratings. Mixed into
:class:`bearingcalc.models.rolling_bearing.RollingBearingSpec` (``docs/physics.md``
§12)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingcalc.core.internal_geometry import (
    RATING_RATIO,
    TOLERANCE,
    EstimatedGeometry,
    estimate_ball_geometry,
    estimate_roller_geometry,
)
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.bearing_method_rules import ELEMENT_FIELDS
from bearingcalc.models.bearing_reads import ReadsBearing
from bearingcalc.models.rules import rule

#: The groove conformities an estimated ball bearing takes (the common fi, fe).
ESTIMATED_CONFORMITIES = (0.52, 0.53)


class GeometryEstimate(ReadsBearing):
    """The internal geometry of a bearing as mounted, estimated where the spec leaves
    it out."""

    if TYPE_CHECKING:  # the method's field (MountingFields)
        method: str

    @property
    def estimates_geometry(self) -> bool:
        """Whether the internal geometry is to be estimated: the method as mounted, none
        of the elements' sizes given, and the catalogue data to estimate them from."""
        if self.method != "iso-16281" or not self.type_traits.mounted:
            return False
        if any(getattr(self, name) is not None
               for names in ELEMENT_FIELDS.values() for name in names):
            return False
        return all(value is not None for value in (
            self.bore_diameter, self.outside_diameter, self.dynamic_load_rating,
            self.static_load_rating))

    def estimated_geometry(self) -> EstimatedGeometry | None:
        """The estimate of the elements' count and size, None where none fits; made once,
        from the nominal catalogue data (a study or sweep that varies them varies the
        bearing's ratings, not its balls or rollers)."""
        args = (_nominal(self.bore_diameter), _nominal(self.outside_diameter))
        ratings = (_nominal(self.dynamic_load_rating), _nominal(self.static_load_rating),
                   _nominal(self.angle), self.type)
        if self.rollers:
            width = None if self.width is None else _nominal(self.width)
            return estimate_roller_geometry(*args, width, *ratings)
        return estimate_ball_geometry(*args, *ratings)

    def estimated_inputs(self) -> dict[str, Any]:
        """The solver inputs the estimate fills in; none where the spec gives them. Where
        the bearing's size varies (``select``'s catalogue rows, a sweep of the bore) each
        size has its own estimate, from its designs' middle ratings; NaN where none
        fits, which the solver refuses."""
        if not self.estimates_geometry:
            return {}
        estimate = self.estimated_geometry()
        if estimate is None or not estimate.acceptable:
            return {}
        sizes = [self.bore_diameter, self.outside_diameter, self.width]
        if all(np.ndim(size) == 0 or np.ptp(size) == 0 for size in sizes if size is not None):
            return self._filled(estimate)
        return self._estimated_per_size()

    def _filled(self, estimate: Any) -> dict[str, Any]:
        """The inputs an estimate fills in (arrays of estimates' values alike)."""
        if self.rollers:
            return {"roller_count": estimate.count, "roller_diameter": estimate.diameter,
                    "roller_length": estimate.length,
                    "pitch_diameter": estimate.pitch_diameter}
        fi, fo = (self.inner_groove_conformity, self.outer_groove_conformity)
        return {"ball_count": estimate.count, "ball_diameter": estimate.diameter,
                "pitch_diameter": estimate.pitch_diameter,
                "inner_groove_conformity": ESTIMATED_CONFORMITIES[0] if fi is None else fi,
                "outer_groove_conformity": ESTIMATED_CONFORMITIES[1] if fo is None else fo}

    def _estimated_per_size(self) -> dict[str, Any]:
        """Each distinct size's estimate laid out over the designs."""
        values = [self.bore_diameter, self.outside_diameter,
                  0.0 if self.width is None else self.width, self.dynamic_load_rating,
                  self.static_load_rating]
        shape = np.broadcast_shapes(*(np.shape(value) for value in values))
        flat = [np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for v in values]
        sizes, which = np.unique(np.stack(flat[:3], axis=1), axis=0, return_inverse=True)
        which = np.ravel(which)
        angle, kind = _nominal(self.angle), self.type
        columns: dict[str, list[float]] = {}
        for index, (bore, outside, width) in enumerate(sizes):
            mine = which == index
            ratings = (float(np.median(flat[3][mine])), float(np.median(flat[4][mine])),
                       angle, kind)
            found = (estimate_roller_geometry(bore, outside, width or None, *ratings)
                     if self.rollers else estimate_ball_geometry(bore, outside, *ratings))
            usable = found is not None and found.acceptable
            for name, value in self._filled(found).items() if usable else ():
                columns.setdefault(name, [math.nan] * len(sizes))[index] = value
        if not columns:  # no size has an estimate: the names from the spec's own
            columns = {name: [math.nan] * len(sizes)
                       for name in self._filled(self.estimated_geometry())}
        return {name: np.array(column, dtype=float)[which].reshape(shape)
                for name, column in columns.items()}

    def estimate_notes(self) -> list[str]:
        """The warning that names every estimated value."""
        filled = self.estimated_inputs()
        if not filled:
            return []
        estimate = self.estimated_geometry()
        named = ", ".join(
            f"{name} {value:g}" if isinstance(value, int) or "conformity" in name
            else f"{name} {value * 1e3:.4g} mm" for name, value in filled.items()
            if getattr(self, name) is None)
        return [f"internal geometry estimated from the catalogue (ISO 281's C and ISO 76's "
                f"C0 of it {estimate.rating_ratio - 1:+.1%} and {estimate.static_ratio - 1:+.1%} "
                f"from the catalogue's): {named}; give the maker's for the bearing's own"]

    @rule
    def _geometry_estimated(self) -> SpecFieldError | None:
        if not self.estimates_geometry:
            return None
        estimate = self.estimated_geometry()
        if estimate is not None and estimate.acceptable:
            return None
        family = "balls" if not self.rollers else "rollers"
        nearest = "" if estimate is None else (
            f" (the nearest, {estimate.count} {family} of {estimate.diameter * 1e3:.4g} mm, "
            f"gives C {estimate.rating_ratio - 1:+.1%} and C0 "
            f"{estimate.static_ratio - 1:+.1%} off)")
        low, high = (ratio - 1.0 for ratio in RATING_RATIO)
        return SpecFieldError(ELEMENT_FIELDS[self.type_traits.family][0], "missing, and no "
                              "internal geometry of usual proportions gives ISO 76's C0 "
                              f"within {TOLERANCE:.0%} of the catalogue's and ISO 281's C "
                              f"within {low:+.0%} to {high:+.0%} of it{nearest}: give the "
                              "maker's internal geometry", at="method")


def _nominal(value: Any) -> float:
    """A number of the spec, or the middle of the values a study or sweep gives it."""
    return float(np.median(value))
