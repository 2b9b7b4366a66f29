"""The drawing job (seed 001's third task): ``draw(arm, scene, file, sheet, pen)``.

Planned whole before anything moves: the file read and fitted onto the sheet,
cut to what the arm reaches with the pen (a note says what was cut), the pen
picked up from its stand (unless ``held``), every stroke and pen-up move solved
and checked for clearance, the pen put back. Then it runs and, on a simulated
arm, what the pen drew is measured from the World (``DrawJob.metrics``).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import is_number
from ..arm import Plan, Start, plan_steps
from ..model import ArmModel
from ..scene import Pen, Scene, Sheet
from ._errors import DrawingError, DrawingWarning
from ._fit import Fit, as_fit
from ._metrics import DrawingMetrics, PenTrace
from ._pen import pick_pen, put_pen, stand_of
from ._plan import DrawingPlan, plan_drawing
from ._reach import Run, nothing_reachable, reach_note, reachable_runs
from ._rig import Rig, plan_strokes
from ._segments_job import Segment, as_steps, count, end_q

if TYPE_CHECKING:
    from ..arm import Arm

F64 = NDArray[np.float64]
T = TypeVar("T", Sheet, Pen)


@dataclass(frozen=True)
class DrawOptions:
    """How a drawing is planned and drawn, in millimetres and degrees.

    Attributes:
        tolerance: the strokes stay this close to the file [mm] (default 0.1).
        margin: blank border kept on the sheet [mm].
        pen_up: the tip's height above the paper between strokes [mm].
        pitch: the pen's angle above the horizontal while drawing [deg] (-60: tilted
            30 deg from vertical, which the OpenManipulator-X and the Lynx6 both hold
            over the whole shipped sheet).
        speed: the tip's speed along lines [mm/s].
        held: the pen is in the gripper already (no pick up, no putting back).
        clearance: height above the stand's grasp point to come down from [mm].
    """

    tolerance: float = 0.1
    margin: float = 10.0
    pen_up: float = 10.0
    pitch: float = -60.0
    speed: float = 30.0
    held: bool = False
    clearance: float = 30.0

    def check(self) -> DrawOptions:
        """Self, or InputError naming the value out of range and the range."""
        for name, value, lo, hi, unit in (
            ("tolerance", self.tolerance, 1e-3, 5.0, "mm"),
            ("margin", self.margin, 0.0, 100.0, "mm"),
            ("pen_up", self.pen_up, 1.0, 100.0, "mm"),
            ("speed", self.speed, 1.0, 500.0, "mm/s"),
            ("clearance", self.clearance, 30.0, 500.0, "mm"),
            ("pitch", self.pitch, -90.0, 0.0, "deg"),
        ):
            if not (is_number(value) and math.isfinite(value) and lo <= value <= hi):
                raise InputError(f"{name} must be {lo:g}..{hi:g} {unit}, got {value!r}")
        return self


@dataclass(frozen=True)
class DrawJob:
    """A drawing job, planned (and, once run, measured).

    Attributes:
        plan: the strokes on the sheet, in order, cut to reach (``plan.notes`` say what was cut).
        sheet, pen: what it draws on and with.
        segments: every move in order (joint moves, gripper commands, paths).
        motion: the same moves as the arm's plan (``armkit.arm.Plan``), from the arm
            as it was when planned, each timed by its driver's forecast.
        tip: the arm's model with the pen's tip as its tool point.
        T_world_base: the arm's base in the scene (4, 4).
        options: how it was planned.
        trace, metrics: what the simulated pen drew (None until run on a simulator).
        physics: the scene's physics: ``"mujoco"`` has MuJoCo judge the ink.
    """

    plan: DrawingPlan
    sheet: Sheet
    pen: Pen
    segments: tuple[Segment, ...]
    motion: Plan
    tip: ArmModel
    T_world_base: F64
    options: DrawOptions
    trace: PenTrace | None = None
    metrics: DrawingMetrics | None = None
    physics: str = "rules"

    @property
    def q_start(self) -> F64:
        """The joints when planned [rad], shape (dof,)."""
        return self.motion.q_start

    def lines(self) -> list[str]:
        """What the job does, for people: one line each."""
        c = count(self.segments)
        p = self.plan
        out = [
            f"draw {Path(p.source).name} on {self.sheet.name} with {self.pen.name}: "
            f"{len(p.strokes)} strokes, pen down {p.pen_down_length * 1e3:.1f} mm, "
            f"pen up {p.pen_up_length * 1e3:.1f} mm planned; "
            + ", ".join(f"{v} {k}" for k, v in c.items())
        ]
        out += [f"note: {n}" for n in p.notes]
        if self.metrics is not None:
            out.append(f"drawn: {self.metrics}")
        return out


def plan_draw(
    arm: Arm | Start,
    scene: Scene,
    file: str | Path,
    sheet: str | None = None,
    pen: str | None = None,
    *,
    options: DrawOptions | None = None,
    fit: Fit | bool | None = None,
) -> DrawJob:
    """Plan the job from the arm's joints now; nothing moves (errors as ``draw``). The
    sheet and pen stand where the scene puts them (millimetres and degrees, as every scene
    file gives them); ``options`` are in millimetres, degrees and mm/s (``DrawOptions``).

    ``arm`` may be an ``armkit.tasks.Start`` (a model and joint angles, as the tasks
    take it): the job is planned from there, as ``armkit check`` plans a script's
    ``draw``. What is cut for reach is said in ``plan.notes`` and as a
    ``DrawingWarning``, as what is cut at the sheet's edge is."""
    opts = (options or DrawOptions()).check()
    plan = plan_on_sheet(scene, file, sheet, pen, options=opts, fit=fit)
    the_sheet, the_pen = find_sheet(scene, sheet), find_pen(scene, pen)
    stand = stand_of(scene, the_pen)
    rig = make_rig(arm.model, scene, the_sheet, the_pen, opts)
    start = arm if isinstance(arm, Start) else arm.start()
    q0 = start.q
    segments: list[Segment] = []
    if stand is not None and not opts.held and not pen_in_hand(start, the_pen):
        segments += pick_pen(rig, stand, the_pen, q0, opts.clearance / 1000.0)
    q = end_q(segments, q0)
    runs, note = _reachable(rig, plan, q, arm.model.name)
    segments += plan_strokes(rig, runs, q)
    if stand is not None and not opts.held:
        segments += put_pen(rig, stand, the_pen, end_q(segments, q0), opts.clearance / 1000.0)
    plan = replace(plan, strokes=tuple(r.uv for r in runs), notes=plan.notes + note)
    steps = plan_steps(
        start, f"draw {Path(plan.source).name}", as_steps(segments, rig.tip, opts.speed / 1000.0)
    )
    return DrawJob(
        plan, the_sheet, the_pen, tuple(segments), steps, rig.tip, scene.T_world_base, opts,
        physics=scene.physics,
    )  # fmt: skip


def pen_in_hand(start: Start, pen: Pen) -> bool:
    """Whether the gripper at ``start`` holds ``pen`` already (an interrupted drawing
    left it there: it is not picked up again, only put back); DrawingError if it holds
    another tool."""
    if start.tool is None:
        return False
    if start.tool.name != pen.name:
        raise DrawingError(
            f"the gripper holds the {start.tool.name}, not the {pen.name}: "
            "open the gripper to let it go first (armkit grip WIDTH_MM), or armkit scene reset"
        )
    return True


def plan_on_sheet(
    scene: Scene,
    file: str | Path,
    sheet: str | None = None,
    pen: str | None = None,
    *,
    options: DrawOptions | None = None,
    fit: Fit | bool | None = None,
) -> DrawingPlan:
    """The part of ``plan_draw`` no arm is needed for, refused the same way: the sheet
    and the pen of the scene, the pen's stand (unless ``held``), and the file planned on
    the sheet (DrawingError: nothing to draw, everything off the sheet, ...). The
    script's ``draw`` is checked with it."""
    opts = (options or DrawOptions()).check()
    the_sheet, the_pen = find_sheet(scene, sheet), find_pen(scene, pen)
    if stand_of(scene, the_pen) is None and not opts.held:
        raise DrawingError(f"no stand in scene {scene.name} holds {the_pen.name}; use held")
    fitted = replace(as_fit(fit), margin=opts.margin / 1000.0)
    return plan_drawing(file, the_sheet, fitted, opts.tolerance / 1000.0)


def _reachable(rig: Rig, plan: DrawingPlan, q: F64, arm: str) -> tuple[list[Run], tuple[str, ...]]:
    """The plan's strokes cut to the arm's reach, and a note on what was cut."""
    sheet = rig.sheet
    runs, cut, total = reachable_runs(
        rig.tip, list(plan.strokes), sheet.to_world, rig.scene.to_base, rig.pitch, q,
        sheet.normal * rig.pen_up,
    )  # fmt: skip
    if not runs:
        raise nothing_reachable(plan.source, arm)
    note = reach_note(plan.source, cut, total, arm)
    for line in note:
        warnings.warn(line, DrawingWarning, stacklevel=2)  # once for check and run
    return runs, note


def make_rig(model: ArmModel, scene: Scene, sheet: Sheet, pen: Pen, opts: DrawOptions) -> Rig:
    """The arm holding ``pen``: its tip model and its jaws model."""
    try:
        closed = model.with_grip_width(pen.diameter)
    except InputError:
        g = model.gripper
        raise DrawingError(
            f"the {model.name} gripper closes on {g.width_min * 1e3:g}..{g.width_max * 1e3:g} mm; "
            f"the pen {pen.name} is {pen.diameter * 1e3:g} mm wide: give the pen a holder that fits"
        ) from None
    length = pen.tool_length(model.name, closed.tool_length)
    tip = closed.with_tool_length(length)
    jaws = closed.with_tool_length(length - pen.tip_offset)
    return Rig(tip, jaws, scene, sheet, math.radians(opts.pitch), opts.pen_up / 1000.0, 0.0)


def find_sheet(scene: Scene, name: str | None) -> Sheet:
    """The scene's sheet called ``name`` (None: its only sheet); DrawingError listing them."""
    return _named(scene.sheets, name, "sheet", scene.name)


def find_pen(scene: Scene, name: str | None) -> Pen:
    """The scene's pen called ``name`` (None: its only pen); DrawingError listing them."""
    return _named(scene.pens, name, "pen", scene.name)


def _named(items: tuple[T, ...], name: str | None, kind: str, scene: str) -> T:
    names = ", ".join(i.name for i in items) or "none"
    if name is None and len(items) == 1:
        return items[0]
    if not items:
        what = "sheet of paper to draw on" if kind == "sheet" else f"{kind} to draw with"
        raise DrawingError(
            f"scene {scene} has no {what}; draw in a scene with a sheet and a pen, such as "
            "the shipped one: --scene drawing"
        )
    found = [i for i in items if i.name == name]
    if not found:
        asked = f"no {kind} {name!r}" if name is not None else f"which {kind}? (--{kind} NAME)"
        raise DrawingError(f"{asked} in scene {scene}; its {kind}s: {names}")
    return found[0]
