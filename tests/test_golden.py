"""The tool's output for every example, compared with the recorded golden set byte for
byte (see tests/golden/cases.py)."""

from __future__ import annotations

import pytest

from tests.golden.cases import RECORDS, cases, run, stage

CASES = cases()


@pytest.fixture(scope="module")
def at_root(tmp_path_factory):
    root = tmp_path_factory.mktemp("golden")
    stage(root)
    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(root)
        yield


def test_every_case_has_a_record_and_every_record_a_case():
    assert {path.stem for path in RECORDS.glob("*.txt")} == set(CASES)


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_output_is_the_recorded_one(at_root, name):
    expected = (RECORDS / f"{name}.txt").read_text(encoding="utf-8")
    assert run(CASES[name]) == expected
