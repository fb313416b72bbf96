"""Spec of ``kind: disk-on-circle`` (docs/physics.md §2)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pydantic import Field

from bearingcalc.models.base import Spec
from bearingcalc.models.quantities import AngularAccel, AngularSpeed, PositiveLength

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import DiskOnCircleInputs


class DiskOnCircleSpec(Spec):
    """A disk rolling on the outside (external) or inside (internal) of a circle."""

    kind: Literal["disk-on-circle"]
    name: str | None = None
    disk_radius: PositiveLength = Field(description="radius r of the rolling disk")
    surface_radius: PositiveLength = Field(description="radius R of the circular surface")
    contact: Literal["external", "internal"] = "external"
    disk_speed: AngularSpeed = Field(description="absolute angular velocity ω of the disk")
    disk_accel: AngularAccel = 0.0
    surface_speed: AngularSpeed = Field(0.0, description="Ω; 0 for a fixed surface")
    surface_accel: AngularAccel = 0.0

    def solver_inputs(self) -> DiskOnCircleInputs:
        """SI inputs of :func:`bearingcalc.core.disk_on_circle.evaluate`."""
        return {
            "disk_radius": self.disk_radius,
            "surface_radius": self.surface_radius,
            "internal": self.contact == "internal",
            "disk_speed": self.disk_speed,
            "disk_accel": self.disk_accel,
            "surface_speed": self.surface_speed,
            "surface_accel": self.surface_accel,
        }
