"""The tasks' own inputs: an arm that is not one, a lift out of range, and a plan made
with ``dry_run`` then run with ``run_plan`` (the README's way) simulating its cubes."""

from __future__ import annotations

import pytest

from armkit import Arm, InputError, load_model, tasks
from armkit.scene import load_scene


def test_a_model_for_an_arm_is_refused_naming_what_to_give() -> None:
    # was AttributeError: 'ArmModel' object has no attribute 'world'
    scene = load_scene("board_001")
    with pytest.raises(InputError, match=r"stack: arm must be an armkit.Arm .*got an ArmModel"):
        tasks.stack(load_model("openmanipulator_x"), scene, ["red", "green"], dry_run=True)  # type: ignore[arg-type]


@pytest.mark.parametrize("lift", ["x", -10.0, 1e6, float("nan"), True])
def test_lift_is_0_to_500_mm(lift: object) -> None:
    # 'x' was a TypeError, -10 accepted, 1e6 said 'clearance must be 30..500 mm'
    arm, scene = Arm("openmanipulator_x"), load_scene("board_001")
    with pytest.raises(InputError, match=r"lift must be 0\.\.500 mm"):
        tasks.move_item(arm, scene, "red", (180.0, -100.0, 0.0), lift=lift, dry_run=True)  # type: ignore[arg-type]


def test_a_dry_run_plan_run_by_run_plan_moves_the_cubes_too() -> None:
    # run_plan moved the arm but attached no physics: green stayed in its socket for
    # the next task, though red sat on it
    arm, scene = Arm("openmanipulator_x"), load_scene("board_001")
    plan = tasks.stack(arm, scene, ["green", "red"], rotate_first=None, dry_run=True)
    tasks.run_plan(arm, plan)
    physics = tasks.attached(arm)
    assert physics is not None
    assert physics.scene.cube("red").position[2] == pytest.approx(0.028, abs=1e-3)
    with pytest.raises(tasks.TaskError, match="it is under red"):
        tasks.pick(arm, scene, "green", dry_run=True)


def test_a_socket_index_of_thousands_of_digits_is_refused_in_words() -> None:
    """Found by the script fuzzer: board[10...0, 1] with 4,403 digits reached the user as
    Python's 'Exceeds the limit (4300 digits) for integer string conversion'."""
    scene = load_scene("board_001")
    with pytest.raises(InputError, match=r"rows 0\.\.2, cols 0\.\.2; got a row or column of more"):
        tasks.resolve(scene, "board[" + "9" * 5000 + ", 1]")
    with pytest.raises(InputError, match=r"got \(999999, 1\)"):
        tasks.resolve(scene, "board[999999, 1]")
