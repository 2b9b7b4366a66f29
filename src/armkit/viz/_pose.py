"""A 3D picture of an arm in one pose, with every joint frame's axis indicators (001 1.3.1)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from .._files import check_output_path
from ..kinematics import fk_frames, pitch_of
from ..model import ArmModel

AXIS_COLOURS = ("tab:red", "tab:green", "tab:blue")  # x, y, z


def plot_pose(
    model: ArmModel, q: NDArray[np.float64], path: str | Path, title: str | None = None
) -> Path:
    """Draw ``model`` at joint angles ``q`` [rad], shape (dof,), into an image file.

    Links are drawn between successive frame origins; each frame gets x/y/z
    indicators (red/green/blue) of a length scaled to the arm. Returns the path (proven
    writable before anything is drawn: ``InputError`` if not).
    """
    out = check_output_path(path)
    plt = _pyplot()
    frames = fk_frames(model, q)
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    _draw(ax, frames)
    T = frames[-1]
    x, y, z = (T[:3, 3] * 1000).tolist()
    pitch = math.degrees(float(pitch_of(T)))
    ax.set_title(
        title or f"{model.name}: gripper ({x:.0f}, {y:.0f}, {z:.0f}) mm, pitch {pitch:.0f} deg"
    )
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out


def _pyplot() -> Any:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise ArmkitError("plotting needs matplotlib: pip install 'armkit[plot]'") from None
    return plt


def _draw(ax: Any, frames: NDArray[np.float64]) -> None:
    pts = frames[:, :3, 3] * 1000
    ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], "-o", color="0.3", linewidth=4, markersize=5)
    reach = max(float(np.abs(pts).max()), 50.0)
    size = 0.12 * reach
    for T in frames:
        origin = T[:3, 3] * 1000
        for k in range(3):
            tip = origin + T[:3, k] * size
            ax.plot(*zip(origin, tip, strict=True), color=AXIS_COLOURS[k], linewidth=1.5)
    ax.plot([-reach, reach], [0, 0], [0, 0], color="0.85", linewidth=0.8)
    ax.set_xlim(-reach, reach)
    ax.set_ylim(-reach, reach)
    ax.set_zlim(0 if pts[:, 2].min() >= 0 else -reach, reach)
    ax.set_xlabel("x mm (forward)")
    ax.set_ylabel("y mm (left)")
    ax.set_zlabel("z mm (up)")
    ax.set_box_aspect((1, 1, 1 if pts[:, 2].min() < 0 else 0.5))
