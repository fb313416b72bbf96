"""Spec of ``kind: thrust-bearing`` (docs/physics.md §1)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pydantic import Field

from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import Spec, SpecModel
from bearingcalc.models.materials import BallMaterial
from bearingcalc.models.plain_numbers import BallCount, Ratio
from bearingcalc.models.quantities import Angle, AngularSpeed, Force, PositiveLength, PositiveStress
from bearingcalc.models.rules import rule

if TYPE_CHECKING:
    from bearingcalc.core.solver_inputs import ThrustBearingInputs

_GEOMETRY = ("ball size", "contact_angle", "pitch_radius")


class ThrustBearingLimits(SpecModel):
    max_spin_to_roll: Ratio = Field(0.01, description="largest allowed |spin/roll| at the shaft")
    max_contact_pressure: PositiveStress = Field(4.2e9, description="largest Hertz pressure "
                                                 "at any contact (ISO 76's 4200 MPa)")


class ThrustBearingSpec(Spec):
    """A thrust bearing: balls between a fixed race and a shaft (docs/physics.md §1).

    At most one of the ball size, ``contact_angle`` and ``pitch_radius`` may be
    left out; it is then solved for pure rolling.
    """

    kind: Literal["thrust-bearing"]
    name: str | None = None
    ball_diameter: PositiveLength | None = None
    ball_radius: PositiveLength | None = None
    contact_angle: Angle | None = Field(None, description="shaft contact angle θ")
    pitch_radius: PositiveLength | None = Field(None, description="radius b of the ball centres")
    shaft_speed: AngularSpeed
    ball_count: BallCount | None = None
    axial_load: Force | None = Field(None, description="thrust Fa on the shaft, shared by "
                                     "the balls; adds the contact stresses")
    material: BallMaterial = BallMaterial()
    limits: ThrustBearingLimits = ThrustBearingLimits()

    @rule
    def _one_ball_size(self) -> SpecFieldError | None:
        if self.ball_diameter is not None and self.ball_radius is not None:
            return SpecFieldError("ball_radius", "give ball_diameter or ball_radius, not both")
        return None

    @rule
    def _one_unknown_at_most(self) -> SpecFieldError | None:
        given = (self.ball_size is not None, self.contact_angle is not None,
                 self.pitch_radius is not None)
        if given.count(False) > 1:
            missing = " and ".join(n for n, g in zip(_GEOMETRY, given, strict=True) if not g)
            return SpecFieldError(
                "contact_angle" if not given[1] else "pitch_radius",
                f"{missing} are all missing; give at least two of ball_diameter (or "
                "ball_radius), contact_angle and pitch_radius (the third is solved for pure "
                "rolling)")
        return None

    @rule
    def _load_shared(self) -> SpecFieldError | None:
        if self.axial_load is not None and self.ball_count is None:
            return SpecFieldError("axial_load", "the axial load is shared by the balls: give "
                                  "ball_count too")
        return None

    @property
    def ball_size(self) -> float | None:
        """Ball radius r from either field. [m]"""
        if self.ball_radius is not None:
            return self.ball_radius
        return None if self.ball_diameter is None else self.ball_diameter / 2.0

    def solver_inputs(self) -> ThrustBearingInputs:
        """SI inputs of :func:`bearingcalc.core.thrust_bearing.evaluate`."""
        return {
            "ball_radius": self.ball_size,
            "contact_angle": self.contact_angle,
            "pitch_radius": self.pitch_radius,
            "shaft_speed": self.shaft_speed,
            "ball_count": self.ball_count,
            "max_spin_to_roll": self.limits.max_spin_to_roll,
            "axial_load": self.axial_load,
            "elastic_modulus": self.material.elastic_modulus,
            "poisson_ratio": self.material.poisson_ratio,
            "density": self.material.density,
            "max_contact_pressure": self.limits.max_contact_pressure,
        }

    def field_as_written(self, field: str) -> str:
        """The spec's own name for a solver input (ball_radius may be ball_diameter)."""
        if field == "ball_radius" and self.ball_diameter is not None:
            return "ball_diameter"
        return field
