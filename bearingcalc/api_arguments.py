"""The arguments of the Python API, checked before any work: a spec as a path, a YAML
text or a mapping of plain data, and the options of the studies. A wrong type or value
is an :class:`~bearingcalc.errors.ArgumentError` naming the function, the argument and
what it takes; a mapping's bad value is a :class:`~bearingcalc.errors.SpecError` at its
field, as a file's would be."""

from __future__ import annotations

import math
import numbers
import os
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from bearingcalc.errors import ArgumentError, SpecError
from bearingcalc.models.yaml_loader import MAX_DEPTH, MAX_FILE_BYTES, MAX_NODES, Document
from bearingcalc.wording import article, did_you_mean

#: What ``spec`` takes, for the messages.
SPEC_TAKES = "a spec file's path, a spec's YAML text (str) or a mapping"
#: The label a spec given as a mapping has in messages, where a file has its path.
MAPPING_SOURCE = "<mapping>"
TEXT_SOURCE = "<string>"


def spec_documents(spec: Any, function: str) -> list[Document]:
    """The documents of ``spec``: a path (``str`` or ``os.PathLike``; ``file.yaml#2``
    picks a document), a YAML text (a text of several lines, or one line with a colon
    that names no file) or a mapping of plain data."""
    from bearingcalc.evaluation import load_selected
    from bearingcalc.models.yaml_loader import load_documents

    if isinstance(spec, Mapping):
        return load_documents(MAPPING_SOURCE, _mapping_text(spec))
    if isinstance(spec, os.PathLike):
        return load_selected(os.fsdecode(os.fspath(spec)))
    if isinstance(spec, str):
        if not spec.strip():
            raise ArgumentError(function, "spec", f"an empty text is no spec; give {SPEC_TAKES}")
        if "\0" in spec:
            raise ArgumentError(function, "spec", "a text with a NUL character is neither a "
                                f"path nor YAML text; give {SPEC_TAKES}")
        if len(spec.encode("utf-8", "surrogatepass")) > MAX_FILE_BYTES:
            raise ArgumentError(function, "spec", f"a text of over {MAX_FILE_BYTES // 1024} KiB "
                                "is too large for a spec")
        if _names_a_file(spec):
            return load_selected(spec.strip())
        return load_documents(TEXT_SOURCE, spec)
    raise ArgumentError(function, "spec", f"{describe(spec)} is not a spec; give {SPEC_TAKES}"
                        + _hint(spec))


def _names_a_file(text: str) -> bool:
    """Whether a text is a path: one line that names a file, ends in .yaml or .yml (maybe
    with ``#N``), or has no colon (and so cannot be a YAML mapping)."""
    if "\n" in text or "\r" in text:
        return False
    stripped = text.strip()
    try:
        if Path(stripped).exists() or Path(stripped.rpartition("#")[0] or stripped).is_file():
            return True
    except (OSError, ValueError):  # a name too long, or with a NUL: not a file's
        return False
    file_part = stripped.rpartition("#")[0] if "#" in stripped else stripped
    return file_part.lower().endswith((".yaml", ".yml")) or ":" not in stripped


def describe(value: Any) -> str:
    """How a message names a value of the wrong type."""
    if value is None:
        return "None"
    if isinstance(value, bool):
        return f"{value} (true or false)"
    if isinstance(value, numbers.Number):
        return f"the number {value!r}"
    if isinstance(value, (bytes, bytearray)):
        return "bytes"
    if isinstance(value, (list, tuple, set, frozenset)):
        return f"a {type(value).__name__} of {len(value)}"
    return article(type(value).__name__)


def _hint(spec: Any) -> str:
    if isinstance(spec, (bytes, bytearray)):
        return " (decode the bytes first: spec.decode('utf-8'))"
    if isinstance(spec, (list, tuple)):
        return " (solve each one: [bearingcalc.solve(s) for s in specs])"
    return ""


def _mapping_text(spec: Mapping[Any, Any]) -> str:
    """A mapping spec as YAML text, so that it is read and located as a file is; a value
    YAML cannot hold plainly is a SpecError at its field."""
    import yaml

    counted = [0]
    plain = _plain(spec, (), set(), counted)
    return yaml.safe_dump(plain, sort_keys=False, allow_unicode=True)


def _plain(value: Any, path: tuple[str, ...], open_: set[int], counted: list[int]) -> Any:
    """``value`` as plain YAML data (numpy numbers as Python's); refuses what a spec file
    could not hold, at its dotted field (list items from 1)."""
    counted[0] += 1
    if counted[0] > MAX_NODES:
        raise _at(path, f"more than {MAX_NODES} values: a spec is smaller")
    if value is None or isinstance(value, (str, bool)):
        return value
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, (Mapping, list, tuple)):
        if len(path) >= MAX_DEPTH:
            raise _at(path, f"nested too deeply: specs nest at most {MAX_DEPTH} levels")
        if id(value) in open_:
            raise _at(path, "holds itself: a spec is a tree of values")
        open_.add(id(value))
        try:
            if isinstance(value, Mapping):
                out = {}
                for key, item in value.items():
                    if not isinstance(key, str):
                        raise _at(path, f"a key must be a field's name (text), got "
                                  f"{describe(key)}")
                    out[key] = _plain(item, (*path, key), open_, counted)
                return out
            return [_plain(item, (*path, str(i)), open_, counted)
                    for i, item in enumerate(value, 1)]
        finally:
            open_.discard(id(value))
    raise _at(path, f"{describe(value)} is not a value a spec holds: write text ('12.7 mm'), "
              "a number, true or false, a list or a mapping")


def _at(path: tuple[str, ...], message: str) -> SpecError:
    return SpecError(message, source=MAPPING_SOURCE, field=".".join(path) or None)


def choice(value: Any, function: str, argument: str, choices: Iterable[str]) -> str:
    """``value`` if it is one of ``choices``."""
    options = tuple(choices)
    if not isinstance(value, str) or value not in options:
        shown = repr(value) if isinstance(value, str) else describe(value)
        typo = did_you_mean(value, options) if isinstance(value, str) else ""
        raise ArgumentError(function, argument, f"one of {', '.join(map(repr, options))}, "
                            f"got {shown}{typo}")
    return value


def names(value: Any, function: str, argument: str, what: str, example: str) -> list[str]:
    """A text (one name, or names separated by commas) or a sequence of texts, as a list
    without repeats."""
    if isinstance(value, str):
        given = [part.strip() for part in value.split(",")]
    elif isinstance(value, Iterable) and not isinstance(value, (Mapping, bytes, bytearray)):
        given = list(value)
    else:
        raise ArgumentError(function, argument, f"give {what} as a list of texts, like "
                            f"{example}, got {describe(value)}")
    wrong = [item for item in given if not isinstance(item, str)]
    if wrong:
        raise ArgumentError(function, argument, f"each of {what} is a text, like {example}, "
                            f"got {describe(wrong[0])}")
    return list(dict.fromkeys(item.strip() for item in given if item.strip()))


def whole_number(value: Any, function: str, argument: str, low: int,
                 high: int | None = None, example: str = "", why: str = "") -> int:
    """``value`` as an int from ``low`` to ``high`` (a float with no fraction, like
    1e5, counts); ``why`` says where the highest comes from."""
    span = f"from {low:,} to {high:,}{why}" if high is not None else f"of {low:,} or more"
    wanted = f"a whole number {span}" + (f", like {example}" if example else "")
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        shown = repr(value) if isinstance(value, str) else describe(value)
        raise ArgumentError(function, argument, f"{wanted}, got {shown}")
    if isinstance(value, numbers.Integral):
        number = int(value)
    elif math.isfinite(float(value)) and float(value).is_integer():
        number = int(float(value))
    else:
        raise ArgumentError(function, argument, f"{wanted}, got {float(value)!r}")
    if number < low or (high is not None and number > high):
        raise ArgumentError(function, argument, f"{wanted}, got {number:,}")
    return number


def unknown_result(function: str, argument: str, key: Any, kind: str,
                   known: Mapping[str, Any]) -> ArgumentError:
    """The error of ``key``, which is no result of ``known`` (a spec of ``kind``)."""
    if not isinstance(key, str):
        return ArgumentError(function, argument, f"a result's key is a text, like "
                             f"{next(iter(known))!r}, got {describe(key)}")
    return ArgumentError(function, argument, f"{key!r} is not a result of this {kind} spec"
                         f"{did_you_mean(key, known)}; choose from {', '.join(known)}")


#: The formats a chart is drawn in, by the file's suffix.
CHART_SUFFIXES = (".png", ".svg")


def chart_path(path: Any, function: str) -> Path:
    """A chart's ``path``: a .png or .svg file in a folder that exists."""
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentError(function, "path", f"a file's path ending in .png or .svg, or None "
                            f"for the SVG a notebook shows, got {describe(path)}")
    target = Path(path)
    if target.suffix.lower() not in CHART_SUFFIXES:
        raise ArgumentError(function, "path", f"{str(path)!r}: a chart is a .png or .svg file; "
                            "end the name in one of them")
    if target.is_dir() or not target.parent.is_dir():
        what = "is a folder" if target.is_dir() else "is in no folder that exists"
        raise ArgumentError(function, "path", f"{str(path)!r} {what}; give a file in an "
                            "existing folder")
    return target
