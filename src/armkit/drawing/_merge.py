"""Joining strokes whose ends meet (vpype's ``linemerge``): fewer pen lifts.

Each stroke in turn grows at its end, then at its start, by any other stroke
with an end within ``tolerance`` (reversed if need be), until no end is near.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ._grid import cell_pairs

F64 = NDArray[np.float64]
PARTNERS = 32  # ends an end may be joined to, at most (of a pile of coincident ends)
BLOCK = 1 << 16  # ends paired at once (bounds the memory of the pairs)


def merge_strokes(strokes: Sequence[F64], tolerance: float) -> list[F64]:
    """Strokes (N, 2) each [m] joined where one's end lies within ``tolerance``
    [m] of another's end; the order of the first strokes of each chain is kept."""
    n = len(strokes)
    if n < 2:
        return list(strokes)
    ends = np.vstack([np.vstack([s[0], s[-1]]) for s in strokes])  # 2i: start, 2i+1: end
    neighbours: list[list[int]] = [[] for _ in range(2 * n)]
    for first in range(0, 2 * n, BLOCK):
        block = ends[first : first + BLOCK]
        q, p = cell_pairs(block, ends, max(tolerance, 1e-12), most=PARTNERS)
        q += first
        near = (p // 2 != q // 2) & (np.sum((ends[q] - ends[p]) ** 2, axis=1) <= tolerance**2)
        for a, b in zip(q[near].tolist(), p[near].tolist(), strict=True):
            if len(neighbours[a]) < PARTNERS:
                neighbours[a].append(b)
    used = [False] * n
    out = []
    for i in range(n):
        if not used[i]:
            used[i] = True
            chain = _grow(i, neighbours, used)
            out.append(_join(strokes, chain))
    return out


def _grow(i: int, neighbours: list[list[int]], used: list[bool]) -> list[tuple[int, bool]]:
    """The chain from stroke i: (stroke, reversed) pairs in drawing order."""
    forward: list[tuple[int, bool]] = [(i, False)]
    backward: list[tuple[int, bool]] = []
    for chain, tip in ((forward, 2 * i + 1), (backward, 2 * i)):
        while True:
            nxt = next((e for e in neighbours[tip] if not used[e // 2]), None)
            if nxt is None:
                break
            j, entered_at_end = nxt // 2, nxt % 2 == 1
            used[j] = True
            chain.append((j, entered_at_end))
            tip = 2 * j + (0 if entered_at_end else 1)
    # the backward chain is walked away from stroke i: reverse it to draw towards i
    return [(j, not r) for j, r in reversed(backward)] + forward


def _join(strokes: Sequence[F64], chain: list[tuple[int, bool]]) -> F64:
    parts = [strokes[j][::-1] if r else strokes[j] for j, r in chain]
    out = [parts[0]]
    for prev, part in itertools.pairwise(parts):
        out.append(part[1:] if np.array_equal(prev[-1], part[0]) else part)
    return np.vstack(out)
