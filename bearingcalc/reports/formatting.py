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

        def render_str(self, text: str, **options: Any) -> Any:
            # Every text printed or put in a table: its numbers kept whole.
            return numbers_whole(super().render_str(text, **options))

        def print(self, *objects: Any, **options: Any) -> None:
            # rich joins the texts of one print into a plain Text, which would break at
            # a no-break space: a text holding one is printed as a renderable instead.
            super().print(*(self._whole(item, options) for item in objects), **options)

        def _whole(self, item: Any, options: dict[str, Any]) -> Any:
            if not isinstance(item, str) or not any(space in item for space in _HELD):
                return item
            from rich.containers import Renderables

            return Renderables([self.render_str(
                item, markup=options.get("markup"), emoji=options.get("emoji"),
                highlight=options.get("highlight"))])

    target = stream if stream is not None else sys.stdout
    is_terminal = getattr(target, "isatty", lambda: False)()
    return _Console(file=stream, highlight=False, width=None if is_terminal else PIPE_WIDTH)


#: No-break spaces (a number's thousands separators among them) -> letters of the
#: Private Use Area, each one cell wide as they are, that hold them while rich finds
#: where to break a line: rich breaks at every Unicode space, no-break ones too.
_HELD = {"\u00a0": "\ue000", "\u2007": "\ue001", "\u202f": "\ue002"}
_HOLD = str.maketrans(_HELD)
_RELEASE = str.maketrans({held: space for space, held in _HELD.items()})


def numbers_whole(text: Any) -> Any:
    """A rich Text that never breaks a line at a no-break space ("20\u202f000 h" stays
    on one line, in a table's cell and in a printed line), or ``text`` itself where it
    holds none."""
    if not any(space in text.plain for space in _HELD):
        return text
    from rich.measure import Measurement
    from rich.text import Text

    class _Whole(Text):
        def __rich_measure__(self, console: Any, options: Any) -> Measurement:
            # the narrowest a table may make it: its longest run between breakable spaces
            held = Text(self.plain.translate(_HOLD))
            return held.__rich_measure__(console, options)

        def wrap(self, console: Any, width: int, **options: Any) -> Any:
            held = self.copy()
            held.plain = self.plain.translate(_HOLD)
            lines = Text.wrap(held, console, width, **options)
            for line in lines:
                line.plain = line.plain.translate(_RELEASE)
            return lines

    whole = _Whole(text.plain, style=text.style, justify=text.justify,
                   overflow=text.overflow, no_wrap=text.no_wrap, end=text.end,
                   tab_size=text.tab_size)
    whole.spans[:] = text.spans
    return whole


def print_whole(out: Any, text: str) -> None:
    """Print a line that names a file (a report's heading) whole: rich never breaks it,
    however long the file's path (a terminal folds a line wider than itself), so that
    the name reads and copies as it is."""
    out.print(text, soft_wrap=True)


def safe_text(text: str) -> str:
    """Spec-supplied text made safe for a rich table: no control characters, no markup."""
    from rich.markup import escape

    return escape(printable(text))


def format_number(value: float) -> str:
    """Seven significant digits; exact zero stays 0."""
    if value == 0:
        return "0"
    return f"{value:.7g}"
