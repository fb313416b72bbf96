"""Reading spec files: safe YAML with the line of every key, and hard limits.

Only plain YAML data is accepted: mappings, sequences and scalars with the
standard tags. A tag such as ``!!python/object`` is refused before anything is
constructed, so no spec can run code. Files over ``MAX_FILE_BYTES``, documents
that expand (through aliases) to more than ``MAX_NODES`` nodes, and nesting
deeper than ``MAX_DEPTH`` are refused, so a hostile file cannot hang or exhaust
memory.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from bearingcalc.errors import SpecError
from bearingcalc.models.field_path import FieldPath
from bearingcalc.models.spec_files import MAX_FILE_BYTES, read_spec_text, wide_encoding
from bearingcalc.models.yaml_schema import (
    _LOADER,
    _MAP_TAG,
    _PLAIN_TAGS,
    _SEQ_TAG,
    _core_value,
    plain_scalar,
)

MAX_NODES = 10_000
MAX_DEPTH = 20

__all__ = ["MAX_DEPTH", "MAX_FILE_BYTES", "MAX_NODES", "Document", "is_spec_file",
           "load_documents", "plain_scalar", "read_spec_text", "wide_encoding"]

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
        self._new_document(1)

    def _new_document(self, start_line: int) -> None:
        """Start a document's tree afresh: no open container, anchor, key line or value."""
        self.stack: list[_Container] = []
        self.anchors: dict[str, tuple[Any, int]] = {}
        self.lines: dict[KeyPath, int] = {}
        self.nodes = 0
        self.root: Any = None
        self.start_line = start_line

    def _fail(self, message: str, event: yaml.Event) -> SpecError:
        return SpecError(message, source=self.label, line=event.start_mark.line + 1)

    def documents(self) -> list[Document]:
        """Every document of the stream: its data and the line of each key."""
        documents: list[Document] = []
        while self.loader.check_event():
            event = self.loader.get_event()
            if isinstance(event, yaml.DocumentStartEvent):
                self._new_document(event.start_mark.line + 1)
            elif isinstance(event, yaml.DocumentEndEvent):
                documents.append(Document(source=self.label, path=self.label,
                                          index=len(documents) + 1, data=self.root,
                                          start_line=self.start_line, lines=self.lines))
            elif isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
                self._close(event)
            elif not isinstance(event, (yaml.StreamStartEvent, yaml.StreamEndEvent)):
                self._add(event)
        return documents

    def _close(self, event: yaml.Event) -> None:
        """A list or mapping ends (attached to its parent when it started): refused if it
        is a key, kept under its anchor with its size, or the document's root."""
        done = self.stack.pop()
        if done.key_start is not None:
            raise self._key_error(done.value, done.key_start, event)
        if done.anchor is not None:
            self.anchors[done.anchor] = (done.value, self.nodes - done.first_node + 1)
        if not self.stack:
            self.root = done.value

    def _add(self, event: Any) -> None:
        """A scalar, an alias (its anchor's value, counted at its anchor's size) or a list
        or mapping that starts: counted against the size limit, then attached."""
        if isinstance(event, yaml.AliasEvent):
            if event.anchor not in self.anchors:
                raise self._fail(f"unknown alias '*{event.anchor}'", event)
            value, size = self.anchors[event.anchor]
        else:
            size, value = 1, self._new_value(event)
        self.nodes += size
        if self.nodes > MAX_NODES:
            raise self._fail(f"document too large: more than {MAX_NODES} values "
                             "(YAML aliases count as copies)", event)
        if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
            self._open(value, event)
            return
        if isinstance(event, yaml.ScalarEvent) and event.anchor is not None:
            self.anchors[event.anchor] = (value, 1)
        if self.stack:
            self._attach(value, event)
        else:
            self.root = value

    def _new_value(self, event: Any) -> Any:
        """An empty mapping or list, or a scalar's value, once its tag is allowed."""
        if isinstance(event, yaml.MappingStartEvent):
            self._check_tag(event, _MAP_TAG)
            return {}
        if isinstance(event, yaml.SequenceStartEvent):
            self._check_tag(event, _SEQ_TAG)
            return []
        return self._scalar(event)

    def _open(self, value: Any, event: Any) -> None:
        """A list or mapping starts: attached to its parent and open for its values."""
        if len(self.stack) >= MAX_DEPTH:
            raise self._fail(_TOO_DEEP, event)
        parent_path = self.stack[-1].key_path if self.stack else ()
        key_path = _child_path(self.stack, parent_path)
        is_key = self._attach(value, event)
        self.stack.append(_Container(value, key_path, event.anchor, self.nodes))
        if is_key:  # refused at its end, when the whole key can be shown
            self.stack[-1].key_start = event

    def _attach(self, value: Any, event: yaml.Event) -> bool:
        """Put a value into the container on top of the stack; True where it is a
        mapping's key that is itself a list or mapping (refused once it is read)."""
        if not self.stack:
            return False
        parent = self.stack[-1]
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
            self.lines[(*parent.key_path, value)] = event.start_mark.line + 1
            return False
        parent.value[parent.pending_key] = value
        parent.pending_key = _NO_KEY
        return False

    def _key_error(self, value: Any, start: yaml.Event, end: yaml.Event) -> SpecError:
        """A key that is no plain name (null, a number, true or false, a list, a mapping,
        an alias to one), named as written."""
        written = _key_as_written(self.text, value, start, end)
        shown = written if len(written) <= 40 else f"{written[:37]}..."
        what = ("the key is empty" if written == "" and value is None
                else f"the key '{shown}' is {_kind_of(value)}")
        return self._fail(f"a key must be a plain name, like speed in 'speed: 1500 rpm'; "
                          f"{what}", start)

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


def _key_as_written(text: str, value: Any, start: yaml.Event, end: yaml.Event) -> str:
    """A key as the spec writes it: an alias by its name, a list or mapping in one line."""
    if isinstance(start, yaml.AliasEvent):
        return f"*{start.anchor}"
    if isinstance(start, yaml.ScalarEvent):
        return start.value
    written = " ".join(_written(text, start.start_mark, end.end_mark).split())
    if not written.startswith(("[", "{")):  # a block list or mapping: in one line
        written = yaml.safe_dump(value, default_flow_style=True, width=10**6).strip()
    return written


def _child_path(stack: list[_Container], parent_path: KeyPath) -> KeyPath:
    """The key path of a container that starts inside the one on top of ``stack``."""
    if not stack:
        return ()
    parent = stack[-1]
    if isinstance(parent.value, list):
        return (*parent_path, len(parent.value))
    return (*parent_path, parent.pending_key)


def _written(text: str, start: Any, end: Any) -> str:
    """The text between two marks, found by line and column (counted in characters
    by every YAML parser)."""
    lines = _LINE_BREAKS.split(text)
    if start.line >= len(lines):
        return ""
    if start.line == end.line:
        return lines[start.line][start.column:end.column]
    middle = lines[start.line + 1:end.line]
    last = lines[end.line][:end.column] if end.line < len(lines) else ""
    return "\n".join([lines[start.line][start.column:], *middle, last])


def is_spec_file(path: Path) -> bool:
    """Whether a path names a spec file by its suffix."""
    return path.suffix.lower() in (".yaml", ".yml")
