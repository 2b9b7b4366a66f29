"""A bank of simulated position servos, stepped at a fixed rate.

Each joint is three stages, as in a real servo or a servo controller:

1. profile generator: the controller's own interpolation from the current
   setpoint to the goal. Either velocity- and acceleration-limited (Dynamixel
   velocity profile, SSC-32 ``S``; a new goal mid-move continues from the
   current velocity) or linear over a given time (SSC-32 ``T``, a Dynamixel
   time-based profile with no acceleration ramp);
2. motor: follows the setpoint with a first-order lag (time constant ``lag``),
   its speed capped;
3. gear train: optional backlash, a dead band of ``backlash`` between the
   motor and the joint.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class ServoParams:
    """How a simulated servo behaves.

    Attributes:
        lag: position-controller time constant [s].
        backlash: total dead band of the gear train [rad].
        settle: a move is done when the motor is this close to the goal [rad].
        dt: simulation step [s] (also the recording period).
        motor_speed_margin: the motor may run this factor above the joint's max velocity.
    """

    lag: float = 0.015
    backlash: float = 0.0
    settle: float = math.radians(0.05)
    dt: float = 0.001
    motor_speed_margin: float = 1.2


class ServoBank:
    """``dof`` servos stepped together; every array has shape (dof,), radians."""

    def __init__(self, q0: F64, vmax: F64, params: ServoParams) -> None:
        self.params = params
        self.goal = q0.copy()
        self.setpoint = q0.copy()
        self.velocity = np.zeros_like(q0)
        self.vlim = vmax.copy()
        self.alim = np.ones_like(q0)
        self.motor = q0.copy()
        self.joint = q0.copy()
        self.motor_vmax = vmax * params.motor_speed_margin
        self._alpha = 1.0 - math.exp(-params.dt / params.lag) if params.lag > 0 else 1.0
        self._linear_left = 0.0

    def command_profile(self, goal: F64, vlim: F64, alim: F64) -> None:
        """Go to ``goal`` with per-joint velocity ``vlim`` [rad/s] and acceleration
        ``alim`` [rad/s^2], continuing from the current setpoint velocity."""
        self.goal, self.vlim, self.alim = goal.copy(), vlim.copy(), np.maximum(alim, 1e-9)
        self._linear_left = 0.0

    def command_linear(self, goal: F64, duration: float) -> None:
        """Go to ``goal`` at constant speed, every joint arriving after ``duration`` [s]."""
        steps = max(1, round(duration / self.params.dt))
        self.goal = goal.copy()
        self.velocity = (goal - self.setpoint) / (steps * self.params.dt)
        self._linear_left = steps * self.params.dt

    def halt(self) -> None:
        """Freeze the setpoint where it is now (the motor settles onto it)."""
        self.goal = self.setpoint.copy()
        self.velocity[:] = 0.0
        self._linear_left = 0.0

    @property
    def profile_done(self) -> bool:
        """True when the setpoint has reached the goal."""
        return self._linear_left <= 0.0 and bool(np.all(self.setpoint == self.goal))

    def settled(self) -> bool:
        """True when the setpoint is at the goal and the motor is within ``settle`` of it."""
        near = np.max(np.abs(self.motor - self.goal), initial=0.0) <= self.params.settle
        return self.profile_done and bool(near)

    def step(self) -> None:
        """Advance every servo by one ``dt``."""
        if self._linear_left > 0.0:
            self._step_linear()
        else:
            self._step_profile()
        self._step_motor()

    def _step_linear(self) -> None:
        dt = self.params.dt
        self._linear_left -= dt
        if self._linear_left <= dt * 1e-6:
            self._linear_left = 0.0
            self.setpoint = self.goal.copy()
            self.velocity[:] = 0.0
        else:
            self.setpoint = self.setpoint + self.velocity * dt

    def _step_profile(self) -> None:
        """Velocity toward the goal, braking so as to stop on it (the sqrt law)."""
        dt = self.params.dt
        err = self.goal - self.setpoint
        wanted = np.sign(err) * np.minimum(self.vlim, np.sqrt(2.0 * self.alim * np.abs(err)))
        dv = np.clip(wanted - self.velocity, -self.alim * dt, self.alim * dt)
        self.velocity = self.velocity + dv
        nxt = self.setpoint + self.velocity * dt
        # past the goal, or within 1e-12 rad of it (a step smaller than one ulp of the
        # angle would otherwise never land: a joint that barely moves in a shared profile)
        arrived = ((self.goal - nxt) * err <= 0.0) | (np.abs(self.goal - nxt) < 1e-12)
        self.setpoint = np.where(arrived, self.goal, nxt)
        self.velocity = np.where(arrived, 0.0, self.velocity)

    def _step_motor(self) -> None:
        dt = self.params.dt
        move = np.clip(
            (self.setpoint - self.motor) * self._alpha,
            -self.motor_vmax * dt,
            self.motor_vmax * dt,
        )
        self.motor = self.motor + move
        half = self.params.backlash / 2.0
        self.joint = np.clip(self.joint, self.motor - half, self.motor + half)
