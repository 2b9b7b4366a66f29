"""Each statement's motion planned from a ``Start``: the one planner of ``armkit check``
(which folds the plans, each from where the last one ends) and ``armkit run`` (which
plans each from the arm as it reads it, then carries it out). Every quantity in SI."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..arm import Plan, Start, plan_follow, plan_joints
from ..kinematics import fk, ik
from ..motion import TimedStreaming, line
from ._resolve import JointPose, Point, Target

F64 = NDArray[np.float64]
LINE_SPACING = 0.002  # a straight line is followed through points 2 mm apart [m]


@dataclass(frozen=True)
class Pace:
    """The script's speeds: ``fraction`` of every joint's max velocity for joint moves
    (None: full speed), ``tool_speed`` along straight lines [m/s]."""

    fraction: float | None = None
    tool_speed: float = TimedStreaming().speed


def plan_move(start: Start, target: Target, straight: bool, pace: Pace) -> Plan:
    """``move`` (a joint move) or ``line`` (the tool along a straight line) to ``target``.

    Raises:
        UnreachableError, JointLimitError, PathError: as the arm refuses the move.
    """
    if straight:
        return plan_line(start, target, pace)
    if isinstance(target, JointPose):
        goal = target.q
    else:
        goal = np.asarray(ik(start.kin, target.xyz, target.pitch, start.q).q, dtype=np.float64)
    return plan_joints(start, goal, speed=pace.fraction)


def plan_line(start: Start, target: Target, pace: Pace) -> Plan:
    """The tool point in a straight line from where it is to ``target`` at
    ``pace.tool_speed`` (a joint pose: its tool point, the pitch left free)."""
    here = np.asarray(fk(start.kin, start.q)[:3, 3], dtype=np.float64)
    if isinstance(target, Point):
        goal, pitch = target.xyz, target.pitch
    else:
        goal, pitch = np.asarray(fk(start.kin, target.q)[:3, 3], dtype=np.float64), None
    if np.linalg.norm(goal - here) < 1e-6:  # there already (to 1 µm)
        return Plan("line", start, (), start)
    points = line(here, goal, LINE_SPACING)
    return plan_follow(start, points, pitch, TimedStreaming(speed=pace.tool_speed), "line")


def plan_turn(start: Start, joint: str, angle: float, relative: bool, pace: Pace) -> Plan:
    """``turn JOINT [by] ANGLE`` [rad]: that joint to (or by) ``angle``, the others stay."""
    goal = start.q.copy()
    j = start.model.joint_index(joint)
    goal[j] = goal[j] + angle if relative else angle
    return plan_joints(start, goal, speed=pace.fraction, label=f"turn {joint}")


def plan_home(start: Start, pace: Pace) -> Plan:
    """``home``: every joint to the model's home angles."""
    return plan_joints(start, start.model.home, speed=pace.fraction, label="home")
