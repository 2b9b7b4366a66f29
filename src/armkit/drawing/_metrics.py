"""What was drawn, against the plan: the figures AxiDraw reports and two errors.

A ``PenTrace`` is the pen tip through time (the simulator records it): times,
world points and whether the tip touched the paper. ``measure`` projects it
onto the sheet and compares the pen-down parts with the plan's strokes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._distance import distance_to_strokes, hausdorff
from ._errors import DrawingError
from ._plan import DrawingPlan, SheetPlane
from ._simplify import simplify

F64 = NDArray[np.float64]
TRACE_TOLERANCE = 1e-6  # [m]: the ink is simplified this much before the Hausdorff distance


@dataclass(frozen=True)
class PenTrace:
    """The pen tip: times ``t`` (N,) [s], non-decreasing; ``points`` (N, 3) [m]
    in the world; ``down`` (N,) bool, True where the tip is on the paper."""

    t: F64
    points: F64
    down: NDArray[np.bool_]

    def __post_init__(self) -> None:
        n = len(self.t)
        if self.points.shape != (n, 3) or self.down.shape != (n,) or n < 1:
            raise DrawingError(
                f"a trace needs t (N,), points (N, 3), down (N,) with N >= 1, got "
                f"{self.t.shape}, {self.points.shape}, {self.down.shape}"
            )
        if not (np.all(np.isfinite(self.t)) and np.all(np.isfinite(self.points))):
            raise DrawingError("a trace's times and points must be finite")
        if np.any(np.diff(self.t) < 0):
            raise DrawingError("a trace's times must not decrease")


@dataclass(frozen=True)
class DrawingMetrics:
    """How a drawing went [m, s]: ``hausdorff`` and ``rms_cross_track`` compare
    the ink with the plan on the sheet; ``pen_down_length``, ``pen_up_length``
    (the tip's travel, 3-D), ``pen_lifts`` and ``duration`` as AxiDraw reports."""

    hausdorff: float
    rms_cross_track: float
    pen_down_length: float
    pen_up_length: float
    pen_lifts: int
    duration: float

    def __str__(self) -> str:
        return (
            f"Hausdorff {self.hausdorff * 1e3:.2f} mm, RMS cross-track "
            f"{self.rms_cross_track * 1e3:.2f} mm, pen down {self.pen_down_length * 1e3:.1f} mm, "
            f"pen up {self.pen_up_length * 1e3:.1f} mm, {self.pen_lifts} pen lifts, "
            f"{self.duration:.1f} s"
        )


def sheet_uv(sheet: SheetPlane, points: F64) -> tuple[F64, F64]:
    """World points (N, 3) [m] as sheet (u, v) (N, 2) [m] and height above the
    sheet (N,) [m], from ``sheet.to_world`` alone."""
    o, pu, pv = np.asarray(sheet.to_world(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])))
    u, v = pu - o, pv - o
    n = np.cross(u, v)
    n = n / np.linalg.norm(n)
    basis = np.column_stack([u, v, n])  # world = o + basis @ (u, v, h)
    uvh = np.linalg.solve(basis, (np.asarray(points) - o).T).T
    return uvh[:, :2], uvh[:, 2]


def ink(trace: PenTrace, sheet: SheetPlane, within: float = 0.0) -> list[F64]:
    """The pen-down runs of the trace on the sheet, (K, 2) each [m]; with
    ``within`` > 0 [m], simplified to that tolerance (a 1 kHz trace has many
    points a few micrometres apart)."""
    uv, _ = sheet_uv(sheet, trace.points)
    d = trace.down.astype(np.int8)
    edges = np.flatnonzero(np.diff(np.concatenate([[0], d, [0]])))
    runs = [uv[a:b] for a, b in zip(edges[::2], edges[1::2], strict=True)]
    return simplify(runs, within) if within > 0 else runs


def measure(plan: DrawingPlan, trace: PenTrace, sheet: SheetPlane) -> DrawingMetrics:
    """Compare the trace with the plan on ``sheet`` (the plan's sheet in the world)."""
    runs = ink(trace, sheet, within=TRACE_TOLERANCE)
    if not runs:
        raise DrawingError("the trace never touches the paper: nothing was drawn")
    uv, _ = sheet_uv(sheet, trace.points)
    step = np.linalg.norm(np.diff(trace.points, axis=0), axis=1)
    both_down = trace.down[:-1] & trace.down[1:]
    cross = distance_to_strokes(uv[trace.down], plan.strokes)
    return DrawingMetrics(
        hausdorff=hausdorff(list(plan.strokes), runs),
        rms_cross_track=float(np.sqrt(np.mean(cross**2))),
        pen_down_length=float(step[both_down].sum()),
        pen_up_length=float(step[~both_down].sum()),
        pen_lifts=int(np.sum(trace.down[:-1] & ~trace.down[1:]) + trace.down[-1]),
        duration=float(trace.t[-1] - trace.t[0]),
    )
