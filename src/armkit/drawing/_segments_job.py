"""The pieces a drawing job is made of, planned before anything moves."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..arm import Step
from ..model import ArmModel
from ..motion import JointPath, TimedStreaming

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class JointMove:
    """A move in joint space to ``q`` [rad], shape (dof,)."""

    label: str
    q: F64


@dataclass(frozen=True)
class GripMove:
    """The gripper to ``width`` [m]; ``holds`` whether the pen is in it afterwards."""

    label: str
    width: float
    holds: bool


@dataclass(frozen=True)
class PathMove:
    """A Cartesian path for the pen tip (``path.points`` scene... base frame [m]);
    ``draws``: a stroke (down onto the paper, along it, up again) or a pen-up move."""

    label: str
    path: JointPath
    draws: bool


Segment = JointMove | GripMove | PathMove


def end_q(segments: list[Segment], q0: F64) -> F64:
    """The joints [rad] after the last move of ``segments`` (``q0`` if none)."""
    for s in reversed(segments):
        if isinstance(s, JointMove):
            return s.q
        if isinstance(s, PathMove):
            last: F64 = s.path.q[-1]
            return last
    return q0


def count(segments: tuple[Segment, ...]) -> dict[str, int]:
    """How many of each kind: joint moves, gripper commands, strokes, pen-up paths."""
    return {
        "joint moves": sum(isinstance(s, JointMove) for s in segments),
        "gripper": sum(isinstance(s, GripMove) for s in segments),
        "strokes": sum(isinstance(s, PathMove) and s.draws for s in segments),
        "pen-up paths": sum(isinstance(s, PathMove) and not s.draws for s in segments),
    }


def as_steps(segments: list[Segment], tip: ArmModel, speed: float) -> list[Step]:
    """The segments as the arm's plan steps: pen paths streamed at the tip's ``speed``
    [m/s], solved with ``tip`` (the arm with the pen's tip as its tool point)."""
    streamer = TimedStreaming(speed=speed)
    out = []
    for s in segments:
        if isinstance(s, JointMove):
            out.append(Step(s.label, q=s.q))
        elif isinstance(s, GripMove):
            out.append(Step(s.label, grip=s.width))
        else:
            path = s.path
            out.append(Step(s.label, q=path.q[-1], path=path, streamer=streamer, kin=tip))
    return out


def stack(points: list[F64]) -> F64:
    """Points (N_i, 3) joined, consecutive duplicates dropped."""
    p = np.vstack(points)
    keep = np.concatenate([[True], np.linalg.norm(np.diff(p, axis=0), axis=1) > 1e-9])
    out: F64 = p[keep]
    return out
