"""Lubrication of a rolling bearing: the operating viscosity, given or found from the
oil's ν40 and ν100 at the operating temperature (ISO 281:2007 Annex; ASTM D341)."""

from __future__ import annotations

import math

import numpy as np
from pydantic import Field

from bearingcalc.core.iso281 import (
    MAX_OPERATING_VISCOSITY,
    walther_temperature,
    walther_viscosity,
)
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import SpecModel
from bearingcalc.models.quantities import PositiveViscosity, Temperature
from bearingcalc.models.rules import rule


class Lubrication(SpecModel):
    """The operating viscosity, given or found from ν40, ν100 and the temperature."""

    viscosity: PositiveViscosity | None = Field(None, description="operating kinematic "
                                                "viscosity ν")
    viscosity_40: PositiveViscosity | None = Field(None, description="ν at 40 °C")
    viscosity_100: PositiveViscosity | None = Field(None, description="ν at 100 °C")
    temperature: Temperature | None = Field(None, description="operating temperature")
    ep_additives: bool = Field(False, description="a lubricant with proven effective EP "
                               "additives: below κ = 1, with eC >= 0.2, aISO takes κ = 1, "
                               "at most 3 (ISO 281 9.3.3.3.4)")

    @rule
    def _one_form(self) -> SpecFieldError | None:
        table = (self.viscosity_40, self.viscosity_100, self.temperature)
        if self.viscosity is not None and any(v is not None for v in table):
            return SpecFieldError("viscosity", "give viscosity, or viscosity_40, "
                                  "viscosity_100 and temperature, not both")
        if self.viscosity is None and any(v is None for v in table):
            return SpecFieldError("", "give viscosity (like 20 mm^2/s), or all of "
                                  "viscosity_40, viscosity_100 and temperature")
        return None

    @rule
    def _thins_when_heated(self) -> SpecFieldError | None:
        if None in (self.viscosity_40, self.viscosity_100) or (
                self.viscosity_40 > self.viscosity_100):  # type: ignore[operator]
            return None
        return SpecFieldError("viscosity_100", f"must be below viscosity_40 (an oil thins "
                              f"as it warms), got {_mm2s(self.viscosity_100)} against "
                              f"{_mm2s(self.viscosity_40)} at 40 degC")

    @rule
    def _within_walther(self) -> SpecFieldError | None:
        """ASTM D341's line is extrapolated only as far as the oil stays a liquid."""
        if None in (self.viscosity_40, self.viscosity_100, self.temperature) or not (
                self.viscosity_40 > self.viscosity_100):  # type: ignore[operator]
            return None
        with np.errstate(over="ignore"):  # far below the pour point ν overflows: refused below
            nu = float(walther_viscosity(self.viscosity_40, self.viscosity_100,
                                         self.temperature))
        if nu <= MAX_OPERATING_VISCOSITY:
            return None
        coldest = float(walther_temperature(self.viscosity_40, self.viscosity_100,
                                            MAX_OPERATING_VISCOSITY))
        shown = f"{nu * 1e6:.3g} mm²/s" if math.isfinite(nu) else "no finite viscosity"
        return SpecFieldError("temperature", f"{self.temperature - 273.15:.4g} degC is far "
                              f"outside this oil's viscosity–temperature relation (ASTM "
                              f"D341 gives {shown}, a solid); it holds above "
                              f"{coldest - 273.15:.0f} degC, where ν stays below 10⁶ mm²/s: "
                              "give the operating temperature, or the viscosity itself")


def _mm2s(viscosity: float | None) -> str:
    return f"{(viscosity or 0.0) * 1e6:g} mm²/s"
