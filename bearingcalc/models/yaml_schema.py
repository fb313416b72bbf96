"""The YAML 1.2 core schema of spec files: which plain scalars are null, booleans, whole
and real numbers, and their values (PyYAML's own resolver follows YAML 1.1)."""

from __future__ import annotations

import math
import re
from typing import Any, ClassVar

import yaml

from bearingcalc.number_grammar import NUMBER

_BASE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class _Yaml12Loader(_BASE_LOADER):  # type: ignore[misc, valid-type]
    """PyYAML's parser with the YAML 1.2 core schema's plain-scalar rules.

    PyYAML resolves plain scalars by YAML 1.1 rules: ``1e-2`` is a string, ``014``
    octal, ``1:00`` sexagesimal, ``2024-01-01`` a date and ``<<`` a merge key.
    Editors and check-jsonschema follow YAML 1.2, so specs are read the same way.
    """

    yaml_implicit_resolvers: ClassVar[dict[str | None, list[tuple[str, re.Pattern[str]]]]] = {}


# The YAML 1.2 core schema (https://yaml.org/spec/1.2.2/#1023-core-schema), tag by tag.
_CORE_SCHEMA = {
    "tag:yaml.org,2002:null": (r"^(?:~|null|Null|NULL|)$", [*"~nN", ""]),
    "tag:yaml.org,2002:bool": (r"^(?:true|True|TRUE|false|False|FALSE)$", list("tTfF")),
    "tag:yaml.org,2002:int": (r"^(?:[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+)$",
                              list("-+0123456789")),
    "tag:yaml.org,2002:float": (
        rf"^(?:{NUMBER}|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$", list("-+.0123456789")),
}
for _tag, (_pattern, _first) in _CORE_SCHEMA.items():
    _Yaml12Loader.add_implicit_resolver(_tag, re.compile(_pattern), _first)
_LOADER = _Yaml12Loader
_PLAIN_TAGS = {
    "tag:yaml.org,2002:str", "tag:yaml.org,2002:int", "tag:yaml.org,2002:float",
    "tag:yaml.org,2002:bool", "tag:yaml.org,2002:null",
}
_MAP_TAG = "tag:yaml.org,2002:map"
_SEQ_TAG = "tag:yaml.org,2002:seq"


def plain_scalar(text: str) -> Any:
    """The value of ``text`` written as a plain (unquoted) YAML scalar in a spec: None,
    true or false, an int, a float, or the text itself (``'90 %'``, ``'1 kN'``)."""
    stripped = text.strip()
    for tag, (pattern, _) in _CORE_SCHEMA.items():
        if re.match(pattern, stripped) and stripped:
            return _core_value(tag, stripped)
    return stripped


def _core_value(tag: str, text: str) -> Any:
    """The value of a scalar by the YAML 1.2 core schema (explicit tags included)."""
    if tag.endswith(":str"):
        return text
    if tag.endswith(":null"):
        if text not in ("~", "null", "Null", "NULL", ""):
            raise ValueError(text)
        return None
    if tag.endswith(":bool"):
        lowered = text.lower()
        if lowered not in ("true", "false"):
            raise ValueError(text)
        return lowered == "true"
    if tag.endswith(":int"):
        if text.startswith(("0o", "0x")):
            return int(text[2:], 8 if text[1] == "o" else 16)
        if not re.fullmatch(r"[-+]?[0-9]+", text):
            raise ValueError(text)
        # Decimal, whatever the leading zeros: YAML 1.2 has no implicit octal.
        return int(text, 10)
    special = {".inf": math.inf, "+.inf": math.inf, "-.inf": -math.inf, ".nan": math.nan}
    if text.lower() in special:
        return special[text.lower()]
    if not re.fullmatch(NUMBER, text):
        raise ValueError(text)
    return float(text)
