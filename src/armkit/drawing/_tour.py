"""Local search on an open tour of strokes: 2-opt and Or-opt, in numpy batches.

Positions 1..n hold the strokes; 0 is the start (free if None) and n + 1 the
free end; a free point is NaN and any move to or from it costs nothing. A
stroke at position k is entered at A_k and left at B_k.

- 2-opt (i, j): reverse positions i+1..j (each stroke flipped): the moves
  B_i -> A_{i+1}, B_j -> A_{j+1} become B_i -> B_j, A_{i+1} -> A_{j+1}.
- Or-opt (p, L, q, r): take the L <= 3 strokes at p..p+L-1 out and put them
  after position q, reversed if r.

Candidates come from each end's nearest ends (``nearest_k``); every pass
computes all their gains at once and applies the best ones whose edge ranges
do not overlap (each such move changes only the order inside its range).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._grid import nearest_k

F64 = NDArray[np.float64]
IntArray = NDArray[np.intp]
Bools = NDArray[np.bool_]
NEIGHBOURS = 10
ALL_PAIRS = 150  # up to this many strokes every end is a candidate of every other
OR_LENGTHS = (1, 2, 3)
MIN_GAIN = 0.002  # a pass pair gaining less than this share of the travel is the last


def improve(
    heads: F64,
    tails: F64,
    order: IntArray,
    flip: Bools,
    start: F64 | None,
    passes: int,
    near: Near | None = None,
) -> tuple[IntArray, Bools]:
    """2-opt and Or-opt passes, alternating, until a pair of them gains less than
    ``MIN_GAIN`` of the pen-up travel or ``passes`` run out (so the work grows as
    N log N: a bounded number of passes, each sorting its candidates). ``near``:
    the candidate pairs of ends (``Near.of``), found once for several calls."""
    near = near if near is not None else Near.of(heads, tails)
    order, flip = order.copy(), flip.copy()
    before = np.inf
    for _ in range(passes):
        gained = False
        for step in (_two_opt_pass, _or_opt_pass):
            A, B = _tour_points(heads, tails, order, flip, start)
            gained |= step(order, flip, A, B, _ends(order, flip, near, A, B))
        A, B = _tour_points(heads, tails, order, flip, start)
        length = float(_dist(B[:-1], A[1:]).sum())
        if not gained or length > before * (1.0 - MIN_GAIN):
            break
        before = length
    return order, flip


def _tour_points(
    heads: F64, tails: F64, order: IntArray, flip: Bools, start: F64 | None
) -> tuple[F64, F64]:
    """Entry A and exit B of positions 0..n+1 (NaN: free)."""
    a = np.where(flip[:, None], tails[order], heads[order])
    b = np.where(flip[:, None], heads[order], tails[order])
    s = np.full((1, 2), np.nan) if start is None else np.asarray(start, dtype=np.float64)[None]
    free = np.full((1, 2), np.nan)
    return np.vstack([s, a, free]), np.vstack([s, b, free])


def _dist(p: F64, q: F64) -> F64:
    """Row-wise distances; 0 where either point is free (NaN)."""
    return np.asarray(np.nan_to_num(np.hypot(*(p - q).T), nan=0.0), dtype=np.float64)


@dataclass(frozen=True)
class Near:
    """Pairs of near ends of different strokes: e, f (end ids: k < n head of k,
    else tail of k - n) and their distance d [m]."""

    e: IntArray
    f: IntArray
    d: F64

    @classmethod
    def of(cls, heads: F64, tails: F64) -> Near:
        """The near ends of strokes with these heads and tails (N, 2) [m]."""
        points, n = np.vstack([heads, tails]), len(heads)
        k = 2 * n - 1 if n <= ALL_PAIRS else NEIGHBOURS
        near = nearest_k(points, k)
        e = np.repeat(np.arange(2 * n), near.shape[1])
        f = near.ravel()
        keep = (f >= 0) & (e % n != f % n)
        e, f = e[keep], f[keep]
        return cls(e, f, np.hypot(*(points[e] - points[f]).T))


def _ends(
    order: IntArray, flip: Bools, near: Near, A: F64, B: F64
) -> tuple[IntArray, Bools, IntArray, Bools]:
    """Near pairs of ends as (position of e, e is an exit, position of f, f is an exit),
    only those closer than e's present pen-up move (no gain is possible otherwise)."""
    n = len(order)
    pos = np.empty(n, dtype=np.intp)
    pos[order] = np.arange(1, n + 1)
    flipped = np.empty(n, dtype=bool)
    flipped[order] = flip
    se, sf = near.e % n, near.f % n
    pe, xe = pos[se], (near.e >= n) != flipped[se]  # a tail not flipped, or a head flipped
    edge = _dist(B[:-1], A[1:])  # edge k: B_k -> A_{k+1}
    keep = near.d < edge[np.where(xe, pe, pe - 1)]
    sf = sf[keep]
    return pe[keep], xe[keep], pos[sf], ((near.f[keep] >= n) != flipped[sf])


def _two_opt_pass(order: IntArray, flip: Bools, A: F64, B: F64, ends: tuple) -> bool:  # type: ignore[type-arg]
    pe, xe, pf, xf = ends
    n = len(order)
    lo, hi = np.minimum(pe, pf), np.maximum(pe, pf)
    exits, entries = xe & xf, ~xe & ~xf
    i = np.concatenate([lo[exits], lo[entries] - 1, np.arange(n)])
    j = np.concatenate([hi[exits], hi[entries] - 1, np.arange(1, n + 1)])
    gain = (
        _dist(B[i], A[i + 1])
        + _dist(B[j], A[j + 1])
        - _dist(B[i], B[j])
        - _dist(A[i + 1], A[j + 1])
    )
    chosen = _disjoint(i, j, gain, n)
    for a, b in chosen:
        order[a:b] = order[a:b][::-1].copy()
        flip[a:b] = ~flip[a:b][::-1]
    return bool(chosen)


def _or_opt_pass(order: IntArray, flip: Bools, A: F64, B: F64, ends: tuple) -> bool:  # type: ignore[type-arg]
    n = len(order)
    p, q, size, r = _or_candidates(ends, n)
    e = p + size - 1
    ok = (p >= 1) & (e <= n) & ((q < p - 1) | (q > e))
    p, q, size, r, e = p[ok], q[ok], size[ok], r[ok], e[ok]
    removal = _dist(B[p - 1], A[p]) + _dist(B[e], A[e + 1]) - _dist(B[p - 1], A[e + 1])
    forward = _dist(B[q], A[p]) + _dist(B[e], A[q + 1])
    backward = _dist(B[q], B[e]) + _dist(A[p], A[q + 1])
    gain = removal + _dist(B[q], A[q + 1]) - np.where(r, backward, forward)
    chosen = _independent(p, q, size, r, gain, n)
    if chosen:
        _apply_moves(order, flip, chosen)
    return bool(chosen)


def _independent(p: IntArray, q: IntArray, size: IntArray, r: Bools, gain: F64, n: int) -> list:  # type: ignore[type-arg]
    """The improving Or-opt moves, best first, each touching positions (the moved
    strokes, their neighbours p-1 and e+1, and q, q+1) no other chosen move touches:
    their gains add up, as no stroke any of them reads is moved or turned by another."""
    touched = np.zeros(n + 2, dtype=bool)
    chosen = []
    good = np.flatnonzero(gain > 1e-12)
    for k in good[np.argsort(-gain[good], kind="stable")].tolist():
        a, b, at = int(p[k]), int(p[k] + size[k] - 1), int(q[k])
        if touched[a - 1 : b + 2].any() or touched[at] or touched[at + 1]:
            continue
        touched[a - 1 : b + 2] = True
        touched[at] = touched[at + 1] = True
        chosen.append((a, at, int(size[k]), bool(r[k])))
    return chosen


def _apply_moves(order: IntArray, flip: Bools, moves: list) -> None:  # type: ignore[type-arg]
    """Or-opt moves (p, q, L, reversed) applied at once: each run of L strokes at
    positions p.. (1-based) goes between positions q and q + 1, by sorting keys."""
    key = np.arange(1, len(order) + 1, dtype=np.float64)
    turned = flip.copy()
    for p, q, size, rev in moves:
        ranks = np.arange(1, size + 1) / (size + 1)
        key[p - 1 : p - 1 + size] = q + (ranks[::-1] if rev else ranks)
        if rev:
            turned[p - 1 : p - 1 + size] = ~turned[p - 1 : p - 1 + size]
    new = np.argsort(key, kind="stable")
    order[:] = order[new]
    flip[:] = turned[new]


def _or_candidates(ends: tuple, n: int) -> tuple[IntArray, IntArray, IntArray, Bools]:  # type: ignore[type-arg]
    """Or-opt moves (p, q, L, reversed) suggested by near ends, and every run to
    the very start or end (free ends have no neighbours to suggest them)."""
    pe, xe, pf, xf = ends
    ps, qs, ls, rs = [], [], [], []
    for size in OR_LENGTHS:
        # e is the first moved stroke's entry (p = pe) or the last one's exit (p = pe - L + 1);
        # f is where they go: after its position q if an exit, before it if an entry.
        # They go reversed when e and f are both entries or both exits.
        for e_exit, p in ((False, pe), (True, pe - size + 1)):
            for f_exit, q in ((False, pf - 1), (True, pf)):
                m = (xe == e_exit) & (xf == f_exit)
                ps.append(p[m])
                qs.append(q[m])
                rs.append(np.full(int(m.sum()), e_exit == f_exit))
                ls.append(np.full(int(m.sum()), size))
        first = np.arange(1, n - size + 2)
        for q_end, rev in ((0, False), (0, True), (n, False), (n, True)):
            ps.append(first)
            qs.append(np.full(len(first), q_end))
            rs.append(np.full(len(first), rev))
            ls.append(np.full(len(first), size))
    return (
        np.concatenate(ps),
        np.concatenate(qs),
        np.concatenate(ls),
        np.concatenate(rs).astype(bool),
    )


def move(order: IntArray, flip: Bools, p: int, q: int, L: int, rev: bool) -> None:
    """Move positions p..p+L-1 after position q (1-based positions), reversed if
    ``rev``, in place (one move; the reference of ``_apply_moves``)."""
    seg, fseg = order[p - 1 : p - 1 + L].copy(), flip[p - 1 : p - 1 + L].copy()
    if rev:
        seg, fseg = seg[::-1], ~fseg[::-1]
    if q > p:  # later: the strokes between shift back
        order[p - 1 : q - L] = order[p - 1 + L : q].copy()
        flip[p - 1 : q - L] = flip[p - 1 + L : q].copy()
        order[q - L : q], flip[q - L : q] = seg, fseg
    else:  # earlier: the strokes between shift on
        order[q + L : p - 1 + L] = order[q : p - 1].copy()
        flip[q + L : p - 1 + L] = flip[q : p - 1].copy()
        order[q : q + L], flip[q : q + L] = seg, fseg


def _disjoint(
    lo: IntArray, hi: IntArray, gain: F64, n: int, payload: IntArray | None = None
) -> list:  # type: ignore[type-arg]
    """The improving moves, best first, whose edge ranges lo..hi do not overlap:
    (lo, hi) pairs, or the payload rows if given."""
    touched = np.zeros(n + 2, dtype=bool)
    chosen = []
    good = np.flatnonzero(gain > 1e-12)
    for k in good[np.argsort(-gain[good], kind="stable")]:
        a, b = int(lo[k]), int(hi[k])
        if not touched[a : b + 1].any():
            touched[a : b + 1] = True
            chosen.append((a, b) if payload is None else tuple(int(v) for v in payload[k]))
    return chosen
