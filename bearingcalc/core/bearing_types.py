"""The rolling bearing types and what each is: one table read by the solvers, the spec
models, the catalogue, ``select`` and the docs.

Each :class:`BearingTraits` says which rolling elements a type has, whether it is radial
or thrust, how many rows it may have and whether it pairs, how its contact angle is
found, which of the spec's fields apply to it, which formulas of ISO 281:2007 (with its
material factor bm, Table 1) and ISO 76:2006 rate it, and how its equivalent load is
found. A type is named once, by the name its catalogue rows carry; the spec's other
spellings (``thrust`` for ``thrust-ball``) resolve to it in :func:`traits`.
"""

from __future__ import annotations

import math
from enum import Enum
from typing import NamedTuple

from bearingcalc.core.common import Family


class AngleRule(Enum):
    """How a type's contact angle α is found."""

    FIXED = "α is the type's own; a given angle must equal it"
    DEFAULT = "α is the type's own unless given"
    GIVEN = "α must be given"


class RatingFormula(Enum):
    """ISO 281:2007's formula of the basic dynamic load rating C from the geometry."""

    RADIAL_BALL = "7.1: Cr = bm·fc·(i·cosα)^0.7·Z^(2/3)·Dw^1.8"
    THRUST_BALL = "7.1: Ca = bm·fc·Z^(2/3)·Dw^1.8 (α = 90°)"
    RADIAL_ROLLER = "8.1: Cr = bm·fc·(i·Lwe·cosα)^(7/9)·Z^(3/4)·Dwe^(29/27)"
    THRUST_ROLLER = "8.1: Ca = bm·fc·(Lwe·cosα)^(7/9)·tanα·Z^(3/4)·Dwe^(29/27)"
    CATALOGUE = "from the catalogue only (ISO 281's fc is not built in)"


class StaticFormula(Enum):
    """ISO 76:2006's formula of the basic static load rating C0 from the geometry."""

    RADIAL_BALL = "C0r = f0·i·Z·Dw²·cosα"
    RADIAL_ROLLER = "C0r = 44·(1 − Dwe·cosα/Dpw)·i·Z·Lwe·Dwe·cosα"
    THRUST_ROLLER = "C0a = 220·(1 − Dwe·cosα/Dpw)·Z·Lwe·Dwe·sinα"
    CATALOGUE = "from the catalogue only (ISO 76's f0 is not built in)"


class LoadRule(Enum):
    """How ISO 281:2007 finds a type's equivalent dynamic load P (and its X, Y, e)."""

    GROOVE_TABLE = "Table 3, X = 0.56 and e, Y in f0·Fa/C0"
    ANGLE_TABLE = "Table 3, X, Y and e in α (20° to 45°)"
    SELF_ALIGNING = "Table 3, double row: X = 1, Y1 to e; X = 0.65, Y2 above"
    AXIAL_ONLY = "P = Fa"
    RADIAL_ONLY = "P = Fr: the line contact has no contact angle"
    RADIAL_ROLLER = "8.2, e = 1.5·tanα"
    THRUST_ROLLER = "8.2, X = tanα, Y = 1 (Fa/Fr > e = 1.5·tanα)"


#: The fields of a spec that belong to one family of rolling elements.
BALL_FIELDS = frozenset({"ball_count", "ball_diameter", "inner_groove_conformity",
                         "outer_groove_conformity", "static_factor", "race_control",
                         "limits.max_spin_to_roll"})
ROLLER_FIELDS = frozenset({"roller_count", "roller_diameter", "roller_length", "rows"})
#: The crown of a spherical roller and its raceway's radius across the rolling direction.
CROWN_FIELDS = frozenset({"roller_profile_radius", "raceway_radius"})


class BearingTraits(NamedTuple):
    """What a bearing type is (see the module's docstring)."""

    name: str
    #: The spec's spellings of the type, the first its own name.
    spec_names: tuple[str, ...]
    family: Family
    thrust: bool
    #: The rows of rolling elements a bearing of the type may have (``rows``).
    rows: tuple[int, ...]
    #: Whether it pairs back-to-back, face-to-face or in tandem (``arrangement``).
    pairable: bool
    #: A single row carries an axial load in one direction only, and induces one from
    #: its radial load (a shaft's pair is adjusted against each other).
    one_way: bool
    angle_rule: AngleRule
    #: α of the type where it has its own, else None. [rad]
    contact_angle: float | None
    #: An angle a spec could give, for the messages that ask for one.
    example_angle: str | None
    #: ISO 281:2007 Table 1, bm. [1]
    material_factor: float
    rating_formula: RatingFormula
    static_formula: StaticFormula
    load_rule: LoadRule
    #: The catalogue's e, Y and Y0 are the bearing's load factors (the other ball
    #: bearings' come from ISO 281's and ISO 76's tables).
    catalogue_factors: bool = False
    #: The catalogue's bearings of the type have two rows by their form.
    double_row_form: bool = False
    #: α follows from a catalogue's e = 1.5·tanα (ISO 281 8.2), and a shallow α is
    #: questioned.
    inclined: bool = False
    #: A spherical roller: point contacts of a crowned roller (CROWN_FIELDS apply).
    crowned: bool = False
    #: A needle roller bearing may have a drawn cup (bm = 1.0, Table 1).
    drawn_cup: bool = False
    #: The outer ring is a cup with a chamfer of its own (the catalogue's ``cup_r_min``).
    cupped: bool = False
    #: Designation forms whose ring has no ribs, so carry no axial load: (form, ring).
    ribless_forms: tuple[tuple[str, str], ...] = ()
    #: ISO/TS 16281's load distribution solves a single bearing of the type
    #: (``method: iso-16281``).
    mounted: bool = False
    #: The share of the pitch circle its elements fill, Z·Dw/(π·Dpw), least and most,
    #: for estimating its internal geometry (a deep-groove bearing assembled by the
    #: eccentric method fills about 0.55 to 0.6, an angular-contact one 0.65 to 0.8, a
    #: cylindrical roller bearing about 0.8).
    fill: tuple[float, float] | None = None
    #: A roller's effective length in diameters: least, most and usual.
    roller_proportion: tuple[float, float, float] | None = None
    #: Which of ISO 5753-1's tables gives its radial clearance groups ("radial-ball",
    #: "cylindrical"), None where none does.
    clearance_table: str | None = None

    @property
    def fields(self) -> frozenset[str]:
        """The spec's element fields that apply to the type."""
        if self.family == "ball":
            return BALL_FIELDS
        extra = {"drawn_cup"} if self.drawn_cup else set()
        return ROLLER_FIELDS | (CROWN_FIELDS if self.crowned else frozenset()) | extra

    def load_factor_names(self, double: bool) -> tuple[str, ...]:
        """The catalogue factors a spec's ``load_factors`` of the type gives: of a single
        row, or of a double row or a back-to-back or face-to-face pair."""
        if self.load_rule is LoadRule.SELF_ALIGNING:
            return ("e", "y1", "y2", "y0")
        if double:
            return ("e", "y1", "x", "y2") if self.family == "ball" else ("e", "y1", "y2")
        return ("e", "y") if self.family == "roller" else ("x", "y", "e")


_RIGHT = math.pi / 2
_BALL = {"family": "ball", "rows": (1,), "material_factor": 1.3}
_ROLLER = {"family": "roller", "catalogue_factors": True}

#: Every type, radial ball bearings first, in the order the docs and messages list them.
TABLE: tuple[BearingTraits, ...] = (
    BearingTraits("deep-groove", ("deep-groove",), thrust=False, pairable=False,
                  one_way=False, angle_rule=AngleRule.DEFAULT, contact_angle=0.0,
                  example_angle=None, rating_formula=RatingFormula.RADIAL_BALL,
                  static_formula=StaticFormula.RADIAL_BALL,
                  load_rule=LoadRule.GROOVE_TABLE, mounted=True, fill=(0.45, 0.7),
                  clearance_table="radial-ball", **_BALL),
    BearingTraits("angular-contact", ("angular-contact",), thrust=False, pairable=True,
                  one_way=True, angle_rule=AngleRule.GIVEN, contact_angle=None,
                  example_angle="40 deg", rating_formula=RatingFormula.RADIAL_BALL,
                  static_formula=StaticFormula.RADIAL_BALL,
                  load_rule=LoadRule.ANGLE_TABLE, mounted=True, fill=(0.55, 0.9), **_BALL),
    BearingTraits("self-aligning-ball", ("self-aligning-ball",), thrust=False,
                  pairable=False, one_way=False, angle_rule=AngleRule.DEFAULT,
                  contact_angle=0.0, example_angle=None,
                  rating_formula=RatingFormula.CATALOGUE,
                  static_formula=StaticFormula.CATALOGUE,
                  load_rule=LoadRule.SELF_ALIGNING, catalogue_factors=True,
                  double_row_form=True, **_BALL),
    BearingTraits("thrust-ball", ("thrust", "thrust-ball"), thrust=True, pairable=False,
                  one_way=False, angle_rule=AngleRule.FIXED, contact_angle=_RIGHT,
                  example_angle=None, rating_formula=RatingFormula.THRUST_BALL,
                  static_formula=StaticFormula.CATALOGUE,
                  load_rule=LoadRule.AXIAL_ONLY, **_BALL),
    BearingTraits("cylindrical-roller", ("cylindrical-roller",), thrust=False, rows=(1, 2),
                  pairable=False, one_way=False, angle_rule=AngleRule.FIXED,
                  contact_angle=0.0, example_angle=None, material_factor=1.1,
                  rating_formula=RatingFormula.RADIAL_ROLLER,
                  static_formula=StaticFormula.RADIAL_ROLLER,
                  load_rule=LoadRule.RADIAL_ONLY, ribless_forms=(("NU", "inner"), ("N", "outer")),
                  mounted=True, fill=(0.6, 0.95), roller_proportion=(0.6, 2.5, 1.0),
                  clearance_table="cylindrical", **_ROLLER),
    BearingTraits("needle-roller", ("needle-roller",), thrust=False, rows=(1, 2),
                  pairable=False, one_way=False, angle_rule=AngleRule.FIXED,
                  contact_angle=0.0, example_angle=None, material_factor=1.1,
                  rating_formula=RatingFormula.RADIAL_ROLLER,
                  static_formula=StaticFormula.RADIAL_ROLLER,
                  load_rule=LoadRule.RADIAL_ONLY, drawn_cup=True, mounted=True,
                  fill=(0.6, 0.97), roller_proportion=(2.5, 10.0, 4.0),
                  clearance_table="cylindrical", **_ROLLER),
    BearingTraits("tapered-roller", ("tapered-roller",), thrust=False, rows=(1, 2),
                  pairable=True, one_way=True, angle_rule=AngleRule.GIVEN,
                  contact_angle=None, example_angle="15 deg", material_factor=1.1,
                  rating_formula=RatingFormula.RADIAL_ROLLER,
                  static_formula=StaticFormula.RADIAL_ROLLER,
                  load_rule=LoadRule.RADIAL_ROLLER, inclined=True, cupped=True, mounted=True,
                  fill=(0.6, 0.95), roller_proportion=(0.8, 3.0, 1.6), **_ROLLER),
    BearingTraits("spherical-roller", ("spherical-roller",), thrust=False, rows=(1, 2),
                  pairable=False, one_way=False, angle_rule=AngleRule.GIVEN,
                  contact_angle=None, example_angle="15 deg", material_factor=1.15,
                  rating_formula=RatingFormula.RADIAL_ROLLER,
                  static_formula=StaticFormula.RADIAL_ROLLER,
                  load_rule=LoadRule.RADIAL_ROLLER, double_row_form=True, inclined=True,
                  crowned=True, **_ROLLER),
    BearingTraits("thrust-cylindrical-roller", ("thrust-cylindrical-roller",), thrust=True,
                  rows=(1,), pairable=False, one_way=False, angle_rule=AngleRule.FIXED,
                  contact_angle=_RIGHT, example_angle=None, material_factor=1.0,
                  rating_formula=RatingFormula.THRUST_ROLLER,
                  static_formula=StaticFormula.THRUST_ROLLER,
                  load_rule=LoadRule.THRUST_ROLLER, **_ROLLER),
    BearingTraits("thrust-spherical-roller", ("thrust-spherical-roller",), thrust=True,
                  rows=(1,), pairable=False, one_way=False, angle_rule=AngleRule.GIVEN,
                  contact_angle=None, example_angle="50 deg", material_factor=1.15,
                  rating_formula=RatingFormula.THRUST_ROLLER,
                  static_formula=StaticFormula.THRUST_ROLLER,
                  load_rule=LoadRule.THRUST_ROLLER, crowned=True, **_ROLLER),
    BearingTraits("thrust-tapered-roller", ("thrust-tapered-roller",), thrust=True,
                  rows=(1,), pairable=False, one_way=False, angle_rule=AngleRule.GIVEN,
                  contact_angle=None, example_angle="50 deg", material_factor=1.1,
                  rating_formula=RatingFormula.THRUST_ROLLER,
                  static_formula=StaticFormula.THRUST_ROLLER,
                  load_rule=LoadRule.THRUST_ROLLER, **_ROLLER),
)

#: Each type by its own name and by every spelling a spec may use.
_BY_NAME = {spelling: entry for entry in TABLE for spelling in entry.spec_names}
#: The types' own names, as catalogue rows carry them, in the table's order.
TYPE_NAMES: tuple[str, ...] = tuple(entry.name for entry in TABLE)
#: Every spelling a spec may use, in the table's order.
SPEC_NAMES: tuple[str, ...] = tuple(_BY_NAME)
#: ISO 281:2007 Table 1: bm of a drawn-cup needle roller bearing (sheet-metal outer ring).
DRAWN_CUP_MATERIAL_FACTOR = 1.0


def traits(name: str) -> BearingTraits:
    """The traits of the type a spec, a catalogue row or a solver input names.

    Raises
    ------
    KeyError : not a bearing type.
    """
    return _BY_NAME[str(name)]


def type_name(name: str) -> str:
    """The type's own name for any of its spellings (``thrust`` -> ``thrust-ball``); a
    name that is not a type's, unchanged (its refusal is the caller's)."""
    entry = _BY_NAME.get(name) if isinstance(name, str) else None
    return name if entry is None else entry.name


def names_where(**wanted: object) -> tuple[str, ...]:
    """The types' own names whose traits equal every one given, in the table's order
    (``names_where(family="roller", thrust=True)``)."""
    return tuple(entry.name for entry in TABLE
                 if all(getattr(entry, trait) == value for trait, value in wanted.items()))
