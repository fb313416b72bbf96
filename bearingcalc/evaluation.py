"""From a YAML document to checked results: the one path every command takes.

``load_spec_file`` reads a file into documents; ``parse_document`` validates one
against its kind's model; ``evaluate_document`` solves it and judges it against
its limits. Errors come out as :class:`SpecError` with file, line and field.
"""

from __future__ import annotations

import functools
import math
import re
import sys
import traceback
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ValidationError

from bearingcalc.catalogue.fill import fill as fill_from_catalogue
from bearingcalc.core.common import DerivedTest
from bearingcalc.errors import SpecError, SpecFieldError
from bearingcalc.kinds import KINDS, Kind, bin_column, unknown_kind
from bearingcalc.models.base import Spec, nested_model
from bearingcalc.models.field_path import FieldPath, is_list_field
from bearingcalc.models.rules import problems_despite
from bearingcalc.models.yaml_loader import (
    Document,
    load_documents,
)
from bearingcalc.verdicts import Verdict, judge
from bearingcalc.wording import closest, did_you_mean, plural


@dataclass
class Evaluation:
    """The solved results of one valid spec, in SI units."""

    source: str
    kind: str
    name: str
    results: dict[str, float | None]      # None: unbounded (see warnings)
    units: dict[str, str]
    margins: dict[str, float]
    warnings: list[str] = field(default_factory=list)
    #: names of the rows of the kind's tables of results (a duty cycle's bins)
    row_names: dict[str, str] = field(default_factory=dict)
    #: every limit judged, the worst first
    verdicts: list[Verdict] = field(default_factory=list)
    #: the catalogue row of each bearing taken from one: ``catalogue_source`` (or
    #: ``pinion_bearing_1_catalogue_source``) -> designation, maker and source
    sources: dict[str, str] = field(default_factory=dict)

    @property
    def within_limits(self) -> bool:
        return all(margin >= 0 for margin in self.margins.values())

    @property
    def violations(self) -> list[str]:
        """A line per limit broken, the worst first, in engineering terms."""
        from bearingcalc.reports.formatting import verdict_line

        named = {verdict.key for verdict in self.verdicts}
        return [verdict_line(verdict) for verdict in self.verdicts if not verdict.passed] + [
            f"{key} is {value:.4g} (below 0)" for key, value in self.margins.items()
            if value < 0 and key not in named]


def parse_document(document: Document, *, rules: bool = True) -> tuple[Kind, Spec]:
    """Validate one document against the model of its ``kind`` (its fields only, without
    the cross-field rules, where ``rules`` is False)."""
    data = document.data
    if not isinstance(data, dict):
        got = "nothing" if data is None else f"a {type(data).__name__}"
        raise document.error(f"a spec is a mapping of keys (kind: thrust-bearing, ...), got {got}")
    kind_name = data.get("kind")
    if kind_name is None:
        raise document.error(f"missing key 'kind': one of {', '.join(KINDS)}", field="kind")
    kind = KINDS.get(kind_name) if isinstance(kind_name, str) else None
    if kind is None:
        raise document.error(unknown_kind(kind_name), field="kind")
    data, catalogue = fill_from_catalogue(data, kind.model.CATALOGUE_PLACES, document.path,
                                          lambda message, field: document.error(message,
                                                                                field=field))
    try:
        spec = kind.model.model_validate(data, context=None if rules else {"rules": False})
    except ValidationError as exc:
        errors = [_one_problem(document, kind.model, problem)
                  for problem in _typos_for_missing(kind.model, exc.errors(include_url=False))]
        # A hinted unknown key (bevel-gears' 'speed') already says what its rule would.
        said = {field for key, (_, fields) in getattr(kind.model, "UNKNOWN_KEY_HINTS",
                                                      {}).items() if key in data
                for field in fields}
        errors += [_rule_error(document, problem)
                   for problem in _rule_problems_despite(kind.model, data, exc)
                   if problem.field not in said]
        raise _in_line_order(document, errors) from None
    except SpecFieldError as problem:
        errors = [_rule_error(document, each) for each in (problem, *problem.more)]
        raise _in_line_order(document, errors) from None
    if catalogue.rows:
        spec._catalogue_sources = catalogue.sources()
        spec._catalogue_notes = catalogue.notes
    elif "catalogue" in data:
        raise document.error("no bearing names a designation, so the catalogue is not read: "
                             "give a bearing's designation, like designation: 6205, or leave "
                             "catalogue out", field="catalogue")
    return kind, spec


def _rule_error(document: Document, problem: SpecFieldError) -> SpecError:
    """A rule's problem at the line of its field, or of the key it belongs to when the
    field is not in the spec (a missing key)."""
    key_path = FieldPath.parse(problem.field).parts
    if problem.at is not None and key_path not in document.lines:
        key_path = FieldPath.parse(problem.at).parts
    return document.error(problem.message, field=problem.field, key_path=key_path)


def _in_line_order(document: Document, errors: list[SpecError]) -> SpecError:
    """The first error of a spec, with the others in its ``more``, all in line order."""
    errors.sort(key=lambda error: error.line or 0)
    errors[0].more = errors[1:]
    return errors[0]


def _rule_problems_despite(model: type[Spec], data: dict[str, Any],
                           exc: ValidationError) -> list[SpecFieldError]:
    """The problems of the spec's cross-field rules that read only valid fields.

    The invalid top-level fields are given stand-ins (their default, their schema's
    example, an empty list or group) so that the model can be built; rules that read
    them are not run. When no stand-in serves, no rule runs: the field errors come first.
    """
    invalid = {str(error["loc"][0]) for error in exc.errors() if error["loc"]}
    # A field that an unknown key is a typo of: the spec gives it, under another name.
    invalid |= {meant for error in exc.errors() if error["type"] == "extra_forbidden"
                and len(error["loc"]) == 1
                and (meant := closest(str(error["loc"][0]), model.model_fields))}
    stand_in = {key: value for key, value in data.items() if key not in invalid}
    for name in invalid & set(model.model_fields):
        info = model.model_fields[name]
        if info.is_required():
            example = _example(model, (name,))
            stand_in[name] = (example if example is not None else [] if is_list_field(info)
                              else {})
    try:
        partial = model.model_validate(stand_in, context={"rules": False})
    except (ValidationError, SpecFieldError):
        return []
    return problems_despite(partial, invalid)


def _typos_for_missing(model: type[Spec], errors: list[Any]) -> list[Any]:
    """pydantic's errors, less a required key's 'missing' where an unknown key beside it
    is a typo of it: the typo is the one cause, said at its line."""
    meant = set()
    for error in errors:
        loc = tuple(error["loc"])
        if error["type"] == "extra_forbidden" and loc:
            parent = _model_at(model, tuple(str(part) for part in loc[:-1]))
            close = closest(str(loc[-1]), parent.model_fields) if parent else None
            if close is not None:
                meant.add((*loc[:-1], close))
    return [error for error in errors
            if not (error["type"] == "missing" and tuple(error["loc"]) in meant)]


def evaluate_documents(documents: Sequence[Document]) -> list[Evaluation | SpecError]:
    """Evaluate many documents: each valid one solved, each bad one refused with its error.

    Specs of the same kind that give the same inputs are stacked into arrays and
    solved in one vectorised call, so a batch costs little more than its parsing.
    """
    outcomes: list[Evaluation | SpecError | None] = [None] * len(documents)
    groups: dict[tuple[str, tuple[Any, ...]], list[tuple[int, Spec, dict[str, Any]]]] = {}
    for index, document in enumerate(documents):
        try:
            kind, spec = parse_document(document)
            inputs = spec.solver_inputs()
        except SpecError as error:
            outcomes[index] = error
            continue
        except Exception as exc:  # one spec's surprise never costs the others their report
            outcomes[index] = _internal_error(document, exc)
            continue
        # Specs solved together must give the same inputs and the same words (a bearing
        # type): which results exist depends on both.
        groups.setdefault((kind.name, _layout(inputs)), []).append((index, spec, inputs))
    for (kind_name, _), members in groups.items():
        kind = KINDS[kind_name]
        try:
            _solve_group(documents, kind, members, outcomes)
        except Exception:
            # Solve them one by one, so only the spec at fault is refused.
            for member in members:
                try:
                    _solve_group(documents, kind, [member], outcomes)
                except Exception as exc:
                    outcomes[member[0]] = _internal_error(documents[member[0]], exc)
    return outcomes  # type: ignore[return-value]


def _solve_group(documents: Sequence[Document], kind: Kind,
                 members: list[tuple[int, Spec, dict[str, Any]]],
                 outcomes: list[Evaluation | SpecError | None]) -> None:
    """Solve specs of one kind with the same inputs given in one vectorised call."""
    stacked = _stacked([member[2] for member in members])
    raw, status, flags = kind.evaluate_with_warnings(stacked)
    columns = {key: values.tolist() for key, values in raw.items()}
    flagged = {key: np.asarray(values, dtype=bool).tolist() for key, values in flags.items()}
    codes = status.tolist()
    for row, (index, spec, _) in enumerate(members):
        values = {key: column[row] for key, column in columns.items()}
        raised = [kind.warnings[key] for key, column in flagged.items() if column[row]]
        try:
            outcomes[index] = _judge(documents[index], kind, spec, values, codes[row], raised)
        except SpecError as error:
            outcomes[index] = error


def _layout(inputs: Any) -> Any:
    """What must agree for specs to be solved together: the structure of their solver
    inputs, which inputs are given, and their words (a bearing type); not the numbers."""
    if isinstance(inputs, dict):
        return tuple((key, _layout(value)) for key, value in inputs.items())
    if isinstance(inputs, list):
        return tuple(_layout(item) for item in inputs)
    if isinstance(inputs, np.ndarray):  # a duty cycle's bins: their number must agree
        return np.shape(inputs)
    return inputs if inputs is None or isinstance(inputs, str) else float


def _stacked(inputs: list[Any]) -> Any:
    """Solver inputs of specs with one layout, each number replaced by an array of them."""
    first = inputs[0]
    if isinstance(first, dict):
        return {key: _stacked([each[key] for each in inputs]) for key in first}
    if isinstance(first, list):
        return [_stacked([each[i] for each in inputs]) for i in range(len(first))]
    if isinstance(first, np.ndarray):  # the bins stay on the first axis, the specs follow
        return np.stack(inputs, axis=-1)
    return first if first is None or isinstance(first, str) else np.array(inputs)


#: Whether an internal error's traceback goes to stderr where it is caught (the command
#: line's --debug); without, it is only the spec's one line, as the run goes on.
_TRACEBACKS: dict[str, bool] = {"shown": False}


def show_tracebacks(shown: bool) -> None:
    """Print (or not) the traceback of every internal error as it is caught."""
    _TRACEBACKS["shown"] = shown


def note_internal_error(exc: BaseException) -> None:
    """An exception caught so that one spec's failure does not stop the others: its
    traceback on stderr when :func:`show_tracebacks` asked for it."""
    if _TRACEBACKS["shown"]:
        traceback.print_exception(exc, file=sys.stderr)


def _internal_error(document: Document, exc: Exception) -> SpecError:
    note_internal_error(exc)
    return document.error(f"internal error ({type(exc).__name__}: {str(exc)[:200]}); "
                          "please report it with this spec")


def evaluate_document(document: Document) -> Evaluation:
    """Solve one document and judge it against its limits; raises SpecError."""
    (outcome,) = evaluate_documents([document])
    if isinstance(outcome, SpecError):
        raise outcome
    return outcome


def evaluate_file(path: str | Path) -> list[Evaluation | SpecError]:
    """Every document of a file (or the one ``file.yaml#N`` names), each evaluated or
    refused with its error."""
    try:
        documents = load_selected(path)
    except SpecError as error:
        return [error]
    return evaluate_documents(documents)


def load_selected(path: str | Path) -> list[Document]:
    """The documents of a spec file, or only the N-th for ``file.yaml#N`` (as reports
    name the documents of a multi-document file); raises SpecError."""
    text_path, _, index = str(path).rpartition("#")
    if not text_path or Path(str(path)).exists() or not Path(text_path).is_file():
        return load_documents(path)
    documents = load_documents(text_path)
    if not re.fullmatch(r"[0-9]{1,9}", index) or not 1 <= int(index) <= len(documents):
        raise SpecError(f"'#{index}' does not pick a document: write {text_path}#N with N "
                        f"from 1 to {len(documents)} (the file has "
                        f"{plural(len(documents), 'document')})", source=text_path)
    return [documents[int(index) - 1]]


def load_one_spec(path: str | Path) -> tuple[Kind, Spec, Document]:
    """The one spec of a file (``file.yaml#N`` picks a document of several); raises SpecError."""
    documents = load_selected(path)
    if len(documents) > 1:
        raise SpecError(f"the file holds {len(documents)} specs; pick one as "
                        f"{path}#1 .. #{len(documents)}", source=str(path))
    kind, spec = parse_document(documents[0])
    return kind, spec, documents[0]


def _judge(document: Document, kind: Kind, spec: Spec, raw: dict[str, float],
           code: int, raised: Sequence[str] = ()) -> Evaluation:
    """One spec's results from its solved values and status code."""
    if code:
        name, reason = kind.status_reasons[code]
        name = spec.field_as_written(name)
        written = FieldPath.parse(name).get(document.data)
        # A test of a quantity found from several fields: the field's value is not it.
        quoted = isinstance(written, (str, int, float)) and not isinstance(reason, DerivedTest)
        got = f", got {written}" if quoted else ""
        raise document.error(f"{reason}{got}", field=name)
    results: dict[str, float | None] = {}
    warnings: list[str] = [*spec.catalogue_notes(), *spec.warnings(), *raised]
    for key, value in raw.items():
        if math.isnan(value):
            raise document.error(f"{key} cannot be computed for this design; please report it")
        if math.isinf(value):
            warnings.append(f"{key} is unbounded (null in JSON): "
                            + ("the bin is at rest" if bin_column(key) is not None
                               else "the limit holds however far it goes"))
            results[key] = None
        else:
            results[key] = value
    units = {key: kind.results[key][0] for key in results}
    margins = {key: value for key in kind.margins
               if (value := results.get(key)) is not None}
    name = spec.name or _default_name(document)
    warnings += spec.result_notes(results)
    return Evaluation(document.source, kind.name, name, results, units, margins, warnings,
                      spec.row_names(), judge(kind, results, margins),
                      spec.catalogue_sources())


def _default_name(document: Document) -> str:
    stem = Path(document.path).stem
    return stem if document.source == document.path else f"{stem}#{document.index}"


def _one_problem(document: Document, model: type[Spec], error: Any) -> SpecError:
    key_path = tuple(error["loc"])
    loc = tuple(str(part) for part in key_path)
    dotted = str(FieldPath(key_path))
    error_type, message = error["type"], str(error["msg"])
    if error_type == "extra_forbidden":
        parent = _model_at(model, loc[:-1])
        known = list(parent.model_fields) if parent else []
        hint = getattr(parent, "UNKNOWN_KEY_HINTS", {}).get(loc[-1])
        if hint is not None:  # a key whose near names would each change the meaning
            message = f"unknown key '{loc[-1]}': {hint[0]}"
        else:
            message = f"unknown key '{loc[-1]}'{did_you_mean(loc[-1], known)}"
            if not did_you_mean(loc[-1], known):
                message += f"; allowed keys: {', '.join(k for k in known if k != 'kind')}"
    elif error_type == "missing":
        example = _example(model, loc)
        message = f"missing required key '{loc[-1]}'" + (f", e.g. {loc[-1]}: {example}"
                                                        if example else "")
    elif error_type in ("model_type", "model_attributes_type", "dict_type"):
        message = f"must be a mapping of keys, got {error.get('input')!r}"
    elif error_type == "literal_error":
        given = error.get("input")
        expected = str(error.get("ctx", {}).get("expected", ""))
        # Words are quoted in pydantic's list, numbers (a grade: 1, 2 or 3) are not.
        options = re.findall(r"'([^']*)'", expected) or re.findall(r"-?\d+(?:\.\d+)?",
                                                                  expected)
        hint = (" (a number: write it without quotes)" if str(given) in options
                else did_you_mean(str(given), options))
        message = f"must be one of {', '.join(options)}, got {given!r}{hint}"
    elif error_type in _OWN_WORDS:
        message = f"{_OWN_WORDS[error_type]}, got {error.get('input')!r}"
    else:
        message = message.removeprefix("Value error, ")
    return document.error(message, field=dotted, key_path=key_path)


#: The project's words for the type errors pydantic words its own way.
_OWN_WORDS = {
    "bool_type": "must be true or false",
    "bool_parsing": "must be true or false",
    "list_type": "must be a list (items on lines of their own, each after '- ', or [a, b])",
    "string_type": "must be text",
}


def _model_at(model: type[BaseModel], loc: tuple[str, ...]) -> type[BaseModel] | None:
    current: type[BaseModel] | None = model
    for part in loc:
        if part.isdigit() and current is not None:
            continue  # an item of a list field: the same model as the list's
        if current is None or part not in current.model_fields:
            return None
        current = nested_model(current.model_fields[part])
    return current


@functools.lru_cache(maxsize=32)
def _schema(model: type[BaseModel]) -> dict[str, Any]:
    return model.model_json_schema()


def _example(model: type[BaseModel], loc: tuple[str, ...]) -> str | None:
    parent = _model_at(model, loc[:-1])
    if parent is None:
        return None
    prop = _schema(parent).get("properties", {}).get(loc[-1], {})
    examples = prop.get("examples") or [
        option["examples"][0] for option in prop.get("anyOf", []) if option.get("examples")]
    return str(examples[0]) if examples else None

