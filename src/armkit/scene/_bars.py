"""The instruments of a scene file: ``[[xylophones]]`` (bars interpolated from the first
to the last, or given bar by bar: ``bars = [{note = "C5", top_mm = [x, y, z]}, ...]``)
and ``[[drums]]``."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from ._fields import Entry, entries
from ._instruments import Drum, Xylophone, note_name, note_number
from ._object import Placed
from ._rect import Rect

XYLOPHONE_KEYS = (
    "name", "bars", "bar_size_mm", "row_deg", "first_bar_mm", "last_bar_mm", "lowest_note",
    "bar_count",
)  # fmt: skip
_ROW_KEYS = ("first_bar_mm", "last_bar_mm", "lowest_note", "bar_count")
_BAR_KEYS = ("note", "top_mm", "size_mm", "row_deg")
_DRUM_KEYS = ("name", "position_mm", "radius_mm", "top_z_mm", "note")
MAX_BARS = 88


def load_xylophones(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Xylophone, ...]:
    """``[[xylophones]]``: bar centres from ``first_bar_mm`` to ``last_bar_mm`` one
    semitone apart, or ``bars``, a list of ``{note, top_mm, size_mm, row_deg}``."""
    out = []
    for e in entries(path, data, "xylophones", XYLOPHONE_KEYS):
        xylophone = _by_bar(e) if e.has("bars") else _interpolated(e)
        _check_apart(e, xylophone)
        out.append(xylophone)
    return tuple(out)


def load_drums(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Drum, ...]:
    """``[[drums]]``: a round head of ``radius_mm`` at ``top_z_mm``."""
    out = []
    for e in entries(path, data, "drums", _DRUM_KEYS):
        position = e.point_mm("position_mm")
        top = e.mm("top_z_mm")
        if top <= position[2]:
            raise e.fail("top_z_mm", f"must be above the drum's base ({position[2] * 1000:g} mm)")
        out.append(
            Drum(e.name(), position, e.positive_mm("radius_mm"), top, e.integer("note", hi=127))
        )
    return tuple(out)


def _interpolated(e: Entry) -> Xylophone:
    if e.has("row_deg"):
        raise e.fail(
            "row_deg", "only with bars: here the row runs from first_bar_mm to last_bar_mm"
        )
    first, last = e.point_mm("first_bar_mm"), e.point_mm("last_bar_mm")
    count = e.integer("bar_count", lo=2, hi=MAX_BARS)
    if float(np.linalg.norm(last[:2] - first[:2])) < 1e-3:
        raise e.fail("last_bar_mm", "must be at least 1 mm from first_bar_mm across the table")
    bar = e.sizes_mm("bar_size_mm", 2)
    note = e.integer("lowest_note", lo=0, hi=127 - count + 1)
    return Xylophone.interpolated(e.name(), first, last, note, count, (bar[0], bar[1]))


def _by_bar(e: Entry) -> Xylophone:
    """Bars given one by one: each note once, any notes, in any order."""
    mixed = [k for k in _ROW_KEYS if e.has(k)]
    if mixed:
        raise e.fail(mixed[0], "give either bars or first_bar_mm/last_bar_mm/lowest_note/bar_count")
    items = e.data["bars"]
    if not isinstance(items, list) or not 1 <= len(items) <= MAX_BARS:
        raise e.fail("bars", f"must be a list of 1..{MAX_BARS} tables {{note, top_mm}}")
    size = e.sizes_mm("bar_size_mm", 2) if e.has("bar_size_mm") else None
    bars = [Entry(e.path, f"{e.where}.bars[{k}]", item, _BAR_KEYS) for k, item in enumerate(items)]
    notes = [_note(b) for b in bars]
    for k, note in enumerate(notes):
        if notes.index(note) != k:
            raise bars[k].fail("note", f"{note_name(note)} is already bars[{notes.index(note)}]")
    tops = np.array([b.point_mm("top_mm") for b in bars])
    sizes = np.array([_size(b, size) for b in bars])
    default = _default_row(e, notes, tops)
    rows = np.array([b.deg("row_deg") if b.has("row_deg") else default for b in bars])
    order = np.argsort(notes)
    return Xylophone(e.name(), tuple(sorted(notes)), tops[order], sizes[order], rows[order])


def _note(bar: Entry) -> int:
    """A bar's note: a MIDI number 0..127 or a name (C4 = 60, F#5, Bb3)."""
    value = bar.data.get("note")
    if isinstance(value, str):
        number = note_number(value)
        if number is None:
            raise bar.fail("note", f"must be a note name like C4, F#5 or Bb3 (MIDI 0..127), got {value!r}")  # fmt: skip
        return number
    return bar.integer("note", lo=0, hi=127)


def _size(bar: Entry, default: tuple[float, ...] | None) -> tuple[float, ...]:
    if bar.has("size_mm") or default is None:
        if not bar.has("size_mm"):
            raise bar.fail("size_mm", "missing: give it here or bar_size_mm for every bar")
        return bar.sizes_mm("size_mm", 2)
    return default


def _default_row(e: Entry, notes: list[int], tops: np.ndarray) -> float:
    """``row_deg`` of the xylophone, else the direction from its lowest bar to its highest."""
    if e.has("row_deg"):
        return e.deg("row_deg")
    low, high = tops[int(np.argmin(notes))], tops[int(np.argmax(notes))]
    if float(np.linalg.norm(high[:2] - low[:2])) < 1e-3:
        raise e.fail("row_deg", "missing: give the row's direction (deg from x towards y)")
    return math.atan2(float(high[1] - low[1]), float(high[0] - low[0]))


def _check_apart(e: Entry, x: Xylophone) -> None:
    """No two bars may overlap seen from above (a strike would hit both)."""
    rects = [
        Rect(x.tops[k, :2], (x.sizes[k, 1] / 2, x.sizes[k, 0] / 2), float(x.rows[k]))
        for k in range(len(x.notes))
    ]
    for i in range(len(rects)):
        for j in range(i):
            if rects[i].overlaps(rects[j], slack=1e-5):
                a, b = note_name(x.notes[j]), note_name(x.notes[i])
                raise e.fail(
                    "bars" if e.has("bars") else "bar_size_mm",
                    f"the bars of {a} and {b} overlap seen from above; move them apart or make them narrower",
                )
