"""Every solver takes the typed mapping its registration declares: every example's and
template's inputs (a duty cycle's too, and each of a drive's bearings) have every key the
type requires and none it does not name."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from bearingcalc.core.solver_inputs import CycleInputs, MountedBearingInputs
from bearingcalc.evaluation import load_one_spec
from bearingcalc.kinds import KINDS

ROOT = Path(__file__).resolve().parents[1]
SPECS = sorted([*ROOT.glob("specs/*.yaml"), *ROOT.glob("bearingcalc/templates/*.yaml")])


def _keys_missing_and_unknown(inputs: dict[str, Any], declared: type) -> tuple[set, set]:
    required = set(declared.__required_keys__)  # type: ignore[attr-defined]
    known = required | set(declared.__optional_keys__)  # type: ignore[attr-defined]
    return required - set(inputs), set(inputs) - known


@pytest.mark.parametrize("name", sorted(KINDS))
def test_every_kind_declares_what_its_solver_takes(name):
    declared = KINDS[name].solver.input_type()
    assert declared is not None and declared.__required_keys__, name


@pytest.mark.parametrize("path", SPECS, ids=[path.name for path in SPECS])
def test_the_inputs_of_every_example_are_the_declared_ones(path):
    kind, spec, _ = load_one_spec(path)
    inputs = dict(spec.solver_inputs())
    missing, unknown = _keys_missing_and_unknown(inputs, kind.solver.input_type())
    assert not missing and not unknown, (missing, unknown)
    has_cycle = getattr(spec, "duty_cycle", None) is not None
    assert has_cycle == (set(CycleInputs.__optional_keys__) <= set(inputs))
    for bearings in inputs.get("shafts", {}).values():
        for bearing in bearings:
            assert _keys_missing_and_unknown(bearing, MountedBearingInputs) == (set(), set())


def test_the_check_finds_a_key_too_many_and_one_missing():
    kind, spec, _ = load_one_spec(ROOT / "specs" / "disk-on-circle.yaml")
    inputs = {**spec.solver_inputs(), "disk_radius_typo": 1.0}
    del inputs["disk_radius"]
    assert _keys_missing_and_unknown(inputs, kind.solver.input_type()) == ({"disk_radius"},
                                                                      {"disk_radius_typo"})
