"""A short move whose shortest time is the triangle's (it accelerates half the way and
brakes the other half) ramps half its time: ``ramp_time`` gave 0 when the rounding of
``shortest_time`` put the need a hair above total^2, and the Dynamixel driver then sent
a constant-speed profile that stopped dead (its arrival took 9 ms longer than forecast)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from armkit import Arm
from armkit.arm import plan_joints
from armkit.model import limits, load_model, move_time, ramp_time


@pytest.mark.parametrize("ticks", [[0, 38, -9, -29], [0, 40, -17, -23], [0, -5, 60, -56]])
def test_a_triangle_ramps_half_its_time(ticks: list[int]) -> None:
    model = load_model("openmanipulator_x")
    per_tick = 2.0 * math.pi / 4096.0
    q0, q1 = model.home, model.home + np.array(ticks) * per_tick
    total = move_time(model, q0, q1)
    _, amax = limits(model)
    assert ramp_time(total, q1 - q0, amax) == pytest.approx(total / 2.0, rel=1e-6)
    assert ramp_time(total * 0.9, q1 - q0, amax) == 0.0  # shorter than any ramp allows


def test_a_short_dynamixel_move_takes_its_forecast() -> None:
    with warnings.catch_warnings(), Arm("openmanipulator_x", "sim") as arm:
        warnings.simplefilter("ignore")
        for ticks in ([0, 38, -9, -29], [0, -38, 9, 29]):
            q = arm.read() + np.array(ticks) * 2.0 * math.pi / 4096.0
            plan = plan_joints(arm.start(), q)
            t0 = arm.clock.now()
            arm.run(plan)
            assert arm.clock.now() - t0 == pytest.approx(plan.seconds, abs=0.002)
