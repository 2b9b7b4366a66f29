"""How precisely an arm carries a task out: the moves it makes down to a grasp or
release point, and how far a cube it put down may end from where the plan puts it.

Servo arms close their loop: 001's three waypoints down, 1 mm and 1 deg. An arm on
timed motors (the OWI-535, ``[drivers.owi535]``) moves open loop: its model file says
how many moves down and how much the objects may be off (``task_waypoints``,
``task_tolerance_mm``, ``task_turn_tolerance_deg``; see the OWI's model file for why).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..model import ArmModel, owi_section

WAYPOINTS = 3  # 001: three waypoints down from the clearance height
POSE_TOLERANCE = 1e-3  # [m]: a cube this far from where the plan puts it is a failure
TURN_TOLERANCE = math.radians(1.0)  # [rad]


@dataclass(frozen=True)
class Precision:
    """What a task may expect of an arm.

    Attributes:
        waypoints: moves from the clearance height down to a grasp or release point.
        tolerance: how far [m] a cube may end from its planned pose.
        turn: how much [rad] it may end turned from it.
    """

    waypoints: int = WAYPOINTS
    tolerance: float = POSE_TOLERANCE
    turn: float = TURN_TOLERANCE


def precision_of(model: ArmModel) -> Precision:
    """The arm's precision for tasks: its ``[drivers.owi535]`` task fields if it has
    that table (an open-loop arm), else 001's three waypoints and 1 mm, 1 deg."""
    if "owi535" not in model.drivers:
        return Precision()
    cfg = owi_section(model)
    return Precision(
        cfg.task_waypoints,
        cfg.task_tolerance_mm / 1000.0,
        math.radians(cfg.task_turn_tolerance_deg),
    )
