"""A small fake of the simulation World of the contract (``world.arm()``, ``attach``,
``SimArm.q()/grip()/grip_stop()``) and a driver moving it, for the scene and task
tests. Not armkit's simulator: it moves joints and jaws at once, in a few steps."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from armkit.connect import forecaster
from armkit.drivers import Forecast
from armkit.model import ArmModel

F64 = NDArray[np.float64]
STEPS_PER_MOVE = 8


class FakeSimArm:
    """The truth about one arm: joints [rad] and jaw opening [m], the jaws stopped
    by an object when the scene says so."""

    def __init__(self, model: ArmModel, q: F64) -> None:
        self.model = model
        self.name = model.name
        self._q = np.array(q, dtype=float)
        self._width = model.gripper.width_max
        self._stop: float | None = None

    def q(self) -> F64:
        return self._q.copy()

    def grip(self) -> float:
        return self._width if self._stop is None else max(self._width, self._stop)

    def grip_stop(self, width: float | None) -> None:
        self._stop = width


class FakeWorld:
    """One arm; observers called after every small step."""

    def __init__(self, model: ArmModel, q: F64) -> None:
        self.sim = FakeSimArm(model, q)
        self.t = 0.0
        self.observers: list[Any] = []

    def arm(self, name: str | None = None) -> FakeSimArm:
        assert name in (None, self.sim.name)
        return self.sim

    def attach(self, observer: Any) -> Callable[[], None]:
        self.observers.append(observer)
        return lambda: self.observers.remove(observer)

    def step(self) -> None:
        self.t += 0.001
        for observer in list(self.observers):
            observer.on_step(self, self.t)

    def move(self, q: F64) -> None:
        start = self.sim.q()
        for s in np.linspace(0.0, 1.0, STEPS_PER_MOVE + 1)[1:]:
            self.sim._q = start + s * (np.asarray(q) - start)
            self.step()

    def set_grip(self, width: float) -> None:
        start = self.sim._width
        for s in np.linspace(0.0, 1.0, STEPS_PER_MOVE + 1)[1:]:
            self.sim._width = start + s * (width - start)
            self.step()


class VirtualClock:
    """Time that passes only when somebody sleeps: the fake world moves at once, so what
    waits for it (a task's pause for the gripper, 0.5 s on real hardware) need not wait
    in real time."""

    def __init__(self) -> None:
        self.t = 0.0
        self.slept: list[float] = []

    def now(self) -> float:
        return self.t

    def sleep(self, seconds: float) -> None:
        self.slept.append(seconds)
        self.t += max(0.0, seconds)


class FakeDriver:
    """An armkit Driver on the fake world; counts the commands it was sent. Its clock
    is virtual (``VirtualClock``): the tasks' waits cost no real time."""

    moves = "smart"

    def __init__(self, world: FakeWorld) -> None:
        self.world = world
        self.commands = 0
        self.clock = VirtualClock()

    @property
    def joint_names(self) -> tuple[str, ...]:
        return self.world.sim.model.joint_names

    def move(
        self,
        q: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        self.commands += 1
        self.world.move(q)

    def read(self) -> F64:
        return self.world.sim.q()

    def grip(self, width: float) -> None:
        self.commands += 1
        self.world.set_grip(width)

    def forecast(self, q0: F64, q1: F64, **options: Any) -> Forecast:
        """The model's own driver's forecast (this fake moves at once)."""
        return forecaster(self.world.sim.model).forecast(q0, q1, **options)

    def forecast_grip(self, before: float | None, width: float) -> float:
        return forecaster(self.world.sim.model).forecast_grip(before, width)

    def stop(self) -> None:
        pass

    def close(self) -> None:
        pass
