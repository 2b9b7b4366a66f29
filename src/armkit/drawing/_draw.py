"""Running a planned drawing job on an arm, and the job's one call for scripts
and the CLI: ``draw(arm, scene, file, sheet=None, pen=None, ...)``."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from ..scene import HeldTool, Scene
from ._errors import DrawingError
from ._fit import Fit
from ._job import DrawJob, DrawOptions, plan_draw
from ._metrics import PenTrace, measure
from ._picture import check_picture_path
from ._picture import preview as draw_preview
from ._picture import result as draw_result
from ._segments_job import GripMove, PathMove
from ._tracer import PenTracer

if TYPE_CHECKING:
    from ..arm import Arm, Step
    from ..physics import MujocoPenTracer

DrawProgress = Callable[["DrawJob", int], None]  # (the job, strokes drawn so far)


def draw(
    arm: Arm,
    scene: Scene,
    file: str | Path,
    sheet: str | None = None,
    pen: str | None = None,
    *,
    options: DrawOptions | None = None,
    fit: Fit | bool | None = None,
    preview: str | Path | None = None,
    result: str | Path | None = None,
    dry_run: bool = False,
    progress: DrawProgress | None = None,
) -> DrawJob:
    """Draw the SVG or G-code ``file`` on ``sheet`` with ``pen`` (None: the scene's only one).

    Drawn at the file's real size, centred on the sheet (refused with its size if it
    does not fit); ``fit=True`` scales it to the sheet, a ``Fit`` places it exactly.
    Planned whole first (see ``DrawOptions``: the tolerance, margin, pen-up height and
    clearance in millimetres, the pen's pitch in degrees, its speed in mm/s);
    ``preview`` [.png/.svg/.pdf] draws the
    plan before moving; ``dry_run`` stops there. On a simulated arm the pen's trace
    is measured (``DrawJob.metrics``) and ``result`` pictures what it drew.
    ``progress(job, n)`` is called once planned (n = 0, before anything moves) and
    after each move (n: the strokes drawn so far).

    Raises:
        DrawingError: a bad file (naming line and column), sheet or pen.
        InputError: a picture path that cannot be written (before anything moves).
        UnreachableError: a move cannot be made (TaskError naming the step). Nothing moved.
    """
    for picture in (preview, result):
        if picture is not None:
            check_picture_path(picture)
    if result is not None and arm.world is None:
        raise DrawingError(
            "a result picture needs a simulated arm (what the pen drew is measured "
            "in the simulator); leave it out on real hardware",
            file=str(result),
        )
    job = plan_draw(arm, scene, file, sheet, pen, options=options, fit=fit)
    if progress is not None:
        progress(job, 0)
    if preview is not None:
        draw_preview(job.plan, preview)
    if dry_run:
        return job
    job = run_job(arm, job, progress)
    if result is not None and job.trace is not None:
        draw_result(job.plan, job.trace, job.sheet, result)
    return job


def run_job(arm: Arm, job: DrawJob, progress: DrawProgress | None = None) -> DrawJob:
    """Carry ``job`` out on ``arm`` (``Arm.run`` of its motion, as ``plan_draw`` planned
    it: ``DrawOptions`` in millimetres, degrees and mm/s); on a simulator, with its trace
    and metrics (``DrawingMetrics``); ``progress(job, n)`` after each move (n: the
    strokes drawn so far)."""
    world, sim = arm.world, arm.sim
    tracer = _tracer(arm, job, sim.name if sim else None)
    tracer.holding = job.options.held or job.motion.start.tool is not None
    if tracer.holding:
        arm.hold_tool(pen_held(job))
    detach = world.attach(tracer) if world is not None else None
    done = _Progress(job, tracer, arm, progress)
    try:
        arm.run(job.motion, say=done.before)
        done.after(len(job.segments))
    finally:
        if detach is not None:
            detach()
    trace = _trace(tracer)
    if trace is None or not trace.down.any():
        return job
    return replace(job, trace=trace, metrics=measure(job.plan, trace, job.sheet))


def _tracer(arm: Arm, job: DrawJob, name: str | None) -> PenTracer | MujocoPenTracer:
    """The pen's tracer: the tip's height over the paper, or MuJoCo's contacts."""
    if job.physics != "mujoco":
        return PenTracer(job.tip, job.sheet, job.T_world_base, name)
    from ..physics import MujocoPenTracer

    table = Scene("table", float(job.sheet.origin[2]), job.T_world_base)
    return MujocoPenTracer(arm.model, job.tip, job.sheet, table, job.pen.tip_offset, name)


def _trace(tracer: PenTracer | MujocoPenTracer) -> PenTrace | None:
    if isinstance(tracer, PenTracer):
        return tracer.trace()
    found = tracer.recorded()
    return None if found is None else PenTrace(*found)


def pen_held(job: DrawJob) -> HeldTool:
    """``job``'s pen as the arm holds it: its tip the tool point, the jaws on its holder."""
    return HeldTool(job.pen.name, job.tip.tool_length, job.pen.diameter)


class _Progress:
    """What the job does around each of its moves: the pen held or not (the tracer, the
    arm's held tool, so an interrupted job leaves it kept), the strokes counted for
    ``progress``."""

    def __init__(
        self,
        job: DrawJob,
        tracer: PenTracer | MujocoPenTracer,
        arm: Arm,
        progress: DrawProgress | None,
    ) -> None:
        self.job, self.tracer, self.arm, self.progress = job, tracer, arm, progress
        self.strokes = 0

    def before(self, k: int, step: Step) -> None:
        """Before move ``k`` (1-based): the one before it is done."""
        if k > 1:
            self.after(k - 1)
        seg = self.job.segments[k - 1]
        if isinstance(seg, GripMove):
            self.tracer.holding = self.tracer.holding and seg.holds
            self.arm.hold_tool(pen_held(self.job) if seg.holds else None)

    def after(self, k: int) -> None:
        """Move ``k`` (1-based) is done."""
        seg = self.job.segments[k - 1]
        if isinstance(seg, GripMove):
            self.tracer.holding = seg.holds
        elif isinstance(seg, PathMove):
            self.strokes += seg.draws
        if self.progress is not None:
            self.progress(self.job, self.strokes)
