"""Play a Performance on the emulated XM430s' own motion model (the simulator's
time-based profile, fed the ticks and times ``drivers.dynamixel`` would send) and
find where the stick tip really crosses each bar top."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from armkit.drivers.dynamixel import profile_times, ramp_for
from armkit.kinematics import fk
from armkit.music import Performance
from armkit.sim._dxl_servo import Profile

F64 = NDArray[np.float64]
TICKS_PER_RAD = 4096 / (2 * math.pi)


@dataclass(frozen=True)
class Played:
    """Where the tip went below a strike's top: first crossing [s] and time below [s]."""

    time: float
    below: float


def joint_track(perf: Performance, times: F64, q0: F64) -> F64:
    """Joint angles [rad], shape (N, dof), of servos that run every move of ``perf``."""
    model = perf.model
    v_max = np.array([j.max_velocity for j in model.joints])
    a_max = np.array([j.max_acceleration for j in model.joints])
    servos = [Profile(2048 + q * TICKS_PER_RAD, 0.0, -1.0) for q in q0]
    segments: list[tuple[float, list[Profile]]] = [(-1.0, servos)]
    for move in perf.moves:
        now = [s.at(move.t)[0] for s in segments[-1][1]]
        read = (np.rint(now) - 2048) / TICKS_PER_RAD
        goal = np.rint(2048 + move.q * TICKS_PER_RAD)
        fastest, _ = profile_times((goal - 2048) / TICKS_PER_RAD - read, v_max * move.speed, a_max)
        total_ms = max(1, math.ceil(1000.0 * fastest))
        ramp_ms = round(
            1000 * ramp_for(total_ms / 1000, (goal - 2048) / TICKS_PER_RAD - read, a_max)
        )
        ramp, total = min(ramp_ms, total_ms / 2) / 1000, total_ms / 1000
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
