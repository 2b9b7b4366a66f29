"""First pass over an SVG file with expat: is it XML, is it an SVG, are the
attributes armkit draws from well formed? Every problem names the file, line and
column. Also finds the text elements, which a plotter cannot draw as they are.
"""

from __future__ import annotations

import re
import xml.parsers.expat
from collections.abc import Callable
from dataclasses import dataclass

from . import _svg_syntax as syntax
from ._errors import DrawingError
from ._svg_limits import Guard

SVG_NS = "http://www.w3.org/2000/svg"
SHAPE_LENGTHS = {
    "rect": ("x", "y", "width", "height", "rx", "ry"),
    "circle": ("cx", "cy", "r"),
    "ellipse": ("cx", "cy", "rx", "ry"),
    "line": ("x1", "y1", "x2", "y2"),
    "svg": ("x", "y", "width", "height"),
    "use": ("x", "y", "width", "height"),
}
NON_NEGATIVE = {"width", "height", "r", "rx", "ry"}


@dataclass(frozen=True)
class Element:
    """An SVG element as expat saw it: local ``tag``, ``attrs``, where its start
    tag begins (1-based ``line`` and ``column``)."""

    tag: str
    attrs: dict[str, str]
    line: int
    column: int


@dataclass(frozen=True)
class Checked:
    """What the first pass found: every SVG element in document order, and those
    a plotter cannot draw as they are (text, images)."""

    elements: tuple[Element, ...]
    left_out: tuple[Element, ...]


def _checks(tag: str) -> dict[str, Callable[[str], syntax.Problem]]:
    """The attribute checkers for an element of this (local) tag name."""
    checks: dict[str, Callable[[str], syntax.Problem]] = {
        "transform": syntax.transform_list,
    }
    checks["d"] = syntax.path_data  # svgelements reads d on any element
    if tag in ("polyline", "polygon"):
        checks["points"] = syntax.numbers
    if tag in ("svg", "symbol"):
        checks["viewBox"] = syntax.view_box
    for name in SHAPE_LENGTHS.get(tag, ()):
        checks[name] = _length_check(name in NON_NEGATIVE)
    return checks


def _length_check(non_negative: bool) -> Callable[[str], syntax.Problem]:
    def check(value: str) -> syntax.Problem:
        return None if value.strip() == "auto" else syntax.length(value, non_negative)

    return check


def check_svg(data: bytes, file: str) -> Checked:
    """Raise ``DrawingError`` at the first problem; return the elements found."""
    parser = xml.parsers.expat.ParserCreate(namespace_separator=" ")
    guard = Guard(parser, data, file)
    elements: list[Element] = []

    def start(name: str, attrs: dict[str, str]) -> None:
        ns, _, tag = name.rpartition(" ")
        at = Element(tag, dict(attrs), parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
        guard.started(tag, at.attrs, at.line, at.column)
        if not elements and (tag != "svg" or ns not in ("", SVG_NS)):
            raise _error(file, at, f"the root element is <{tag}>, not <svg>; give an SVG file")
        if ns in ("", SVG_NS):
            if elements and tag == "svg":
                _check_nested(file, at)
            elements.append(at)
            _check_element(data, file, at, parser.CurrentByteIndex)

    parser.StartElementHandler = start
    try:
        parser.Parse(data, True)
    except xml.parsers.expat.ExpatError as e:
        what = xml.parsers.expat.errors.messages.get(e.code, str(e))
        raise DrawingError(
            f"not well-formed XML ({what}); fix the file or export it again",
            file=file,
            line=e.lineno,
            column=e.offset + 1,
        ) from None
    if not elements:
        raise DrawingError("no <svg> element; give an SVG file", file=file, line=1, column=1)
    guard.check_uses()
    left_out = tuple(e for e in elements if e.tag in ("text", "image"))
    return Checked(tuple(elements), left_out)


def _error(file: str, at: Element, what: str) -> DrawingError:
    return DrawingError(what, file=file, line=at.line, column=at.column)


def _check_nested(file: str, at: Element) -> None:
    """svgelements 1.9 scales a nested <svg>'s x, y by its viewBox: refuse that one case."""
    moved = any(_nonzero(at.attrs.get(k, "0")) for k in ("x", "y"))
    if moved and "viewBox" in at.attrs:
        raise _error(
            file,
            at,
            "a nested <svg> with both x/y and a viewBox would be placed wrongly; "
            'put its content in a <g transform="translate(x y) scale(...)"> instead',
        )


def _nonzero(value: str) -> bool:
    m = syntax.NUMBER.match(value.strip())
    return m is not None and float(m.group()) != 0.0


def _check_element(data: bytes, file: str, at: Element, byte: int) -> None:
    """Raise at the first attribute of ``at`` that is not well formed."""
    if at.tag == "path" and "d" not in at.attrs:
        raise _error(file, at, "<path> has no d attribute; give it path data or remove it")
    for attr, check in _checks(at.tag).items():
        if attr in at.attrs and (problem := check(at.attrs[attr])):
            offset, expected = problem
            line, col = _attribute_position(data, byte, attr, offset)
            raise DrawingError(
                f'<{at.tag}> {attr}="{_clip(at.attrs[attr])}": expected {expected} '
                f"at character {offset + 1}; fix the attribute",
                file=file,
                line=line or at.line,
                column=col or at.column,
            )


def _attribute_position(
    data: bytes, tag_start: int, attr: str, offset: int
) -> tuple[int | None, int | None]:
    """Line and column (1-based) of character ``offset`` of attribute ``attr``'s
    value in the start tag at byte ``tag_start``; (None, None) if not found."""
    end = data.find(b">", tag_start)
    tag = data[tag_start : end if end >= 0 else len(data)]
    m = re.search(rb"[\s]" + re.escape(attr.encode()) + rb"\s*=\s*[\"']", tag)
    if tag_start < 0 or not m:
        return None, None
    value_start = tag_start + m.end()
    prefix = data[:value_start].decode("utf-8", errors="replace")
    value = data[value_start:].decode("utf-8", errors="replace")[:offset]
    text = prefix + value
    line = text.count("\n") + 1
    return line, len(text) - (text.rfind("\n") + 1) + 1


def _clip(value: str, width: int = 40) -> str:
    value = " ".join(value.split())
    return value if len(value) <= width else value[: width - 3] + "..."
