"""The scene as text: one line per object, in millimetres and degrees."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from .._inputs import mm
from .._terminal import count
from ._board import Board
from ._cube import Cube
from ._instruments import Drum, Xylophone, note_name
from ._scene import Scene

F64 = NDArray[np.float64]


def _deg(a: float) -> str:
    return f"{round(math.degrees(a), 1) + 0.0:.1f} deg"  # never -0.0


def describe(scene: Scene) -> list[str]:
    """Lines describing every object of ``scene``."""
    base = scene.T_world_base
    yaw = math.atan2(base[1, 0], base[0, 0])
    out = [
        f"scene {scene.name}" + (f" ({scene.source})" if scene.source else ""),
        f"  table at z = {scene.table_z * 1000:.1f} mm; arm base at {mm(base[:3, 3])}, yaw {_deg(yaw)}",
    ]
    sections = (
        ("boards", [_board(b) for b in scene.boards]),
        ("cubes", [_cube(scene, c) for c in scene.cubes]),
        ("containers", [f"{c.name}: {_size(c.size)} outside, wall {c.wall * 1000:.1f} mm, floor centre {mm(c.position)}" for c in scene.containers]),
        ("places", [f"{p.name}: {mm(p.position)}" + ("" if p.pitch is None else f", pitch {_deg(p.pitch)}") for p in scene.places]),
        ("pens", [f"{p.name}: {p.length * 1000:.1f} mm long, {p.holder_length * 1000:.1f} mm in its stand, tip {p.tip_offset * 1000:.1f} mm beyond the tool point" for p in scene.pens]),
        ("pen stands", [f"{s.name}: {mm(s.position)}, holds {s.pen}" for s in scene.pen_stands]),
        ("sheets", [f"{s.name}: {s.width * 1000:.1f} x {s.height * 1000:.1f} mm, corner {mm(s.origin)}, normal {np.round(s.normal, 3).tolist()}" for s in scene.sheets]),
        ("instruments", [_instrument(i) for i in scene.instruments]),
        ("hands", [f"{h.name}: {_size(h.size)}, centre {mm(h.position)}" for h in scene.hands]),
    )  # fmt: skip
    for title, lines in sections:
        if lines:
            out.append(f"{title}:")
            out.extend(f"  {line}" for line in lines)
    if len(out) == 2:
        out.append("  nothing on the table")
    return out


def _size(size: tuple[float, ...]) -> str:
    return " x ".join(f"{v * 1000:.1f}" for v in size) + " mm"


def _board(b: Board) -> str:
    return (
        f"{b.name}: {b.rows} x {b.cols} sockets {b.socket_size * 1000:.1f} mm wide, "
        f"{b.socket_depth * 1000:.1f} mm deep, {b.pitch * 1000:.1f} mm apart; top centre "
        f"{mm(b.origin)}, yaw {_deg(b.yaw)}, {_size((*b.size, b.thickness))}"
    )


def _cube(scene: Scene, c: Cube) -> str:
    where = ""
    for b in scene.boards:
        found = b.socket_at(c.position)
        if found is not None and abs(b.socket(*found)[2] - c.position[2]) < 1e-4:
            where = f", in {b.name}[{found[0]}, {found[1]}]"
    return f"{c.name}: {c.size * 1000:.1f} mm at {mm(c.position)}, yaw {_deg(c.yaw)}, {c.up_face} up{where}"


def _instrument(i: Xylophone | Drum) -> str:
    if isinstance(i, Xylophone):
        bars = ", ".join(f"{note_name(n)} {mm(i.bar_top(n))}" for n in i.notes)
        return f"{i.name}: xylophone, {count(len(i.notes), 'bar')} (note, top centre): {bars}"
    return f"{i.name}: drum (note {i.note}), head r {i.radius * 1000:.1f} mm at {mm(i.head)}"
