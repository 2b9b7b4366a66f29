"""The simulated OWI behaves like the real one: gravity, slip, coast, battery, limits."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from armkit.model import ArmModel
from armkit.sim import World, WorldClock
from armkit.sim.owi_physics import OwiPhysics, OwiUnit, random_unit

DEG = math.radians


def quiet(owi: ArmModel, **changes: object) -> OwiUnit:
    """A unit without slip, coast, drain or asymmetry unless asked for."""
    unit = random_unit(owi, 1)
    base = dict(slip=np.zeros(4), coast=np.zeros(4), drain=0.0, asym=np.zeros(4), jitter=0.0)
    return replace(unit, **{**base, **changes})  # type: ignore[arg-type]


def run(
    physics: OwiPhysics, clock: WorldClock, joint: int, direction: int, seconds: float
) -> float:
    start = physics.true_q()[joint]
    dirs = np.zeros(4)
    dirs[joint] = direction
    physics.command(dirs, 0, False)
    clock.sleep(seconds)
    physics.command(np.zeros(4), 0, False)
    return float(physics.true_q()[joint] - start)


def test_loaded_joint_is_faster_lowering_than_lifting(owi: ArmModel) -> None:
    clock = World().clock
    q0 = np.radians([0.0, 40.0, 30.0, 0.0])
    p = OwiPhysics(owi, quiet(owi), clock, 1, q0)
    down = run(p, clock, 1, 1, 1.0)
    p.q = q0.copy()
    up = -run(p, clock, 1, -1, 1.0)
    assert down > 1.3 * up


def test_base_has_no_gravity_and_slip_and_coast_add_travel(owi: ArmModel) -> None:
    clock = World().clock
    plain = OwiPhysics(owi, quiet(owi), clock, 1)
    slippy = OwiPhysics(
        owi, quiet(owi, slip=np.full(4, DEG(2)), coast=np.full(4, DEG(1))), clock, 1
    )
    a, b = run(plain, clock, 0, 1, 1.0), run(slippy, clock, 0, 1, 1.0)
    assert b - a == pytest.approx(DEG(3))
    assert run(plain, clock, 0, -1, 1.0) == pytest.approx(-a)


def test_battery_drains_with_motor_time(owi: ArmModel) -> None:
    clock = World().clock
    p = OwiPhysics(owi, quiet(owi, drain=2e-3), clock, 1, np.radians([-135.0, 0, 0, 0]))
    first = run(p, clock, 0, 1, 1.0)
    run(p, clock, 1, 1, 50.0)  # use the batteries
    p.q[0] = -DEG(135)
    assert run(p, clock, 0, 1, 1.0) < 0.95 * first


def test_joints_slip_at_their_limits(owi: ArmModel) -> None:
    clock = World().clock
    p = OwiPhysics(owi, quiet(owi), clock, 1)
    run(p, clock, 3, 1, 60.0)
    assert p.true_q()[3] == pytest.approx(DEG(60))
    p.command(np.array([0, 0, 0, 1.0]), 0, False)
    assert p.at_limit(3)


def test_units_differ_by_seed_and_repeat_with_it(owi: ArmModel) -> None:
    assert not np.allclose(random_unit(owi, 1).speed, random_unit(owi, 2).speed)
    assert np.array_equal(random_unit(owi, 3).speed, random_unit(owi, 3).speed)


def test_simulated_clock_never_waits() -> None:
    clock = World().clock
    clock.sleep(3600.0)
    clock.sleep(-5.0)
    assert clock.now() == 3600.0
