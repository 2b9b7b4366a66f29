"""Play a Performance on the simulated XM430s' own motion model (``armkit.sim.xm430``'s
time-based profile, fed the ticks, totals and ramps ``drivers.dynamixel`` sends: the
shared timing rule of ``armkit.model._limits``, from where the driver starts a move)
and find where the stick tip really crosses each bar top."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from armkit.drivers._sent import SentProfile
from armkit.kinematics import fk
from armkit.model._limits import limits, move_time, ramp_time
from armkit.music import Performance
from armkit.sim.xm430 import Profile

F64 = NDArray[np.float64]
TICKS_PER_RAD = 4096 / (2 * math.pi)


@dataclass(frozen=True)
class Played:
    """Where the tip went below a strike's top: first crossing [s] and time below [s]."""

    time: float
    below: float


def _start(now: list[float], sent: SentProfile | None, t: float) -> F64:
    """Where ``DynamixelDriver`` starts the profile of a move [rad]: where its last
    profile has the servos unless they read more than its 30-tick tolerance away,
    then where they read."""
    read = (np.rint(now) - 2048) / TICKS_PER_RAD
    if sent is None:
        return read
    commanded = sent.where(t)
    near = np.max(np.abs(read - commanded)) * TICKS_PER_RAD <= 30
    return commanded if near else read


def joint_track(perf: Performance, times: F64, q0: F64) -> F64:
    """Joint angles [rad], shape (N, dof), of servos that run every move of ``perf``."""
    model = perf.model
    _, a_max = limits(model)
    servos = [Profile(2048 + q * TICKS_PER_RAD, 0.0, -1.0) for q in q0]
    segments: list[tuple[float, list[Profile]]] = [(-1.0, servos)]
    sent: SentProfile | None = None
    for move in perf.moves:
        now = [s.at(move.t)[0] for s in segments[-1][1]]
        start = _start(now, sent, move.t)
        goal = np.rint(2048 + move.q * TICKS_PER_RAD)
        end = (goal - 2048) / TICKS_PER_RAD  # the profile runs to the goal's tick
        seconds = move_time(model, start, end, speed=move.speed)
        total_ms = max(1, math.ceil(1000.0 * seconds - 1e-9))
        ramp_ms = min(round(1000.0 * ramp_time(seconds, end - start, a_max)), total_ms // 2)
        ramp, total = ramp_ms / 1000, total_ms / 1000
        q = np.asarray(move.q, dtype=np.float64)
        sent = SentProfile(start, q, end, goal.astype(np.int64), move.t, total)
        segments.append(
            (
                move.t,
                [Profile(p, g - p, move.t, ramp, total) for p, g in zip(now, goal, strict=True)],
            )
        )
    q = np.empty((len(times), len(q0)))
    starts = np.array([t for t, _ in segments])
    which = np.searchsorted(starts, times, side="right") - 1
    for k, (_, profiles) in enumerate(segments):
        rows = np.flatnonzero(which == k)
        for j, prof in enumerate(profiles):
            q[rows, j] = [prof.at(t)[0] for t in times[rows]]
    return (q - 2048) / TICKS_PER_RAD


def played(perf: Performance, q0: F64, step: float = 0.0001) -> list[Played | None]:
    """For each strike, the emulated tip's crossing of its top near the planned time."""
    out: list[Played | None] = []
    for strike in perf.strikes:
        times = np.arange(strike.time - 0.05, strike.time + 0.08, step)
        z = fk(perf.model, joint_track(perf, times, q0))[:, 2, 3] - strike.target.point[2]
        below = np.flatnonzero(z < 0)
        if below.size == 0:
            out.append(None)
            continue
        i = below[0]
        t = times[i - 1] + step * z[i - 1] / (z[i - 1] - z[i])
        out.append(Played(float(t), float(below.size * step)))
    return out
