"""The import contracts (pyproject.toml, checked by lint-imports in CI) cover every module."""

from __future__ import annotations

import pkgutil

import pytest

import bearingcalc
from tests.conftest import ROOT


def test_every_module_is_forbidden_to_import_the_command_line():
    tomllib = pytest.importorskip("tomllib")  # Python 3.11 and newer
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]
    (contract,) = [c for c in config["contracts"]
                   if c["forbidden_modules"] == ["bearingcalc.cli"]]
    modules = {f"bearingcalc.{info.name}" for info in pkgutil.iter_modules(bearingcalc.__path__)}
    # templates holds YAML files only
    assert set(contract["source_modules"]) == modules - {
        "bearingcalc.cli", "bearingcalc.__main__", "bearingcalc.templates"}
