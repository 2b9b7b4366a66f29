"""A Dynamixel arm's calibration as points: what the simulator needs to mount its servos."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..model import ArmModel


def calibration_points(
    model: ArmModel, config: Mapping[str, Any] | None = None
) -> list[tuple[int, int, tuple[float, float], tuple[float, float]]]:
    """The calibration as this driver uses it, as points: (servo ID, joint index or -1
    for the gripper, two ticks, the angles [rad] or openings [m] at those ticks)."""
    cfg = model.drivers["dynamixel"] if config is None else config
    center = float(cfg.get("center_tick", 2048))
    per_rad = float(cfg.get("ticks_per_turn", 4096)) / (2.0 * math.pi)
    points = [
        (int(sid), j, (center, center + per_rad), (0.0, 1.0)) for j, sid in enumerate(cfg["ids"])
    ]
    closed, opened = cfg.get("gripper_ticks", (1500, 2600))
    g = model.gripper
    points.append(
        (int(cfg["gripper_id"]), -1, (float(closed), float(opened)), (g.width_min, g.width_max))
    )
    return points
