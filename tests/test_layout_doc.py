"""docs/layout.md is the map of the package: every module and package of bearingcalc/
is named in it by its path, and every module it names exists."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "bearingcalc"
LAYOUT = ROOT / "docs" / "layout.md"

#: a path in backticks: `core/solver.py`, `bearingcalc/kinds.py`, `cli/`
_NAMED = re.compile(r"`((?:bearingcalc/)?[A-Za-z0-9_./<>*-]+?(?:\.py|/))`")
_SPECIAL = {"__init__.py", "__main__.py"}


def _named_paths() -> set[str]:
    """Every path the doc names in backticks, relative to bearingcalc/ (or to the
    repository for tests/ and benchmarks/)."""
    found = set()
    for match in _NAMED.finditer(LAYOUT.read_text(encoding="utf-8")):
        path = match.group(1)
        found.add(path.removeprefix("bearingcalc/"))
    return found


def _modules_and_packages() -> set[str]:
    """Every module and package under bearingcalc/, relative to it (``core/solver.py``,
    ``core/``), but for __init__ and __main__ files and caches."""
    paths = set()
    for path in PACKAGE.rglob("*"):
        if "__pycache__" in path.parts:
            continue
        relative = path.relative_to(PACKAGE).as_posix()
        if path.is_dir() and (path / "__init__.py").exists():
            paths.add(relative + "/")
        elif path.suffix == ".py" and path.name not in _SPECIAL:
            paths.add(relative)
    return paths


def test_every_module_and_package_is_named() -> None:
    missing = sorted(_modules_and_packages() - _named_paths())
    assert not missing, f"docs/layout.md does not name: {missing}"


def test_every_named_module_exists() -> None:
    stale = []
    for path in sorted(_named_paths()):
        if "<" in path or "*" in path:  # a pattern such as core/<kind>.py
            continue
        base = ROOT if path.split("/")[0] in {"tests", "benchmarks", "docs", "specs",
                                              ".ci"} else PACKAGE
        if not (base / path).exists():
            stale.append(path)
    assert not stale, f"docs/layout.md names modules that do not exist: {stale}"


def test_the_check_finds_a_missing_and_a_stale_name() -> None:
    # The pattern reads the names it must: a module, a package, a prefixed path.
    text = "`core/solver.py`, `cli/`, `bearingcalc/kinds.py`, `report.py`"
    named = {m.group(1).removeprefix("bearingcalc/") for m in _NAMED.finditer(text)}
    assert named == {"core/solver.py", "cli/", "kinds.py", "report.py"}
    assert not (PACKAGE / "report.py").exists()
