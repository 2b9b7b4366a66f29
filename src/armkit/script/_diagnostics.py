"""Messages about a script: ``file:line:col: error: message``, the line and a caret.

Every problem found while parsing and checking is collected (not only the
first); misspelt names get a "did you mean" from ``difflib``.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Literal

from .._errors import ScriptError
from ._ast import Loc, Source

Severity = Literal["error", "warning"]


@dataclass(frozen=True)
class Diagnostic:
    """One problem at a place in a script.

    Attributes:
        loc: line and column (1-based).
        message: what is wrong, what is allowed, what to do.
        severity: ``error`` (nothing moves) or ``warning``.
        notes: more lines (``called from line 12``), printed after the caret.
    """

    loc: Loc
    message: str
    severity: Severity = "error"
    notes: tuple[str, ...] = ()

    def format(self, source: Source) -> str:
        """``file:line:col: error: message``, the source line and a caret under the column."""
        text = source.line(self.loc.line)
        head = f"{source.name}:{self.loc.line}:{self.loc.col}: {self.severity}: {self.message}"
        lines = [head]
        if text:
            lines += ["    " + text.expandtabs(1), "    " + " " * (self.loc.col - 1) + "^"]
        lines += [f"    note: {n}" for n in self.notes]
        return "\n".join(lines)


def suggest(word: str, choices: Iterable[str]) -> str:
    """``"; did you mean 'move'?"`` for the closest of ``choices``, or ''."""
    close = difflib.get_close_matches(word, list(choices), n=1, cutoff=0.6)
    return f"; did you mean {close[0]!r}?" if close else ""


class ScriptCheckError(ScriptError, ValueError):
    """A script failed its check; nothing moved.

    Attributes:
        diagnostics: every problem found, in line order.
        source: the script.
    """

    def __init__(self, source: Source, diagnostics: list[Diagnostic]) -> None:
        self.source = source
        self.diagnostics = diagnostics
        errors = [d for d in diagnostics if d.severity == "error"]
        first = errors[0] if errors else None
        where = f"{source.name}:{first.loc.line}:{first.loc.col}" if first else source.name
        count = f"{len(errors)} error{'s' if len(errors) != 1 else ''}"
        what = first.message if first else "failed its check"
        super().__init__(f"{where}: {what} ({count} in {source.name}; nothing moved)")

    def report(self) -> str:
        """Every diagnostic, formatted with its line and caret."""
        return "\n".join(d.format(self.source) for d in self.diagnostics)


def sorted_unique(diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
    """In line and column order, each (place, message) once."""
    seen: dict[tuple[int, int, str], Diagnostic] = {}
    for d in diagnostics:
        seen.setdefault((d.loc.line, d.loc.col, d.message), d)
    return sorted(seen.values(), key=lambda d: (d.loc.line, d.loc.col))
