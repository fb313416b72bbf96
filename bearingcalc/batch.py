"""Batch checking: find spec files, give every spec one status, use both cores.

Statuses: ``pass`` (valid and within its limits), ``fail`` (valid, a limit is
violated) and ``invalid`` (cannot be read or validated). One bad file never
stops the batch.
"""

from __future__ import annotations

import fnmatch
import glob
import os
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from bearingcalc import reads
from bearingcalc.errors import SpecError
from bearingcalc.evaluation import (
    Evaluation,
    evaluate_documents,
    load_selected,
    note_internal_error,
)
from bearingcalc.models.yaml_loader import Document, is_spec_file
from bearingcalc.verdicts import Verdict

PASS, FAIL, INVALID = "pass", "fail", "invalid"
#: Below this many files a worker pool costs more than it saves.
PARALLEL_THRESHOLD = 400


@dataclass
class CheckRecord:
    """The verdict on one spec (one document of a file)."""

    spec: str
    kind: str | None
    name: str | None
    status: str
    messages: list[str] = field(default_factory=list)
    margins: dict[str, float] = field(default_factory=dict)
    #: every limit judged, the worst first (each margin a fraction of its limit)
    verdicts: list[Verdict] = field(default_factory=list)
    #: the catalogue row of each bearing taken from one (see Evaluation.sources)
    sources: dict[str, str] = field(default_factory=dict)

    @property
    def governing_margin(self) -> tuple[str, float] | None:
        """The margin that decides pass or fail: the smallest as a fraction of its limit
        where the kind says what it judges, else the smallest."""
        if self.verdicts:
            return self.verdicts[0].key, self.margins[self.verdicts[0].key]
        if not self.margins:
            return None
        key = min(self.margins, key=self.margins.__getitem__)
        return key, self.margins[key]


def discover(paths: Sequence[str | Path]) -> list[Path | CheckRecord]:
    """Spec files named by ``paths`` in order, with an invalid record where a path names none.

    A path is a file (taken whatever its suffix), a folder (searched recursively
    for ``*.yaml`` and ``*.yml``, skipping hidden folders) or a glob pattern
    (``**`` spans folders). Neither folders nor globs follow symbolic links to
    folders, so links cannot loop or repeat a tree; a file reached twice (by two
    paths, or through a link) is checked once; a folder that cannot be read is an
    invalid record of its own. ``file.yaml#N`` names one document of a file.
    """
    entries: list[Path | CheckRecord] = []
    seen: set[str] = set()

    def add(found: Iterable[Path]) -> None:
        for path in found:
            real = os.path.realpath(path)
            if real not in seen:
                seen.add(real)
                entries.append(path)

    for raw in paths:
        path = Path(raw)
        problems: list[CheckRecord] = []
        if path.is_dir():
            found = sorted(_walk(path, problems))
            if not found and not problems:
                entries.append(_invalid(str(path), "no spec files (*.yaml, *.yml) in this "
                                        "folder"))
            add(found)
        elif path.exists() or path.is_symlink():
            add([path])
        elif glob.has_magic(str(raw)):
            found = sorted(_glob(str(raw), problems))
            if not found and not problems:
                entries.append(_invalid(str(raw), "the pattern matches no file"))
            add(found)
        elif _document_path(str(raw)) is not None:
            entries.append(Path(raw))
        else:
            entries.append(_invalid(str(raw), "no such file or folder; check the path"))
        entries.extend(problems)
    return entries


def _document_path(raw: str) -> Path | None:
    """The file of ``file.yaml#N`` when that file exists, else None."""
    head, sep, index = raw.rpartition("#")
    return Path(head) if sep and head and index and Path(head).is_file() else None


def spec_file(spec: str | Path) -> Path:
    """The file a spec argument reads: ``file.yaml`` for ``file.yaml#N`` (unless a file
    has that very name), else the argument itself, as ``evaluation.load_selected`` reads."""
    head, sep, _ = str(spec).rpartition("#")
    if sep and head and not Path(spec).exists() and Path(head).is_file():
        return Path(head)
    return spec if isinstance(spec, Path) else Path(spec)


def files_read(entries: Iterable[Path | CheckRecord]) -> list[Path]:
    """The files that checking ``entries`` (from ``discover``) reads."""
    return [spec_file(entry) for entry in entries if isinstance(entry, Path)]


def check_paths(paths: Sequence[str | Path], jobs: int = 1,
                progress: Callable[[int], None] | None = None) -> list[CheckRecord]:
    """Records for everything ``paths`` name, in the order they name it."""
    return check_entries(discover(paths), jobs, progress)


def check_entries(entries: Sequence[Path | CheckRecord], jobs: int = 1,
                  progress: Callable[[int], None] | None = None) -> list[CheckRecord]:
    """Records for the entries ``discover`` found, in their order."""
    files = [entry for entry in entries if isinstance(entry, Path)]
    checked = iter(check_files(files, jobs, progress))
    records: list[CheckRecord] = []
    for entry in entries:
        if isinstance(entry, CheckRecord):
            records.append(entry)
            continue
        records.extend(next(checked))
    return records


def _walk(folder: Path, problems: list[CheckRecord]) -> Iterable[Path]:
    for root, dirs, names in os.walk(folder, followlinks=False,
                                     onerror=_unreadable_folder(problems)):
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        for name in names:
            path = Path(root) / name
            if is_spec_file(path):
                yield path


def _unreadable_folder(problems: list[CheckRecord]) -> Callable[[OSError], None]:
    def record(error: OSError) -> None:
        problems.append(_invalid(str(error.filename), "cannot read the folder: "
                                 f"{error.strerror or error}; its specs were not checked"))
    return record


def _glob(pattern: str, problems: list[CheckRecord]) -> Iterable[Path]:
    """Files matching ``pattern`` (``*``, ``?``, ``[...]`` within a name, ``**`` across
    folders), found without following links to folders."""
    parts = Path(pattern).parts
    fixed = 0
    while fixed < len(parts) - 1 and not glob.has_magic(parts[fixed]):
        fixed += 1
    root = Path(*parts[:fixed]) if fixed else Path(".")
    wanted = parts[fixed:]
    if not root.is_dir():
        return
    deep = "**" in wanted
    for current, dirs, names in os.walk(root, followlinks=False,
                                        onerror=_unreadable_folder(problems)):
        relative = Path(current).relative_to(root).parts
        if not deep and len(relative) >= len(wanted) - 1:
            dirs[:] = []
        for name in names:
            if _matches((*relative, name), wanted):
                yield Path(current) / name


def _matches(names: tuple[str, ...], patterns: tuple[str, ...]) -> bool:
    """Whether path parts ``names`` match glob parts ``patterns`` (as glob.glob would,
    hidden names matching only patterns that start with a dot)."""
    if not patterns:
        return not names
    head = patterns[0]
    if head == "**":
        return _matches(names, patterns[1:]) or (
            bool(names) and not names[0].startswith(".") and _matches(names[1:], patterns))
    if not names or (names[0].startswith(".") and not head.startswith(".")):
        return False
    return fnmatch.fnmatchcase(names[0], head) and _matches(names[1:], patterns[1:])


def check_files(files: Sequence[Path], jobs: int = 1,
                progress: Callable[[int], None] | None = None) -> list[list[CheckRecord]]:
    """The records of every spec in each of ``files``, one list per file, in order.

    With ``jobs`` > 1 and enough files, files are shared among worker processes
    in chunks; the records come back in the same order either way.
    """
    records: list[list[CheckRecord]] = []
    if jobs <= 1 or len(files) < PARALLEL_THRESHOLD:
        for chunk in _chunks(files, 200):
            records.extend(check_chunk(chunk))
            if progress:
                progress(len(chunk))
        return records
    # Loaded here, not with the module: most runs (sweep, tolerance, small checks) start
    # no pool and would pay for these imports at every start.
    from concurrent.futures import ProcessPoolExecutor
    from multiprocessing import get_all_start_methods, get_context

    chunk_size = max(50, min(500, len(files) // (jobs * 4)))
    # fork shares the loaded modules with the workers: no second start-up per worker.
    context = get_context("fork") if "fork" in get_all_start_methods() else None
    from bearingcalc.catalogue.places import default_catalogue, set_default_catalogue

    # A worker that does not fork learns the command's --catalogue here.
    with ProcessPoolExecutor(max_workers=jobs, mp_context=context,
                             initializer=set_default_catalogue,
                             initargs=(default_catalogue(),)) as pool:
        chunks = list(_chunks(files, chunk_size))
        for chunk, (result, read) in zip(chunks, pool.map(_check_chunk_noting_reads, chunks),
                                         strict=True):
            records.extend(result)
            reads.note_all(read)  # a worker's catalogues are files this run reads too
            if progress:
                progress(len(chunk))
    return records


def _check_chunk_noting_reads(files: Sequence[Path]
                              ) -> tuple[list[list[CheckRecord]], dict[str, str]]:
    """:func:`check_chunk` in a worker process, with the files it read."""
    with reads.tracking() as read:
        return check_chunk(files), read


def check_chunk(files: Sequence[Path]) -> list[list[CheckRecord]]:
    """Records of a list of files: every document loaded, then all solved together."""
    loaded: list[list[Document] | CheckRecord] = []
    for path in files:
        try:
            loaded.append(load_selected(path))
        except SpecError as error:
            loaded.append(CheckRecord(str(path), None, None, INVALID, error.lines()))
        except Exception as exc:  # one file's surprise never stops the batch
            note_internal_error(exc)
            loaded.append(_invalid(str(path), f"{path}: internal error ({type(exc).__name__}); "
                                   "please report it with this file"))
    documents = [doc for item in loaded if isinstance(item, list) for doc in item]
    outcomes = iter(evaluate_documents(documents))
    return [[item] if isinstance(item, CheckRecord) else [to_record(next(outcomes)) for _ in item]
            for item in loaded]


def to_record(outcome: Evaluation | SpecError) -> CheckRecord:
    """The check verdict of one evaluation or error."""
    if isinstance(outcome, SpecError):
        return CheckRecord(outcome.source, None, None, INVALID, outcome.lines())
    status = PASS if outcome.within_limits else FAIL
    return CheckRecord(outcome.source, outcome.kind, outcome.name, status,
                       [*outcome.violations, *outcome.warnings], dict(outcome.margins),
                       list(outcome.verdicts), dict(outcome.sources))


def exit_status(records: Iterable[CheckRecord]) -> int:
    """0 all pass; 1 some fail and none invalid; 2 any invalid."""
    statuses = {record.status for record in records}
    if INVALID in statuses or not statuses:
        return 2
    return 1 if FAIL in statuses else 0


def _invalid(spec: str, message: str) -> CheckRecord:
    return CheckRecord(spec, None, None, INVALID, [message])


def _chunks(items: Sequence[Path], size: int) -> Iterable[Sequence[Path]]:
    for start in range(0, len(items), size):
        yield items[start:start + size]

