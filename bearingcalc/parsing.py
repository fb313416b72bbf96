"""A YAML document to a valid spec of its kind, or one line per cause.

``parse_document`` fills a spec's bearings from their catalogue rows and validates it
against its kind's model. Its problems are worded in the project's words, at the line
of their field, in line order, and a problem that follows from another is not said:
an unknown key that is a typo of a field stands for that field, so neither the rules
that read the field nor its 'missing required key' repeat it.
"""

from __future__ import annotations

import functools
import re
from typing import TYPE_CHECKING, Any

from pydantic import BaseModel, ValidationError

from bearingcalc.catalogue.places import names_a_designation
from bearingcalc.errors import SpecError, SpecFieldError
from bearingcalc.kinds import KINDS, Kind, unknown_kind
from bearingcalc.models.base import Spec, nested_model, spec_errors
from bearingcalc.models.field_path import FieldPath, is_list_field
from bearingcalc.models.rules import problems_despite
from bearingcalc.models.yaml_loader import Document
from bearingcalc.wording import closest, did_you_mean

if TYPE_CHECKING:
    from bearingcalc.catalogue.fill import CatalogueUse


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
    data, catalogue = _filled(document, kind, data)
    try:
        spec = kind.model.model_validate(data, context=None if rules else {"rules": False})
    except ValidationError as exc:
        errors = [_one_problem(document, kind.model, problem)
                  for problem in _typos_for_missing(kind.model, spec_errors(exc))]
        # A hinted unknown key (bevel-gears' 'speed') already says what its rule would.
        said = {field for key, (_, fields) in getattr(kind.model, "UNKNOWN_KEY_HINTS",
                                                      {}).items() if key in data
                for field in fields}
        errors += [_rule_error(document, problem)
                   for problem in _rule_problems_despite(kind.model, data, exc)
                   if problem.field not in said]
        raise _in_line_order(document, _at_catalogue_rows(document, errors, catalogue)
                             ) from None
    except SpecFieldError as problem:
        errors = [_rule_error(document, each) for each in (problem, *problem.more)]
        raise _in_line_order(document, _at_catalogue_rows(document, errors, catalogue)
                             ) from None
    if catalogue is not None and catalogue.rows:
        spec._catalogue_sources = catalogue.sources()
        spec._catalogue_notes = catalogue.notes
    elif "catalogue" in data:
        raise document.error("no bearing names a designation, so the catalogue is not read: "
                             "give a bearing's designation, like designation: 6205, or leave "
                             "catalogue out", field="catalogue")
    return kind, spec


def _filled(document: Document, kind: Kind, data: dict[str, Any]
            ) -> tuple[dict[str, Any], CatalogueUse | None]:
    """``data`` with its bearings filled from their catalogue rows, and what the
    catalogue gave; None where no bearing names a designation (no catalogue is read)."""
    if not names_a_designation(data, kind.model.CATALOGUE_PLACES):
        return data, None
    from bearingcalc.catalogue.fill import fill

    try:
        return fill(data, kind.model.CATALOGUE_PLACES, document.path,
                    lambda message, field: document.error(message, field=field))
    except SpecError:
        # 'catalog: bearings.csv' leaves the designation without its catalogue: the typo
        # is the one cause, said at its line.
        typos = _typo_problems(document, kind.model, data)
        if typos:
            raise _in_line_order(document, typos) from None
        raise


def _at_catalogue_rows(document: Document, errors: list[SpecError],
                       catalogue: CatalogueUse | None) -> list[SpecError]:
    """``errors``, each of a value the catalogue filled (which the spec does not hold)
    said at the bearing's designation, with the catalogue's file, row line and column."""
    if catalogue is None:
        return errors
    out = []
    for error in errors:
        where = catalogue.filled.get(error.field or "")
        if where is None:
            out.append(error)
            continue
        # at the spec's catalogue: where it names one, as the catalogue's other problems
        field = "catalogue" if "catalogue" in document.data else where.designation
        out.append(document.error(where.said(error.message), field=field))
    return out


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
    invalid = {str(error["loc"][0]) for error in spec_errors(exc) if error["loc"]}
    # A field that an unknown key is a typo of: the spec gives it, under another name.
    invalid |= {meant for error in spec_errors(exc) if error["type"] == "extra_forbidden"
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


def _typo_problems(document: Document, model: type[Spec], data: dict[str, Any]
                   ) -> list[SpecError]:
    """The spec's unknown keys that are typos of a field, each as its one line."""
    try:
        model.model_validate(data, context={"rules": False})
    except ValidationError as exc:
        return [_one_problem(document, model, error)
                for error in spec_errors(exc)
                if error["type"] == "extra_forbidden" and error["loc"]
                and (_near_field(model, tuple(str(part) for part in error["loc"]))
                     or _misplaced(model, tuple(str(part) for part in error["loc"])))]
    except SpecFieldError:
        pass
    return []


def _misplaced(model: type[Spec], loc: tuple[str, ...]) -> bool:
    """Whether the unknown key at ``loc`` is a key of the spec's top level, written in a
    group or list item (a drive bearing's ``catalogue``)."""
    return len(loc) > 1 and loc[-1] in model.model_fields


def _near_field(model: type[Spec], loc: tuple[str, ...]) -> str | None:
    """The field of the model at ``loc[:-1]`` that the unknown key ``loc[-1]`` is a
    typo of, if any."""
    parent = _model_at(model, loc[:-1])
    return closest(loc[-1], parent.model_fields) if parent else None


def _typos_for_missing(model: type[Spec], errors: list[Any]) -> list[Any]:
    """pydantic's errors, less a required key's 'missing' where an unknown key beside it
    is a typo of it: the typo is the one cause, said at its line."""
    meant = set()
    for error in errors:
        loc = tuple(error["loc"])
        if error["type"] == "extra_forbidden" and loc:
            close = _near_field(model, tuple(str(part) for part in loc))
            if close is not None:
                meant.add((*loc[:-1], close))
    return [error for error in errors
            if not (error["type"] == "missing" and tuple(error["loc"]) in meant)]


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
                if _misplaced(model, loc):
                    message += (f" here: {loc[-1]} is a key of the spec's top level, for "
                                "the whole spec")
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

