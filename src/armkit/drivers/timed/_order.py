"""In which order to turn the joints one after another so the arm does not
sweep through the table: the order whose path keeps the arm highest (its
lowest point first, then its average height while travelling), which gives
000's rules of thumb -- elbow first when going home, lift before travelling,
lower last."""

from __future__ import annotations

import itertools

import numpy as np
from numpy.typing import NDArray

from ..._errors import UnreachableError

F64 = NDArray[np.float64]
SAMPLES = 8  # poses checked per joint turn
TABLE_TOLERANCE_M = 0.005  # how far below z = 0 a point may be estimated to go


def safe_order(
    q0: F64,
    q1: F64,
    lengths: tuple[float, float, float],
    shoulder_height: float,
    table: bool = True,
) -> list[int]:
    """Indices of the joints that differ between ``q0`` and ``q1`` [rad], shape (4,),
    in the order to turn them one at a time. ``table=False``: the best order even if
    all of them dip below z = 0 (the arm stands at a table's edge, as for calibration).

    Raises:
        UnreachableError: every order takes the arm through the table (reason ``"table"``).
    """
    moving = [j for j in range(4) if abs(q1[j] - q0[j]) > 1e-9]
    best: tuple[float, float] | None = None
    best_order: list[int] = []
    for order in itertools.permutations(moving):
        score = _score(q0, q1, list(order), lengths, shoulder_height)
        if best is None or score > best:
            best, best_order = score, list(order)
    if table and best is not None and best[0] < -TABLE_TOLERANCE_M:
        raise UnreachableError(
            f"every joint order takes the arm {-best[0] * 1000:.0f} mm below the table; "
            "choose a higher target or move through an intermediate point",
            reason="table",
        )
    return best_order


def _score(
    q0: F64, q1: F64, order: list[int], lengths: tuple[float, float, float], h: float
) -> tuple[float, float]:
    """(lowest height [m] rounded to 1 mm, mean height weighted by angle turned)."""
    q = np.array(q0, dtype=float)
    lows, means, weights = [lowest_point(q, lengths, h)], [], []
    for j in order:
        path = np.repeat(q[None, :], SAMPLES, axis=0)
        path[:, j] = np.linspace(q[j], q1[j], SAMPLES)
        heights = np.array([lowest_point(p, lengths, h) for p in path])
        lows.append(float(heights.min()))
        means.append(float(heights.mean()))
        weights.append(abs(q1[j] - q[j]))
        q[j] = q1[j]
    mean = float(np.average(means, weights=weights)) if weights else 0.0
    return (round(min(lows), 3), mean)


def lowest_point(q: F64, lengths: tuple[float, float, float], shoulder_height: float) -> float:
    """Height [m] above the table of the lowest of elbow, wrist and grip point at pose ``q``."""
    phi = np.cumsum(np.asarray(q, dtype=float)[1:4])
    z = shoulder_height + np.cumsum(np.asarray(lengths) * np.cos(phi))
    return float(z.min())
