"""Distances from points to polylines, exact, through a grid of segment midpoints.

A segment no longer than ``cell`` whose nearest point lies within cell / 2 of a
query has its midpoint within one cell of it, so the 3 x 3 cells around each
query find it; queries with nothing that close are measured against every
segment (a few, far from the drawing).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ._grid import cell_pairs

F64 = NDArray[np.float64]
CELL = 1e-3  # [m]
CHUNK = 256  # queries per block in the fallback (each against every segment)
QUERIES = 20_000  # queries per block on a grid


def segments_of(strokes: Sequence[F64], longest: float = CELL) -> tuple[F64, F64]:
    """Every segment of the strokes (N, 2) as (start, end) arrays (M, 2), none
    longer than ``longest`` [m]; a one-point stroke is a zero-length segment."""
    starts, ends = [], []
    for s in strokes:
        s = s if len(s) > 1 else np.vstack([s, s])
        a, b = s[:-1], s[1:]
        pieces = np.maximum(1, np.ceil(np.linalg.norm(b - a, axis=1) / longest)).astype(np.intp)
        k = np.repeat(np.arange(len(a)), pieces)
        first = np.repeat(np.cumsum(pieces) - pieces, pieces)
        f0 = (np.arange(len(k)) - first) / pieces[k]
        f1 = f0 + 1.0 / pieces[k]
        starts.append(a[k] + f0[:, None] * (b - a)[k])
        ends.append(a[k] + f1[:, None] * (b - a)[k])
    if not starts:
        return np.zeros((0, 2)), np.zeros((0, 2))
    return np.vstack(starts), np.vstack(ends)


def _point_segment(p: F64, a: F64, b: F64) -> F64:
    """Row-wise distance of p from segment a-b, all (K, 2)."""
    ab = b - a
    den = np.einsum("ij,ij->i", ab, ab)
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.where(den > 0, den, 1.0), 0.0, 1.0)
    return np.asarray(np.hypot(*(p - a - t[:, None] * ab).T), dtype=np.float64)


def distance_to_strokes(points: F64, strokes: Sequence[F64], cell: float = CELL) -> F64:
    """Distance [m] of each point (N, 2) from the nearest stroke, shape (N,)."""
    a, b = segments_of(strokes, cell)
    best = np.full(len(points), np.inf)
    if len(a) == 0 or len(points) == 0:
        return best
    mid = (a + b) / 2
    span = float(np.ptp(np.vstack([points, mid]), axis=0).max())
    todo = np.arange(len(points))
    while len(todo) and cell < span:  # coarser grids for the points still far
        for block in np.array_split(todo, max(1, len(todo) // QUERIES)):
            q, s = cell_pairs(points[block], mid, cell, reach=1)
            np.minimum.at(best, block[q], _point_segment(points[block[q]], a[s], b[s]))
        todo = todo[best[todo] > cell / 2]
        cell *= 4.0
    for block in np.array_split(todo, max(1, len(todo) // CHUNK)) if len(todo) else ():
        p = np.repeat(points[block], len(a), axis=0)
        d = _point_segment(p, np.tile(a, (len(block), 1)), np.tile(b, (len(block), 1)))
        best[block] = d.reshape(len(block), len(a)).min(axis=1)
    return best


def sample(strokes: Sequence[F64], spacing: float) -> F64:
    """Points along the strokes no more than ``spacing`` [m] apart, shape (K, 2)."""
    a, b = segments_of(strokes, spacing)
    if len(a) == 0:
        return np.zeros((0, 2))
    return np.vstack([a, b[-1:]]) if len(strokes) == 1 else np.vstack([a, b])


def hausdorff(a: Sequence[F64], b: Sequence[F64], spacing: float = 1e-4) -> float:
    """Hausdorff distance [m] between two sets of polylines, each sampled every
    ``spacing`` [m] (the result is exact to within spacing / 2)."""
    if not a or not b:
        return float("inf")
    ab = distance_to_strokes(sample(a, spacing), b).max()
    ba = distance_to_strokes(sample(b, spacing), a).max()
    return float(max(ab, ba))
