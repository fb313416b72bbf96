"""Verdicts in engineering terms: what each margin judges (:class:`Judged`, in the
registry), each limit judged as a value against its limit (:class:`Verdict`), and the
line that says a verdict (:func:`verdict_line`)."""

from __future__ import annotations

import math
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass

from bearingcalc.units import to_display


@dataclass(frozen=True)
class Judged:
    """How a margin judges a result against its limit, for verdicts in engineering terms.

    ``quantity`` is the result judged (or a function of the results where no one result
    is it: a drive's smallest s0). The margin is formed as ``form`` says: "ratio"
    (quantity/limit − 1), "difference" (quantity − limit, or limit − |quantity| for an
    upper limit) or "fraction" (1 − quantity/limit); the limit follows from the margin
    and the quantity, and every margin reads as a fraction of its limit.
    """

    #: what is judged, in words (or a function of the results: which gear governs)
    name: str | Callable[[Mapping[str, float | None]], str]
    #: the result judged; or results in order of preference, the first the design has
    #: (a bearing solved as mounted is judged on its reference life); or a function
    quantity: str | tuple[str, ...] | Callable[[Mapping[str, float | None]], float | None]
    at_least: bool
    form: str = "difference"
    #: how a verdict names the limit: "required" (a life), "min" (a safety), "max"
    word: str = ""
    #: what the limit is a limit of, where the name says more ("smallest static safety
    #: s0" has a "min static safety s0"); the name otherwise
    limit_of: str = ""

    @property
    def limit_word(self) -> str:
        return self.word or ("min" if self.at_least else "max")

    def limit_named(self) -> str:
        """The limit in words: its word and what it limits ("min static safety s0")."""
        return f"{self.limit_word} {self.limit_of or self.named({})}"

    def named(self, results: Mapping[str, float | None]) -> str:
        return self.name(results) if callable(self.name) else self.name

    def key(self, available: Collection[str]) -> str | None:
        """The result judged among the ``available`` ones; None where it is a function
        of several."""
        if isinstance(self.quantity, str):
            return self.quantity
        if isinstance(self.quantity, tuple):
            return next((key for key in self.quantity if key in available), None)
        return None

    def value(self, results: Mapping[str, float | None]) -> float | None:
        """The judged quantity (its size, for an upper limit on a signed one)."""
        if callable(self.quantity):
            value = self.quantity(results)
        else:
            key = self.key({k for k, v in results.items() if v is not None})
            value = None if key is None else results.get(key)
        return None if value is None else (value if self.at_least else abs(value))

    def limit(self, value: float, margin: float) -> float:
        """The limit that gives ``margin`` at ``value``; NaN where the margin does not
        tell it (a pressure of 0 has the margin 1 against any limit)."""
        if self.form in ("ratio", "fraction"):
            scale = 1.0 + margin if self.form == "ratio" else 1.0 - margin
            return value / scale if scale != 0 else math.nan
        return value - margin if self.at_least else value + margin

    def fraction(self, margin: float, limit: float) -> float:
        """The margin as a fraction of the limit: value/limit − 1 for a lower limit,
        1 − value/limit for an upper one. A limit of 0 has no fraction: any value off it
        counts as ±100 % (of the value), so that it ranks with the true fractions."""
        if self.form in ("ratio", "fraction"):
            return margin
        if limit == 0:
            return 0.0 if margin == 0 else math.copysign(1.0, margin)
        return margin / abs(limit)


def smallest_bearing_safety(results: Mapping[str, float | None]) -> float | None:
    """The smallest s0 of a drive's bearings, read from the tables of its results along
    the member axis (``results.tables``, as :class:`~bearingcalc.result_keys.FlatResults`
    carries them)."""
    found = [value for table in getattr(results, "tables", ()) if table.axis == "member"
             for key in table.column("static_safety_factor")
             if key is not None and (value := results.get(key)) is not None]
    return min(found) if found else None


@dataclass(frozen=True)
class Verdict:
    """One limit judged: the quantity, its value and limit [SI], and the margin as a
    fraction of the limit (value/limit − 1 for a lower limit, 1 − value/limit for an
    upper one; below 0 where the limit is broken)."""

    key: str          # the margin's result key
    name: str         # what is judged, in words
    value: float
    limit: float
    unit: str         # SI unit of value and limit
    margin: float
    at_least: bool    # a lower limit (a life, a safety) or an upper one (a pressure)
    limit_word: str   # how the limit is named: "required", "min", "max"

    @property
    def passed(self) -> bool:
        return self.margin >= 0


def judge(judges: Mapping[str, Judged], declared: Mapping[str, tuple[str, str]],
          results: Mapping[str, float | None], margins: Mapping[str, float]) -> list[Verdict]:
    """Each judged margin as a :class:`Verdict`, the worst first.

    ``judges`` is what each margin judges (a kind's ``judged``), ``declared`` the result
    key -> (SI unit, meaning) the units are read from (a kind's ``results``). A margin
    with no judge, or whose value or limit the results do not give, is left out.
    """
    verdicts = []
    for key, margin in margins.items():
        judged = judges.get(key)
        value = None if judged is None else judged.value(results)
        if judged is None or value is None:
            continue
        limit = judged.limit(value, margin)
        if not math.isfinite(limit):  # said as the plain margin instead
            continue
        judged_key = judged.key({k for k, v in results.items() if v is not None})
        unit = declared[judged_key][0] if judged_key is not None else declared[key][0]
        verdicts.append(Verdict(key, judged.named(results), value, limit, unit,
                                judged.fraction(margin, limit), judged.at_least,
                                judged.limit_word))
    return sorted(verdicts, key=lambda verdict: verdict.margin)


#: Between a number's groups of three digits: a narrow no-break space (SI brochure).
THOUSANDS = "\u202f"
#: Between a number and its unit: a no-break space, so that "20 000 h" is read whole.
BEFORE_UNIT = "\u00a0"


def verdict_line(verdict: Verdict) -> str:
    """"modified rating life 5 981 h < required 20 000 h (margin −70 %)": the value and
    limit in display units, each number whole with its unit (no-break spaces)."""
    value, unit = to_display(verdict.value, verdict.unit)
    limit, _ = to_display(verdict.limit, verdict.unit)
    unit = f"{BEFORE_UNIT}{unit}" if unit else ""
    word = verdict.limit_word
    if verdict.passed:
        sign = "≥" if verdict.at_least else "≤"
    else:
        sign = "<" if verdict.at_least else ">"
    return (f"{verdict.name} {_engineering(value)}{unit} {sign} {word} "
            f"{_engineering(limit)}{unit} (margin "
            f"{f'{100 * verdict.margin:+.3g}'.replace('-', '−')}{BEFORE_UNIT}%)")


def _engineering(value: float) -> str:
    """A number as an engineer writes it: 5 981, 20 000, 1.018, 0.0012."""
    if abs(value) >= 1000:
        return f"{value:,.0f}".replace(",", THOUSANDS)
    return f"{value:.4g}"


#: What the margins the kinds share judge.
def _life_named(results: Mapping[str, float | None]) -> str:
    return ("modified reference rating life"
            if results.get("modified_reference_rating_life") is not None
            else "modified rating life")


LIFE = Judged(_life_named, ("modified_reference_rating_life", "modified_rating_life"), True,
              "ratio", "required")
STATIC = Judged("static safety s0", "static_safety_factor", True)
CONTACT = Judged("contact pressure", "max_contact_pressure", False, "fraction")


def _weaker(name: str, key: str) -> Judged:
    """A safety judged at the weaker of the pinion and gear B (where gear B is rated),
    named for the member that governs."""
    def members(results: Mapping[str, float | None]) -> tuple[float | None, float | None]:
        return results.get(key), results.get(f"gear_b_{key}")

    def value(results: Mapping[str, float | None]) -> float | None:
        found = [v for v in members(results) if v is not None]
        return min(found) if found else None

    def named(results: Mapping[str, float | None]) -> str:
        pinion, gear = members(results)
        if gear is None or pinion is None:
            return name
        return f"gear B's {name}" if gear < pinion else f"the pinion's {name}"

    return Judged(named, value, True)


PAIR = {
    "face_width_margin": Judged("face width ratio b/Re", "face_width_ratio", False),
    "bending_safety_margin": _weaker("bending safety S_F", "bending_safety"),
    "contact_safety_margin": _weaker("contact safety S_H", "contact_safety"),
    "slip_margin": Judged("apex mismatch", "apex_mismatch", False),
}


def _spin_to_roll(results: Mapping[str, float | None]) -> float | None:
    """A ball bearing's larger |spin/roll| of its two races."""
    found = [abs(value) for key in ("inner_spin_to_roll", "outer_spin_to_roll")
             if (value := results.get(key)) is not None]
    return max(found) if found else None


#: A ball bearing's spin-to-roll limit, on the larger ratio of its two races.
SPIN_TO_ROLL = Judged("spin-to-roll ratio", _spin_to_roll, False)
