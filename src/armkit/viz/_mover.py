"""Move an ``Arm`` towards the latest goal, at the pace of real time, from one thread.

The page asks for a new goal many times a second (a slider or the target being
dragged); only the latest one matters. ``Mover`` keeps that one goal and a
thread that sends it (``wait=False``) and then lets time pass until the arm is
there or a newer goal arrives. On a simulated arm, whose clock is virtual, the
thread advances the simulation in step with the wall clock, so a person sees
the arm move as it would; a real arm moves by itself and is only waited for.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._clock import WallClock
from .._errors import ArmkitError
from ..arm import Arm

F64 = NDArray[np.float64]
STEP = 0.01  # [s] of time per pacing step
REACHED = math.radians(0.05)  # every joint this close: the move is done
LONGEST = 60.0  # [s] of wall time one move is waited for


@dataclass(frozen=True)
class Goal:
    """What to do next: joint angles ``q`` [rad] (dof,), and/or a gripper opening
    ``grip`` [m]; ``speed`` is the fraction of each joint's max velocity."""

    q: F64 | None = None
    grip: float | None = None
    speed: float = 0.5


class Mover:
    """Drive ``arm`` to the latest ``Goal`` (see the module doc).

    ``on_error`` receives the one-line reason when a goal is refused (joint limit,
    too fast, device error); the arm then stays where it is.
    """

    def __init__(self, arm: Arm, on_error: Callable[[str], None] = print) -> None:
        self.arm = arm
        self.on_error = on_error
        self._virtual = not isinstance(arm.clock, WallClock)
        self._goal: Goal | None = None
        self._busy = False
        self._cond = threading.Condition()
        self._stop = False
        self._thread = threading.Thread(target=self._run, name="armkit-mover", daemon=True)
        self._thread.start()

    @property
    def idle(self) -> bool:
        """True when no goal is waiting or being moved to."""
        with self._cond:
            return self._goal is None and not self._busy

    def request(self, goal: Goal) -> None:
        """Replace whatever goal is waiting by ``goal``."""
        with self._cond:
            self._goal = goal
            self._cond.notify()

    def wait_idle(self, timeout: float = 30.0) -> bool:
        """Block until idle (True) or ``timeout`` [s] passed (False)."""
        deadline = time.monotonic() + timeout
        while not self.idle:
            if time.monotonic() > deadline:
                return False
            time.sleep(0.01)
        return True

    def close(self) -> None:
        """Stop the thread (the arm stops where it is)."""
        with self._cond:
            self._stop = True
            self._cond.notify()
        self._thread.join(timeout=5.0)

    def _run(self) -> None:
        while True:
            with self._cond:
                while self._goal is None and not self._stop:
                    self._cond.wait()
                if self._stop:
                    return
                goal, self._goal, self._busy = self._goal, None, True
            try:
                self._go(goal)
            except (ArmkitError, ValueError) as exc:
                self.on_error(str(exc))
            finally:
                with self._cond:
                    self._busy = False

    def _go(self, goal: Goal | None) -> None:
        if goal is None:
            return
        if goal.grip is not None:
            self.arm.grip(goal.grip * 1000.0)
        if goal.q is not None:
            self.arm.move_joints(np.degrees(goal.q).tolist(), speed=goal.speed, wait=False)
            self._pace(goal.q)

    def _pace(self, q: F64) -> None:
        """Let time pass until the arm is at ``q`` [rad] or a newer goal arrives."""
        deadline = time.monotonic() + LONGEST
        while np.max(np.abs(self.arm.read() - q)) > REACHED:
            if time.monotonic() > deadline:
                raise ArmkitError(f"the arm did not reach its goal within {LONGEST:.0f} s")
            with self._cond:
                if self._goal is not None or self._stop:
                    return
            started = time.monotonic()
            self.arm.clock.sleep(STEP)
            if self._virtual:
                time.sleep(max(0.0, STEP - (time.monotonic() - started)))
