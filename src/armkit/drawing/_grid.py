"""A uniform grid over 2-D points: every pair of points in nearby cells, in numpy.

The one spatial index of the drawing package: merging finds stroke ends that
meet, ordering finds each end's near neighbours, the metrics find the nearest
planned segment to each traced point.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]
IntArray = NDArray[np.intp]
EXACT = 1000


def cell_pairs(
    queries: F64, points: F64, cell: float, reach: int = 1, most: int | None = None
) -> tuple[IntArray, IntArray]:
    """Index pairs (q, p) of every query (Q, 2) and point (P, 2) whose grid
    cells (side ``cell``) are at most ``reach`` cells apart on each axis: all
    pairs closer than ``cell * reach``, and some farther ones. ``most``: at most
    that many points of one cell for one query (a pile of points in one cell,
    thousands of copies of one line, would otherwise pair each with each)."""
    if len(queries) == 0 or len(points) == 0:
        empty = np.zeros(0, dtype=np.intp)
        return empty, empty
    origin = np.minimum(queries.min(axis=0), points.min(axis=0))
    cp = np.floor((points - origin) / cell).astype(np.int64)
    cq = np.floor((queries - origin) / cell).astype(np.int64)
    width = int(max(cp[:, 1].max(), cq[:, 1].max())) + 2 * reach + 3
    key = cp[:, 0] * width + cp[:, 1]
    order = np.argsort(key, kind="stable")
    sorted_keys = key[order]
    qs, ps = [], []
    for dx in range(-reach, reach + 1):
        for dy in range(-reach, reach + 1):
            k = (cq[:, 0] + dx) * width + (cq[:, 1] + dy)
            lo = np.searchsorted(sorted_keys, k, side="left")
            hi = np.searchsorted(sorted_keys, k, side="right")
            n = hi - lo if most is None else np.minimum(hi - lo, most)
            q = np.repeat(np.arange(len(queries)), n)
            start = np.repeat(lo - np.concatenate([[0], np.cumsum(n)[:-1]]), n)
            qs.append(q)
            ps.append(order[start + np.arange(len(q))])
    return np.concatenate(qs), np.concatenate(ps)


def nearest_k(points: F64, k: int, cell: float | None = None) -> IntArray:
    """For every point (P, 2), up to ``k`` other points among the nearest in
    its 5 x 5 cells, shape (P, k), padded with -1 (approximate k nearest;
    exact for up to ``EXACT`` points)."""
    n = len(points)
    if n <= EXACT:  # small: every pair, exactly
        d = np.sum((points[:, None] - points[None]) ** 2, axis=2)
        np.fill_diagonal(d, np.inf)
        out = np.argsort(d, axis=1, kind="stable")[:, :k]
        return np.pad(out, ((0, 0), (0, k - out.shape[1])), constant_values=-1).astype(np.intp)
    if cell is None:
        w, h = np.ptp(points, axis=0) if n else (1.0, 1.0)
        cell = max(float(np.sqrt(2.0 * w * h / max(n, 1))), 2.0 * max(w, h) / max(n, 1), 1e-9)
    q, p = cell_pairs(points, points, cell, reach=2, most=k + 1)
    keep = q != p
    q, p = q[keep], p[keep]
    d = np.sum((points[q] - points[p]) ** 2, axis=1)
    order = np.lexsort((d, q))
    q, p = q[order], p[order]
    first = np.searchsorted(q, np.arange(n))
    rank = np.arange(len(q)) - first[q]
    out = np.full((n, k), -1, dtype=np.intp)
    use = rank < k
    out[q[use], rank[use]] = p[use]
    return out
