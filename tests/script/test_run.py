"""Running scripts on the simulated arm through the public Arm API."""

from __future__ import annotations

import inspect
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from script_arms import CountingDriver, counting_arm

import armkit.tasks
from armkit import Arm, DeviceError
from armkit.arm import Start
from armkit.script import (
    JOBS,
    JobParam,
    JobSpec,
    ScriptCheckError,
    ScriptRunError,
    Source,
    run_source,
)


def _run(arm: Arm, text: str, **options: Any) -> Any:
    return run_source(arm, Source("job.arm", text), **options)


def test_moves_reach_their_targets(arm: tuple[Arm, CountingDriver]) -> None:
    a, _ = arm
    _run(a, "pose above = xyz 180 0 80 pitch -90\nmove above\nline 180 0 40\ngrip 30mm\n")
    x, y, z, pitch = a.position()
    assert (x, y, z) == pytest.approx((180, 0, 40), abs=0.5)
    assert pitch == pytest.approx(-90, abs=0.5)
    _run(a, "joints 10 -30 20 10\nturn waist by 5\nturn elbow 0\n")
    assert list(a.angles().values()) == pytest.approx([15, -30, 0, 10], abs=0.1)


def test_a_failed_check_moves_nothing(arm: tuple[Arm, CountingDriver]) -> None:
    a, driver = arm
    before = a.driver.read()
    with pytest.raises(ScriptCheckError) as info:
        _run(a, "home\nmove xyz 180 0 80 pitch -90\nturn waist by 10\nmove xyz 900 0 0\n")
    assert "job.arm:4:1:" in str(info.value)
    assert driver.sent == 0
    assert np.array_equal(a.driver.read(), before)


def test_plan_time_matches_the_simulated_time(arm: tuple[Arm, CountingDriver]) -> None:
    a, _ = arm
    t0 = a.clock.now()
    result = _run(a, "move xyz 180 0 80 pitch -90\nmove xyz 150 100 60 pitch -60\nhome\nwait 1s\n")
    took = a.clock.now() - t0  # simulated seconds, not wall time
    assert took == pytest.approx(result.timetable.total, rel=0.1)


def test_plan_time_counts_a_line_s_move_onto_its_start(arm: tuple[Arm, CountingDriver]) -> None:
    """A line at another pitch than the arm's first turns the arm onto its start (as
    ``Arm.follow`` does); the plan counts that move (it was 0.75 s short of 7.36 s)."""
    a, _ = arm
    t0 = a.clock.now()
    text = "move xyz 180 0 80\nline xyz 180 80 80\nline xyz 120 -60 60\nhome\n"
    result = _run(a, text)
    assert a.clock.now() - t0 == pytest.approx(result.timetable.total, rel=0.03)


class _Failing(CountingDriver):
    def __init__(self, inner: Any, fail_at: int) -> None:
        super().__init__(inner)
        self.fail_at, self.stops = fail_at, 0

    def move(self, q: Any, **options: Any) -> None:
        if self.sent + 1 == self.fail_at:
            raise DeviceError("servo 3 reports an overload")
        super().move(q, **options)

    def stop(self) -> None:
        self.stops += 1
        super().stop()


def test_a_run_time_fault_names_the_line_and_the_iteration() -> None:
    a, plain = counting_arm()
    driver = _Failing(plain.inner, fail_at=5)  # the 5th move: 'move a' of iteration 3
    a.driver = driver  # type: ignore[assignment]
    text = "pose a = xyz 180 0 80 pitch -90\npose b = xyz 180 50 80 pitch -90\n"
    text += "repeat 5\n  move a\n  move b\nend\n"
    with pytest.raises(ScriptRunError) as info:
        _run(a, text)
    assert str(info.value) == (
        "job.arm:4:3: servo 3 reports an overload (repeat iteration 3 of 5 (line 3))"
    )
    assert info.value.loc.line == 4 and driver.stops >= 1


def test_the_whole_script_repeats(arm: tuple[Arm, CountingDriver]) -> None:
    a, _ = arm
    text = "define bump(d)\n  turn waist by d\nend\nbump 10\n"
    _run(a, text, repeat=3)
    # turn_by adds to the read-back angle, so the servos' settling error adds up a little
    assert a.angles()["waist"] == pytest.approx(30, abs=0.5)
    # run 16 goes past 180 deg (the read-back is within a tick of 30 + 10 per run)
    with pytest.raises(ScriptCheckError, match=r"job.arm:2:3: waist 1[89]\d\.\d\d deg") as info:
        _run(a, text, repeat=20)
    assert info.value.diagnostics[0].notes == (
        "in bump called at line 4",
        "run 16 of 20 (--repeat)",
    )


def test_a_job_runs_through_its_table_entry(
    arm: tuple[Arm, CountingDriver], monkeypatch: pytest.MonkeyPatch
) -> None:
    # check and run both plan the job with its table entry's function, from a Start (the
    # check's from its fold, the run's from the arm as it reads it), then run carries it out
    a, _ = arm
    calls: list[tuple[Any, ...]] = []
    real = armkit.tasks.move_item

    def move_item(arm_: Any, scene: Any, **kwargs: Any) -> object:
        # the arguments must be ones the real task takes (a fake taking **kwargs hid
        # 'pick(item=...)' while the real pick takes 'cube')
        inspect.signature(real).bind(arm_, scene, **kwargs)
        calls.append((arm_, scene, kwargs))
        return real(arm_, scene, **kwargs)

    monkeypatch.setattr(armkit.tasks, "move_item", move_item)
    text = "pose spot = xyz 150 0 30 pitch -90\nmove-item spot to xyz 150 50 30\nturn waist by 10\n"
    _run(a, text)
    (checked, _, _), (ran, scene, kwargs) = calls
    assert isinstance(ran, Start) and scene.name == "empty"  # no scene: the empty table
    assert np.allclose(ran.q, checked.q, atol=1e-3)  # where the check planned it from
    assert kwargs["item"] == pytest.approx([150.0, 0.0, 30.0])  # tasks take points in mm
    assert kwargs["to"] == pytest.approx([150.0, 50.0, 30.0])
    # carried out: the item put down at (150, 50) mm, then the waist 10 deg further
    assert a.angles()["waist"] == pytest.approx(math.degrees(math.atan2(50, 150)) + 10, abs=0.5)


def test_adding_a_job_is_one_entry(
    arm: tuple[Arm, CountingDriver], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    a, _ = arm
    got: dict[str, object] = {}
    spec = JobSpec(
        (JobParam("times", "count"), JobParam("height", "length", keyword="up", required=False),
         JobParam("song", "file", keyword="humming", required=False, choices=(".txt",))),
        lambda arm_, scene, **kw: got.update(kw), "wave the gripper",
    )  # fmt: skip
    monkeypatch.setitem(JOBS, "wave", spec)
    (tmp_path / "la.txt").write_text("la")
    _run(a, "wave 3 up 2cm humming la.txt\n", base_dir=tmp_path)
    assert got == {"times": 3, "height": pytest.approx(20.0), "song": tmp_path / "la.txt"}


def test_owi_timed_rotation_and_light() -> None:
    a, driver = counting_arm("owi535")
    try:
        before = a.angles()["shoulder"]
        _run(a, "light on\nrun shoulder forward 1.5s\nrun base left 500ms\nlight off\n")
        assert a.angles()["shoulder"] > before + 10
        assert a.angles()["base"] < 0
        assert driver.sent == 4
    finally:
        a.close()


OWI_PROGRAM = """\
run shoulder forward 1.5s
run elbow forward 1s
grip close
grip close
grip open
turn wrist by -20
turn base by 3
move xyz 200 0 150
home
"""


def test_owi_plan_time_is_the_timed_driver_s() -> None:
    """The check times an OWI script as its driver runs it (gravity, overshoot, battery,
    two-leg short turns, a gripper already closed), not at each joint's top speed."""
    a, _ = counting_arm("owi535")
    try:
        t0 = a.clock.now()
        result = _run(a, OWI_PROGRAM)
        took = a.clock.now() - t0  # simulated seconds, not wall time
        assert result.timetable.unknown == 0
        assert result.timetable.total == pytest.approx(took, rel=0.02)
    finally:
        a.close()


def test_grip_open_and_close_use_the_gripper_range(arm: tuple[Arm, CountingDriver]) -> None:
    a, _ = arm
    _run(a, "grip close\ngrip open\ngrip 1in\n")
    with pytest.raises(ScriptCheckError, match=r"job.arm:1:6: grip 76.2 mm is outside"):
        _run(a, "grip 3in\n")
    assert math.isfinite(a.position().z)
