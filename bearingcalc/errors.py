"""The package's exception family. Only the CLI turns these into exit codes."""

from __future__ import annotations


class BearingcalcError(Exception):
    """Base of every error bearingcalc reports to the user."""


class SpecError(BearingcalcError):
    """A spec that cannot be read or is invalid.

    Renders as one line: ``path:line: field: what is wrong, what would be right``.
    """

    def __init__(self, message: str, *, source: str = "<spec>", line: int | None = None,
                 field: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.source = source
        self.line = line
        self.field = field
        #: Further problems of the same spec, each a line of its own.
        self.more: list[SpecError] = []

    def lines(self) -> list[str]:
        """Every problem, one line each: this one first, then ``more``."""
        return [str(self), *(str(other) for other in self.more)]

    def __str__(self) -> str:
        where = self.source if self.line is None else f"{self.source}:{self.line}"
        what = f"{self.field}: {self.message}" if self.field else self.message
        return f"{where}: {what}"


class SpecFieldError(Exception):
    """Raised by spec models' physics checks to blame one field.

    It deliberately does not derive from ValueError: pydantic then lets it pass
    through unchanged, and the loader attaches file and line.
    """

    def __init__(self, field: str, message: str, *, at: str | None = None) -> None:
        super().__init__(message)
        self.field = field
        self.message = message
        #: The key whose line the problem belongs to when ``field`` is missing from the
        #: spec (a missing contamination_factor belongs to the lubrication block).
        self.at = at
        #: Further problems of the same spec, found by other rules.
        self.more: list[SpecFieldError] = []


class OptionError(SpecError):
    """A bad value of a command's option (``--vary``, ``--max-width``), found by
    bearingcalc rather than by the command line's parser.

    The command line says it as the parser says its own problems, in one line:
    ``bearingcalc sweep: Invalid value for '--vary' / '-v': MESSAGE (see 'bearingcalc
    sweep -h')``. Elsewhere it reads as a SpecError: ``source: --vary: MESSAGE``.
    """

    def __init__(self, option: str, message: str, *, source: str = "<options>") -> None:
        super().__init__(message, source=source, field=option)
        self.option = option
