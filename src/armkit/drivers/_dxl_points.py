"""A Dynamixel arm's calibration as points: what the simulator needs to mount its servos."""

from __future__ import annotations

import math

from ..model import ArmModel, DynamixelSection, dynamixel_section


def dynamixel_points(
    model: ArmModel, config: DynamixelSection | None = None
) -> list[tuple[int, int, tuple[float, float], tuple[float, float]]]:
    """The calibration as this driver uses it, as points: (servo ID, joint index or -1
    for the gripper, two ticks, the angles [rad] or openings [m] at those ticks).
    ``config``: the setup (default: the model's ``[drivers.dynamixel]``)."""
    cfg = dynamixel_section(model) if config is None else config
    center = cfg.center_tick
    per_rad = cfg.ticks_per_turn / (2.0 * math.pi)
    points = [(sid, j, (center, center + per_rad), (0.0, 1.0)) for j, sid in enumerate(cfg.ids)]
    closed, opened = cfg.gripper_ticks
    g = model.gripper
    if cfg.gripper_id is not None:
        grip = (cfg.gripper_id, -1, (float(closed), float(opened)), (g.width_min, g.width_max))
        points.append(grip)
    return points
