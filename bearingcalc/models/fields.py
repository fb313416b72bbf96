"""Where the field types lived before they were split by job; kept for the modules
that have not moved to :mod:`bearingcalc.models.base`, ``quantities``,
``plain_numbers`` and ``materials`` yet."""

from bearingcalc.models.base import SpecModel, field_parser, nested_model  # noqa: F401
from bearingcalc.models.quantities import Measured, Tolerance  # noqa: F401
