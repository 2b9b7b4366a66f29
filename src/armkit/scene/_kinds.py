"""The registry of the kinds of object a scene file holds: one entry each (its section,
its loader, where a ``Scene`` keeps its objects), in the order they are read (a cube
may stand in a board's socket, a pen stand holds a pen read before it). Each kind's
module holds its dataclass, its loader, its solids for the clearance check, the
surfaces it offers and its primitives for the views (the protocol: ``_object``)."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from ._bars import load_drums, load_xylophones
from ._board import load_boards
from ._container import load_containers
from ._cube import load_cubes
from ._hand import load_hands
from ._object import ObjectKind
from ._pen import load_pen_stands, load_pens
from ._place import load_places
from ._scene import Scene
from ._surfaces import load_sheets

OBJECT_KINDS: tuple[ObjectKind[Any], ...] = (
    ObjectKind("boards", load_boards, lambda s, found: replace(s, boards=found)),
    ObjectKind("containers", load_containers, lambda s, found: replace(s, containers=found)),
    ObjectKind("places", load_places, lambda s, found: replace(s, places=found)),
    ObjectKind("pens", load_pens, lambda s, found: replace(s, pens=found)),
    ObjectKind("sheets", load_sheets, lambda s, found: replace(s, sheets=found)),
    ObjectKind("xylophones", load_xylophones, lambda s, found: _instruments(s, found)),
    ObjectKind("drums", load_drums, lambda s, found: _instruments(s, found)),
    ObjectKind("hands", load_hands, lambda s, found: replace(s, hands=found)),
    ObjectKind("cubes", load_cubes, lambda s, found: replace(s, cubes=found)),
    ObjectKind("pen_stands", load_pen_stands, lambda s, found: replace(s, pen_stands=found)),
)


def _instruments(scene: Scene, found: tuple[Any, ...]) -> Scene:
    return replace(scene, instruments=(*scene.instruments, *found))
