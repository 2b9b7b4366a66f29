"""A plan's time is what running it takes: every driver forecasts its own moves and grips
(``Driver.forecast``), and on the simulator the forecast is the run (its time, and the
joints the driver reads after it)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from armkit import Arm, tasks
from armkit.scene import load_scene

ARMS = ("openmanipulator_x", "lynx6", "owi535")
TUNES = Path(__file__).parents[2] / "examples" / "music"


@pytest.mark.filterwarnings("ignore:the OWI-535's joint angles are an uncertain estimate")
@pytest.mark.parametrize("name", ARMS)
def test_a_joint_move_takes_its_forecast_and_ends_where_forecast(name: str) -> None:
    rng = np.random.default_rng(26)
    with Arm(name) as arm:
        lo, hi = arm.model.lower + 0.1, arm.model.upper - 0.1
        for k in range(6):
            goal = arm.read() if k == 3 else np.clip(arm.model.home + rng.uniform(-0.5, 0.5, arm.model.dof), lo, hi)  # fmt: skip
            plan = arm.plan_move_joints(np.degrees(goal).tolist(), speed=(None, 0.4)[k % 2])
            began = arm.clock.now()
            arm.run(plan)
            assert arm.clock.now() - began == pytest.approx(plan.seconds, rel=0.01, abs=2e-3)
            np.testing.assert_allclose(arm.read(), plan.end.q, atol=1e-9)


def test_a_grip_closing_on_a_cube_is_forecast_to_stop_on_it() -> None:
    scene = load_scene("board_001")
    with Arm("openmanipulator_x", scene=scene) as arm:
        plan = tasks.pick(arm, scene, "red", dry_run=True)
        times: list[float] = []
        run = tasks.run_plan
        run(arm, plan, lambda k, step: times.append(arm.clock.now()))
        times.append(arm.clock.now())
    k = next(i for i, s in enumerate(plan.steps) if s.label.startswith("close on"))
    closing = plan.steps[k]
    assert closing.seconds < plan.steps[k - 3].seconds + 1.0  # not the full close
    # the run waits for the arm to stand still around the grip: up to 10 ms each side
    assert times[k + 1] - times[k] == pytest.approx(closing.seconds, abs=0.025)


def test_a_piece_takes_its_plan_and_the_last_note_is_listened_to() -> None:
    from armkit import music

    scene = load_scene("xylophone")
    with Arm("openmanipulator_x", scene=scene) as arm:
        perf = music.prepare(arm, scene, TUNES / "frere_jacques.txt")
        plan = music.performance_plan(arm.start(), perf, scene)
        began = arm.clock.now()
        music.perform(arm, scene, perf)
        took = arm.clock.now() - began
    assert plan.steps[-1].label == "listen to the last note"
    assert took == pytest.approx(plan.seconds, abs=0.02)
