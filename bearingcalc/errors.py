"""The package's exception family. Only the CLI turns these into exit codes."""

from __future__ import annotations

from dataclasses import dataclass


class BearingcalcError(Exception):
    """Base of every error bearingcalc reports to the user."""


@dataclass(frozen=True)
class Problem:
    """One problem of a spec, as data: the file, its line (None where the problem is
    the file's as a whole), the field (None where no field is at fault) and the message.
    ``str()`` of it is the line the command line prints."""

    file: str
    line: int | None
    field: str | None
    message: str

    def __str__(self) -> str:
        where = self.file if self.line is None else f"{self.file}:{self.line}"
        what = f"{self.field}: {self.message}" if self.field else self.message
        return f"{where}: {what}"


class SpecError(BearingcalcError):
    """A spec that cannot be read or is invalid: every problem found, the first of them
    in ``message``, ``source``, ``line`` and ``field``, the others in ``more``.

    Each problem renders as one line, ``path:line: field: what is wrong, what would be
    right``; ``str()`` is every line, ``lines()`` the lines as a list and ``problems``
    the problems as data (:class:`Problem`).
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

    @property
    def first(self) -> Problem:
        """The first problem alone (the one ``message``, ``line`` and ``field`` give)."""
        return Problem(self.source, self.line, self.field, self.message)

    @property
    def problems(self) -> list[Problem]:
        """Every problem, this one first, then those of ``more`` (and of theirs)."""
        return [self.first, *(problem for other in self.more for problem in other.problems)]

    def lines(self) -> list[str]:
        """Every problem, one line each: this one first, then ``more``."""
        return [str(problem) for problem in self.problems]

    def __str__(self) -> str:
        return "\n".join(self.lines())


class ArgumentError(SpecError, ValueError):
    """An argument of a function of :mod:`bearingcalc.api` that is of the wrong type or
    value: ``source`` is the function (``'tolerance()'``), ``field`` the argument. It is
    a SpecError, so that one ``except`` catches every bad input, and a ValueError."""

    def __init__(self, function: str, argument: str, message: str) -> None:
        super().__init__(message, source=f"{function}()", field=argument)


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
