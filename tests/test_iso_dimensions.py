"""The shipped ISO boundary dimensions against second makers' catalogues, entered apart
from it, and for the smoothness of each series; ISO 15's bore code against the table.

Sources (each file's header names its documents):
- shipped, ``bearingcalc/data/iso_boundary_dimensions.csv``: NSK, *Rolling Bearings*,
  CAT. No. E1102e, for every series but 64; Koyo (JTEKT), CAT. No. B2001RUS, for 64;
- second, ``tests/data/iso_dimensions_second_source.csv``: Koyo (JTEKT), CAT. No. B2001RUS;
- third, ``tests/data/iso_dimensions_third_source.csv``: KYK, general bearing catalogue,
  for the 64 series and 30304 (which the second lacks, or which is the 64 series' own).

A tapered roller bearing's two chamfers are compared apart: ``r_min`` is the cone's (NSK's
and Koyo's r, KYK's r_s min), ``cup_r_min`` the cup's (NSK's and Koyo's r1, KYK's r1s min).
"""

from __future__ import annotations

import csv
import itertools
from pathlib import Path

import pytest

from bearingcalc.catalogue.designation import parse_designation
from bearingcalc.catalogue.iso import iso_series, iso_table
from tests.conftest import ROOT

DATA = Path(__file__).resolve().parent / "data"
NUMBERS = ("bore_diameter [mm]", "outside_diameter [mm]", "width [mm]", "r_min [mm]")
#: Numbers only some types have: empty in a row of any other type.
OPTIONAL_NUMBERS = ("cup_r_min [mm]",)


def _rows(path: Path) -> dict[str, dict[str, str]]:
    with path.open(encoding="utf-8") as handle:
        lines = [line for line in handle if not line.startswith("#")]
    return {row["designation"]: row for row in csv.DictReader(lines)}


SHIPPED = _rows(ROOT / "bearingcalc" / "data" / "iso_boundary_dimensions.csv")
SECOND = _rows(DATA / "iso_dimensions_second_source.csv")
THIRD = _rows(DATA / "iso_dimensions_third_source.csv")


def _agree(ours: dict[str, str], theirs: dict[str, str]) -> list[str]:
    """The columns where two rows of a designation differ (an ISO 355 code only where
    both print one)."""
    differ = [name for name in NUMBERS if float(ours[name]) != float(theirs[name])]
    differ += [name for name in OPTIONAL_NUMBERS
               if _optional(ours[name]) != _optional(theirs[name])]
    if ours["type"] != theirs["type"]:
        differ.append("type")
    if ours["iso355_series"] and theirs["iso355_series"] and (
            ours["iso355_series"] != theirs["iso355_series"]):
        differ.append("iso355_series")
    return differ


def _optional(cell: str) -> float | None:
    return float(cell) if cell.strip() else None


@pytest.mark.parametrize(("other", "name"), [(SECOND, "second"), (THIRD, "third")])
def test_every_row_both_sources_print_agrees(other, name):
    common = sorted(set(SHIPPED) & set(other))
    assert len(common) >= (300 if name == "second" else 15)
    disagree = {designation: _agree(SHIPPED[designation], other[designation])
                for designation in common}
    assert {key: value for key, value in disagree.items() if value} == {}


def test_every_shipped_row_is_printed_by_a_maker_other_than_its_own():
    """The 64 series is Koyo's own, so KYK confirms it; the rest are NSK's, which Koyo or
    KYK confirms."""
    unconfirmed = [designation for designation in SHIPPED
                   if designation not in (THIRD if designation.startswith("64")
                                          else {**SECOND, **THIRD})]
    assert unconfirmed == []
    assert len(SHIPPED) == len(iso_table()) >= 340


def test_the_cup_chamfer_is_given_for_every_tapered_row_and_no_other():
    """Every tapered row carries its cup's chamfer, confirmed by Koyo (KYK for 30304, which
    the second lacks); no other type has a cup."""
    tapered = {designation for designation, row in SHIPPED.items()
               if row["type"] == "tapered-roller"}
    given = {designation for designation, row in SHIPPED.items()
             if row["cup_r_min [mm]"].strip()}
    assert given == tapered and len(tapered) == 91
    confirmed = {designation for designation in tapered
                 if (SECOND.get(designation) or THIRD[designation])["cup_r_min [mm]"].strip()}
    assert confirmed == tapered


def test_a_cup_chamfer_is_never_larger_than_its_cone_s():
    """As both makers print them, a tapered bearing's cup chamfer is its cone's or the
    next smaller of the chamfers these series use (0.3 mm, 0.6, 1, 1.5, 2, 2.5, 3, 4);
    no other type has one."""
    steps = [0.3, 0.6, 1, 1.5, 2, 2.5, 3, 4]
    for designation, dimensions in iso_table().items():
        if dimensions.type != "tapered-roller":
            assert dimensions.cup_r_min is None, designation
            continue
        cone, cup = (round(value * 1e3, 9) for value in (dimensions.r_min,
                                                          dimensions.cup_r_min))
        assert steps.index(cone) - steps.index(cup) in (0, 1), designation


def test_the_table_gives_both_chamfers_of_a_tapered_bearing_in_metres():
    """30211: NSK p. B118 prints r 2, r1 1.5 (Koyo the same)."""
    dimensions = iso_table()["30211"]
    assert (dimensions.r_min, dimensions.cup_r_min) == pytest.approx((2e-3, 1.5e-3),
                                                                     rel=1e-12)


@pytest.mark.parametrize("series", iso_series())
def test_each_series_is_smooth(series):
    """Down a series the bore rises by its code, the outside diameter rises, and the
    width and the chamfers (a tapered bearing's cone's and cup's) never shrink."""
    rows = [row for designation, row in SHIPPED.items() if designation[:-2] == series]
    bores = [float(row["bore_diameter [mm]"]) for row in rows]
    outside = [float(row["outside_diameter [mm]"]) for row in rows]
    widths = [float(row["width [mm]"]) for row in rows]
    chamfers = [float(row["r_min [mm]"]) for row in rows]
    cup_chamfers = [float(row["cup_r_min [mm]"] or 0) for row in rows]
    assert bores == sorted(set(bores))
    assert all(b < a for b, a in itertools.pairwise(outside))
    assert widths == sorted(widths) and chamfers == sorted(chamfers)
    assert cup_chamfers == sorted(cup_chamfers)
    assert all(d < big for d, big in zip(bores, outside, strict=True))


def test_the_bore_code_gives_every_bore():
    """ISO 15: 00 = 10 mm, 01 = 12, 02 = 15, 03 = 17, then the code × 5 mm."""
    for designation, dimensions in iso_table().items():
        parsed = parse_designation(designation)
        assert parsed is not None and parsed.basic == designation
        assert parsed.bore_diameter == pytest.approx(dimensions.bore_diameter * 1e3,
                                                     abs=1e-12), designation
