"""The physics of a servo arm: each joint (and the gripper) driven by one servo output.

A simulated controller (an SSC-32, a Maestro, a bus of XM430s) generates each
channel's setpoint in its own units (pulse µs, tick), ramped by its own
firmware. Each servo then behaves as a real one does:

1. a ``Mount`` turns the setpoint into the joint angle [rad] (gripper opening
   [m]) the servo is asked for: the servo's characteristic and how it is mounted;
2. the motor follows that setpoint with a first-order lag (time constant
   ``lag``), its speed capped at ``motor_speed_margin`` x the joint's maximum;
3. the gear train has an optional dead band (``backlash``); the joint stops at
   the model's limits (the mechanical stops).

The gripper moves at ``grip_speed`` toward its setpoint and stops where an
object blocks it (``grip_stop``).
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel
from ._arm import Truth

F64 = NDArray[np.float64]
GRIPPER = -1
_SNAP = 1e-12  # [rad]: a motor this close to its setpoint lands on it (the lag never would)  # Mount.joint of the gripper's servo


class Outputs(Protocol):
    """A simulated controller as its servos see it."""

    def setpoint(self, channel: int, t: float) -> float | None:
        """What ``channel`` asks its servo for at time ``t`` [s], in device units; None =
        nothing (never commanded, pulses off, torque off): the servo holds where it is."""
        ...

    def busy(self, t: float) -> bool:
        """True while any channel's setpoint is still changing."""
        ...


@dataclass(frozen=True)
class Mount:
    """One controller channel turning one joint (``joint`` index) or the gripper (GRIPPER).

    ``units`` (device units, strictly monotonic) and ``values`` ([rad] or [m],
    increasing) are corresponding points; between and beyond them the relation is
    linear (the end segments extend).
    """

    channel: int
    joint: int
    units: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self) -> None:
        if len(self.units) < 2 or len(self.units) != len(self.values):
            raise ValueError(f"channel {self.channel}: a mount needs >= 2 matching points")

    def to_si(self, unit: float) -> float:
        """Device units -> [rad] or [m]."""
        xs, ys = self.units, self.values
        if xs[0] > xs[-1]:
            xs, ys = xs[::-1], ys[::-1]
        return _interp(unit, xs, ys)

    def from_si(self, value: float) -> float:
        """[rad] or [m] -> device units."""
        return _interp(value, self.values, self.units)

    @property
    def slope(self) -> float:
        """Device units per [rad] or [m] (of the first segment)."""
        return (self.units[1] - self.units[0]) / (self.values[1] - self.values[0])


def _interp(x: float, xs: Sequence[float], ys: Sequence[float]) -> float:
    i = min(max(bisect.bisect_right(xs, x), 1), len(xs) - 1)
    x0, x1, y0, y1 = xs[i - 1], xs[i], ys[i - 1], ys[i]
    if x1 == x0:  # a degenerate table (a gripper 0..0 mm wide, that never opens): its start
        return y0
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0)


@dataclass(frozen=True)
class ServoParams:
    """How the simulated servos behave.

    Attributes:
        lag: position-controller time constant [s].  backlash: gear dead band [rad].
        settle: a servo counts as arrived this close to its setpoint [rad].
        motor_speed_margin: the motor may run this factor above the joint's max velocity.
        grip_speed: gripper opening/closing speed [m/s].
    """

    lag: float = 0.015
    backlash: float = 0.0
    settle: float = math.radians(0.05)
    motor_speed_margin: float = 1.2
    grip_speed: float = 0.05


class ServoBody:
    """Servos on every joint of ``model`` (and a gripper servo if mounted), see module doc."""

    def __init__(
        self, model: ArmModel, params: ServoParams, truth: Truth, mounts: Sequence[Mount]
    ) -> None:
        self.model, self.params = model, params
        self.outputs: Outputs | None = None
        self.mounts = tuple(m for m in mounts if m.joint != GRIPPER)
        self.grip_mount = next((m for m in mounts if m.joint == GRIPPER), None)
        self.motor = np.array(truth.q, dtype=np.float64)
        self.velocity = np.zeros_like(self.motor)  # of the motors [rad/s]
        self.joint = self.motor.copy()
        self.setpoint = self.motor.copy()
        self.lower, self.upper = model.lower, model.upper
        self.motor_vmax = np.array([j.peak_velocity for j in model.joints]) * (  # the servo's own
            params.motor_speed_margin
        )
        self.grip_width = truth.grip
        self.grip_goal = truth.grip
        self.grip_velocity = 0.0  # [m/s]
        self._stop: float | None = None
        self._last_setpoint: dict[int, tuple[float, float]] = {}  # channel -> (unit, si)
        self._busy = False
        self._moving = False
        self._t = 0.0  # the end of the last step [s]

    def step(self, t: float, dt: float) -> None:
        """Integrate one step of ``dt`` [s] ending at ``t``."""
        outputs, self._t = self.outputs, t
        if outputs is not None:
            for mount in self.mounts:
                si = self._target(outputs, mount, t)
                if si is not None:
                    self.setpoint[mount.joint] = si
            if self.grip_mount is not None:
                si = self._target(outputs, self.grip_mount, t)
                if si is not None:
                    self.grip_goal = si
            self._busy = outputs.busy(t)
        self._move_motors(dt)
        self._move_gripper(dt)

    def _target(self, outputs: Outputs, mount: Mount, t: float) -> float | None:
        unit = outputs.setpoint(mount.channel, t)
        if unit is None:
            return None
        last = self._last_setpoint.get(mount.channel)
        if last is not None and last[0] == unit:
            return last[1]
        si = mount.to_si(unit)
        self._last_setpoint[mount.channel] = (unit, si)
        return si

    def _move_motors(self, dt: float) -> None:
        error = self.setpoint - self.motor
        if not error.any():  # at rest on the setpoint: nothing to integrate
            if self._moving:
                self.velocity[:] = 0.0
                self._moving = False
            return
        lag = self.params.lag
        alpha = 1.0 - math.exp(-dt / lag) if lag > 0 else 1.0
        cap = self.motor_vmax * dt
        move = np.minimum(np.maximum(error * alpha, -cap), cap)
        move[np.abs(error) < _SNAP] = error[np.abs(error) < _SNAP]  # land exactly
        self.motor += move
        self.velocity = move / dt
        self._moving = True
        half = self.params.backlash / 2.0
        joint = np.minimum(np.maximum(self.joint, self.motor - half), self.motor + half)
        self.joint = np.minimum(np.maximum(joint, self.lower), self.upper)

    def _move_gripper(self, dt: float) -> None:
        step = self.params.grip_speed * dt
        width = self.grip_width + min(step, max(-step, self.grip_goal - self.grip_width))
        if self._stop is not None and width < self._stop <= self.grip_width:
            width = self._stop
        self.grip_velocity = (width - self.grip_width) / dt
        self.grip_width = width

    def q(self) -> F64:
        """True joint angles [rad], shape (dof,)."""
        return self.joint

    def grip(self) -> float:
        """True gripper opening [m]."""
        return self.grip_width

    def grip_stop(self, width: float | None) -> None:
        """Jaws stop at ``width`` [m] while closing (None: nothing between them)."""
        self._stop = width

    def place(self, joint: int, value: float) -> None:
        """Put ``joint`` (GRIPPER: the opening [m]) at ``value`` [rad], at rest."""
        if joint == GRIPPER:
            self.grip_width = self.grip_goal = value
            return
        self.motor[joint] = self.joint[joint] = self.setpoint[joint] = value

    def limp(self) -> tuple[int, ...]:
        """Indices of the joints whose servo holds nothing (torque off, no pulses)."""
        outputs = self.outputs
        if outputs is None:
            return tuple(range(len(self.joint)))
        return tuple(m.joint for m in self.mounts if outputs.setpoint(m.channel, self._t) is None)

    def push(self, q: F64) -> None:
        """A hand moves the joints to ``q`` [rad], shape (dof,), stopped by the mechanical
        limits. ValueError (nothing moved) if a joint that would move is held by its servo."""
        q = np.minimum(np.maximum(np.asarray(q, dtype=np.float64), self.lower), self.upper)
        if q.shape != self.joint.shape:
            raise ValueError(f"push takes {len(self.joint)} joint angles [rad], got {q.shape}")
        free = self.limp()
        held = [j for j in np.flatnonzero(np.abs(q - self.joint) > 1e-9) if j not in free]
        if held:
            names = ", ".join(self.model.joint_names[j] for j in held)
            raise ValueError(f"{names}: the servo holds it (torque on); turn the torque off first")
        for j in free:
            self.place(j, float(q[j]))
            self.velocity[j] = 0.0

    def speed(self, joint: int) -> float:
        """How fast ``joint``'s motor turns [rad/s] (GRIPPER: the opening changes [m/s])."""
        return self.grip_velocity if joint == GRIPPER else float(self.velocity[joint])

    def position(self, joint: int) -> float:
        """What an encoder on ``joint``'s output reads [rad] (GRIPPER: the opening [m])."""
        return self.grip_width if joint == GRIPPER else float(self.joint[joint])

    def at_rest(self) -> bool:
        """Setpoints steady and every motor within ``settle`` of its setpoint."""
        near = float(np.max(np.abs(self.motor - self.setpoint), initial=0.0)) <= self.params.settle
        grip_still = abs(self.grip_goal - self.grip_width) < 1e-6 or self._stop is not None
        return not self._busy and near and grip_still

    def truth(self) -> Truth:
        """Joint angles and gripper opening, to keep between processes."""
        return Truth(tuple(float(a) for a in self.joint), float(self.grip_width))
