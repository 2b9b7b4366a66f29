"""000's moveItem for the OWI-535: pick an object at A, lift it, carry it,
place it at B -- with the gripper level (000's IK) and the joints turned in an
order that keeps the arm off the table."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import UnreachableError
from ..drivers.timed import TimedDriver
from ..drivers.timed._order import TABLE_TOLERANCE_M, lowest_point
from ..kinematics import ik
from ..model import ArmModel

F64 = NDArray[np.float64]
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
    """Pick up the object whose top is at ``a_m`` and put it down at ``b_m`` [m], shape (3,).

    Every pose is solved before anything moves, so an unreachable A or B (or a
    point above them) raises ``UnreachableError`` and the arm stays still.
    Sequence: open, above A, down to A, close, lift, above B, down to B, open, lift.
    """
    a, b = np.asarray(a_m, dtype=float), np.asarray(b_m, dtype=float)
    up = np.array([0.0, 0.0, lift_m])
    names = ("above A", "A", "above A", "above B", "B", "above B")
    points = (a + up, a, a + up, b + up, b, b + up)
    poses = _solve_all(model, driver.read(), points)
    tell = say or (lambda _text: None)
    driver.open_gripper(True)
    for k, (name, q) in enumerate(zip(names, poses, strict=True)):
        tell(f"to {name}: ({', '.join(f'{v * 1000:.0f}' for v in points[k])}) mm")
        driver.move(q)
        if k == 1:
            tell("grasp")
            driver.open_gripper(False)
        elif k == 4:
            tell("release")
            driver.open_gripper(True)


def _solve_all(model: ArmModel, q0: F64, points: tuple[F64, ...]) -> list[F64]:
    """IK for each point, each seeded with the previous solution (smallest joint moves).

    Raises:
        UnreachableError: a point is out of reach, or its pose puts the arm in the table.
    """
    poses, seed = [], q0
    lengths = (model.dh[2].a, model.dh[3].a, model.tool_length)
    for p in points:
        seed = np.asarray(ik(model, p, None, seed).q, dtype=float)
        if lowest_point(seed, lengths, model.dh[0].d) < -TABLE_TOLERANCE_M:
            where = ", ".join(f"{v * 1000:.0f}" for v in p)
            raise UnreachableError(
                f"reaching ({where}) mm with the gripper level puts the arm in the table; "
                "choose a higher point",
                reason="table",
            )
        poses.append(seed)
    return poses
