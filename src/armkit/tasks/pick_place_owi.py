"""000's moveItem for the OWI-535, built on ``armkit.tasks``: pick the item whose
grip point is A, lift it, carry it, put it down at B -- the whole way planned and
checked (reach, limits, the table) before the first motor runs, with the gripper
level (000's IK) and the joints turned by the driver in an order that keeps the
arm off the table."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

from .._errors import InputError
from ..arm import Arm
from ..drivers.timed import TimedDriver
from ..model import ArmModel
from ..scene import Scene
from ._jobs import move_item
from ._run import run_plan

LIFT_M = 0.04  # how high above A and B the gripper travels [m]


def pick_place(
    model: ArmModel,
    driver: TimedDriver,
    a_m: ArrayLike,
    b_m: ArrayLike,
    *,
    lift_m: float = LIFT_M,
    say: Callable[[str], None] | None = None,
) -> None:
    """Pick up the item whose grip point is ``a_m`` and put it down at ``b_m`` [m], (3,).

    Raises:
        TaskError: (an ``UnreachableError``) a step is out of reach or puts the arm
            in the table; it names the step and nothing moves.
    """
    a = np.asarray(a_m, dtype=float) * 1000.0
    b = np.asarray(b_m, dtype=float) * 1000.0
    arm = Arm(model, driver)
    lift = lift_m * 1000.0
    if not 30.0 <= lift <= 500.0:
        raise InputError(f"lift must be 30..500 mm (001: at least 30 above A and B), got {lift:g}")
    plan = move_item(
        arm, Scene("table"), tuple(a), tuple(b), lift=lift, clearance=lift, dry_run=True
    )
    tell = say or (lambda _text: None)
    run_plan(arm, plan, lambda k, step: tell(f"{k}/{len(plan.steps)} {step.label}"))
