"""Writing output files atomically, so a failed run never leaves half a report."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import IO


def atomic_write(path: str | Path, write: Callable[[IO[str]], None]) -> None:
    """Call ``write`` on a temporary file beside ``path``, then rename it over ``path``.

    If ``write`` raises (or the process is interrupted) the temporary file is
    removed and an existing ``path`` is left exactly as it was.
    """
    target = Path(path)
    if target.exists() and not target.is_file():
        # /dev/null, /dev/stdout, a FIFO: nothing to protect, and nothing to rename over.
        with open(target, "w", encoding="utf-8", newline="") as stream:
            write(stream)
        return
    handle = tempfile.NamedTemporaryFile(  # noqa: SIM115 - closed below, renamed on success
        "w", encoding="utf-8", newline="", dir=target.parent or ".",
        prefix=f".{target.name}.", suffix=".tmp", delete=False)
    try:
        with handle:
            write(handle)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(handle.name, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(handle.name)
        raise
