"""Curves to polylines within a tolerance, every segment kind in one numpy batch.

A curve sampled at n + 1 evenly spaced parameters strays from its chords by at
most h² max|c''| / 8 (h = the parameter step), so n = ceil(sqrt(max|c''| / (8 tol)))
per unit of parameter keeps every chord within ``tol`` of the curve: for a cubic
max|c''| = 6 max(|p0 - 2p1 + p2|, |p1 - 2p2 + p3|), for a quadratic 2 |p0 - 2p1 + p2|,
for an elliptic arc max(rx, ry) per radian.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ._errors import DrawingError
from ._segments import Cubic, EllipticArc, FigurePath, Line, Quad, Segment

F64 = NDArray[np.float64]
MAX_POINTS = 5_000_000  # a flattened drawing larger than this is refused


def flatten_paths(paths: Sequence[FigurePath], tolerance: float) -> list[F64]:
    """One polyline per non-empty path, shape (N, 2), in the paths' units;
    ``tolerance`` in the same units."""
    if not (math.isfinite(tolerance) and tolerance > 0):
        raise DrawingError(f"tolerance must be > 0, got {tolerance}")
    segments = [s for p in paths for s in p.segments]
    pieces = flatten_segments(segments, tolerance)
    out, k = [], 0
    for p in paths:
        n = len(p.segments)
        if n:
            run = pieces[k : k + n]
            out.append(np.vstack([run[0], *(r[1:] for r in run[1:])]))
        k += n
    return out


def flatten_segments(segments: Sequence[Segment], tolerance: float) -> list[F64]:
    """Each segment as points (n + 1, 2) from its start to its end."""
    out: list[F64 | None] = [None] * len(segments)
    for kind, fn in ((Line, _lines), (Quad, _beziers), (Cubic, _beziers), (EllipticArc, _arcs)):
        idx = [i for i, s in enumerate(segments) if isinstance(s, kind)]
        if idx:
            for i, pts in zip(idx, fn([segments[i] for i in idx], tolerance), strict=True):
                out[i] = pts
    return [p for p in out if p is not None]


def _lines(segs: list[Segment], tol: float) -> list[F64]:
    return [np.vstack([s.start, s.end]) for s in segs if isinstance(s, Line)]


def _counts(need: F64) -> NDArray[np.intp]:
    """Chords per segment for the given sqrt(curvature bound / 8 tol) values."""
    n = np.maximum(1, np.ceil(np.nan_to_num(need, nan=1.0, posinf=MAX_POINTS))).astype(np.intp)
    if int(n.sum()) > MAX_POINTS:
        raise DrawingError(
            f"flattening needs {int(n.sum())} points (at most {MAX_POINTS}); "
            "raise the tolerance or scale the drawing down"
        )
    return n


def _params(n: NDArray[np.intp]) -> tuple[F64, NDArray[np.intp]]:
    """Parameters in [0, 1] for every segment, concatenated, and the segment of each."""
    owner = np.repeat(np.arange(len(n)), n + 1)
    first = np.concatenate([[0], np.cumsum(n + 1)[:-1]])
    step = np.arange(len(owner)) - first[owner]
    return step / n[owner], owner


def _split(points: F64, n: NDArray[np.intp]) -> list[F64]:
    return list(np.split(points, np.cumsum(n + 1)[:-1]))


def _beziers(segs: list[Segment], tol: float) -> list[F64]:
    """Quadratic or cubic Bézier curves (one kind per call)."""
    P = np.stack([s.p for s in segs if isinstance(s, Quad | Cubic)])  # (K, 3 or 4, 2)
    second = np.linalg.norm(P[:, :-2] - 2 * P[:, 1:-1] + P[:, 2:], axis=2).max(axis=1)
    degree = P.shape[1] - 1
    n = _counts(np.sqrt(degree * (degree - 1) * second / (8 * tol)))
    t, owner = _params(n)
    t, u, C = t[:, None], 1 - t[:, None], P[owner]
    if degree == 2:
        pts = u * u * C[:, 0] + 2 * u * t * C[:, 1] + t * t * C[:, 2]
    else:
        pts = u**3 * C[:, 0] + 3 * u * u * t * C[:, 1] + 3 * u * t * t * C[:, 2] + t**3 * C[:, 3]
    return _split(pts, n)


def _arcs(segs: list[Segment], tol: float) -> list[F64]:
    arcs = [s for s in segs if isinstance(s, EllipticArc)]
    c = np.array([a.center for a in arcs], dtype=np.float64).reshape(-1, 2)
    rx, ry, rot, t0, sw = (
        np.array([getattr(a, f) for a in arcs], dtype=np.float64)
        for f in ("rx", "ry", "rotation", "t0", "sweep")
    )
    n = _counts(np.abs(sw) * np.sqrt(np.maximum(np.abs(rx), np.abs(ry)) / (8 * tol)))
    s, owner = _params(n)
    t = t0[owner] + sw[owner] * s
    x, y = rx[owner] * np.cos(t), ry[owner] * np.sin(t)
    cr, sr = np.cos(rot[owner]), np.sin(rot[owner])
    pts = c[owner] + np.column_stack([cr * x - sr * y, sr * x + cr * y])
    return _split(pts, n)
