"""Where a field of a TOML file is written: ``cubes[2].size_mm[1]`` -> its line and
column, so that an error about a value read from a scene or model file says
``FILE:LINE:COL:`` as a TOML syntax error does.

The text is read line by line as a person lays a TOML file out: ``[table]`` and
``[[array]]`` headers, then ``key = value`` lines (dotted keys too). A field inside
an inline table or array is placed at the key that holds it; a field that is not
written (missing, so a default) is placed at its table's header.
"""

from __future__ import annotations

import re

from ._errors import ModelError
from ._input_limits import where

_HEADER = re.compile(r"\s*(\[\[?)\s*([^\]#]*?)\s*\]")
_KEY = re.compile(
    r"""\s*((?:[A-Za-z0-9_-]+|"[^"\n]*"|'[^'\n]*')(?:\s*\.\s*(?:[A-Za-z0-9_-]+|"[^"\n]*"|'[^'\n]*'))*)\s*="""
)
_PART = re.compile(r"""[A-Za-z0-9_-]+|"([^"\n]*)"|'([^'\n]*)'""")
_INDEX = re.compile(r"\[\d+\]$")


def _parts(dotted: str) -> list[str]:
    return [m.group(1) or m.group(2) or m.group(0) for m in _PART.finditer(dotted)]


def fields(text: str) -> dict[str, tuple[int, int]]:
    """Every table and key written in ``text``: dotted name (``cubes[2].size_mm``) ->
    (line, column) of its header or key, 1-based."""
    found: dict[str, tuple[int, int]] = {}
    counts: dict[str, int] = {}
    table = ""
    for number, line in enumerate(text.split("\n"), start=1):
        header = _HEADER.match(line)
        if header and not _KEY.match(line):
            name = ".".join(_parts(header.group(2)))
            if header.group(1) == "[[":
                found.setdefault(name, (number, header.start(1) + 1))  # the array: its first
                counts[name] = counts.get(name, -1) + 1
                name = f"{name}[{counts[name]}]"
            table = name
            found.setdefault(table, (number, header.start(1) + 1))
            continue
        key = _KEY.match(line)
        if key:
            name = ".".join(_parts(key.group(1)))
            found.setdefault(f"{table}.{name}".strip("."), (number, key.start(1) + 1))
    return found


def locate(text: str, field: str) -> tuple[int, int]:
    """(line, column) where ``field`` is written, or where the nearest table or key
    that holds it is; (0, 0) if none of it is written."""
    known = fields(text)
    name = field
    while name:
        if name in known:
            return known[name]
        trimmed = _INDEX.sub("", name)
        name = trimmed if trimmed != name else name.rpartition(".")[0]
    return 0, 0


def located(exc: ModelError, text: str) -> ModelError:
    """``exc`` (an error about a field of a file) again, its message starting with
    ``FILE:LINE:COL:`` where the field is written; ``exc`` itself if it names no field."""
    file, field = exc.file, exc.field
    message = str(exc)
    if file is None or field is None or not message.startswith(f"{file}: "):
        return exc
    line, column = locate(text, field)
    if line == 0:
        return exc
    again = type(exc)(
        f"{where(file, line, column)}: {message[len(file) + 2 :]}", file=file, field=field
    )
    return again
