"""The timing model: 000's constant rate, gravity, overshoot, battery; and its fit."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from armkit.drivers.timed import JointTiming, TimingModel, constant_rate, default_timing
from armkit.drivers.timed._fit import Traverse, fit_drain, fit_timing
from armkit.drivers.timed._timing import load_side
from armkit.model import ArmModel

DEG = math.radians


def test_constant_rate_is_000s_formula(owi: ArmModel) -> None:
    tm = constant_rate(owi)
    q = np.zeros(4)
    # 000: shoulder 200 deg in 13.0 s -> 30 deg takes 30 / (200 / 13) s
    assert tm.duration(q, 1, DEG(30)) == pytest.approx(30 / (200 / 13.0), rel=1e-9)
    assert tm.duration(q, 0, DEG(-45)) == pytest.approx(45 / (270 / 15.3), rel=1e-9)


def test_duration_and_advance_are_inverse(owi: ArmModel) -> None:
    tm = default_timing(owi)
    q = np.radians([10.0, 30.0, 60.0, -20.0])
    for j, target in ((0, 70.0), (1, -40.0), (2, 120.0), (3, 35.0)):
        t = tm.duration(q, j, DEG(target), motor_s=300.0)
        d = 1 if DEG(target) > q[j] else -1
        assert tm.advance(q, j, d, t, motor_s=300.0) == pytest.approx(DEG(target), abs=1e-9)


def test_gravity_lowering_is_faster_than_lifting(owi: ArmModel) -> None:
    tm = default_timing(owi)
    leaning = np.radians([0.0, 40.0, 40.0, 10.0])  # load hangs forward
    down = tm.duration(leaning, 1, DEG(60))
    up = tm.duration(leaning, 1, DEG(20))
    assert down < up
    assert load_side(leaning, tm.lengths, 1) > 0 and load_side(-leaning, tm.lengths, 1) < 0


def test_overshoot_shortens_the_powered_time(owi: ArmModel) -> None:
    tm = constant_rate(owi)
    with_slip = replace(
        tm, joints=(JointTiming(tm.joints[0].rates, False, (DEG(3), DEG(3))), *tm.joints[1:])
    )
    q = np.zeros(4)
    rate = tm.joints[0].rates[0]
    assert with_slip.duration(q, 0, DEG(30)) == pytest.approx(DEG(27) / rate)
    assert with_slip.duration(q, 0, DEG(2)) == 0.0  # the overshoot alone covers it


def test_battery_slows_the_motors(owi: ArmModel) -> None:
    tm = replace(constant_rate(owi), drain=1e-4)
    q = np.zeros(4)
    assert tm.duration(q, 0, DEG(30), motor_s=1000.0) == pytest.approx(
        tm.duration(q, 0, DEG(30)) / 0.9
    )


def synthetic_runs(truth: TimingModel, owi: ArmModel) -> list[Traverse]:
    """Traverses timed exactly by ``truth`` (limit to limit, and pulses then the rest)."""
    poses = {
        1: [(0, 0, 90, 60), (0, 0, -90, -60)],
        2: [(0, -90, 0, 0), (0, 110, 0, 0)],
        3: [(0, -90, 150, 0), (0, -90, 0, 0)],
    }
    runs, used = [], 0.0
    for j in (1, 2, 3):
        for pose in poses[j]:
            for _ in range(2):
                for d in (1, -1):
                    q = np.radians(np.array(pose, dtype=float))
                    q[j] = truth.lower[j] if d > 0 else truth.upper[j]
                    t = truth.duration(q, j, truth.upper[j] if d > 0 else truth.lower[j], used)
                    runs.append(Traverse(j, d, t, tuple(q), used))
                    used += t
    return runs


def test_fit_recovers_a_known_model(owi: ArmModel) -> None:
    base = default_timing(owi)
    rates = {1: (0.33, 0.18, 0.31, 0.17), 2: (0.29, 0.2, 0.28, 0.19), 3: (0.3, 0.25, 0.31, 0.26)}
    joints = tuple(
        JointTiming(rates.get(j, jt.rates), jt.gravity, (0.0, 0.0))
        for j, jt in enumerate(base.joints)
    )
    truth = replace(base, joints=joints, drain=5e-5)
    start = replace(base, joints=tuple(replace(jt, overshoot=(0.0, 0.0)) for jt in base.joints))
    fitted = fit_timing(start, synthetic_runs(truth, owi))
    assert fitted.drain == pytest.approx(5e-5, rel=0.05)
    for j in (1, 2, 3):
        assert fitted.joints[j].rates == pytest.approx(rates[j], rel=0.03)


def test_drain_needs_repeated_runs(owi: ArmModel) -> None:
    assert fit_drain([Traverse(0, 1, 15.0, (0.0,) * 4, 0.0)], 1e-5) == 1e-5
