"""The servos as the strike planner times them: how they move (the predictors) and
how their position loop lags what they are told.

A Dynamixel's loop is taken as a pure delay (the latency table's). A hobby servo's
is a first-order lag (time constant ``loop`` [s]): it builds up behind a ramp over a
few time constants, so a stroke that starts while the servo still lags the move
before it, or from rest, touches sooner than the full lag says. ``lagged_contact``
runs that lag over the commands the planner has made (exactly, sample by sample)
and finds where the head crosses the top.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ._predict import JointProfile, Predictor, Rebound

F64 = NDArray[np.float64]
STEP = 0.0005  # [s] the lag is run at this step
SETTLED = 6.0  # time constants after which a servo is taken to have caught up


@dataclass(frozen=True)
class Servos:
    """How the servos move: ``move`` for travel and strokes, ``rebound`` for rebounds,
    and ``loop``: their position loop's first-order time constant [s] (0: a pure delay)."""

    move: Predictor
    rebound: Rebound
    loop: float = 0.0


def lagged_contact(
    model: ArmModel, commands: Sequence[tuple[float, JointProfile]], top: float, after: float,
    tau: float,
) -> float | None:  # fmt: skip
    """When [s] the head, behind a first-order lag of ``tau`` [s], first goes below ``top``
    [m, base frame] after ``after`` [s]: ``commands`` are (send time [s], profile) in time
    order, each held at its end until the next; the lag starts caught up ``SETTLED``
    time constants before the last command but one. None if it never does."""
    begin = commands[max(0, len(commands) - 3)][0] - SETTLED * tau
    t0, last = commands[-1]
    times = np.arange(begin, t0 + last.duration + SETTLED * tau, STEP)
    setpoint = _setpoints(commands, times)
    decay = math.exp(-STEP / tau)
    y = np.empty_like(setpoint)
    y[0] = setpoint[0]
    mid = (setpoint[1:] + setpoint[:-1]) / 2.0  # the setpoint over each step, to O(STEP^2)
    for k in range(1, len(times)):
        y[k] = mid[k - 1] + (y[k - 1] - mid[k - 1]) * decay
    z = fk(model, y)[:, 2, 3] - top
    below = np.flatnonzero((z < 0.0) & (times > after))
    if below.size == 0 or below[0] == 0:
        return None
    k = int(below[0])
    return float(times[k - 1] + STEP * z[k - 1] / (z[k - 1] - z[k]))  # linear between samples


def _setpoints(commands: Sequence[tuple[float, JointProfile]], times: F64) -> F64:
    """The commanded joint angles [rad] at ``times`` [s], shape (N, dof)."""
    first = commands[0][1].sample(np.array([0.0]))[0][0]
    out = np.tile(first, (len(times), 1))
    for t0, profile in commands:
        on = times >= t0
        if np.any(on):
            local = np.minimum(times[on] - t0, profile.duration)
            out[on] = profile.sample(local)[0]
    return out
