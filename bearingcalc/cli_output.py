"""Where the command line's output goes: reports to stdout or to files written all or
none, plots beside them, a progress bar on stderr, every error as one line on stderr
with the exit status that goes with it, and the help that lists the kinds.

The commands in ``bearingcalc.cli`` decide what to write; this module decides how.
It never imports the CLI.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import traceback
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any, BinaryIO, TypeVar

import typer
from typer.core import TyperCommand, TyperGroup

from bearingcalc import reads
from bearingcalc.errors import OptionError, SpecError
from bearingcalc.output import StagedFiles, Target, check_targets, reason
from bearingcalc.wording import printable

if TYPE_CHECKING:
    import click

T = TypeVar("T")

#: Writes one report onto a stream: text, or bytes for a binary format (Parquet).
Writer = Callable[[IO[Any]], None]

EXIT_OK, EXIT_LIMIT, EXIT_INVALID = 0, 1, 2
#: Interrupted (Ctrl-C): the shell's 128 + SIGINT.
EXIT_INTERRUPTED = 130
#: A closed output pipe whose run's status is unknown: the shell's 128 + SIGPIPE.
EXIT_BROKEN_PIPE = 141


class StdoutError(Exception):
    """Standard output could not be written (a full disk, a failing device)."""


def output_target(output: Path | None, holds: str, suffix: str) -> Target | None:
    """The file ``--output`` names, holding ``holds`` (like ``report``); ``suffix`` is
    that of the file name suggested when it is refused."""
    return None if output is None else Target(output, "--output", holds, suffix)


def check_plot_name(plot: Path | None) -> None:
    """Refuse a ``--plot`` that names neither a PNG nor an SVG file."""
    if plot is not None and plot.suffix.lower() not in (".png", ".svg"):
        raise OptionError("--plot", f"{str(plot)!r}: give a .png or .svg file name",
                          source=str(plot))


def check_parquet_output(spec_path: Path, output: Path | None) -> None:
    """Refuse Parquet output without a file to write or without pyarrow, the optional
    extra that writes it."""
    if output is None:
        raise OptionError("--format", "parquet writes a file: give --output grid.parquet",
                          source=str(spec_path))
    try:
        import pyarrow  # noqa: F401
    except ImportError:
        raise SpecError("Parquet output needs pyarrow, the optional extra: pip install "
                        "'bearingcalc[parquet]'", source=str(output)) from None


def plot_target(plot: Path | None) -> Target | None:
    return None if plot is None else Target(plot, "--plot", "plot", plot.suffix.lower())


def refuse_unwritable(command: str, specs: Iterable[Path], *targets: Target | None) -> None:
    """Refuse, before any work, an output that cannot be written or would replace an input:
    one of ``specs``, or the catalogue ``--catalogue`` or ``BEARINGCALC_CATALOGUE`` names
    (an input of every spec that names none, whether or not one does). A file found only
    in the work (a catalogue a spec names) is refused by ``StagedFiles`` once it is read.
    """
    from bearingcalc.catalogue.places import default_catalogue

    for spec in specs:
        reads.note(spec, "spec")
    catalogue = default_catalogue()
    if catalogue is not None:
        reads.note(catalogue, "catalogue")
    check_targets([target for target in targets if target is not None], command)


def stage_plot(files: StagedFiles, plot: Target, draw: Callable[[BinaryIO, str], None]
               ) -> None:
    """Draw a picture into ``plot`` among ``files``, in the format its suffix names."""
    files.add(plot, lambda stream: draw(stream, plot.path.suffix[1:].lower()), binary=True)


def emit(write: Writer, output: Target | None, files: StagedFiles, *,
         binary: bool = False) -> None:
    """Write a report to ``output`` among ``files`` (as bytes when ``binary``), or to
    stdout when there is no ``output``."""
    if output is None:
        write_stdout(write)
    else:
        files.add(output, write, binary=binary)


def write_stdout(write: Writer) -> None:
    """Write a report to stdout; a write error other than a closed pipe is the run's error."""
    try:
        write(sys.stdout)
        sys.stdout.flush()
    except BrokenPipeError:
        # The reader left (| head): stop writing, but keep the run's exit status,
        # which says whether the specs passed.
        silence_stdout()
    except OSError as error:
        silence_stdout()
        raise StdoutError(reason(error)) from None


def silence_stdout() -> None:
    """Point stdout at /dev/null, so the flush at exit does not fail a second time."""
    try:
        stdout = sys.stdout.fileno()
    except (OSError, ValueError):
        return  # not a file descriptor (a captured stream): nothing is flushed to it at exit
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, stdout)
    os.close(devnull)


def with_progress(work: Callable[[Callable[[int], None] | None], T], total: int | None = None,
                  label: str = "checking") -> T:
    """Run ``work`` with a progress callback drawing a bar on stderr, when it is a terminal.

    The bar is transient and shows after a second, so quick runs print nothing extra.
    """
    if not sys.stderr.isatty():
        return work(None)
    import time

    from rich.console import Console
    from rich.progress import Progress

    started = time.monotonic()
    with Progress(console=Console(stderr=True), transient=True, auto_refresh=False) as bar:
        task = bar.add_task(label, total=total)

        def tick(count: int) -> None:
            bar.advance(task, count)
            if time.monotonic() - started > 1.0:
                bar.refresh()

        return work(tick)


def bad_option(option: str, message: str) -> Exception:
    """The usage error of a bad value of the running command's ``option`` (like
    ``--vary``, or an argument's metavar ``KIND``), said as the parser says its own:
    ``bearingcalc sweep: Invalid value for '--vary' / '-v': MESSAGE (see 'bearingcalc
    sweep -h')`` (:class:`OneLineUsageErrors`)."""
    context = _current_context()
    params = context.command.params if context is not None else []
    param = next((p for p in params if option in p.opts or option == p.metavar), None)
    hint = None if param is not None else f"'{option}'"
    return typer.BadParameter(message, ctx=context, param=param, param_hint=hint)


def _current_context() -> Any:
    """The running command's context, from the click that typer runs on: its own copy
    in newer typer, click itself in older."""
    import importlib

    for name in ("typer._click.globals", "click.globals"):
        try:
            module = importlib.import_module(name)
        except ImportError:
            continue
        context = module.get_current_context(silent=True)
        if context is not None:
            return context
    return None


def print_error(error: Exception) -> None:
    """``error`` on stderr: a spec's problems one per line, anything else as one line."""
    lines = error.lines() if isinstance(error, SpecError) else [f"error: {error}"]
    # Control characters from a spec are shown as escapes, never sent to the terminal.
    print("\n".join(printable(line) for line in lines), file=sys.stderr)


class _CtrlC:
    """Python's own Ctrl-C (a KeyboardInterrupt where the main thread is), remembering
    that it came: a compiled module whose import Ctrl-C cuts short raises an ImportError
    of its own that keeps no trace of the interruption."""

    pressed = False

    @classmethod
    def install(cls) -> bool:
        """Take Ctrl-C over for this command's run, where Python's own handler has it
        (a run in a thread of another program's, or under its handler, keeps that
        program's); whether it did."""
        if threading.current_thread() is not threading.main_thread() or (
                signal.getsignal(signal.SIGINT) is not signal.default_int_handler):
            return False
        cls.pressed = False
        signal.signal(signal.SIGINT, cls._handle)
        return True

    @classmethod
    def uninstall(cls) -> None:
        """Give Ctrl-C back to Python's own handler, forgetting that it came."""
        signal.signal(signal.SIGINT, signal.default_int_handler)
        cls.pressed = False

    @classmethod
    def _handle(cls, signum: int, frame: Any) -> None:
        cls.pressed = True
        signal.default_int_handler(signum, frame)


def _interrupted(exc: BaseException, watched: bool = False) -> bool:
    """Whether Ctrl-C caused ``exc``: a KeyboardInterrupt, an error raised while one was
    handled (a library imported during Ctrl-C may turn it into an ImportError), or, where
    this run ``watched`` Ctrl-C, any error after it was pressed."""
    if watched and _CtrlC.pressed:
        return True
    seen: set[int] = set()
    current: BaseException | None = exc
    while current is not None and id(current) not in seen:
        if isinstance(current, KeyboardInterrupt):
            return True
        seen.add(id(current))
        current = current.__cause__ or current.__context__
    return False


class errors_as_exit:
    """A command's run: turns any unexpected exception into one line on stderr and exit
    status 2 (an interruption and a closed output pipe get the shell's statuses for
    them), and keeps the files the run reads (:mod:`bearingcalc.reads`), which no
    output may replace."""

    def __init__(self, debug: bool) -> None:
        self.debug = debug
        self._reads = reads.tracking()

    def __enter__(self) -> None:
        self._took_ctrl_c = _CtrlC.install()
        self._reads.__enter__()
        if self.debug:  # also the errors that specs' runs catch and go on after
            from bearingcalc.evaluation import show_tracebacks

            show_tracebacks(True)

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: object) -> bool:
        self._reads.__exit__(None, None, None)
        if self.debug:
            from bearingcalc.evaluation import show_tracebacks

            show_tracebacks(False)
        interrupted = exc is not None and _interrupted(exc, self._took_ctrl_c)
        if self._took_ctrl_c:
            _CtrlC.uninstall()
        if exc is None or isinstance(exc, (typer.Exit, typer.Abort, SystemExit)):
            return False
        if interrupted:
            print("interrupted", file=sys.stderr)
            raise typer.Exit(EXIT_INTERRUPTED)
        if isinstance(exc, BrokenPipeError):
            silence_stdout()
            raise typer.Exit(EXIT_BROKEN_PIPE)
        if isinstance(exc, StdoutError):
            print(f"cannot write the output: {exc}", file=sys.stderr)
            raise typer.Exit(EXIT_INVALID)
        if isinstance(exc, OptionError):
            raise bad_option(exc.option, exc.message) from None
        if self.debug:
            traceback.print_exception(exc)
        if isinstance(exc, SpecError):
            print_error(exc)
        else:
            print(f"internal error: {type(exc).__name__}: {exc} "
                  "(run again with --debug for the traceback, and please report it)",
                  file=sys.stderr)
        raise typer.Exit(EXIT_INVALID)


class _WordedParameters:
    """Help that names a parameter's value in words, not by the parser's types: an
    option's value by its metavar (``FILE``, ``N``), a flag by none."""

    params: list[Any]

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        for param in self.params:
            _quiet_type(param)

    def get_help_option(self, ctx: click.Context) -> Any:
        option = super().get_help_option(ctx)  # type: ignore[misc]
        if option is not None:
            _quiet_type(option)
        return option


class WordedHelp(_WordedParameters, TyperCommand):
    """A command whose help speaks in words, and whose usage line names the arguments
    as the help does: ``[OPTIONS] SPEC...``."""

    def collect_usage_pieces(self, ctx: click.Context) -> list[str]:
        pieces = [self.options_metavar] if self.options_metavar else []
        for param in self.get_params(ctx):
            if param.param_type_name == "argument":
                word = param.metavar or (param.name or "").upper()
                word += "..." if param.nargs != 1 and not word.endswith("...") else ""
                pieces.append(word if param.required else f"[{word}]")
        return pieces


def _quiet_type(param: Any) -> None:
    """Show a flag with no value, and an argument by its metavar alone.

    Newer typer names the Python type beside a parameter (``<bool>``,
    ``<list[Path]>``); a flag's empty metavar replaces it, and an argument's metavar
    already says what it is.
    """
    if getattr(param, "is_flag", False) and param.metavar is None:
        param.metavar = ""
    if param.param_type_name == "argument" and hasattr(param, "display_type_rich"):
        param.display_type_rich = lambda ctx: None


class HelpListsKinds(WordedHelp):
    """A command whose ``--help`` ends with every registered kind and its summary.

    The list is read from the registry when the help is shown, so a new kind appears
    in it without an edit to the command, and a run that shows no help never builds it.
    It is a table of its own, so a summary that wraps stays in its column.
    """

    def format_help(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        from rich import box
        from rich.console import Console
        from rich.panel import Panel
        from rich.table import Table

        from bearingcalc.kinds import KINDS

        super().format_help(ctx, formatter)
        kinds = Table.grid(padding=(0, 2))
        kinds.add_column(style="bold cyan", no_wrap=True)
        kinds.add_column()
        for name, kind in KINDS.items():
            kinds.add_row(name, kind.summary)
        kinds.add_row("", "")
        kinds.add_row("", "'bearingcalc new KIND' prints a commented template spec of KIND.")
        # as wide as typer draws the panels above it
        width = os.environ.get("TERMINAL_WIDTH")
        console = Console(width=int(width) if width and width.isdigit() else None)
        console.print(Panel(kinds, title="Kinds (a spec's 'kind:')", title_align="left",
                            border_style="dim", box=box.ROUNDED))


class OneLineUsageErrors(_WordedParameters, TyperGroup):
    """The command group whose help speaks in words (:class:`WordedHelp`), and whose
    usage errors (an unknown option, a missing argument, a
    bad option value) are one line on stderr with exit status 2, as every other error
    is: no usage block, no box."""

    def main(self, *args: Any, standalone_mode: bool = True, **kwargs: Any) -> Any:
        if not standalone_mode:
            return super().main(*args, standalone_mode=False, **kwargs)
        try:
            status = super().main(*args, standalone_mode=False, **kwargs)
        except Exception as error:
            # click's exceptions (typer may carry its own copy of click): by their kind
            kinds = {cls.__name__ for cls in type(error).__mro__}
            if "Abort" in kinds:
                print("bearingcalc: stopped", file=sys.stderr)
                sys.exit(130)
            if "ClickException" not in kinds:
                raise
            context = getattr(error, "ctx", None)
            if "NoArgsIsHelpError" in kinds and context is not None:  # bare: its help
                print(context.get_help())
                sys.exit(EXIT_INVALID)
            where = context.command_path if context is not None else "bearingcalc"
            message = printable(error.format_message())  # type: ignore[attr-defined]
            if "UsageError" in kinds:
                print(f"{where}: {message} (see '{where} -h')", file=sys.stderr)
                sys.exit(EXIT_INVALID)
            print(f"{where}: {message}", file=sys.stderr)
            sys.exit(getattr(error, "exit_code", EXIT_INVALID))
        sys.exit(status if isinstance(status, int) else EXIT_OK)
