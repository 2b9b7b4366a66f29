"""``SimArm``: the truth about one simulated arm, and the physics behind it (its ``Body``)."""

from __future__ import annotations

import contextlib
import math
import threading
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import is_number, shown
from ..model import ArmModel
from ..sensing import NOISE_V
from ._recording import Recorder, Recording
from ._sensor import SimulatedSensor

if TYPE_CHECKING:
    from ..scene import HeldTool, ScenePhysics
    from ..sensing import SensorMount

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Truth:
    """What a simulated arm really is, as kept between processes.

    Attributes:
        q: joint angles [rad], shape (dof,).  grip: gripper opening [m].
        motor_s: motor-seconds used since the batteries were new (the OWI's fade), [s].
        tool: the tool in the gripper (a pen, a mallet) or None.
    """

    q: tuple[float, ...]
    grip: float
    motor_s: float = 0.0
    tool: HeldTool | None = None


class Body(Protocol):
    """The physics of one arm: servos behind a controller, or the OWI's motors."""

    def step(self, t: float, dt: float) -> None:
        """Integrate from ``t - dt`` to ``t`` [s]."""
        ...

    def q(self) -> F64:
        """True joint angles now [rad], shape (dof,) (a view: copy it to keep it)."""
        ...

    def grip(self) -> float:
        """True gripper opening now [m]."""
        ...

    def grip_stop(self, width: float | None) -> None:
        """Stop the closing jaws at ``width`` [m] (an object between them); None: free."""
        ...

    def at_rest(self) -> bool:
        """True when nothing is moving or about to move (every servo at its setpoint)."""
        ...

    def truth(self) -> Truth:
        """The state to keep between processes."""
        ...


class SimArm:
    """The truth about one simulated arm (see ``armkit.sim``'s module doc).

    Attributes:
        model: the arm.  name: its name in its world (unique there).
        device: the simulated controller driving it (``ssc32.SimSSC32``, ``maestro.SimMaestro``,
            ``dynamixel.SimDynamixelBus``, ``owi535.SimOwiUsb``): for tests and tools that
            inject faults or read what it received.
        analog: analog input channel -> function giving volts (0..5 V). On a Lynx6 these
            are the SSC-32's VA..VD (channels 0..3); elsewhere a serial ADC board's
            channels. A distance sensor installs its function here.
    """

    def __init__(self, model: ArmModel, body: Body, name: str | None = None) -> None:
        self.model, self.name = model, name or model.name
        self.body = body
        self.device: object | None = None  # the simulated controller driving it (tests, tools)
        self.analog: dict[int, Callable[[], float]] = {}
        self._lock: contextlib.AbstractContextManager[object] = threading.RLock()
        self._recorder = Recorder(model.joint_names, 2)
        self._tool: HeldTool | None = None

    def join(self, lock: contextlib.AbstractContextManager[object], rows: int, now: float) -> None:
        """Called by ``World.add_arm``: share the world's ``lock``, keep ``rows`` samples of
        recording, the first at ``now`` [s]."""
        self._lock = lock
        self._recorder = Recorder(self.model.joint_names, rows)
        self._recorder.add(now, self.body.q())

    def q(self) -> F64:
        """True joint angles [rad], shape (dof,)."""
        with self._lock:
            return np.array(self.body.q(), dtype=np.float64)

    def grip(self) -> float:
        """True gripper opening [m]."""
        with self._lock:
            return float(self.body.grip())

    def install_sensor(
        self,
        physics: ScenePhysics,
        mount: SensorMount,
        *,
        channel: int = 0,
        noise: float = NOISE_V,
        seed: int = 2,
    ) -> SimulatedSensor:
        """Put a simulated GP2D120 on the hand at ``mount``, seeing ``physics``'s objects,
        on analog input ``channel`` (0 = the SSC-32's ``VA``, or the ADC board's first
        channel), with noise ``noise`` [V] seeded ``seed``; returns it."""
        sensor = SimulatedSensor(self, physics, mount, noise, seed)
        self.analog[channel] = sensor
        return sensor

    def grip_stop(self, width: float | None) -> None:
        """The scene calls this when the jaws close on an object of ``width`` [m]: the
        simulated gripper stops there (None: no obstacle).

        Raises:
            InputError: ``width`` is not None nor a finite number >= 0 [m]; nothing changes.
        """
        if width is not None and not (is_number(width) and 0.0 <= width < math.inf):
            raise InputError(
                f"{self.name}: grip_stop takes the width of the object between the jaws, a "
                f"finite number >= 0 [m] (0.03 for a 30 mm cube), or None for none; "
                f"got {shown(width)}"
            )
        with self._lock:
            self.body.grip_stop(None if width is None else float(width))

    @property
    def tool(self) -> HeldTool | None:
        """The tool in the gripper (a pen, a mallet), or None."""
        return self._tool

    def hold_tool(self, tool: HeldTool | None) -> None:
        """The jaws hold ``tool`` (they stop on it at its width), or nothing (None: free)."""
        with self._lock:
            self._tool = tool
            self.body.grip_stop(None if tool is None else tool.width)

    def truth(self) -> Truth:
        """What is kept between processes: the body's state and the tool held."""
        with self._lock:
            return replace(self.body.truth(), tool=self._tool)

    def push(self, q: F64) -> None:
        """Move the arm by hand to joint angles ``q`` [rad], shape (dof,), as a person does
        with the torque off: only the joints whose servo holds nothing (a Dynamixel with
        Torque Enable 0) may move; the mechanical limits stop them. The drivers read the
        new angles through their real protocol. ValueError, nothing moved, if a joint that
        would move is held (torque on) or the arm cannot be moved by hand (the OWI's gears)."""
        push = getattr(self.body, "push", None)
        if not callable(push):
            raise ValueError(f"{self.name}: its gears cannot be turned by hand")
        with self._lock:
            push(np.asarray(q, dtype=np.float64))

    def push_grip(self, width: float) -> None:
        """Open or close the jaws by hand to ``width`` [m], as ``push`` moves the joints:
        ValueError, nothing moved, if the gripper's servo holds them (torque on)."""
        push_grip = getattr(self.body, "push_grip", None)
        if not callable(push_grip):
            raise ValueError(f"{self.name}: its jaws cannot be moved by hand")
        with self._lock:
            push_grip(float(width))

    def at_rest(self) -> bool:
        """True when every joint and the gripper have settled."""
        with self._lock:
            return self.body.at_rest()

    def recording(self) -> Recording:
        """True joint angles, one sample per step (bounded: the world's ``record_s``)."""
        with self._lock:
            return self._recorder.recording()

    def begin(self) -> None:
        """Before a run of steps (the world calls this, holding its lock): the body takes
        its controller's outputs as they stand, where it can (``ServoBody.begin``)."""
        begin = getattr(self.body, "begin", None)
        if begin is not None:
            begin()

    def step(self, t: float, dt: float) -> None:
        """One simulation step (the world calls this, holding its lock)."""
        self.body.step(t, dt)
        self._recorder.add(t, self.body.q())

    def runnable(self, times: F64) -> bool:
        """Whether the body can step through ``times`` [s] at once (``ServoBody.runnable``:
        its outputs say a stretch, its jaws stay still); an OWI's cannot."""
        runnable = getattr(self.body, "runnable", None)
        return runnable is not None and bool(runnable(times))

    def run(self, times: F64, dt: float) -> None:
        """The steps ending at ``times`` [s] at once (after ``runnable`` said yes): each
        recorded as ``step`` records it."""
        self._recorder.add_many(times, self.body.run(times, dt))  # type: ignore[attr-defined]

    def recent(self, count: int) -> F64:
        """The last ``count`` recorded joint angles [rad], shape (count, dof), oldest first
        (an observer of a stretch of steps reads what each step recorded)."""
        with self._lock:
            return self._recorder.last(count)

    def hold(self, t: float, dt: float, count: int) -> None:
        """``count`` steps of ``dt`` [s] from ``t`` [s] in which nothing moves (the world
        skips them, holding its lock): recorded where the arm is, the body not stepped."""
        self._recorder.hold(t, dt, count, self.body.q())
