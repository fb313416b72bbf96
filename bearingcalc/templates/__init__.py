"""Commented template specs, one per kind (``{kind}.yaml``) and, where a kind has types
of its own template, one per type (``{kind}.{type}.yaml``)."""

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


def template_types(kind: str) -> list[str]:
    """The types with a template of ``kind``: the kind's own template's type first."""
    folder = resources.files(__name__)
    default = _default_type(folder.joinpath(f"{kind}.yaml").read_text("utf-8"))
    others = sorted(entry.name[len(kind) + 1:-len(".yaml")] for entry in folder.iterdir()
                    if entry.name.startswith(f"{kind}.") and entry.name.endswith(".yaml")
                    and entry.name != f"{kind}.yaml")
    return ([default] if default else []) + others


def _default_type(text: str) -> str | None:
    found = _TYPE_LINE.search(text)
    return found.group(1) if found else None
