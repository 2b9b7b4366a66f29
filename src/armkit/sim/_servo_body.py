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

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol, cast

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel
from ._arm import Truth
from ._mount import GRIPPER as GRIPPER
from ._mount import Mount as Mount

F64 = NDArray[np.float64]
_SNAP = 1e-12  # [rad]: a motor this close to its setpoint lands on it (the lag never would)
_MANY = 32  # a stretch of at least this many steps evaluates its setpoints as arrays


class Outputs(Protocol):
    """A simulated controller as its servos see it."""

    def setpoint(self, channel: int, t: float) -> float | None:
        """What ``channel`` asks its servo for at time ``t`` [s], in device units; None =
        nothing (never commanded, pulses off, torque off): the servo holds where it is."""
        ...

    def busy(self, t: float) -> bool:
        """True while any channel's setpoint is still changing."""
        ...


class Stretch(Protocol):
    """Outputs that can say a stretch of steps at once (``_xm430_drive.Drives``)."""

    def setpoint(self, channel: int, t: float) -> float | None: ...

    def setpoints(self, channel: int, times: F64) -> F64 | None:
        """``setpoint`` at every time of ``times`` [s], shape (N,); None: nothing."""
        ...

    def settled(self, channel: int, t: float) -> bool:
        """True when ``channel``'s setpoint stays what it is at ``t`` [s] from then on."""
        ...

    def busy(self, t: float) -> bool: ...


def frozen(outputs: Outputs) -> Outputs:
    """``outputs`` as they stand until the host's next bytes: the controller's
    ``frozen()`` where it has one (a Dynamixel bus: each servo's drive taken once),
    else the controller itself (pulse outputs are already functions of time)."""
    freeze = getattr(outputs, "frozen", None)
    if freeze is None:
        return outputs
    taken: Outputs = freeze()
    return taken


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
    """Servos on every joint of ``model`` (and a gripper servo if mounted), see module doc.

    The state is kept as Python floats (a handful of joints: cheaper than numpy per step);
    ``step`` integrates one step, ``run`` a stretch of them at once (the world's choice),
    with the same arithmetic: the same angles to the bit.
    """

    def __init__(
        self, model: ArmModel, params: ServoParams, truth: Truth, mounts: Sequence[Mount]
    ) -> None:
        self.model, self.params = model, params
        self.outputs: Outputs | None = None
        self.mounts = tuple(m for m in mounts if m.joint != GRIPPER)
        self.grip_mount = next((m for m in mounts if m.joint == GRIPPER), None)
        self.motor = [float(a) for a in truth.q]
        self.velocity = [0.0] * len(self.motor)  # of the motors [rad/s]
        self.joint = list(self.motor)
        self.setpoint = list(self.motor)
        self.lower, self.upper = model.lower.tolist(), model.upper.tolist()
        self.motor_vmax = [j.peak_velocity * params.motor_speed_margin for j in model.joints]
        self.grip_width = truth.grip
        self.grip_goal = truth.grip
        self.grip_velocity = 0.0  # [m/s]
        self._stop: float | None = None
        self._last_setpoint: dict[int, tuple[float, float]] = {}  # channel -> (unit, si)
        self._busy = False
        self._moving = False
        self._t = 0.0  # the end of the last step [s]
        self._now: Outputs | None = None  # the outputs as taken by ``begin``
        self._stretch: Stretch | None = None  # the same, if they say a stretch at once

    def begin(self) -> None:
        """Take the controller's outputs as they stand (``frozen``): the world calls this
        before each run of steps, as they change only when the host's bytes arrive."""
        self._now = None if self.outputs is None else frozen(self.outputs)
        says_stretch = callable(getattr(self._now, "settled", None))
        self._stretch = cast("Stretch", self._now) if says_stretch else None

    def step(self, t: float, dt: float) -> None:
        """Integrate one step of ``dt`` [s] ending at ``t``."""
        outputs, self._t = self.outputs if self._now is None else self._now, t
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
        motor, setpoint = self.motor, self.setpoint
        if motor == setpoint:  # at rest on the setpoint: nothing to integrate
            if self._moving:
                self.velocity = [0.0] * len(motor)
                self._moving = False
            return
        lag, half = self.params.lag, self.params.backlash / 2.0
        alpha = 1.0 - math.exp(-dt / lag) if lag > 0 else 1.0
        joint, velocity, vmax = self.joint, self.velocity, self.motor_vmax
        lower, upper = self.lower, self.upper
        for j, goal in enumerate(setpoint):
            error = goal - motor[j]
            cap = vmax[j] * dt
            move = error if abs(error) < _SNAP else min(max(error * alpha, -cap), cap)
            m = motor[j] = motor[j] + move
            velocity[j] = move / dt
            held = min(max(joint[j], m - half), m + half)
            joint[j] = min(max(held, lower[j]), upper[j])
        self._moving = True

    def _move_gripper(self, dt: float) -> None:
        step = self.params.grip_speed * dt
        width = self.grip_width + min(step, max(-step, self.grip_goal - self.grip_width))
        if self._stop is not None and width < self._stop <= self.grip_width:
            width = self._stop
        self.grip_velocity = (width - self.grip_width) / dt
        self.grip_width = width

    # -- a stretch of steps at once ------------------------------------------------
    def runnable(self, times: F64) -> bool:
        """Whether ``run`` can do the steps ending at ``times`` [s]: the outputs say a
        stretch at once and the jaws stay still through it (the world steps any other
        stretch one by one, for the observers that watch the jaws close)."""
        outputs = self._stretch
        if outputs is None:
            return False
        goal = self._grip_goal(outputs, float(times[0]))
        return goal is not None and self._jaws_still(goal)

    def run(self, times: F64, dt: float) -> F64:
        """The steps of ``dt`` [s] ending at ``times`` [s], shape (N,), as ``step`` at each
        (after ``runnable`` said yes); returns the joint angles after each, (N, dof) [rad]."""
        outputs, setpoint = self._stretch, self.setpoint
        if outputs is None:  # not runnable: nothing to do
            return np.empty((0, len(self.joint)))
        goal = self._grip_goal(outputs, float(times[0]))
        self.grip_goal, self.grip_velocity = self.grip_goal if goal is None else goal, 0.0
        columns: list[tuple[int, list[float]]] = []
        for mount in self.mounts:
            column = self._column(outputs, mount, times)
            if isinstance(column, list):
                columns.append((mount.joint, column))
            elif column is not None:
                setpoint[mount.joint] = column
        rows = []
        for k in range(len(times)):
            for j, column in columns:
                setpoint[j] = column[k]
            self._move_motors(dt)
            rows.append(list(self.joint))
        self._t = float(times[-1])
        self._busy = outputs.busy(self._t)
        return np.array(rows, dtype=np.float64)

    def _column(self, outputs: Stretch, mount: Mount, times: F64) -> list[float] | float | None:
        """``mount``'s setpoints [rad] through ``times`` [s]: one (it stays), one per step,
        or None (its servo holds nothing). A few steps go one by one, many at once
        (``to_si_many``: the same numbers)."""
        if outputs.settled(mount.channel, float(times[0])):
            return self._target(outputs, mount, float(times[0]))
        if len(times) < _MANY:
            units = [outputs.setpoint(mount.channel, t) for t in times.tolist()]
            return [mount.to_si(u) for u in units if u is not None]
        many = outputs.setpoints(mount.channel, times)
        return None if many is None else mount.to_si_many(many).tolist()

    def _grip_goal(self, outputs: Stretch, t: float) -> float | None:
        """The gripper's goal from ``t`` [s] on, if it stays one (None: it changes)."""
        mount = self.grip_mount
        if mount is None:
            return self.grip_goal
        if not outputs.settled(mount.channel, t):
            return None
        goal = self._target(outputs, mount, t)
        return self.grip_goal if goal is None else goal

    def _jaws_still(self, goal: float) -> bool:
        """Whether the jaws stay where they are with ``goal`` [m] (there, or stopped on an
        object they close on)."""
        width = self.grip_width
        return goal == width or (self._stop is not None and goal < width == self._stop)

    def q(self) -> F64:
        """True joint angles [rad], shape (dof,)."""
        return np.array(self.joint, dtype=np.float64)

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
        if q.shape != (len(self.joint),):
            raise ValueError(f"push takes {len(self.joint)} joint angles [rad], got {q.shape}")
        free = self.limp()
        moved = np.flatnonzero(np.abs(q - np.array(self.joint)) > 1e-9).tolist()
        held = [j for j in moved if j not in free]
        if held:
            names = ", ".join(self.model.joint_names[j] for j in held)
            raise ValueError(f"{names}: the servo holds it (torque on); turn the torque off first")
        for j in free:
            self.place(j, float(q[j]))
            self.velocity[j] = 0.0

    def push_grip(self, width: float) -> None:
        """A hand opens or closes the jaws to ``width`` [m] (within the gripper's range).
        ValueError (nothing moved) if the gripper's servo holds them."""
        g, mount, outputs = self.model.gripper, self.grip_mount, self.outputs
        if mount is None or (
            outputs is not None and outputs.setpoint(mount.channel, self._t) is not None
        ):
            raise ValueError("gripper: the servo holds it (torque on); turn the torque off first")
        self.place(GRIPPER, min(max(width, g.width_min), g.width_max))
        self.grip_velocity = 0.0

    def speed(self, joint: int) -> float:
        """How fast ``joint``'s motor turns [rad/s] (GRIPPER: the opening changes [m/s])."""
        return self.grip_velocity if joint == GRIPPER else float(self.velocity[joint])

    def position(self, joint: int) -> float:
        """What an encoder on ``joint``'s output reads [rad] (GRIPPER: the opening [m])."""
        return self.grip_width if joint == GRIPPER else float(self.joint[joint])

    def at_rest(self) -> bool:
        """Setpoints steady and every motor within ``settle`` of its setpoint."""
        gap = max((abs(m - s) for m, s in zip(self.motor, self.setpoint, strict=True)), default=0.0)
        near = gap <= self.params.settle
        grip_still = abs(self.grip_goal - self.grip_width) < 1e-6 or self._stop is not None
        return not self._busy and near and grip_still

    def truth(self) -> Truth:
        """Joint angles and gripper opening, to keep between processes."""
        return Truth(tuple(float(a) for a in self.joint), float(self.grip_width))
