"""The materials of rolling elements and races: elastic constants and density."""

from __future__ import annotations

from pydantic import Field

from bearingcalc.models.base import SpecModel
from bearingcalc.models.plain_numbers import PoissonRatio
from bearingcalc.models.quantities import ElasticModulus, PositiveDensity

#: Bearing steel (AISI 52100 / 100Cr6), ball and rings alike: E = 207.5 GPa (the value
#: of bearing makers' contact calculations), ν = 0.3, ρ = 7850 kg/m³.
STEEL_MODULUS, STEEL_POISSON, STEEL_DENSITY = 207.5e9, 0.3, 7850.0


class ElasticMaterial(SpecModel):
    """The elastic constants of ball and races (the same material for both)."""

    elastic_modulus: ElasticModulus = Field(STEEL_MODULUS, description="Young's modulus E")
    poisson_ratio: PoissonRatio = Field(STEEL_POISSON, description="Poisson's ratio ν")


class BallMaterial(ElasticMaterial):
    """Elastic constants and the density of the balls (for their centrifugal force)."""

    density: PositiveDensity = Field(STEEL_DENSITY, description="density of the balls")
