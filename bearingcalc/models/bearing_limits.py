"""The limits a rolling bearing is judged against (``kind: rolling-bearing``'s
``limits``; a drive's bearings share its life and static safety)."""

from __future__ import annotations

from pydantic import Field

from bearingcalc.models.base import SpecModel
from bearingcalc.models.plain_numbers import Ratio
from bearingcalc.models.quantities import (
    Length,
    PositiveStiffness,
    PositiveStress,
    PositiveTime,
)


class BallBearingLimits(SpecModel):
    min_rating_life: PositiveTime | None = Field(None, description="judged on the modified "
                                                 "rating life; not judged when absent")
    min_static_safety: Ratio = Field(1.0, description="smallest static safety factor s0")
    max_spin_to_roll: Ratio | None = Field(None, description="largest |spin/roll|, judged "
                                           "at the race that is not controlling")
    max_contact_pressure: PositiveStress | None = Field(
        None, description="largest Hertz pressure; ISO 76's by default: 4200 MPa for ball "
        "bearings, 4000 MPa for roller bearings")
    min_stiffness_radial: PositiveStiffness | None = Field(
        None, description="iso-16281: the least radial stiffness, like 100 N/µm")
    min_stiffness_axial: PositiveStiffness | None = Field(
        None, description="iso-16281: the least axial stiffness, like 50 N/µm")
    min_operating_clearance: Length | None = Field(
        None, description="iso-16281 with a mounting: the least operating clearance, like "
        "0 µm (no assembly preloaded); negative: the most preload")
