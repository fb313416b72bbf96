"""The spec file reader: key lines, multi-document files, and hostile input."""

from __future__ import annotations

import pytest

from bearingcalc.errors import SpecError
from bearingcalc.models.yaml_loader import MAX_FILE_BYTES, load_documents


def write(tmp_path, text, name="spec.yaml"):
    path = tmp_path / name
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    return path


def refused(path) -> SpecError:
    with pytest.raises(SpecError) as info:
        load_documents(path)
    return info.value


def test_records_the_line_of_every_key(tmp_path):
    path = write(tmp_path, "# comment\nkind: thrust-bearing\nlimits:\n  max_spin_to_roll: 0.02\n")
    (document,) = load_documents(path)
    assert document.data == {"kind": "thrust-bearing", "limits": {"max_spin_to_roll": 0.02}}
    assert document.line_of(("limits", "max_spin_to_roll")) == 4
    assert document.line_of(("kind",)) == 2
    assert document.source == str(path)


def test_multi_document_files_number_their_documents(tmp_path):
    path = write(tmp_path, "a: 1\n---\nb: 2\n---\nc: 3\n")
    documents = load_documents(path)
    assert [d.source for d in documents] == [f"{path}#{i}" for i in (1, 2, 3)]
    assert documents[2].line_of(("c",)) == 5


def test_aliases_share_their_value(tmp_path):
    (document,) = load_documents(write(tmp_path, "a: &x {n: 1}\nb: *x\n"))
    assert document.data["b"] == {"n": 1}


@pytest.mark.parametrize(("content", "message"), [
    ("", "empty file"),
    ("a: [1\n", "malformed YAML"),
    ("a: 1\na: 2\n", "duplicate key 'a'"),
    ("a: !!python/object/apply:os.system ['echo owned']\n", "YAML tag"),
    ("!!python/object:builtins.dict\na: 1\n", "YAML tag"),
    ("a: !!binary aGVsbG8=\n", "YAML tag"),
    ("? [1, 2]\n: 3\n", "a key must be a plain name"),
    ("a: " + "[" * 5000 + "]" * 5000 + "\n", "nested too deeply"),
    (b"kind: x\xff\xfe\n", "not UTF-8"),
    (b"\x00\x01\x02binary", "binary file"),
])
def test_bad_files_are_refused_with_a_reason(tmp_path, content, message):
    assert message in str(refused(write(tmp_path, content)))


def test_python_tags_are_never_executed(tmp_path):
    marker = tmp_path / "owned"
    refused(write(tmp_path, f"a: !!python/object/apply:os.system ['touch {marker}']\n"))
    assert not marker.exists()


def test_alias_bomb_is_refused_without_expanding(tmp_path):
    lines = ["a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    for previous, name in zip("abcdefgh", "bcdefghi", strict=True):
        lines.append(f"{name}: &{name} [" + ", ".join([f"*{previous}"] * 9) + "]")
    assert "document too large" in str(refused(write(tmp_path, "\n".join(lines) + "\n")))


def test_large_files_are_refused(tmp_path):
    path = write(tmp_path, "# " + "x" * MAX_FILE_BYTES + "\n")
    assert "file too large" in str(refused(path))


def test_missing_file_and_folder(tmp_path):
    assert "no such file" in str(refused(tmp_path / "nope.yaml"))
    assert "is a folder" in str(refused(tmp_path))
