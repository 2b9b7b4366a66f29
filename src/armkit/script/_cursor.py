"""Reading one line's tokens: words from a set, names, numbers with units, targets.

A ``Problem`` stops the line (its structure is wrong); a unit or value
mistake is recorded and reading goes on, so one line can report several.
"""

from __future__ import annotations

import math
from collections.abc import Collection

from ._ast import XYZ, Here, JointList, Loc, Num, PoseName, Ref, TargetExpr, Value
from ._diagnostics import suggest
from ._lexer import Token
from ._units import UNITS, Dim, UnitProblem, to_si


def _is_name(text: str, reserved: Collection[str]) -> bool:
    return bool(text) and Token("word", text, 0).is_name and text not in reserved


class Problem(Exception):
    """What is wrong at a column of the line."""

    def __init__(self, col: int, message: str) -> None:
        super().__init__(message)
        self.col = col
        self.message = message


class Cursor:
    """The tokens of one statement, read left to right.

    Attributes:
        line: the line number.  usage: the statement's usage, for messages.
        soft: problems found that did not stop the reading, as (column, message).
        reserved: words that cannot be names (commands, keywords, units).
    """

    def __init__(self, tokens: list[Token], line: int, end_col: int, reserved: Collection[str]):
        self.tokens, self.line, self.end_col = tokens, line, end_col
        self.i = 0
        self.usage = ""
        self.soft: list[tuple[int, str]] = []
        self.reserved = reserved

    def loc(self, token: Token | None = None) -> Loc:
        """Where ``token`` (default: the next one, or the end of the line) is."""
        t = token or self.peek()
        return Loc(self.line, t.col if t else self.end_col)

    def peek(self, ahead: int = 0) -> Token | None:
        """The next token (or the one ``ahead`` after it), None at the end."""
        k = self.i + ahead
        return self.tokens[k] if k < len(self.tokens) else None

    def at_end(self) -> bool:
        """No token left."""
        return self.i >= len(self.tokens)

    def take(self, what: str) -> Token:
        """The next token; a Problem naming ``what`` was expected at the end."""
        t = self.peek()
        if t is None:
            raise Problem(self.end_col, f"expected {what} here{self._usage()}")
        self.i += 1
        return t

    def end(self) -> None:
        """A Problem if anything is left on the line."""
        t = self.peek()
        if t is not None:
            raise Problem(t.col, f"unexpected {t.text!r}{self._usage()}")

    def word(self, choices: Collection[str], what: str) -> Token:
        """The next token, which must be one of ``choices`` (did you mean ...)."""
        t = self.take(what)
        if t.text not in choices:
            listed = ", ".join(choices)
            raise Problem(
                t.col, f"expected {what} ({listed}), got {t.text!r}{suggest(t.text, choices)}"
            )
        return t

    def accept(self, word: str) -> Token | None:
        """The next token if it is ``word`` (then consumed), else None."""
        t = self.peek()
        if t is not None and t.kind == "word" and t.text == word:
            self.i += 1
            return t
        return None

    def accept_punct(self, mark: str) -> bool:
        """Consume the next token if it is the punctuation ``mark``."""
        t = self.peek()
        if t is not None and t.kind == "punct" and t.text == mark:
            self.i += 1
            return True
        return False

    def name(self, what: str) -> Token:
        """A name: letters, digits, ``_`` and ``-``, starting with a letter; not reserved."""
        t = self.take(what)
        if not t.is_name:
            raise Problem(t.col, f"expected {what} (a name like 'above'), got {t.text!r}")
        if t.text in self.reserved:
            raise Problem(t.col, f"{t.text!r} is a word of the language; choose another name")
        return t

    def value(self, dim: Dim, what: str) -> Value:
        """A number (unit attached, written after it, or defaulted) or a parameter name."""
        t = self.take(what)
        if t.kind == "word" and t.is_name and t.text not in self.reserved:
            return Ref(t.text, self.loc(t))
        name = t.text[1:]
        if t.kind == "word" and t.text.startswith("-") and _is_name(name, self.reserved):
            return Ref(name, self.loc(t), negate=True)
        if t.kind != "number":
            raise Problem(t.col, f"expected {what} (a number), got {t.text!r}{self._usage()}")
        unit = t.unit
        nxt = self.peek()
        if unit is None and nxt is not None and nxt.kind == "word" and nxt.text in UNITS:
            unit = nxt.text
            self.i += 1
        self.check_number(t.value, unit, dim, t.col)
        return Num(t.value, unit, self.loc(t))

    def check_number(self, value: float, unit: str | None, dim: Dim, col: int) -> None:
        """Record a soft problem if ``value`` with ``unit`` is not a finite ``dim``."""
        try:
            si = to_si(value, unit, dim)
        except UnitProblem as exc:
            self.soft.append((col, str(exc)))
            return
        if not math.isfinite(si):
            self.soft.append((col, f"{value} is not a finite number"))

    def has_value(self) -> bool:
        """The next token can start a value (a number, or a name that is not reserved)."""
        t = self.peek()
        return t is not None and (t.kind == "number" or (t.is_name and t.text not in self.reserved))

    def target(self, what: str = "a target") -> TargetExpr:
        """``xyz X Y Z [pitch P]``, ``X Y Z [pitch P]``, ``joints A ...``, ``here`` or a pose name."""
        t = self.peek()
        if t is None:
            raise Problem(
                self.end_col, f"expected {what} (xyz X Y Z, joints A B ..., or a pose name)"
            )
        loc = self.loc(t)
        if self.accept("xyz") or t.kind == "number":
            return self._xyz(loc)
        if self.accept("joints"):
            angles = []
            while self.has_value():
                angles.append(self.value("angle", "a joint angle"))
            if not angles:
                raise Problem(self.loc().col, "expected joint angles after 'joints' [deg]")
            return JointList(tuple(angles), loc)
        if self.accept("here"):
            return Here(loc)
        return PoseName(self.name(f"{what} (xyz X Y Z, joints A B ..., or a pose name)").text, loc)

    def _xyz(self, loc: Loc) -> XYZ:
        x = self.value("length", "x [mm]")
        y = self.value("length", "y [mm]")
        z = self.value("length", "z [mm]")
        pitch = self.value("angle", "the pitch [deg]") if self.accept("pitch") else None
        return XYZ(x, y, z, pitch, loc)

    def _usage(self) -> str:
        return f"; usage: {self.usage}" if self.usage else ""
