"""The damped least-squares step dq = argmin |J dq - e|^2 + lam |dq|^2 for one target in
plain floats: the Jacobian-iteration baseline's step, and the LM reference's
(tests/numeric/lm_reference.py; production LM runs compiled, ``_lmc.c``).

It solves in the smaller of the two spaces (m x m with J J^T, or n x n with
J^T J). A Cholesky loop on floats costs about 11 us for 4 task rows and 20 us
for 6, where unrolled code costs 3 us and ``np.linalg.solve`` 10 us, so
``dls_step`` has three variants (3 task rows by the adjugate, 4 rows unrolled,
the rest by numpy); tests pin every one to the definition. Joints marked frozen
(at a limit, pushing outwards) get no motion.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]
Lane = Any  # a float (one target) or an array of shape (k,) (k targets)


def dls_step(
    cols: list[tuple[float, ...]], e: list[float], lam: float, free: list[bool] | None
) -> list[float]:
    """Damped least-squares joint step for one target.

    Args:
        cols: task Jacobian J by columns: per joint, m floats [task unit / rad].
        e: task error, m floats [task unit].
        lam: damping, > 0 [task unit^2].
        free: per joint, False to keep it still; None: all free.

    Returns:
        dq: joint step [rad], one float per joint (0.0 for frozen joints).
    """
    if free is not None and not all(free):
        idx = [i for i, f in enumerate(free) if f]
        dq = [0.0] * len(free)
        if idx:
            for i, v in zip(idx, dls_step([cols[i] for i in idx], e, lam, None), strict=True):
                dq[i] = v
        return dq
    m, n = len(e), len(cols)
    if m == 3 and n >= 3:
        return _step3(cols, e, lam)
    if m == 4 and n >= 4:
        return _step4(cols, e, lam)
    return _step_numpy(cols, e, lam)


def advance(
    q: list[float], dq: list[float], max_step: float, lo: tuple[float, ...], hi: tuple[float, ...]
) -> list[float]:
    """q + dq [rad], dq scaled down so that no joint moves more than ``max_step`` [rad],
    every joint clamped into [lo, hi]."""
    biggest = max(map(abs, dq))
    k = max_step / biggest if biggest > max_step else 1.0
    out = []
    for v, d, a, b in zip(q, dq, lo, hi, strict=True):
        t = v + k * d
        out.append(a if t < a else (b if t > b else t))
    return out


def _step3(cols: list[tuple[float, ...]], e: list[float], lam: float) -> list[float]:
    """The damped step for 3 task rows, J^T (J J^T + lam I)^-1 e, with the 3 x 3
    system solved by its adjugate."""
    a = d = f = c = g = h = 0.0
    for x, y, z in cols:
        a += x * x
        d += x * y
        f += x * z
        c += y * y
        g += y * z
        h += z * z
    a, c, h = a + lam, c + lam, h + lam
    i00, i01, i02 = c * h - g * g, f * g - d * h, d * g - c * f
    i11, i12, i22 = a * h - f * f, d * f - a * g, a * c - d * d
    det = max(a * i00 + d * i01 + f * i02, 1e-300)
    b0, b1, b2 = e
    y0 = (i00 * b0 + i01 * b1 + i02 * b2) / det
    y1 = (i01 * b0 + i11 * b1 + i12 * b2) / det
    y2 = (i02 * b0 + i12 * b1 + i22 * b2) / det
    return [x * y0 + y * y1 + z * y2 for x, y, z in cols]


def _step4(cols: list[tuple[float, ...]], e: list[float], lam: float) -> list[float]:
    """The damped step for 4 task rows, J^T (J J^T + lam I)^-1 e, with the 4 x 4
    system's Cholesky factorisation unrolled."""
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
    l00 = math.sqrt(max(s00 + lam, 1e-300))
    l10, l20, l30 = s01 / l00, s02 / l00, s03 / l00
    l11 = math.sqrt(max(s11 + lam - l10 * l10, 1e-300))
    l21, l31 = (s12 - l20 * l10) / l11, (s13 - l30 * l10) / l11
    l22 = math.sqrt(max(s22 + lam - l20 * l20 - l21 * l21, 1e-300))
    l32 = (s23 - l30 * l20 - l31 * l21) / l22
    l33 = math.sqrt(max(s33 + lam - l30 * l30 - l31 * l31 - l32 * l32, 1e-300))
    b0, b1, b2, b3 = e
    y0 = b0 / l00
    y1 = (b1 - l10 * y0) / l11
    y2 = (b2 - l20 * y0 - l21 * y1) / l22
    y3 = (b3 - l30 * y0 - l31 * y1 - l32 * y2) / l33
    x3 = y3 / l33
    x2 = (y2 - l32 * x3) / l22
    x1 = (y1 - l21 * x2 - l31 * x3) / l11
    x0 = (y0 - l10 * x1 - l20 * x2 - l30 * x3) / l00
    return [x * x0 + y * x1 + z * x2 + w * x3 for x, y, z, w in cols]


def _step_numpy(cols: list[tuple[float, ...]], e: list[float], lam: float) -> list[float]:
    """The damped step by ``np.linalg.solve``: for 6 task rows (half the time of the
    Cholesky loop on floats) and for fewer joints than task rows."""
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
