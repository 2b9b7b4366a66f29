"""What of a plan the arm can reach with the pen: each stroke densified, solved
point by point (IK with the pen as the tool), and cut where it cannot be reached.

``reachable_runs`` solves every point of every stroke in a few batches
(``motion.chained_ik``); ``reachable_runs_loop`` is the point-by-point reference
it equals (tests/drawing/test_fast_plan.py), and what runs where the batches cannot
answer (no closed form at the pen's pitch)."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import UnreachableError
from ..kinematics import ik
from ..model import ArmModel
from ..motion import batchable, chained_ik, reachable_at
from ._errors import DrawingError

F64 = NDArray[np.float64]
SPACING = 0.002  # [m] between the points of a stroke the arm is sent through


@dataclass(frozen=True)
class Run:
    """A reachable piece of a stroke: sheet points (N, 2) [m], world points (N, 3) [m]
    (scene frame) and the joints there (N, dof) [rad]."""

    uv: F64
    world: F64
    q: F64


def densify(stroke: F64, spacing: float = SPACING) -> F64:
    """The polyline (N, D) with points added so that none are more than ``spacing`` [m]
    apart (each piece cut into equal parts; ``densify_loop`` is the reference)."""
    a, b = stroke[:-1], stroke[1:]
    if len(a) == 0:
        return stroke[:1].copy()
    d = b - a
    n = np.maximum(1, np.ceil(np.sqrt(np.einsum("ij,ij->i", d, d)) / spacing)).astype(np.intp)
    piece = np.repeat(np.arange(len(a)), n)
    j = np.arange(len(piece)) - np.repeat(np.cumsum(n) - n, n) + 1
    t = j / n[piece]
    return np.vstack([stroke[:1], a[piece] + d[piece] * t[:, None]])


def densify_loop(stroke: F64, spacing: float = SPACING) -> F64:
    """``densify`` piece by piece (the reference)."""
    out = [stroke[:1]]
    for a, b in itertools.pairwise(stroke):
        n = max(1, math.ceil(float(np.linalg.norm(b - a)) / spacing))
        out.append(a + (b - a) * (np.arange(1, n + 1) / n)[:, None])
    return np.vstack(out)


def reachable_runs(
    kin: ArmModel,
    strokes: list[F64],
    to_world: object,
    to_base: object,
    pitch: float,
    q0: F64,
    lift: F64,
) -> tuple[list[Run], float, float]:
    """The reachable runs of ``strokes`` (sheet (u, v) [m]) in drawing order, the
    length cut [m] and the whole length [m]. ``to_world``: (N, 2) -> (N, 3) scene
    points; ``to_base``: scene -> base frame; ``pitch`` [rad]; ``q0`` the seed;
    ``lift`` (3,) [m]: the pen-up offset, which must be reachable too."""
    if not batchable(kin, pitch) or not strokes:
        return reachable_runs_loop(kin, strokes, to_world, to_base, pitch, q0, lift)
    uvs = [densify(s) for s in strokes]
    uv_all = np.vstack(uvs)
    world = np.asarray(to_world(uv_all))  # type: ignore[operator]
    base = np.asarray(to_base(world))  # type: ignore[operator]
    above = np.asarray(to_base(world + lift))  # type: ignore[operator]
    ok = reachable_at(kin, above, pitch) & reachable_at(kin, base, pitch)
    qs = np.zeros((len(uv_all), kin.dof))
    solved = chained_ik(kin, base[ok], pitch, q0)
    if solved is None:
        return reachable_runs_loop(kin, strokes, to_world, to_base, pitch, q0, lift)
    qs[ok] = solved
    runs: list[Run] = []
    cut = total = 0.0
    bounds = np.cumsum([0] + [len(u) for u in uvs])
    for uv, lo, hi in zip(uvs, bounds[:-1], bounds[1:], strict=True):
        c, t = _cut_into_runs(runs, uv, world[lo:hi], qs[lo:hi], ok[lo:hi])
        cut, total = cut + c, total + t
    return runs, cut, total


def _cut_into_runs(
    runs: list[Run], uv: F64, world: F64, qs: F64, ok: NDArray[np.bool_]
) -> tuple[float, float]:
    """Append the reachable runs of one stroke; its length cut and whole length [m]."""
    seg = np.linalg.norm(np.diff(uv, axis=0), axis=1)
    edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(np.int8), [0]])))
    for a, b in zip(edges[::2], edges[1::2], strict=True):
        if b - a >= 2 or len(uv) == 1:
            runs.append(Run(uv[a:b], world[a:b], qs[a:b]))
    return float(seg[~(ok[:-1] & ok[1:])].sum()), float(seg.sum())


def reachable_runs_loop(
    kin: ArmModel,
    strokes: list[F64],
    to_world: object,
    to_base: object,
    pitch: float,
    q0: F64,
    lift: F64,
) -> tuple[list[Run], float, float]:
    """``reachable_runs`` point by point with ``ik`` (the reference)."""
    runs: list[Run] = []
    cut = total = 0.0
    seed = q0
    for stroke in strokes:
        uv = densify_loop(stroke)
        world = np.asarray(to_world(uv))  # type: ignore[operator]
        base = np.asarray(to_base(world))  # type: ignore[operator]
        ok, qs = np.zeros(len(uv), dtype=bool), np.zeros((len(uv), kin.dof))
        above = np.asarray(to_base(world + lift))  # type: ignore[operator]
        for i, p in enumerate(base):
            try:
                ik(kin, above[i], pitch, seed)
                qs[i] = seed = ik(kin, p, pitch, seed).q
                ok[i] = True
            except UnreachableError:
                continue
        seg = np.linalg.norm(np.diff(uv, axis=0), axis=1)
        total += float(seg.sum())
        cut += float(seg[~(ok[:-1] & ok[1:])].sum())
        edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(np.int8), [0]])))
        for a, b in zip(edges[::2], edges[1::2], strict=True):
            if b - a >= 2 or len(uv) == 1:
                runs.append(Run(uv[a:b], world[a:b], qs[a:b]))
    return runs, cut, total


def reach_note(source: str, cut: float, total: float, arm: str) -> tuple[str, ...]:
    """One line saying what was cut for reach, or nothing."""
    if cut <= 1e-6:
        return ()
    return (
        f"{source}: cut {cut * 1e3:.1f} mm of {total * 1e3:.1f} mm of line that the {arm} "
        "cannot reach with the pen; move the sheet nearer or scale the drawing down",
    )


def nothing_reachable(source: str, arm: str) -> DrawingError:
    """The error when no stroke is within reach."""
    return DrawingError(
        f"the {arm} reaches none of the drawing with the pen on this sheet; "
        "move the sheet nearer or try another --pitch",
        file=source,
    )
