"""Arm takes numbers for its numeric arguments, never text, and a pitch in -180..180 deg.

Was: ``move_to("200", 0, 50)`` and ``turn_by("waist", "20")`` moved (numpy read the
text as numbers) while ``grip("open")`` was refused, and ``move_to(200, 0, 50,
pitch=1000)`` moved (the kinematics wrapped 1000 deg). Now each is an InputError naming
the argument and its unit, and nothing is sent.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest

from armkit._arm_inputs import pitch_radians
from armkit._errors import ArmkitError, InputError
from armkit.arm import Arm
from armkit.model import load_model
from armkit.sim import World

OMX = load_model("openmanipulator_x")
CALLS: dict[str, tuple[Callable[[Arm], object], str]] = {
    "move_to x": (lambda a: a.move_to("200", 0, 50), r"x, y, z \[mm\] must be numbers, not text"),  # type: ignore[arg-type]
    "move_to z": (lambda a: a.move_to(200, 0, b"50"), r"x, y, z \[mm\]"),  # type: ignore[arg-type]
    "move_to pitch": (lambda a: a.move_to(200, 0, 50, "-90"), r"pitch \[deg\] must be a number, not text"),  # type: ignore[arg-type]
    "move_to speed": (lambda a: a.move_to(200, 0, 50, speed="0.5"), r"speed must be a number, not text"),  # type: ignore[arg-type]
    "move_to duration": (lambda a: a.move_to(200, 0, 50, duration="2"), r"duration \[s\]"),  # type: ignore[arg-type]
    "move_to timeout": (lambda a: a.move_to(200, 0, 50, timeout="1"), r"timeout \[s\]"),  # type: ignore[arg-type]
    "turn_by": (lambda a: a.turn_by("waist", "20"), r"waist \[deg\] must be a number, not text, got '20'"),  # type: ignore[arg-type]
    "turn_to": (lambda a: a.turn_to("elbow", "20"), r"elbow \[deg\] must be a number, not text"),  # type: ignore[arg-type]
    "move_joints dict": (lambda a: a.move_joints({"waist": "20"}), r"waist \[deg\]"),  # type: ignore[dict-item]
    "move_joints list": (lambda a: a.move_joints([0, "10", 0, 0]), r"joint angles \[deg\] must be numbers, not text"),  # type: ignore[list-item]
    "move_joints array": (lambda a: a.move_joints(np.array(["0", "10", "0", "0"])), r"joint angles \[deg\]"),
    "grip": (lambda a: a.grip("20"), r"grip width \[mm\] must be a number, not text, got '20'"),  # type: ignore[arg-type]
    "home speed": (lambda a: a.home(speed="1"), r"speed must be a number, not text"),  # type: ignore[arg-type]
    "approach": (lambda a: a.approach("170", 0, 50), r"x, y, z \[mm\]"),  # type: ignore[arg-type]
    "follow": (lambda a: a.follow([[170, 0, 50], ["180", 0, 50]]), r"points_mm \[mm\] must be numbers, not text"),
    "follow array": (lambda a: a.follow(np.array([["170", "0", "50"], ["180", "0", "50"]])), r"points_mm \[mm\]"),
    "follow objects": (lambda a: a.follow(np.array([[170, 0, 50], [180, "0", 50]], dtype=object)), r"points_mm \[mm\]"),
    "pitch 1000": (lambda a: a.move_to(200, 0, 50, pitch=1000), r"pitch \[deg\] must be -180\.\.180 \(the approach angle above the horizontal: 0 level, -90 pointing straight down\), got 1000"),
    "pitch -181": (lambda a: a.move_to(200, 0, 50, pitch=-181), r"pitch \[deg\] must be -180\.\.180.*got -181"),
    "pitch of a path": (lambda a: a.follow([[170, 0, 50], [180, 0, 50]], 270), r"pitch \[deg\] must be -180\.\.180"),
    "pitch of approach": (lambda a: a.approach(170, 0, 50, -450), r"pitch \[deg\] must be -180\.\.180"),
    "pitch of retreat": (lambda a: a.retreat(-1e6), r"pitch \[deg\] must be -180\.\.180"),
}  # fmt: skip


@pytest.mark.parametrize("name", list(CALLS))
def test_text_for_a_number_and_a_pitch_beyond_180_are_refused_and_nothing_moves(name: str) -> None:
    call, message = CALLS[name]
    with Arm(OMX, "sim") as arm:
        world = arm.world
        assert isinstance(world, World)
        start = arm.angles()
        with pytest.raises(InputError, match=message) as refused:
            call(arm)
        assert isinstance(refused.value, ArmkitError) and isinstance(refused.value, ValueError)
        assert world.now() == 0.0  # nothing was sent, nothing waited for
        assert len(world.recording().t) == 1
        assert arm.angles() == start


def test_numbers_of_every_kind_still_move_and_pitch_is_taken_up_to_180() -> None:
    with Arm(OMX, "sim") as arm:
        arm.move_to(np.float64(200), np.int64(0), 50, pitch=np.float32(-45))
        x, y, z, pitch = arm.position()
        assert math.dist((x, y, z), (200, 0, 50)) < 1.0 and pitch == pytest.approx(-45, abs=0.5)
        arm.move_to(170, 0, 60, -90, speed=np.float64(0.5), duration=2)
        arm.turn_by("waist", np.int32(10))
        assert arm.angles()["waist"] == pytest.approx(10, abs=0.5)
    for deg in (-180, 180, -180.0, 180.0, 0):
        assert pitch_radians(deg) == pytest.approx(math.radians(deg))
    assert pitch_radians(None) is None
