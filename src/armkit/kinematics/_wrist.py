"""The spherical-wrist family: a base yaw, two parallel shoulder and elbow axes, then three
wrist axes meeting in a point (the PUMA 560 and most 6R arms), solved exactly for a full
pose with up to eight branches.

The wrist centre C lies on all three wrist axes, so its place depends on the first three
joints only: C = p + R c_t (c_t: C in the tool frame) is a yaw + 2-planar position problem,
``_closed_fast``'s, with C as the tool point (two base and two elbow branches). The
rotation of any revolute chain is R(q) = exp(w_0 q_0) ... exp(w_5 q_5) R(0) with w_i the
signed axes at q = 0; the first three give A = Rot(w_0, q_0) Rot(u, q_1 + k q_2) (u = w_1,
k = w_1 . w_2 = +-1), leaving exp(w_3 t_3) exp(w_4 t_4) exp(w_5 t_5) = G = A^T R R(0)^T:
Paden-Kahan subproblem 2 (where G takes w_5, two branches), then subproblem 1 for t_5.
The wrist is singular where G w_5 lies along w_3: t_3 is then free and keeps the seed's.
Recognised from the axes at q = 0 (``wrist_family``), whatever the frames; tests pin
the scalar solver (``wrist_solver``) to the vectorised one (``_wrist_batch``) and
every branch to FK.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from ._closed_fast import FixedSolver, Found, Misses, Q, fixed_solver
from ._family import PlanarFamily, detect

F64 = NDArray[np.float64]
Vec3 = tuple[float, float, float]
V = tuple[Any, Any, Any]  # a vector of floats, or of lanes (arrays (N,)) per component
WristSolver = Callable[[float, float, float, tuple[float, ...], Q, "Misses | None"], Found]
_EPS = 1e-9
_TWO_PI = 2.0 * math.pi
WHY = "is not a spherical-wrist 6R arm (base yaw, 2 parallel axes, 3 axes meeting in a point)"


@dataclass(frozen=True)
class WristFamily:
    """The geometry of a spherical-wrist arm.

    Attributes:
        arm: the yaw + 2-planar family with the wrist centre as its tool point.
        centre: the wrist centre in the tool frame, c_t [m].
        R0: the tool rotation at q = 0, row-major.
        w: the six signed joint axes at q = 0 (unit vectors).
        k: w_1 . w_2 (+1 or -1).
        shift: the base axis's (x, y) off the world origin [m] (``Chain.shift``).
    """

    arm: PlanarFamily
    centre: Vec3
    R0: tuple[float, ...]
    w: tuple[Vec3, ...]
    k: float
    shift: tuple[float, float]


def wrist_family(
    axes: list[Vec3], points: list[Vec3], tool: F64, shift: tuple[float, float]
) -> WristFamily | str:
    """The geometry from the signed axes, a point on each and the tool pose (4, 4) at
    q = 0 (points and tool moved by ``shift``); or one line saying why not."""
    if len(axes) != 6:
        return WHY
    a, o = np.array(axes, dtype=float), np.array(points, dtype=float)
    P = [np.eye(3) - np.outer(v, v) for v in a[3:]]  # projections off each wrist axis
    A = sum(P, np.zeros((3, 3)))
    if abs(np.linalg.det(A)) < 1e-12:
        return WHY  # wrist axes all parallel
    c = np.linalg.solve(A, sum((Pk @ ok for Pk, ok in zip(P, o[3:], strict=True)), np.zeros(3)))
    if max(float(np.linalg.norm(Pk @ (c - ok))) for Pk, ok in zip(P, o[3:], strict=True)) > _EPS:
        return WHY
    if abs(a[3] @ a[4]) > 1 - 1e-6 or abs(a[4] @ a[5]) > 1 - 1e-6:
        return WHY
    u = a[1]
    T = np.eye(4)
    T[:3, 0], T[:3, 3] = np.cross([0.0, 0.0, 1.0], u), c
    arm = detect(axes[:3], points[:3], T)
    if not isinstance(arm, PlanarFamily) or arm.base != 0 or arm.planar != (1, 2):
        return WHY
    R, p = tool[:3, :3], tool[:3, 3]
    c_t = R.T @ (c - p)
    w = tuple((float(x), float(y), float(z)) for x, y, z in a)
    return WristFamily(
        arm, (float(c_t[0]), float(c_t[1]), float(c_t[2])), tuple(R.ravel().tolist()), w,
        float(np.sign(a[1] @ a[2])), shift,
    )  # fmt: skip


def wrist_solver(wf: WristFamily, lower: Q, upper: Q) -> WristSolver:
    """solve(x, y, z, R, seed, misses): every solution for the tool point (x, y, z) [m] and
    rotation R (row-major 9 floats), unsorted, as (squared distance to seed, q) pairs."""
    position: FixedSolver = fixed_solver(wf.arm, lower[:3], upper[:3])
    (w0, w1, _, _, _, w5), k, (cx, cy, cz), (bx, by) = wf.w, wf.k, wf.centre, wf.shift
    R0 = wf.R0
    s0 = w0[2]  # the base axis is +z or -z
    r5 = _constants(wf).r5
    # R0^T w5 and R0^T r5: G v = A^T R (R0^T v)
    a5 = tuple(R0[i] * w5[0] + R0[3 + i] * w5[1] + R0[6 + i] * w5[2] for i in range(3))
    ar = tuple(R0[i] * r5[0] + R0[3 + i] * r5[1] + R0[6 + i] * r5[2] for i in range(3))
    lo3, lo4, lo5, hi3, hi4, hi5 = lower[3], lower[4], lower[5], upper[3], upper[4], upper[5]
    wide3, wide4, wide5 = (upper[j] - lower[j] > _TWO_PI - 2e-9 for j in (3, 4, 5))  # 2 ways in
    cos, sin = math.cos, math.sin
    # Work in the world turned about z so that w1 is +y (B): the base turn stays a turn
    # about z and the plane's turn becomes one about y, a 2D turn in x-z
    ux, uy = w1[0], w1[1]  # w1 is horizontal
    angles = _float_angles(_turned(_constants(wf), ux, uy))

    def solve(
        x: float, y: float, z: float, R: tuple[float, ...], seed: Q, misses: Misses | None
    ) -> Found:
        r00, r01, r02, r10, r11, r12, r20, r21, r22 = R
        px = x + r00 * cx + r01 * cy + r02 * cz - bx
        py = y + r10 * cx + r11 * cy + r12 * cz - by
        pz = z + r20 * cx + r21 * cy + r22 * cz
        mx, my = r00 * a5[0] + r01 * a5[1] + r02 * a5[2], r10 * a5[0] + r11 * a5[1] + r12 * a5[2]
        md = (uy * mx - ux * my, ux * mx + uy * my, r20 * a5[0] + r21 * a5[1] + r22 * a5[2])
        mx, my = r00 * ar[0] + r01 * ar[1] + r02 * ar[2], r10 * ar[0] + r11 * ar[1] + r12 * ar[2]
        mg = (uy * mx - ux * my, ux * mx + uy * my, r20 * ar[0] + r21 * ar[1] + r22 * ar[2])
        found: Found = []
        e0, e1, e2, e3, e4, e5 = seed
        last, bd, bg = math.nan, md, mg
        for _, (q0, q1, q2) in position(px, py, pz, None, seed[:3], misses):
            if q0 != last:  # A^T: undo the base turn (shared by both elbows), then the plane's
                last, c, s = q0, cos(s0 * q0), sin(s0 * q0)
                bd = (c * md[0] + s * md[1], c * md[1] - s * md[0], md[2])
                bg = (c * mg[0] + s * mg[1], c * mg[1] - s * mg[0], mg[2])
            cu, su = cos(q1 + k * q2), sin(q1 + k * q2)  # turn back about y
            d = (cu * bd[0] - su * bd[2], bd[1], su * bd[0] + cu * bd[2])
            g = (cu * bg[0] - su * bg[2], bg[1], su * bg[0] + cu * bg[2])
            b = (q0 - e0) ** 2 + (q1 - e1) ** 2 + (q2 - e2) ** 2
            for a3, a4, a5_ in angles(d, g, e3):
                v3 = a3 if lo3 <= a3 <= hi3 and not wide3 else _fit(a3, lo3, hi3, e3)
                v4 = a4 if lo4 <= a4 <= hi4 and not wide4 else _fit(a4, lo4, hi4, e4)
                v5 = a5_ if lo5 <= a5_ <= hi5 and not wide5 else _fit(a5_, lo5, hi5, e5)
                if v3 is None or v4 is None or v5 is None:
                    if misses is not None:
                        misses.reasons.append("joint_limit")
                    continue
                dist = b + (v3 - e3) ** 2 + (v4 - e4) ** 2 + (v5 - e5) ** 2
                found.append((dist, (q0, q1, q2, v3, v4, v5)))
        return found

    return solve


class WristConstants(NamedTuple):
    """The wrist axes w3, w4, w5 at q = 0 and what subproblem 2 needs of them: w3 . w4,
    w4 . w5, (w3 . w4)^2 - 1, w3 x w4 and its squared length; r5, t5: w5's normal plane."""

    w3: Vec3
    w4: Vec3
    w5: Vec3
    s34: float
    c45: float
    den: float
    x34: Vec3
    n34: float
    r5: Vec3
    t5: Vec3


def _turned(k: WristConstants, ux: float, uy: float) -> WristConstants:
    """The constants in the frame turned about z that takes the unit (ux, uy, 0) to +y."""

    def b(v: Vec3) -> Vec3:
        return (uy * v[0] - ux * v[1], ux * v[0] + uy * v[1], v[2])

    return k._replace(w3=b(k.w3), w4=b(k.w4), w5=b(k.w5), x34=b(k.x34), r5=b(k.r5), t5=b(k.t5))


def _constants(wf: WristFamily) -> WristConstants:
    """The wrist's constants (``WristConstants``)."""
    w3, w4, w5 = wf.w[3:]
    s34, x34 = _dot(w3, w4), _cross(w3, w4)
    r5 = _unit(_cross(w5, (1.0, 0.0, 0.0) if abs(w5[0]) < 0.9 else (0.0, 1.0, 0.0)))
    n34 = _dot(x34, x34)
    return WristConstants(
        w3, w4, w5, s34, _dot(w4, w5), s34 * s34 - 1.0, x34, n34, r5, _cross(w5, r5)
    )


def _fit(v: float, lo: float, hi: float, near: float) -> float | None:
    """v [rad] moved by whole turns into [lo, hi] (clamped within 1e-9), the turn nearest
    ``near`` [rad] where two fit (a joint of a turn or more); None where none does."""
    w = near + math.remainder(v - near, _TWO_PI)
    if not lo - 1e-9 <= w <= hi + 1e-9:
        w += _TWO_PI if w < lo else -_TWO_PI
        if not lo - 1e-9 <= w <= hi + 1e-9:
            return None
    return lo if w < lo else (hi if w > hi else w)


def _float_angles(
    k: WristConstants,
) -> Callable[[Vec3, Vec3, float], list[tuple[float, float, float]]]:
    """``_wrist_angles`` for one target in floats, with the constants bound (the scalar
    solver's fast path; tests pin it to the lanes). A wrist whose w3 and w5 are parallel
    at q = 0 and perpendicular to w4 (the PUMA's) gets its second branch by the identity
    Rot(w3, a) Rot(w4, b) Rot(w5, c) = Rot(w3, a + pi) Rot(w4, -b) Rot(w5, c + pi)."""
    (w3x, w3y, w3z), (w4x, w4y, w4z), (w5x, w5y, w5z) = k.w3, k.w4, k.w5
    (x34x, x34y, x34z), (r5x, r5y, r5z), (t5x, t5y, t5z) = k.x34, k.r5, k.t5
    s34, c45, den, n34 = k.s34, k.c45, k.den, k.n34
    y45x, y45y, y45z = _cross(k.w4, k.w5)
    flip = _flips(k)
    cos, sin, atan2, sqrt, pi, rem = (
        math.cos,
        math.sin,
        math.atan2,
        math.sqrt,
        math.pi,
        math.remainder,
    )

    def angles(d: Vec3, g: Vec3, seed3: float) -> list[tuple[float, float, float]]:
        dx, dy, dz = d
        d3 = w3x * dx + w3y * dy + w3z * dz
        ex, ey, ez = dy * w3z - dz * w3y, dz * w3x - dx * w3z, dx * w3y - dy * w3x  # d x w3
        off = ex * ex + ey * ey + ez * ez  # |d off w3|^2 (see ``_wrist_angles``)
        alpha, beta = (s34 * c45 - d3) / den, (s34 * d3 - c45) / den
        gamma2 = (
            off if flip else (1.0 - alpha * alpha - beta * beta - 2.0 * alpha * beta * s34) / n34
        )
        if gamma2 < -1e-9:
            return []
        singular = off <= 1e-18
        gamma = sqrt(gamma2) if gamma2 > 0.0 else 0.0
        out = []
        for sign in (1.0,) if singular or gamma2 <= 1e-18 or flip else (1.0, -1.0):
            if singular:  # w5 along w3: t3 free, the seed's
                cx, cy, cz, t3 = dx, dy, dz, seed3
            else:
                cx = alpha * w3x + beta * w4x + sign * gamma * x34x
                cy = alpha * w3y + beta * w4y + sign * gamma * x34y
                cz = alpha * w3z + beta * w4z + sign * gamma * x34z
                t3 = atan2(cx * ex + cy * ey + cz * ez, cx * dx + cy * dy + cz * dz - d3 * d3)
            t4 = atan2(
                cx * y45x + cy * y45y + cz * y45z, cx * w5x + cy * w5y + cz * w5z - c45 * c45
            )
            c, s = cos(t3), -sin(t3)  # h = Rot(w4, -t4) Rot(w3, -t3) g, Rodrigues inline
            gx, gy, gz = g
            kk = (1.0 - c) * (w3x * gx + w3y * gy + w3z * gz)
            hx = c * gx + s * (w3y * gz - w3z * gy) + kk * w3x
            hy = c * gy + s * (w3z * gx - w3x * gz) + kk * w3y
            hz = c * gz + s * (w3x * gy - w3y * gx) + kk * w3z
            c, s = cos(t4), -sin(t4)
            kk = (1.0 - c) * (w4x * hx + w4y * hy + w4z * hz)
            gx = c * hx + s * (w4y * hz - w4z * hy) + kk * w4x
            gy = c * hy + s * (w4z * hx - w4x * hz) + kk * w4y
            gz = c * hz + s * (w4x * hy - w4y * hx) + kk * w4z
            t5 = atan2(t5x * gx + t5y * gy + t5z * gz, r5x * gx + r5y * gy + r5z * gz)
            out.append((t3, t4, t5))
            if flip and not singular:
                out.append((rem(t3 + pi, 2.0 * pi), -t4, rem(t5 + pi, 2.0 * pi)))
        return out

    return angles


def _flips(k: WristConstants) -> bool:
    """Whether w3 and w5 are parallel at q = 0 and perpendicular to w4 (see ``_float_angles``)."""
    return abs(abs(_dot(k.w3, k.w5)) - 1.0) < 1e-12 and abs(k.s34) < 1e-12 and abs(k.c45) < 1e-12


def _dot(a: V, b: V) -> Any:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a: V, b: V) -> V:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _unit(a: Vec3) -> Vec3:
    n = math.sqrt(_dot(a, a))
    return (a[0] / n, a[1] / n, a[2] / n)
