"""Every stroke and pen-up move of a drawing planned in a few numpy batches.

The same plan as ``_rig.plan_strokes`` (the reference, one stroke at a time) where
that one makes every pen-up move a joint move: every stroke's points solved as one
chain (``motion.chained_ik``: each point nearest the previous one's, the pen-up
goal of a stroke being its first point), the tip's stray between samples, the
links' clearance and the pen's height over every pen-up sweep checked at once.
Where any of that fails, or a pen-up move must be a line, it answers None and the
reference plans (and refuses) stroke by stroke. Tests: tests/drawing/test_fast_plan.py.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel
from ..motion import JointPath, batchable, chained_ik, deviation
from ..scene import Scene, Sheet, check_clear, joint_sweeps
from ._reach import Run, densify
from ._segments_job import JointMove, PathMove, Segment, stack

F64 = NDArray[np.float64]
STEP = 0.001  # [m] between the points of a pen-down line (as _rig.STEP)
TOLERANCE = 2e-4  # [m] the tip's stray between samples (as _rig._path)


class RigLike(Protocol):
    """What is read of a ``_rig.Rig`` (the arm holding the pen)."""

    @property
    def tip(self) -> ArmModel: ...
    @property
    def jaws(self) -> ArmModel: ...
    @property
    def scene(self) -> Scene: ...
    @property
    def sheet(self) -> Sheet: ...
    @property
    def pitch(self) -> float: ...
    @property
    def pen_up(self) -> float: ...
    @property
    def margin(self) -> float: ...
    def height(self, q: F64) -> F64: ...


def stroke_points(run: Run, lift: F64) -> F64:
    """A stroke's tip points (scene frame) [m]: down onto the paper from ``lift``
    (3,) [m] above its first point, along it, up again; ``_rig._stroke``'s points."""
    down = densify(np.array([run.world[0] + lift, run.world[0]]), STEP)
    up = densify(np.array([run.world[-1], run.world[-1] + lift]), STEP)
    return stack([down, densify(run.world, STEP), up])


def strokes_at_once(rig: RigLike, runs: list[Run], q0: F64) -> list[Segment] | None:
    """``plan_strokes(rig, runs, q0)`` in batches, or None: plan stroke by stroke."""
    if not runs or not batchable(rig.tip, rig.pitch):
        return None
    lift = rig.sheet.normal * rig.pen_up
    points = [rig.scene.to_base(stroke_points(run, lift)) for run in runs]
    sizes = np.array([len(p) for p in points])
    first = np.cumsum(sizes) - sizes
    base = np.vstack(points)
    q = chained_ik(rig.tip, base, rig.pitch, q0)
    if q is None:
        return None
    inside = np.ones(len(base) - 1, dtype=bool)
    inside[first[1:] - 1] = False  # from one stroke's last point to the next one's first
    if len(inside) and float(deviation(rig.tip, base, q)[inside].max(initial=0.0)) > TOLERANCE:
        return None
    starts = np.vstack([q0[None, :], q[first[1:] - 1]])
    sweeps = joint_sweeps(starts, q[first])
    low = min(float(rig.height(sweeps).min()), float(rig.height(starts).min()))
    if low < rig.pen_up / 2 - 1e-6:
        return None
    hit = check_clear(rig.jaws, np.vstack([q, sweeps]), rig.scene, margin=rig.margin)
    if hit is not None:
        return None
    segments: list[Segment] = []
    for k, (p, a, n) in enumerate(zip(points, first, sizes, strict=True), 1):
        segments.append(JointMove(f"pen up to stroke {k}", q[a]))
        segments.append(PathMove(f"stroke {k}/{len(runs)}", JointPath(p, q[a : a + n]), True))
    return segments
