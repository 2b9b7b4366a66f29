"""Pictures of a plan and of what was drawn, at the sheet's real size.

Two colours: ink (pen down) and travel (pen up, dashed). matplotlib (the
``plot`` extra) is imported only here, when a picture is asked for.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._files import check_output_path
from ._errors import DrawingError
from ._metrics import PenTrace, ink, sheet_uv
from ._plan import DrawingPlan, SheetPlane

F64 = NDArray[np.float64]
INK, TRAVEL, EDGE = "#1b2a6b", "#e4572e", "#b0b0b0"
SUFFIXES = (".png", ".svg", ".pdf")


def check_picture_path(path: str | Path, option: str = "") -> Path:
    """The path, once a picture (.png, .svg or .pdf) is proven writable there
    (``armkit._files.check_output_path``; ``option`` names it in the error, as
    ``--preview``); else ``InputError``. Call it before anything moves."""
    return check_output_path(path, option, SUFFIXES)


def preview(plan: DrawingPlan, path: str | Path, dpi: float = 150.0) -> Path:
    """Draw the plan: strokes in ink, pen-up moves between them dashed."""
    p = check_picture_path(path)
    fig, ax = _sheet_axes(plan.size, f"{Path(plan.source).name or 'plan'}: plan", dpi)
    _travel(ax, [s[0] for s in plan.strokes], [s[-1] for s in plan.strokes], plan.start)
    _lines(ax, plan.strokes, INK, 0.6)
    return _save(fig, p, dpi)


def result(
    plan: DrawingPlan, trace: PenTrace, sheet: SheetPlane, path: str | Path, dpi: float = 150.0
) -> Path:
    """Draw what the pen put on the paper (ink) and where it moved lifted (dashed)."""
    p = check_picture_path(path)
    fig, ax = _sheet_axes(plan.size, f"{Path(plan.source).name or 'plan'}: drawn", dpi)
    uv, _ = sheet_uv(sheet, trace.points)
    up = ~(trace.down[:-1] & trace.down[1:])
    segs = np.stack([uv[:-1][up], uv[1:][up]], axis=1) * 1e3
    _collection(ax, segs, TRAVEL, 0.4, dashed=True)
    _lines(ax, ink(trace, sheet), INK, 0.6)
    return _save(fig, p, dpi)


def _sheet_axes(size: tuple[float, float], title: str, dpi: float) -> tuple[Any, Any]:
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise DrawingError("pictures need matplotlib: pip install 'armkit[plot]'") from None
    w, h = size[0] * 1e3, size[1] * 1e3  # [mm]
    fig = Figure(figsize=(w / 25.4, h / 25.4), dpi=dpi)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.set_xlim(0, w)
    ax.set_ylim(0, h)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.add_patch(_rect(w, h))
    ax.text(2, 2, title, fontsize=6, color=EDGE)
    return fig, ax


def _rect(w: float, h: float) -> Any:
    from matplotlib.patches import Rectangle

    return Rectangle((0, 0), w, h, fill=False, edgecolor=EDGE, linewidth=1.0)


def _lines(ax: Any, strokes: Sequence[F64], colour: str, width: float) -> None:
    segs = [np.stack([s[:-1], s[1:]], axis=1) for s in strokes if len(s) > 1]
    if segs:
        _collection(ax, np.vstack(segs) * 1e3, colour, width)
    dots = np.array([s[0] for s in strokes if len(s) == 1 or np.all(s == s[0])]).reshape(-1, 2)
    if len(dots):
        ax.plot(*(dots * 1e3).T, ".", color=colour, markersize=1.5)


def _travel(ax: Any, heads: list[F64], tails: list[F64], start: F64 | None) -> None:
    ends = ([start] if start is not None else []) + tails[:-1]
    begins = heads if start is not None else heads[1:]
    if begins:
        segs = np.stack([np.array(ends), np.array(begins)], axis=1) * 1e3
        _collection(ax, segs, TRAVEL, 0.4, dashed=True)


def _collection(ax: Any, segs: F64, colour: str, width: float, dashed: bool = False) -> None:
    from matplotlib.collections import LineCollection

    style = (0, (3, 2)) if dashed else "solid"
    ax.add_collection(LineCollection(list(segs), colors=colour, linewidths=width, linestyles=style))


def _save(fig: Any, path: Path, dpi: float) -> Path:
    try:
        fig.savefig(path, dpi=dpi)
    except OSError as e:
        raise DrawingError(
            f"cannot write the picture ({e.strerror or e})", file=str(path)
        ) from None
    return path
