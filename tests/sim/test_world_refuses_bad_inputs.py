"""The simulation world refuses what it cannot use, as InputErrors, changing nothing.

Was: ``World().attach(None)`` was accepted and the next step raised AttributeError;
``World(rate_hz=0)`` and ``World(pace=0)`` raised a plain ValueError (not an
ArmkitError); ``advance(-1)``, ``advance(nan)`` and ``grip_stop(-1)`` were accepted;
``recording().write_csv("/nonexistent/x.csv")`` raised numpy's FileNotFoundError.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import pytest

from armkit import Arm, ArmkitError, InputError
from armkit.sim import World


class Counter:
    def __init__(self) -> None:
        self.steps = 0

    def on_step(self, world: World, t: float) -> None:
        self.steps += 1


@pytest.mark.parametrize(
    "observer, got",
    [
        (None, "got None"),
        (print, "got a builtin_function_or_method"),
        ("on_step", "got 'on_step'"),
        (Counter, "got the class Counter \\(attach an instance of it\\)"),
    ],
)
def test_attach_refuses_what_is_not_an_observer_and_attaches_nothing(
    observer: object, got: str
) -> None:
    world = World()
    with Arm("openmanipulator_x", "sim", world=world) as arm:
        with pytest.raises(InputError, match=r"an observer must be an object with a method "
                           r"on_step\(world, t\).*" + got):  # fmt: skip
            world.attach(observer)  # type: ignore[arg-type]
        arm.move_joints({"waist": 10})  # was: AttributeError on the next step
        counter = Counter()
        detach = world.attach(counter)
        world.advance(0.01)
        detach()
        assert counter.steps == 10


@pytest.mark.parametrize(
    "options, message",
    [
        ({"rate_hz": 0}, r"rate_hz must be 1\.\.100000 simulation steps per simulated second"),
        ({"rate_hz": math.nan}, r"rate_hz must be 1\.\.100000.*got nan"),
        ({"rate_hz": "1000"}, r"rate_hz must be 1\.\.100000.*got '1000'"),
        ({"rate_hz": True}, r"rate_hz must be 1\.\.100000.*got True"),
        ({"pace": 0}, r"pace must be a number > 0 of simulated seconds per wall second"),
        ({"pace": math.inf}, r"pace must be a number > 0"),
        ({"record_s": -1}, r"record_s must be a number > 0 of seconds"),
        ({"record_s": None}, r"record_s must be a number > 0.*got None"),
    ],
)
def test_world_options_out_of_range_are_input_errors(
    options: dict[str, object], message: str
) -> None:
    with pytest.raises(InputError, match=message) as refused:
        World(**options)  # type: ignore[arg-type]
    assert isinstance(refused.value, ArmkitError) and isinstance(refused.value, ValueError)


@pytest.mark.parametrize("seconds", [-1, -1e-9, math.nan, math.inf, -math.inf, "1", None, True])
def test_advance_refuses_negative_and_non_finite_seconds_and_time_stays(seconds: object) -> None:
    world = World()
    with Arm("openmanipulator_x", "sim", world=world):
        world.advance(0.25)
        samples = len(world.recording().t)
        with pytest.raises(InputError, match="advance takes a finite number of seconds >= 0"):
            world.advance(seconds)  # type: ignore[arg-type]
        assert world.now() == 0.25 and len(world.recording().t) == samples
        world.advance(0)  # nothing, allowed
        world.advance(1)  # an int is a number of seconds
        assert world.now() == pytest.approx(1.25)


def test_clock_sleep_keeps_the_clock_contract_a_past_deadline_is_nothing() -> None:
    world = World()
    world.clock.sleep(-1.0)
    world.clock.sleep(0)
    assert world.now() == 0.0
    with pytest.raises(InputError, match="advance takes a finite number"):
        world.clock.sleep(math.inf)  # was: run to infinity
    with pytest.raises(InputError, match="advance takes a finite number"):
        world.clock.sleep(math.nan)
    assert world.now() == 0.0


@pytest.mark.parametrize("width", [-1, -0.001, math.nan, math.inf, "0.03", True])
def test_grip_stop_refuses_what_is_not_a_width(width: object) -> None:
    with Arm("lynx6", "sim") as arm:
        assert arm.world is not None
        truth = arm.world.arm()
        with pytest.raises(InputError, match=r"grip_stop takes the width of the object between "
                           r"the jaws, a finite number >= 0 \[m\]"):  # fmt: skip
            truth.grip_stop(width)  # type: ignore[arg-type]
        closed = arm.model.gripper.width_min
        arm.grip(closed * 1000.0)
        arm.world.advance(2.0)
        assert truth.grip() == pytest.approx(closed, abs=1e-4)  # closed freely: no stop set
        truth.grip_stop(0.03)
        truth.grip_stop(None)


def test_write_csv_checks_the_path_first_and_writes_nothing_there(tmp_path: Path) -> None:
    with Arm("lynx6", "sim") as arm:
        assert arm.world is not None
        arm.world.advance(0.01)
        rec = arm.world.recording()
    with pytest.raises(InputError, match=r"cannot write /nonexistent/x\.csv: the folder "
                       r"/nonexistent does not exist; create it first"):  # fmt: skip
        rec.write_csv("/nonexistent/x.csv")
    with pytest.raises(InputError, match="it is a directory"):
        rec.write_csv(tmp_path)
    out = tmp_path / "r.csv"
    out.write_text("old\n")
    assert rec.write_csv(str(out)) == len(rec.t) == 11
    lines = out.read_text().splitlines()
    assert lines[0].startswith("t_s,") and len(lines) == 12
    assert sorted(os.listdir(tmp_path)) == ["r.csv"]  # atomic: no temporary left beside it
