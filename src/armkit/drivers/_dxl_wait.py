"""Waiting for Dynamixel servos after a command: Moving polled until they stop, their
encoders given a moment to settle on the goal tick, then the check that each arrived
(within the arrival tolerance [ticks]), else DeviceError naming the servo."""

from __future__ import annotations

from numpy import int64
from numpy.typing import NDArray

from .._clock import Clock
from .._errors import DeviceError
from ..devices.dynamixel import DynamixelBus

POLL_S = 0.005  # between reads of Moving and Present Position while waiting [s]
SETTLE_S = 0.3  # longest wait for a stopped servo's encoder to reach its goal tick [s]


def wait_arrival(
    bus: DynamixelBus,
    clock: Clock,
    ids: list[int],
    goal: NDArray[int64],
    timeout: float,
    tolerance: int,
) -> None:
    """Wait for ``ids`` to stop (at most ``timeout`` [s]) and settle on ``goal`` [tick],
    shape (len(ids),) (their encoders on it, for at most ``SETTLE_S``), then check they
    arrived within ``tolerance`` [ticks]."""
    if not stopped(bus, clock, ids, timeout):
        raise DeviceError(f"servos {ids}: still moving {timeout:.1f} s after the command")
    deadline = clock.now() + SETTLE_S
    while not _on_goal(bus, ids, goal) and clock.now() < deadline:
        clock.sleep(POLL_S)
    _check_arrival(bus, ids, goal, tolerance)


def stopped(bus: DynamixelBus, clock: Clock, ids: list[int], timeout: float) -> bool:
    """Poll Moving until every servo in ``ids`` stops (True) or ``timeout`` [s] (False)."""
    deadline = clock.now() + timeout
    while any(bus.sync_read("Moving", ids).values()):
        if clock.now() > deadline:
            return False
        clock.sleep(POLL_S)
    return True


def _on_goal(bus: DynamixelBus, ids: list[int], goal: NDArray[int64]) -> bool:
    present = bus.sync_read("Present Position", ids)
    return all(present[sid] == g for sid, g in zip(ids, goal.tolist(), strict=True))


def _check_arrival(bus: DynamixelBus, ids: list[int], goal: NDArray[int64], tolerance: int) -> None:
    present = bus.sync_read("Present Position", ids)
    for sid, target in zip(ids, goal.tolist(), strict=True):
        if abs(present[sid] - target) > tolerance:
            raise DeviceError(
                f"servo {sid}: stopped at tick {present[sid]}, goal {target}"
                f" (tolerance {tolerance}); is it blocked or did it miss the command?"
            )
