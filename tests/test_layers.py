"""The import contracts (pyproject.toml, checked by lint-imports in CI) cover every module."""

from __future__ import annotations

import pkgutil
import re

import bearingcalc
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
