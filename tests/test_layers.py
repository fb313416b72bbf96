"""The import contracts (pyproject.toml, checked by lint-imports in CI) cover every module."""

from __future__ import annotations

import pkgutil
import re

import bearingcalc
import bearingcalc.core
from tests.conftest import ROOT


def test_every_module_is_forbidden_to_import_the_command_line():
    text = (ROOT / "pyproject.toml").read_text()
    # The contract whose forbidden module is the command line alone (read as text, since
    # Python 3.10 has no TOML reader).
    block = re.search(r'source_modules = \[([^\]]*)\]\nforbidden_modules = \["bearingcalc\.cli"\]',
                      text)
    assert block is not None
    contract = {"source_modules": re.findall(r'"([^"]+)"', block[1])}
    modules = {f"bearingcalc.{info.name}" for info in pkgutil.iter_modules(bearingcalc.__path__)}
    # templates holds YAML files only
    assert set(contract["source_modules"]) == modules - {
        "bearingcalc.cli", "bearingcalc.__main__", "bearingcalc.templates"}


def test_every_module_has_its_place_in_the_layers():
    """The whole package's ``layers`` contract names every top-level module and package
    but the command line's entry point (so a new module is given its layer)."""
    text = (ROOT / "pyproject.toml").read_text()
    block = re.search(r'type = "layers"\nlayers = \[(.*?)\n\]', text, re.S)
    assert block is not None
    named = set(re.findall(r"bearingcalc\.[a-z_]+", block[1]))
    modules = {f"bearingcalc.{info.name}" for info in pkgutil.iter_modules(bearingcalc.__path__)}
    assert named == modules - {"bearingcalc.__main__"}


def test_the_solvers_have_layers_of_their_own():
    """Inside core/, every module has its place: the kinds' solvers above the standards
    and contact mechanics, those above what every solver returns."""
    text = (ROOT / "pyproject.toml").read_text()
    block = re.search(r'containers = \["bearingcalc.core"\]\nlayers = \[(.*?)\n\]', text, re.S)
    assert block is not None
    named = set(re.findall(r"[a-z_0-9]+", block[1]))
    modules = {info.name for info in pkgutil.iter_modules(bearingcalc.core.__path__)}
    assert named == modules
