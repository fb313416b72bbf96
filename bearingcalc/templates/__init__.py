"""Commented template specs, one per kind (``{kind}.yaml``); where a kind has types of
their own template, one per type (``{kind}.{type}.yaml``); and where it has methods
besides its default, one per method (``{kind}.method-{method}.yaml``)."""

from __future__ import annotations

import re
from importlib import resources

from bearingcalc.wording import did_you_mean

_TYPE_LINE = re.compile(r"^type:\s*([\w-]+)", re.MULTILINE)


def template_text(kind: str, type_name: str | None = None) -> str:
    """The template of ``kind``, or of its type ``type_name`` (the kind's own template
    where that is its type).

    Raises
    ------
    LookupError : the kind has no template of that type; the message names those it has.
    """
    folder = resources.files(__name__)
    default = folder.joinpath(f"{kind}.yaml").read_text("utf-8")
    if type_name is None or _default_type(default) == type_name:
        return default
    types = template_types(kind)
    if type_name not in types:
        raise LookupError(f"no {kind} template of type {type_name!r}"
                          f"{did_you_mean(type_name, types)}; templates: {', '.join(types)}")
    return folder.joinpath(f"{kind}.{type_name}.yaml").read_text("utf-8")


#: The stem of a method's template after the kind's name.
METHOD_PREFIX = "method-"


def method_template_text(kind: str, method: str) -> str:
    """The template of ``kind`` solved by ``method``.

    Raises
    ------
    LookupError : the kind has no template of that method; the message names those it has.
    """
    methods = template_methods(kind)
    if method not in methods:
        have = f"; templates: {', '.join(methods)}" if methods else ""
        raise LookupError(f"no {kind} template of method {method!r}"
                          f"{did_you_mean(method, methods)}{have}")
    return resources.files(__name__).joinpath(
        f"{kind}.{METHOD_PREFIX}{method}.yaml").read_text("utf-8")


def template_methods(kind: str) -> list[str]:
    """The methods with a template of ``kind`` besides its default."""
    stem = f"{kind}.{METHOD_PREFIX}"
    return sorted(entry.name[len(stem):-len(".yaml")]
                  for entry in resources.files(__name__).iterdir()
                  if entry.name.startswith(stem) and entry.name.endswith(".yaml"))


def template_types(kind: str) -> list[str]:
    """The types with a template of ``kind``: the kind's own template's type first."""
    folder = resources.files(__name__)
    default = _default_type(folder.joinpath(f"{kind}.yaml").read_text("utf-8"))
    others = sorted(entry.name[len(kind) + 1:-len(".yaml")] for entry in folder.iterdir()
                    if entry.name.startswith(f"{kind}.") and entry.name.endswith(".yaml")
                    and entry.name != f"{kind}.yaml"
                    and not entry.name.startswith(f"{kind}.{METHOD_PREFIX}"))
    return ([default] if default else []) + others


def _default_type(text: str) -> str | None:
    found = _TYPE_LINE.search(text)
    return found.group(1) if found else None
