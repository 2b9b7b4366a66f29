"""One unit system per public face (issue 26): every job function a person calls takes
millimetres and degrees, as ``Arm`` does, and its docstring says so; the kinematics
core below stays SI."""

from __future__ import annotations

import inspect
import re
from collections.abc import Callable

import pytest

from armkit import drawing, music, tasks

JOBS: tuple[Callable[..., object], ...] = (
    tasks.pick, tasks.place, tasks.move_item, tasks.rotate_cube, tasks.stack,
    tasks.search, tasks.reach, tasks.plan_search, tasks.plan_reach,
    drawing.draw, music.play,
)  # fmt: skip


@pytest.mark.parametrize("job", JOBS, ids=lambda job: f"{job.__module__}.{job.__name__}")
def test_every_job_function_names_millimetres_and_degrees(job: Callable[..., object]) -> None:
    doc = inspect.getdoc(job) or ""
    assert re.search(r"\bmm\b|millimetre", doc), f"{job.__name__}: no millimetres in its doc"
    assert re.search(r"\bdeg\b|degree", doc), f"{job.__name__}: no degrees in its doc"


def test_no_job_default_is_in_metres_or_radians() -> None:
    # a length default under 1 (0.11 for 110 mm) or an angle default under 3.2 (pi) is
    # a value in SI at the public face
    for job in JOBS:
        for p in inspect.signature(job).parameters.values():
            if p.name in ("start", "stop", "step", "height", "near", "amplitude", "lift"):
                assert isinstance(p.default, int | float) and p.default >= 3.2, (job, p)


def test_the_draw_options_are_millimetres_and_degrees() -> None:
    options = drawing.DrawOptions()
    assert (options.pen_up, options.pitch, options.speed) == (10.0, -60.0, 30.0)
    with pytest.raises(ValueError, match=r"pitch must be -90\.\.0 deg"):
        drawing.DrawOptions(pitch=-100.0).check()
