"""Messages about a script: ``file:line:col: error: message``, the line and a caret.

Every problem found while parsing and checking is collected (not only the
first); misspelt names get a "did you mean" from ``difflib``.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from typing import Literal

from .._errors import ScriptError
from .._inputs import brief
from ._ast import Loc, Source

Severity = Literal["error", "warning"]
# a number of 10 or more digits before its point, standing alone (not in a path or a name)
SAME_PLACES = 20  # places of one failure named in its note, at most (then "and N more")
_LONG_NUMBER = re.compile(r"(?<![\w./\\-])-?\d{10,}(?:\.\d+)?(?![\w/\\]|\.\d)")


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

    def __post_init__(self) -> None:
        object.__setattr__(self, "message", compact_numbers(self.message))
        object.__setattr__(self, "notes", collapse(self.notes))

    def format(self, source: Source) -> str:
        """``file:line:col: error: message``, the source line and a caret under the column."""
        text = source.line(self.loc.line)
        head = f"{source.name}:{self.loc.line}:{self.loc.col}: {self.severity}: {self.message}"
        lines = [head]
        if text:
            lines += ["    " + text.expandtabs(1), "    " + " " * (self.loc.col - 1) + "^"]
        lines += [f"    note: {n}" for n in self.notes]
        return "\n".join(lines)


def compact_numbers(text: str) -> str:
    """``text`` with every number of 10 or more digits before its point in 3 significant
    digits: ``waist 1e+308 deg is outside its limits``, not the 300 digits that
    ``f"{angle:.2f}"`` gives (the unit written after it stays)."""
    return _LONG_NUMBER.sub(lambda m: brief(float(m.group(0))), text)


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


def collapse(notes: Sequence[str]) -> tuple[str, ...]:
    """``notes`` with a run of repeats said once: a procedure calling itself 50 deep is
    ``in f called at line 2 (50 times)``, two calling each other
    ``in g called at line 5; in f called at line 9 (25 times)``."""
    out: list[str] = []
    i = 0
    while i < len(notes):
        period, times = 1, 1
        for p in range(1, (len(notes) - i) // 2 + 1):
            block = list(notes[i : i + p])
            k = 1
            while list(notes[i + k * p : i + (k + 1) * p]) == block:
                k += 1
            if k > 1 and k * p > period * times:
                period, times = p, k
        block_text = "; ".join(notes[i : i + period])
        out.append(f"{block_text} ({times} times)" if times > 1 else block_text)
        i += period * times
    return tuple(out)


def sorted_unique(diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
    """In line and column order, each failure once: the same message at several places
    (a procedure's line failing for each call) is reported at the first, with a note
    naming the others."""
    places: dict[tuple[str, str], dict[Loc, Diagnostic]] = {}
    for d in sorted(diagnostics, key=lambda d: (d.loc.line, d.loc.col)):
        places.setdefault((d.severity, d.message), {}).setdefault(d.loc, d)
    out = []
    for same in places.values():
        first, *others = same.values()
        if others:
            lines = [_place(o.loc, first.loc) for o in others[:SAME_PLACES]]
            more = len(others) - len(lines)
            also = f"the same at {'line' if len(others) == 1 else 'lines'} {', '.join(lines)}"
            also += f" and {more} more" if more else ""
            first = replace(first, notes=(*first.notes, also))
        out.append(first)
    return sorted(out, key=lambda d: (d.loc.line, d.loc.col))


def _place(loc: Loc, first: Loc) -> str:
    return f"{loc.line}" if loc.line != first.line else f"{loc.line} column {loc.col}"
