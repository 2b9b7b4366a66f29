"""A still world is not stepped 1000 times a simulated second: a long wait on a resting
arm advances the virtual clock at once, with the same truth and recording as stepping."""

from __future__ import annotations

import numpy as np
import pytest

from armkit import Arm
from armkit.model import load_model
from armkit.script import Source, run_source
from armkit.sim import World

OMX = load_model("openmanipulator_x")


class Counter:
    """An observer that must see every step (it has no ``may_skip``)."""

    def __init__(self) -> None:
        self.steps = 0

    def on_step(self, world: World, t: float) -> None:
        self.steps += 1


class Skippable(Counter):
    def may_skip(self) -> bool:
        return True


def test_a_ten_minute_wait_in_a_script_advances_the_virtual_clock() -> None:
    with Arm(OMX, "sim") as arm:
        assert arm.world is not None
        counter = Skippable()
        arm.world.attach(counter)
        t0 = arm.clock.now()
        run_source(arm, Source("wait.arm", "home\nwait 600\n"))
        assert arm.clock.now() - t0 == pytest.approx(600.0, abs=0.01)
        assert counter.steps < 600_000 // 100  # skipped: far fewer than 1 kHz x 600 s
        rec = arm.world.recording()
        assert rec.t[-1] == pytest.approx(arm.clock.now(), abs=0.001)
        assert np.allclose(np.diff(rec.t), 0.001, atol=1e-6)
        assert np.allclose(rec.q, rec.q[-1])  # the last 120 s: at rest


def test_skipping_keeps_the_truth_and_the_recording_of_stepping() -> None:
    """One arm moves then rests; a world whose observer forbids skipping steps it all."""
    results = []
    for observer in (Counter(), Skippable()):
        world = World(record_s=5.0)
        with Arm(OMX, "sim", world=world) as arm:
            world.attach(observer)
            arm.move_joints([30, -40, 20, 10], wait=False)
            world.advance(20.0)
            rec = world.recording()
            results.append((world.now(), world.arm().q(), rec.t, rec.q, observer.steps))
    (t_a, q_a, rt_a, rq_a, n_a), (t_b, q_b, rt_b, rq_b, n_b) = results
    assert n_a == 20_000 and n_b < n_a  # the first is stepped every 1 ms
    assert t_a == t_b == pytest.approx(20.0)
    assert np.array_equal(q_a, q_b)
    assert rt_a.shape == rt_b.shape == (5000,)
    assert np.allclose(rt_a, rt_b, atol=1e-9) and np.array_equal(rq_a, rq_b)


def test_a_moving_arm_is_never_skipped() -> None:
    with Arm(OMX, "sim") as arm:
        assert arm.world is not None
        counter = Skippable()
        arm.world.attach(counter)
        arm.move_joints([60, 0, 0, 0], duration=3.0, wait=False)
        arm.world.advance(2.0)
        assert counter.steps == 2000
        assert not arm.world.arm().at_rest()


def test_the_owi_rests_through_a_long_wait() -> None:
    with Arm("owi535", "sim") as arm:
        q0 = arm.world.arm().q() if arm.world is not None else None
        run_source(arm, Source("owi.arm", "wait 3600\n"))
        assert arm.clock.now() == pytest.approx(3600.0, abs=0.01)
        assert arm.world is not None and np.array_equal(arm.world.arm().q(), q0)


@pytest.mark.parametrize(("capacity", "first", "held"), [(10, 3, 4), (10, 3, 9), (10, 12, 5), (10, 0, 25), (5000, 4095, 3)])  # fmt: skip
def test_a_held_run_of_samples_is_recorded_as_added_one_by_one(
    capacity: int, first: int, held: int
) -> None:
    from armkit.sim._recording import Recorder

    one, many = Recorder(("a", "b"), capacity), Recorder(("a", "b"), capacity)
    for k in range(first):
        for r in (one, many):
            r.add(k * 0.001, np.array([k, -k], dtype=float))
    q = np.array([7.0, 8.0])
    for k in range(first, first + held):
        one.add(k * 0.001, q)
    many.hold(first * 0.001, 0.001, held, q)
    a, b = one.recording(), many.recording()
    assert np.allclose(a.t, b.t) and np.array_equal(a.q, b.q)
