"""000's moveItem for the OWI-535, built on ``armkit.tasks``: pick the item whose
grip point is A, lift it, carry it, put it down at B -- the whole way planned and
checked (reach, limits, the table) before the first motor runs, with the gripper
level (000's IK) and the joints turned by the driver in an order that keeps the
arm off the table."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from .._errors import InputError
from .._inputs import is_number, shown
from ..arm import Arm
from ..scene import Scene
from ._jobs import move_item
from ._live import run_plan

LIFT_MM = 40.0  # how high above A and B the gripper travels [mm]


def pick_place(
    arm: Arm,
    a: Sequence[float],
    b: Sequence[float],
    *,
    lift: float = LIFT_MM,
    say: Callable[[str], None] | None = None,
) -> None:
    """Pick up the item whose grip point is ``a`` and put it down at ``b``, (x, y, z)
    [mm], travelling ``lift`` [mm] (30..500) above them with the gripper level (pitch
    0 deg, 000's IK); ``say`` tells each step.

    Raises:
        TaskError: (an ``UnreachableError``) a step is out of reach or puts the arm
            in the table; it names the step and nothing moves.
    """
    if not (is_number(lift) and 30.0 <= lift <= 500.0):
        raise InputError(
            f"lift must be 30..500 mm (001: at least 30 above A and B), got {shown(lift)}"
        )
    plan = move_item(
        arm, Scene("table"), tuple(a), tuple(b), lift=lift, clearance=lift, dry_run=True
    )
    tell = say or (lambda _text: None)
    run_plan(arm, plan, lambda k, step: tell(f"{k}/{len(plan.steps)} {step.label}"))
