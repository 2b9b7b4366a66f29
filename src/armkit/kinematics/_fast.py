"""The closed form specialised to one model: constants bound once, plain floats.

This is the same math as ``_analytic`` (which stays the readable reference and
produces the error messages); here it is unrolled for the two common shapes
(base yaw + 3 planar joints with a pitch; 2 planar joints in a fixed plane)
so one call costs a few microseconds. Tests check that both agree.
Every candidate angle is brought into (-pi, pi] and then, if needed, moved by
one turn into its joint's limits; joints whose range exceeds a turn use the
general solver.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ..model import ArmModel
from ._family import PlanarFamily, family_of

Q = tuple[float, ...]
Ranked = list[tuple[float, Q]]  # (squared distance to the seed, solution), unsorted
FastSolver = Callable[[float, float, float, float | None, Q], tuple[Q, Ranked] | None]
_TWO_PI = 2.0 * math.pi
_SLACK = 1e-9


def fast_solver(model: ArmModel) -> FastSolver | None:
    """The model's fast closed form (cached), or None where only the general one applies."""
    if "fast" not in model._cache:
        fam = family_of(model)
        model._cache["fast"] = _make(model, fam) if fam is not None else None
    solver: FastSolver | None = model._cache["fast"]
    return solver


def _make(model: ArmModel, fam: PlanarFamily) -> FastSolver | None:
    head = (fam.base is not None) + len(fam.planar)
    if any(j.upper - j.lower > _TWO_PI for j in model.joints[:head]):
        return None
    if fam.base is not None and len(fam.planar) == 3 and fam.planar[0] == 1:
        return _yaw_three(model, fam)
    if fam.base is None and len(fam.planar) == 2 and fam.lateral == 0.0 and model.dof == 2:
        return _planar_two(model, fam)
    return None


def _links(fam: PlanarFamily) -> tuple[float, float, float, float, float, float]:
    """l1, l2 [m]; k0 = l1^2 + l2^2, k1 = 2 l1 l2; angle of link 1; bend of link 2 [rad]."""
    (l1x, l1z), (l2x, l2z) = fam.links[0], fam.links[1]
    l1, l2 = math.hypot(l1x, l1z), math.hypot(l2x, l2z)
    ang1 = math.atan2(l1z, l1x)
    return l1, l2, l1 * l1 + l2 * l2, 2.0 * l1 * l2, ang1, math.atan2(l2z, l2x) - ang1


def _yaw_three(model: ArmModel, fam: PlanarFamily) -> FastSolver:
    lo0, lo1, lo2, lo3 = (j.lower - _SLACK for j in model.joints[:4])
    hi0, hi1, hi2, hi3 = (j.upper + _SLACK for j in model.joints[:4])
    l1, l2, k0, k1, ang1, bend = _links(fam)
    c1x, c1z = fam.c1
    v3x, v3z = fam.links[2]
    s1, s2, s3 = fam.sigma
    bs, lat, az, phi0 = fam.base_sign, fam.lateral, fam.azimuth_r, fam.phi0
    c0, s0 = math.cos(phi0), math.sin(phi0)
    tp, sqrt, atan2, acos, rem = _TWO_PI, math.sqrt, math.atan2, math.acos, math.remainder
    sin, cos, pi = math.sin, math.cos, math.pi

    def solve(
        x: float, y: float, z: float, pitch: float | None, seed: Q
    ) -> tuple[Q, Ranked] | None:
        r2 = x * x + y * y - lat * lat
        if pitch is None or r2 <= 1e-24:
            return None
        rr, heading = sqrt(r2), atan2(y, x) - az
        sp, cp = sin(pitch), cos(pitch)
        if lat:
            sp = sp * rr / sqrt(r2 + lat * lat)
            norm = sqrt(sp * sp + cp * cp)
            sp, cp = sp / norm, cp / norm
        e0, e1, e2, e3 = seed[0], seed[1], seed[2], seed[3]
        rest = seed[4:]
        found: Ranked = []
        best_d, best = math.inf, seed
        if lat:
            bases = (bs * (heading - atan2(-lat, rr)), bs * (heading - atan2(-lat, -rr)))
        else:
            bases = (bs * heading, bs * (heading + pi))
        for r, ca, q0 in ((rr, cp, bases[0]), (-rr, -cp, bases[1])):
            q0 = rem(q0, tp)
            q0 = q0 + tp if q0 < lo0 else (q0 - tp if q0 > hi0 else q0)
            if not lo0 <= q0 <= hi0:
                continue
            c, s = ca * c0 + sp * s0, sp * c0 - ca * s0  # (cos, sin) of the wrist turn
            wx, wz = r - (c * v3x - s * v3z) - c1x, z - (s * v3x + c * v3z) - c1z
            cg = (wx * wx + wz * wz - k0) / k1
            if cg > 1.0 + 1e-12 or cg < -1.0 - 1e-12:
                continue
            cg = 1.0 if cg > 1.0 else (-1.0 if cg < -1.0 else cg)
            g, t = acos(cg), atan2(l2 * sqrt(1.0 - cg * cg), l1 + l2 * cg)
            aim, turn = atan2(wz, wx) - ang1, atan2(s, c)
            for gg, tt in ((g, t), (-g, -t)) if g > 1e-12 else ((g, t),):
                a1 = aim - tt
                q1 = rem(s1 * a1, tp)
                q1 = q1 + tp if q1 < lo1 else (q1 - tp if q1 > hi1 else q1)
                if not lo1 <= q1 <= hi1:
                    continue
                a2 = gg - bend
                q2 = rem(s2 * a2, tp)
                q2 = q2 + tp if q2 < lo2 else (q2 - tp if q2 > hi2 else q2)
                if not lo2 <= q2 <= hi2:
                    continue
                q3 = rem(s3 * (turn - a1 - a2), tp)
                q3 = q3 + tp if q3 < lo3 else (q3 - tp if q3 > hi3 else q3)
                if lo3 <= q3 <= hi3:
                    d0, d1, d2, d3 = q0 - e0, q1 - e1, q2 - e2, q3 - e3
                    d = d0 * d0 + d1 * d1 + d2 * d2 + d3 * d3
                    sol = (q0, q1, q2, q3, *rest) if rest else (q0, q1, q2, q3)
                    found.append((d, sol))
                    if d < best_d:
                        best_d, best = d, sol
        return (best, found) if found else None

    return solve


def _planar_two(model: ArmModel, fam: PlanarFamily) -> FastSolver:
    lo1, lo2 = (j.lower - _SLACK for j in model.joints)
    hi1, hi2 = (j.upper + _SLACK for j in model.joints)
    l1, l2, k0, k1, ang1, bend = _links(fam)
    c1x, c1z = fam.c1
    s1, s2 = fam.sigma
    ux, uy = fam.u[0], fam.u[1]
    tp, atan2, acos, sqrt, rem = _TWO_PI, math.atan2, math.acos, math.sqrt, math.remainder

    def solve(
        x: float, y: float, z: float, pitch: float | None, seed: Q
    ) -> tuple[Q, Ranked] | None:
        if pitch is not None or abs(x * ux + y * uy) > 1e-9:
            return None
        wx, wz = -uy * x + ux * y - c1x, z - c1z
        cg = (wx * wx + wz * wz - k0) / k1
        if cg > 1.0 + 1e-12 or cg < -1.0 - 1e-12:
            return None
        cg = 1.0 if cg > 1.0 else (-1.0 if cg < -1.0 else cg)
        g, t = acos(cg), atan2(l2 * sqrt(1.0 - cg * cg), l1 + l2 * cg)
        aim = atan2(wz, wx) - ang1
        found: Ranked = []
        for gg, tt in ((g, t), (-g, -t)) if g > 1e-12 else ((g, t),):
            q1 = rem(s1 * (aim - tt), tp)
            q1 = q1 + tp if q1 < lo1 else (q1 - tp if q1 > hi1 else q1)
            q2 = rem(s2 * (gg - bend), tp)
            q2 = q2 + tp if q2 < lo2 else (q2 - tp if q2 > hi2 else q2)
            if lo1 <= q1 <= hi1 and lo2 <= q2 <= hi2:
                found.append(((q1 - seed[0]) ** 2 + (q2 - seed[1]) ** 2, (q1, q2)))
        return (min(found)[1], found) if found else None

    return solve
