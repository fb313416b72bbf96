"""What a kind is: a solver that describes itself, a spec model derived from Spec, a
template, a docs page and a registry entry. Every registered kind has each."""

from __future__ import annotations

import numpy as np
import pytest

from bearingcalc.core.solver import Solution, Solver
from bearingcalc.evaluation import load_one_spec
from bearingcalc.kinds import KINDS
from bearingcalc.models.base import Spec, nested_model
from bearingcalc.models.rules import rule, rules_of
from tests.conftest import ROOT


@pytest.mark.parametrize("name", sorted(KINDS))
def test_a_kind_has_every_part(name):
    kind = KINDS[name]
    assert isinstance(kind.solver, Solver)
    assert issubclass(kind.model, Spec)
    assert {"kind", "name"} <= set(kind.model.model_fields)
    assert (ROOT / "bearingcalc" / "templates" / f"{name}.yaml").is_file()
    assert (ROOT / "docs" / "kinds" / f"{name}.md").is_file()
    assert set(kind.margins) <= set(kind.results)
    governing = {key for entry in kind.governing
                 for key in ((entry,) if isinstance(entry, str) else entry)}
    assert governing <= set(kind.results)
    for heading, keys in kind.groups.items():
        assert set(keys) <= set(kind.results), heading


@pytest.mark.parametrize("name", sorted(KINDS))
def test_a_solver_returns_a_solution_with_warnings_apart_from_results(name):
    _, spec, _ = load_one_spec(ROOT / "bearingcalc" / "templates" / f"{name}.yaml")
    solution = KINDS[name].solver.evaluate(spec.solver_inputs(), None)
    assert isinstance(solution, Solution)
    assert set(solution.results) <= set(KINDS[name].results)
    assert set(solution.warnings) <= set(KINDS[name].warnings)
    for flags in solution.warnings.values():
        assert np.asarray(flags).dtype == bool


def test_no_method_shadows_a_rule():
    """A rule is collected by name through the bases: a plain method of the same name in
    a subclass would drop it without a word, so the collection refuses that."""
    class Base(Spec):
        @rule
        def _checked(self) -> None:
            return None

    class Shadowing(Base):
        def _checked(self) -> None:  # type: ignore[override]
            return None

    with pytest.raises(TypeError, match="shadows the rule"):
        rules_of(Shadowing)


@pytest.mark.parametrize("name", sorted(KINDS))
def test_every_model_of_a_kind_collects_its_rules(name):
    model = KINDS[name].model
    rules_of(model)  # raises where a method shadows a rule
    for field in model.model_fields.values():
        held = nested_model(field)
        if held is not None:
            rules_of(held)


@pytest.mark.parametrize("name", sorted(KINDS))
def test_a_kind_declares_its_report(name):
    """The standards a kind's report cites, each with a section of docs/physics.md that
    exists, and drawings the report knows (with any solver function they name)."""
    import importlib
    import re

    from bearingcalc.plots.report import DRAWINGS

    kind = KINDS[name]
    assert kind.standards
    physics = (ROOT / "docs" / "physics.md").read_text(encoding="utf-8")
    headings = set(re.findall(r"^#+ §(\d+) ", physics, re.M))
    for line in kind.standards:
        cited = re.findall(r"§(\d+)(?![-\d])", line)  # not a book's §15-1
        assert cited, line
        assert set(cited) <= headings, (line, sorted(headings))
    for plot in kind.plots:
        assert plot.name in DRAWINGS
        if plot.solver_function:
            module, _, function = plot.solver_function.partition(":")
            assert callable(getattr(importlib.import_module(module), function))


@pytest.mark.parametrize("name", sorted(KINDS))
def test_results_along_axes_follow_a_declared_result(name):
    """Each axis's results name the result of one value per design they follow (or none:
    last), and every axis is one of the declared axes."""
    from bearingcalc.core.solver import AXES

    kind = KINDS[name]
    for axis, declared in kind.along.items():
        assert axis in AXES
        assert declared.after == "" or declared.after in kind.results, (axis, declared.after)
        assert declared.columns
