"""The spherical-wrist closed form for N targets at once (``_wrist``'s math on numpy
lanes, over cache-sized chunks): the vectorised reference the scalar solver is pinned to,
and ``ik_batch``'s path for full poses."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._closed import Candidates, best, solve
from ._closed_fast import Q
from ._wrist import V, Vec3, WristConstants, WristFamily, _constants, _cross, _dot, _flips

F64 = NDArray[np.float64]
CHUNK = 4096  # targets per pass (``_forward.CHUNK``)
_TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Bounds:
    """Joint limits [rad] of the first ``dof`` joints (what ``_closed.solve`` reads)."""

    dof: int
    lower: Q
    upper: Q


def solve_wrist_batch(
    wf: WristFamily, lower: Q, upper: Q, P: F64, R: F64, seed: F64
) -> tuple[F64, NDArray[np.bool_]]:
    """``wrist_solver`` for N targets at once: tool points P (N, 3) [m], rotations R
    (N, 3, 3), seeds (N, 6) [rad] -> the valid solution nearest each seed (NaN rows where
    none) and ok (N,): every branch as lanes, the same math (``_wrist_angles``) on arrays,
    over cache-sized chunks."""
    q, ok = np.full((len(P), 6), np.nan), np.zeros(len(P), dtype=bool)
    k = _constants(wf)
    R0 = np.array(wf.R0).reshape(3, 3)
    c5, cr, cc = R0.T @ k.w5, R0.T @ k.r5, np.array(wf.centre)  # R times these: lane sums
    for at in (slice(i, i + CHUNK) for i in range(0, len(P), CHUNK)):
        r = np.ascontiguousarray(R[at].reshape(-1, 9).T)  # row-major entries as lanes
        md, mg, cw = (
            tuple(r[3 * i] * v[0] + r[3 * i + 1] * v[1] + r[3 * i + 2] * v[2] for i in range(3))
            for v in (c5, cr, cc)
        )
        C = np.stack(cw, axis=1) + P[at] - [*wf.shift, 0.0]
        pos = solve(Bounds(3, lower[:3], upper[:3]), wf.arm, C, None, seed[at, :3])
        lanes, fits = [], []
        for kk in range(pos.lanes.shape[1]):
            q0, q1, q2 = pos.lanes[:, kk]
            c, s = np.cos(wf.w[0][2] * q0), np.sin(wf.w[0][2] * q0)
            cu, su = np.cos(q1 + wf.k * q2), -np.sin(q1 + wf.k * q2)
            d = _rot((c * md[0] + s * md[1], c * md[1] - s * md[0], md[2]), wf.w[1], cu, su)
            g = _rot((c * mg[0] + s * mg[1], c * mg[1] - s * mg[0], mg[2]), wf.w[1], cu, su)
            with np.errstate(invalid="ignore"):
                for angles in _wrist_angles(d, g, seed[at, 3], k):
                    fit, row = pos.fits[kk].copy(), [q0, q1, q2]
                    for j, a in zip((3, 4, 5), angles, strict=True):
                        v, inside = _wrap_near(a, lower[j], upper[j], seed[at, j])
                        row.append(v)
                        fit &= inside
                    lanes.append(np.stack(row))
                    fits.append(fit)
        cand = Candidates(np.stack(lanes, axis=1), np.stack(fits), pos.checks, pos.bad)
        q[at], ok[at] = best(cand, seed[at])
    return q, ok


def _wrap_near(v: F64, lo: float, hi: float, near: F64) -> tuple[F64, NDArray[np.bool_]]:
    """``_fit`` over lanes: the angles, clamped, and where they fit."""
    w = near + np.remainder(v - near + math.pi, _TWO_PI) - math.pi
    w = np.where(w > hi + 1e-9, w - _TWO_PI, np.where(w < lo - 1e-9, w + _TWO_PI, w))
    return np.clip(w, lo, hi), (w >= lo - 1e-9) & (w <= hi + 1e-9)


def _wrist_angles(d: V, g: V, seed3: F64, k: WristConstants) -> list[tuple[F64, F64, F64]]:
    """The wrist's (t3, t4, t5) [rad] per branch, with exp(w3 t3) exp(w4 t4) w5 = d and
    exp(w3 t3) exp(w4 t4) exp(w5 t5) r5 = g, over lanes (arrays (N,)): 2 branches, NaN in a
    lane where it has none (w5 cannot point along d; the second where singular: d along
    w3, t3 then ``seed3``). |d off w3|^2 = |d x w3|^2, not 1 - (w3 . d)^2: it stays
    exact near the singularity."""
    w3, w4, w5, x34 = k.w3, k.w4, k.w5, k.x34
    d3, e = _dot(w3, d), _cross(d, w3)
    off = _dot(e, e)
    alpha, beta = (k.s34 * k.c45 - d3) / k.den, (k.s34 * d3 - k.c45) / k.den
    flip = _flips(k)
    gamma2 = (
        off if flip else (1.0 - alpha * alpha - beta * beta - 2.0 * alpha * beta * k.s34) / k.n34
    )
    singular = off <= 1e-18
    alpha = np.where(gamma2 < -1e-9, math.nan, alpha)
    gamma = np.sqrt(np.maximum(gamma2, 0.0))
    out: list[tuple[F64, F64, F64]] = []
    for sign in (1.0,) if flip else (1.0, -1.0):
        c = tuple(alpha * w3[i] + beta * w4[i] + sign * gamma * x34[i] for i in range(3))
        c = tuple(np.where(singular, d[i], c[i]) for i in range(3))
        t3 = np.where(singular, seed3, np.arctan2(_dot(c, e), _dot(c, d) - d3 * d3))
        t4 = _turn(w4, w5, c, np.arctan2)
        h = _rot(_rot(g, w3, np.cos(t3), -np.sin(t3)), w4, np.cos(t4), -np.sin(t4))
        t5 = np.arctan2(_dot(k.t5, h), _dot(k.r5, h))
        out.append((np.where(singular & (sign < 0), math.nan, t3), t4, t5))
    if flip:
        t3, t4, t5 = out[0]
        out.append((np.where(singular, math.nan, t3 + math.pi), -t4, t5 + math.pi))
    return out


def _rot(v: V, w: Vec3, c: Any, s: Any) -> V:
    """v turned about the unit axis w by the angle of cosine c and sine s (Rodrigues)."""
    k = (1.0 - c) * (w[0] * v[0] + w[1] * v[1] + w[2] * v[2])
    return (
        c * v[0] + s * (w[1] * v[2] - w[2] * v[1]) + k * w[0],
        c * v[1] + s * (w[2] * v[0] - w[0] * v[2]) + k * w[1],
        c * v[2] + s * (w[0] * v[1] - w[1] * v[0]) + k * w[2],
    )


def _turn(w: Vec3, p: V, q: V, atan2: Callable[[Any, Any], Any]) -> Any:
    """Subproblem 1: the angle [rad] about the unit axis w that takes p towards q."""
    return atan2(_dot(w, _cross(p, q)), _dot(p, q) - _dot(w, p) * _dot(w, q))
