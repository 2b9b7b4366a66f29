"""A top view of a scene (matplotlib: the ``plot`` extra, imported only here)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InputError
from .._files import check_output_path
from ..kinematics import fk_frames
from ..model import ArmModel
from ._instruments import Drum, Xylophone, note_name
from ._rect import Rect
from ._rotations import rot_z
from ._scene import Scene

PICTURE_SUFFIXES = (".png", ".svg", ".pdf")  # what top_view writes


def top_view(scene: Scene, path: Path, model: ArmModel | None = None) -> None:
    """Draw ``scene`` from above (millimetres) with the arm at its home pose into ``path``
    (.png, .svg or .pdf; InputError if it cannot be written there)."""
    check_output_path(path, suffixes=PICTURE_SUFFIXES)
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise InputError("the picture needs matplotlib: pip install 'armkit[plot]'") from None
    fig, ax = plt.subplots(figsize=(7, 7))
    try:
        _draw(ax, scene, model)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm] (forward)")
        ax.set_ylabel("y [mm] (left)")
        ax.set_title(f"scene {scene.name}, from above")
        ax.grid(True, alpha=0.3)
        fig.savefig(path, dpi=120, bbox_inches="tight")
    finally:
        plt.close(fig)


def _poly(ax: Any, corners_m: np.ndarray, **style: Any) -> None:
    from matplotlib.patches import Polygon

    ax.add_patch(Polygon(corners_m[:, :2] * 1000, closed=True, **style))


def _draw(ax: Any, scene: Scene, model: ArmModel | None) -> None:
    for b in scene.boards:
        plate = Rect(b.origin[:2], (b.size[0] / 2, b.size[1] / 2), b.yaw).corners()
        _poly(ax, plate, facecolor="#d8e6f0", edgecolor="#4a6a80")
        for r in range(b.rows):
            for c in range(b.cols):
                hole = Rect(b.socket(r, c)[:2], (b.socket_size / 2,) * 2, b.yaw).corners()
                _poly(ax, hole, facecolor="white", edgecolor="#4a6a80", lw=0.8)
        ax.annotate(b.name, b.origin[:2] * 1000 + np.array([0, b.size[1] * 500 + 6]), ha="center")
    for box in scene.containers:
        outer = Rect(box.position[:2], (box.size[0] / 2, box.size[1] / 2), 0.0).corners()
        _poly(ax, outer, facecolor="#efe3c8", edgecolor="#8a6d3b")
        ax.annotate(box.name, box.position[:2] * 1000, ha="center", va="center")
    for hand in scene.hands:
        palm = Rect(hand.position[:2], (hand.size[0] / 2, hand.size[1] / 2), 0.0).corners()
        _poly(ax, palm, facecolor="#f2c9a8", edgecolor="#8a5a3b")
        ax.annotate(hand.name, hand.position[:2] * 1000 + np.array([12, 0]), va="center")
    for s in scene.sheets:
        _poly(ax, s.corners(), facecolor="#fafafa", edgecolor="grey", ls="--")
    for inst in scene.instruments:
        _instrument(ax, inst)
    for cube in scene.cubes:
        foot = Rect(cube.position[:2], (cube.size / 2,) * 2, cube.yaw).corners()
        _poly(ax, foot, facecolor=_colour(cube.name), edgecolor="black", alpha=0.85)
        ax.annotate(
            f"{cube.name}\n{cube.up_face} up",
            cube.position[:2] * 1000,
            ha="center",
            va="center",
            fontsize=7,
        )
    for place in scene.places:
        ax.plot(*(place.position[:2] * 1000), "k+", ms=10)
        ax.annotate(place.name, place.position[:2] * 1000 + 4)
    for stand in scene.pen_stands:
        ax.plot(*(stand.position[:2] * 1000), "o", mfc="none", mec="purple", ms=9)
    _arm(ax, scene, model)


def _instrument(ax: Any, inst: Xylophone | Drum) -> None:
    from matplotlib.patches import Circle

    if isinstance(inst, Drum):
        centre = (float(inst.position[0]) * 1000, float(inst.position[1]) * 1000)
        ax.add_patch(Circle(centre, inst.radius * 1000, fc="#f3d9d9", ec="brown"))
        return
    for note in inst.notes:
        length, width = inst.bar_size(note)
        bar = Rect(inst.bar_top(note)[:2], (width / 2, length / 2), inst.bar_row(note))
        sharp = note % 12 in (1, 3, 6, 8, 10)
        _poly(ax, bar.corners(), facecolor="#b89a50" if sharp else "#e8d08a", edgecolor="#8a6d3b")
        ax.annotate(
            note_name(note),
            bar.center * 1000,
            ha="center",
            va="center",
            fontsize=6,
            rotation=(math.degrees(inst.bar_row(note)) + 90.0 + 90.0) % 180.0 - 90.0,
        )


def _arm(ax: Any, scene: Scene, model: ArmModel | None) -> None:
    base = scene.T_world_base
    ax.plot(base[0, 3] * 1000, base[1, 3] * 1000, "ks", ms=9)
    heading = rot_z(math.atan2(base[1, 0], base[0, 0])) @ np.array([0.04, 0.0, 0.0])
    ax.annotate(
        "", (base[:2, 3] + heading[:2]) * 1000, base[:2, 3] * 1000, arrowprops={"arrowstyle": "->"}
    )
    if model is not None:
        frames = fk_frames(model, model.home)[:, :3, 3]
        pts = frames @ base[:3, :3].T + base[:3, 3]
        ax.plot(
            pts[:, 0] * 1000,
            pts[:, 1] * 1000,
            "-o",
            color="dimgrey",
            ms=3,
            label=f"{model.name} at home",
        )
        ax.legend(loc="lower left", fontsize=8)


def _colour(name: str) -> str:
    named = {"red": "#e06060", "green": "#60b060", "blue": "#6080e0", "yellow": "#e0d060"}
    return named.get(name, "#c0c0c0")
