"""The columns a bearing catalogue may have: what each holds, its dimension, and the
spec field of a rolling bearing it fills."""

from __future__ import annotations

from dataclasses import dataclass

from bearingcalc.units import (
    ANGLE,
    ANGULAR_SPEED,
    DIMENSIONLESS,
    FORCE,
    LENGTH,
    MASS,
    Dimension,
)


@dataclass(frozen=True)
class Column:
    """One column: ``dimension`` None for text, DIMENSIONLESS for a plain number (no
    unit in the header), ``whole`` for a count; ``field`` is the spec field it fills
    (a dotted path within a bearing), None where it fills none."""

    name: str
    dimension: Dimension | None
    required: bool = False
    field: str | None = None
    whole: bool = False


COLUMNS: dict[str, Column] = {column.name: column for column in (
    Column("designation", None, required=True),
    Column("maker", None, required=True),
    Column("type", None, required=True, field="type"),
    Column("bore_diameter", LENGTH, required=True, field="bore_diameter"),
    Column("outside_diameter", LENGTH, required=True, field="outside_diameter"),
    Column("width", LENGTH, required=True, field="width"),
    Column("dynamic_load_rating", FORCE, required=True, field="dynamic_load_rating"),
    Column("static_load_rating", FORCE, required=True, field="static_load_rating"),
    Column("source", None, required=True),
    Column("fatigue_load_limit", FORCE, field="fatigue_load_limit"),
    Column("static_factor", DIMENSIONLESS, field="static_factor"),
    Column("contact_angle", ANGLE, field="contact_angle"),
    Column("e", DIMENSIONLESS, field="load_factors.e"),
    Column("y1", DIMENSIONLESS, field="load_factors.y1"),
    Column("y2", DIMENSIONLESS, field="load_factors.y2"),
    Column("y0", DIMENSIONLESS, field="load_factors.y0"),
    Column("pressure_centre", LENGTH),
    Column("reference_speed", ANGULAR_SPEED),
    Column("limiting_speed", ANGULAR_SPEED),
    Column("mass", MASS),
    Column("r_min", LENGTH),
    Column("cup_r_min", LENGTH),
    Column("ball_count", DIMENSIONLESS, field="ball_count", whole=True),
    Column("ball_diameter", LENGTH, field="ball_diameter"),
    Column("roller_count", DIMENSIONLESS, field="roller_count", whole=True),
    Column("roller_diameter", LENGTH, field="roller_diameter"),
    Column("roller_length", LENGTH, field="roller_length"),
    Column("pitch_diameter", LENGTH, field="pitch_diameter"),
)}

REQUIRED = tuple(name for name, column in COLUMNS.items() if column.required)
#: The numbers of a row, in SI: every column with a dimension.
NUMERIC = tuple(name for name, column in COLUMNS.items() if column.dimension is not None)
