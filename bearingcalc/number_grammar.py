"""How specs write numbers: one grammar for quantities, plain numbers, percentages,
the JSON Schema and the YAML reader.

A number is ASCII digits with an optional sign, decimal point and exponent: ``12``,
``-0.5``, ``.25``, ``1e-3``, ``12.7E+2``. Full-width digits, commas, underscores,
``0x`` prefixes and the words ``inf`` and ``nan`` are not numbers. The same language
is YAML 1.2's core-schema float (https://yaml.org/spec/1.2.2/#1023-core-schema), so
what the YAML reader calls a number and what a quantity's text calls one agree.

The patterns use only non-capturing groups and character classes, which read the same
in Python's ``re`` and in the ECMA-262 regular expressions of JSON Schema.
"""

from __future__ import annotations

#: Digits with an optional decimal point, or a point and digits: ``12``, ``12.``,
#: ``12.5``, ``.5``.
UNSIGNED_DECIMAL = r"(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)"
#: A power of ten: ``e-3``, ``E+12``.
EXPONENT = r"(?:[eE][-+]?[0-9]+)"
#: A signed decimal without an exponent.
DECIMAL = rf"[-+]?{UNSIGNED_DECIMAL}"
#: Any number a spec may write.
NUMBER = rf"{DECIMAL}{EXPONENT}?"
