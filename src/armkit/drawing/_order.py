"""Ordering strokes and choosing their directions to cut pen-up travel.

Greedy nearest neighbour (from ``start``, or the end nearest the drawing's
lower-left corner), then 2-opt on the open tour: reversing the run of strokes
between two pen-up moves (each stroke in it flipped) replaces the moves
B_i -> A_{i+1} and B_j -> A_{j+1} by B_i -> B_j and A_{i+1} -> A_{j+1}
(A entry, B exit). Candidate moves come from each end's nearest ends (a grid),
their gains are computed at once in numpy, and every pass applies the best
non-overlapping improving moves. Last, closed strokes are re-entered at the
vertex nearest their neighbours.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ._grid import nearest_k

F64 = NDArray[np.float64]
IntArray = NDArray[np.intp]
NEIGHBOURS = 8


def order_strokes(strokes: Sequence[F64], start: F64 | None = None, passes: int = 100) -> list[F64]:
    """The strokes (N, 2) [m] reordered and maybe reversed, starting near
    ``start`` (2,) [m] if given (its travel counts), else anywhere."""
    n = len(strokes)
    if n == 0:
        return []
    heads = np.array([s[0] for s in strokes])
    tails = np.array([s[-1] for s in strokes])
    order, flip = greedy_order(heads, tails, start)
    if n > 1:
        order, flip = two_opt(heads, tails, order, flip, start, passes)
    out = [strokes[i][::-1] if f else strokes[i] for i, f in zip(order, flip, strict=True)]
    return reloop(out, start)


def pen_up_length(strokes: Sequence[F64], start: F64 | None = None) -> float:
    """Pen-up travel between the strokes [m] (from ``start`` too, if given)."""
    if not strokes:
        return 0.0
    tails = np.array([s[-1] for s in strokes[:-1]]).reshape(-1, 2)
    heads = np.array([s[0] for s in strokes[1:]]).reshape(-1, 2)
    total = float(np.linalg.norm(heads - tails, axis=1).sum())
    return total + (float(np.linalg.norm(strokes[0][0] - start)) if start is not None else 0.0)


def greedy_order(heads: F64, tails: F64, start: F64 | None) -> tuple[IntArray, NDArray[np.bool_]]:
    """Nearest-neighbour tour: stroke indices (N,) and which are reversed (N,)."""
    n = len(heads)
    ends = np.vstack([heads, tails])  # k < n: head of k; k >= n: tail of k - n
    here = ends.min(axis=0) if start is None else np.asarray(start, dtype=np.float64)
    x, y = ends[:, 0].copy(), ends[:, 1].copy()
    ids = np.arange(2 * n)  # which end each entry of x, y is (compacted as ends are used)
    order = np.empty(n, dtype=np.intp)
    flip = np.empty(n, dtype=bool)
    where = np.arange(2 * n)  # entry of each end in x, y
    used = 0  # entries of x, y used since the last compaction
    for step in range(n):
        dx, dy = x - here[0], y - here[1]
        k = int(ids[int(np.argmin(dx * dx + dy * dy))])
        i, rev = k % n, k >= n
        order[step], flip[step] = i, rev
        x[where[i]] = x[where[i + n]] = np.inf
        here = heads[i] if rev else tails[i]
        used += 2
        if 2 * used >= len(ids) > 64:  # half the entries are used: compact
            used = 0
            keep = np.isfinite(x)
            x, y, ids = x[keep], y[keep], ids[keep]
            where[ids] = np.arange(len(ids))
    return order, flip


def _tour_points(
    heads: F64, tails: F64, order: IntArray, flip: NDArray[np.bool_], start: F64 | None
) -> tuple[F64, F64]:
    """Entry A and exit B of positions 0..n+1; 0 is the start, n + 1 the free end (NaN: free)."""
    a = np.where(flip[:, None], tails[order], heads[order])
    b = np.where(flip[:, None], heads[order], tails[order])
    s = np.full((1, 2), np.nan) if start is None else np.asarray(start, dtype=np.float64)[None]
    free = np.full((1, 2), np.nan)
    return np.vstack([s, a, free]), np.vstack([s, b, free])


def _dist(p: F64, q: F64) -> F64:
    """Distances between rows; 0 where either is free (NaN)."""
    return np.asarray(np.nan_to_num(np.hypot(*(p - q).T), nan=0.0), dtype=np.float64)


def two_opt(
    heads: F64,
    tails: F64,
    order: IntArray,
    flip: NDArray[np.bool_],
    start: F64 | None,
    passes: int,
) -> tuple[IntArray, NDArray[np.bool_]]:
    """Improve an open tour by 2-opt moves until none gains or ``passes`` run out."""
    n = len(order)
    ends = np.vstack([heads, tails])
    near = nearest_k(ends, min(NEIGHBOURS, 2 * n - 1))
    order, flip = order.copy(), flip.copy()
    for _ in range(passes):
        A, B = _tour_points(heads, tails, order, flip, start)
        i, j = _candidates(order, flip, near, n)
        gain = (
            _dist(B[i], A[i + 1])
            + _dist(B[j], A[j + 1])
            - _dist(B[i], B[j])
            - _dist(A[i + 1], A[j + 1])
        )
        good = gain > 1e-12
        if not np.any(good):
            break
        _apply(order, flip, i[good], j[good], gain[good])
    return order, flip


def _candidates(
    order: IntArray, flip: NDArray[np.bool_], near: IntArray, n: int
) -> tuple[IntArray, IntArray]:
    """Candidate moves (i, j), 0 <= i < j <= n: reverse positions i+1..j."""
    pos = np.empty(n, dtype=np.intp)
    pos[order] = np.arange(1, n + 1)
    # endpoint e (e < n: head of e; else tail of e - n) sits at position pos and is
    # that position's exit if (tail and not flipped) or (head and flipped)
    stroke = np.arange(2 * n) % n
    is_tail = np.arange(2 * n) >= n
    flipped = np.empty(n, dtype=bool)
    flipped[order] = flip
    is_exit = is_tail != flipped[stroke]
    e = np.repeat(np.arange(2 * n), near.shape[1])
    f = near.ravel()
    ok = f >= 0
    e, f = e[ok], f[ok]
    pe, pf = pos[stroke[e]], pos[stroke[f]]
    both_exit = is_exit[e] & is_exit[f] & (pe != pf)
    both_entry = ~is_exit[e] & ~is_exit[f] & (pe != pf)
    i = np.concatenate(
        [np.minimum(pe, pf)[both_exit], np.minimum(pe, pf)[both_entry] - 1, np.arange(n)]
    )
    j = np.concatenate(
        [np.maximum(pe, pf)[both_exit], np.maximum(pe, pf)[both_entry] - 1, np.arange(1, n + 1)]
    )
    return i, j


def _apply(order: IntArray, flip: NDArray[np.bool_], i: IntArray, j: IntArray, gain: F64) -> None:
    """Apply the best improving moves whose edge ranges i..j do not overlap."""
    touched = np.zeros(len(order) + 2, dtype=bool)
    for k in np.argsort(-gain, kind="stable"):
        a, b = int(i[k]), int(j[k])
        if touched[a : b + 1].any():
            continue
        touched[a : b + 1] = True
        order[a:b] = order[a:b][::-1].copy()
        flip[a:b] = ~flip[a:b][::-1]


def reloop(strokes: list[F64], start: F64 | None, passes: int = 2) -> list[F64]:
    """Closed strokes (first point == last) entered at the vertex that makes
    the travel from the previous stroke plus to the next one shortest."""
    out = list(strokes)
    closed = [k for k, s in enumerate(out) if len(s) > 3 and np.array_equal(s[0], s[-1])]
    for _ in range(passes):
        for k in closed:
            prev = out[k - 1][-1] if k > 0 else start
            nxt = out[k + 1][0] if k + 1 < len(out) else None
            s = out[k][:-1]
            cost = np.zeros(len(s))
            for p in (prev, nxt):
                if p is not None:
                    cost += np.hypot(*(s - p).T)
            v = int(np.argmin(cost))
            if v:
                out[k] = np.vstack([s[v:], s[: v + 1]])
    return out
