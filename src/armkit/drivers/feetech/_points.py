"""A Feetech arm's calibration as points: what the simulator needs to mount its servos."""

from __future__ import annotations

import math

import numpy as np

from ...model import FEETECH_SECTION, ArmModel, FeetechSection

GRIP_POINTS = 17  # the chord law in as many points (piecewise linear between them)


def feetech_points(
    model: ArmModel, config: FeetechSection | None = None
) -> list[tuple[int, int, tuple[float, ...], tuple[float, ...]]]:
    """(servo ID, joint index or -1 for the gripper, steps, the angles [rad] or openings
    [m] at those steps), as the driver maps them."""
    cfg = FEETECH_SECTION.of(model) if config is None else config
    per_rad = cfg.ticks_per_turn / (2.0 * math.pi)
    points: list[tuple[int, int, tuple[float, ...], tuple[float, ...]]] = [
        (sid, j, (c, c + d * per_rad), (0.0, 1.0))
        for j, (sid, d, c) in enumerate(zip(cfg.ids, cfg.direction, cfg.centers, strict=True))
    ]
    g = model.gripper
    if cfg.gripper_id is not None and g.width_max > g.width_min:
        widths = np.linspace(g.width_min, g.width_max, GRIP_POINTS).tolist()
        ticks = tuple(
            cfg.gripper_zero_tick + cfg.gripper_direction * cfg.jaw_angle(w) * per_rad
            for w in widths
        )
        points.append((cfg.gripper_id, -1, ticks, tuple(widths)))
    return points
