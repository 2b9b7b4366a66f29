"""The drawing pipeline's entry point: a source onto a sheet, as ordered strokes.

``plan_drawing(source, sheet, fit, tolerance)`` reads (SVG, G-code or a
``Figure`` of shapes), flattens curves, fits the drawing onto the sheet, cuts
what falls outside its printable area, joins strokes whose ends meet,
simplifies, and orders the strokes to cut pen-up travel. Everything stays
within ``tolerance`` of the source: flattening and simplifying get half each.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError
from .._inputs import brief, is_number, shown
from ._errors import DrawingError, DrawingWarning
from ._figure import Figure
from ._fit import Fit, apply, as_fit, clip_to_box, fit_transform
from ._gcode import read_gcode
from ._merge import merge_strokes
from ._order import order_strokes, pen_up_length
from ._shapes import uv_point
from ._simplify import simplify
from ._svg import read_svg

F64 = NDArray[np.float64]
GCODE_SUFFIXES = (".gcode", ".nc", ".ngc", ".gc", ".g", ".tap")
MAX_SHEET = 10.0  # [m] a sheet's width or height, as any size in a scene (10000 mm)


class SheetLike(Protocol):
    """Anything with a sheet's size: ``armkit.scene.Sheet`` or ``PaperSize``."""

    @property
    def width(self) -> float: ...  # [m], along u
    @property
    def height(self) -> float: ...  # [m], along v


class SheetPlane(Protocol):
    """A sheet placed in the world: ``armkit.scene.Sheet``."""

    def to_world(self, uv: F64) -> F64: ...  # (N, 2) [m] -> (N, 3) [m]


@dataclass(frozen=True)
class PaperSize:
    """A sheet's size alone [m] (the scene's ``Sheet`` also places it): width and
    height each > 0 and at most 10 m (A5 portrait is ``PaperSize(0.148, 0.210)``).

    Raises:
        InputError: a width or height that is not a number in that range.
    """

    width: float
    height: float

    def __post_init__(self) -> None:
        for name, v in (("width", self.width), ("height", self.height)):
            if not (is_number(v) and 0.0 < v <= MAX_SHEET):  # NaN fails too
                finite = is_number(v) and math.isfinite(v)
                got = f"{shown(v)} m ({brief(float(v) * 1e3)} mm)" if finite else shown(v)
                raise InputError(
                    f"PaperSize {name} must be more than 0 and at most {MAX_SHEET * 1e3:g} mm, "
                    f"given in metres (A5 is PaperSize(0.148, 0.210)), got {got}"
                )


@dataclass(frozen=True)
class DrawingPlan:
    """What to draw, in order.

    Attributes:
        strokes: pen-down polylines in drawing order, each (N, 2), sheet (u, v) [m].
        size: the sheet's (width, height) [m].
        transform: (3, 3) map from the source's metres (y up) to (u, v).
        tolerance: the largest distance of the strokes from the source [m].
        source: the file's name or a label.
        notes: what was left out or cut, one line each.
        start: where the pen starts (u, v) [m], or None (anywhere).
        dwell: pauses the source asks for [s].
    """

    strokes: tuple[F64, ...]
    size: tuple[float, float]
    transform: F64
    tolerance: float
    source: str
    notes: tuple[str, ...] = ()
    start: F64 | None = None
    dwell: float = 0.0

    @property
    def pen_down_length(self) -> float:
        """Length of every stroke [m]."""
        return float(sum(np.linalg.norm(np.diff(s, axis=0), axis=1).sum() for s in self.strokes))

    @property
    def pen_up_length(self) -> float:
        """Pen-up travel between strokes (and from ``start``, if set) [m]."""
        return pen_up_length(self.strokes, self.start)

    @property
    def pen_lifts(self) -> int:
        """How often the pen is lifted: once after each stroke."""
        return len(self.strokes)

    def world_strokes(self, sheet: SheetPlane) -> tuple[F64, ...]:
        """The strokes on the sheet's plane in the world, (N, 3) each [m]."""
        return tuple(np.asarray(sheet.to_world(s), dtype=np.float64) for s in self.strokes)


def read_drawing(path: str | Path, *, z_down: float = 0.0) -> Figure:
    """Read an SVG or G-code file (by its suffix) into a ``Figure``."""
    if not isinstance(path, str | Path):
        raise DrawingError(f"the drawing must be a file path (str or Path), got {path!r}")
    suffix = Path(path).suffix.lower()
    if suffix == ".svg":
        return read_svg(path)
    if suffix in GCODE_SUFFIXES:
        return read_gcode(path, z_down=z_down)
    raise DrawingError(
        f"cannot tell the format from the suffix {suffix or '(none)'!r}; "
        f"give a .svg or a G-code file ({' '.join(GCODE_SUFFIXES)})",
        file=str(path),
    )


def plan_drawing(
    source: Figure | str | Path,
    sheet: SheetLike | tuple[float, float],
    fit: Fit | bool | None = None,
    tolerance: float = 1e-4,
    *,
    start: ArrayLike | None = None,
) -> DrawingPlan:
    """Plan ``source`` on ``sheet`` (or a (width, height) [m]) within ``tolerance`` [m];
    the pen starts at ``start`` (u, v) [m] if given. ``fit``: None or False draws the
    file at its real size centred on the sheet (DrawingError with its size if it does
    not fit), True scales it to the sheet, a ``Fit`` says exactly how. Raise
    ``DrawingError``."""
    size = _size(sheet)
    if not (is_number(tolerance) and math.isfinite(tolerance) and tolerance > 0):
        raise DrawingError(f"tolerance must be > 0 m, got {shown(tolerance)}")
    uv0 = None if start is None else uv_point(start, "start")
    fig = source if isinstance(source, Figure) else read_drawing(source)
    fit = as_fit(fit)
    M, strokes = _fitted(fig, size, fit, tolerance)
    margin = np.full(2, fit.margin)
    kept = clip_to_box(strokes, margin - 1e-9, np.array(size) - margin + 1e-9)
    notes = fig.notes + _cut_note(fig.source, strokes, kept, fit)
    if not kept:
        raise DrawingError(
            "everything lies outside the sheet; fit it to the sheet", file=fig.source
        )
    strokes = simplify(merge_strokes(kept, tolerance / 2), tolerance / 2)
    ordered = order_strokes(strokes, uv0)
    return DrawingPlan(tuple(ordered), size, M, tolerance, fig.source, notes, uv0, fig.dwell)


def _size(sheet: object) -> tuple[float, float]:
    """The sheet's (width, height) [m], each > 0 (DrawingError otherwise)."""
    if isinstance(sheet, tuple | list):
        w, h = uv_point(sheet, "sheet (width, height)").tolist()
    else:
        w, h = getattr(sheet, "width", None), getattr(sheet, "height", None)
        if not (is_number(w) and is_number(h)):
            raise DrawingError(
                "sheet must be a Sheet (armkit.scene), a PaperSize or (width, height) [m], "
                f"got {shown(sheet)}"
            )
    if not all(math.isfinite(v) and v > 0 for v in (w, h)):  # type: ignore[arg-type]
        raise DrawingError(f"the sheet's width and height must be > 0 m, got {shown((w, h))}")
    return float(w), float(h)  # type: ignore[arg-type]


def _fitted(
    fig: Figure, size: tuple[float, float], fit: Fit, tolerance: float
) -> tuple[F64, list[F64]]:
    """The fit's map and the strokes flattened within tolerance / 2 on the sheet."""
    extent = fig.extent()
    if not fig.paths:
        gcode = Path(fig.source).suffix.lower() in GCODE_SUFFIXES
        hint = " (the pen never goes down: Z <= z_down, M3 or M300 S30)" if gcode else ""
        raise DrawingError("nothing to draw" + hint, file=fig.source)
    if not math.isfinite(extent):
        raise DrawingError("coordinates are not finite", file=fig.source)
    coarse = fig.flatten(max(extent, 1e-9) / 2000)
    try:
        M = fit_transform(coarse, size, fit)
    except DrawingError as e:
        if e.file:
            raise
        raise DrawingError(str(e), file=fig.source) from None
    k = float(np.sqrt(abs(np.linalg.det(M[:2, :2]))))
    fine = fig.flatten(tolerance / 2 / max(k, 1e-12))
    M = fit_transform(fine, size, fit)
    strokes = apply(M, fine)
    if not all(np.all(np.isfinite(s)) for s in strokes):
        raise DrawingError("coordinates overflow after the transforms", file=fig.source)
    return M, strokes


def _cut_note(source: str, before: list[F64], after: list[F64], fit: Fit) -> tuple[str, ...]:
    def length(strokes: list[F64]) -> float:
        return float(sum(np.linalg.norm(np.diff(s, axis=0), axis=1).sum() for s in strokes))

    cut = length(before) - length(after)
    if cut <= 1e-6:
        return ()
    note = (
        f"{source}: cut {cut * 1e3:.1f} mm of {length(before) * 1e3:.1f} mm of line outside the "
        f"sheet's printable area (margin {fit.margin * 1e3:g} mm); scale it down or fit it"
    )
    warnings.warn(note, DrawingWarning, stacklevel=3)
    return (note,)
