"""A real-time job that falls behind says so (issue 28): with the machine busy, a
'real-time' job (--view) ran 4.6 times slower than real time and nothing said it. The
real-time World measures its stepping against the time it covers (World.slowdown) and
the CLI warns once the job is done."""

from __future__ import annotations

import time

import pytest

from armkit.cli._watch import SlowdownWarning, say_slowdown
from armkit.sim import World


class Busy:
    """An observer as slow as a busy machine makes the world: 3 ms per 1 ms step."""

    def on_step(self, world: World, t: float) -> None:
        time.sleep(0.003)


def test_a_world_that_cannot_keep_pace_is_said_to() -> None:
    world = World(realtime=True)
    try:
        world.attach(Busy())
        world.advance(0.15)
        assert world.slowdown() >= 2.0  # stepping took at least twice the time it covered
        with pytest.warns(SlowdownWarning, match=r"ran up to \d+\.\dx slower than real time"):
            say_slowdown(world)
    finally:
        world.close()


def test_a_world_that_keeps_pace_says_nothing() -> None:
    virtual = World()
    virtual.attach(Busy())
    virtual.advance(0.01)
    assert virtual.slowdown() == 1.0  # virtual time has no pace to keep
    world = World(realtime=True)
    try:
        world.advance(0.05)  # nothing to step: it keeps pace
        assert world.slowdown() == 1.0
        say_slowdown(world)  # no warning (pytest turns an unexpected one into an error)
    finally:
        world.close()
