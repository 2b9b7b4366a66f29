"""How long an OWI motor must run to turn a joint by an angle, and back.

Per joint and direction: a rate [rad/s]; for the gravity-loaded joints, per
direction, two rates chosen by whether the move lowers or lifts the load
beyond the joint (the side of its axis the load hangs on, from the arm's
geometry, changes along the move, so times are integrated in small angle
steps); a fixed extra
travel per move (gear slip at start + coast at stop); and a battery factor,
speed * (1 - drain * motor-seconds used). 000's model is the special case of
one rate per joint (limit span / traverse time) and nothing else.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]
STEP = math.radians(1.0)  # integration step [rad]


@dataclass(frozen=True)
class JointTiming:
    """One joint's timing.

    Attributes:
        rates: [rad/s]: (forwards lowering, forwards lifting, backwards lowering,
            backwards lifting) the load; forwards = towards the upper limit.
        gravity: whether the rate depends on the load's side of the axis; if not,
            only the "lowering" rates are used.
        overshoot: travel per move beyond the powered time's [rad], (forwards, backwards).
    """

    rates: tuple[float, float, float, float]
    gravity: bool = False
    overshoot: tuple[float, float] = (0.0, 0.0)


@dataclass(frozen=True)
class TimingModel:
    """Timing of every joint of one unit.

    Attributes:
        joints: one JointTiming per joint, model order (base, shoulder, elbow, wrist).
        lower, upper: the unit's joint limits [rad].
        lengths: upper arm, lower arm, wrist to grip point [m] (for the load side).
        weights: relative masses at the elbow, the wrist and the grip point.
        drain: fractional speed lost per motor-second [1/s].
        gripper_s: gripper travel time, one way [s].
        min_move_s: shortest move the motors do reliably [s].
    """

    joints: tuple[JointTiming, ...]
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    lengths: tuple[float, float, float]
    weights: tuple[float, float, float] = (1.0, 1.0, 1.0)
    drain: float = 0.0
    gripper_s: float = 1.7
    min_move_s: float = 0.2

    def rate(self, q: F64, j: int, direction: int, motor_s: float) -> float:
        """Speed [rad/s] of joint ``j`` turning ``direction`` (+1/-1) at pose ``q`` [rad]."""
        jt = self.joints[j]
        lifting = jt.gravity and direction * load_side(q, self.lengths, j, self.weights) <= 0.0
        return jt.rates[(0 if direction > 0 else 2) + lifting] * self.battery(motor_s)

    def battery(self, motor_s: float) -> float:
        """Speed factor of the batteries after ``motor_s`` motor-seconds: 1 - drain * motor_s,
        at least 0.3."""
        return max(0.3, 1.0 - self.drain * motor_s)

    def overshoot(self, j: int, direction: int) -> float:
        """Travel per move beyond the powered part [rad]."""
        return self.joints[j].overshoot[0 if direction > 0 else 1]

    def duration(self, q: F64, j: int, target: float, motor_s: float = 0.0) -> float:
        """Motor time [s] to turn joint ``j`` from ``q[j]`` to ``target`` [rad]; 0 when the
        overshoot alone covers the distance."""
        direction = 1 if target >= q[j] else -1
        powered = abs(target - float(q[j])) - self.overshoot(j, direction)
        if powered <= 0.0:
            return 0.0
        t = 0.0
        for _angle, dt in self._walk(q, j, direction, motor_s, powered):
            t += dt
        return float(t)

    def advance(
        self, q: F64, j: int, direction: int, seconds: float, motor_s: float = 0.0
    ) -> float:
        """Angle [rad] of joint ``j`` after its motor ran ``seconds`` [s] from pose ``q``,
        overshoot included, clamped to the limits."""
        if seconds <= 0.0:
            return float(q[j])
        angle, t = float(q[j]), 0.0
        for angle, dt in self._walk(q, j, direction, motor_s, math.inf):
            if t + dt >= seconds:
                angle += direction * STEP * ((seconds - t) / dt - 1.0)
                break
            t += dt
        angle += direction * self.overshoot(j, direction)
        return min(self.upper[j], max(self.lower[j], angle))

    def _walk(
        self, q: F64, j: int, direction: int, motor_s: float, distance: float
    ) -> Iterator[tuple[float, float]]:
        """(angle after the step, time of the step) in STEP increments, to ``distance``
        or a limit."""
        pose = np.array(q, dtype=float)
        start, limit = float(q[j]), self.upper[j] if direction > 0 else self.lower[j]
        end = min(distance, max(0.0, direction * (limit - start)) + STEP)
        done = 0.0
        while done < end - 1e-12:
            h = min(STEP, end - done)
            pose[j] = start + direction * (done + h / 2)
            done += h
            yield start + direction * done, h / self.rate(pose, j, direction, motor_s)


def load_side(
    q: F64,
    lengths: tuple[float, float, float],
    j: int,
    weights: tuple[float, float, float] = (1, 1, 1),
) -> float:
    """Forward offset [m] of the centre of the masses (``weights``, at the elbow, wrist
    and grip point) beyond joint ``j`` from its axis, in the arm's plane; > 0: turning
    ``j`` forwards lowers the load. 0 for the base (j = 0)."""
    if j == 0:
        return 0.0
    phi, x = 0.0, [0.0]
    for k in range(3):
        phi += float(q[k + 1])
        x.append(x[-1] + lengths[k] * math.sin(phi))
    w = weights[j - 1 :]
    return sum(wk * xk for wk, xk in zip(w, x[j:], strict=True)) / sum(w) - x[j - 1]
