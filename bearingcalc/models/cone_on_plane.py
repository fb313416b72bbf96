"""Spec of ``kind: cone-on-plane`` (docs/physics.md §3)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pydantic import Field

from bearingcalc.models.base import Spec
from bearingcalc.models.quantities import Angle, AngularAccel, AngularSpeed, PositiveLength

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import ConeOnPlaneInputs


class ConeOnPlaneSpec(Spec):
    """A right circular cone rolling on a fixed plane about its fixed apex."""

    kind: Literal["cone-on-plane"]
    name: str | None = None
    half_angle: Angle = Field(description="half-angle β of the cone, 0 deg < β < 90 deg")
    spin_speed: AngularSpeed = Field(description="angular speed ω about the contact line")
    spin_accel: AngularAccel = 0.0
    axis_point_height: PositiveLength | None = Field(
        None, description="height a above the plane of a point on the cone axis")

    def solver_inputs(self) -> ConeOnPlaneInputs:
        """SI inputs of :func:`bearingcalc.core.cone_on_plane.evaluate`."""
        return {
            "half_angle": self.half_angle,
            "spin_speed": self.spin_speed,
            "spin_accel": self.spin_accel,
            "axis_point_height": self.axis_point_height,
        }
