"""A path refused between two points far apart says so: two points 50 mm apart (the
waist turning 14 deg between them) were blamed on 'an elbow flip or a singularity'."""

from __future__ import annotations

import pytest

from armkit import Arm
from armkit.motion import PathError


def test_points_far_apart_are_named_with_the_fix() -> None:
    arm = Arm("openmanipulator_x")
    with pytest.raises(PathError) as info:
        arm.follow([(200, 0, 50), (200, 50, 50)], pitch=-90)
    text = str(info.value)
    assert "the points are 50.0 mm apart and the arm moves in joint space between them" in text
    assert text.endswith("add points in between (armkit.motion.line, e.g. every 5 mm)")
    assert info.value.reason == "discontinuous"
