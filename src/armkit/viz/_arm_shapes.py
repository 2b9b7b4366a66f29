"""An arm as primitives: the link capsules of the clearance check, the jaws, the frames.

The links are the clearance check's own capsules (``armkit.scene.arm_capsules``:
capsule i joins the origins of frames i and i + 1 of ``fk_frames``, capsule 0 the
base column, the last one the flange to the tool point), so what the view shows
is what the clearance check tests.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._primitives import RGB, Axes, Box, Capsule, Primitive, moved, pose
from ..kinematics import fk_frames
from ..model import ArmModel
from ..scene import Scene, arm_capsules

F64 = NDArray[np.float64]

LINK_COLOUR: RGB = (232, 118, 16)  # orange: every link
BASE_COLOUR: RGB = (70, 70, 78)  # dark grey: the base column
JAW_COLOUR: RGB = (40, 40, 46)
TABLE_COLOUR: RGB = (214, 208, 196)
TRAIL_COLOUR: RGB = (30, 110, 230)
JAW_LENGTH = 0.03  # [m] along the approach axis, ending at the tool point
JAW_THICKNESS = 0.006  # [m]


def arm_primitives(
    model: ArmModel,
    q: ArrayLike,
    grip: float | None = None,
    *,
    frames: bool = False,
    T_world_base: F64 | None = None,
) -> list[Primitive]:
    """The arm at joint angles ``q`` [rad] with its jaws open to ``grip`` [m] (None:
    fully open), named ``/arm/link_<i>``, ``/arm/jaw_<l|r>``, ``/arm/frame_<i>``; in the
    scene's frame when ``T_world_base`` (4, 4) is given (a scene's base placement)."""
    F = fk_frames(model, q)
    caps = arm_capsules(model, q)
    shapes: list[Primitive] = [
        Capsule(
            f"/arm/link_{i}",
            caps.p0[i],
            caps.p1[i],
            float(caps.radii[i]),
            BASE_COLOUR if i == 0 else LINK_COLOUR,
        )
        for i in range(len(caps.radii))
    ]
    width = model.gripper.width_max if grip is None else grip
    shapes += jaw_boxes(F[-1], width, float(caps.radii[-1]))
    if frames:
        shapes += [Axes(f"/arm/frame_{i}", T, 0.04) for i, T in enumerate(F)]
    if T_world_base is None:
        return shapes
    return [moved(s, T_world_base) for s in shapes]


def jaw_boxes(T_tool: F64, width: float, radius: float) -> list[Primitive]:
    """Two jaws either side of the tool point along the tool's y axis, ``width`` [m]
    apart, reaching from the tool point back along the approach (x) axis."""
    height = max(radius, 0.008)
    size = np.array([JAW_LENGTH, JAW_THICKNESS, height])
    jaws: list[Primitive] = []
    for side, sign in (("l", 1.0), ("r", -1.0)):
        offset = pose((-JAW_LENGTH / 2, sign * (width / 2 + JAW_THICKNESS / 2), 0.0))
        jaws.append(Box(f"/arm/jaw_{side}", size, T_tool @ offset, JAW_COLOUR))
    palm = np.array([JAW_THICKNESS, width + 2 * JAW_THICKNESS, height])
    back = pose((-JAW_LENGTH - JAW_THICKNESS / 2, 0.0, 0.0))
    jaws.append(Box("/arm/palm", palm, T_tool @ back, JAW_COLOUR))
    return jaws


TABLE_DROP = 0.0005  # [m] the table is drawn this much below its plane (see table_primitive)


def table_primitive(model: ArmModel, scene: Scene | None = None) -> Box:
    """The table: a thin slab whose top is the plane ``model.table_z`` (a scene's
    ``table_z``), around the arm's base, wide enough for the arm's reach. It is drawn
    ``TABLE_DROP`` below that plane so that what lies on it in the plane (a sheet of
    paper) is not drawn in the same plane as it: two faces at one depth flicker
    (z-fighting) as the view turns."""
    reach = max(0.2, 1.1 * reach_of(model))
    thickness = 0.01
    base = np.zeros(3) if scene is None else scene.T_world_base[:3, 3]
    top = (model.table_z if scene is None else scene.table_z) - TABLE_DROP
    T = pose((float(base[0]), float(base[1]), top - thickness / 2))
    return Box("/table", np.array([2 * reach, 2 * reach, thickness]), T, TABLE_COLOUR)


def reach_of(model: ArmModel) -> float:
    """How far the tool point can get from the base column [m]: the link lengths
    summed beyond the first frame (an upper bound)."""
    origins = fk_frames(model, model.home)[1:, :3, 3]
    return float(np.sum(np.linalg.norm(np.diff(origins, axis=0), axis=1)))
