"""Fewer points within a tolerance: Ramer–Douglas–Peucker on every stroke.

Every point dropped lies within ``tolerance`` of the chord that replaces it,
so the simplified stroke stays within ``tolerance`` of the original. The ends
are always kept.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


def simplify(strokes: Sequence[F64], tolerance: float) -> list[F64]:
    """Each stroke (N, 2) [m] with the points RDP keeps at ``tolerance`` [m]."""
    return [s if len(s) < 3 else s[_rdp_keep(s, tolerance)] for s in strokes]


def _rdp_keep(s: F64, tolerance: float) -> NDArray[np.bool_]:
    """Mask of the points kept, shape (N,)."""
    keep = np.zeros(len(s), dtype=bool)
    keep[0] = keep[-1] = True
    stack = [(0, len(s) - 1)]
    while stack:
        i, j = stack.pop()
        if j - i < 2:
            continue
        d = _distances(s[i + 1 : j], s[i], s[j])
        k = int(np.argmax(d))
        if d[k] > tolerance:
            m = i + 1 + k
            keep[m] = True
            stack.append((i, m))
            stack.append((m, j))
    return keep


def _distances(p: F64, a: F64, b: F64) -> F64:
    """Distance of points p (M, 2) from the segment a-b [m]."""
    ab = b - a
    denom = float(ab @ ab)
    if denom == 0.0:
        return np.asarray(np.linalg.norm(p - a, axis=1), dtype=np.float64)
    t = np.clip((p - a) @ ab / denom, 0.0, 1.0)
    return np.asarray(np.linalg.norm(p - (a + t[:, None] * ab), axis=1), dtype=np.float64)
