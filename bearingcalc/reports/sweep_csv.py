"""The sweep's CSV: one row per point, the varied inputs, every result (SI, units in the
header) and the reason a point is impossible (empty results then).

The rows are formatted a block of ``BLOCK_ROWS`` at a time: one ``orjson`` call
writes every number of the block (shortest round-trip form; ``null`` for a number
that is not finite), and a few passes over the block's bytes turn that into CSV
lines, with no work per line. Formatting a million rows is the cost of a large
sweep, and Python's float formatting would take several times as long.

The result is byte for byte what a writer line by line gives (``tests/test_sweep.py``
keeps one to compare): each row formatted by ``orjson`` alone, ``null`` emptied, a
whole-number input's ``.0`` dropped, then ``,`` and the reason, or ``,`` alone. The
block path equals it because:

- ``orjson`` writes a number the same alone or inside a 2-D array, and writes the
  array as ``[[a,b],[c,d]]`` with no spaces; no number's text holds ``[``, ``]``,
  ``,`` or a line end. So deleting ``]`` and making ``[`` a line end ends every row
  but the last in ``,`` and a line end: a possible design's line, empty reason
  included. The last row ends in ``]]`` instead: its ending is a piece of its own.
- An impossible design's results are all NaN and its inputs finite, as a sweep
  gives them. Its first result is set to its status code before formatting, so its
  row ends ``,<code>.0,null,…,null,`` and a line end, with one ``null`` per further
  result. Led by a comma and anchored at a line end, that text can only be the
  row's results; it is replaced by empty fields and the reason, one pass per code
  present in the block.
- A possible design could end its row in the same text only with a status code as
  its first result and nothing finite after it; such a block, a block of no
  results (no field to carry the code) and a block where an impossible design has a
  finite result go the marked path, where the code rides in a last column of its
  own (``null`` for a possible design) and ``],[`` ends every row.
- ``null`` is emptied last, and only in a block where a possible design has a
  number that is not finite: before that, the impossible rows' ``null`` had to be
  there to be found.
- The reasons are fixed sentences of the solvers (CSV-quoted when they need it):
  none holds another code's row end.
- Whole-number inputs lose their ``.0`` by the same function in both writers, and
  a block ends with a line end, so blocks join as lines do.

The bytes are UTF-8, written straight to the text stream's buffer once the text
written before them (the header) is flushed.
"""

from __future__ import annotations

from typing import IO, TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from bearingcalc.reports.csv_cells import csv_text_field

if TYPE_CHECKING:  # the report type only; its module loads with the command
    from bearingcalc.sweeps import Sweep

#: Rows formatted at a time: large enough that the passes per block cost nothing per
#: row, small enough that a block's text stays a few megabytes.
BLOCK_ROWS = 50_000


def sweep_columns(sweep: Sweep) -> list[tuple[str, NDArray]]:
    """(header, values) of the CSV's numeric columns: the varied inputs, then every result."""
    # "input." keeps a varied input apart from the result of the same name.
    columns = [(f"input.{axis.name} [{axis.unit}]", sweep.inputs[axis.name])
               for axis in sweep.axes]
    units = sweep.units
    columns += [(f"{key} [{units[key]}]", values) for key, values in sweep.results.items()]
    return columns


def write_sweep_csv(sweep: Sweep, stream: IO[str]) -> None:
    """The sweep as CSV on ``stream``: a header line, then a line per point (see the
    module's docstring)."""
    columns = sweep_columns(sweep)
    stream.write(",".join(csv_text_field(name) for name in [*(name for name, _ in columns),
                                                             "reason"]) + "\n")
    integer_axes = [axis.integer for axis in sweep.axes]
    reasons = {code: ("," + csv_text_field(sweep.reason(code))).encode() for code in
               np.unique(sweep.status).tolist() if code}
    for start in range(0, len(sweep.status), BLOCK_ROWS):
        stop = min(start + BLOCK_ROWS, len(sweep.status))
        block = np.column_stack([values[start:stop].astype(float) for _, values in columns])
        pieces = _csv_block(block, sweep.status[start:stop], len(sweep.axes), reasons)
        if any(integer_axes):
            lines = [_integer_fields(line, integer_axes)
                     for line in b"".join(pieces).split(b"\n")[:-1]]
            pieces = [b"\n".join(lines) + b"\n"]
        for piece in pieces:
            _write_bytes(stream, piece)


#: Row by row, orjson's "[[a,b],[c,d]]" with "]" deleted and "[" made a line end: each
#: row then ends in "," and a line end, a possible design's row end exactly.
_ROWS = bytes.maketrans(b"[", b"\n")


def _csv_block(block: NDArray, codes: NDArray, inputs: int, reasons: dict[int, bytes]
               ) -> list[bytes | memoryview]:
    """CSV lines of a block of rows (the varied inputs, then the results) with their
    status codes, in passes over the whole block's text and none per line; in pieces,
    to be written one after the other without joining them. The module's docstring
    says why they are the line writer's lines, and which blocks go to
    :func:`_csv_block_marked` instead.
    """
    import orjson

    results = block.shape[1] - inputs
    impossible = codes != 0
    present = np.unique(codes[impossible]).tolist()
    finite = np.isfinite(block)
    if present and (results == 0 or finite[impossible, inputs:].any()
                    or _could_read_as_impossible(block[:, inputs:], finite[:, inputs:],
                                                 impossible, present)):
        return _csv_block_marked(block, codes, reasons)
    block[impossible, inputs] = codes[impossible]
    text = orjson.dumps(block, option=orjson.OPT_SERIALIZE_NUMPY).translate(_ROWS, b"]")
    # "[[" became two line ends, and the last row ends in "]]": it has no row end yet.
    # code -> (its row's results as written, the same as CSV: empty fields and the reason)
    blanks = {code: (b"," + repr(float(code)).encode() + b",null" * (results - 1),
                     b"," * results + reasons[code]) for code in present}
    for written, line in blanks.values():
        text = text.replace(written + b",\n", line + b"\n")
    last, ending = len(text), b",\n"
    if codes[-1]:
        written, line = blanks[int(codes[-1])]
        last, ending = last - len(written), line + b"\n"
    if not finite[~impossible].all():
        # Only now, so that the impossible rows' nulls above were still there to find.
        return [bytes(memoryview(text)[2:last]).replace(b"null", b""), ending]
    return [memoryview(text)[2:last], ending]


def _could_read_as_impossible(results: NDArray, finite: NDArray, impossible: NDArray,
                              codes: list[int]) -> bool:
    """Whether a possible design's results could end its row as an impossible one's:
    a code as its first result and nothing finite after it."""
    return bool((~impossible & np.isin(results[:, 0], codes)
                 & ~finite[:, 1:].any(axis=1)).any())


def _csv_block_marked(block: NDArray, codes: NDArray, reasons: dict[int, bytes]
                      ) -> list[bytes | memoryview]:
    """:func:`_csv_block` for any block: the status code rides along as a last column,
    so that ``,<code>],[`` ends every row and one pass per code present replaces it."""
    import orjson

    marker = np.where(codes == 0, np.nan, codes.astype(float))
    text = orjson.dumps(np.column_stack([block, marker]), option=orjson.OPT_SERIALIZE_NUMPY)
    body = text[2:-2].replace(b"],[", b"\n").replace(b"null", b"") + b"\n"
    for code in np.unique(codes).tolist():
        if code:
            body = body.replace(b"," + repr(float(code)).encode() + b"\n",
                                reasons[code] + b"\n")
    # A possible design's marker was a null: the line ends in the reason's empty field.
    return [body]


def _write_bytes(stream: IO[str], data: bytes | memoryview) -> None:
    """UTF-8 bytes onto a text stream: straight to its buffer where it has one."""
    buffer = getattr(stream, "buffer", None)
    if buffer is None:
        stream.write(bytes(data).decode())
        return
    stream.flush()
    buffer.write(data)


def _integer_fields(line: bytes, integer_axes: list[bool]) -> bytes:
    """``line`` with the ``.0`` of each whole-number input (the first fields) dropped."""
    fields = line.split(b",", len(integer_axes))
    for i, integer in enumerate(integer_axes):
        if integer and fields[i].endswith(b".0"):
            fields[i] = fields[i][:-2]
    return b",".join(fields)


#: The reference line writer of the tests quotes a reason as this writer does.
_csv_text = csv_text_field
