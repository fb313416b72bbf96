"""Small helpers for the words users read: articles, plurals, safe text."""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable

_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029]")


def article(word: str) -> str:
    """'a length', 'an angle'."""
    return f"an {word}" if word[:1].lower() in "aeiou" else f"a {word}"


def plural(count: int, noun: str) -> str:
    """'1 document', '2 documents'."""
    return f"{count} {noun}" if count == 1 else f"{count} {noun}s"


def printable(text: str) -> str:
    r"""``text`` with control characters written as escapes (``\x1b``, ``\n``).

    Names, file names and values come from specs and must not move the cursor,
    colour the terminal, start a fake line of their own or break XML.

    >>> printable("TB\n\x1b[32mPASS")
    'TB\\n\\x1b[32mPASS'
    """
    return _CONTROL.sub(lambda m: repr(m.group())[1:-1], text)


def spreadsheet_text(text: str) -> str:
    """``text`` as a CSV cell that a spreadsheet shows and never runs: printable, and
    with a leading ' where it would start a formula (=, +, -, @, a tab or a return).

    >>> spreadsheet_text("=cmd|' /c calc'!A1")
    "'=cmd|' /c calc'!A1"
    """
    # The first character as written: a tab or a return is escaped by printable, but
    # the cell is marked as text all the same.
    shown = printable(text)
    return "'" + shown if text[:1] in ("=", "+", "-", "@", "\t", "\r") else shown


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """" (did you mean 'x'?)" for the closest of ``choices`` to a mistyped word, or "".

    >>> did_you_mean("ball-bearings", ["ball-bearing", "bevel-gears"])
    " (did you mean 'ball-bearing'?)"
    """
    close = closest(word, choices)
    return f" (did you mean '{close}'?)" if close else ""


def closest(word: str, choices: Iterable[str]) -> str | None:
    """The closest of ``choices`` to a mistyped word, or None where none is close.

    >>> closest("radial_lod", ["radial_load", "axial_load"])
    'radial_load'
    """
    close = difflib.get_close_matches(word, list(choices), n=1, cutoff=0.6)
    return close[0] if close else None
