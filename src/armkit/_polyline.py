"""How far a travelled path strays from the ideal one: distance to a polyline (used by
``armkit.motion``, which exports it, and by the timed driver's waypoint planner)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._errors import InputError

F64 = NDArray[np.float64]
_CHUNK = 1024


def distance_to_polyline(points: ArrayLike, polyline: ArrayLike) -> F64:
    """Distance [m] from each of ``points``, shape (N, 3), to the nearest point of
    the polyline through ``polyline``, shape (M, 3), M >= 2. Returns shape (N,)."""
    x = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    v = np.asarray(polyline, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 3 or v.shape[0] < 2:
        raise InputError(f"polyline must have shape (M, 3) with M >= 2, got {v.shape}")
    a, ab = v[:-1], np.diff(v, axis=0)
    length2 = np.maximum(np.sum(ab * ab, axis=1), 1e-30)
    out = np.empty(x.shape[0])
    for lo in range(0, x.shape[0], _CHUNK):
        rel = x[lo : lo + _CHUNK, None, :] - a[None]
        s = np.clip(np.sum(rel * ab, axis=2) / length2, 0.0, 1.0)
        gap = rel - s[..., None] * ab
        out[lo : lo + _CHUNK] = np.sqrt(np.min(np.sum(gap * gap, axis=2), axis=1))
    return out
