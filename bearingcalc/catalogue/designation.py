"""Bearing designations: the basic designation that fixes the boundary dimensions, and
the suffixes that do not.

A basic designation is an optional letter prefix of cylindrical roller bearings (NU, NJ,
NUP, N, NF) and digits: the series (``62``, ``222``, ``NU22``) and the bore code, its
last two digits (``05``; a miniature bearing's three digits end in its bore in mm,
``608``). ISO 15's rule reads the bore code: 00 = 10 mm, 01 = 12 mm,
02 = 15 mm, 03 = 17 mm, and from 04 to 96 the code times 5 mm. Whatever follows (``-2RS``,
``2Z``, ``C3``, ``E``, ``J2/Q``, ``BECBP``) changes no dimension: it is kept, and not used
to look a bearing up. A designation is read in Unicode's compatibility form, so that
full-width digits (``６２０５``) are the bearing they read as, checked against ISO.
"""

from __future__ import annotations

import re
import unicodedata
from dataclasses import dataclass

#: The bores of the first four codes; from 04 on, the code times 5 mm. [mm]
SMALL_BORES = {0: 10.0, 1: 12.0, 2: 15.0, 3: 17.0}

#: Makers' own prefixes of a standard bearing (NSK's high-capacity HR, NTN's 4T-), which
#: change no boundary dimension.
_BASIC = re.compile(r"(?:HR|4T-|ET-)?\s*(?P<prefix>NUP|NU|NJ|NF|N)?\s*(?P<digits>[0-9]{3,6})"
                    r"(?![0-9])", re.IGNORECASE)
_SEPARATORS = re.compile(r"[\s\-]+")


@dataclass(frozen=True, slots=True)
class Designation:
    """A designation as written, read into its parts."""

    text: str            # as written, stripped
    basic: str           # prefix and digits: 'NJ205', '6205', '30205'
    suffixes: tuple[str, ...]
    #: the basic designation the boundary dimensions are filed under: a cylindrical
    #: roller bearing's N, NJ, NUP and NF forms under NU
    iso_key: str

    @property
    def bore_diameter(self) -> float | None:
        """d by ISO 15's bore code, the last two digits [mm]; None for a code above 96.
        Three digits without a prefix are a miniature bearing, whose last digit is its
        bore in mm (``608``: 8 mm)."""
        if len(self.basic) == 3:
            return float(self.basic[-1])
        return bore_from_code(int(self.basic[-2:]))


def bore_from_code(code: int) -> float | None:
    """ISO 15's bore d [mm] of a bore code: 00 = 10, 01 = 12, 02 = 15, 03 = 17, then
    the code times 5 (04 = 20 to 96 = 480); None outside 00 to 96."""
    if code in SMALL_BORES:
        return SMALL_BORES[code]
    return 5.0 * code if 4 <= code <= 96 else None


def normal_form(text: str | int) -> str:
    """A designation in Unicode's compatibility form (NFKC), stripped: full-width digits
    and letters (``６３０５``, typed with an East Asian input method) are the ASCII ones,
    a no-break space a space, so that the bearing is the one its characters read as."""
    return unicodedata.normalize("NFKC", str(text)).strip()


def parse_designation(text: str | int) -> Designation | None:
    """The parts of a designation (``'6205-2RS C3'``, ``6205``, ``'NU 206 ECP'``, the
    full-width ``'６２０５'``, read in :func:`normal_form`); None where it does not start
    with a basic designation (a special bearing's own name)."""
    written = str(text).strip()
    normal = normal_form(written)
    match = _BASIC.match(normal)
    if match is None:
        return None
    prefix, digits = (match["prefix"] or "").upper(), match["digits"]
    rest = normal[match.end():]
    suffixes = tuple(part for part in _SEPARATORS.split(rest) if part) if rest else ()
    return Designation(written, prefix + digits, suffixes, "NU" + digits if prefix else digits)
