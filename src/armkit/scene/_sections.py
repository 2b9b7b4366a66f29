"""Scene file sections for drawing and music: sheets, drums (xylophones: ``_bars``)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ._fields import Entry, entries
from ._instruments import Drum
from ._surfaces import PAPER_SIZES, Sheet

_SHEET = ("name", "size", "width_mm", "height_mm", "landscape", "origin_mm", "u", "v")
_DRUM = ("name", "position_mm", "radius_mm", "top_z_mm", "note")


def sheets(path: Path, data: dict[str, Any]) -> tuple[Sheet, ...]:
    """``[[sheets]]``: a preset ``size`` (A3..A6, ``landscape = true`` to turn it) or
    ``width_mm``/``height_mm``; ``origin_mm`` a corner; ``u``, ``v`` its edge
    directions (default: along x and y, lying on the table)."""
    return tuple(_sheet(e) for e in entries(path, data, "sheets", _SHEET))


def _sheet(e: Entry) -> Sheet:
    if e.has("size") == (e.has("width_mm") or e.has("height_mm")):
        raise e.fail("size", "give either size (A3, A4, A5, A6) or width_mm and height_mm")
    if e.has("size"):
        width, height = PAPER_SIZES[e.text("size", choices=tuple(PAPER_SIZES))]
    else:
        width, height = e.positive_mm("width_mm"), e.positive_mm("height_mm")
    landscape = e.data.get("landscape", False)
    if not isinstance(landscape, bool):
        raise e.fail("landscape", f"must be true or false, got {landscape!r}")
    if landscape:
        width, height = height, width
    u, v = e.direction("u", [1.0, 0.0, 0.0]), e.direction("v", [0.0, 1.0, 0.0])
    if abs(float(u @ v)) > 1e-6:
        raise e.fail("v", f"must be at right angles to u, got u = {u.tolist()}, v = {v.tolist()}")
    return Sheet(e.name(), e.point_mm("origin_mm"), u, v, width, height)


def drums(path: Path, data: dict[str, Any]) -> tuple[Drum, ...]:
    """``[[drums]]``: a round head of ``radius_mm`` at ``top_z_mm``."""
    out = []
    for e in entries(path, data, "drums", _DRUM):
        position = e.point_mm("position_mm")
        top = e.mm("top_z_mm")
        if top <= position[2]:
            raise e.fail("top_z_mm", f"must be above the drum's base ({position[2] * 1000:g} mm)")
        out.append(
            Drum(e.name(), position, e.positive_mm("radius_mm"), top, e.integer("note", hi=127))
        )
    return tuple(out)
