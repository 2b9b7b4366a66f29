"""The shape of a TOML text, checked before a parser reads it: how deep its tables
and arrays nest (``MAX_NESTING``) and how long its numbers are
(``MAX_NUMBER_CHARS``). Python's TOML parser recurses once per bracket and turns
any run of digits into an integer, so a file of ``[[[[...`` or of a 5000-digit
number would stop it with a RecursionError or a ValueError instead of a message.

The scan is linear in the text: strings and comments are skipped whole, and one
it cannot follow (a string left open) ends the scan, the parser then says where.
"""

from __future__ import annotations

import re

from ._input_limits import MAX_NESTING, MAX_NUMBER_CHARS, LimitError

_NEXT = re.compile(r"""[\[\]{}=,."'#\n]|[0-9_]{""" + str(MAX_NUMBER_CHARS + 1) + ",}")
_BASIC = re.compile(r'"(?:[^"\\\n]|\\.)*"')
_BASIC_MULTI = re.compile(
    r'"""(?:[^"\\]|\\.|"(?!""))*"""(?!")|"""(?:[^"\\]|\\.|"(?!""))*""""{1,2}', re.S
)


class _Scan:
    """Where the scan is: line, its start, open brackets and the dots of keys."""

    def __init__(self, text: str, file: str) -> None:
        self.text, self.file = text, file
        self.line, self.line_start = 1, 0
        self.table = 0  # dotted parts of the current [table] header
        self.levels: list[tuple[str, int]] = []  # open brackets: (bracket, key dots before it)
        self.dots = 0  # dots of the key being read
        self.in_key = True

    def fail(self, at: int, message: str) -> LimitError:
        return LimitError(self.file, message, self.line, at - self.line_start + 1)

    def depth(self) -> int:
        return self.table + sum(1 + d for _, d in self.levels) + self.dots

    def deeper(self, at: int) -> None:
        if self.depth() > MAX_NESTING:
            raise self.fail(
                at, f"nesting deeper than {MAX_NESTING} (tables and arrays inside each other)"
            )

    def newlines(self, start: int, end: int) -> None:
        count = self.text.count("\n", start, end)
        if count:
            self.line += count
            self.line_start = self.text.rfind("\n", start, end) + 1


def check_toml_shape(text: str, file: str) -> None:
    """Refuse ``text`` nested deeper than ``MAX_NESTING`` or with a number longer than
    ``MAX_NUMBER_CHARS``, at the line and column where it happens.

    Raises:
        LimitError: ``FILE:LINE:COL: nesting deeper than 32 ...`` or ``... a number of more
            than 40 digits ...``.
    """
    s = _Scan(text, file)
    pos = 0
    while (m := _NEXT.search(text, pos)) is not None:
        at, token = m.start(), m.group(0)
        pos = m.end()
        if len(token) > 1:
            raise s.fail(
                at,
                f"a number of more than {MAX_NUMBER_CHARS} digits; no value armkit reads needs that many",
            )
        if token in "\"'":
            end = _string_end(text, at)
            if end < 0:
                return  # left open: the parser says where
            s.newlines(at, end)
            pos = end
        elif token == "#":
            pos = text.find("\n", at)
            pos = len(text) if pos < 0 else pos
        elif token == "\n":
            s.line, s.line_start = s.line + 1, pos
            if not s.levels:
                s.dots, s.in_key = 0, True
        else:
            pos = _punct(s, token, at, pos)


def _punct(s: _Scan, token: str, at: int, pos: int) -> int:
    """Follow one bracket, ``=``, ``,`` or ``.``; the position to go on from."""
    if token == "[" and not s.levels and not s.text[s.line_start : at].strip():
        return _header(s, at)
    if token in "[{":
        s.levels.append((token, s.dots))
        s.dots, s.in_key = 0, token == "{"
        s.deeper(at)
    elif token in "]}":
        if s.levels:
            s.levels.pop()
        s.dots = 0
    elif token == "=":
        s.in_key = False
        s.deeper(at)
    elif token == ",":
        s.dots, s.in_key = 0, bool(s.levels) and s.levels[-1][0] == "{"
    elif token == "." and s.in_key:
        s.dots += 1
    return pos


def _header(s: _Scan, at: int) -> int:
    """A ``[table]`` or ``[[array]]`` header: its dotted parts are its depth."""
    end = s.text.find("\n", at)
    end = len(s.text) if end < 0 else end
    name = re.sub(r'"(?:[^"\\]|\\.)*"|\'[^\']*\'', "x", s.text[at:end].split("#", 1)[0])
    s.table = name.split("]", 1)[0].count(".") + 1 + name.startswith("[[")
    s.dots, s.in_key = 0, True
    s.deeper(at)
    return end


def _string_end(text: str, at: int) -> int:
    """The index after the string that starts at ``at``, or -1 if it is never closed."""
    if text.startswith('"""', at):
        m = _BASIC_MULTI.match(text, at)
        return m.end() if m else -1
    if text.startswith("'''", at):
        end = text.find("'''", at + 3)
        if end < 0:
            return -1
        while text.startswith("'", end + 3) and end + 3 - at < len(text):
            end += 1  # up to two quotes may end the content
        return end + 3
    if text[at] == '"':
        m = _BASIC.match(text, at)
        return m.end() if m else -1
    end = text.find("'", at + 1)
    return -1 if end < 0 or "\n" in text[at:end] else end + 1
