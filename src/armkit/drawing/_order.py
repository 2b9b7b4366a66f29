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

from ._grid import EXACT
from ._tour import Near, improve

F64 = NDArray[np.float64]
IntArray = NDArray[np.intp]
ROUNDS = 3


def order_strokes(strokes: Sequence[F64], start: F64 | None = None, passes: int = 100) -> list[F64]:
    """The strokes (N, 2) [m] reordered and maybe reversed, starting near
    ``start`` (2,) [m] if given (its travel counts), else anywhere."""
    n = len(strokes)
    if n == 0:
        return []
    out = best_out = list(strokes)
    best = np.inf
    near = None
    for rounds in range(ROUNDS):  # a re-entered loop has new ends: search again
        heads = np.array([s[0] for s in out])
        tails = np.array([s[-1] for s in out])
        if rounds == 0:
            order, flip = greedy_order(heads, tails, start)
        else:
            order, flip = np.arange(n), np.zeros(n, dtype=bool)
        if n > 1:  # the near ends of the first round serve the next ones (re-entered loops)
            near = Near.of(heads, tails) if near is None or n <= EXACT else near
            order, flip = improve(heads, tails, order, flip, start, passes, near)
        out = reloop(
            [out[i][::-1] if f else out[i] for i, f in zip(order, flip, strict=True)], start
        )
        length = pen_up_length(out, start)
        if length > best - 1e-9:
            break
        best, best_out = length, out
    return best_out


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
