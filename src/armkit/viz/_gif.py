"""An animated GIF of an arm moving along a joint path (matplotlib 3-D).

``record_path`` moves an ``Arm`` through joint poses and samples its
read-back ``fps`` times per second of its own clock (virtual time on the
simulator, so a long path records in a moment); ``write_gif`` draws each
sample from the same primitives as the web view.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from ..arm import Arm
from ..kinematics import fk
from ..model import ArmModel
from ._arm_shapes import TRAIL_COLOUR, arm_primitives, reach_of, table_primitive
from ._cubes import CUBE_POSITIONS, CUBE_SIZE
from ._primitives import Box, Capsule, Cylinder, Primitive
from ._target import check_target

F64 = NDArray[np.float64]
HOLD = 0.3  # [s] the arm rests at each pose of the path
LONGEST = 120.0  # [s] of arm time one recording may take


def default_tour(model: ArmModel) -> list[F64]:
    """Home, then 40 mm above each cube of the cubes scene that the arm can reach
    pointing down (any pitch if not), then home [rad], each shape (dof,)."""
    tour = [model.home]
    for x, y, z in CUBE_POSITIONS.values():
        above = np.array([x, y, model.table_z + z + CUBE_SIZE + 0.04])
        for pitch in (-math.pi / 2, None):
            check = check_target(model, above, pitch, tour[-1])
            if check.q is not None:
                tour.append(check.q)
                break
    return [*tour, model.home]


def record_path(arm: Arm, poses: Sequence[F64], fps: float) -> tuple[F64, F64]:
    """Move ``arm`` through ``poses`` [rad] (each (dof,)) and sample its joints every
    1/``fps`` [s]: times (N,) [s] from the start and joint angles (N, dof) [rad]."""
    dt = 1.0 / fps
    start = arm.clock.now()
    times, qs = [0.0], [arm.driver.read()]
    for q in poses:
        arm.move_joints(np.degrees(q).tolist(), wait=False)
        rest_until = None
        while rest_until is None or arm.clock.now() < rest_until:
            arm.clock.sleep(dt)
            times.append(arm.clock.now() - start)
            qs.append(arm.driver.read())
            if rest_until is None and np.max(np.abs(qs[-1] - q)) < math.radians(0.1):
                rest_until = arm.clock.now() + HOLD
            if times[-1] > LONGEST:
                raise ArmkitError(f"the path takes longer than {LONGEST:.0f} s; give fewer poses")
    return np.array(times), np.array(qs)


def write_gif(
    model: ArmModel,
    times: F64,
    q: F64,
    path: str | Path,
    *,
    scene: Sequence[Primitive] = (),
    fps: float = 15.0,
) -> Path:
    """Draw ``q`` [rad], shape (N, dof), sampled at ``times`` [s] (N,), into the GIF
    ``path`` at ``fps`` frames per second, with ``scene`` and the tool's trail."""
    plt, animation = _matplotlib()
    fig = plt.figure(figsize=(6.4, 4.8), dpi=80)
    ax = fig.add_subplot(projection="3d")
    tips = fk(model, q)[:, :3, 3]
    static = [table_primitive(model), *scene]

    def frame(i: int) -> list[Any]:
        ax.cla()
        _axes(ax, model)
        for prim in [*static, *arm_primitives(model, q[i])]:
            _draw(ax, prim)
        ax.plot(*tips[: i + 1].T, color=_rgb(TRAIL_COLOUR), linewidth=1.5)
        ax.set_title(f"{model.name}  t = {times[i]:.2f} s")
        return []

    anim = animation.FuncAnimation(fig, frame, frames=len(times), blit=False)
    out = Path(path)
    anim.save(out, writer=animation.PillowWriter(fps=fps))
    plt.close(fig)
    return out


def _matplotlib() -> tuple[Any, Any]:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib import animation
    except ImportError:
        raise ArmkitError("an animation needs matplotlib: pip install 'armkit[plot]'") from None
    return plt, animation


def _axes(ax: Any, model: ArmModel) -> None:
    r = reach_of(model)
    ax.set_xlim(-0.5 * r, r)
    ax.set_ylim(-0.75 * r, 0.75 * r)
    ax.set_zlim(model.table_z, model.table_z + r)
    ax.set_box_aspect((1.5, 1.5, 1.0))
    ax.view_init(elev=28, azim=-50)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")


def _draw(ax: Any, prim: Primitive) -> None:
    if isinstance(prim, Capsule):
        pts = np.stack([prim.p0, prim.p1])
        ax.plot(
            *pts.T,
            color=_rgb(prim.color),
            linewidth=max(2.0, prim.radius * 400),
            solid_capstyle="round",
        )
    elif isinstance(prim, Box | Cylinder):
        _solid(ax, prim)


def _solid(ax: Any, prim: Box | Cylinder) -> None:
    """A box (or a cylinder's bounding box) as six faces."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    if isinstance(prim, Box):
        size = prim.size
    else:
        size = np.array([2 * prim.radius, 2 * prim.radius, prim.height])
    signs = np.array(
        [[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64
    )
    corners = (prim.T[:3, :3] @ (signs * size / 2).T).T + prim.T[:3, 3]
    faces = [[0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4], [1, 3, 7, 5]]
    poly = Poly3DCollection(
        [corners[f] for f in faces], facecolor=_rgb(prim.color), edgecolor="0.3", linewidth=0.3
    )
    ax.add_collection3d(poly)


def _rgb(color: tuple[int, int, int]) -> tuple[float, float, float]:
    return (color[0] / 255.0, color[1] / 255.0, color[2] / 255.0)
