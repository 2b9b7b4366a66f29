"""SVG files to a ``Figure`` through svgelements (the ``svg`` extra).

Paths and the basic shapes (rect, circle, ellipse, line, polyline, polygon),
with their transforms, ``use`` references and the root's viewBox, as svgelements
resolves them at 96 px per inch; hidden elements (display:none) are left out.
Text is left out with a warning: convert it to paths first (Inkscape: Path >
Object to Path). The file is checked first (``_svg_check``), so a problem names
its line and column.
"""

from __future__ import annotations

import io
import warnings
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

import numpy as np

from .._input_limits import MAX_DRAWING_BYTES, LimitError, read_limited
from ._errors import DrawingError, DrawingWarning
from ._figure import Figure
from ._segments import Cubic, EllipticArc, FigurePath, Line, Quad, Segment
from ._svg_check import SVG_NS, Element, check_svg

METRES_PER_PX = 0.0254 / 96.0  # CSS: 96 px per inch
SVGELEMENTS_FAILURES = (
    ValueError,
    TypeError,
    IndexError,
    KeyError,
    AttributeError,
    ZeroDivisionError,
    OverflowError,
    RecursionError,
)


def read_svg(path: str | Path) -> Figure:
    """Read an SVG file; raise ``DrawingError`` naming the file, line and column."""
    name = str(path)
    data = read_bytes(path)
    checked = check_svg(data, name)
    try:
        import svgelements
    except ImportError:
        raise DrawingError(
            "reading SVG needs svgelements: pip install 'armkit[svg]'", file=name
        ) from None
    try:
        paths = _paths(data, svgelements)
    except SVGELEMENTS_FAILURES as e:
        # the checks above should leave svgelements nothing to choke on; if they
        # missed something, find the element it chokes on, alone
        at = next((el for el in checked.elements if not _reads(el, svgelements)), None)
        raise DrawingError(
            f"svgelements cannot read {'<' + at.tag + '>' if at else 'it'} "
            f"({type(e).__name__}: {e}); fix or remove it",
            file=name,
            line=at.line if at else None,
            column=at.column if at else None,
        ) from e
    notes = _left_out_note(name, checked.left_out)
    k = METRES_PER_PX
    to_metres = np.array([[k, 0.0, 0.0], [0.0, -k, 0.0], [0.0, 0.0, 1.0]])
    return Figure(tuple(paths), to_metres, source=name, notes=notes)


def _left_out_note(name: str, left_out: tuple[Element, ...]) -> tuple[str, ...]:
    """Warn about, and note, the text and images a pen cannot draw."""
    if not left_out:
        return ()
    kinds = sorted({e.tag for e in left_out})
    where = ", ".join(f"line {e.line}" for e in left_out[:3]) + (
        " ..." if len(left_out) > 3 else ""
    )
    note = (
        f"{name}: {len(left_out)} {' and '.join(kinds)} element(s) left out ({where}); "
        "convert text to paths to draw it (Inkscape: Path > Object to Path), trace images"
    )
    warnings.warn(note, DrawingWarning, stacklevel=3)
    return (note,)


def _paths(data: bytes, se: Any) -> list[FigurePath]:
    svg = se.SVG.parse(io.BytesIO(data))
    return [p for e in svg.elements() for p in _element_paths(e, se)]


def _reads(element: Element, se: Any) -> bool:
    """Whether svgelements reads this element alone, in an SVG of its own."""
    attrs = " ".join(f"{k.rpartition(' ')[2]}={quoteattr(v)}" for k, v in element.attrs.items())
    alone = f'<svg xmlns="{SVG_NS}"><{element.tag} {attrs}/></svg>'.encode()
    try:
        _paths(alone, se)
    except SVGELEMENTS_FAILURES:
        return False
    return True


def read_bytes(path: str | Path) -> bytes:
    """The file's bytes, or ``DrawingError`` naming it and why it cannot be read (or
    that it is larger than ``MAX_DRAWING_BYTES``)."""
    try:
        return read_limited(path, MAX_DRAWING_BYTES, "drawing")
    except LimitError as e:
        raise DrawingError(e.problem, file=e.file) from None


def _element_paths(element: Any, se: Any) -> list[FigurePath]:
    """The pen-down runs of one svgelements element (none for non-shapes)."""
    if not isinstance(element, se.Shape):
        return []
    if element.values.get("visibility") in ("hidden", "collapse"):
        return []
    runs: list[list[Segment]] = []
    for seg in abs(se.Path(element)):
        if isinstance(seg, se.Move):
            runs.append([])
            continue
        mine = _segment(seg, se)
        if mine is not None:
            if not runs:
                runs.append([])
            runs[-1].append(mine)
    return [FigurePath(tuple(r)) for r in runs if r]


def _xy(point: Any) -> np.ndarray:
    return np.array([float(point.x), float(point.y)])


def _segment(seg: Any, se: Any) -> Segment | None:
    """One svgelements segment as armkit's; None for zero-length closes."""
    if seg.start is None or seg.end is None:
        return None
    if isinstance(seg, se.Close | se.Line):
        if isinstance(seg, se.Close) and seg.start == seg.end:
            return None
        return Line(_xy(seg.start), _xy(seg.end))
    if isinstance(seg, se.CubicBezier):
        return Cubic(np.array([_xy(seg.start), _xy(seg.control1), _xy(seg.control2), _xy(seg.end)]))
    if isinstance(seg, se.QuadraticBezier):
        return Quad(np.array([_xy(seg.start), _xy(seg.control), _xy(seg.end)]))
    if isinstance(seg, se.Arc):
        if seg.rx == 0 or seg.ry == 0 or seg.sweep == 0:
            return Line(_xy(seg.start), _xy(seg.end))
        return EllipticArc(
            _xy(seg.center),
            float(seg.rx),
            float(seg.ry),
            float(seg.get_rotation()),
            float(seg.get_start_t()),
            float(seg.sweep),
        )
    return None
