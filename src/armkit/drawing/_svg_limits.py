"""What an SVG file may ask of its reader, checked in the first pass (``_svg_check``)
before svgelements reads it: XML read safely, and the file's size as drawn bounded.

- Entities: an external one (``SYSTEM "file:///etc/passwd"``, a URL) or a parameter
  entity is refused, so nothing is read from disk or the network; an internal one
  may not hold markup or other entities (the billion laughs nests them) and all
  their uses together may not expand beyond ``MAX_ENTITY_EXPANSION`` characters.
  A reference to an entity the file does not define is refused where it is.
- Shape: elements inside elements at most ``MAX_SVG_DEPTH`` deep, at most
  ``MAX_SVG_ELEMENTS`` elements and ``MAX_SEGMENTS`` path segments once every
  ``<use>`` is expanded (a use of a group of uses multiplies), and no ``<use>``
  that shows itself.
"""

from __future__ import annotations

import re
import xml.parsers.expat
from dataclasses import dataclass, field

from .._input_limits import MAX_SEGMENTS, MAX_SVG_DEPTH, MAX_SVG_ELEMENTS
from ._errors import DrawingError

MAX_ENTITY_CHARS = 1_000  # one internal entity's text (Illustrator's namespace URIs)
MAX_ENTITY_EXPANSION = 1_000_000  # characters all entity references expand to
_REFERENCE = re.compile(rb"&([A-Za-z_:][\w.:-]*);")
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_COMMAND = re.compile(r"([MmLlHhVvCcSsQqTtAa])([^A-DF-Za-df-z]*)|[Zz]")
_ARGS = {"m": 2, "l": 2, "t": 2, "h": 1, "v": 1, "c": 6, "s": 4, "q": 4, "a": 7}
XLINK = "http://www.w3.org/1999/xlink"
SEGMENTS = (
    f"more than {MAX_SEGMENTS} path segments (lines, arcs, curves); simplify the drawing "
    "(e.g. vpype linesimplify) or split it"
)


@dataclass
class Node:
    """An element for the expansion count: where it is, its children, what it uses."""

    tag: str
    line: int
    column: int
    children: list[int] = field(default_factory=list)
    href: str = ""
    segments: int = 0  # of its own path data or points


class Guard:
    """The entity rules and the shape rules of one expat pass over ``data``."""

    def __init__(self, parser: xml.parsers.expat.XMLParserType, data: bytes, file: str) -> None:
        self.parser, self.data, self.file = parser, data, file
        self.entities: dict[str, int] = {}  # internal entities: name -> length of their text
        self.counted = False
        self.nodes: list[Node] = []
        self.ids: dict[str, int] = {}
        self.open: list[int] = []
        self.segments = 0  # of the elements so far, uses not expanded
        parser.SetParamEntityParsing(xml.parsers.expat.XML_PARAM_ENTITY_PARSING_NEVER)
        parser.EntityDeclHandler = self.declared
        parser.SkippedEntityHandler = self.skipped
        parser.ExternalEntityRefHandler = self.external
        parser.EndElementHandler = self.closed

    def here(self) -> tuple[int, int]:
        return self.parser.CurrentLineNumber, self.parser.CurrentColumnNumber + 1

    def refuse(self, what: str, at: tuple[int, int] | None = None) -> DrawingError:
        line, column = at or self.here()
        return DrawingError(what, file=self.file, line=line, column=column)

    def declared(
        self, name: str, is_parameter: bool, value: str | None, base: str | None,
        system_id: str | None, public_id: str | None, notation: str | None,
    ) -> None:  # fmt: skip
        if is_parameter or value is None:
            kind = "a parameter entity" if is_parameter else "an external entity"
            source = f" ({system_id})" if system_id else ""
            raise self.refuse(
                f"{kind} &{name};{source}: armkit reads nothing but the file itself; "
                "remove the DOCTYPE or export the drawing again"
            )
        if len(value) > MAX_ENTITY_CHARS or "&" in value or "<" in value:
            raise self.refuse(
                f"the entity &{name}; holds markup, other entities or more than "
                f"{MAX_ENTITY_CHARS} characters (a billion-laughs file expands so); "
                "remove the DOCTYPE or export the drawing again"
            )
        self.entities[name] = len(value)

    def skipped(self, name: str, is_parameter: bool) -> None:
        raise self.refuse(f"&{name}; is not defined in the file; write the text itself")

    def external(self, *args: object) -> int:
        raise self.refuse("an external entity: armkit reads nothing but the file itself")

    def started(self, tag: str, attrs: dict[str, str], line: int, column: int) -> None:
        """An SVG element begins: count it, its depth, its id and what it uses."""
        if not self.counted:
            self._expansion()
        if len(self.open) >= MAX_SVG_DEPTH:
            raise self.refuse(
                f"elements nested deeper than {MAX_SVG_DEPTH} (groups inside groups); "
                "ungroup some of them", (line, column)
            )  # fmt: skip
        if len(self.nodes) >= MAX_SVG_ELEMENTS:
            raise self.refuse(
                f"more than {MAX_SVG_ELEMENTS} elements; simplify the drawing", (line, column)
            )
        href = attrs.get(f"{XLINK} href", attrs.get("href", "")) if tag == "use" else ""
        segments = (
            path_segments(attrs.get("d", "")) + len(_NUMBER.findall(attrs.get("points", ""))) // 2
        )
        self.nodes.append(Node(tag, line, column, [], href.strip().removeprefix("#"), segments))
        self.segments += segments
        if self.segments > MAX_SEGMENTS:
            raise self.refuse(SEGMENTS, (line, column))
        k = len(self.nodes) - 1
        if self.open:
            self.nodes[self.open[-1]].children.append(k)
        if "id" in attrs:
            self.ids.setdefault(attrs["id"], k)
        self.open.append(k)

    def closed(self, name: str) -> None:
        if self.open:
            self.open.pop()

    def _expansion(self) -> None:
        """Once, at the first element (the DTD is behind): what the references expand to."""
        self.counted = True
        if not self.entities:
            return
        total = sum(
            self.entities.get(m.group(1).decode(), 0) for m in _REFERENCE.finditer(self.data)
        )
        if total > MAX_ENTITY_EXPANSION:
            raise self.refuse(
                f"its entities expand to {total} characters, more than {MAX_ENTITY_EXPANSION}; "
                "write the text itself"
            )

    def check_uses(self) -> None:
        """Refuse a use that shows itself, or uses that expand beyond the limits."""
        if not self.nodes:
            return
        elements, segments = self._measure(0)
        if elements > MAX_SVG_ELEMENTS:
            raise self._at(
                0,
                f"its <use> elements expand it to more than {MAX_SVG_ELEMENTS} elements; simplify the drawing",
            )
        if segments > MAX_SEGMENTS:
            raise self._at(
                0,
                f"more than {MAX_SEGMENTS} path segments (lines, arcs, curves); simplify the drawing (e.g. vpype linesimplify)",
            )

    def _next(self, k: int) -> list[int]:
        n = self.nodes[k]
        used = self.ids.get(n.href) if n.href else None
        return [*n.children, *(() if used is None else (used,))]

    def _measure(self, root: int) -> tuple[int, int]:
        """Elements and path segments under ``root`` once uses are expanded (capped
        just above the limits), walked without recursion; refuses a loop and a depth
        beyond the limit."""
        size: dict[int, tuple[int, int]] = {}
        depth: dict[int, int] = {}
        stack: list[tuple[int, list[int], int]] = [(root, self._next(root), 0)]
        busy = {root}
        while stack:
            k, nxt, i = stack.pop()
            if i < len(nxt):
                stack.append((k, nxt, i + 1))
                child = nxt[i]
                if child in busy:
                    raise self._at(k, f"a <{self.nodes[k].tag}> that shows itself; remove the loop")
                if child not in size:
                    busy.add(child)
                    stack.append((child, self._next(child), 0))
                continue
            busy.discard(k)
            elements = 1 + sum(size[c][0] for c in nxt)
            segments = self.nodes[k].segments + sum(size[c][1] for c in nxt)
            size[k] = (min(elements, MAX_SVG_ELEMENTS + 1), min(segments, MAX_SEGMENTS + 1))
            depth[k] = 1 + max((depth[c] for c in nxt), default=0)
            if depth[k] > MAX_SVG_DEPTH:
                raise self._at(
                    k, f"its <use> elements nest it deeper than {MAX_SVG_DEPTH}; ungroup some"
                )
        return size[root]

    def _at(self, k: int, what: str) -> DrawingError:
        return self.refuse(what, (self.nodes[k].line, self.nodes[k].column))


def path_segments(d: str) -> int:
    """About how many segments path data ``d`` draws (a command's numbers over the
    numbers one segment of it takes; a close is one): for the limit, not the drawing."""
    count = 0
    for m in _COMMAND.finditer(d):
        if m.group(1) is None:
            count += 1
        else:
            count += max(1, len(_NUMBER.findall(m.group(2))) // _ARGS[m.group(1).lower()])
    return count
