"""One unit system per public face (issue 26): every job function a person calls takes
millimetres and degrees, as ``Arm`` does, and its docstring says so; the kinematics
core below stays SI."""

from __future__ import annotations

import inspect
import re
from collections.abc import Callable

import pytest

from armkit import drawing, music, tasks
from armkit.jobs import CLI_JOBS
from armkit.jobs import JOBS as SPECS

PACKAGES = (tasks, drawing, music)
# what a job plans or does: a plan, a job planned whole, or what it did
RESULTS = re.compile(r"\b(Plan|DrawJob|Performance|Played|SearchResult|ReachResult)\b")


def _public_functions() -> list[Callable[..., object]]:
    return [
        f
        for package in PACKAGES
        for name, f in sorted(vars(package).items())
        if not name.startswith("_") and inspect.isfunction(f)
    ]


def job_functions() -> list[Callable[..., object]]:
    """Every public job function: a function of ``tasks``, ``drawing`` or ``music`` that
    takes an arm (an ``Arm`` or a ``Start``) and plans or does a job on it, and every job
    function of the job table (the CLI's commands and the script's statements)."""
    found = []
    for f in _public_functions():
        params = list(inspect.signature(f).parameters.values())
        takes_arm = bool(params) and re.search(r"\b(Arm|Start)\b", str(params[0].annotation))
        if takes_arm and RESULTS.search(str(inspect.signature(f).return_annotation)):
            found.append(f)
    return found


def _by_name(name: str) -> Callable[..., object]:
    """The function a job spec's ``call`` runs (it imports it by name when the job runs)."""
    found = [getattr(p, name) for p in PACKAGES if inspect.isfunction(getattr(p, name, None))]
    assert len(found) == 1, f"job {name!r}: found in {len(found)} job packages"
    return found[0]


SPEC_JOBS = [_by_name(spec.call.__name__) for spec in (*SPECS.values(), *CLI_JOBS.values())]
JOBS: tuple[Callable[..., object], ...] = tuple(dict.fromkeys([*job_functions(), *SPEC_JOBS]))


def test_the_walk_finds_the_jobs_of_every_package() -> None:
    expected = {
        tasks.pick, tasks.place, tasks.move_item, tasks.rotate_cube, tasks.stack,
        tasks.search, tasks.reach, tasks.plan_search, tasks.plan_reach,
        drawing.draw, drawing.plan_draw, drawing.run_job,
        music.play, music.prepare, music.plan_play, music.performance_plan, music.perform,
    }  # fmt: skip
    assert expected <= set(JOBS) and set(SPEC_JOBS) <= set(JOBS)


@pytest.mark.parametrize("job", JOBS, ids=lambda job: f"{job.__module__}.{job.__name__}")
def test_every_job_function_names_millimetres_and_degrees(job: Callable[..., object]) -> None:
    doc = inspect.getdoc(job) or ""
    assert re.search(r"\bmm\b|millimetre", doc), f"{job.__name__}: no millimetres in its doc"
    assert re.search(r"\bdeg\b|degree", doc), f"{job.__name__}: no degrees in its doc"


@pytest.mark.parametrize("job", JOBS, ids=lambda job: f"{job.__module__}.{job.__name__}")
def test_no_job_function_takes_metres_or_radians(job: Callable[..., object]) -> None:
    # a job's docstring names the unit of each quantity it takes: never SI at this face
    doc = inspect.getdoc(job) or ""
    assert not re.search(r"\[(m|rad|m/s|rad/s)\]", doc), f"{job.__name__}: [m] or [rad]"
    assert not re.search(r"\b(metres|radians)\b", doc), f"{job.__name__}: metres or radians"


def test_no_job_default_is_in_metres_or_radians() -> None:
    # a length default under 1 (0.11 for 110 mm) or an angle default under 3.2 (pi) is
    # a value in SI at the public face
    for job in JOBS:
        for p in inspect.signature(job).parameters.values():
            quantity = p.name in ("start", "stop", "step", "height", "near", "amplitude", "lift")
            if quantity and p.default is not p.empty:
                assert isinstance(p.default, int | float) and p.default >= 3.2, (job, p)


def test_the_draw_options_are_millimetres_and_degrees() -> None:
    options = drawing.DrawOptions()
    assert (options.pen_up, options.pitch, options.speed) == (10.0, -60.0, 30.0)
    with pytest.raises(ValueError, match=r"pitch must be -90\.\.0 deg"):
        drawing.DrawOptions(pitch=-100.0).check()
