"""Distances between segments, boxes and planes, vectorised over many pairs (numpy)."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]
GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0
ITERATIONS = 24  # golden-section steps: the segment parameter to 1e-5 (2 um on 20 cm)


def box_signed_distance(p: F64, half: F64) -> F64:
    """Signed distance [m] from points ``p`` (..., 3), in a box's own frame, to the
    box of half sizes ``half`` (..., 3) centred at the origin: negative inside."""
    q = np.abs(p) - half
    outside = np.linalg.norm(np.maximum(q, 0.0), axis=-1)
    inside = np.minimum(np.max(q, axis=-1), 0.0)
    out: F64 = outside + inside
    return out


def segment_box_distance(a: F64, b: F64, half: F64) -> F64:
    """Smallest signed distance [m] from segments a-b (P, 3) to boxes (P, 3 half
    sizes), all in each box's own frame. The signed distance to a convex box is
    convex along a segment, so a golden-section search finds its minimum."""
    lo, hi = np.zeros(a.shape[0]), np.ones(a.shape[0])
    d = b - a
    x1 = hi - GOLDEN * (hi - lo)
    x2 = lo + GOLDEN * (hi - lo)
    f1 = box_signed_distance(a + x1[:, None] * d, half)
    f2 = box_signed_distance(a + x2[:, None] * d, half)
    for _ in range(ITERATIONS):
        left = f1 <= f2  # the minimum lies in [lo, x2]
        hi = np.where(left, x2, hi)
        lo = np.where(left, lo, x1)
        x2n = np.where(left, x1, lo + GOLDEN * (hi - lo))
        x1n = np.where(left, hi - GOLDEN * (hi - lo), x2)
        f_new = box_signed_distance(a + np.where(left, x1n, x2n)[:, None] * d, half)
        f1, f2 = np.where(left, f_new, f2), np.where(left, f1, f_new)
        x1, x2 = x1n, x2n
    ends = np.minimum(box_signed_distance(a, half), box_signed_distance(b, half))
    out: F64 = np.minimum(np.minimum(f1, f2), ends)
    return out


def box_box_gap(c1: F64, R1: F64, h1: F64, c2: F64, R2: F64, h2: F64) -> F64:
    """Separating-axis gap [m] between oriented boxes, P pairs: centres (P, 3),
    rotations (P, 3, 3) (columns = box axes), half sizes (P, 3). Positive: the largest
    gap along the 15 candidate axes (a lower bound of their distance); negative:
    overlapping, by at least that much along every axis (the smallest overlap)."""
    A, B = R1.transpose(0, 2, 1), R2.transpose(0, 2, 1)  # rows = box axes, (P, 3, 3)
    a, b = A[:, :, None, :], B[:, None, :, :]
    cross = np.stack(
        [
            a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
            a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
            a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0],
        ],
        axis=-1,
    ).reshape(-1, 9, 3)
    L = np.concatenate([A, B, cross], axis=1)  # (P, 15, 3)
    norm = np.linalg.norm(L, axis=-1)
    valid = norm > 1e-9
    L = L / np.where(valid, norm, 1.0)[..., None]
    r1 = np.sum(np.abs(np.einsum("pkj,pji->pki", L, R1)) * h1[:, None, :], axis=-1)
    r2 = np.sum(np.abs(np.einsum("pkj,pji->pki", L, R2)) * h2[:, None, :], axis=-1)
    dist = np.abs(np.einsum("pkj,pj->pk", L, c2 - c1))
    gap = np.where(valid, dist - r1 - r2, -np.inf)
    out: F64 = np.max(gap, axis=1)
    return out


def box_corners(c: F64, R: F64, h: F64) -> F64:
    """The 8 corners of boxes: centres (P, 3), rotations (P, 3, 3), half sizes (P, 3) -> (P, 8, 3)."""
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
    local = signs[None, :, :] * h[:, None, :]
    out: F64 = c[:, None, :] + np.einsum("pij,pkj->pki", R, local)
    return out


def segment_segment_distance(p0: F64, p1: F64, q0: F64, q1: F64) -> F64:
    """Smallest distance [m] between segments p0-p1 and q0-q1, each end (..., 3), shape
    (...): the closest points' parameters in closed form, clamped to the segments
    (Ericson, Real-Time Collision Detection, 5.1.9); a segment may be a point."""
    d1, d2, r = p1 - p0, q1 - q0, p0 - q0
    a, e, b = _dot(d1, d1), _dot(d2, d2), _dot(d1, d2)
    c, f = _dot(d1, r), _dot(d2, r)
    line_a, line_e = a > 1e-18, e > 1e-18  # else that segment is a point
    aa, ee = np.where(line_a, a, 1.0), np.where(line_e, e, 1.0)
    den = a * e - b * b  # 0 for parallel segments: any s is nearest, take 0
    crossing = den > 1e-12 * a * e
    s = np.where(crossing, np.clip((b * f - c * e) / np.where(crossing, den, 1.0), 0, 1), 0)
    t = (b * s + f) / ee  # q's parameter nearest p(s); outside q: clamp it, redo s
    s = np.where(t < 0.0, np.clip(-c / aa, 0, 1), np.where(t > 1.0, np.clip((b - c) / aa, 0, 1), s))
    s = np.where(line_a, np.where(line_e, s, np.clip(-c / aa, 0, 1)), 0.0)
    t = np.clip((b * s + f) / ee, 0, 1) * line_e
    out: F64 = np.linalg.norm(r + d1 * s[..., None] - d2 * t[..., None], axis=-1)
    return out


def _dot(u: F64, v: F64) -> F64:
    out: F64 = np.einsum("...i,...i->...", u, v)
    return out
