"""What every report shares: the rich console, numbers as tables show them, and
spec-supplied text made safe to print."""

from __future__ import annotations

from typing import IO, Any

from bearingcalc.wording import printable

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
