"""G-code lines to words: a letter and a number, with the column of each.

Comments in parentheses and after ';' are dropped, as are block numbers (N) and
'%' tape marks. Anything else that is not a word is refused with its line and
column.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ._errors import DrawingError

WORD = re.compile(r"([A-Za-z])[ \t]*([+-]?(?:\d+\.?\d*|\.\d+))")
BLANK = re.compile(r"[ \t\r\f\v]*")
EXPONENT = re.compile(r"[eE][+-]?\d+")  # right after a number: 1e30 (G-code has no exponents)
MAX_VALUE = 1e6  # any word's value: mm, inches, seconds, a feed rate, a servo value


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
        exponent = EXPONENT.match(text, m.end())
        if exponent:
            raise DrawingError(
                f"{m.group()}{exponent.group()}: G-code numbers have no exponent; write the "
                f"value in plain digits, at most {MAX_VALUE:.0f} (X1500, not X1.5e3)",
                file=file,
                line=line,
                column=pos + 1,
            )
        value = float(m.group(2))
        if not abs(value) <= MAX_VALUE:
            word = m.group() if len(m.group()) <= 20 else f"{m.group()[:16]}..."
            raise DrawingError(
                f"{word} is out of range; a G-code value here is at most {MAX_VALUE:.0f}",
                file=file,
                line=line,
                column=pos + 1,
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
