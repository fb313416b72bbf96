"""Reading spec files: safe YAML with the line of every key, and hard limits.

Only plain YAML data is accepted: mappings, sequences and scalars with the
standard tags. A tag such as ``!!python/object`` is refused before anything is
constructed, so no spec can run code. Files over ``MAX_FILE_BYTES``, documents
that expand (through aliases) to more than ``MAX_NODES`` nodes, and nesting
deeper than ``MAX_DEPTH`` are refused, so a hostile file cannot hang or exhaust
memory.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

import yaml

from bearingcalc.errors import SpecError
from bearingcalc.models.field_path import FieldPath
from bearingcalc.models.spec_files import MAX_FILE_BYTES, read_spec_text, wide_encoding
from bearingcalc.number_grammar import NUMBER

MAX_NODES = 10_000
MAX_DEPTH = 20

__all__ = ["MAX_DEPTH", "MAX_FILE_BYTES", "MAX_NODES", "Document", "is_spec_file",
           "load_documents", "plain_scalar", "read_spec_text", "wide_encoding"]

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

KeyPath = tuple[str | int, ...]


@dataclass
class Document:
    """One YAML document of a spec file, with the line of each key."""

    source: str                     # "specs/tb.yaml", or "specs/tb.yaml#2" in a multi-document file
    path: str
    index: int                      # 1-based position in the file
    data: Any
    start_line: int
    lines: dict[KeyPath, int] = field(default_factory=dict)

    def line_of(self, key_path: KeyPath) -> int:
        """Line of the deepest key of ``key_path`` that the document has."""
        for end in range(len(key_path), 0, -1):
            line = self.lines.get(key_path[:end])
            if line is not None:
                return line
        return self.start_line

    def error(self, message: str, field: str | None = None,
              key_path: KeyPath | None = None) -> SpecError:
        """A SpecError located at ``key_path`` (default: the dotted ``field``)."""
        if key_path is None:
            key_path = FieldPath.parse(field).parts if field else ()
        return SpecError(message, source=self.source, line=self.line_of(key_path), field=field)


_TOO_DEEP = f"nested too deeply: specs nest at most {MAX_DEPTH} levels"


def _flow_depth(text: str, end: int) -> int:
    """How many flow collections ([ or {) are open at ``end`` of ``text`` (quotes and
    comments aside: an estimate that is exact for the nesting attacks it is for)."""
    head = text[:end]
    return head.count("[") + head.count("{") - head.count("]") - head.count("}")


def load_documents(path: str | os.PathLike[str], text: str | None = None) -> list[Document]:
    """Every YAML document of a spec file, in order.

    Raises
    ------
    SpecError : the file cannot be read, is not YAML, holds no document, or
        breaks one of the limits above.
    """
    label = str(path)
    if text is None:
        text = read_spec_text(path)
    loader = _LOADER(text)
    try:
        documents = _Builder(loader, label, text).documents()
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark is not None else None
        if mark is not None and _flow_depth(text, mark.index) > MAX_DEPTH:
            # Newer YAML parsers stop deep nesting themselves, in words of their own.
            raise SpecError(_TOO_DEEP, source=label, line=line) from None
        problem = exc.problem or exc.context or "malformed YAML"
        raise SpecError(f"malformed YAML: {problem}", source=label, line=line) from None
    except yaml.YAMLError as exc:
        raise SpecError(f"malformed YAML: {exc}", source=label) from None
    finally:
        loader.dispose()
    if not documents:
        raise SpecError("empty file: a spec is a YAML mapping that starts with "
                        "'kind: thrust-bearing' (see 'specs/')", source=label)
    if len(documents) > 1:
        for document in documents:
            document.source = f"{label}#{document.index}"
    return documents


class _Container:
    """A mapping or sequence under construction."""

    __slots__ = ("anchor", "first_node", "key_path", "key_start", "pending_key", "value")

    def __init__(self, value: Any, key_path: KeyPath, anchor: str | None, first_node: int) -> None:
        self.value = value
        self.key_path = key_path
        self.pending_key: Any = _NO_KEY
        self.anchor = anchor
        self.first_node = first_node
        #: where it starts, for a list or mapping written as a mapping's key
        self.key_start: Any = None


_NO_KEY = object()
#: Line breaks as YAML counts them.
_LINE_BREAKS = re.compile("\r\n|[\r\n\x85\u2028\u2029]")


def _kind_of(value: Any) -> str:
    """What a key that is no name is, for a message."""
    if value is None:
        return "null (no name)"
    if isinstance(value, bool):
        return "true or false (quote a name that reads so)"
    if isinstance(value, (int, float)):
        return "a number"
    if isinstance(value, list):
        return "a list"
    return "a mapping"


class _Builder:
    """Builds plain Python data straight from parser events, recording key lines.

    Working on events rather than composed nodes keeps nesting out of the C
    stack (libyaml's composer recurses and crashes on very deep input), and
    lets an alias reuse its anchor's object while counting its size, so an
    alias bomb is refused without being expanded.
    """

    def __init__(self, loader: Any, label: str, text: str = "") -> None:
        self.loader = loader
        self.label = label
        self.text = text

    def _fail(self, message: str, event: yaml.Event) -> SpecError:
        return SpecError(message, source=self.label, line=event.start_mark.line + 1)

    def documents(self) -> list[Document]:
        loader = self.loader
        documents: list[Document] = []
        stack: list[_Container] = []
        anchors: dict[str, tuple[Any, int]] = {}
        lines: dict[KeyPath, int] = {}
        nodes = 0
        start_line = 1
        root: Any = None
        while loader.check_event():
            event = loader.get_event()
            if isinstance(event, yaml.DocumentStartEvent):
                stack, anchors, lines, nodes, root = [], {}, {}, 0, None
                start_line = event.start_mark.line + 1
                continue
            if isinstance(event, yaml.DocumentEndEvent):
                documents.append(Document(source=self.label, path=self.label,
                                          index=len(documents) + 1, data=root,
                                          start_line=start_line, lines=lines))
                continue
            if isinstance(event, (yaml.StreamStartEvent, yaml.StreamEndEvent)):
                continue
            if isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
                done = stack.pop()
                if done.key_start is not None:
                    raise self._key_error(done.value, done.key_start, event)
                if done.anchor is not None:
                    anchors[done.anchor] = (done.value, nodes - done.first_node + 1)
                if not stack:
                    root = done.value
                continue  # attached to its parent when it started
            if isinstance(event, yaml.AliasEvent):
                if event.anchor not in anchors:
                    raise self._fail(f"unknown alias '*{event.anchor}'", event)
                value, size = anchors[event.anchor]
            else:
                size = 1
                parent_path = stack[-1].key_path if stack else ()
                if isinstance(event, yaml.MappingStartEvent):
                    self._check_tag(event, _MAP_TAG)
                    value = {}
                elif isinstance(event, yaml.SequenceStartEvent):
                    self._check_tag(event, _SEQ_TAG)
                    value = []
                else:
                    value = self._scalar(event)
            nodes += size
            if nodes > MAX_NODES:
                raise self._fail(f"document too large: more than {MAX_NODES} values "
                                 "(YAML aliases count as copies)", event)
            if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
                if len(stack) >= MAX_DEPTH:
                    raise self._fail(_TOO_DEEP,
                                     event)
                key_path = self._child_path(stack, parent_path)
                is_key = self._attach(stack, value, event, lines)
                stack.append(_Container(value, key_path, event.anchor, nodes))
                if is_key:  # refused at its end, when the whole key can be shown
                    stack[-1].key_start = event
                continue
            if isinstance(event, yaml.ScalarEvent) and event.anchor is not None:
                anchors[event.anchor] = (value, 1)
            if stack:
                self._attach(stack, value, event, lines)
            else:
                root = value
        return documents

    @staticmethod
    def _child_path(stack: list[_Container], parent_path: KeyPath) -> KeyPath:
        if not stack:
            return ()
        parent = stack[-1]
        if isinstance(parent.value, list):
            return (*parent_path, len(parent.value))
        return (*parent_path, parent.pending_key)

    def _attach(self, stack: list[_Container], value: Any, event: yaml.Event,
                lines: dict[KeyPath, int]) -> bool:
        """Put a value into the container on top of the stack; True where it is a
        mapping's key that is itself a list or mapping (refused once it is read)."""
        if not stack:
            return False
        parent = stack[-1]
        if isinstance(parent.value, list):
            parent.value.append(value)
            return False
        if parent.pending_key is _NO_KEY:
            if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
                return True
            if not isinstance(value, str):
                raise self._key_error(value, event, event)
            if value == "<<":
                raise self._fail("YAML merge keys ('<<') are not supported in specs", event)
            if value in parent.value:
                raise self._fail(f"duplicate key '{value}'", event)
            parent.pending_key = value
            lines[(*parent.key_path, value)] = event.start_mark.line + 1
            return False
        parent.value[parent.pending_key] = value
        parent.pending_key = _NO_KEY
        return False

    def _key_error(self, value: Any, start: yaml.Event, end: yaml.Event) -> SpecError:
        """A key that is no plain name (null, a number, true or false, a list, a mapping,
        an alias to one), named as written."""
        if isinstance(start, yaml.AliasEvent):
            written = f"*{start.anchor}"
        elif isinstance(start, yaml.ScalarEvent):
            written = start.value
        else:
            written = " ".join(self._written(start.start_mark, end.end_mark).split())
            if not written.startswith(("[", "{")):  # a block list or mapping: in one line
                written = yaml.safe_dump(value, default_flow_style=True, width=10**6).strip()
        shown = written if len(written) <= 40 else f"{written[:37]}..."
        what = ("the key is empty" if written == "" and value is None
                else f"the key '{shown}' is {_kind_of(value)}")
        return self._fail(f"a key must be a plain name, like speed in 'speed: 1500 rpm'; "
                          f"{what}", start)

    def _written(self, start: Any, end: Any) -> str:
        """The text between two marks, found by line and column (counted in characters
        by every YAML parser)."""
        lines = _LINE_BREAKS.split(self.text)
        if start.line >= len(lines):
            return ""
        if start.line == end.line:
            return lines[start.line][start.column:end.column]
        middle = lines[start.line + 1:end.line]
        last = lines[end.line][:end.column] if end.line < len(lines) else ""
        return "\n".join([lines[start.line][start.column:], *middle, last])

    def _check_tag(self, event: Any, default_tag: str) -> None:
        if event.tag is not None and event.tag not in (default_tag, "!"):
            raise self._fail(f"YAML tag '{event.tag}' is not allowed in a spec; "
                             "write plain values", event)

    def _scalar(self, event: Any) -> Any:
        tag = event.tag
        if tag is None or tag == "!":
            tag = self.loader.resolve(yaml.ScalarNode, event.value, event.implicit)
        if tag not in _PLAIN_TAGS:
            raise self._fail(f"YAML tag '{tag}' is not allowed in a spec; write plain values",
                             event)
        try:
            return _core_value(tag, event.value)
        except ValueError:
            shown = event.value if len(event.value) <= 40 else f"{event.value[:30]}…"
            raise self._fail(f"'{shown}' is not a valid {tag.rsplit(':', 1)[-1]}",
                             event) from None


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


def is_spec_file(path: Path) -> bool:
    """Whether a path names a spec file by its suffix."""
    return path.suffix.lower() in (".yaml", ".yml")
