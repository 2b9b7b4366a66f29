"""Picking the pen up from its stand and putting it back (001's third task), with
the tasks' planner: open, 001's way down from above (a joint move to 30 mm over
the grasp point, three steps down), close on the pen's holder, back up."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..scene import Pen, PenStand, Scene
from ..tasks import Step
from ..tasks.steps import Context, Options, State, down, grip, up
from ._rig import Rig
from ._segments_job import GripMove, JointMove, Segment

F64 = NDArray[np.float64]
JAW_ROOM = 0.010  # [m] the jaws open this much wider than the holder on each side


def grasp_point(scene: Scene, stand: PenStand, pen: Pen) -> F64:
    """Where the jaws' tool point holds the pen in its stand (scene frame) [m]: the
    tip ``holder_length`` into the stand along the pen's axis, the jaws
    ``tip_offset`` back from the tip."""
    out = stand.position - scene.T_world_base[:3, 3]
    out[2] = 0.0
    n = float(np.linalg.norm(out))
    radial = out / n if n > 1e-9 else np.array([1.0, 0.0, 0.0])
    axis = math.cos(stand.pitch) * radial + np.array([0.0, 0.0, math.sin(stand.pitch)])
    point: F64 = stand.position + axis * (pen.holder_length - pen.tip_offset)
    return point


def opening(rig: Rig, pen: Pen) -> float:
    """How wide the jaws open to take the pen [m]."""
    return min(rig.jaws.gripper.width_max, pen.diameter + 2 * JAW_ROOM)


def pick_pen(rig: Rig, stand: PenStand, pen: Pen, q: F64, clearance: float) -> list[Segment]:
    """Open, come down on the pen in ``stand`` from above, close, go back up."""
    ctx, st = _start(rig, q, clearance, f"draw: pick up {pen.name}")
    p = grasp_point(rig.scene, stand, pen)
    st = grip(ctx, st, opening(rig, pen), f"open to take {pen.name}")
    st = down(ctx, st, p, stand.pitch, f"pick {pen.name}", kin=rig.jaws, ignore=frozenset())
    st = grip(ctx, st, pen.diameter, f"close on {pen.name}")
    st = up(ctx, st, p, stand.pitch, f"pick {pen.name}", kin=rig.jaws, ignore=frozenset())
    return _segments(st.steps, pen)


def put_pen(rig: Rig, stand: PenStand, pen: Pen, q: F64, clearance: float) -> list[Segment]:
    """Come down over ``stand`` from above with the pen, open, go back up."""
    ctx, st = _start(rig, q, clearance, f"draw: put {pen.name} back")
    p = grasp_point(rig.scene, stand, pen)
    label = f"put {pen.name} in {stand.name}"
    st = down(ctx, st, p, stand.pitch, label, kin=rig.jaws, ignore=frozenset())
    st = grip(ctx, st, opening(rig, pen), f"release {pen.name}")
    st = up(ctx, st, p, stand.pitch, f"leave {stand.name}", kin=rig.jaws, ignore=frozenset())
    return _segments(st.steps, pen)


def _start(rig: Rig, q: F64, clearance: float, task: str) -> tuple[Context, State]:
    ctx = Context(rig.jaws, Options(clearance=clearance, margin=rig.margin), task)
    return ctx, State(q, rig.scene, None, None)


def _segments(steps: tuple[Step, ...], pen: Pen) -> list[Segment]:
    out: list[Segment] = []
    for s in steps:
        if s.grip is not None:
            out.append(GripMove(s.label, s.grip, s.grip <= pen.diameter + 1e-9))
        elif s.q is not None:
            out.append(JointMove(s.label, s.q))
    return out


def stand_of(scene: Scene, pen: Pen) -> PenStand | None:
    """The stand the scene has ``pen`` in, or None."""
    return next((s for s in scene.pen_stands if s.pen == pen.name), None)
