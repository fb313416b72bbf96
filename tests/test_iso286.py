"""The shipped ISO 286 tables and their lookup (bearingcalc/catalogue/iso286.py) against
sources other than the ones the tables were entered from, and for their own consistency.

Entered from (each file's header says the same):
- ``bearingcalc/data/iso286_grades.csv``, IT3 to IT12: NSK Ltd., *Rolling Bearings*,
  CAT. No. E1102e (2007 E-7), Appendix Table 11, pp. C22-C23, in the text transcription
  ArtemFilin1990/Mar (commit e901cb50c72a1d590725e0b0a001a45a0b03d1db),
  07_Бренды_и_каталоги/Бренды/каталоги/Каталог_подшипников_качения_NSK.md.txt;
- ``bearingcalc/data/iso286_deviations.csv``, fundamental deviations and Δ (ISO 286-1
  Tables 2 and 3): rf-ghofmockel/rf-tolerance, data/DIN286/DIN286TypeData.js and
  DIN286DeltaData.js (commit 857eff3aa59e4bcdee3c64cfb0e39c81b5d19e40), G over 3 up to
  6 mm corrected from +2 to +4 µm (the file's header gives the evidence).

Checked against:
- ``tests/data/iso286_grades_second_source.csv``: SKF General Catalogue, Russian edition,
  Table 10, p. 195, in the text transcription ArtemFilin1990/Mar (commit
  b623d8e17ca13788f4f01e3469621a974a5a9bd8),
  07_Бренды_и_каталоги/Бренды/каталоги/Общий_каталог_подшипников_SKF.md.txt;
- ``tests/data/iso286_second_source.csv``, limit deviations of printed classes: SKF, the
  same catalogue, Tables 7a-7e (shafts) and 8a-8e (housings), pp. 174-193; NSK, the same
  catalogue as above, Appendix Table 9, pp. C18-C19 (n6 p6 r6 r7 up to 80 mm, which the
  SKF transcription lacks); GB/T 1800.2-2020, China's adoption of ISO 286-2:2010, Tables
  4-6, 8-10, 21, 22, 24, 25 and 27, in the extraction zensgit/cad-ml-platform,
  data/knowledge/iso286_deviations.json (commit 22e3c77c9881d57fc9095c2ff87c0e566be01c16);
  the one cell a source misprints is listed in ``MISPRINTS`` with its evidence;
- ISO 286-1's own relations, between the two shipped tables: Δ = ITn − IT(n−1) (the rule
  Table 3's Δ values come from), each hole letter the mirror of its shaft letter (F = −f,
  G = −g, H = −h, K = −k, M = −m, N = −n, P = −p), and
  the tolerance unit i = 0.45·∛D + 0.001·D times the grade factors 7 to 160 (IT5 to
  IT12), D the geometric mean of the range, a sanity bound only: the table's rounding
  does not follow the formula everywhere.
"""

from __future__ import annotations

import csv
import itertools
import math
from pathlib import Path

import pytest

from bearingcalc.catalogue.iso286 import (
    HOLE_LETTERS,
    SHAFT_LETTERS,
    is_hole,
    limit_deviations,
    standard_tolerance,
)
from tests.conftest import ROOT

DATA = Path(__file__).resolve().parent / "data"
SHIPPED = ROOT / "bearingcalc" / "data"
UM = 1e-6
MM = 1e-3
#: IT5 to IT12 in tolerance units i (ISO 286-1:2010 Table 1's basis).
UNIT_FACTORS = {5: 7, 6: 10, 7: 16, 8: 25, 9: 40, 10: 64, 11: 100, 12: 160}
#: The bearing seat classes that must be reproduced over the whole span 3 to 500 mm.
SEAT_CLASSES = ("k5", "m5", "m6", "n6", "p6", "j5", "j6", "js5", "h5", "h6", "g6", "f6",
                "H6", "H7", "H8", "J6", "J7", "K6", "K7", "M6", "M7", "N7", "P7", "G6",
                "G7", "F7")


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8") as handle:
        return list(csv.DictReader(line for line in handle if not line.startswith("#")))


GRADES = _rows(SHIPPED / "iso286_grades.csv")
DEVIATIONS = _rows(SHIPPED / "iso286_deviations.csv")
SECOND_GRADES = _rows(DATA / "iso286_grades_second_source.csv")
SECOND_LIMITS = _rows(DATA / "iso286_second_source.csv")
#: Cells a second source misprints: (source, class, over [mm]) -> why it is a misprint.
MISPRINTS = {
    ("SKF", "M5", "18"): "Table 8d prints M5 over 18 up to 30 mm as -4/-14 µm, 10 µm wide where "
                         "IT5 is 9 µm; its own fit line below it (+14/-4 against a bearing "
                         "bore of 0/-9 µm) gives ES = -5 µm, as GB/T 1800.2 does",
}


def _range(row: dict[str, str]) -> tuple[float, float]:
    return float(row["over_mm"]), float(row["up_to_mm"])


def _sizes(row: dict[str, str]) -> list[float]:
    """Sizes [mm] a second-source row is checked at: the size its range ends on, and its
    middle where the lookup takes it (a '1 to 3' row is the standard's 'up to 3')."""
    over, up_to = _range(row)
    middle = (over + up_to) / 2.0
    return [up_to] + ([middle] if middle >= 3.0 else [])


def test_grades_agree_with_a_second_maker():
    shipped = {_range(row)[1]: row for row in GRADES}
    assert len(SECOND_GRADES) == len(GRADES) == 13
    differ = {}
    for row in SECOND_GRADES:
        ours = shipped[_range(row)[1]]
        for grade in range(3, 13):
            name = f"IT{grade}"
            if float(ours[name]) != float(row[name]):
                differ[(_range(row), name)] = (ours[name], row[name])
    assert differ == {}


def test_grades_grow_with_grade_and_with_size():
    for row in GRADES:
        values = [float(row[f"IT{grade}"]) for grade in range(3, 13)]
        assert values == sorted(values) and len(set(values)) == len(values), row
    for grade in range(3, 13):
        column = [float(row[f"IT{grade}"]) for row in GRADES]
        assert column == sorted(column), grade
        if grade >= 5:  # IT3 and IT4 repeat over 3-6 and 6-10 mm in the standard
            assert len(set(column)) == len(column), grade


@pytest.mark.parametrize("row", GRADES, ids=lambda row: "{}-{}".format(*_range(row)))
def test_grades_follow_the_tolerance_unit(row):
    over, up_to = _range(row)
    # The standard takes the first range as 1 to 3 mm for the formula; its values there
    # were kept from before the formula and sit some 15 % above it.
    mean = math.sqrt(max(over, 1.0) * up_to)
    unit = 0.45 * mean ** (1.0 / 3.0) + 0.001 * mean
    bound = 0.16 if over == 0.0 else 0.10
    for grade, factor in UNIT_FACTORS.items():
        value = float(row[f"IT{grade}"])
        assert abs(value - factor * unit) <= bound * factor * unit, (grade, value, factor * unit)


def test_deviation_ranges_tile_3_to_500_mm_inside_the_grade_ranges():
    ranges = [_range(row) for row in DEVIATIONS]
    assert ranges[0][0] == 0.0 and ranges[-1][1] == 500.0
    assert all(a[1] == b[0] for a, b in itertools.pairwise(ranges))
    grade_ranges = [_range(row) for row in GRADES]
    for over, up_to in ranges:
        assert any(a <= over and up_to <= b for a, b in grade_ranges), (over, up_to)


def _grade_row(up_to: float) -> dict[str, str]:
    return next(row for row in GRADES if _range(row)[0] < up_to <= _range(row)[1])


@pytest.mark.parametrize("row", DEVIATIONS, ids=lambda row: "{}-{}".format(*_range(row)))
def test_delta_is_the_step_from_the_grade_below(row):
    """ISO 286-1 Table 3: Δ = ITn − IT(n−1), and nothing up to 3 mm; the two tables came
    from different sources."""
    over, up_to = _range(row)
    grades = _grade_row(up_to)
    for grade in range(4, 9):
        step = float(grades[f"IT{grade}"]) - float(grades[f"IT{grade - 1}"])
        assert float(row[f"delta_{grade}"]) == (0.0 if over == 0.0 else step), grade


@pytest.mark.parametrize("row", DEVIATIONS, ids=lambda row: "{}-{}".format(*_range(row)))
def test_each_hole_letter_mirrors_its_shaft_letter(row):
    pairs = {"EI_F": "es_f", "EI_G": "es_g", "EI_H": "es_h", "ES_K": "ei_k", "ES_M": "ei_m",
             "ES_N": "ei_n", "ES_P": "ei_p"}
    assert {hole: float(row[hole]) for hole in pairs} == {
        hole: -float(row[shaft]) for hole, shaft in pairs.items()}


@pytest.mark.parametrize("source", ["SKF", "NSK", "GBT"])
def test_limits_agree_with_second_sources(source):
    rows = [row for row in SECOND_LIMITS if row["source"] == source
            and (source, row["tolerance_class"], row["over_mm"]) not in MISPRINTS]
    assert len(rows) >= {"SKF": 500, "NSK": 28, "GBT": 800}[source]
    differ = {}
    for row in rows:
        expected = (float(row["lower_um"]) * UM, float(row["upper_um"]) * UM)
        for size in _sizes(row):
            got = limit_deviations(row["tolerance_class"], size * MM)
            if got != pytest.approx(expected, abs=1e-12):
                differ[(row["tolerance_class"], size)] = (
                    tuple(round(value / UM, 3) for value in got), expected)
    assert differ == {}


def test_each_misprint_is_one_and_another_source_prints_the_cell_right():
    for source, tolerance_class, over in MISPRINTS:
        printed = _second(source, tolerance_class, float(over))
        others = [_second(other, tolerance_class, float(over)) for other in ("SKF", "GBT")
                  if other != source]
        ours = limit_deviations(tolerance_class, float(over) * MM + 1e-6)
        assert ours != pytest.approx(printed, abs=1e-12)
        assert all(ours == pytest.approx(other, abs=1e-12) for other in others)
        assert printed[1] - printed[0] != pytest.approx(ours[1] - ours[0], abs=1e-12)


@pytest.mark.parametrize("tolerance_class", SEAT_CLASSES)
def test_every_bearing_seat_class_is_checked_from_3_to_500_mm(tolerance_class):
    """The seat classes are printed by a second source over the whole span, so that the
    test above reaches every range of each."""
    spans = sorted(_range(row) for row in SECOND_LIMITS
                   if row["tolerance_class"] == tolerance_class)
    reach = 3.0
    for over, up_to in spans:
        if over <= reach < up_to or (over < 3.0 and up_to >= 3.0):
            reach = max(reach, up_to)
    assert reach == 500.0, (tolerance_class, spans)


def _second(source: str, tolerance_class: str, over: float) -> tuple[float, float]:
    row = next(row for row in SECOND_LIMITS if row["source"] == source
               and row["tolerance_class"] == tolerance_class and float(row["over_mm"]) == over)
    return float(row["lower_um"]) * UM, float(row["upper_um"]) * UM


def test_a_size_on_a_boundary_takes_the_range_it_ends():
    assert limit_deviations("k6", 0.030) == pytest.approx(_second("SKF", "k6", 18), abs=1e-12)
    assert limit_deviations("k6", 0.030001) == pytest.approx(_second("SKF", "k6", 30),
                                                             abs=1e-12)
    # 3 mm exactly is the standard's 'up to and including 3 mm' range.
    assert limit_deviations("k6", 0.003) == pytest.approx(_second("SKF", "k6", 1), abs=1e-12)
    assert limit_deviations("j8", 0.003) == pytest.approx(_second("GBT", "j8", 0), abs=1e-12)
    assert limit_deviations("r6", 0.065) == pytest.approx(_second("NSK", "r6", 50), abs=1e-12)
    # 0.1 + 0.2 - 0.3 m off 65 mm is a floating-point ulp, not a size.
    assert limit_deviations("r6", 0.065 + (0.1 + 0.2 - 0.3)) == limit_deviations("r6", 0.065)
    assert limit_deviations("P7", 0.5) == pytest.approx(_second("SKF", "P7", 400), abs=1e-12)


def test_every_held_class_spans_its_standard_tolerance():
    classes = [f"{letter}{grade}" for letter in SHAFT_LETTERS + HOLE_LETTERS
               for grade in range(4, 9)
               if not (letter in ("j", "J") and grade < 5 + (letter == "J"))
               and (letter, grade) != ("j", 8)]
    for row in DEVIATIONS:
        over, up_to = _range(row)
        for size in [size for size in (up_to, (over + up_to) / 2.0) if size >= 3.0]:
            for tolerance_class in classes:
                lower, upper = limit_deviations(tolerance_class, size * MM)
                width = standard_tolerance(int(tolerance_class[-1]), size * MM)
                assert upper - lower == pytest.approx(width, abs=1e-12), (tolerance_class, size)
                if tolerance_class[:-1] in ("js", "JS"):
                    assert lower == -upper


def test_case_decides_hole_or_shaft():
    assert is_hole("H7") and is_hole("JS6") and not is_hole("k5") and not is_hole("js6")
    assert limit_deviations("H7", 0.05) != limit_deviations("h7", 0.05)


@pytest.mark.parametrize(("tolerance_class", "size", "names"), [
    ("x5", 0.05, ["'x'", "f, g, h, j, js, k, m, n, p, r", "F, G, H, J, JS, K, M, N, P"]),
    ("Js7", 0.05, ["'Js'", "f, g, h, j, js, k, m, n, p, r"]),
    ("k9", 0.05, ["grade 9", "grades 4 to 8"]),
    ("J5", 0.05, ["grade 5", "grades 6 to 8"]),
    ("j4", 0.05, ["grade 4", "grades 5 to 8", "j8 only up to 3 mm"]),
    ("j8", 0.01, ["only up to 3 mm", "10 mm", "j7"]),
    ("k", 0.05, ["k5", "H7"]),
    ("k5", 0.0029, ["2.9 mm", "3 mm to 500 mm"]),
    ("H7", 0.5001, ["500.1 mm", "3 mm to 500 mm"]),
    ("H7", math.nan, ["nan", "positive length"]),
])
def test_bad_input_is_refused_in_one_sentence(tolerance_class, size, names):
    with pytest.raises(ValueError) as caught:
        limit_deviations(tolerance_class, size)
    message = str(caught.value)
    assert all(name in message for name in names), message
    assert message.endswith(".") and ". " not in message, message


def test_standard_tolerance_refuses_a_grade_outside_the_table():
    with pytest.raises(ValueError, match="IT3 to IT12"):
        standard_tolerance(13, 0.05)
    assert standard_tolerance(12, 0.05) == pytest.approx(250 * UM, abs=1e-12)
