"""The damped least-squares step dq = argmin |J dq - e|^2 + lam |dq|^2, in plain floats.

Sized for 2-6 joints and 3-6 task rows: it solves in the smaller of the two
spaces (m x m with J J^T, or n x n with J^T J) by a Cholesky factorisation.
Joints marked frozen (at a limit, pushing outwards) get no motion.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np


def dls_step(
    cols: list[tuple[float, ...]], e: list[float], lam: float, free: list[bool] | None
) -> list[float]:
    """Damped least-squares joint step.

    Args:
        cols: task Jacobian J by columns: per joint, m floats [task unit / rad].
        e: task error, m floats [task unit].
        lam: damping, > 0 [task unit^2].
        free: per joint, False to keep it still; None: all free.

    Returns:
        dq: joint step [rad], one float per joint (0.0 for frozen joints).
    """
    if free is None or all(free):
        return _step(cols, e, lam)
    idx = [i for i, f in enumerate(free) if f]
    dq = [0.0] * len(free)
    if idx:
        for i, v in zip(idx, _step([cols[i] for i in idx], e, lam), strict=True):
            dq[i] = v
    return dq


def _step(cols: list[tuple[float, ...]], e: list[float], lam: float) -> list[float]:
    """The damped step for a Jacobian with every column free."""
    m, n = len(e), len(cols)
    if m == 3 and n >= 3:
        return _step3(cols, e, lam)
    if m == 4 and n >= 4:
        return _step4(cols, e, lam)
    return _step_numpy(cols, e, lam)


def _step_numpy(cols: list[tuple[float, ...]], e: list[float], lam: float) -> list[float]:
    """The damped step by numpy, for the sizes without an unrolled form."""
    Jt = np.array(cols)  # (n, m)
    if Jt.shape[1] <= Jt.shape[0]:
        A = Jt.T @ Jt
        A.flat[:: A.shape[0] + 1] += lam
        step: list[float] = (Jt @ np.linalg.solve(A, np.array(e))).tolist()
        return step
    A = Jt @ Jt.T
    A.flat[:: A.shape[0] + 1] += lam
    step = np.linalg.solve(A, Jt @ np.array(e)).tolist()
    return step


def _step3(cols: list[tuple[float, ...]], e: list[float], lam: float) -> list[float]:
    """The damped step for 3 task rows: J^T (J J^T + lam I)^-1 e, unrolled."""
    a = d = f = c = g = h = 0.0
    for x, y, z in cols:
        a += x * x
        d += x * y
        f += x * z
        c += y * y
        g += y * z
        h += z * z
    y0, y1, y2 = _solve3(((a + lam, d, f), (d, c + lam, g), (f, g, h + lam)), e)
    return [x * y0 + y * y1 + z * y2 for x, y, z in cols]


def _step4(cols: list[tuple[float, ...]], e: list[float], lam: float) -> list[float]:
    """The damped step for 4 task rows: J^T (J J^T + lam I)^-1 e, accumulated by columns."""
    s00 = s01 = s02 = s03 = s11 = s12 = s13 = s22 = s23 = s33 = 0.0
    for x, y, z, w in cols:
        s00 += x * x
        s01 += x * y
        s02 += x * z
        s03 += x * w
        s11 += y * y
        s12 += y * z
        s13 += y * w
        s22 += z * z
        s23 += z * w
        s33 += w * w
    y0, y1, y2, y3 = _solve4(
        (s00 + lam, s01, s02, s03, s11 + lam, s12, s13, s22 + lam, s23, s33 + lam), e
    )
    return [x * y0 + y * y1 + z * y2 + w * y3 for x, y, z, w in cols]


def _solve4(u: tuple[float, ...], b: Sequence[float]) -> tuple[float, float, float, float]:
    """x with A x = b for a symmetric positive definite 4 x 4 A given by its upper
    triangle u = (a00, a01, a02, a03, a11, a12, a13, a22, a23, a33): Cholesky, unrolled."""
    a00, a01, a02, a03, a11, a12, a13, a22, a23, a33 = u
    l00 = math.sqrt(max(a00, 1e-300))
    l10, l20, l30 = a01 / l00, a02 / l00, a03 / l00
    l11 = math.sqrt(max(a11 - l10 * l10, 1e-300))
    l21, l31 = (a12 - l20 * l10) / l11, (a13 - l30 * l10) / l11
    l22 = math.sqrt(max(a22 - l20 * l20 - l21 * l21, 1e-300))
    l32 = (a23 - l30 * l20 - l31 * l21) / l22
    l33 = math.sqrt(max(a33 - l30 * l30 - l31 * l31 - l32 * l32, 1e-300))
    y0 = b[0] / l00
    y1 = (b[1] - l10 * y0) / l11
    y2 = (b[2] - l20 * y0 - l21 * y1) / l22
    y3 = (b[3] - l30 * y0 - l31 * y1 - l32 * y2) / l33
    x3 = y3 / l33
    x2 = (y2 - l32 * x3) / l22
    x1 = (y1 - l21 * x2 - l31 * x3) / l11
    x0 = (y0 - l10 * x1 - l20 * x2 - l30 * x3) / l00
    return x0, x1, x2, x3


def _solve3(A: Sequence[Sequence[float]], b: Sequence[float]) -> list[float]:
    """x with A x = b for a symmetric positive definite 3 x 3 A, by the adjugate."""
    (a, d, e), (_, c, f), (_, _, g) = A
    b0, b1, b2 = b
    i00, i01, i02 = c * g - f * f, e * f - d * g, d * f - c * e
    i11, i12, i22 = a * g - e * e, d * e - a * f, a * c - d * d
    det = a * i00 + d * i01 + e * i02
    if det <= 1e-300:
        det = 1e-300
    return [
        (i00 * b0 + i01 * b1 + i02 * b2) / det,
        (i01 * b0 + i11 * b1 + i12 * b2) / det,
        (i02 * b0 + i12 * b1 + i22 * b2) / det,
    ]
