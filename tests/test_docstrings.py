r"""Docstrings hold no control characters but the newline.

A backslash sequence of LaTeX in a docstring that is not a raw string turns into a
control character (``\frac`` into a form feed, ``\alpha`` into a bell, ``\theta`` into a
tab, ``\right`` into a carriage return), and the formula silently loses letters.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import unicodedata
from collections.abc import Iterator
from types import ModuleType

import pytest

import bearingcalc

#: Modules that run something when imported.
SKIPPED = {"bearingcalc.__main__"}


def _modules() -> list[str]:
    names = [bearingcalc.__name__]
    for info in pkgutil.walk_packages(bearingcalc.__path__, prefix="bearingcalc."):
        if info.name not in SKIPPED:
            names.append(info.name)
    return sorted(names)


def _documented(module: ModuleType) -> Iterator[tuple[str, str]]:
    """(qualified name, docstring) of the module and of every class, function, method and
    property defined in it."""
    yield module.__name__, module.__doc__ or ""
    seen: set[int] = set()

    def walk(owner: object, prefix: str) -> Iterator[tuple[str, str]]:
        for name, member in vars(owner).items():
            target = member.fget if isinstance(member, property) else member
            target = getattr(target, "__func__", target)   # staticmethod, classmethod
            if not (inspect.isclass(target) or inspect.isfunction(target)):
                continue
            if getattr(target, "__module__", None) != module.__name__ or id(target) in seen:
                continue
            seen.add(id(target))
            yield f"{prefix}.{name}", target.__doc__ or ""
            if inspect.isclass(target):
                yield from walk(target, f"{prefix}.{name}")

    yield from walk(module, module.__name__)


def _control_characters(text: str) -> list[str]:
    return [f"U+{ord(ch):04X} at {i}" for i, ch in enumerate(text)
            if ch != "\n" and unicodedata.category(ch) == "Cc"]


@pytest.mark.parametrize("module_name", _modules())
def test_no_docstring_holds_a_control_character(module_name):
    module = importlib.import_module(module_name)
    found = {name: bad for name, doc in _documented(module) if (bad := _control_characters(doc))}
    assert not found, found


def test_the_check_finds_latex_turned_into_control_characters():
    def formula() -> None:
        """.. math:: Q = \frac{F_a}{Z\\sin\theta}"""  # not a raw string, on purpose

    def written_right() -> None:
        r""".. math:: Q = \frac{F_a}{Z\sin\theta}"""

    assert _control_characters(formula.__doc__) == ["U+000C at 14", "U+0009 at 29"]
    assert _control_characters(written_right.__doc__) == []
    assert _control_characters("line one\nline two\r\n") == ["U+000D at 17"]
