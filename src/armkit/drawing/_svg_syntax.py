"""The SVG attribute grammars that svgelements forgives: path data, point lists,
transform lists, view boxes and lengths.

Each checker returns None when the value is well formed, else (offset, what):
the 0-based character offset in the value where it goes wrong and what was
expected there. svgelements renders a path up to its first error, as browsers
do; a plotter must not silently drop the rest, so armkit refuses instead.
"""

from __future__ import annotations

import math
import re

NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
SEP = re.compile(r"[\s,]*")
LENGTH = re.compile(
    r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(px|mm|cm|in|pt|pc|em|ex|%)?\s*$"
)
LARGEST = 1e9  # no coordinate in a drawing file is this large
PATH_ARGS = {"m": 2, "l": 2, "t": 2, "h": 1, "v": 1, "c": 6, "s": 4, "q": 4, "a": 7, "z": 0}
TRANSFORM_ARGS = {
    "matrix": (6,),
    "translate": (1, 2),
    "scale": (1, 2),
    "rotate": (1, 3),
    "skewX": (1,),
    "skewY": (1,),
}
Problem = tuple[int, str] | None


def _number(text: str, pos: int) -> int | str:
    """The end of the number at ``pos``, or what was expected there."""
    m = NUMBER.match(text, pos)
    if not m:
        return "a number"
    value = float(m.group())
    if not (math.isfinite(value) and abs(value) <= LARGEST):
        return f"a number of at most {LARGEST:g} in size"
    return m.end()


def _skip(text: str, pos: int) -> int:
    """The first offset at or after ``pos`` that is not a space or comma."""
    m = SEP.match(text, pos)
    return m.end() if m else pos


def path_data(d: str) -> Problem:
    """Check SVG path data (SVG 1.1 §8.3.9): commands and their argument counts."""
    pos = _skip(d, 0)
    if pos == len(d):
        return None  # an empty d draws nothing, which is allowed
    if d[pos] not in "Mm":
        return pos, "path data to start with M or m"
    cmd = ""
    while pos < len(d):
        if d[pos].lower() in PATH_ARGS:
            cmd, pos = d[pos], pos + 1
            if cmd in "Zz":
                pos = _skip(d, pos)
                continue
        elif cmd in ("", "Z", "z"):
            return pos, "a path command (one of M L H V C S Q T A Z)"
        for k in range(PATH_ARGS[cmd.lower()]):
            pos = _skip(d, pos)
            if cmd.lower() == "a" and k in (3, 4):
                if pos >= len(d) or d[pos] not in "01":
                    return pos, f"an arc flag (0 or 1) in '{cmd}'"
                pos += 1
                continue
            end = _number(d, pos)
            if isinstance(end, str):
                return pos, f"{end} in '{cmd}' ({PATH_ARGS[cmd.lower()]} numbers)"
            pos = end
        pos = _skip(d, pos)
    return None


def numbers(text: str, count: int | None = None, what: str = "numbers") -> Problem:
    """Check a list of numbers separated by commas or spaces; ``count`` numbers
    if given, else an even count (x, y pairs)."""
    pos, found = _skip(text, 0), 0
    while pos < len(text):
        end = _number(text, pos)
        if isinstance(end, str):
            return pos, end
        pos, found = _skip(text, end), found + 1
    if count is not None and found != count:
        return len(text), f"{count} {what}, found {found}"
    if count is None and found % 2:
        return len(text), f"x, y pairs of {what}, found an odd count ({found})"
    return None


def transform_list(text: str) -> Problem:
    """Check an SVG transform list: matrix, translate, scale, rotate, skewX, skewY."""
    pattern = re.compile(r"[\s,]*([A-Za-z]+)\s*\(([^)]*)\)")
    pos = 0
    while _skip(text, pos) < len(text):
        m = pattern.match(text, pos)
        if not m or m.group(1) not in TRANSFORM_ARGS:
            start = _skip(text, pos)
            return start, "a transform: " + ", ".join(f"{k}(...)" for k in TRANSFORM_ARGS)
        args, allowed = m.group(2), TRANSFORM_ARGS[m.group(1)]
        counts = [c for c in allowed if numbers(args, c) is None]
        if not counts:
            wanted = " or ".join(str(c) for c in allowed)
            return m.start(2), f"{wanted} numbers in {m.group(1)}(...)"
        pos = m.end()
    return None


def view_box(text: str) -> Problem:
    """Check a viewBox: four numbers, width and height > 0."""
    problem = numbers(text, 4, "numbers (min-x min-y width height)")
    if problem:
        return problem
    w, h = (float(v) for v in NUMBER.findall(text)[2:])
    if not (w > 0 and h > 0):
        return 0, f"a width and height > 0, got {w:g} and {h:g}"
    return None


def length(text: str, non_negative: bool) -> Problem:
    """Check one length: a number with an optional unit (px mm cm in pt pc em ex %)."""
    m = LENGTH.match(text)
    if not m:
        return 0, "a length: a number with an optional unit (px, mm, cm, in, pt, pc, em, ex, %)"
    value = float(m.group(1))
    if not (math.isfinite(value) and abs(value) <= LARGEST):
        return m.start(1), f"a number of at most {LARGEST:g} in size"
    if non_negative and value < 0:
        return m.start(1), f"a length >= 0, got {value:g}"
    return None
