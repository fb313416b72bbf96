"""The files a run reads, so that no file the run writes replaces one of them.

Every reader notes the file it opens (a spec, a catalogue, a table shipped with the
package) with :func:`note`, and ``bearingcalc.output`` refuses an output that is the
same file as any noted one. Notes are kept only inside :func:`tracking` (a command's
run): outside it, as in the Python API, noting keeps nothing, so that a long session
never compares an output with files read long before.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator, Mapping

#: The runs being tracked, innermost last: each maps a file, as it was named, to what
#: it holds in messages ('spec', 'catalogue').
_RUNS: list[dict[str, str]] = []


def note(path: str | os.PathLike[str], holds: str) -> None:
    """Note that the run reads ``path``, a file holding ``holds`` (``'catalogue'``)."""
    if _RUNS:
        _RUNS[-1].setdefault(os.fspath(path), holds)


def note_all(files: Mapping[str, str]) -> None:
    """Note every file of ``files`` (what :func:`tracking` gave a worker process)."""
    for path, holds in files.items():
        note(path, holds)


def noted() -> dict[str, str]:
    """The files the tracked run has read so far, each with what it holds."""
    return dict(_RUNS[-1]) if _RUNS else {}


@contextlib.contextmanager
def tracking() -> Iterator[dict[str, str]]:
    """Keep the notes of the files read inside the block, in the dict it gives."""
    files: dict[str, str] = {}
    _RUNS.append(files)
    try:
        yield files
    finally:
        # by identity: another run's notes may be equal to these
        del _RUNS[next(i for i, run in enumerate(_RUNS) if run is files)]
