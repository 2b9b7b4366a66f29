"""The registry of the kinds of object a scene file holds: one entry each, in the order
they are read (a cube may stand in a board's socket, a pen stand holds a pen read
before it). Each kind's module holds its dataclass, its loader, its solids for the
clearance check and its primitives for the views (the protocol: ``_object``)."""

from __future__ import annotations

from ._bars import load_drums, load_xylophones
from ._board import load_boards
from ._container import load_containers
from ._cube import load_cubes
from ._hand import load_hands
from ._object import ObjectKind
from ._pen import load_pen_stands, load_pens
from ._place import load_places
from ._surfaces import load_sheets

OBJECT_KINDS: tuple[ObjectKind, ...] = (
    ObjectKind("boards", load_boards),
    ObjectKind("containers", load_containers),
    ObjectKind("places", load_places),
    ObjectKind("pens", load_pens),
    ObjectKind("sheets", load_sheets),
    ObjectKind("xylophones", load_xylophones),
    ObjectKind("drums", load_drums),
    ObjectKind("hands", load_hands),
    ObjectKind("cubes", load_cubes),
    ObjectKind("pen_stands", load_pen_stands),
)
