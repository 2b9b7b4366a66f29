"""The limits of everything armkit reads, and the first checks every reader makes.

Each input is refused or accepted in time and memory bounded by these numbers:
a file's size is checked before it is read whole, its text and lines before they
are parsed, its nesting before a parser recurses into it, and its counts before
they are planned. A refusal is one line that says where (``FILE:LINE:COL:``, as
editors and terminals read it; ``FILE:`` when it is about the whole file), which
limit and its value, and what to do. docs/limits.md lists them all.
"""

from __future__ import annotations

import codecs
import os
from pathlib import Path

from ._errors import InputError

KB, MB = 1_000, 1_000_000
# sizes of whole files [bytes]
MAX_SCRIPT_BYTES = 1 * MB  # a .arm script, and the lines piped into the shell at once
MAX_TOML_BYTES = 1 * MB  # a scene file, an arm model file
MAX_DRAWING_BYTES = 20 * MB  # an SVG or G-code file
MAX_SCORE_BYTES = 256 * KB  # a MIDI file, an RTTTL tune, a note list
# shape of a text
MAX_LINE_CHARS = 10_000  # one line of a script, the shell, TOML, G-code, a note list, RTTTL
MAX_NESTING = 32  # blocks in a script; tables and arrays in TOML
MAX_SVG_DEPTH = 64  # elements inside elements in an SVG file
MAX_NUMBER_CHARS = 40  # one number as written (digits, sign, point, exponent)
MAX_NUMBER = 1e9  # a number in a script, in the units it is written in (and not NaN)
MIN_NUMBER = 1e-9  # ... and one that is not 0 at least this large
# counts
MAX_STATEMENTS = 10_000  # statements in one script (a repeat's body counts once)
MAX_OBJECTS = 200  # objects in one scene (cubes, boards, sheets, instruments, ...)
MAX_NOTES = 10_000  # notes in one score
MAX_SVG_ELEMENTS = 100_000  # elements in one SVG file, its <use> elements expanded
MAX_SEGMENTS = 500_000  # lines, arcs and curves in one drawing (SVG path data, G-code moves)


class LimitError(InputError):
    """An input beyond one of the limits, or not text: the message starts with where
    (``FILE:LINE:COL:`` or ``FILE:``). Attributes: file, line, column (0 = the whole file)."""

    def __init__(self, file: str, message: str, line: int = 0, column: int = 0) -> None:
        super().__init__(f"{where(file, line, column)}: {message}")
        self.file, self.line, self.column, self.problem = file, line, column, message


def where(file: str, line: int = 0, column: int = 0) -> str:
    """``FILE:LINE:COL`` (1-based), or ``FILE`` when the line is not known (0)."""
    return f"{file}:{line}:{max(column, 1)}" if line > 0 else file


def size_text(n: int) -> str:
    """A byte count as a person reads it: ``1 MB``, ``20 MB``, ``500 kB``, ``12 bytes``."""
    if n >= MB:
        return f"{n / MB:g} MB"
    return f"{n / KB:g} kB" if n >= KB else f"{n} bytes"


def read_limited(path: str | Path, limit: int, what: str) -> bytes:
    """The bytes of ``path``, refused unreadable or longer than ``limit`` bytes before
    more than ``limit + 1`` are read (a device such as /dev/zero never ends).

    Raises:
        LimitError: ``FILE: cannot read it (why)``, ``FILE: is a directory``, or
            ``FILE: larger than LIMIT, the most a WHAT may be``.
    """
    name = str(path)
    try:
        if os.path.isdir(path):
            raise LimitError(name, f"is a directory; give a {what} file")
        with open(path, "rb") as handle:
            data = handle.read(limit + 1)
    except OSError as exc:
        raise LimitError(
            name, f"cannot read the {what} ({exc.strerror or exc}); check the path"
        ) from None
    except ValueError as exc:  # a NUL in the name
        raise LimitError(name.replace("\0", "\\0"), f"cannot read the {what} ({exc})") from None
    if len(data) > limit:
        raise LimitError(
            name, f"larger than {size_text(limit)}, the most a {what} may be; split it or "
            "check that it is the file you meant",
        )  # fmt: skip
    return data


def decode(data: bytes, file: str) -> str:
    """``data`` as text: UTF-8 (a BOM is dropped), or UTF-16 that starts with its BOM.

    Raises:
        LimitError: at the line and column of the first byte that is not UTF-8, or of
            the first NUL (a binary file, not text).
    """
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            text = data.decode("utf-16")
        except UnicodeDecodeError:
            raise LimitError(
                file, "not UTF-16 text after its byte order mark; save it as UTF-8"
            ) from None
    else:
        try:
            text = data.decode("utf-8-sig")
        except UnicodeDecodeError as exc:
            good = data[: exc.start].decode("utf-8-sig")
            line, column = position(good, len(good))
            bad = data[exc.start : max(exc.end, exc.start + 1)].hex(" ")
            what = f"byte{'s' * (' ' in bad)} {bad}"
            raise LimitError(
                file, f"not UTF-8 text ({what}); save it as UTF-8", line, column
            ) from None
    nul = text.find("\0")
    if nul >= 0:
        line, column = position(text, nul)
        raise LimitError(file, "a NUL character: this is not a text file", line, column)
    return text


def position(text: str, index: int) -> tuple[int, int]:
    """1-based (line, column) of ``text[index]``."""
    line = text.count("\n", 0, index) + 1
    return line, index - (text.rfind("\n", 0, index) + 1) + 1


def check_lines(text: str, file: str, limit: int = MAX_LINE_CHARS) -> None:
    """Refuse the first line longer than ``limit`` characters, at its column ``limit + 1``."""
    for number, line in enumerate(text.split("\n"), start=1):
        if len(line) > limit:
            raise LimitError(
                file, f"a line longer than {limit} characters; break it into shorter lines",
                number, limit + 1,
            )  # fmt: skip


def read_text(path: str | Path, limit: int, what: str) -> str:
    """The text of ``path``, every limit above checked (size, encoding, line length)."""
    text = decode(read_limited(path, limit, what), str(path))
    check_lines(text, str(path))
    return text
