"""Carrying out a plan on an arm, step by step (every step was checked when planned)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from .._errors import ArmkitError, InputError
from .._inputs import shown
from ._plan import Plan, Step

if TYPE_CHECKING:
    from ..arm import Arm

START_TOLERANCE = math.radians(0.5)  # the arm must be where the plan starts
GRIP_S = 0.5  # [s] time given to a real gripper to open or close
SETTLE_MAX_S = 5.0  # [s] the longest wait for a simulated arm to come to rest


def run_plan(arm: Arm, plan: Plan, say: Callable[[int, Step], None] | None = None) -> None:
    """Move ``arm`` through ``plan``: joint moves and gripper commands in order.

    On a simulated arm the plan's scene is simulated with it (its physics attached to
    the arm's world, as a task that runs attaches it), so the cubes move as planned.

    Raises:
        ArmkitError: the arm is not where the plan starts (it moved since planning);
            nothing moves then.
    """
    if not isinstance(plan, Plan):
        raise InputError(
            f"plan must be a Plan (from a task, e.g. tasks.pick(..., dry_run=True)), "
            f"got {shown(plan)}"
        )
    from ._live import attach_scene  # _live runs plans through here

    attach_scene(arm, plan.before)
    now = arm.driver.read()
    off = float(np.max(np.abs(now - plan.q_start)))
    if off > START_TOLERANCE:
        raise ArmkitError(
            f"the arm moved {math.degrees(off):.1f} deg since the plan '{plan.task}' was made; "
            "plan it again"
        )
    scene, arm.scene = arm.scene, None  # checked when planned, with the grasps allowed
    arm.held = None
    try:
        for k, step in enumerate(plan.steps, 1):
            if say is not None:
                say(k, step)
            if step.grip is not None:
                settle(arm)
                arm.grip(step.grip * 1000.0)
                settle(arm)
            elif step.q is not None:
                arm.move_joints(np.degrees(step.q).tolist())  # the table is checked again
    finally:
        arm.scene = scene
        arm.held = plan.held  # what the gripper holds now, as planned


def settle(arm: Arm) -> None:
    """Wait until the arm and its gripper stand still: on a simulated arm until its
    truth is at rest (at most SETTLE_MAX_S of simulated time), else GRIP_S."""
    sim = arm.sim
    if sim is None:
        arm.clock.sleep(GRIP_S)
        return
    waited = 0.0
    while not sim.at_rest() and waited < SETTLE_MAX_S:
        arm.clock.sleep(0.01)
        waited += 0.01
