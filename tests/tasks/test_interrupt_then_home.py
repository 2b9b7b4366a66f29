"""Recover from any state (issue 28, item 1). Ctrl-C during a drawing left the simulated
OpenManipulator-X with its gripper's tool point 3.7-8.7 mm below the table (the pen's
holder is 10 mm shorter than the gripper), and then 'home', a lift and every joint move
were refused ("the gripper would be N mm into the table") with no way out said.

Every job is interrupted at random instants of the simulator's virtual clock (a
KeyboardInterrupt injected where the job waits on it, where Ctrl-C reaches a real run),
and 'home' must then succeed: a move that only takes the arm out of the table or an
object is allowed from a start already inside (scene.move_refusal), and home lifts the
gripper straight up first (Arm.lift_out). ``make test`` interrupts each job at 3
instants; ARMKIT_PROFILE=ci at 20."""

from __future__ import annotations

import os
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from armkit import Arm, drawing, music, tasks
from armkit.scene import load_scene
from armkit.sim import World

INSTANTS = 20 if os.environ.get("ARMKIT_PROFILE") == "ci" else 3
SQUARE = (
    '<svg xmlns="http://www.w3.org/2000/svg" width="30mm" height="30mm" viewBox="0 0 30 30">'
    '<rect x="0" y="0" width="30" height="30" fill="none" stroke="black"/></svg>'
)
TUNE = "tempo 120 mf\nC5 e D5 e E5 e F5 e G5 q E5 q C5 q\n"

Job = Callable[[Arm, Any, Path], object]
JOBS: dict[str, tuple[str, str, Job]] = {
    "pick": ("openmanipulator_x", "board_001", lambda a, s, d: tasks.pick(a, s, "red")),
    "move-item": (
        "openmanipulator_x", "board_001", lambda a, s, d: tasks.move_item(a, s, "red", "board[2,2]"),
    ),
    "rotate-cube": ("openmanipulator_x", "board_001", lambda a, s, d: tasks.rotate_cube(a, s, "green")),
    "stack": ("openmanipulator_x", "board_001", lambda a, s, d: tasks.stack(a, s, ["red", "green"])),
    "pick-place": (
        "openmanipulator_x", "board_001",
        lambda a, s, d: (tasks.pick(a, s, "red"), tasks.place(a, s, "red", "board[2,2]")),
    ),
    "search": ("lynx6", "search_002", lambda a, s, d: tasks.search(a, s)),
    "reach": ("lynx6", "reach_003", lambda a, s, d: tasks.reach(a, s)),
    "draw": ("openmanipulator_x", "drawing", lambda a, s, d: drawing.draw(a, s, d / "square.svg")),
    "play": ("openmanipulator_x", "xylophone", lambda a, s, d: music.play(a, s, d / "tune.txt")),
}  # fmt: skip


class Interrupted(Exception):
    """The injected interrupt did not reach the job (it ended first)."""


def _interrupt_at(world: World, at: float) -> Callable[[], None]:
    """Raise KeyboardInterrupt in whoever advances ``world`` past ``at`` [s] (simulated);
    returns the undo."""
    advance = world.advance

    def interrupting(seconds: float) -> None:
        now = world.now()
        if now + seconds >= at:
            advance(max(0.0, at - now))
            world.advance = advance  # type: ignore[method-assign]  # once, as one Ctrl-C
            raise KeyboardInterrupt
        advance(seconds)

    world.advance = interrupting  # type: ignore[method-assign]

    def undo() -> None:
        world.advance = advance  # type: ignore[method-assign]

    return undo


def _run(name: str, tmp_path: Path, at: float | None) -> tuple[float, bool]:
    """Run job ``name`` on a fresh simulated arm, interrupted at ``at`` [s] (None: not),
    then home; (the job's simulated duration, whether it was interrupted)."""
    arm_name, scene_name, job = JOBS[name]
    scene = load_scene(scene_name)
    world = World()
    with Arm(arm_name, "sim", world=world, scene=scene) as arm:
        t0 = world.now()
        undo = _interrupt_at(world, t0 + at) if at is not None else (lambda: None)
        interrupted = False
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                job(arm, scene, tmp_path)
        except KeyboardInterrupt:
            interrupted = True
        finally:
            undo()
        took = world.now() - t0
        arm.home()  # must always find its way out
        assert np.allclose(arm.driver.read(), arm.model.home, atol=np.radians(0.5))
    return took, interrupted


@pytest.fixture
def files(tmp_path: Path) -> Path:
    (tmp_path / "square.svg").write_text(SQUARE)
    (tmp_path / "tune.txt").write_text(TUNE)
    return tmp_path


@pytest.mark.parametrize("name", list(JOBS))
def test_every_job_interrupted_anywhere_then_home_succeeds(name: str, files: Path) -> None:
    whole, interrupted = _run(name, files, None)
    assert whole > 0.5 and not interrupted
    rng = np.random.default_rng(sorted(JOBS).index(name))  # fixed seeds
    cut = 0
    for at in rng.uniform(0.0, whole, INSTANTS):
        _, was = _run(name, files, float(at))
        cut += was
    assert cut == INSTANTS  # each instant fell inside the job


def test_a_move_that_only_takes_the_arm_out_is_allowed_and_one_deeper_is_not() -> None:
    from armkit.model import load_model
    from armkit.scene import is_inside, move_refusal

    model = load_model("openmanipulator_x")
    from armkit.kinematics import ik

    low = ik(model, (0.2, 0.0, -0.004), -np.pi / 2, model.home).q  # tool point 4 mm under
    up = ik(model, (0.2, 0.0, 0.03), -np.pi / 2, low).q
    deeper = ik(model, (0.2, 0.0, -0.008), -np.pi / 2, low).q
    aside = ik(model, (0.25, 0.0, -0.004), -np.pi / 2, low).q
    assert is_inside(model, low, None) is not None
    assert move_refusal(model, low, up[None], None) is None  # out: allowed
    refused = move_refusal(model, low, deeper[None], None)
    assert refused is not None and "goes deeper" in str(refused) and "straight up" in str(refused)
    assert move_refusal(model, low, aside[None], None) is not None  # along the table: not out


@pytest.mark.parametrize("name", ["draw", "play"])
def test_an_interrupted_job_leaves_its_tool_kept_with_the_joints(name: str, files: Path) -> None:
    """Interrupted half-way (the pen on the paper, the mallet over the bars), the tool is
    kept in the state file with the joints: the next arm on that file plans with its tip
    (the tool point is not under the table), goes home, and a drawing resumed with the pen
    in the gripper does not pick it up again but puts it back, lifting the pen straight
    off the paper first (no ink dragged from where it was cut short)."""
    arm_name, scene_name, job = JOBS[name]
    scene, state = load_scene(scene_name), files / "kept.json"
    whole, _ = _run(name, files, None)
    world = World()
    with Arm(arm_name, "sim", str(state), world=world, scene=scene) as arm:
        undo = _interrupt_at(world, world.now() + whole / 2)
        with pytest.raises(KeyboardInterrupt), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            job(arm, scene, files)
        undo()
        tool = arm.tool
        assert tool is not None and tool.name == ("pen" if name == "draw" else "mallet")
    with Arm(arm_name, "sim", str(state), scene=scene) as arm:
        assert arm.tool == tool and arm.start().tool == tool
        assert arm.position()[2] > -1.0  # [mm]: the tip kept, not the jaws' point under it
        if name == "draw":  # resumed where it was cut short, the pen on the paper
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                done = drawing.draw(arm, scene, files / "square.svg")
            grips = [s for s in done.segments if type(s).__name__ == "GripMove"]
            assert len(grips) == 1 and arm.tool is None  # only put back
            assert done.segments[0].label.endswith("pen up")  # straight off the paper first
            assert done.metrics is not None and done.metrics.hausdorff < 0.5e-3, done.metrics
        arm.home()
        assert arm.tool == (None if name == "draw" else tool)  # home lets nothing go
    if name == "draw":
        with Arm(arm_name, "sim", str(state), scene=scene) as arm:
            assert arm.tool is None
