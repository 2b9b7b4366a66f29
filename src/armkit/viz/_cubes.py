"""A small scene made of primitives: a board with sockets and three cubes (001's task 2).

Until the scene package's objects are mapped onto primitives, this is the
scene ``armkit view --cubes`` shows and the browser tests look for.
"""

from __future__ import annotations

import numpy as np

from ._primitives import RGB, Box, Cylinder, Primitive, pose

CUBE_SIZE = 0.025  # [m] 001's cubes
BOARD_COLOUR: RGB = (150, 110, 70)  # brown
SOCKET_COLOUR: RGB = (90, 62, 38)
CUBE_COLOURS: dict[str, RGB] = {
    "cube_a": (200, 20, 180),  # magenta
    "cube_b": (25, 70, 230),  # blue
    "cube_c": (20, 180, 180),  # teal
}
CUBE_POSITIONS = {  # centre of the bottom face [m], on the board
    "cube_a": (0.2, -0.08, 0.004),
    "cube_b": (0.12, 0.12, 0.004),
    "cube_c": (0.225, 0.06, 0.004),
}
BOARD = (0.17, 0.0, 0.2, 0.3, 0.004)  # centre x, y [m], size x, y [m], thickness [m]


def cubes_scene(table_z: float = 0.0) -> list[Primitive]:
    """The board (its top ``BOARD[4]`` above ``table_z`` [m]), six sockets and three
    cubes named ``/scene/cube_a`` .. ``/scene/cube_c``."""
    cx, cy, sx, sy, thick = BOARD
    shapes: list[Primitive] = [
        Box(
            "/scene/board",
            np.array([sx, sy, thick]),
            pose((cx, cy, table_z + thick / 2)),
            BOARD_COLOUR,
        )
    ]
    for i, (x, y) in enumerate(
        [(0.12, -0.1), (0.12, 0.0), (0.22, -0.1), (0.22, 0.0), (0.12, 0.1), (0.22, 0.1)]
    ):
        T = pose((x, y, table_z + thick + 0.0005))
        shapes.append(Cylinder(f"/scene/socket_{i}", 0.017, 0.001, T, SOCKET_COLOUR))
    for name, (x, y, z) in CUBE_POSITIONS.items():
        centre = (x, y, table_z + z + CUBE_SIZE / 2)
        shapes.append(
            Box(f"/scene/{name}", np.full(3, CUBE_SIZE), pose(centre, 0.3), CUBE_COLOURS[name])
        )
    return shapes
