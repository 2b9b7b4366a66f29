"""Motion predictors: how a servo moves from one joint pose to another, as the
planner must know it to land a strike on the beat.

A predictor is a function ``(q0, q1, speed) -> JointProfile``: the motion [rad]
the arm's servos will follow when told to go from ``q0`` to ``q1`` at ``speed``
(a fraction of each joint's maximum velocity). It must be the model the servos
(real or simulated) actually follow; the constant part of what it misses
(bus latency, servo lag) is what the per-bar latency table absorbs.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import ArmModel, limits, ramp_time, shortest_time
from ..motion import Trapezoid, trapezoid

F64 = NDArray[np.float64]


class JointProfile(Protocol):
    """A rest-to-rest joint move (``motion.Trapezoid``, ``motion.Quintic``, ``LinearMove``)."""

    @property
    def duration(self) -> float:
        """Time of the move [s]."""
        ...

    def sample(self, t: ArrayLike) -> tuple[F64, F64, F64]:
        """Position [rad], velocity [rad/s], acceleration [rad/s^2] at times ``t`` [s]
        from the move's start, shape (N,) -> three (N, dof) arrays."""
        ...


Predictor = Callable[[F64, F64, float], JointProfile]
# (q0, q1, speed, around) -> the rebound's motion from q0 to q1 [rad], sent with a
# duration long enough from any pose of ``around`` (shape (k, dof): the stroke's ends,
# where the driver may think the joints are); see ``timed_predictor``.
Rebound = Callable[[F64, F64, float, F64], JointProfile]


def rebound_of(predictor: Predictor) -> Rebound:
    """The rebound of servos whose every move is timed as ``predictor`` says (hobby
    servos' group moves): the same move from ``q0``, ``around`` unused."""

    def predict(q0: F64, q1: F64, speed: float, around: F64) -> JointProfile:
        return predictor(q0, q1, speed)

    return predict


@dataclass(frozen=True)
class LinearMove:
    """Every joint at constant speed from ``q0`` to ``q1`` [rad] in ``duration`` [s]
    (an SSC-32 group move with a ``T`` time: no ramps)."""

    q0: F64
    q1: F64
    duration: float

    def sample(self, t: ArrayLike) -> tuple[F64, F64, F64]:
        """Position, velocity, acceleration at times ``t`` [s], shape (N,) -> (N, dof) each."""
        tt = np.asarray(t, dtype=np.float64)[:, None]
        span = max(self.duration, 1e-12)
        s = np.clip(tt / span, 0.0, 1.0)
        moving = (tt >= 0.0) & (tt < self.duration)
        vel = np.where(moving, (self.q1 - self.q0) / span, 0.0)
        return self.q0 + s * (self.q1 - self.q0), vel, np.zeros_like(vel)


def time_based_predictor(
    model: ArmModel, tick: float = 0.001, ticks_per_turn: int | None = None
) -> Predictor:
    """Dynamixel time-based profiles as ``drivers.dynamixel`` commands them (the shared
    timing rule of ``armkit.model._limits``): from ``q0`` to the goal rounded to the
    servo's position resolution, ``ticks_per_turn`` (default the model's
    ``[drivers.dynamixel]`` value, else 4096), the shortest rest-to-rest trapezoid along
    the joint-space line, its total rounded up to ``tick`` [s] (1 ms on the XM430), the
    ramp that keeps every joint under its acceleration limit rounded to ``tick``, every
    joint on the same normalised trapezoid."""
    _, a_max = limits(model)
    turn = ticks_per_turn or int(model.drivers.get("dynamixel", {}).get("ticks_per_turn", 4096))
    per_rad = turn / (2.0 * math.pi)

    def predict(q0: F64, q1: F64, speed: float) -> JointProfile:
        start = np.asarray(q0, dtype=np.float64)
        goal = np.rint(np.asarray(q1, dtype=np.float64) * per_rad) / per_rad
        fastest = shortest_time(model, start, goal, speed)
        steps = max(1, math.ceil(fastest / tick - 1e-9))
        # sent with its duration (steps * tick): the driver ramps as that time allows
        ramp = min(round(ramp_time(steps * tick, goal - start, a_max) / tick), steps // 2) * tick
        return ramped_line(start, goal, steps * tick, ramp)

    return predict


def timed_predictor(
    model: ArmModel, tick: float = 0.001, ticks_per_turn: int | None = None
) -> Rebound:
    """Dynamixel time-based profiles sent with a duration (``driver.move(q, duration=T)``),
    the rebound's: ``(q0, q1, speed, around) -> JointProfile`` from ``q0`` to ``q1``
    [rad] in the least time T that keeps every joint within ``speed`` x its maximum
    velocity moving at constant speed from ``q0`` and from every pose of ``around``
    (shape (k, dof): the driver checks the duration from its own estimate of where the
    joints are, on the stroke between its ends), rounded up to ``tick`` [s]; the servos ramp as the acceleration limits
    allow in T (``ramp_time``: no ramp when T is shorter than any ramp needs, a step in
    velocity the servos' own position loop smooths, as a time-based profile with
    Profile Acceleration 0 does)."""
    v_max, a_max = limits(model)
    turn = ticks_per_turn or int(model.drivers.get("dynamixel", {}).get("ticks_per_turn", 4096))
    per_rad = turn / (2.0 * math.pi)

    def predict(q0: F64, q1: F64, speed: float, around: F64) -> JointProfile:
        start, asked = np.asarray(q0, dtype=np.float64), np.asarray(q1, dtype=np.float64)
        goal = np.rint(asked * per_rad) / per_rad  # where the servos go; the driver times `asked`
        poses = np.vstack([start, np.asarray(around, dtype=np.float64).reshape(-1, start.size)])
        far = np.max(np.maximum(np.abs(poses - goal), np.abs(poses - asked)), axis=0)
        steps = max(1, math.ceil(float(np.max(far / (v_max * speed))) / tick - 1e-9))
        ramp = min(round(ramp_time(steps * tick, goal - start, a_max) / tick), steps // 2)
        return ramped_line(start, goal, steps * tick, ramp * tick)

    return predict


def trapezoid_predictor(model: ArmModel) -> Predictor:
    """Per-joint trapezoids (``motion.trapezoid``): velocity-limited profiles that
    arrive together, as a Dynamixel velocity profile or ``Arm.move`` plans them."""

    def predict(q0: F64, q1: F64, speed: float) -> JointProfile:
        return trapezoid(model, q0, q1, speed=speed)

    return predict


def group_move_predictor(model: ArmModel, tick: float = 0.001) -> Predictor:
    """Hobby-servo group moves (SSC-32 ``T``): linear in time, the slowest joint at
    ``speed`` x its maximum velocity sets the time, rounded up to ``tick`` [s]."""
    v_max = np.array([j.max_velocity for j in model.joints])

    def predict(q0: F64, q1: F64, speed: float) -> JointProfile:
        start, end = np.asarray(q0, dtype=np.float64), np.asarray(q1, dtype=np.float64)
        slowest = float(np.max(np.abs(end - start) / (v_max * speed), initial=0.0))
        return LinearMove(start, end, math.ceil(slowest / tick - 1e-9) * tick)

    return predict


def ramped_line(q0: F64, q1: F64, total: float, ramp: float) -> Trapezoid:
    """A trapezoid of ``total`` [s] with ramps of ``ramp`` [s] (<= total / 2) along the
    joint-space line from ``q0`` to ``q1`` [rad] (an XM430 time-based profile)."""
    ramp = min(ramp, total / 2.0)
    dist = np.abs(q1 - q0)
    peak = dist / (total - ramp) if total > 0 else 0.0 * dist
    accel = peak / ramp if ramp > 0 else 0.0 * dist
    return Trapezoid(q0, q1, total, peak, accel)
