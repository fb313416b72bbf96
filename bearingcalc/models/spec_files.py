"""Reading a spec file's text: a regular file within the size limit, in UTF-8; a file
in UTF-16 or UTF-32 (as Windows editors save 'Unicode' text) is named so."""

from __future__ import annotations

import os
import re
import stat

from bearingcalc import reads
from bearingcalc.errors import SpecError

MAX_FILE_BYTES = 1024 * 1024


def read_spec_text(path: str | os.PathLike[str]) -> str:
    """The text of a spec file, or a SpecError saying why it cannot be read."""
    label = str(path)
    reads.note(path, "spec")
    try:
        # A FIFO or device named *.yaml would block or never end: refuse before opening.
        mode = os.stat(path).st_mode
        if stat.S_ISDIR(mode):
            raise SpecError("is a folder, not a spec file; give a .yaml file "
                            "(or use 'bearingcalc check' for folders)", source=label)
        if not stat.S_ISREG(mode):
            raise SpecError("not a regular file; give a .yaml file", source=label)
        with open(path, "rb") as handle:
            raw = handle.read(MAX_FILE_BYTES + 1)
    except FileNotFoundError:
        what = "a broken symbolic link" if os.path.islink(path) else "no such file"
        raise SpecError(f"{what}; check the path", source=label) from None
    except OSError as exc:
        raise SpecError(f"cannot read the file: {exc.strerror or exc}", source=label) from None
    if len(raw) > MAX_FILE_BYTES:
        raise SpecError(f"file too large: specs are at most {MAX_FILE_BYTES // 1024} KiB",
                        source=label)
    refuse_wide_text(raw, label, "save it as UTF-8")
    if b"\0" in raw:
        raise SpecError("binary file, not YAML text", source=label)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise SpecError(f"not UTF-8 text (byte 0x{raw[exc.start]:02x} at offset {exc.start}); "
                        "save the file as UTF-8", source=label) from None


#: Byte-order marks of the encodings wider than UTF-8, the longer first (UTF-32 LE's
#: begins with UTF-16 LE's).
_BOMS = ((b"\xff\xfe\x00\x00", "UTF-32 (little-endian, with a byte-order mark)"),
         (b"\x00\x00\xfe\xff", "UTF-32 (big-endian, with a byte-order mark)"),
         (b"\xff\xfe", "UTF-16 (little-endian, with a byte-order mark)"),
         (b"\xfe\xff", "UTF-16 (big-endian, with a byte-order mark)"))
_WIDE = (("utf-32-le", "UTF-32 (little-endian)"), ("utf-32-be", "UTF-32 (big-endian)"),
         ("utf-16-le", "UTF-16 (little-endian)"), ("utf-16-be", "UTF-16 (big-endian)"))
#: Characters no text file holds (NUL and the other C0 controls but tab and line ends).
_NOT_TEXT = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f]")


def refuse_wide_text(raw: bytes, source: str, advice: str) -> None:
    """A SpecError naming the encoding where ``raw`` is UTF-16 or UTF-32 text, with
    ``advice`` (how to save it as UTF-8)."""
    encoding = wide_encoding(raw)
    if encoding is not None:
        raise SpecError(f"the file is {encoding} text; {advice}", source=source)


def wide_encoding(raw: bytes) -> str | None:
    """The name of the UTF-16 or UTF-32 encoding ``raw`` is text in (with or without a
    byte-order mark), or None: a file saved as 'Unicode' by an editor on Windows. Without
    a mark, the bytes are taken as such text when they decode to text without control
    characters and hold a NUL (which UTF-8 text never does), in the byte order that
    reads the most ASCII."""
    for mark, name in _BOMS:
        if raw.startswith(mark) and (len(raw) - len(mark)) % (4 if "32" in name else 2) == 0:
            return name
    if b"\0" not in raw:
        return None
    ascii_share: dict[str, float] = {}
    for codec, name in _WIDE:
        try:
            text = raw.decode(codec)
        except UnicodeDecodeError:
            continue
        if text and not _NOT_TEXT.search(text):
            ascii_share[name] = sum(char < "\x80" for char in text) / len(text)
    # A spec is mostly ASCII: the byte order that reads it so is the file's.
    return max(ascii_share, key=ascii_share.__getitem__) if ascii_share else None
