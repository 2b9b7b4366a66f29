"""Split one script line into tokens (words, numbers with units, strings, punctuation).

Columns are 1-based, as editors count them. A ``#`` starts a comment that runs
to the end of the line (outside a quoted string).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Literal

from .._input_limits import MAX_NUMBER, MAX_NUMBER_CHARS, MIN_NUMBER

Kind = Literal["word", "number", "string", "punct"]

_DELIM = r"(?=[\s#=(),]|$)"
_NUMBER = re.compile(
    r"(?P<num>[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)(?P<unit>[A-Za-z%][A-Za-z0-9/%]*)?"
    + _DELIM
)
_STRING = re.compile(r'"(?P<body>(?:[^"\\]|\\.)*)"')
_WORD = re.compile(r'[^\s#"=(),]+')
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_-]*\Z")
# a board's socket, ``board[ROW,COL]`` (spaces allowed inside the brackets): one word
_CELL = re.compile(r"[A-Za-z_][A-Za-z0-9_-]*\[[^\]#\"]*\]")
_CELL_WHOLE = re.compile(r"[A-Za-z_][A-Za-z0-9_-]*\[\s*\d+\s*,\s*\d+\s*\]\Z")


@dataclass(frozen=True)
class Token:
    """One token.

    Attributes:
        kind: ``word``, ``number``, ``string`` or ``punct``.
        text: the source text (a string's text without its quotes).
        col: column of its first character (1-based).
        value: a number's value as written (no unit applied).
        unit: a number's unit written right after it (``1.5s``), or None.
    """

    kind: Kind
    text: str
    col: int
    value: float = 0.0
    unit: str | None = None

    @property
    def is_name(self) -> bool:
        """A word that can name a command, pose, procedure or parameter."""
        return self.kind == "word" and _NAME.match(self.text) is not None


class LexError(ValueError):
    """A line that cannot be split into tokens (an unclosed string)."""

    def __init__(self, col: int, message: str) -> None:
        super().__init__(message)
        self.col = col


def tokenize(line: str) -> list[Token]:
    """The tokens of ``line``, comments dropped.

    Raises:
        LexError: an unclosed string.
    """
    tokens: list[Token] = []
    i, n = 0, len(line)
    while i < n:
        ch = line[i]
        if ch.isspace():
            i += 1
        elif ch == "#":
            break
        elif ch in "=(),":
            tokens.append(Token("punct", ch, i + 1))
            i += 1
        elif ch == '"':
            m = _STRING.match(line, i)
            if m is None:
                raise LexError(i + 1, 'this string has no closing "')
            tokens.append(Token("string", m["body"].replace('\\"', '"'), i + 1))
            i = m.end()
        else:
            token = _word_or_number(line, i)
            tokens.append(token)
            i += len(token.text)
    return tokens


def is_cell(text: str) -> bool:
    """``text`` names a board's socket: ``NAME[ROW,COL]``."""
    return _CELL_WHOLE.match(text) is not None


def _word_or_number(line: str, i: int) -> Token:
    cell = _CELL.match(line, i)
    if cell is not None:
        return Token("word", cell.group(0), i + 1)
    m = _NUMBER.match(line, i)
    if m is not None:
        if len(m["num"]) > MAX_NUMBER_CHARS:
            raise LexError(
                i + 1, f"a number of more than {MAX_NUMBER_CHARS} characters; no value a script "
                "needs has that many digits",
            )  # fmt: skip
        value = float(m["num"])
        if not (math.isfinite(value) and abs(value) <= MAX_NUMBER):
            raise LexError(
                i + 1, f"{m['num']} is larger than {MAX_NUMBER:g}; no value a script needs is"
            )
        if 0 < abs(value) < MIN_NUMBER:
            raise LexError(i + 1, f"{m['num']} is smaller than {MIN_NUMBER:g} (and not 0)")
        return Token("number", m.group(0), i + 1, value, m["unit"])
    w = _WORD.match(line, i)
    if w is None:  # cannot happen: every other character starts a word
        raise LexError(i + 1, f"unexpected character {line[i]!r}")
    return Token("word", w.group(0), i + 1)
