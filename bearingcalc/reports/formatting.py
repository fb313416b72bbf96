"""What every report shares: the rich console, numbers as tables show them, and
spec-supplied text made safe to print."""

from __future__ import annotations

from typing import IO, TYPE_CHECKING, Any

from bearingcalc.units import to_display
from bearingcalc.wording import printable

if TYPE_CHECKING:  # the report type only
    from bearingcalc.verdicts import Verdict

#: Width of tables when the output is not a terminal (a pipe, a CI log, a file): wide
#: enough that a row stays one line, instead of rich's 80 columns.
PIPE_WIDTH = 200


def console(stream: IO[str] | None = None) -> Any:
    """A rich console on ``stream`` (default stdout): the terminal's width on a terminal,
    ``PIPE_WIDTH`` columns elsewhere."""
    import sys

    from rich.console import Console

    class _Console(Console):
        def on_broken_pipe(self) -> None:
            # rich would exit with status 1 here; the CLI keeps the run's own status.
            raise BrokenPipeError

    target = stream if stream is not None else sys.stdout
    is_terminal = getattr(target, "isatty", lambda: False)()
    return _Console(file=stream, highlight=False, width=None if is_terminal else PIPE_WIDTH)


def safe_text(text: str) -> str:
    """Spec-supplied text made safe for a rich table: no control characters, no markup."""
    from rich.markup import escape

    return escape(printable(text))


def format_number(value: float) -> str:
    """Seven significant digits; exact zero stays 0."""
    if value == 0:
        return "0"
    return f"{value:.7g}"


def verdict_line(verdict: Verdict) -> str:
    """"modified rating life 5 981 h < required 20 000 h (margin −70 %)": the value and
    limit in display units."""
    value, unit = to_display(verdict.value, verdict.unit)
    limit, _ = to_display(verdict.limit, verdict.unit)
    unit = f" {unit}" if unit else ""
    word = verdict.limit_word
    if verdict.passed:
        sign = "≥" if verdict.at_least else "≤"
    else:
        sign = "<" if verdict.at_least else ">"
    return (f"{verdict.name} {_engineering(value)}{unit} {sign} {word} "
            f"{_engineering(limit)}{unit} (margin "
            f"{f'{100 * verdict.margin:+.3g}'.replace('-', '−')} %)")


def _engineering(value: float) -> str:
    """A number as an engineer writes it: 5 981, 20 000, 1.018, 0.0012."""
    if abs(value) >= 1000:
        return f"{value:,.0f}".replace(",", "\u202f")
    return f"{value:.4g}"
