"""Output files: refused when they would replace a file the run reads, written all or none.

``check_targets`` decides, before any work, whether each file a run will write can
be written; ``StagedFiles`` writes them so that a failed run leaves every one of
them as it was. Both refuse a file the run reads, as :mod:`bearingcalc.reads` has
noted them: the specs before any work, and whatever else the run read (a catalogue a
spec names, the environment's catalogue) once the work is done.
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import IO, Any

from bearingcalc import reads
from bearingcalc.errors import SpecError


@dataclass(frozen=True)
class Target:
    """A file a run writes, as the user named it."""

    path: Path
    #: The option that names it, like ``--output``.
    option: str
    #: What it holds, in messages: ``report``, ``results``, ``plot``.
    holds: str
    #: The suffix of a file name suggested instead of a refused one, like ``.csv``.
    suffix: str

    def error(self, message: str) -> SpecError:
        return SpecError(message, source=str(self.path), field=self.option)

    def cannot_write(self, why: str) -> SpecError:
        return self.error(f"cannot write the {self.holds}: {why}")


def reason(error: OSError) -> str:
    """The OS's words for ``error``, as the rest of a sentence: 'no space left on device'."""
    return (error.strerror or str(error)).lower()


def check_targets(targets: Sequence[Target], command: str) -> None:
    """Refuse a target that cannot be written or would replace a file the run reads.

    The files read are those noted in :mod:`bearingcalc.reads` so far. A target is the
    same file as one of them, or as another target, when both resolve to the same real
    path or the same device and inode (``..``, symbolic links, hard links); a target
    that does not exist yet replaces nothing. Devices and FIFOs are written directly
    and never replace a file. ``command`` names the suggested file
    (``drive-sweep.csv``). Raises SpecError.
    """
    files = [_FileId.of(target.path) for target in targets]
    for index, (target, file) in enumerate(zip(targets, files, strict=True)):
        if not file.replaceable:
            continue
        problem = _unwritable(target, file)
        if problem:
            raise target.cannot_write(problem)
        for earlier, earlier_file in zip(targets[:index], files[:index], strict=True):
            if file.same_as(earlier_file):
                raise target.error(f"names the same file as {earlier.option}; give each "
                                   "its own file")
    refuse_replacing_reads(list(zip(targets, files, strict=True)), command)


def refuse_replacing_reads(targets: Sequence[tuple[Target, _FileId]], command: str) -> None:
    """Refuse any of ``targets`` (each with where it leads) that is a file the run has
    read (:func:`bearingcalc.reads.noted`): a spec, a catalogue, any file at all."""
    existing = [(target, file) for target, file in targets
                if file.replaceable and file.key is not None]
    if not existing:
        return
    for path, holds in reads.noted().items():
        # The same inode is the same file, and one stat per input finds it; the real path
        # costs a stat per folder of the path, so it is compared only without an inode.
        try:
            status = os.stat(path)
            read = _FileId(None, (status.st_dev, status.st_ino), status.st_mode)
        except OSError:
            read = _FileId(os.path.realpath(path), None, None)
        for target, file in existing:
            if file.same_as(read):
                instead = f"{Path(path).stem}-{command}{target.suffix}"
                raise target.error(f"would replace the {holds} {path} that this run "
                                   f"reads; write the {target.holds} to another file, "
                                   f"like {instead}")


@dataclass(frozen=True)
class _FileId:
    """Where a path leads: its real path, and its device and inode when it exists."""

    real: str | None
    key: tuple[int, int] | None
    mode: int | None

    @classmethod
    def of(cls, path: Path) -> _FileId:
        real = os.path.realpath(path)
        try:
            status = os.stat(real)
        except OSError:
            return cls(real, None, None)
        return cls(real, (status.st_dev, status.st_ino), status.st_mode)

    @property
    def replaceable(self) -> bool:
        """A regular file, a folder or nothing yet: anything but a device or a FIFO."""
        return self.mode is None or stat.S_ISREG(self.mode) or stat.S_ISDIR(self.mode)

    def same_as(self, other: _FileId) -> bool:
        return ((self.real is not None and self.real == other.real)
                or (self.key is not None and self.key == other.key))


def _unwritable(target: Target, file: _FileId) -> str | None:
    """Why ``target`` cannot be written, or None."""
    if file.mode is not None and stat.S_ISDIR(file.mode):
        example = target.path / f"{target.holds}{target.suffix}"
        return f"it is a folder; name a file in it, like {example}"
    # Name the folder as the user wrote it, unless a link leads elsewhere.
    folder = Path(file.real).parent
    shown = folder if os.path.islink(target.path) else target.path.parent
    try:
        mode = os.stat(folder).st_mode
    except FileNotFoundError:
        return f"the folder {shown} does not exist; create it first or choose another"
    except OSError as error:
        return f"{shown}: {reason(error)}"
    if not stat.S_ISDIR(mode):
        return f"{shown} is a file, not a folder"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"the folder {shown} does not allow new files (permission denied)"
    return None


class StagedFiles:
    """Output files written all or none.

    ``add`` writes each file to a temporary file beside it; when the ``with`` block
    ends without an error every one is renamed into place, and on any error (even
    while renaming) every temporary file is removed and every target is left as it
    was. A link is written through: the file it names is replaced and the link stays.
    Devices and FIFOs (/dev/null, /dev/stdout, a pipe) have nothing to protect or to
    rename over: they are written directly, once every file has been staged. Before
    anything is renamed or written, a target that is a file the run has read (noted
    in :mod:`bearingcalc.reads`, however late the run read it) is refused, and the
    file is left as it was; ``command`` names the file suggested instead.
    """

    def __init__(self, command: str) -> None:
        self.command = command
        self._staged: list[tuple[Target, str, Path]] = []
        self._direct: list[tuple[Target, Path, Callable[[IO[Any]], None], bool]] = []

    def __enter__(self) -> StagedFiles:
        return self

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: object) -> None:
        if exc is None:
            self._commit()
        else:
            self._discard()

    def add(self, target: Target, write: Callable[[IO[Any]], None], *,
            binary: bool = False) -> None:
        """Call ``write`` on the file that will become ``target`` (bytes when ``binary``,
        else UTF-8 text); raises SpecError when it cannot be written."""
        real = Path(os.path.realpath(target.path))
        if not _FileId.of(real).replaceable:
            self._direct.append((target, real, write, binary))
            return
        try:
            temporary = _write_temporary(real, write, binary)
        except OSError as error:
            raise target.cannot_write(reason(error)) from None
        self._staged.append((target, temporary, real))

    def _commit(self) -> None:
        try:
            refuse_replacing_reads([(target, _FileId.of(real))
                                    for target, _, real in self._staged], self.command)
            for target, real, write, binary in self._direct:
                mode, encoding, newline = _mode(binary)
                try:
                    with open(real, mode, encoding=encoding, newline=newline) as stream:
                        write(stream)
                except OSError as error:
                    raise target.cannot_write(reason(error)) from None
            self._rename_all()
        finally:
            self._discard()

    def _rename_all(self) -> None:
        """Rename every staged file into place. A file about to be replaced is first kept
        under a second name beside it (a hard link), so that when a later rename fails,
        the files already renamed are put back (or removed, where there was none)."""
        kept: list[str] = []
        undo: list[tuple[Path, str | None]] = []  # a renamed target and its former file
        try:
            while self._staged:
                target, temporary, real = self._staged[0]
                existed = real.exists()
                former = _keep_aside(real, temporary) if existed else None
                if former is not None:
                    kept.append(former)
                try:
                    # Temporary files are private (0600); give the file the mode a new
                    # file gets, or the mode of the file it replaces.
                    os.chmod(temporary, _new_file_mode(real))
                    os.replace(temporary, real)
                except OSError as error:
                    raise target.cannot_write(reason(error)) from None
                self._staged.pop(0)
                if former is not None or not existed:
                    undo.append((real, former))
        except BaseException:
            for real, former in reversed(undo):
                with contextlib.suppress(OSError):
                    if former is None:
                        os.unlink(real)
                    else:
                        os.replace(former, real)
            raise
        finally:
            for former in kept:
                _remove(former)

    def _discard(self) -> None:
        for _, temporary, _ in self._staged:
            _remove(temporary)
        self._staged.clear()
        self._direct.clear()


def _write_temporary(target: Path, write: Callable[[IO[Any]], None], binary: bool) -> str:
    """The name of a temporary file beside ``target`` holding what ``write`` wrote;
    nothing is left behind when ``write`` fails or the run is interrupted."""
    mode, encoding, newline = _mode(binary)
    handle = tempfile.NamedTemporaryFile(  # noqa: SIM115 - closed below, renamed on commit
        mode, encoding=encoding, newline=newline, dir=target.parent,
        prefix=f".{target.name}.", suffix=".tmp", delete=False)
    try:
        with handle:
            write(handle)
            handle.flush()
            os.fsync(handle.fileno())
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(handle.name)
        raise
    return handle.name


def _keep_aside(target: Path, temporary: str) -> str | None:
    """A second name for ``target``, beside it, or None where hard links cannot be made
    (then the file cannot be put back)."""
    aside = temporary.removesuffix(".tmp") + ".old"
    try:
        os.link(target, aside)
    except OSError:
        return None
    return aside


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.unlink(path)


def _mode(binary: bool) -> tuple[str, str | None, str | None]:
    return ("wb", None, None) if binary else ("w", "utf-8", "")


def _new_file_mode(target: Path) -> int:
    if target.exists():
        return target.stat().st_mode & 0o777
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask
