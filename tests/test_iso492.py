"""The shipped ISO 492 tables of Δdmp and ΔDmp and their lookup
(bearingcalc/catalogue/iso492.py) against sources other than the ones the tables were
entered from, and for their own smoothness.

Entered from (each file's header says the same):
- radial bearings but tapered roller bearings, classes Normal, 6 and 5: NSK Ltd., *Rolling
  Bearings*, CAT. No. E1102e (2007 E-7), Table 8.2.1 (inner rings), pp. A60-A61, and Table
  8.2.2 (outer rings), pp. A62-A63, in the text transcription ArtemFilin1990/Mar (commit
  e901cb50c72a1d590725e0b0a001a45a0b03d1db),
  07_Бренды_и_каталоги/Бренды/каталоги/Каталог_подшипников_качения_NSK.md.txt;
- metric tapered roller bearings, classes Normal and 5: GOST 520-2011 (interstate standard
  harmonised with ISO 492:2002, NEQ), Tables 16 and 17 (Normal), 23 and 24 (class 5), in
  ArtemFilin1990/Mar (commit b623d8e17ca13788f4f01e3469621a974a5a9bd8),
  12_Прочее_сопутствующее/Прочее/GOST_520-2011_Podshipniki_kacheniya.md.

Checked against:
- ``tests/data/iso492_second_source.csv``, a second maker for every class: SKF, General
  Catalogue (Russian edition, 1129 pages), Tables 3 to 5 (radial Normal, P6, P5), pp.
  125-127, and Tables 6 to 8 (tapered Normal, CLN = class 6X, P5), pp. 128-130, in the text
  transcription ArtemFilin1990/Mar (commit b623d8e17ca13788f4f01e3469621a974a5a9bd8),
  07_Бренды_и_каталоги/Бренды/каталоги/Общий_каталог_подшипников_SKF.md.txt;
- ``tests/data/iso492_third_source.csv``: for radial bearings GOST 520-2011 Tables 1 to 6
  (the same file as above); for tapered roller bearings, a maker for the bores over 400 mm
  and outside diameters over 800 mm that SKF does not print, FBJ's catalogue (Russian
  edition), Tables 3.4.1 and 3.4.2, p. 17, in ArtemFilin1990/Mar (commit
  e901cb50c72a1d590725e0b0a001a45a0b03d1db),
  07_Бренды_и_каталоги/Бренды/каталоги/Каталог_подшипников_FBJ.md.txt.

Where the sources differ (``KNOWN_DIFFERENCES`` holds each, and the test fails on any
other, or if one of these goes away):
- GOST 520 Table 1 splits the Normal class's bores at 1200 mm where NSK and SKF split at
  1250 mm: over 1200 up to 1250 mm GOST gives -160 µm, NSK and SKF -125 µm; NSK's is
  shipped.
- FBJ prints -120 µm for the Normal class's tapered bores over 80 up to 120 mm, a misprint
  of -20 µm: its Vdp (20) and Vdmp (15) in that row are the -20 µm row's of GOST 520 Table
  16, and SKF and GOST print -20 µm.
Not entered, and why the tables stop where they do (the data module's docstring has more):
NSK's Table 8.3 for tapered roller bearings follows NSK's own standard (Normal -8 µm over 10
up to 18 mm where SKF, FBJ and GOST print -12 µm); over 500 up to 630 mm of tapered bore
GOST 520 prints -60 µm and FBJ and NSK -50 µm; SKF alone prints radial classes 6 and 5 past
NSK's and GOST's last rows.
"""

from __future__ import annotations

import csv
import itertools
from collections.abc import Callable
from pathlib import Path

import pytest

from bearingcalc.catalogue.iso492 import bore_deviation, outside_deviation
from tests.conftest import ROOT, refused_in_one_sentence

DATA = Path(__file__).resolve().parent / "data"
SHIPPED = ROOT / "bearingcalc" / "data"
UM = 1e-6
MM = 1e-3

#: (ring, bearing kind, class)
Key = tuple[str, str, str]
#: (over [mm], up to [mm], lower deviation [µm]) of one printed row
Step = tuple[float, float, float]
#: (source, ring, kind, class, over [mm], up to [mm]) of a stretch where a source and the
#: shipped table differ -> the evidence.
KNOWN_DIFFERENCES: dict[tuple[str, str, str, str, float, float], str] = {
    ("gost520", "bore", "radial", "normal", 1200.0, 1250.0):
        "GOST 520 Table 1's row 1200-1600 mm (-160 µm) begins at 1200 mm; NSK and SKF print "
        "1000-1250 mm at -125 µm",
    ("fbj", "bore", "tapered", "normal", 80.0, 120.0):
        "FBJ's -120 µm is a misprint of -20 µm: Vdp 20 and Vdmp 15 in its row are the -20 µm "
        "row's",
}
LOOKUPS: dict[str, Callable[..., tuple[float, float]]] = {
    "bore": bore_deviation, "outside": outside_deviation}


def _read(path: Path, ring: str | None = None) -> list[dict[str, str]]:
    with path.open(encoding="utf-8") as handle:
        rows = list(csv.DictReader(line for line in handle if not line.startswith("#")))
    if ring is not None:
        for row in rows:
            row["ring"] = ring
    return rows


SHIPPED_ROWS = (_read(SHIPPED / "iso492_bore.csv", "bore")
                + _read(SHIPPED / "iso492_outside.csv", "outside"))
SECOND = _read(DATA / "iso492_second_source.csv")
THIRD = _read(DATA / "iso492_third_source.csv")


def _steps(rows: list[dict[str, str]]) -> dict[Key, list[Step]]:
    """Each (ring, kind, class)'s rows in order of diameter."""
    steps: dict[Key, list[Step]] = {}
    for row in rows:
        key = (row["ring"], row["bearing_kind"], row["tolerance_class"])
        steps.setdefault(key, []).append(
            (float(row["over_mm"]), float(row["up_to_mm"]), float(row["lower_um"])))
    return {key: sorted(value) for key, value in steps.items()}


def _value(steps: list[Step], size: float) -> float | None:
    return next((lower for over, up_to, lower in steps if over < size <= up_to), None)


def _shipped_um(key: Key, size: float) -> float:
    """The shipped lookup's lower deviation [µm] at ``size`` [mm], through the module."""
    ring, kind, tolerance_class = key
    lower, upper = LOOKUPS[ring](size * MM, tolerance_class=tolerance_class,
                                 tapered=kind == "tapered")
    assert upper == 0.0
    return round(lower / UM, 6)


def _stretches(ours: list[Step], theirs: list[Step]) -> list[tuple[float, float]]:
    """The stretches between the two tables' row bounds where both have rows."""
    low = max(ours[0][0], theirs[0][0])
    high = min(ours[-1][1], theirs[-1][1])
    bounds = sorted({b for step in ours + theirs for b in step[:2] if low <= b <= high})
    return list(itertools.pairwise(bounds))


def _differences(source_rows: list[dict[str, str]]) -> dict[tuple, tuple[float, float]]:
    """Every stretch where a source's printed value and the shipped lookup differ:
    (source, ring, kind, class, over, up to) -> (shipped, printed) [µm]."""
    shipped = _steps(SHIPPED_ROWS)
    found = {}
    for source, rows in itertools.groupby(sorted(source_rows, key=lambda r: r["source"]),
                                          key=lambda r: r["source"]):
        for key, theirs in _steps(list(rows)).items():
            # SKF's CLN (ISO's 6X) is checked through the lookup's 6X against the Normal rows
            ours = shipped[(key[0], key[1], "normal" if key[2] == "6X" else key[2])]
            for over, up_to in _stretches(ours, theirs):
                middle = 0.5 * (over + up_to)
                printed = _value(theirs, middle)
                if printed is not None and _shipped_um(key, middle) != printed:
                    found[(source, *key, over, up_to)] = (_shipped_um(key, middle), printed)
    return found


@pytest.mark.parametrize(("rows", "sources"), [(SECOND, {"skf"}),
                                               (THIRD, {"gost520", "fbj"})])
def test_every_value_two_sources_print_agrees_but_the_known_differences(rows, sources):
    assert {row["source"] for row in rows} == sources
    found = _differences(rows)
    expected = {key for key in KNOWN_DIFFERENCES if key[0] in sources}
    assert set(found) == expected, {key: found.get(key) for key in set(found) ^ expected}


def test_the_known_differences_are_as_printed():
    found = _differences(THIRD)
    assert found[("gost520", "bore", "radial", "normal", 1200.0, 1250.0)] == (-125.0, -160.0)
    assert found[("fbj", "bore", "tapered", "normal", 80.0, 120.0)] == (-20.0, -120.0)


def test_every_shipped_row_is_printed_alike_by_a_maker_other_than_its_own():
    """NSK's radial rows by SKF; GOST 520's tapered rows by SKF or, past SKF's last rows,
    FBJ: each stretch of a shipped row between the makers' row bounds agrees with one."""
    makers = [_steps(SECOND), _steps([row for row in THIRD if row["source"] == "fbj"])]
    unconfirmed = []
    for key, ours in _steps(SHIPPED_ROWS).items():
        bounds = sorted({b for steps in [ours] + [maker.get(key, []) for maker in makers]
                         for step in steps for b in step[:2]
                         if ours[0][0] <= b <= ours[-1][1]})
        for over, up_to in itertools.pairwise(bounds):
            middle = 0.5 * (over + up_to)
            if all(_value(maker.get(key, []), middle) != _value(ours, middle)
                   for maker in makers):
                unconfirmed.append((*key, over, up_to))
    assert unconfirmed == []


def test_the_lookup_reads_every_shipped_row():
    for key, steps in _steps(SHIPPED_ROWS).items():
        for over, up_to, lower in steps:
            assert _shipped_um(key, up_to) == lower
            assert _shipped_um(key, 0.5 * (over + up_to)) == lower


@pytest.mark.parametrize("key", sorted(_steps(SHIPPED_ROWS)))
def test_rows_run_on_and_the_deviation_grows_with_the_diameter(key):
    steps = _steps(SHIPPED_ROWS)[key]
    for (over, up_to, lower), (next_over, _, next_lower) in itertools.pairwise(steps):
        assert over < up_to == next_over
        assert next_lower <= lower < 0.0
    assert all(float(row["upper_um"]) == 0.0 for row in SHIPPED_ROWS)


@pytest.mark.parametrize(("ring", "kind", "classes"), [
    ("bore", "radial", ("normal", "6", "5")), ("outside", "radial", ("normal", "6", "5")),
    ("bore", "tapered", ("normal", "5")), ("outside", "tapered", ("normal", "5"))])
def test_a_finer_class_has_a_narrower_band(ring, kind, classes):
    steps = _steps(SHIPPED_ROWS)
    for coarse, fine in itertools.pairwise(classes):
        ours, theirs = steps[(ring, kind, coarse)], steps[(ring, kind, fine)]
        for over, up_to in _stretches(ours, theirs):
            middle = 0.5 * (over + up_to)
            assert _value(ours, middle) < _value(theirs, middle), (coarse, fine, middle)


@pytest.mark.parametrize(("ring", "kind", "tolerance_class", "low", "high"), [
    ("bore", "radial", "normal", 3.0, 500.0), ("bore", "radial", "6", 3.0, 500.0),
    ("bore", "radial", "5", 3.0, 400.0), ("outside", "radial", "normal", 3.0, 630.0),
    ("outside", "radial", "6", 3.0, 630.0), ("outside", "radial", "5", 3.0, 630.0),
    ("bore", "tapered", "normal", 10.0, 500.0), ("bore", "tapered", "5", 10.0, 400.0),
    ("outside", "tapered", "normal", 18.0, 630.0), ("outside", "tapered", "5", 18.0, 630.0)])
def test_the_tables_span_the_sizes_asked_of_them(ring, kind, tolerance_class, low, high):
    steps = _steps(SHIPPED_ROWS)[(ring, kind, tolerance_class)]
    assert steps[0][0] <= low and steps[-1][1] >= high


# Values typed from NSK E1102e Table 8.2 and GOST 520-2011 Tables 16, 17, not from the CSV.
@pytest.mark.parametrize(("lookup", "diameter_mm", "tolerance_class", "tapered", "lower_um"), [
    (bore_deviation, 25.0, "normal", False, -10.0),     # 6205: over 18 up to 30
    (bore_deviation, 30.0, "normal", False, -10.0),     # a bound belongs to the row it ends
    (bore_deviation, 30.000001, "normal", False, -12.0),
    (bore_deviation, 0.6, "normal", False, -8.0),       # NSK: 0.6 mm is in the first group
    (outside_deviation, 2.5, "5", False, -5.0),         # NSK: 2.5 mm is in the first group
    (outside_deviation, 52.0, "6", False, -11.0),
    (outside_deviation, 400.0, "5", False, -20.0),
    (bore_deviation, 55.0, "normal", True, -15.0),      # 30211: d 55, D 100
    (outside_deviation, 100.0, "normal", True, -18.0),
    (bore_deviation, 55.0, "6X", True, -15.0),          # 6X is the Normal class's
    (outside_deviation, 100.0, "5", True, -13.0),
])
def test_values_of_common_bearings(lookup, diameter_mm, tolerance_class, tapered, lower_um):
    lower, upper = lookup(diameter_mm * MM, tolerance_class=tolerance_class, tapered=tapered)
    assert (lower, upper) == pytest.approx((lower_um * UM, 0.0), abs=1e-12)


@pytest.mark.parametrize(("written", "name"), [("PN", "normal"), ("P0", "normal"),
                                               ("Normal", "normal"), ("p6", "6"),
                                               (" P5 ", "5")])
def test_the_other_names_of_the_classes(written, name):
    for lookup, size in ((bore_deviation, 0.04), (outside_deviation, 0.09)):
        assert lookup(size, tolerance_class=written) == lookup(size, tolerance_class=name)


@pytest.mark.parametrize(("call", "words"), [
    (lambda: bore_deviation(0.04, tolerance_class="4"),
     ("'4'", "normal (or PN, P0), 6 (P6), 5 (P5), or 6X (P6X)")),
    (lambda: bore_deviation(0.04, tolerance_class="6X"), ("tapered roller bearings only",)),
    (lambda: outside_deviation(0.09, tolerance_class="6", tapered=True),
     ("no class '6'", "normal, 6X and 5")),
    (lambda: bore_deviation(0.45, tolerance_class="5"), ("450 mm", "0.6 mm to 400 mm")),
    (lambda: outside_deviation(3.0), ("3000 mm", "2.5 mm to 2500 mm")),
    (lambda: bore_deviation(0.008, tapered=True), ("8 mm", "10 mm to 500 mm")),
    (lambda: outside_deviation(0.002), ("2 mm", "2.5 mm to 2500 mm")),
    (lambda: bore_deviation(-0.02), ("positive length",)),
    (lambda: bore_deviation(float("nan")), ("positive length",)),
    (lambda: outside_deviation("wide"), ("positive length",)),
])
def test_a_refusal_is_one_sentence_naming_what_is_right(call, words):
    refused_in_one_sentence(call, words)
