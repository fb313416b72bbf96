"""Spec text and checks that more than one test of bearings as mounted writes: the
tapered bearing the roller and pair tests solve, and a limit judged on an example spec
as mounted and refused under the catalogue method."""

from __future__ import annotations

import json
from pathlib import Path

#: A tapered roller bearing's ratings and internal geometry as lines of a
#: ``kind: rolling-bearing`` spec; the independent references it is checked against are
#: built from the same numbers, so a change here goes there too.
TAPERED_ROLLERS = """dynamic_load_rating: 54 kN
static_load_rating: 63 kN
roller_count: 17
roller_diameter: 7.5 mm
roller_length: 14 mm
pitch_diameter: 45 mm
contact_angle: 14 deg
"""


def solved_with_limits(cli, spec_file, example: str, after: str,
                       limits: tuple[str, ...]) -> tuple[str, dict]:
    """``specs/<example>`` with ``limits`` added below its line ``after`` (an entry of
    its ``limits:``), solved to JSON where one of them fails (exit status 1): the spec's
    text and its record."""
    text = (Path("specs") / example).read_text(encoding="utf-8")
    limited = text.replace(after, after + "".join(f"\n  {limit}" for limit in limits))
    run = cli("solve", spec_file(limited), "--format", "json")
    assert run.code == 1, run.err
    return limited, json.loads(run.out)


def refused_lines(cli, spec_file, text: str) -> list[str]:
    """The error lines of a spec that ``solve`` refuses (exit status 2, nothing on
    stdout)."""
    run = cli("solve", spec_file(text))
    assert run.code == 2, run.out
    assert run.out.strip() == "", run.out
    return run.err.strip().splitlines()
