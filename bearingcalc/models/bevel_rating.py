"""The AGMA 2003 rating block of a bevel pair: quality, steel, hardness, mounting,
geometry factors, load cycles and reliability."""

from __future__ import annotations

import re
from typing import Annotated, Any, Literal

from pydantic import Field, PlainValidator, WithJsonSchema

from bearingcalc.core.bevel_rating import MOUNTING_FACTOR
from bearingcalc.core.gear_materials import GRADES
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import SpecModel
from bearingcalc.models.plain_numbers import (
    _RangedNumber,
    ranged_number,
    reliability,
    shown,
    whole_choice,
)
from bearingcalc.models.quantities import (
    _PLUS_MINUS,
    Measured,
    PositiveLength,
    Temperature,
    Tolerance,
)
from bearingcalc.models.rules import rule
from bearingcalc.number_grammar import UNSIGNED_DECIMAL


class _BrinellHardness(_RangedNumber):
    """A Brinell hardness within AGMA 2003's 180 to 400 HB of through-hardened steel,
    written '300 HB' or 300: a ranged number (so a sweep steps through it) that may carry
    its unit."""

    def __init__(self) -> None:
        super().__init__(180, 400, "through-hardened steel in AGMA 2003", "300 HB",
                         whole=False, exclusive=False)

    def read(self, text: str) -> float:
        """A hardness as a sweep's bounds give it: '250HB' or 250."""
        return _written_hardness(text, word_required=False)

    def __call__(self, value: Any) -> float:
        if isinstance(value, str) and _PLUS_MINUS.search(value):
            return self._toleranced(value)
        if isinstance(value, str):  # in a spec, a number in quotes carries its word
            value = _written_hardness(value, word_required=True)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"write the Brinell hardness like '180 HB', got {value!r}")
        self._check_range(value, shown(value) if isinstance(value, int) else f"{value:g}")
        return float(value)

    def _toleranced(self, text: str) -> Measured:
        """'300 HB ± 10 HB' (or '300 ± 10 HB'): the nominal, with a normal tolerance at
        3σ over the band, as every '±' input of a spec."""
        nominal_text, band_text = _PLUS_MINUS.split(text, maxsplit=1)
        nominal = _written_hardness(nominal_text, word_required=False)
        band = _written_hardness(band_text, word_required=True)
        low, high = nominal - band, nominal + band
        self._check_range(low, f"the band's low end ({low:g} HB)")
        self._check_range(high, f"the band's high end ({high:g} HB)")
        return Measured(nominal, Tolerance(nominal, low, high, unit="1", written_unit="HB"))

    def _check_range(self, value: float, got: str) -> None:
        if not self.low <= value <= self.high:
            raise ValueError(f"must be from 180 to 400 HB ({self.what}), got {got}")


def _written_hardness(text: str, *, word_required: bool) -> float:
    """The number of '300 HB' (or HBW, BHN; or bare where the word is not required)."""
    match = re.fullmatch(rf"\s*({UNSIGNED_DECIMAL})\s*(HB|HBW|BHN)?\s*", text, re.ASCII)
    if match is None or (word_required and match[2] is None):
        raise ValueError(f"write the Brinell hardness like '180 HB', got {text!r}")
    return float(match[1])


Hardness = Annotated[float, PlainValidator(_BrinellHardness()), WithJsonSchema({"anyOf": [
    {"type": "string", "pattern": rf"^\s*{UNSIGNED_DECIMAL}\s*(HB|HBW|BHN)\s*$"},
    {"type": "number", "minimum": 180, "maximum": 400}]})]
RatingReliability = reliability(0.9, 0.9999, "AGMA 2003's K_R")


class BevelRating(SpecModel):
    """The AGMA 2003 strength rating of a bevel pair of steel (straight, Zerol or
    spiral teeth)."""

    quality_number: ranged_number(5, 11, "AGMA transmission accuracy number Qv", "7",  # type: ignore[valid-type]
                                   whole=True)
    material: Literal["through-hardened", "carburized", "nitrided",
                      "flame-or-induction-hardened"] = Field(
        "through-hardened", description="the heat treatment, which sets the allowable "
        "stress numbers (with grade, and hardness for through-hardened steel)")
    grade: whole_choice(1, 2, 3) = Field(  # type: ignore[valid-type]
        1, description="AGMA metallurgical grade")
    hardness: Hardness | None = Field(None, description="Brinell hardness of "
                                      "through-hardened steel (the pinion's)")
    gear_hardness: Hardness | None = Field(
        None, description="gear B's Brinell hardness, through-hardened, for the "
        "hardness-ratio factor C_H")
    temperature: Temperature | None = Field(None, description="the blank's temperature, "
                                            "for K_T (1 up to 250 °F)")
    geometry_factor_bending_gear: ranged_number(1e-6, 10, "J of gear B, from AGMA 2003",  # type: ignore[valid-type]
                                                "0.202") | None = Field(
        None, description="J of gear B, to rate it too")
    cutter_radius: PositiveLength | None = Field(
        None, description="r_c, the face cutter's nominal radius: a spiral pair's K_x")
    mounting: Literal["both-straddle", "one-straddle", "neither-straddle"] = Field(
        description="Kmb 1.00 / 1.10 / 1.25")
    crowned: bool = False
    geometry_factor_bending: ranged_number(1e-6, 10, "J, from AGMA 2003", "0.216")  # type: ignore[valid-type]
    geometry_factor_pitting: ranged_number(1e-6, 10, "I, from AGMA 2003", "0.065")  # type: ignore[valid-type]
    overload_factor: ranged_number(1, 10, "Ko", "1.0") = 1.0  # type: ignore[valid-type]
    cycles: ranged_number(1e3, 1e10, "load cycles of the pinion", "1e7") = 1e7  # type: ignore[valid-type]
    reliability: RatingReliability = 0.99

    @rule
    def _temperature_covered(self) -> SpecFieldError | None:
        if self.temperature is None:
            return None
        celsius = self.temperature - 273.15
        if not 0.0 <= celsius <= 200.0:
            return SpecFieldError("temperature", "must be from 0 °C to 200 °C (32 °F to "
                                  "392 °F): AGMA 2003's K_T starts at 0 °C, and above about "
                                  "200 °C a hardened steel tempers, losing the hardness its "
                                  f"allowable stresses assume; got {celsius:.6g} °C")
        return None

    @rule
    def _steel_given(self) -> SpecFieldError | None:
        grades = GRADES[self.material]
        if self.grade not in grades:
            return SpecFieldError("grade", f"{self.material} steel has grade "
                                  f"{' or '.join(map(str, grades))} in AGMA 2003's table")
        if self.material == "through-hardened" and self.hardness is None:
            return SpecFieldError("hardness", "through-hardened steel needs its Brinell "
                                  "hardness, like 300 HB", at="material")
        if self.gear_hardness is not None and self.geometry_factor_bending_gear is None:
            return SpecFieldError("geometry_factor_bending_gear", "gear_hardness rates gear "
                                  "B: give its J too, like 0.202", at="gear_hardness")
        if self.material != "through-hardened":
            for field in ("hardness", "gear_hardness"):
                if getattr(self, field) is not None:
                    return SpecFieldError(field, f"{self.material} steel's allowable "
                                          "stresses are fixed by its grade: leave the "
                                          "Brinell hardness out")
        return None


#: The rating's solver inputs, in order (the face cutter's radius first).
RATING_INPUTS = (
    "cutter_radius", "quality_number", "hardness", "material", "grade", "gear_hardness",
    "temperature", "geometry_factor_bending_gear", "mounting_factor", "crowned",
    "geometry_factor_bending", "geometry_factor_pitting", "overload_factor", "cycles",
    "reliability")


def rating_inputs(rating: BevelRating | None) -> dict[str, Any]:
    """The SI solver inputs of a pair's rating block (:data:`RATING_INPUTS`): the mounting
    as its factor Kmb, crowning as 1 or 0; None each without a rating."""
    if rating is None:
        return dict.fromkeys(RATING_INPUTS)
    values = {name: getattr(rating, name) for name in RATING_INPUTS
              if name not in ("mounting_factor", "crowned")}
    values["mounting_factor"] = MOUNTING_FACTOR[rating.mounting]
    values["crowned"] = float(rating.crowned)
    return {name: values[name] for name in RATING_INPUTS}
