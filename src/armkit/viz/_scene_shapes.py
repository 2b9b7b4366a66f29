"""A scene (``armkit.scene.Scene``) as primitives: the table, boards and their sockets,
cubes, containers, pen stands, sheets of paper, instruments, hands and named places.

Everything is in the scene's (table's) frame [m]; the arm is drawn there through
``Scene.T_world_base``. Names are stable (``/scene/<object name>``,
``/scene/<board>_sockets/<row>_<col>``), so a view moves a cube by redrawing
the primitive of the same name (``cube_primitive``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..scene import Board, Container, Cube, Drum, Scene, Sheet, Xylophone
from ._primitives import RGB, Box, Cylinder, Label, Primitive, pose

F64 = NDArray[np.float64]

BOARD_COLOUR: RGB = (150, 110, 70)  # brown
SOCKET_COLOUR: RGB = (70, 48, 30)
CONTAINER_COLOUR: RGB = (120, 150, 175)  # grey blue
SHEET_COLOUR: RGB = (250, 250, 250)
STAND_COLOUR: RGB = (90, 90, 100)
PEN_COLOUR: RGB = (240, 200, 30)  # yellow
BAR_COLOURS: tuple[RGB, ...] = ((190, 140, 70), (150, 100, 50))  # naturals, sharps (darker)
DRUM_COLOUR: RGB = (180, 40, 40)
PLACE_COLOUR: RGB = (60, 60, 60)
HAND_COLOUR: RGB = (225, 180, 150)  # skin
# Cubes named after a colour are drawn in it; other cubes take the palette in turn.
NAMED_COLOURS: dict[str, RGB] = {
    "red": (215, 25, 25),
    "green": (20, 170, 40),
    "blue": (25, 70, 230),
    "yellow": (230, 200, 20),
    "magenta": (200, 20, 180),
    "cyan": (20, 180, 180),
    "teal": (20, 180, 180),
}
PALETTE: tuple[RGB, ...] = ((200, 20, 180), (25, 70, 230), (20, 180, 180), (230, 200, 20))
THIN = 0.001  # [m] thickness of paper and of the place marks


def scene_primitives(scene: Scene) -> list[Primitive]:
    """Every object of ``scene`` (the table is the view's own ``table_primitive``)."""
    shapes: list[Primitive] = []
    for board in scene.boards:
        shapes += board_primitives(board)
    for container in scene.containers:
        shapes += container_primitives(container)
    for sheet in scene.sheets:
        shapes.append(sheet_primitive(sheet))
    for stand in scene.pen_stands:
        pen = next((p for p in scene.pens if p.name == stand.pen), None)
        length = pen.length if pen is not None else 0.12
        shapes.append(Cylinder(f"/scene/{stand.name}", 0.015, 0.03, pose(stand.position - np.array([0.0, 0.0, 0.015])), STAND_COLOUR))  # fmt: skip
        tip = stand.position + np.array(
            [0.0, 0.0, length / 2 - (pen.holder_length if pen else 0.0)]
        )
        shapes.append(Cylinder(f"/scene/{stand.pen}", 0.005, length, pose(tip), PEN_COLOUR))
    for instrument in scene.instruments:
        shapes += instrument_primitives(instrument)
    for hand in scene.hands:
        shapes.append(Box(f"/scene/{hand.name}", np.array(hand.size), pose(hand.position), HAND_COLOUR))  # fmt: skip
    for place in scene.places:
        shapes.append(Label(f"/scene/{place.name}", place.position, place.name, PLACE_COLOUR))
    shapes += [cube_primitive(cube, scene) for cube in scene.cubes]
    return shapes


def cube_colour(name: str, scene: Scene | None = None) -> RGB:
    """The colour a cube is drawn in: its name's colour, else the palette by its place
    in ``scene``."""
    if name in NAMED_COLOURS:
        return NAMED_COLOURS[name]
    names = [c.name for c in scene.cubes] if scene is not None else []
    k = names.index(name) if name in names else sum(map(ord, name))
    return PALETTE[k % len(PALETTE)]


def cube_primitive(cube: Cube, scene: Scene | None = None, T: F64 | None = None) -> Box:
    """``cube`` as a box at its pose (or at the centre pose ``T`` (4, 4) [m], held)."""
    where = cube.T if T is None else T
    return Box(f"/scene/{cube.name}", np.full(3, cube.size), where, cube_colour(cube.name, scene))


def board_primitives(board: Board) -> list[Primitive]:
    """The plate (its top at ``board.top_z``) and a dark square in every socket."""
    T = pose(board.origin - np.array([0.0, 0.0, board.thickness / 2]), board.yaw)
    size = np.array([board.size[0], board.size[1], board.thickness])
    shapes: list[Primitive] = [Box(f"/scene/{board.name}", size, T, BOARD_COLOUR)]
    hole = np.array([board.socket_size, board.socket_size, THIN])
    for row in range(board.rows):
        for col in range(board.cols):
            floor = board.socket(row, col) + np.array([0.0, 0.0, board.socket_depth + THIN / 2])
            name = f"/scene/{board.name}_sockets/{row}_{col}"  # not under the board: its frame
            shapes.append(Box(name, hole, pose(floor, board.yaw), SOCKET_COLOUR))
    return shapes


def container_primitives(c: Container) -> list[Primitive]:
    """An open box: the floor and four walls."""
    sx, sy, sz = c.size
    w, base = c.wall, c.position
    parts = [
        ("floor", (sx, sy, w), (0.0, 0.0, w / 2)),
        ("wall_x0", (w, sy, sz), (-(sx - w) / 2, 0.0, sz / 2)),
        ("wall_x1", (w, sy, sz), ((sx - w) / 2, 0.0, sz / 2)),
        ("wall_y0", (sx, w, sz), (0.0, -(sy - w) / 2, sz / 2)),
        ("wall_y1", (sx, w, sz), (0.0, (sy - w) / 2, sz / 2)),
    ]
    return [
        Box(f"/scene/{c.name}/{part}", np.array(size), pose(base + offset), CONTAINER_COLOUR)
        for part, size, offset in parts
    ]


def sheet_primitive(sheet: Sheet) -> Box:
    """A sheet of paper as a thin white box on its plane."""
    R = np.column_stack([sheet.u, sheet.v, sheet.normal])
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, sheet.center - sheet.normal * THIN / 2
    return Box(f"/scene/{sheet.name}", np.array([sheet.width, sheet.height, THIN]), T, SHEET_COLOUR)


def instrument_primitives(instrument: Xylophone | Drum) -> list[Primitive]:
    """A xylophone's bars (naturals light, sharps dark), each at its place, or a drum's body."""
    if isinstance(instrument, Drum):
        head = instrument.head
        height = float(head[2] - instrument.position[2])
        centre = instrument.position + np.array([0.0, 0.0, height / 2])
        return [Cylinder(f"/scene/{instrument.name}", instrument.radius, height, pose(centre), DRUM_COLOUR)]  # fmt: skip
    shapes: list[Primitive] = []
    for note in instrument.notes:
        length, width = instrument.bar_size(note)
        top = instrument.bar_top(note)
        size = np.array([length, width * 0.9, 0.01])
        T = pose(top - np.array([0.0, 0.0, 0.005]), instrument.bar_row(note) + math.pi / 2)
        colour = BAR_COLOURS[int(note % 12 in (1, 3, 6, 8, 10))]
        shapes.append(Box(f"/scene/{instrument.name}/bar_{note}", size, T, colour))
    return shapes
