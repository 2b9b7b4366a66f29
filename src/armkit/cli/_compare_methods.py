"""Seed 003's question, generalised: which way of finding joint angles is best?

Every IK method runs on the same random reachable targets (FK of random joint
vectors inside the limits, fixed seed), each starting from the arm's home
pose, and is scored the same way: verified success (the answer's FK within
1 mm of the target, and 0.1 deg of the pitch / orientation when one is
asked for, with every joint inside its limits), time per call, iterations and
the answer's position error measured by FK.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError, UnreachableError
from ..kinematics import IKBatchResult, closed_form, fk, ik, ik_batch, pitch_of
from ..model import ArmModel
from ._ik_tasks import METHODS, TASKS

F64 = NDArray[np.float64]
VERIFY_POS = 1e-3  # [m]
VERIFY_ANG = math.radians(0.1)  # [rad]
Progress = Callable[[str, int], None]  # (the method under way, targets done by it)


@dataclass(frozen=True)
class Targets:
    """N reachable targets: tool poses T (N, 4, 4) [m] of joint vectors q (N, dof) [rad]."""

    q: F64
    T: F64
    task: str

    @property
    def pitch(self) -> F64:
        """Pitch of each target [rad], shape (N,)."""
        return np.asarray(pitch_of(self.T), dtype=np.float64)


@dataclass(frozen=True)
class MethodScore:
    """One method's row: success share, seconds per call (median, p95; p95 NaN for a
    batch), median iterations (NaN if not reported) and median position error [m]."""

    method: str
    success: float
    median_s: float
    p95_s: float
    median_iterations: float
    median_error: float


def default_task(model: ArmModel) -> str:
    """The natural task for an arm: full pose for 6 joints, position + pitch for
    4-5 (the seed arms' way), position for fewer."""
    return "pose" if model.dof >= 6 else ("position+pitch" if model.dof >= 4 else "position")


def reachable_targets(model: ArmModel, n: int, seed: int, task: str) -> Targets:
    """n targets made by FK of joint vectors drawn uniformly inside the limits."""
    if task not in TASKS:
        raise InputError(f"task must be one of {', '.join(TASKS)}, got {task!r}")
    if n < 1:
        raise InputError(f"n must be at least 1, got {n}")
    q = np.random.default_rng(seed).uniform(model.lower, model.upper, size=(n, model.dof))
    return Targets(q, fk(model, q), task)


def applicable_methods(model: ArmModel, task: str) -> tuple[str, ...]:
    """The methods that apply: the closed form only for its family (yaw + planar without
    an orientation, a spherical wrist with one)."""
    family = closed_form(model)
    closed = (family == "spherical wrist") == (task == "pose") and family != ""
    return tuple(m for m in METHODS if m != "analytic" or closed)


def compare_methods(
    model: ArmModel,
    targets: Targets,
    methods: Sequence[str] | None = None,
    repeats: int = 1,
    progress: Progress | None = None,
) -> list[MethodScore]:
    """Score each method (default: every applicable one) on the same targets; each
    call (or batch) runs ``repeats`` times and the fastest time counts (a busy machine
    only ever adds time). ``progress(method, done)`` is told, outside the timed calls,
    how many targets the method under way has done."""
    if repeats < 1:
        raise InputError(f"repeats must be at least 1, got {repeats}")
    methods = applicable_methods(model, targets.task) if methods is None else methods
    for m in methods:
        if m not in METHODS:
            raise InputError(f"method must be one of {', '.join(METHODS)}, got {m!r}")
    report = progress or _quiet
    scores = []
    for m in methods:
        report(m, 0)
        if m == "lm-batch":
            scores.append(_score_batch(model, targets, repeats))
        else:
            scores.append(_score_calls(model, targets, m, repeats, report))
        report(m, len(targets.q))
    return scores


def _quiet(method: str, done: int) -> None:
    """No progress shown."""


def verified(model: ArmModel, targets: Targets, q: F64) -> NDArray[np.bool_]:
    """Per target, True if q (N, dof) [rad] (NaN rows = no answer) is inside the limits
    and its FK is within 1 mm (and 0.1 deg for pitch / pose tasks) of the target."""
    answered = np.all(np.isfinite(q), axis=1)
    qq = np.where(answered[:, None], q, model.home)
    T = fk(model, qq)
    ok = answered & model.within_limits(qq, slack=0.0)
    ok &= np.linalg.norm(T[:, :3, 3] - targets.T[:, :3, 3], axis=1) <= VERIFY_POS
    if targets.task == "position+pitch":
        d = np.remainder(pitch_of(T) - targets.pitch + np.pi, 2 * np.pi) - np.pi
        ok &= np.abs(d) <= VERIFY_ANG
    elif targets.task == "pose":
        E = targets.T[:, :3, :3] @ T[:, :3, :3].transpose(0, 2, 1)
        cos = np.clip((np.trace(E, axis1=1, axis2=2) - 1.0) / 2.0, -1.0, 1.0)
        ok &= np.arccos(cos) <= VERIFY_ANG
    return np.asarray(ok, dtype=np.bool_)


def _one_call(model: ArmModel, targets: Targets, method: str) -> Callable[[int], object]:
    """A function solving target i by ``method`` through ``armkit.kinematics.ik``."""
    P, R, pitch = targets.T[:, :3, 3], targets.T[:, :3, :3], targets.pitch
    home = model.home

    def call(i: int) -> object:
        if targets.task == "pose":
            return ik(model, P[i], None, home, orientation=R[i], method=method)  # type: ignore[arg-type]
        p = float(pitch[i]) if targets.task == "position+pitch" else None
        return ik(model, P[i], p, home, method=method)  # type: ignore[arg-type]

    return call


def _score_calls(
    model: ArmModel, targets: Targets, method: str, repeats: int, progress: Progress
) -> MethodScore:
    """Time (fastest of ``repeats``) and verify one call per target (``progress`` after
    each)."""
    n = len(targets.q)
    call = _one_call(model, targets, method)
    q = np.full((n, model.dof), np.nan)
    seconds, iterations = np.full(n, np.inf), np.full(n, np.nan)
    for i in range(n):
        for _ in range(repeats):
            start = time.perf_counter()
            try:
                result = call(i)
            except UnreachableError:
                result = None
            seconds[i] = min(seconds[i], time.perf_counter() - start)
        if result is not None:
            q[i], iterations[i] = result.q, result.iterations  # type: ignore[attr-defined]
        progress(method, i + 1)
    return _row(model, targets, method, q, seconds, iterations)


def _score_batch(model: ArmModel, targets: Targets, repeats: int) -> MethodScore:
    """Time one batch call over all targets (fastest of ``repeats``); report it per target."""
    T = targets.T
    pitch = targets.pitch if targets.task == "position+pitch" else None
    pose = targets.task == "pose"

    def run(k: slice) -> IKBatchResult:
        angle = None if pitch is None else pitch[k]
        R = T[k, :3, :3] if pose else None
        return ik_batch(model, T[k, :3, 3], angle, model.home, orientations=R, method="lm")

    run(slice(0, 10))  # numpy's first calls (lapack, einsum) are slow, once per process
    per = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        out = run(slice(None))
        per = min(per, (time.perf_counter() - start) / len(T))
    seconds = np.full(len(T), per)
    row = _row(model, targets, "lm-batch", out.q, seconds, np.full(len(T), np.nan))
    return MethodScore(row.method, row.success, per, math.nan, math.nan, row.median_error)


def _row(
    model: ArmModel, targets: Targets, method: str, q: F64, seconds: F64, iterations: F64
) -> MethodScore:
    answered = np.all(np.isfinite(q), axis=1)
    errors = np.full(len(q), np.nan)
    if answered.any():
        T = fk(model, q[answered])
        errors[answered] = np.linalg.norm(T[:, :3, 3] - targets.T[answered, :3, 3], axis=1)
    return MethodScore(
        method=method,
        success=float(verified(model, targets, q).mean()),
        median_s=float(np.median(seconds)),
        p95_s=float(np.percentile(seconds, 95)),
        median_iterations=float(np.nanmedian(iterations))
        if np.isfinite(iterations).any()
        else math.nan,
        median_error=float(np.nanmedian(errors)) if answered.any() else math.nan,
    )
