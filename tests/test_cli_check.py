"""`bearingcalc check`, `schema` and `new`: statuses, formats, hostile input, editors."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from xml.etree import ElementTree

import pytest
import yaml

from bearingcalc import batch, reports
from bearingcalc.kinds import KINDS
from bearingcalc.templates import template_types
from tests.conftest import ROOT

GOOD = (ROOT / "specs" / "thrust-bearing.yaml").read_text()
FAILING = GOOD.replace("pitch_radius: 26 mm", "pitch_radius: 20 mm").replace(
    "ball_count: 12", "ball_count: 6")
INVALID = GOOD.replace("30 deg", "50 deg")


@pytest.fixture
def mixed(tmp_path):
    """A folder with passing, failing and invalid specs, a multi-document file and a
    hidden folder that must be skipped."""
    root = tmp_path / "designs"
    (root / "sub").mkdir(parents=True)
    (root / ".hidden").mkdir()
    (root / "a-pass.yaml").write_text(GOOD)
    (root / "sub" / "b-fail.yml").write_text(FAILING)
    (root / "sub" / "c-invalid.yaml").write_text(INVALID)
    (root / "d-multi.yaml").write_text(GOOD + "---\n" + FAILING)
    (root / ".hidden" / "e.yaml").write_text(INVALID)
    (root / "notes.txt").write_text("not a spec")
    return root


def json_records(run):
    return [json.loads(line) for line in run.out.splitlines()]


def test_every_spec_gets_one_status_in_json(cli, mixed):
    run = cli("check", mixed, "--format", "json")
    assert run.code == 2
    records = {Path(r["spec"]).name: r for r in json_records(run)}
    assert {name: r["status"] for name, r in records.items()} == {
        "a-pass.yaml": "pass", "d-multi.yaml#1": "pass", "d-multi.yaml#2": "fail",
        "b-fail.yml": "fail", "c-invalid.yaml": "invalid"}
    for record in records.values():
        assert list(record) == ["spec", "kind", "name", "status", "messages", "margins",
                                "verdicts"]
    fail = records["b-fail.yml"]
    assert fail["margins"]["slip_margin"] < 0
    # the verdict in engineering terms: the quantity, the comparison, the limit
    assert fail["messages"][0].startswith("spin-to-roll ratio ") and "> max 0.01" in (
        fail["messages"][0])
    assert fail["verdicts"][0]["key"] == "slip_margin"
    assert "contact_angle" in records["c-invalid.yaml"]["messages"][0]


@pytest.mark.parametrize(("files", "expected"), [
    ({"a.yaml": GOOD}, 0),
    ({"a.yaml": GOOD, "b.yaml": FAILING}, 1),
    ({"a.yaml": GOOD, "b.yaml": FAILING, "c.yaml": INVALID}, 2),
])
@pytest.mark.parametrize("fmt", ["table", "json", "junit"])
def test_exit_status_in_every_format(cli, tmp_path, files, expected, fmt):
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    run = cli("check", tmp_path, "--format", fmt)
    assert run.code == expected


def test_junit_report_has_a_testcase_per_spec(cli, mixed, tmp_path):
    out = tmp_path / "report.xml"
    run = cli("check", mixed, "--format", "junit", "--output", out)
    assert run.code == 2 and run.out == ""
    suite = ElementTree.parse(out).getroot().find("testsuite")
    cases = suite.findall("testcase")
    assert len(cases) == 5
    assert suite.get("failures") == "2" and suite.get("errors") == "1"
    assert sum(c.find("failure") is not None for c in cases) == 2
    assert sum(c.find("error") is not None for c in cases) == 1


def test_table_shows_only_problems_when_there_are_many(cli, tmp_path):
    for i in range(60):
        (tmp_path / f"s{i:02d}.yaml").write_text(GOOD)
    (tmp_path / "zz-fail.yaml").write_text(FAILING)
    run = cli("check", tmp_path)
    assert run.code == 1
    assert "FAIL" in run.out and "PASS" not in run.out
    assert "61 specs: 60 pass, 1 fail, 0 invalid (60 passing not shown" in run.out
    assert cli("check", tmp_path, "--all").out.count("PASS") == 60


def test_glob_and_files_and_order(cli, mixed):
    run = cli("check", str(mixed / "sub" / "*.y*ml"), mixed / "a-pass.yaml", "-f", "json")
    names = [Path(r["spec"]).name for r in json_records(run)]
    assert names == ["b-fail.yml", "c-invalid.yaml", "a-pass.yaml"]


def test_output_is_written_atomically_and_never_truncated_on_failure(cli, mixed, tmp_path,
                                                                      monkeypatch):
    out = tmp_path / "report.jsonl"
    out.write_text("previous report\n")

    def broken(records, stream):
        stream.write("half a line")
        raise RuntimeError("disk full")

    monkeypatch.setattr(reports, "write_check_json_lines", broken)
    run = cli("check", mixed, "--format", "json", "--output", out)
    assert run.code == 2
    assert "internal error" in run.err
    assert out.read_text() == "previous report\n"
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".report")] == []


def test_output_to_a_missing_folder_is_a_clear_error(cli, mixed, tmp_path):
    run = cli("check", mixed, "--output", tmp_path / "no" / "such" / "dir.json")
    assert run.code == 2 and "cannot write the report" in run.err


def test_parallel_and_serial_give_the_same_records(mixed, monkeypatch):
    for i in range(30):
        (mixed / f"extra-{i}.yaml").write_text([GOOD, FAILING, INVALID][i % 3])
    serial = batch.check_paths([mixed], jobs=1)
    monkeypatch.setattr(batch, "PARALLEL_THRESHOLD", 2)
    parallel = batch.check_paths([mixed], jobs=2)
    assert parallel == serial
    assert len(serial) == 35


# --- hostile and broken input -----------------------------------------------------------

def billion_laughs() -> str:
    lines = ["a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    for previous, name in zip("abcdefgh", "bcdefghi", strict=True):
        lines.append(f"{name}: &{name} [" + ", ".join([f"*{previous}"] * 9) + "]")
    return "\n".join(lines) + "\n"


HOSTILE = {
    "huge.yaml": ("kind: thrust-bearing\n# " + "x" * (1024 * 1024) + "\n", "file too large"),
    "bomb.yaml": (billion_laughs(), "document too large"),
    "deep.yaml": ("a: " + "[" * 100_000 + "]" * 100_000 + "\n", "nested too deeply"),
    "deep-map.yaml": ("".join("  " * i + f"k{i}:\n" for i in range(500)), "nested too deeply"),
    "binary.yaml": (bytes(range(256)) * 4, "binary file"),
    "latin1.yaml": ("kind: thrust-bearing\nname: Lösung\n".encode("latin-1"), "not UTF-8"),
    "tag.yaml": ("kind: !!python/object/apply:os.system [id]\n", "YAML tag"),
}


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_files_are_invalid_with_a_reason(cli, tmp_path, name):
    content, fragment = HOSTILE[name]
    (tmp_path / name).write_bytes(content if isinstance(content, bytes) else content.encode())
    (tmp_path / "ok.yaml").write_text(GOOD)
    run = cli("check", tmp_path, "--format", "json")
    assert run.code == 2
    records = {Path(r["spec"]).name: r for r in json_records(run)}
    assert records["ok.yaml"]["status"] == "pass"
    assert records[name]["status"] == "invalid"
    assert fragment in records[name]["messages"][0]


def test_symlink_loops_and_broken_links(cli, tmp_path):
    (tmp_path / "ok.yaml").write_text(GOOD)
    (tmp_path / "loop-a.yaml").symlink_to(tmp_path / "loop-b.yaml")
    (tmp_path / "loop-b.yaml").symlink_to(tmp_path / "loop-a.yaml")
    (tmp_path / "broken.yaml").symlink_to(tmp_path / "missing.yaml")
    (tmp_path / "folder-loop").symlink_to(tmp_path)  # a folder link: not followed
    run = cli("check", tmp_path, "--format", "json")
    records = {Path(r["spec"]).name: r for r in json_records(run)}
    assert set(records) == {"ok.yaml", "loop-a.yaml", "loop-b.yaml", "broken.yaml"}
    assert "symbolic links" in records["loop-a.yaml"]["messages"][0]
    assert "broken symbolic link" in records["broken.yaml"]["messages"][0]
    assert run.code == 2


def test_fifo_named_yaml_does_not_hang(cli, tmp_path):
    os.mkfifo(tmp_path / "pipe.yaml")
    run = cli("check", tmp_path, "--format", "json")
    (record,) = json_records(run)
    assert record["status"] == "invalid" and "not a regular file" in record["messages"][0]


def test_unreadable_file(cli, tmp_path, monkeypatch):
    path = tmp_path / "secret.yaml"
    path.write_text(GOOD)
    real_open = open

    def deny(file, *args, **kwargs):
        if str(file) == str(path):
            raise PermissionError(13, "Permission denied")
        return real_open(file, *args, **kwargs)

    monkeypatch.setattr("builtins.open", deny)
    run = cli("check", path, "--format", "json")
    (record,) = json_records(run)
    assert record["status"] == "invalid"
    assert "cannot read the file: Permission denied" in record["messages"][0]


def test_empty_folder_is_a_clear_error(cli, tmp_path):
    run = cli("check", tmp_path)
    assert run.code == 2
    assert "no spec files" in run.out


def test_missing_path_does_not_stop_the_batch(cli, tmp_path):
    (tmp_path / "ok.yaml").write_text(GOOD)
    run = cli("check", tmp_path / "nope", tmp_path / "ok.yaml", "--format", "json")
    statuses = [r["status"] for r in json_records(run)]
    assert statuses == ["invalid", "pass"] and run.code == 2


def test_paths_with_spaces_and_unicode(cli, tmp_path):
    folder = tmp_path / "Lager Entwürfe ✓"
    folder.mkdir()
    (folder / "Axiallager 20°.yaml").write_text(GOOD)
    run = cli("check", folder, "--format", "json")
    (record,) = json_records(run)
    assert record["status"] == "pass" and record["spec"].endswith("Axiallager 20°.yaml")


# --- schema, templates, pre-commit ----------------------------------------------------------

@pytest.fixture(scope="module")
def schema_file(tmp_path_factory):
    from bearingcalc.schema import spec_schema

    path = tmp_path_factory.mktemp("schema") / "schema.json"
    path.write_text(json.dumps(spec_schema()))
    return path


def check_jsonschema(schema_file, *files):
    exe = shutil.which("check-jsonschema", path=str(Path(sys.executable).parent))
    if exe is None:
        pytest.skip("check-jsonschema is not installed (it is in the test extras)")
    return subprocess.run([exe, "--schemafile", str(schema_file), *map(str, files)],
                          capture_output=True, text=True, check=False)


def test_check_jsonschema_accepts_every_example_spec(schema_file):
    done = check_jsonschema(schema_file, *sorted((ROOT / "specs").rglob("*.yaml")))
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.parametrize(("text", "why"), [
    (GOOD + "pich_radius: 25 mm\n", "unknown key"),
    (GOOD.replace("12.7 mm", "12.7"), "bare number"),
    (GOOD.replace("12.7 mm", "'12.7'"), "string without a unit"),
    (GOOD.replace("ball_count: 12", "ball_count: twelve"), "wrong type"),
    (GOOD.replace("thrust-bearing\n", "thrust-bering\n", 1), "unknown kind"),
])
def test_check_jsonschema_rejects_unknown_keys_and_wrong_types(schema_file, tmp_path, text, why):
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    assert check_jsonschema(schema_file, path).returncode == 1, why


def test_schema_command_prints_draft_2020_12(cli):
    run = cli("schema")
    schema = json.loads(run.out)
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    kind_schema = json.loads(cli("schema", "--kind", "bevel-gears").out)
    assert kind_schema["properties"]["kind"]["const"] == "bevel-gears"
    length = kind_schema["properties"]["module"]["anyOf"][0]
    assert length["$comment"] == "dimension: length; SI unit: m"
    assert length["examples"] == ["12.7 mm"]
    assert cli("schema", "--kind", "nope").code == 2


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_new_templates_pass_check_as_printed(cli, tmp_path, kind):
    run = cli("new", kind)
    assert run.code == 0
    path = tmp_path / f"{kind}.yaml"
    path.write_text(run.out)
    assert cli("check", path).code == 0
    assert run.out == (ROOT / "specs" / f"{kind}.yaml").read_text()


@pytest.mark.parametrize(("kind", "type_name"), [
    (kind, type_name) for kind in sorted(KINDS) for type_name in template_types(kind)[1:]])
def test_every_type_template_passes_check_and_is_an_example(cli, tmp_path, kind, type_name):
    run = cli("new", kind, "--type", type_name)
    assert run.code == 0
    path = tmp_path / f"{kind}-{type_name}.yaml"
    path.write_text(run.out)
    assert cli("check", path).code == 0
    assert f"type: {type_name}" in run.out
    assert run.out == (ROOT / "specs" / f"{kind}-{type_name}.yaml").read_text()


def test_new_type_of_the_default_template_and_unknown_types(cli):
    assert cli("new", "rolling-bearing", "--type", "tapered-roller").out == cli(
        "new", "rolling-bearing").out
    run = cli("new", "rolling-bearing", "--type", "cylindrical")
    assert run.code == 2 and run.err.count("\n") == 1
    assert "cylindrical-roller" in run.err and run.out == ""


def test_new_list_and_unknown_kind(cli):
    run = cli("new", "--list")
    assert run.code == 0 and all(kind in run.out for kind in KINDS)
    assert cli("new", "gearbox").code == 2


def test_pre_commit_hook_definition():
    (hook,) = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    assert hook["id"] == "bearingcalc-check"
    assert hook["entry"] == "bearingcalc check"
    assert hook["language"] == "python"


def test_a_zero_limit_ranks_as_a_whole_limit_broken(cli, tmp_path):
    """A limit of 0 has no fraction: a value off it counts as −100 %, so it ranks first
    among true fractions instead of by its raw size (a mismatch of 1e-3 against 0 is not
    a margin of −0.1 %)."""
    text = ((ROOT / "specs" / "bevel-gears.yaml").read_text()
            .replace("gear_a: {teeth: 12}", "gear_a: {teeth: 12, pitch_angle: 26 deg}")
            .replace("max_apex_mismatch: 0.001", "max_apex_mismatch: 0"))
    (tmp_path / "a.yaml").write_text(text)
    (record,) = json_records(cli("check", tmp_path / "a.yaml", "--format", "json"))
    (verdict,) = record["verdicts"]
    assert verdict["limit"] == 0.0 and verdict["value"] > 0
    assert verdict["margin"] == -1.0 and record["status"] == "fail"


def test_a_validator_reports_the_error_of_the_branch_the_spec_chose(schema_file, tmp_path):
    """The choice of kind is plain JSON Schema (if kind then its branch), so a broken
    rolling-bearing spec gets its own error, not every branch's ('additional properties
    are not allowed' against the thrust bearing)."""
    path = tmp_path / "bad.yaml"
    path.write_text((ROOT / "specs" / "rolling-bearing.yaml").read_text()
                    + "dynamic_load_ratin: 3 kN\n")
    run = check_jsonschema(schema_file, path)
    assert run.returncode == 1
    assert "dynamic_load_ratin" in run.stdout + run.stderr
    assert "ThrustBearing" not in run.stdout + run.stderr
    assert "ball_radius" not in run.stdout + run.stderr
    schema = json.loads(schema_file.read_text())
    text = json.dumps(schema)
    assert "discriminator" not in text and '"x-' not in text  # keywords strict validators refuse


def test_a_narrow_terminal_gets_a_paragraph_per_spec(cli, monkeypatch):
    """Where the table's columns cannot fit, a file name is never broken mid-word: each
    spec is a line (status, file, name, kind) and its verdict the next."""
    from bearingcalc.reports import formatting

    monkeypatch.setattr(formatting, "PIPE_WIDTH", 80)
    run = cli("check", ROOT / "specs", "--all")
    assert run.code == 0, run.err
    lines = run.out.splitlines()
    specs = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "specs").rglob("*.yaml"))
    heads = [line for line in lines if line.startswith("PASS  ")]
    assert len(heads) == len(specs)
    for head in heads:
        assert head.split()[1].endswith(".yaml")
    assert "┃" not in run.out and "│" not in run.out
