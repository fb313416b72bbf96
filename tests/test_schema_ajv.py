"""`bearingcalc schema` under ajv in strict mode.

ajv is the validator of many editors and JavaScript tools, and in strict mode it refuses
what check-jsonschema lets through: unknown keywords, ``required`` names without a
``properties`` entry, keywords applied to a type the schema does not declare. A schema
strict ajv compiles is one the strictest of the common validators accepts.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from bearingcalc.cli import app
from bearingcalc.kinds import KINDS
from bearingcalc.models.yaml_loader import load_documents
from tests.conftest import ROOT

RUN_TIMEOUT = 120
SPECS = sorted((ROOT / "specs").rglob("*.yaml"))
#: .ci/run installs ajv-cli and ajv-formats before the tests and names the command here;
#: without it, an ``ajv`` on PATH is taken. The tests never install anything.
AJV_VARIABLE = "BEARINGCALC_AJV"


def _skip(reason: str) -> None:
    # CI sets the variable: there the strict validator must run, not quietly skip.
    if os.environ.get("BEARINGCALC_REQUIRE_AJV") == "1":
        pytest.fail(reason)
    pytest.skip(reason)


@pytest.fixture(scope="session")
def ajv() -> Path:
    """The ajv command installed before the test run (see .ci/run)."""
    if shutil.which("node") is None:
        _skip("node is not installed, so ajv cannot run")
    named = os.environ.get(AJV_VARIABLE)
    found = named if named else shutil.which("ajv")
    if not found:
        _skip(f"no ajv command: install ajv-cli@5 and ajv-formats@3 and set {AJV_VARIABLE}")
    exe = Path(found)
    if not exe.is_file() or not os.access(exe, os.X_OK):
        _skip(f"{AJV_VARIABLE}={found} is not an executable file")
    return exe


def printed_schema(*args: str) -> dict[str, Any]:
    run = CliRunner().invoke(app, ["schema", *args])
    assert run.exit_code == 0, run.output
    return json.loads(run.stdout)


@pytest.fixture(scope="session")
def schemas(tmp_path_factory) -> dict[str | None, Path]:
    """What `bearingcalc schema` prints, for any spec (key None) and for each kind."""
    folder = tmp_path_factory.mktemp("schemas")
    paths: dict[str | None, Path] = {}
    for kind in (None, *sorted(KINDS)):
        path = folder / f"{kind or 'any'}.json"
        path.write_text(json.dumps(printed_schema(*(["--kind", kind] if kind else []))))
        paths[kind] = path
    return paths


def uses_formats(node: Any) -> bool:
    """Whether a schema has a ``format`` keyword, which strict ajv refuses unless the
    formats are loaded (a property that is named "format" holds a schema, not a string)."""
    if isinstance(node, dict):
        return isinstance(node.get("format"), str) or any(map(uses_formats, node.values()))
    if isinstance(node, list):
        return any(map(uses_formats, node))
    return False


def run_ajv(ajv: Path, command: str, schema: Path, *args: str) -> subprocess.CompletedProcess:
    formats = ["-c", "ajv-formats"] if uses_formats(json.loads(schema.read_text())) else []
    return subprocess.run(
        [str(ajv), command, "--spec=draft2020", "--strict=true", *formats, "-s", str(schema),
         *args],
        capture_output=True, text=True, timeout=RUN_TIMEOUT, check=False)


def as_json_documents(path: Path, folder: Path, text: str | None = None) -> list[Path]:
    """Each YAML document of a spec as a JSON file, read as bearingcalc reads it.

    Plain PyYAML follows YAML 1.1, where ``1e7`` is a string; bearingcalc, editors and
    check-jsonschema follow YAML 1.2, where it is a number, so the spec loader converts.
    """
    stem = "--".join(path.relative_to(ROOT / "specs").with_suffix("").parts)
    written = []
    for document in load_documents(path, text):
        out = folder / f"{stem}.{document.index}.json"
        out.write_text(json.dumps(document.data))
        written.append(out)
    return written


def test_strict_ajv_compiles_the_schema_of_any_spec_and_of_each_kind(ajv, schemas):
    extra = [arg for kind, path in schemas.items() if kind is not None
             for arg in ("-s", str(path))]
    run = run_ajv(ajv, "compile", schemas[None], *extra)
    assert run.returncode == 0, run.stdout + run.stderr


def test_strict_ajv_accepts_every_document_of_every_example_spec(ajv, schemas, tmp_path):
    documents = [out for path in SPECS for out in as_json_documents(path, tmp_path)]
    assert len(documents) >= len(SPECS)
    # One ajv run for all the documents: node's start-up is most of each run's time.
    run = run_ajv(ajv, "validate", schemas[None], "--errors=json",
                  *(arg for out in documents for arg in ("-d", str(out))))
    assert run.returncode == 0, run.stdout + run.stderr


def example(name: str) -> str:
    return (ROOT / "specs" / name).read_text()


#: Broken bearing specs: the example, its broken text, and what ajv must name (the
#: unknown key, or the instance path of the wrong value).
BROKEN = [
    ("rolling-bearing.yaml", example("rolling-bearing.yaml") + "dynamic_load_ratin: 3 kN\n",
     "dynamic_load_ratin"),
    ("rolling-bearing.yaml", example("rolling-bearing.yaml").replace("  e: 0.37", "  e: high"),
     "/load_factors/e"),
    ("ball-bearing.yaml", example("ball-bearing.yaml").replace(
        "dynamic_load_rating: 55.3 kN", "dynamic_load_rating: [55.3 kN]"),
     "/dynamic_load_rating"),
]


def test_strict_ajv_reports_the_error_of_the_branch_the_spec_chose(ajv, schemas, tmp_path):
    """A broken rolling or ball bearing spec is refused for its own field, with no error
    from another kind's branch (such as the thrust bearing's required fields)."""
    documents = []
    for number, (spec, text, _) in enumerate(BROKEN, 1):
        assert text != example(spec), spec
        folder = tmp_path / str(number)
        folder.mkdir()
        documents += as_json_documents(ROOT / "specs" / spec, folder, text)
    run = run_ajv(ajv, "validate", schemas[None], "--errors=json",
                  *(arg for out in documents for arg in ("-d", str(out))))
    output = run.stdout + run.stderr
    assert run.returncode == 1, output
    # Each name is wrong in one document only, so its mention shows that document was
    # refused. Quoted, as ajv's JSON errors hold it: bare, "dynamic_load_ratin" would be
    # found inside "dynamic_load_rating".
    for _, _, mentioned in BROKEN:
        assert json.dumps(mentioned) in output, (mentioned, output)

    chosen = {KINDS[json.loads(out.read_text())["kind"]].model for out in documents}
    own_fields = {name for model in chosen for name in model.model_json_schema()["properties"]}
    schema = json.loads(schemas[None].read_text())
    for index, branch in enumerate(schema.get("allOf", [])):
        other = KINDS[branch["if"]["properties"]["kind"]["const"]].model
        if other not in chosen:
            assert f"#/allOf/{index}/" not in output, (other.__name__, output)
    for other in {kind.model for kind in KINDS.values()} - chosen:
        # pydantic names each model's definition after its class.
        assert other.__name__ not in output, (other.__name__, output)
        for required in set(other.model_json_schema().get("required", [])) - own_fields:
            assert json.dumps(required) not in output, (other.__name__, required, output)
