"""Cross-field rules of spec models, collected so that one run reports them all.

A rule is a method of a spec model marked with :func:`rule`. It reads the model's
fields and returns the problem it finds (a :class:`SpecFieldError` naming the field
at fault, relative to the model), a list of them, or None. Rules are independent of each other, so
every problem of a spec is found at once, not one per run.

When some fields of a spec are invalid, the rules that read none of them still run
(:func:`problems_despite`): their problems are reported beside the field errors.
"""

from __future__ import annotations

import functools
import inspect
import types
from collections.abc import Callable, Collection, Iterator, Sequence
from typing import Any

from pydantic import BaseModel

from bearingcalc.errors import SpecFieldError

#: A rule returns the problem it finds, a list of them, or None.
Rule = Callable[[Any], "SpecFieldError | list[SpecFieldError] | None"]
#: How a subject's problem reads in the whole spec: (problem, every subject has it) -> it.
Renamer = Callable[[SpecFieldError, bool], SpecFieldError]
_RULE_MARK = "_is_spec_rule"
_WHOLE_MARK = "_is_whole_spec_rule"


def rule(method: Rule) -> Rule:
    """Mark a model method as a cross-field rule. A model's rules run base classes first
    (the reverse of its method resolution order), each class's in definition order; the
    problems are then reported in the order of their lines."""
    setattr(method, _RULE_MARK, True)
    return method


def whole_spec_rule(method: Rule) -> Rule:
    """A :func:`rule` of the spec as a whole, checked once even where the spec has
    subjects of its own (``rule_subjects``: the bins of a duty cycle), which every other
    rule checks one by one."""
    setattr(method, _WHOLE_MARK, True)
    return rule(method)


def whole_spec_problems(model: BaseModel) -> list[SpecFieldError]:
    """The problems of a model's :func:`whole_spec_rule` rules alone."""
    return [problem for check in rules_of(type(model)) if getattr(check, _WHOLE_MARK, False)
            for problem in _as_list(check(model))]


@functools.cache
def rules_of(model: type[BaseModel]) -> tuple[Rule, ...]:
    """The rules of a model class, its bases' first, each once."""
    found: dict[str, Rule] = {}
    for klass in reversed(model.__mro__):
        for name, attribute in vars(klass).items():
            if getattr(attribute, _RULE_MARK, False):
                found.pop(name, None)
                found[name] = attribute
            elif name in found:
                # A plain method of the same name would silently drop the rule.
                raise TypeError(f"{klass.__qualname__}.{name} shadows the rule of that "
                                "name of a base class: rename one of them")
    return tuple(found.values())


def problems_of(model: BaseModel) -> list[SpecFieldError]:
    """Every problem the rules find in ``model`` and the models it holds (field names
    relative to ``model``; list items numbered from 1), nested models first."""
    return list(_problems(model, frozenset()))


def problems_despite(model: BaseModel, invalid: Collection[str]) -> list[SpecFieldError]:
    """The problems of the rules that read none of the ``invalid`` top-level fields of
    ``model`` (whose values there are stand-ins, not what the spec says)."""
    return list(_problems(model, frozenset(invalid)))


def _problems(model: BaseModel, invalid: frozenset[str]) -> Iterator[SpecFieldError]:
    for name, value in _held_models(model):
        if name.split(".", 1)[0] in invalid:
            continue
        for problem in _problems(value, frozenset()):
            yield _within(name, problem)
    subjects = _subjects(model, invalid)
    checks = rules_of(type(model))
    if subjects is None:
        yield from _without_consequences(model, [(check, _checked(check, model, invalid))
                                                 for check in checks])
        return
    whole = [check for check in checks if getattr(check, _WHOLE_MARK, False)]
    yield from _without_consequences(model, [(check, _checked(check, model, invalid))
                                             for check in whole])
    yield from _checked_in_each([check for check in checks if check not in whole], subjects,
                                invalid)


def _without_consequences(model: BaseModel, found: Sequence[tuple[Rule, list[SpecFieldError]]]
                          ) -> list[SpecFieldError]:
    """The problems rules found in ``model``, less those that follow from another's.

    A problem of a field given that should not be (a number of rows for a ball bearing, a
    pair of a type that does not pair, an angle out of range) causes every problem that
    goes away when that field is left out: another rule's demand for the double row's
    factors, the tables' factors of that angle. One cause, one line. Where two problems
    each go away without the other's field, both stay: neither is the cause.
    """
    problems = [(check, problem) for check, each in found for problem in each]
    if len(problems) < 2:
        return [problem for _, problem in problems]
    causes = {problem.field for _, problem in problems
              if "." not in problem.field and problem.field in _left_out_values(model)}
    follows: dict[int, set[str]] = {}
    for index, (check, problem) in enumerate(problems):
        follows[index] = {cause for cause in causes if cause != problem.field
                          and not _persists(check, model, problem, cause)}
    kept = []
    for index, (_, problem) in enumerate(problems):
        caused = any(problem.field not in follows[other] for other, (_, cause) in
                     enumerate(problems) if cause.field in follows[index])
        if not caused:
            kept.append(problem)
    return kept or [problem for _, problem in problems]


def _left_out_values(model: BaseModel) -> dict[str, Any]:
    """Each field of ``model`` that the spec gives and may leave out -> its value when left
    out."""
    fields = type(model).model_fields
    return {name: fields[name].get_default(call_default_factory=True)
            for name in model.model_fields_set if name in fields
            and not fields[name].is_required()}


def _persists(check: Rule, model: BaseModel, problem: SpecFieldError, field: str) -> bool:
    """Whether ``check`` still finds ``problem`` in ``model`` with ``field`` left out."""
    default = _left_out_values(model)[field]
    without = model.model_copy(update={field: default})
    object.__setattr__(without, "__pydantic_fields_set__", model.model_fields_set - {field})
    try:
        again = _as_list(check(without))
    except (TypeError, ValueError, AttributeError, ArithmeticError):
        return False  # the rule needs the field: its problem came of it
    return any((other.field, other.message) == (problem.field, problem.message)
               for other in again)


def _subjects(model: BaseModel, invalid: frozenset[str]
              ) -> Sequence[tuple[BaseModel, Renamer]] | None:
    """What a model's rules check in place of the model itself (``rule_subjects``, the
    bins of a duty cycle), or None: the model. Where the fields that make the subjects
    (``SUBJECT_FIELDS``) are invalid, or the subjects cannot be made, nothing: those
    rules would judge the spec by what it does not say."""
    make = getattr(model, "rule_subjects", None)
    if make is None:
        return None
    if invalid & set(getattr(model, "SUBJECT_FIELDS", ())):
        return []
    try:
        return make()  # type: ignore[no-any-return]
    except (TypeError, ValueError, AttributeError, ArithmeticError):
        return []


def _checked(check: Rule, model: BaseModel, invalid: frozenset[str]
             ) -> list[SpecFieldError]:
    """The problems one rule finds in ``model``; with ``invalid`` fields, only if the
    rule reads none of them."""
    if not invalid:
        return _as_list(check(model))
    reads: set[str] = set()
    try:
        problem = check(_ReadRecorder(model, reads))
    except (TypeError, ValueError, AttributeError, ArithmeticError):
        return []  # a stand-in value the rule cannot use: its fields are invalid
    return [] if reads & invalid else _as_list(problem)


def _checked_in_each(checks: Sequence[Rule], subjects: Sequence[tuple[BaseModel, Renamer]],
                     invalid: frozenset[str]) -> Iterator[SpecFieldError]:
    """The rules' problems in each of a spec's subjects (the bins of a duty cycle): those
    every subject has once, as the spec's, the others each as its subject's."""
    found = [(rename, _without_consequences(
        subject, [(check, _checked(check, subject, invalid)) for check in checks]))
        for subject, rename in subjects]
    keys = [{(problem.field, problem.message) for problem in problems} for _, problems in found]
    common = set.intersection(*keys) if keys else set()
    said: set[tuple[str, str]] = set()
    for rename, problems in found:
        for problem in problems:
            named = rename(problem, (problem.field, problem.message) in common)
            if (named.field, named.message) not in said:
                said.add((named.field, named.message))
                yield named


def _held_models(model: BaseModel) -> Iterator[tuple[str, BaseModel]]:
    """(dotted name, model) of every spec model a field of ``model`` holds."""
    for name in type(model).model_fields:
        value = getattr(model, name)
        if isinstance(value, BaseModel):
            yield name, value
        elif isinstance(value, list):
            for index, item in enumerate(value, 1):
                if isinstance(item, BaseModel):
                    yield f"{name}.{index}", item


def own_problems(model: BaseModel) -> list[SpecFieldError]:
    """The problems of ``model``'s own rules, without those of the models it holds (nor
    those that follow from another, see :func:`_without_consequences`)."""
    return _without_consequences(model, [(check, _as_list(check(model)))
                                         for check in rules_of(type(model))])


def _as_list(found: SpecFieldError | list[SpecFieldError] | None) -> list[SpecFieldError]:
    return [] if found is None else found if isinstance(found, list) else [found]


def _within(prefix: str, problem: SpecFieldError) -> SpecFieldError:
    def joined(name: str | None) -> str | None:
        return None if name is None else f"{prefix}.{name}" if name else prefix

    return SpecFieldError(joined(problem.field) or prefix, problem.message,
                          at=joined(problem.at))


class _ReadRecorder:
    """Stands for a model while a rule runs, and records which of its fields the rule
    reads. Properties and methods of the model run with the recorder as ``self``, so
    what they read is recorded too."""

    def __init__(self, model: BaseModel, reads: set[str]) -> None:
        object.__setattr__(self, "_model", model)
        object.__setattr__(self, "_reads", reads)

    def __getattr__(self, name: str) -> Any:
        model = self._model
        if name in type(model).model_fields:
            self._reads.add(name)
            return getattr(model, name)
        attribute = inspect.getattr_static(type(model), name, None)
        if isinstance(attribute, property) and attribute.fget is not None:
            return attribute.fget(self)
        if inspect.isfunction(attribute):
            return types.MethodType(attribute, self)
        return getattr(model, name)
