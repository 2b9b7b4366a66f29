"""Carrying a plan out on a driver, step by step (every step was checked and timed when
planned): joint moves, paths through their streamer, gripper commands, and moves sent
at their planned times. ``Arm.run`` is its one caller: the only way to a driver."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from .._clock import Clock
from .._closing import close_after
from .._errors import ArmkitError, DeviceError
from ..drivers import Driver, TimedMotors
from ..motion import NaiveStepping, follow
from ._plan import Plan, Step

F64 = NDArray[np.float64]
Say = Callable[[int, Step], None]
START_TOLERANCE = math.radians(0.5)  # the arm must be where the plan starts
REACHED = math.radians(0.2)  # a move with a timeout is done when every joint is this close


def check_start(driver: Driver, plan: Plan) -> None:
    """ArmkitError if the arm is not where ``plan`` starts (it moved since planning)."""
    off = float(np.max(np.abs(driver.read() - plan.start.q)))
    if off > START_TOLERANCE:
        raise ArmkitError(
            f"the arm moved {math.degrees(off):.1f} deg since the plan '{plan.task}' was made; "
            "plan it again"
        )


def carry_out(
    driver: Driver,
    clock: Clock,
    plan: Plan,
    say: Say | None,
    settle: Callable[[], None],
    wait: bool = True,
    timeout: float | None = None,
) -> None:
    """Send ``plan``'s steps in order (``say(k, step)`` before each), then wait for the
    moves sent at their times to end; stop the arm if anything goes wrong."""
    begin = clock.now()
    try:
        for k, step in enumerate(plan.steps, 1):
            if say is not None:
                say(k, step)
            _step(driver, clock, step, begin, settle, (wait, timeout))
        timed = [s.at + (s.duration or 0.0) for s in plan.steps if s.at is not None]
        if timed:
            clock.sleep(max(0.0, begin + max(timed) - clock.now()))
    except BaseException as error:
        close_after(driver.stop, error)  # the step's own error stays the one raised
        raise


def _step(
    driver: Driver,
    clock: Clock,
    step: Step,
    begin: float,
    settle: Callable[[], None],
    waiting: tuple[bool, float | None],
) -> None:
    wait, timeout = waiting
    if step.at is not None:  # sent on time, not waited for
        clock.sleep(max(0.0, begin + step.at - clock.now()))
    if step.grip is not None:
        if step.settle:
            settle()
        driver.grip(step.grip)
        if step.settle:
            settle()
    elif step.path is not None:
        assert step.kin is not None
        follow(driver, step.kin, step.path, step.streamer or NaiveStepping(), clock)
    elif step.motor is not None or step.light is not None:
        _timed(driver, step)
    elif step.q is not None and step.at is not None:
        driver.move(step.q, duration=step.duration, speed=step.speed, wait=False)
    elif step.q is not None:
        driver.move(step.q, duration=step.duration, speed=step.speed, wait=wait and timeout is None)
        if wait and timeout is not None:
            wait_until(driver, clock, step.q, timeout)
    else:
        clock.sleep(step.seconds)


def _timed(driver: Driver, step: Step) -> None:
    """A timed motor's run, or the light (planned only for a driver of timed motors)."""
    if not isinstance(driver, TimedMotors):
        raise DeviceError(f"the {type(driver).__name__} driver has no timed motors or light")
    if step.motor is not None:
        driver.turn_for(*step.motor)
    elif step.light is not None:
        driver.set_light(step.light)


def wait_until(driver: Driver, clock: Clock, q: F64, timeout: float) -> None:
    """Poll until every joint is within ``REACHED`` of ``q`` [rad]; DeviceError (the arm
    stopped) after ``timeout`` [s]."""
    deadline = clock.now() + timeout
    while np.max(np.abs(driver.read() - q)) > REACHED:
        if clock.now() >= deadline:
            driver.stop()
            raise DeviceError(f"the arm did not reach its target within {timeout} s; stopped")
        clock.sleep(0.005)
