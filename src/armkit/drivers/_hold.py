"""Holding a serial-bus servo arm (Dynamixel, Feetech) after a stop or a failed move,
without needing any reply.

The hold is one SYNC WRITE of the goals where the last move has each joint now (on a
Dynamixel bus after short hold profiles): a SYNC WRITE has no status packet, so no
servo's silence, garbage or lateness keeps the others from holding, and a servo whose
replies are corrupt still executes it. Then each servo is asked for its Goal Position,
to say exactly which servos confirmed the hold.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from .._errors import DeviceError
from ..devices import PortGoneError
from ..devices.dynamixel import DynamixelBus
from ..devices.feetech import FeetechBus

HoldingBus = DynamixelBus | FeetechBus


def hold(
    bus: HoldingBus, goals: Mapping[int, int], send: bool, goal_of: Callable[[int], int]
) -> tuple[list[int], list[int]]:
    """Hold each servo of ``goals`` (ID -> tick) there (``send`` False: its move has
    ended on that goal already, nothing to send); ``goal_of(id)`` reads a servo's Goal
    Position back. Returns (IDs that confirmed the hold, IDs that did not). A vanished
    port raises (``PortGoneError``)."""
    if send:
        bus.sync_write("Goal Position", dict(goals))
    held: list[int] = []
    silent: list[int] = []
    for sid, goal in goals.items():  # after the hold went out: retrying delays nobody
        try:
            ok = goal_of(sid) == goal
        except PortGoneError:
            raise
        except DeviceError:
            ok = False
        (held if ok else silent).append(sid)
    return held, silent


def report(held_or_failed: Callable[[], tuple[list[int], list[int]]]) -> str:
    """Hold (``held_or_failed()``, as ``hold``) after a failed move; which servos hold,
    in words."""
    try:
        held, silent = held_or_failed()
    except DeviceError as exc:
        return f"the hold could not be sent ({exc})"
    words = f"servos {held} hold where they were" if held else "no servo confirmed a hold"
    return words + (f"; servos {silent} did not confirm that they hold" if silent else "")


def hold_here(bus: HoldingBus, ids: list[int]) -> None:
    """Torque on in ``ids`` where each servo is now (after being moved by hand): Goal
    Position set to Present Position first, so no servo jumps back to an old goal."""
    present = bus.sync_read("Present Position", ids)
    bus.sync_write("Goal Position", present)
    bus.set_torque(ids, True)
