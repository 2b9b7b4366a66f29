"""Joint-space point-to-point profiles: every joint arrives together, as fast as
the model's per-joint velocity and acceleration limits allow (seed 002's group
move).

Three kinds: a trapezoid per joint (bang-coast-bang acceleration, the shortest
time), a trapezoid shared by every joint (the joint-space path is a straight line,
as in an SSC-32 group move or a Dynamixel time-based profile) and a quintic (zero
velocity and acceleration at both ends: no jerk steps; also a straight line).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError
from ..model import ArmModel, check_speed, limits, trapezoid_time

F64 = NDArray[np.float64]

# Peak |velocity| and |acceleration| of the unit quintic 10s^3 - 15s^4 + 6s^5 on [0, 1].
QUINTIC_PEAK_VEL = 1.875
QUINTIC_PEAK_ACC = 10.0 / np.sqrt(3.0)


@dataclass(frozen=True)
class Trapezoid:
    """Per-joint trapezoidal velocity profiles of one common duration.

    Attributes:
        q0, q1: start and end joint angles [rad], shape (dof,).
        duration: time of the move [s], the same for every joint.
        v: cruise speed per joint [rad/s], shape (dof,), >= 0.
        a: acceleration per joint [rad/s^2], shape (dof,), >= 0.
    """

    q0: F64
    q1: F64
    duration: float
    v: F64
    a: F64

    def sample(self, t: ArrayLike) -> tuple[F64, F64, F64]:
        """Position [rad], velocity [rad/s], acceleration [rad/s^2] at times ``t`` [s],
        shape (N,) -> three arrays of shape (N, dof)."""
        tt = np.clip(np.asarray(t, dtype=np.float64), 0.0, self.duration)[:, None]
        direction = np.sign(self.q1 - self.q0)
        a = np.where(self.v > 0, self.a, 0.0)
        ta = np.divide(self.v, a, out=np.zeros_like(a), where=a > 0)
        up, down = np.minimum(tt, ta), np.clip(tt - (self.duration - ta), 0.0, None)
        speed = a * up - a * down
        dist = 0.5 * a * up**2 + self.v * np.clip(tt - ta, 0.0, None) - 0.5 * a * down**2
        acc = np.where(tt < ta, a, 0.0) - np.where(tt > self.duration - ta, a, 0.0)
        return self.q0 + direction * dist, direction * speed, direction * acc


@dataclass(frozen=True)
class Quintic:
    """Quintic polynomial moves of one common duration (rest to rest).

    Attributes:
        q0, q1: start and end joint angles [rad], shape (dof,).
        duration: time of the move [s].
    """

    q0: F64
    q1: F64
    duration: float

    def sample(self, t: ArrayLike) -> tuple[F64, F64, F64]:
        """Position, velocity, acceleration at times ``t`` [s], shape (N,) -> (N, dof) each."""
        big_t = max(self.duration, 1e-12)
        s = np.clip(np.asarray(t, dtype=np.float64), 0.0, big_t)[:, None] / big_t
        delta = self.q1 - self.q0
        pos = 10 * s**3 - 15 * s**4 + 6 * s**5
        vel = (30 * s**2 - 60 * s**3 + 30 * s**4) / big_t
        acc = (60 * s - 180 * s**2 + 120 * s**3) / big_t**2
        return self.q0 + delta * pos, delta * vel, delta * acc


def trapezoid(
    model: ArmModel, q0: ArrayLike, q1: ArrayLike, speed: float = 1.0, duration: float | None = None
) -> Trapezoid:
    """The shortest synchronised trapezoidal move from ``q0`` to ``q1`` [rad], shape (dof,).

    Each joint may use ``speed`` x its max velocity and its max acceleration; the
    slowest joint sets the duration and every other joint is slowed to arrive with it.
    ``duration`` [s] asks for a longer move; shorter than possible raises ValueError.
    """
    start, end, vmax, amax = _limits(model, q0, q1, speed)
    dist = np.abs(end - start)
    fastest = float(np.max(trapezoid_time(dist, vmax, amax), initial=0.0))
    total = _checked_duration(fastest, duration)
    v = _cruise_speed(dist, amax, total)
    return Trapezoid(start, end, total, v, np.where(dist > 0, amax, 0.0))


def trapezoid_in_line(
    model: ArmModel, q0: ArrayLike, q1: ArrayLike, speed: float = 1.0, duration: float | None = None
) -> Trapezoid:
    """The shortest move from ``q0`` to ``q1`` [rad] along the straight joint-space line:
    every joint runs the same normalised trapezoid scaled by its distance, so all
    accelerate, cruise and brake together. Limits and ``duration`` as ``trapezoid``."""
    start, end, vmax, amax = _limits(model, q0, q1, speed)
    dist = np.abs(end - start)
    if not np.any(dist > 0):
        return Trapezoid(start, end, _checked_duration(0.0, duration), 0.0 * dist, 0.0 * dist)
    moving = dist > 0
    v_unit = float(np.min(vmax[moving] / dist[moving]))
    a_unit = float(np.min(amax[moving] / dist[moving]))
    fastest = float(trapezoid_time(np.array([1.0]), np.array([v_unit]), np.array([a_unit]))[0])
    total = _checked_duration(fastest, duration)
    v = float(_cruise_speed(np.array([1.0]), np.array([a_unit]), total)[0])
    return Trapezoid(start, end, total, v * dist, a_unit * dist)


def quintic(
    model: ArmModel, q0: ArrayLike, q1: ArrayLike, speed: float = 1.0, duration: float | None = None
) -> Quintic:
    """The shortest quintic move from ``q0`` to ``q1`` [rad] within every joint's
    velocity (x ``speed``) and acceleration limit; ``duration`` [s] asks for longer."""
    start, end, vmax, amax = _limits(model, q0, q1, speed)
    dist = np.abs(end - start)
    by_vel = QUINTIC_PEAK_VEL * dist / vmax
    by_acc = np.sqrt(QUINTIC_PEAK_ACC * dist / amax)
    fastest = float(np.max(np.maximum(by_vel, by_acc), initial=0.0))
    return Quintic(start, end, _checked_duration(fastest, duration))


def _limits(
    model: ArmModel, q0: ArrayLike, q1: ArrayLike, speed: float
) -> tuple[F64, F64, F64, F64]:
    """Validated start, end [rad] and the velocity and acceleration limits, shape (dof,) each."""
    start = np.asarray(q0, dtype=np.float64).reshape(model.dof)
    end = np.asarray(q1, dtype=np.float64).reshape(model.dof)
    vmax, amax = limits(model, check_speed(speed))
    return start, end, vmax, amax


def _checked_duration(fastest: float, duration: float | None) -> float:
    if duration is None:
        return fastest
    if not np.isfinite(duration) or duration < 0:
        raise InputError(f"duration must be a time >= 0 s, got {duration}")
    if duration < fastest - 1e-9:
        raise InputError(
            f"duration {duration:.3f} s is too short: the joint limits need {fastest:.3f} s or more"
        )
    return duration


def _cruise_speed(dist: F64, amax: F64, total: float) -> F64:
    """Cruise speed [rad/s] covering ``dist`` in ``total`` s with acceleration ``amax``:
    the smaller root of v^2 - a T v + a d = 0."""
    disc = np.clip((amax * total) ** 2 - 4.0 * amax * dist, 0.0, None)
    return np.where(dist > 0, (amax * total - np.sqrt(disc)) / 2.0, 0.0)
