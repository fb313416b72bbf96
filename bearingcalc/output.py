"""Writing output files atomically, so a failed run never leaves half a report."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import IO, Any


def atomic_write(path: str | Path, write: Callable[[IO[Any]], None], *,
                 binary: bool = False) -> None:
    """Call ``write`` on a temporary file beside ``path``, then rename it over ``path``.

    ``binary`` opens the file for bytes (pictures) instead of UTF-8 text.

    If ``write`` raises (or the process is interrupted) the temporary file is
    removed and an existing ``path`` is left exactly as it was.
    """
    # Write through a symbolic link to the file it names: replacing the link with a
    # file would cut whatever the link was there for.
    target = Path(os.path.realpath(path))
    mode, encoding, newline = _mode(binary)
    if target.exists() and not target.is_file():
        if target.is_dir():
            raise IsADirectoryError(21, "is a folder", str(path))
        # /dev/null, /dev/stdout, a FIFO: nothing to protect, and nothing to rename over.
        with open(target, mode, encoding=encoding, newline=newline) as stream:
            write(stream)
        return
    handle = tempfile.NamedTemporaryFile(  # noqa: SIM115 - closed below, renamed on success
        mode, encoding=encoding, newline=newline, dir=target.parent or ".",
        prefix=f".{target.name}.", suffix=".tmp", delete=False)
    try:
        with handle:
            write(handle)
            handle.flush()
            os.fsync(handle.fileno())
        # Temporary files are private (0600); give the report the mode a new file gets.
        os.chmod(handle.name, _new_file_mode(target))
        os.replace(handle.name, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(handle.name)
        raise


def _mode(binary: bool) -> tuple[str, str | None, str | None]:
    return ("wb", None, None) if binary else ("w", "utf-8", "")


def _new_file_mode(target: Path) -> int:
    if target.exists():
        return target.stat().st_mode & 0o777
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask
