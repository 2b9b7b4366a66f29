"""Cartesian paths as sampled points: lines, arcs, circles, polylines, rectangles
and seed 001's trace of a cube's edges.

Every function returns points in the world frame [m], shape (N, 3), the first
and last exactly on the path's ends, consecutive points at most ``spacing`` [m]
apart (evenly spaced on each straight piece or arc). Arcs, circles and
rectangles lie in the horizontal plane of their centre (001 draws on the table).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError

F64 = NDArray[np.float64]
MAX_POINTS = 1_000_000  # points in one path: beyond this a spacing or a size is a mistake


def line(start: ArrayLike, end: ArrayLike, spacing: float) -> F64:
    """Straight line from ``start`` to ``end`` [m], shape (3,) each."""
    p0, p1 = point3(start, "start"), point3(end, "end")
    n = _count(math.dist(p0.tolist(), p1.tolist()), spacing)  # no overflow warning at 1e308
    s = np.linspace(0.0, 1.0, n + 1)[:, None]
    return p0 + s * (p1 - p0)


def arc(center: ArrayLike, radius: float, start_angle: float, sweep: float, spacing: float) -> F64:
    """Arc of a horizontal circle (001): ``center`` [m], ``radius`` [m], from
    ``start_angle`` [rad] (0 = +x, counter-clockwise seen from above) through
    ``sweep`` [rad] (negative = clockwise)."""
    c = point3(center, "center")
    if not (math.isfinite(radius) and radius > 0):
        raise InputError(f"radius must be > 0, got {radius}")
    if not (math.isfinite(start_angle) and math.isfinite(sweep) and sweep != 0):
        raise InputError(
            f"start angle and sweep must be finite and the sweep non-zero, got {sweep}"
        )
    n = _count(abs(sweep) * radius, spacing)
    theta = start_angle + np.linspace(0.0, sweep, n + 1)
    ring = np.column_stack([np.cos(theta), np.sin(theta), np.zeros_like(theta)])
    return c + radius * ring


def circle(center: ArrayLike, radius: float, spacing: float, start_angle: float = 0.0) -> F64:
    """Full horizontal circle, counter-clockwise, starting and ending at ``start_angle`` [rad]."""
    return arc(center, radius, start_angle, 2.0 * math.pi, spacing)


def polyline(vertices: ArrayLike, spacing: float) -> F64:
    """Straight pieces through ``vertices`` [m], shape (M, 3), M >= 2, sampled per piece."""
    v = np.asarray(vertices, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 3 or v.shape[0] < 2 or not np.all(np.isfinite(v)):
        raise InputError(f"vertices must be finite, shape (M, 3) with M >= 2, got {v.shape}")
    pieces = [line(a, b, spacing)[1:] for a, b in itertools.pairwise(v)]
    return np.vstack([v[:1], *pieces])


def rectangle(center: ArrayLike, width: float, depth: float, spacing: float) -> F64:
    """Closed horizontal rectangle: ``width`` along x, ``depth`` along y [m],
    counter-clockwise from the corner at (-x, -y)."""
    c = point3(center, "center")
    if not (width > 0 and depth > 0):
        raise InputError(f"width and depth must be > 0, got {width}, {depth}")
    w, d = width / 2.0, depth / 2.0
    corners = c + np.array([[-w, -d, 0], [w, -d, 0], [w, d, 0], [-w, d, 0], [-w, -d, 0]])
    return polyline(corners, spacing)


# 001 traces a cube's 12 edges in one stroke (retracing three of them):
# bottom square 0-1-2-3-0, then up and around the top, down and up each vertical.
CUBE_ORDER = (0, 1, 2, 3, 0, 4, 5, 1, 5, 6, 2, 6, 7, 3, 7, 4)


def cube_edges(corner: ArrayLike, size: float, spacing: float) -> F64:
    """001's cube trace: every edge of the axis-aligned cube with its lowest
    corner at ``corner`` [m] and edge ``size`` [m], in one continuous stroke."""
    c = point3(corner, "corner")
    if not size > 0:
        raise InputError(f"size must be > 0, got {size}")
    square = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
    top = square + np.array([0.0, 0.0, 1.0])
    cube = np.vstack([square, top]) * size + c
    return polyline(cube[list(CUBE_ORDER)], spacing)


def corners(points: ArrayLike, angle: float = math.radians(20.0)) -> NDArray[np.intp]:
    """Indices of the interior points where the path turns by more than ``angle``
    [rad]: where a drawing must slow to a stop. Shape (K,)."""
    p = np.asarray(points, dtype=np.float64)
    d = np.diff(p, axis=0)
    norm = np.linalg.norm(d, axis=1)
    u = d / np.where(norm > 0, norm, 1.0)[:, None]
    cos_turn = np.sum(u[:-1] * u[1:], axis=1)
    return np.flatnonzero(cos_turn < math.cos(angle)) + 1


def _count(length: float, spacing: float) -> int:
    """Pieces of at most ``spacing`` [m] along ``length`` [m]; InputError beyond MAX_POINTS."""
    if not (math.isfinite(spacing) and spacing > 0):
        raise InputError(f"spacing must be > 0, got {spacing}")
    pieces = length / spacing
    if not pieces <= MAX_POINTS:
        raise InputError(
            f"{length * 1000:.6g} mm at {spacing * 1000:g} mm spacing would be {pieces:.3g} "
            f"points; at most {MAX_POINTS}: use a larger spacing"
        )
    return max(1, math.ceil(pieces - 1e-9))


def point3(p: ArrayLike, name: str) -> F64:
    """``p`` as 3 finite coordinates [m], shape (3,); InputError naming ``name`` otherwise
    (also for things that are not numbers at all)."""
    try:
        a = np.asarray(p, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be 3 numbers [m], got {p!r}") from None
    if a.shape != (3,) or not np.all(np.isfinite(a)):
        shown = ", ".join(f"{v:g}" for v in np.ravel(a)[:6])
        raise InputError(f"{name} must be 3 finite coordinates [m], got ({shown})")
    return a
