"""``[drivers.feetech]``: the servo IDs and step calibration of an arm on a Feetech bus.

A joint's angle q [rad] is the step ``center_tick + direction * q * ticks_per_turn /
2pi``. The gripper of the SO-101/SO-100 is a hinged jaw: its servo turns the jaw by an
angle a and the opening at the tool point is the chord ``w = 2 * hinge_mm * sin(a /
2)`` (the jaw's tip ``gripper_hinge_mm`` from the hinge, in the jaw's plane), so
``a = 2 * asin(w / (2 * hinge_mm))``; a = 0 (jaws shut) is ``gripper_zero_tick``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ._check import NUM, Checker

if TYPE_CHECKING:
    from ._types import ArmModel

FEETECH_BAUDRATES = (1_000_000, 500_000, 250_000, 128_000, 115_200, 76_800, 57_600, 38_400)
_KEYS = {
    "ids": list, "gripper_id": int, "baudrate": int, "ticks_per_turn": int, "center_tick": NUM,
    "direction": list, "gripper_hinge_mm": NUM, "gripper_zero_tick": int,
    "gripper_direction": int, "position_tolerance_ticks": int,
}  # fmt: skip


@dataclass(frozen=True)
class FeetechSection:
    """``[drivers.feetech]`` as typed settings.

    Attributes:
        ids: one servo ID per joint, model order (0..253, all different).
        gripper_id: the gripper's servo ID (None: no gripper).  baudrate: [bit/s].
        ticks_per_turn: steps in one turn.  center_tick: the step at joint angle 0.
        direction: +1 or -1 per joint (-1: the step falls as the angle grows).
        gripper_hinge_mm: the jaw's tip from its hinge [mm].
        gripper_zero_tick: the gripper servo's step with the jaws shut.
        gripper_direction: +1 or -1 (the step's sense as the jaws open).
        position_tolerance_ticks: how close a servo must come to count as arrived.
        center_ticks: per joint, the step at angle 0 where a unit's calibration gives
            each its own (a LeRobot calibration file: the middle of its range); empty:
            ``center_tick`` for every joint.
    """

    ids: tuple[int, ...]
    gripper_id: int | None
    baudrate: int = 1_000_000
    ticks_per_turn: int = 4096
    center_tick: float = 2048.0
    direction: tuple[int, ...] = ()
    gripper_hinge_mm: float = 79.8
    gripper_zero_tick: int = 2048
    gripper_direction: int = 1
    position_tolerance_ticks: int = 20
    center_ticks: tuple[float, ...] = ()

    @property
    def centers(self) -> tuple[float, ...]:
        """The step at angle 0 of each joint."""
        return self.center_ticks or (self.center_tick,) * len(self.ids)

    def jaw_angle(self, width: float) -> float:
        """The jaw's angle [rad] for an opening ``width`` [m] (chord law)."""
        half = min(1.0, max(0.0, width / (2.0 * self.gripper_hinge_mm / 1000.0)))
        return 2.0 * math.asin(half)

    def opening(self, angle: float) -> float:
        """The opening [m] for a jaw angle [rad] (clipped at the shut jaws: 0)."""
        return 2.0 * self.gripper_hinge_mm / 1000.0 * math.sin(max(0.0, angle) / 2.0)


def read_feetech(check: Checker, data: Any, model: ArmModel) -> FeetechSection:
    """Check ``[drivers.feetech]`` (ModelError names the field) and read it."""
    w = "drivers.feetech"
    check.table(data, w, _KEYS, ("ids",))
    ids = data["ids"]
    if len(ids) != model.dof:
        raise check.fail(f"{w}.ids", f"must list {model.dof} servo IDs, one per joint, got {ids}")
    ids = [check.integer(i, f"{w}.ids[{k}]", 0, 253) for k, i in enumerate(ids)]
    grip = data.get("gripper_id")
    if grip is not None:
        grip = check.integer(grip, f"{w}.gripper_id", 0, 253)
    every = [*ids, *([grip] if grip is not None else [])]
    if len(set(every)) != len(every):
        raise check.fail(w, f"servo IDs must all differ, got ids {ids} and gripper_id {grip}")
    get = data.get
    ticks = check.integer(get("ticks_per_turn", 4096), f"{w}.ticks_per_turn", 360, 1_000_000)
    return FeetechSection(
        ids=tuple(ids),
        gripper_id=grip,
        baudrate=check.choice_int(get("baudrate", 1_000_000), f"{w}.baudrate", FEETECH_BAUDRATES),
        ticks_per_turn=ticks,
        center_tick=check.within(get("center_tick", 2048), f"{w}.center_tick", 0, ticks),
        direction=_directions(check, get("direction", [1] * model.dof), f"{w}.direction", model),
        gripper_hinge_mm=check.within(
            get("gripper_hinge_mm", 79.8), f"{w}.gripper_hinge_mm", 1.0, 500.0, "mm"
        ),
        gripper_zero_tick=check.integer(
            get("gripper_zero_tick", 2048), f"{w}.gripper_zero_tick", 0, 4095
        ),
        gripper_direction=check.choice_int(
            get("gripper_direction", 1), f"{w}.gripper_direction", (1, -1)
        ),
        position_tolerance_ticks=check.integer(
            get("position_tolerance_ticks", 20), f"{w}.position_tolerance_ticks", 1, 1000
        ),
    )


def _directions(check: Checker, data: Any, where: str, model: ArmModel) -> tuple[int, ...]:
    if not isinstance(data, list) or len(data) != model.dof:
        raise check.fail(where, f"must list {model.dof} directions, each 1 or -1, got {data!r}")
    return tuple(check.choice_int(d, f"{where}[{k}]", (1, -1)) for k, d in enumerate(data))
