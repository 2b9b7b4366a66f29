"""Fit a unit's timing model to limit-to-limit timings (calibration).

Measurements: full traverses (a joint run from one limit until a person says
it reached the other) and pulse traverses (several short timed pulses, then
the rest of the way timed). From them, in this order: the battery drain (the
same traverse gets slower as motor-seconds are used), each joint's rates
(least squares; for gravity-loaded joints the path is split into the parts
where the move lowers and lifts the load), and the extra travel per move
(start slip + coast, which only short moves reveal).
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from ._timing import STEP, JointTiming, TimingModel, load_side

F64 = NDArray[np.float64]
SLIP_SHARE = 0.5  # part of the extra travel that happens at the start of a move


@dataclass(frozen=True)
class Traverse:
    """One timed run of ``joint`` from one limit to the other.

    Attributes:
        joint: index.  direction: +1 (lower to upper) or -1.
        seconds: measured time [s].  pose: the arm's pose at the start [rad], shape (4,).
        motor_s: motor-seconds used before the run.
        pulses, pulse_s: short pulses run before the timed rest (0 for a full traverse).
    """

    joint: int
    direction: int
    seconds: float
    pose: tuple[float, ...]
    motor_s: float
    pulses: int = 0
    pulse_s: float = 0.0


def fit_timing(base: TimingModel, runs: list[Traverse]) -> TimingModel:
    """``base`` with the drain, rates and overshoot of every joint in ``runs`` fitted."""
    full = [r for r in runs if r.pulses == 0]
    drain = fit_drain(full, base.drain, {j for j, jt in enumerate(base.joints) if jt.gravity})
    model = replace(base, drain=drain)
    for _ in range(2):  # rates depend on the overshoot's start slip and back
        for j in sorted({r.joint for r in full}):
            model = _with_joint(model, j, _fit_rates(model, j, [r for r in full if r.joint == j]))
        for j in sorted({r.joint for r in runs if r.pulses}):
            model = _with_joint(
                model, j, _fit_overshoot(model, j, [r for r in runs if r.joint == j and r.pulses])
            )
    return model


def fit_drain(full: list[Traverse], default: float, gravity: set[int] | None = None) -> float:
    """Fractional speed loss per motor-second from repeated traverses [1/s]: the same
    joint, direction and (for the ``gravity`` joints) pose, timed at different times."""
    groups: dict[tuple[int, int, tuple[float, ...]], list[Traverse]] = defaultdict(list)
    for r in full:
        pose = tuple(np.round(r.pose, 3)) if r.joint in (gravity or set()) else ()
        groups[(r.joint, r.direction, pose)].append(r)
    drains, weights = [], []
    for group in groups.values():
        x = np.array([r.motor_s + r.seconds / 2 for r in group])
        if len(group) < 2 or np.ptp(x) <= 0.0:
            continue
        speed = 1.0 / np.array([r.seconds for r in group])  # v0 * (1 - drain * x)
        slope, v0 = np.polyfit(x, speed, 1)
        drains.append(-slope / v0)
        weights.append(float(np.sum((x - x.mean()) ** 2)))
    if not drains:
        return default
    return min(0.01, max(0.0, float(np.average(drains, weights=weights))))


def _fit_rates(model: TimingModel, j: int, runs: list[Traverse]) -> JointTiming:
    old = model.joints[j]
    rates = list(old.rates)
    for direction, first in ((1, 0), (-1, 2)):
        mine = [r for r in runs if r.direction == direction]
        if mine:
            a, b = _design(model, j, mine)
            rates[first : first + 2] = _solve_pair(a, b, (old.rates[first], old.rates[first + 1]))
    return JointTiming((rates[0], rates[1], rates[2], rates[3]), old.gravity, old.overshoot)


def _design(model: TimingModel, j: int, runs: list[Traverse]) -> tuple[F64, F64]:
    """Rows (lowering, lifting path length [rad]) and battery-corrected times [s]."""
    span = model.upper[j] - model.lower[j]
    rows, times = [], []
    for r in runs:
        slip = SLIP_SHARE * model.overshoot(j, r.direction)
        rows.append(_split(model, j, r, span - slip))
        times.append(r.seconds * model.battery(r.motor_s + r.seconds / 2))
    return np.array(rows), np.array(times)


def _solve_pair(a: F64, b: F64, prior: tuple[float, float]) -> list[float]:
    """(lowering, lifting) rates [rad/s] with ``a @ (1 / rates) = b``; where the runs
    cannot separate the two (one load side only), the prior's ratio is kept."""
    if np.linalg.matrix_rank(a, tol=1e-3 * float(np.abs(a).max())) == 2:
        inv, *_ = np.linalg.lstsq(a, b, rcond=None)
        if np.all(inv > 0):
            return [1.0 / float(inv[0]), 1.0 / float(inv[1])]
    predicted = a @ (1.0 / np.array(prior))
    scale = float(predicted @ b) / float(predicted @ predicted)
    return [prior[0] / scale, prior[1] / scale]


def _split(model: TimingModel, j: int, r: Traverse, length: float) -> list[float]:
    """Path length [rad] the run spends lowering and lifting the load."""
    start = model.lower[j] if r.direction > 0 else model.upper[j]
    pose = np.array(r.pose, dtype=float)
    first = second = 0.0
    for k in range(max(1, math.ceil(length / STEP))):
        h = min(STEP, length - k * STEP)
        pose[j] = start + r.direction * (k * STEP + h / 2)
        is_first = (
            not model.joints[j].gravity
            or r.direction * load_side(pose, model.lengths, j, model.weights) > 0
        )
        first, second = (first + h, second) if is_first else (first, second + h)
    return [first, second]


def _fit_overshoot(model: TimingModel, j: int, runs: list[Traverse]) -> JointTiming:
    old = model.joints[j]
    found = {d: _solve_overshoot(model, j, [r for r in runs if r.direction == d]) for d in (1, -1)}
    up, down = found[1], found[-1]
    over = (old.overshoot[0] if up is None else up, old.overshoot[1] if down is None else down)
    return JointTiming(old.rates, old.gravity, over)


def _solve_overshoot(model: TimingModel, j: int, runs: list[Traverse]) -> float | None:
    """Mean over ``runs`` of the overshoot [rad] that makes pulses + rest span the limits."""
    if not runs:
        return None
    values = [_bisect(_error_of(model, j, r), -0.2, 0.2) for r in runs]
    return float(np.mean(values))


def _error_of(model: TimingModel, j: int, r: Traverse) -> Callable[[float], float]:
    return lambda e: _rest_error(model, j, r, e)


def _rest_error(model: TimingModel, j: int, r: Traverse, e: float) -> float:
    """Predicted minus measured rest time [s] if the overshoot were ``e`` [rad]."""
    trial = _with_joint(
        model, j, JointTiming(model.joints[j].rates, model.joints[j].gravity, (e, e))
    )
    pose = np.array(r.pose, dtype=float)
    pose[j] = model.lower[j] if r.direction > 0 else model.upper[j]
    used = r.motor_s
    for _ in range(r.pulses):
        pose[j] = trial.advance(pose, j, r.direction, r.pulse_s, used)
        used += r.pulse_s
    end = model.upper[j] if r.direction > 0 else model.lower[j]
    ahead = r.direction * (end - pose[j]) - SLIP_SHARE * e
    if ahead <= 0.0:
        return -r.seconds
    bare = _with_joint(
        model, j, JointTiming(model.joints[j].rates, model.joints[j].gravity, (0.0, 0.0))
    )
    return bare.duration(pose, j, pose[j] + r.direction * ahead, used) - r.seconds


def _bisect(f: Callable[[float], float], lo: float, hi: float) -> float:
    """Root of the decreasing function ``f`` on [lo, hi] (an end if it has none there)."""
    for _ in range(20):
        mid = (lo + hi) / 2
        if f(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def _with_joint(model: TimingModel, j: int, jt: JointTiming) -> TimingModel:
    joints = list(model.joints)
    joints[j] = jt
    return replace(model, joints=tuple(joints))
