"""G-code lines to words: a letter and a number, with the column of each.

Comments in parentheses and after ';' are dropped, as are block numbers (N) and
'%' tape marks. Anything else that is not a word is refused with its line and
column.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ._errors import DrawingError

WORD = re.compile(r"([A-Za-z])[ \t]*([+-]?(?:\d+\.?\d*|\.\d+))")
BLANK = re.compile(r"[ \t\r\f\v]*")


@dataclass(frozen=True)
class Word:
    """One G-code word: ``letter`` (upper case), ``value``, where it starts
    (1-based ``column``) and its ``text`` as written."""

    letter: str
    value: float
    column: int
    text: str


def words_of(text: str, line: int, file: str) -> list[Word]:
    """The words of one line (without its newline); ``DrawingError`` at the first bad character."""
    if text.strip() == "%":
        return []
    words: list[Word] = []
    pos = 0
    while True:
        pos = BLANK.match(text, pos).end()  # type: ignore[union-attr]
        if pos >= len(text) or text[pos] == ";":
            return words
        if text[pos] == "(":
            end = text.find(")", pos)
            if end < 0:
                raise DrawingError(
                    "comment '(' is not closed on its line; add ')'",
                    file=file,
                    line=line,
                    column=pos + 1,
                )
            pos = end + 1
            continue
        m = WORD.match(text, pos)
        if not m:
            raise DrawingError(_bad(text, pos), file=file, line=line, column=pos + 1)
        value = float(m.group(2))
        if not math.isfinite(value):
            raise DrawingError(
                f"number {m.group(2)!r} is not finite", file=file, line=line, column=pos + 1
            )
        if m.group(1).upper() != "N":
            words.append(Word(m.group(1).upper(), value, pos + 1, m.group()))
        pos = m.end()


def _bad(text: str, pos: int) -> str:
    ch = text[pos]
    if ch.isalpha():
        return f"'{ch}' is not followed by a number; a word is a letter and a number (G1, X10.5)"
    if ch == "*":
        return "checksums ('*') are not supported; remove them"
    return f"unexpected character {ch!r}; a line holds words (G1 X10), ( comments ) and ; comments"
