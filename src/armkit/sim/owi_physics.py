"""The simulated OWI-535's motors: what really happens to the joints.

Each motor turns its joint at a unit-specific speed, changed by gravity
(a loaded joint is faster when it lowers its load than when it lifts it), by
the battery (speed falls with motor-seconds used), with a jump at start (gear
slip) and at stop (coast), and slips in place at its limits. The model knows
the true angles, so a driver's estimate can be compared with them.
Time comes from a clock (real or simulated); the state is advanced lazily to
``clock.now()`` whenever a command arrives or a reading is taken.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._clock import Clock
from ..model import ArmModel

F64 = NDArray[np.float64]
JOINTS = ("base", "shoulder", "elbow", "wrist")
STEP_S = 0.02  # integration step [s]
LEVER_SCALE_M = 0.02  # lever at which gravity reaches its full effect [m]
# distal masses (relative weight) at fractions of the links (upper, lower, gripper)
MASSES = ((0, 1.0, 1.0), (1, 0.5, 0.3), (1, 1.0, 0.8), (2, 0.5, 0.3), (2, 1.0, 0.5))


@dataclass(frozen=True)
class OwiUnit:
    """One physical unit's true behaviour (every unit differs).

    Attributes:
        speed: motor speed with no load, full battery [rad/s], shape (4,).
        asym: direction asymmetry: speed * (1 + asym * direction), shape (4,).
        gravity: gravity gain, 0 for the base, shape (4,).
        slip: mean gear slip at start [rad], shape (4,).  coast: mean coast at stop [rad], (4,).
        jitter: standard deviation of slip and coast, as a fraction of them.
        drain: fractional speed lost per motor-second.
        gripper_s: gripper travel time, closed to open [s].
        lengths: upper arm, lower arm, wrist to grip point [m].
    """

    speed: F64
    asym: F64
    gravity: F64
    slip: F64
    coast: F64
    jitter: float
    drain: float
    gripper_s: float
    lengths: tuple[float, float, float]


def random_unit(model: ArmModel, seed: int) -> OwiUnit:
    """A plausible unit around the model's nominal timings, drawn with ``seed``."""
    rng = np.random.default_rng(seed)
    cfg = model.drivers["owi535"]
    span = model.upper - model.lower
    nominal = span / np.array([float(cfg["traverse_s"][j]) for j in JOINTS])
    return OwiUnit(
        speed=nominal * rng.uniform(0.85, 1.15, 4),
        asym=rng.uniform(-0.03, 0.03, 4),
        gravity=np.array([0.0, 0.25, 0.2, 0.1]) * rng.uniform(0.8, 1.2, 4),
        slip=np.radians(rng.uniform(1.0, 2.5, 4)),
        coast=np.radians(rng.uniform(0.5, 1.5, 4)),
        jitter=0.15,
        drain=1.5e-4,
        gripper_s=float(cfg["gripper_s"]) * float(rng.uniform(0.9, 1.1)),
        lengths=(model.dh[2].a, model.dh[3].a, model.tool_length),
    )


class OwiPhysics:
    """True joint angles, gripper opening and light of a simulated arm."""

    def __init__(
        self, model: ArmModel, unit: OwiUnit, clock: Clock, seed: int, q0: F64 | None = None
    ) -> None:
        self.model, self.unit, self.clock = model, unit, clock
        self._rng = np.random.default_rng(seed + 1)
        self.q = np.array(model.home if q0 is None else q0, dtype=float)
        self.gripper = 0.0  # 0 = closed, 1 = open
        self.light = False
        self.motor_s = 0.0  # motor-seconds used
        self.dirs = np.zeros(4, dtype=int)
        self.gripper_dir = 0
        self._t = clock.now()

    def command(self, dirs: F64, gripper_dir: int, light: bool) -> None:
        """Apply a new motor state: joint directions, shape (4,) in {-1, 0, 1}."""
        self.advance()
        new = np.asarray(dirs, dtype=int)
        for j in range(4):
            if new[j] != self.dirs[j]:
                old = int(self.dirs[j])
                self._jump(j, old, self.unit.coast[j] * self._factor(j, old))
                self._jump(j, int(new[j]), self.unit.slip[j])
        self.dirs, self.gripper_dir, self.light = new, gripper_dir, light

    @property
    def t(self) -> float:
        """The time the motion is integrated up to [s]."""
        return self._t

    def true_q(self) -> F64:
        """True joint angles now [rad], shape (4,)."""
        self.advance()
        return self.q.copy()

    def at_limit(self, j: int) -> bool:
        """Whether joint ``j`` is pressed against the limit it is driven towards."""
        self.advance()
        d = self.dirs[j]
        return bool(
            (d > 0 and self.q[j] >= self.model.upper[j])
            or (d < 0 and self.q[j] <= self.model.lower[j])
        )

    def advance(self, until: float | None = None) -> None:
        """Integrate the motion up to ``until`` [s] (None: ``clock.now()``)."""
        t = self.clock.now() if until is None else until
        if not self.dirs.any() and self.gripper_dir == 0:  # nothing runs: nothing to integrate
            self._t = max(self._t, t)
            return
        while self._t < t - 1e-12:
            h = min(STEP_S, t - self._t)
            self._step(h)
            self._t += h

    def _step(self, h: float) -> None:
        for j in (int(k) for k in np.flatnonzero(self.dirs)):
            d = int(self.dirs[j])
            self.q[j] += d * self._factor(j, d) * self.unit.speed[j] * h
        self.q = np.clip(self.q, self.model.lower, self.model.upper)
        self.gripper = min(1.0, max(0.0, self.gripper + self.gripper_dir * h / self.unit.gripper_s))
        self.motor_s += h * (np.count_nonzero(self.dirs) + abs(self.gripper_dir))

    def _jump(self, j: int, direction: int, size: float) -> None:
        if direction == 0:
            return
        noisy = size * (1.0 + self.unit.jitter * float(self._rng.standard_normal()))
        self.q[j] = np.clip(self.q[j] + direction * noisy, self.model.lower[j], self.model.upper[j])

    def _factor(self, j: int, direction: int) -> float:
        """Speed factor of joint ``j`` moving ``direction``: asymmetry, gravity, battery."""
        battery = max(0.3, 1.0 - self.unit.drain * self.motor_s)
        down = float(
            np.clip(direction * load_lever(self.q, self.unit.lengths, j) / LEVER_SCALE_M, -1, 1)
        )
        asym = 1.0 + float(self.unit.asym[j]) * direction
        return asym * (1.0 + float(self.unit.gravity[j]) * down) * battery


def load_lever(q: F64, lengths: tuple[float, float, float], j: int) -> float:
    """Mass-weighted forward offset [m] of the load beyond joint ``j`` (1..3) from its axis.

    Positive: the load hangs forward, so turning the joint forwards lowers it.
    0 for the base (j = 0), whose axis is vertical.
    """
    if j == 0:
        return 0.0
    phi, x = 0.0, [0.0]  # forward offsets of shoulder, elbow, wrist, grip point
    for k in range(3):
        phi += float(q[k + 1])
        x.append(x[-1] + lengths[k] * math.sin(phi))
    total, moment = 0.0, 0.0
    for link, frac, weight in MASSES:
        if link >= j - 1:
            point = x[link] + frac * (x[link + 1] - x[link])
            total, moment = total + weight, moment + weight * (point - x[j - 1])
    return moment / total
