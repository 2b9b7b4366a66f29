"""002's search planned from a Start (what ``armkit check`` plans a search with): the
same scan algorithm as the run, its readings predicted from the scene; nothing moves."""

from __future__ import annotations

import pytest

from armkit import Arm, tasks
from armkit.arm import Start
from armkit.scene import load_scene


@pytest.mark.parametrize("name", ["lynx6", "openmanipulator_x"])
def test_the_planned_search_scans_as_the_run_does_and_finds_the_object(name: str) -> None:
    scene = load_scene("search_002")
    with Arm(name) as arm:
        before = arm.read()
        plan = tasks.plan_search(arm.start(), scene)
        assert (arm.read() == before).all()  # planning moved nothing
        result = tasks.search(arm, scene)
    scans = [s.label for s in plan.steps if s.label.startswith("scan at")]
    assert scans == [f"scan at {a:.0f} deg" for a, _ in result.readings]
    assert [s.label for s in plan.steps[-2:]] == ["drop it in bin", "home"]
    assert plan.end.held is None and plan.seconds > 0.0


def test_a_search_finding_nothing_plans_the_scan_and_home() -> None:
    model_scene = load_scene("search_002")
    empty = model_scene.without_cube(model_scene.cubes[0].name)
    arm = Arm("lynx6")
    plan = tasks.plan_search(arm.start(), empty, start=40.0, stop=60.0)
    arm.close()
    assert [s.label for s in plan.steps][-1] == "home"
    assert not any(s.grip is not None and s.label.startswith("close") for s in plan.steps)
    with pytest.raises(ValueError, match=r"0\.\.180 deg"):
        tasks.plan_search(Start(arm.model, arm.model.home), empty, start=200.0)


def test_the_planned_reach_comes_as_near_and_shakes_as_the_run_does() -> None:
    scene = load_scene("reach_003")
    with Arm("lynx6") as arm:
        plan = tasks.plan_reach(arm.start(), scene, shakes=2)
        result = tasks.reach(arm, scene, shakes=2)
    labels = [s.label for s in plan.steps]
    assert result.found and sum(x.startswith("approach step") for x in labels) == result.steps
    assert sum(x.startswith("shake") for x in labels) == 3 * 2 and labels[-1] == "home"
