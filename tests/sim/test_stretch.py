"""A stretch of simulation steps stepped at once (``World._stretch``: the servos' setpoints
evaluated for the whole stretch, then the same 1 kHz recursion) gives the truth, the
recording and the pen's trace of stepping every step one by one, to the bit; so do its
parts: a profile evaluated at many times (``Profile.positions``) and a mount's table
(``Mount.to_si_many``) equal their scalar forms."""

from __future__ import annotations

import numpy as np
import pytest

from armkit import Arm
from armkit.model import load_model
from armkit.sim import World
from armkit.sim import _world as world_module
from armkit.sim._mount import Mount
from armkit.sim._xm430_profile import Profile

OMX = load_model("openmanipulator_x")


def test_a_profile_at_many_times_is_its_value_at_each() -> None:
    rng = np.random.default_rng(7)
    for k in range(2000):
        total = 0.0 if k % 7 == 0 else rng.uniform(0.0, 2.0)
        ramp = 0.0 if k % 5 == 0 else min(rng.uniform(0.0, 1.0), total / 2)
        p = Profile(rng.uniform(0, 4000), rng.uniform(-2000, 2000), rng.uniform(0, 5), ramp, total)
        edges = [p.t0, p.t0 + ramp, p.t0 + total - ramp, p.t0 + total, p.t0 - 1.0]
        times = np.concatenate([np.sort(rng.uniform(0.0, 8.0, 40)), edges])
        expected = np.array([p.at(t)[0] for t in times.tolist()])
        assert np.array_equal(p.positions(times), expected)


@pytest.mark.parametrize(
    ("units", "values"),
    [
        ((0.0, 4095.0), (-np.pi, np.pi)),  # a Dynamixel joint
        ((2483.0, 1613.0), (0.0, 0.075)),  # a gripper whose ticks fall as it opens
        ((500.0, 1000.0, 2000.0, 2500.0), (-1.6, -0.7, 0.8, 1.5)),  # a pulse table
        ((1000.0, 1000.0), (0.02, 0.02)),  # a degenerate gripper that never opens
    ],
)
def test_a_mount_on_many_units_is_its_value_at_each(
    units: tuple[float, ...], values: tuple[float, ...]
) -> None:
    mount = Mount(1, 0, units, values)
    x = np.random.default_rng(3).uniform(min(units) - 500, max(units) + 500, 500)
    x = np.concatenate([x, np.array(units)])
    assert np.array_equal(mount.to_si_many(x), np.array([mount.to_si(u) for u in x.tolist()]))


class EveryStep:
    """An observer that takes stretches; counts them."""

    def __init__(self) -> None:
        self.stretches = 0

    def on_step(self, world: World, t: float) -> None:
        pass

    def on_steps(self, world: World, times: np.ndarray) -> None:
        self.stretches += 1


def _session(one_by_one: bool, monkeypatch: pytest.MonkeyPatch) -> tuple[object, ...]:
    """Moves, a grip, a streamed path and a wait on the simulated OpenManipulator-X."""
    if one_by_one:
        monkeypatch.setattr(world_module, "MIN_STRETCH", 10**9)
    world, observer = World(record_s=60.0), EveryStep()
    with Arm(OMX, "sim", world=world) as arm:
        world.attach(observer)
        arm.move_joints([30, -40, 20, 10])
        arm.grip(20)
        arm.move_to(200, 50, 120)
        line = np.column_stack([np.full(40, 220.0), np.linspace(-60, 60, 40), np.full(40, 90.0)])
        arm.follow(line)
        arm.move_joints([-20, 10, 15, -30], duration=1.3, wait=False)
        world.advance(2.0)
        rec, sim = world.recording(), world.arm()
        result = (world.now(), sim.q(), sim.grip(), rec.t, rec.q, sim.at_rest())
    monkeypatch.undo()
    return (*result, observer.stretches)


def test_stretches_record_what_stepping_one_by_one_records(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    *stretched, n_stretched = _session(False, monkeypatch)
    *stepped, n_stepped = _session(True, monkeypatch)
    assert n_stepped == 0 and n_stretched > 10  # the first really took stretches
    for a, b in zip(stretched, stepped, strict=True):
        assert np.array_equal(a, b)  # type: ignore[arg-type]
