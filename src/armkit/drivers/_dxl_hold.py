"""Holding a Dynamixel arm after a stop or a failed move, without needing any reply.

The hold is one SYNC_WRITE of short hold profiles and of the goals where the last
profile has each joint now: a SYNC_WRITE has no status packet, so no servo's
silence, garbage or lateness keeps the others from holding, and a servo whose
replies are corrupt still executes it. Then each servo is asked for its Goal
Position, to say exactly which servos confirmed the hold.
"""

from __future__ import annotations

from collections.abc import Mapping

from .._errors import DeviceError
from ..devices import PortGoneError
from ..devices.dynamixel import DynamixelBus

HOLD_PROFILE_MS = (50, 100)  # (ramp, total) of a stop: settle on the held tick in 0.1 s


def hold(bus: DynamixelBus, goals: Mapping[int, int], send: bool) -> tuple[list[int], list[int]]:
    """Hold each servo of ``goals`` (ID -> tick) there (``send`` False: its profile has
    ended on that goal already, nothing to send). Returns (IDs that confirmed the hold,
    IDs that did not). A vanished port raises (``PortGoneError``)."""
    if send:
        bus.set_profiles({sid: HOLD_PROFILE_MS for sid in goals})
        bus.sync_write("Goal Position", dict(goals))
    held: list[int] = []
    silent: list[int] = []
    for sid, goal in goals.items():  # after the hold went out: retrying delays nobody
        try:
            ok = bus.read(sid, "Goal Position", alert_ok=True) == goal
        except PortGoneError:
            raise
        except DeviceError:
            ok = False
        (held if ok else silent).append(sid)
    return held, silent


def describe(held: list[int], silent: list[int]) -> str:
    """Which servos hold, in words."""
    words = f"servos {held} hold where they were" if held else "no servo confirmed a hold"
    return words + (f"; servos {silent} did not confirm that they hold" if silent else "")


def hold_here(bus: DynamixelBus, ids: list[int]) -> None:
    """Torque on in ``ids`` where each servo is now (after being moved by hand): Goal
    Position set to Present Position first, so no servo jumps back to an old goal."""
    present = bus.sync_read("Present Position", ids)
    bus.sync_write("Goal Position", present)
    bus.set_torque(ids, True)
