"""No solver function changes what it was handed: a step returns what it found (see
``bearingcalc.core.common.Found``) and its caller gathers it. Checked from the code's
own syntax tree, so a new helper that writes into a dict, list or array argument fails
here, whatever its name."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

CORE = Path(__file__).resolve().parents[1] / "bearingcalc" / "core"
#: methods that change their object in place
MUTATING = {"update", "setdefault", "pop", "popitem", "append", "extend", "insert",
            "clear", "remove", "sort", "fill", "resize", "put", "itemset"}


def _root_name(node: ast.expr) -> str | None:
    """The variable an attribute or subscript chain starts from (``a`` of ``a.b[1]``)."""
    while isinstance(node, ast.Attribute | ast.Subscript):
        node = node.value
    return node.id if isinstance(node, ast.Name) else None


def _written_parameters(function: ast.FunctionDef) -> set[str]:
    """The parameters (other than ``self``) the function writes into."""
    params = {a.arg for a in (*function.args.posonlyargs, *function.args.args,
                              *function.args.kwonlyargs)} - {"self", "cls"}
    rebound = {target.id for node in ast.walk(function) if isinstance(node, ast.Assign)
               for target in node.targets if isinstance(target, ast.Name)}
    written = set()
    for node in ast.walk(function):
        targets: list[ast.expr] = []
        if isinstance(node, ast.Assign):
            targets = [t for t in node.targets if isinstance(t, ast.Subscript | ast.Attribute)]
        elif isinstance(node, ast.AugAssign):
            targets = [node.target]
        elif isinstance(node, ast.Delete):
            targets = list(node.targets)
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
              and node.func.attr in MUTATING):
            targets = [node.func.value]
        written |= {name for target in targets if (name := _root_name(target)) in params}
    # a parameter rebound to a fresh value before it is written is the function's own
    return written - rebound


def _functions() -> list[tuple[str, ast.FunctionDef]]:
    found = []
    for path in sorted(CORE.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef):
                found.append((f"{path.stem}.{node.name}", node))
    return found


def test_the_check_sees_a_helper_that_writes_into_its_arguments():
    source = ("def step(out, flags, checks, x):\n"
              "    out['a'] = 1\n    flags.update(b=2)\n    checks += [(1, x)]\n"
              "def fine(inputs):\n    inputs = dict(inputs)\n    inputs['a'] = 1\n")
    steps = [node for node in ast.parse(source).body if isinstance(node, ast.FunctionDef)]
    assert _written_parameters(steps[0]) == {"out", "flags", "checks"}
    assert _written_parameters(steps[1]) == set()


FUNCTIONS = _functions()


@pytest.mark.parametrize(("name", "function"), FUNCTIONS, ids=[name for name, _ in FUNCTIONS])
def test_no_solver_function_writes_into_what_it_was_handed(name, function):
    assert not _written_parameters(function), name
