"""Spec of ``kind: ball-bearing``: ISO 281 rating life and ISO 76 static safety
(``docs/physics.md`` §5)."""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from pydantic import Field

from bearingcalc.core.ball_bearing import (
    MAX_OPERATING_VISCOSITY,
    walther_temperature,
    walther_viscosity,
)
from bearingcalc.errors import SpecFieldError
from bearingcalc.models.base import Spec, SpecModel
from bearingcalc.models.materials import ElasticMaterial
from bearingcalc.models.plain_numbers import BallCount, Ratio, ranged_number, reliability
from bearingcalc.models.quantities import (
    Angle,
    AngularSpeed,
    Conformity,
    Force,
    PositiveForce,
    PositiveLength,
    PositiveStress,
    PositiveTime,
    PositiveViscosity,
    Temperature,
)
from bearingcalc.models.rules import rule

RELIABILITY_RANGE = (0.90, 0.9995)
#: ISO 76:2006 6.1: the contact pressure at C0 of a ball bearing. [Pa]
ISO_76_PRESSURE = 4.2e9
#: How far a given pitch diameter may lie from (d + D)/2 before it is questioned: real
#: bearings are not exactly symmetric, but a larger offset is usually a typing slip.
PITCH_OFF_CENTRE = 0.05
DEFAULT_CONTACT_ANGLE = {"deep-groove": 0.0, "thrust": math.pi / 2}


Reliability = reliability(*RELIABILITY_RANGE, "ISO 281's range for a1")


UnitFraction = ranged_number(0.0, 1.0, "a fraction", "0.5")


class Lubrication(SpecModel):
    """The operating viscosity, given or found from ν40, ν100 and the temperature."""

    viscosity: PositiveViscosity | None = Field(None, description="operating kinematic "
                                                "viscosity ν")
    viscosity_40: PositiveViscosity | None = Field(None, description="ν at 40 °C")
    viscosity_100: PositiveViscosity | None = Field(None, description="ν at 100 °C")
    temperature: Temperature | None = Field(None, description="operating temperature")

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


class LoadFactors(SpecModel):
    """Catalogue X, Y, e (and X0, Y0) in place of ISO 281's and ISO 76's tables."""

    x: Ratio = Field(description="radial factor X")
    y: Ratio = Field(description="axial factor Y")
    e: Ratio = Field(description="limit of Fa/Fr below which P = Fr")
    x0: Ratio | None = Field(None, description="static radial factor X0")
    y0: Ratio | None = Field(None, description="static axial factor Y0")


class BallBearingLimits(SpecModel):
    min_rating_life: PositiveTime | None = Field(None, description="judged on the modified "
                                                 "rating life; not judged when absent")
    min_static_safety: Ratio = Field(1.0, description="smallest static safety factor s0")
    max_spin_to_roll: Ratio | None = Field(None, description="largest |spin/roll|, judged "
                                           "at the race that is not controlling")
    max_contact_pressure: PositiveStress = Field(
        ISO_76_PRESSURE, description="largest Hertz pressure (ISO 76: 4200 MPa for ball "
        "bearings)")


class BearingFields(SpecModel):
    """What a ball bearing is, apart from how it is loaded and run: its type, catalogue
    ratings, internal geometry, load factors, grooves, material and race control.
    ``kind: ball-bearing`` adds loads, speeds and lubrication; a drive's bearing entry
    (``kind: bevel-drive``) adds its position on the shaft."""

    type: Literal["deep-groove", "angular-contact", "thrust"] = "deep-groove"
    dynamic_load_rating: PositiveForce | None = Field(None, description="C, catalogue")
    static_load_rating: PositiveForce | None = Field(None, description="C0, catalogue")
    fatigue_load_limit: PositiveForce | None = Field(None, description="Cu, catalogue")
    static_factor: Ratio | None = Field(None, description="f0 from the catalogue")
    ball_count: BallCount | None = None
    ball_diameter: PositiveLength | None = Field(None, description="Dw")
    pitch_diameter: PositiveLength | None = Field(None, description="Dpw")
    bore_diameter: PositiveLength | None = Field(None, description="d (for dm only)")
    outside_diameter: PositiveLength | None = Field(None, description="D (for dm only)")
    contact_angle: Angle | None = Field(None, description="α; 0 deg for deep-groove, "
                                        "90 deg for thrust by default")
    race_control: Literal["outer", "inner"] = Field(
        "outer", description="the race at which the ball does not spin (Jones)")
    load_factors: LoadFactors | None = None
    inner_groove_conformity: Conformity | None = Field(
        None, description="fi = inner groove radius / Dw (> 0.5)")
    outer_groove_conformity: Conformity | None = Field(
        None, description="fo = outer groove radius / Dw (> 0.5)")
    material: ElasticMaterial = ElasticMaterial()


class BallBearingSpec(BearingFields, Spec):
    """A rolling ball bearing sized by ISO 281 (life) and ISO 76 (static safety)."""

    kind: Literal["ball-bearing"]
    name: str | None = None
    radial_load: Force = Field(0.0, description="Fr")
    axial_load: Force = Field(0.0, description="Fa")
    speed: AngularSpeed | None = Field(None, description="the rotating ring relative to the "
                                       "other (inner turning, outer fixed)")
    inner_speed: AngularSpeed | None = Field(None, description="inner ring, fixed frame")
    outer_speed: AngularSpeed | None = Field(None, description="outer ring, fixed frame")
    reliability: Reliability = 0.9
    lubrication: Lubrication | None = None
    contamination_factor: UnitFraction | None = Field(None, description="eC, 0 to 1")
    limits: BallBearingLimits = BallBearingLimits()

    @rule
    def _turning(self) -> SpecFieldError | None:
        ring_speeds = self.inner_speed is not None or self.outer_speed is not None
        if self.speed is not None and ring_speeds:
            return SpecFieldError("speed", "give speed (the inner ring turning, the outer "
                                  "fixed), or inner_speed and outer_speed, not both")
        if self.speed is None and not ring_speeds:
            return SpecFieldError("speed", "missing: give speed, like 3000 rpm, or the ring "
                                  "speeds inner_speed and outer_speed")
        if self.speed is not None and not self.speed > 0:
            return SpecFieldError("speed", "must be positive: the life in hours needs a "
                                  "turning bearing, like 3000 rpm")
        if not self.relative_speed > 0:
            return SpecFieldError("inner_speed", "the rings must turn relative to each "
                                  "other: the life in hours needs inner_speed ≠ outer_speed")
        return None

    @rule
    def _loaded(self) -> SpecFieldError | None:
        if self.radial_load == 0 and self.axial_load == 0:
            return SpecFieldError("radial_load", "both loads are zero, so the life is "
                                  "undefined: give radial_load or axial_load, like 10 kN")
        if self.type == "thrust" and self.radial_load > 0:
            return SpecFieldError("radial_load", "a thrust ball bearing (α = 90°) carries no "
                                  "radial load; use angular-contact, or set it to 0 kN")
        return None

    @rule
    def _axial_load_counts(self) -> SpecFieldError | None:
        factors = self.load_factors
        if factors is None or not (factors.y == 0 and self.axial_load > 0):
            return None
        return SpecFieldError("load_factors.y", "Y = 0 leaves the axial load out of the "
                              "equivalent load P = X·Fr + Y·Fa: give the catalogue's Y, above 0")

    @rule
    def _contact_angle(self) -> SpecFieldError | None:
        thrust = self.type == "thrust"
        if thrust and self.contact_angle is not None and not math.isclose(
                self.contact_angle, math.pi / 2, rel_tol=1e-12):
            return SpecFieldError("contact_angle", "a thrust ball bearing has α = 90 deg; "
                                  "leave contact_angle out")
        if self.type == "angular-contact" and self.contact_angle is None:
            return SpecFieldError("contact_angle", "an angular-contact bearing needs its "
                                  "contact angle, like 40 deg")
        if not thrust and not 0 <= self.angle < math.pi / 2:
            return SpecFieldError("contact_angle", "must be from 0 deg to below 90 deg for a "
                                  "radial bearing")
        return None

    @rule
    def _angle_in_tables(self) -> SpecFieldError | None:
        alpha = self.angle
        if self.type != "angular-contact" or (
                math.radians(20) - 1e-12 <= alpha <= math.radians(45) + 1e-12):
            return None
        factors = self.load_factors
        if factors is None or factors.x0 is None or factors.y0 is None:
            return SpecFieldError("load_factors", "ISO 281 tables X, Y, e (and ISO 76 "
                                  "X0, Y0) only for 20 deg <= α <= 45 deg: give "
                                  "load_factors: {x, y, e, x0, y0} from the catalogue",
                                  at="contact_angle")
        return None

    @rule
    def _envelope(self) -> SpecFieldError | None:
        """Bore and outside diameter: both or neither, in order."""
        if (self.bore_diameter is None) != (self.outside_diameter is None):
            return SpecFieldError("outside_diameter" if self.outside_diameter is None
                                  else "bore_diameter",
                                  "give both bore_diameter and outside_diameter, or neither")
        if self.bore_diameter is not None and not (
                self.bore_diameter < self.outside_diameter):  # type: ignore[operator]
            return SpecFieldError("outside_diameter", "must be larger than bore_diameter")
        return None

    @rule
    def _pitch_circle_in_envelope(self) -> SpecFieldError | None:
        envelope = self._envelope_mm()
        if envelope is None or self.pitch_diameter is None:
            return None
        bore, outside = envelope
        pitch = self.pitch_diameter * 1e3
        if bore < pitch < outside:
            return None
        return SpecFieldError("pitch_diameter", f"{pitch:g} mm is outside the rings: the "
                              f"pitch circle lies between bore_diameter ({bore:g} mm) and "
                              f"outside_diameter ({outside:g} mm), near their mean "
                              f"{(bore + outside) / 2:g} mm")

    @rule
    def _ball_in_section(self) -> SpecFieldError | None:
        if self.ball_diameter is not None and self.pitch_diameter is not None and not (
                self.ball_diameter < self.pitch_diameter):
            return SpecFieldError("ball_diameter", "must be smaller than pitch_diameter")
        envelope = self._envelope_mm()
        if envelope is None or self.ball_diameter is None:
            return None
        section = (envelope[1] - envelope[0]) / 2
        if self.ball_diameter * 1e3 < section:
            return None
        return SpecFieldError("ball_diameter", f"{self.ball_diameter * 1e3:g} mm does not "
                              f"fit the ring section: the ball must be smaller than "
                              f"(outside_diameter − bore_diameter)/2 = {section:g} mm")

    @rule
    def _rated(self) -> SpecFieldError | None:
        if self.dynamic_load_rating is None and not self.has_geometry:
            return SpecFieldError("dynamic_load_rating", "missing: give dynamic_load_rating "
                                  "(C from the catalogue, like 55.3 kN), or the geometry "
                                  "ball_count, ball_diameter and pitch_diameter (or "
                                  "bore_diameter and outside_diameter)")
        return None

    @rule
    def _axial_factors_found(self) -> SpecFieldError | None:
        if self.type != "deep-groove" or not self.axial_load > 0 or (
                self.load_factors is not None or self.has_geometry):
            return None
        if self.static_load_rating is not None and self.static_factor is not None:
            return None
        field = "static_load_rating" if self.static_load_rating is None else "static_factor"
        return SpecFieldError(field, "a deep-groove bearing under axial load needs f0 and C0 "
                              "to find e and Y: give static_factor and static_load_rating "
                              "from the catalogue, or the geometry (ball_count, "
                              "ball_diameter, pitch_diameter)", at="axial_load")

    @rule
    def _contamination_with_lubrication(self) -> SpecFieldError | None:
        if self.lubrication is not None and self.contamination_factor is None:
            return SpecFieldError("contamination_factor", "lubrication needs the "
                                  "contamination factor eC (0 to 1, like 0.5; see the "
                                  "cleanliness classes in the README)",
                                  at="lubrication")
        if self.lubrication is None and self.contamination_factor is not None:
            return SpecFieldError("contamination_factor", "applies with lubrication only: "
                                  "give lubrication: {viscosity: ...} too, or leave it out")
        return None

    @rule
    def _lubrication_sizes(self) -> SpecFieldError | None:
        if self.lubrication is None:
            return None
        if self.mean_diameter is None:
            return SpecFieldError("pitch_diameter", "lubrication needs the pitch diameter "
                                  "for ν1: give pitch_diameter, or bore_diameter and "
                                  "outside_diameter", at="lubrication")
        if (self.fatigue_load_limit is None and self.static_load_rating is None
                and (self.type == "thrust" or not self.has_geometry)):
            return SpecFieldError("fatigue_load_limit", "aISO needs Cu: give "
                                  "fatigue_load_limit, or static_load_rating to find it",
                                  at="lubrication")
        return None

    @rule
    def _grooves(self) -> SpecFieldError | None:
        if (self.inner_groove_conformity is None) != (self.outer_groove_conformity is None):
            missing = ("inner_groove_conformity" if self.inner_groove_conformity is None
                       else "outer_groove_conformity")
            return SpecFieldError(missing, "the contact stresses need both groove "
                                  "conformities (like 0.52 and 0.53)")
        if self.inner_groove_conformity is not None and not self.has_geometry:
            return SpecFieldError("inner_groove_conformity", "the contact stresses need the "
                                  "geometry too: ball_count, ball_diameter and pitch_diameter")
        return None

    def _envelope_mm(self) -> tuple[float, float] | None:
        """(d, D) in mm where both are given and in order, else None."""
        if self.bore_diameter is None or self.outside_diameter is None or not (
                self.bore_diameter < self.outside_diameter):
            return None
        return self.bore_diameter * 1e3, self.outside_diameter * 1e3

    @property
    def angle(self) -> float:
        """α used. [rad]"""
        if self.contact_angle is not None:
            return self.contact_angle
        return DEFAULT_CONTACT_ANGLE.get(self.type, 0.0)

    @property
    def relative_speed(self) -> Any:
        """n, the rotating ring relative to the other: ``speed`` or |inner − outer|. [rad/s]"""
        if self.speed is not None:
            return self.speed
        return np.abs(self.ring_speeds[0] - self.ring_speeds[1])

    @property
    def ring_speeds(self) -> tuple[Any, Any]:
        """(inner, outer) ring speeds in the fixed frame; ``speed`` alone turns the inner
        ring with the outer fixed, and a ring speed left out is 0. [rad/s]"""
        if self.speed is not None:
            return self.speed, 0.0
        return (0.0 if self.inner_speed is None else self.inner_speed,
                0.0 if self.outer_speed is None else self.outer_speed)

    @property
    def has_geometry(self) -> bool:
        """Ball count, ball diameter and a pitch diameter (given, or the rings' mean)."""
        return None not in (self.ball_count, self.ball_diameter, self.mean_diameter)

    @property
    def mean_diameter(self) -> float | None:
        """dm for ν1 and Cu: Dpw, else (d + D)/2. [m]"""
        if self.pitch_diameter is not None:
            return self.pitch_diameter
        if self.bore_diameter is not None and self.outside_diameter is not None:
            return 0.5 * (self.bore_diameter + self.outside_diameter)
        return None

    def warnings(self) -> list[str]:
        """What the reader should know about how the results were found."""
        notes = []
        catalogue = [name for name in ("dynamic_load_rating", "static_load_rating")
                     if getattr(self, name) is not None]
        if catalogue and self.has_geometry:
            notes.append(f"catalogue {' and '.join(catalogue)} used for the results; the "
                         "ISO values from the geometry are reported as *_iso")
        if self.lubrication is None:
            notes.append("no lubrication given: aISO = 1, so the modified life ignores "
                         "lubrication and contamination")
        if self.type == "thrust" and self.static_load_rating is None:
            notes.append("no static_load_rating: ISO 76's thrust f0 is not implemented, so "
                         "the static results are left out")
        envelope = self._envelope_mm()
        if envelope is not None:
            middle = (envelope[0] + envelope[1]) / 2
            if self.pitch_diameter is None and self.has_geometry:
                notes.append(f"no pitch_diameter: the geometry takes the rings' mean "
                             f"(d + D)/2 = {middle:g} mm")
            elif self.pitch_diameter is not None and abs(
                    self.pitch_diameter * 1e3 - middle) > PITCH_OFF_CENTRE * middle:
                notes.append(f"pitch_diameter {self.pitch_diameter * 1e3:g} mm is more than "
                             f"{PITCH_OFF_CENTRE:.0%} from the rings' mean (d + D)/2 = "
                             f"{middle:g} mm: check it against the catalogue")
        return notes

    def solver_inputs(self) -> dict[str, Any]:
        """SI inputs of :func:`bearingcalc.core.ball_bearing.evaluate`."""
        lubrication = self.lubrication
        factors = self.load_factors
        return {
            "bearing_type": self.type,
            "dynamic_load_rating": self.dynamic_load_rating,
            "static_load_rating": self.static_load_rating,
            "fatigue_load_limit": self.fatigue_load_limit,
            "static_factor": self.static_factor,
            "ball_count": self.ball_count,
            "ball_diameter": self.ball_diameter,
            "pitch_diameter": self.mean_diameter,
            "mean_diameter": self.mean_diameter,
            "contact_angle": self.angle,
            "radial_load": self.radial_load,
            "axial_load": self.axial_load,
            "speed": self.relative_speed,
            "inner_speed": self.ring_speeds[0],
            "outer_speed": self.ring_speeds[1],
            "race_control": self.race_control,
            "max_spin_to_roll": self.limits.max_spin_to_roll,
            "reliability": self.reliability,
            "viscosity": lubrication.viscosity if lubrication else None,
            "viscosity_40": lubrication.viscosity_40 if lubrication else None,
            "viscosity_100": lubrication.viscosity_100 if lubrication else None,
            "temperature": lubrication.temperature if lubrication else None,
            "contamination_factor": self.contamination_factor,
            "load_x": factors.x if factors else None,
            "load_y": factors.y if factors else None,
            "load_e": factors.e if factors else None,
            "load_x0": factors.x0 if factors else None,
            "load_y0": factors.y0 if factors else None,
            "min_rating_life": self.limits.min_rating_life,
            "min_static_safety": self.limits.min_static_safety,
            "inner_groove_conformity": self.inner_groove_conformity,
            "outer_groove_conformity": self.outer_groove_conformity,
            "elastic_modulus": self.material.elastic_modulus,
            "poisson_ratio": self.material.poisson_ratio,
            "max_contact_pressure": self.limits.max_contact_pressure,
        }
