"""Spec of ``kind: ball-bearing``: ISO 281 rating life and ISO 76 static safety
(``docs/physics.md`` §5)."""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator

from bearingcalc.errors import SpecFieldError
from bearingcalc.spec.fields import (
    Angle,
    AngularSpeed,
    BallCount,
    Conformity,
    ElasticMaterial,
    Force,
    PositiveForce,
    PositiveLength,
    PositiveStress,
    PositiveTime,
    PositiveViscosity,
    Ratio,
    SpecModel,
    Temperature,
    ranged_number,
    reliability,
)

RELIABILITY_RANGE = (0.90, 0.9995)
#: ISO 76:2006 6.1: the contact pressure at C0 of a ball bearing. [Pa]
ISO_76_PRESSURE = 4.2e9
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

    @model_validator(mode="after")
    def _one_form(self) -> Lubrication:
        table = (self.viscosity_40, self.viscosity_100, self.temperature)
        if self.viscosity is not None and any(v is not None for v in table):
            raise SpecFieldError("lubrication.viscosity", "give viscosity, or viscosity_40, "
                                 "viscosity_100 and temperature, not both")
        if self.viscosity is None and any(v is None for v in table):
            raise SpecFieldError("lubrication", "give viscosity (like 20 mm^2/s), or all of "
                                 "viscosity_40, viscosity_100 and temperature")
        return self


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


class BallBearingSpec(BearingFields):
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

    @model_validator(mode="after")
    def _complete(self) -> BallBearingSpec:
        self.check_rules()
        return self

    def check_rules(self) -> None:
        """The kind's rules across fields; raises SpecFieldError naming the field at fault.
        (Also run by ``kind: bevel-drive`` on each of its bearings.)"""
        thrust = self.type == "thrust"
        ring_speeds = self.inner_speed is not None or self.outer_speed is not None
        if self.speed is not None and ring_speeds:
            raise SpecFieldError("speed", "give speed (the inner ring turning, the outer "
                                 "fixed), or inner_speed and outer_speed, not both")
        if self.speed is None and not ring_speeds:
            raise SpecFieldError("speed", "missing: give speed, like 3000 rpm, or the ring "
                                 "speeds inner_speed and outer_speed")
        if self.speed is not None and not self.speed > 0:
            raise SpecFieldError("speed", "must be positive: the life in hours needs a "
                                 "turning bearing, like 3000 rpm")
        if not self.relative_speed > 0:
            raise SpecFieldError("inner_speed", "the rings must turn relative to each other: "
                                 "the life in hours needs inner_speed ≠ outer_speed")
        if self.radial_load == 0 and self.axial_load == 0:
            raise SpecFieldError("radial_load", "both loads are zero, so the life is "
                                 "undefined: give radial_load or axial_load, like 10 kN")
        if thrust and self.radial_load > 0:
            raise SpecFieldError("radial_load", "a thrust ball bearing (α = 90°) carries no "
                                 "radial load; use angular-contact, or set it to 0 kN")
        if thrust and self.contact_angle is not None and not math.isclose(
                self.contact_angle, math.pi / 2, rel_tol=1e-12):
            raise SpecFieldError("contact_angle", "a thrust ball bearing has α = 90 deg; "
                                 "leave contact_angle out")
        if self.type == "angular-contact" and self.contact_angle is None:
            raise SpecFieldError("contact_angle", "an angular-contact bearing needs its "
                                 "contact angle, like 40 deg")
        alpha = self.angle
        if not thrust and not 0 <= alpha < math.pi / 2:
            raise SpecFieldError("contact_angle", "must be from 0 deg to below 90 deg for a "
                                 "radial bearing")
        if self.type == "angular-contact" and not (
                math.radians(20) - 1e-12 <= alpha <= math.radians(45) + 1e-12):
            factors = self.load_factors
            if factors is None or factors.x0 is None or factors.y0 is None:
                raise SpecFieldError("load_factors", "ISO 281 tables X, Y, e (and ISO 76 "
                                     "X0, Y0) only for 20 deg <= α <= 45 deg: give "
                                     "load_factors: {x, y, e, x0, y0} from the catalogue")
        if self.ball_diameter is not None and self.pitch_diameter is not None and not (
                self.ball_diameter < self.pitch_diameter):
            raise SpecFieldError("ball_diameter", "must be smaller than pitch_diameter")
        if (self.bore_diameter is None) != (self.outside_diameter is None):
            raise SpecFieldError("outside_diameter" if self.outside_diameter is None
                                 else "bore_diameter",
                                 "give both bore_diameter and outside_diameter, or neither")
        if self.bore_diameter is not None and not (
                self.bore_diameter < self.outside_diameter):  # type: ignore[operator]
            raise SpecFieldError("outside_diameter", "must be larger than bore_diameter")
        if self.dynamic_load_rating is None and not self.has_geometry:
            raise SpecFieldError("dynamic_load_rating", "missing: give dynamic_load_rating "
                                 "(C from the catalogue, like 55.3 kN), or the geometry "
                                 "ball_count, ball_diameter and pitch_diameter")
        if (self.type == "deep-groove" and self.axial_load > 0 and self.load_factors is None
                and ((self.static_load_rating is None and not self.has_geometry)
                     or (self.static_factor is None and not self.has_geometry))):
            field = "static_load_rating" if self.static_load_rating is None else "static_factor"
            raise SpecFieldError(field, "a deep-groove bearing under axial load needs f0 and "
                                 "C0 to find e and Y: give static_factor and "
                                 "static_load_rating from the catalogue, or the geometry "
                                 "(ball_count, ball_diameter, pitch_diameter)")
        if self.lubrication is not None:
            if self.contamination_factor is None:
                raise SpecFieldError("contamination_factor", "lubrication needs the "
                                     "contamination factor eC (0 to 1, like 0.5; see the "
                                     "README's cleanliness classes)")
            if self.mean_diameter is None:
                raise SpecFieldError("pitch_diameter", "lubrication needs the pitch diameter "
                                     "for ν1: give pitch_diameter, or bore_diameter and "
                                     "outside_diameter")
            if (self.fatigue_load_limit is None and self.static_load_rating is None
                    and (thrust or not self.has_geometry)):
                raise SpecFieldError("fatigue_load_limit", "aISO needs Cu: give "
                                     "fatigue_load_limit, or static_load_rating to find it")
        if (self.inner_groove_conformity is None) != (self.outer_groove_conformity is None):
            missing = ("inner_groove_conformity" if self.inner_groove_conformity is None
                       else "outer_groove_conformity")
            raise SpecFieldError(missing, "the contact stresses need both groove "
                                 "conformities (like 0.52 and 0.53)")
        if self.inner_groove_conformity is not None and not self.has_geometry:
            raise SpecFieldError("inner_groove_conformity", "the contact stresses need the "
                                 "geometry too: ball_count, ball_diameter and pitch_diameter")
        if self.lubrication is None and self.contamination_factor is not None:
            raise SpecFieldError("contamination_factor", "applies with lubrication only: "
                                 "give lubrication: {viscosity: ...} too, or leave it out")

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
        return None not in (self.ball_count, self.ball_diameter, self.pitch_diameter)

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
            "pitch_diameter": self.pitch_diameter,
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
