"""The closed form for one target in plain floats: the scalar fast path of ``_closed``.

The solver binds a family arm's constants as locals of a closure: the math of
``_closed`` for one target at one pitch, a few microseconds a call (without a
pitch: ``_closed_free``). Tests pin it to the vectorised form.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from .._errors import Reason
from ._family import PITCH_TOLERANCE, PlanarFamily, planes, turn_of
from ._lanes import FLOATS
from ._pose import pitch_of_phi

Q = tuple[float, ...]
Found = list[tuple[float, Q]]  # (squared joint distance to the seed, solution)
_TWO_PI = 2.0 * math.pi
_SLACK = 1e-9
_STRAIGHT = 1.0 - 1e-12  # cos of the elbow nearer 1 than this: straight (or folded); the
# tool point moves by 1e-13 m, and one elbow is found where rounding would make two


@dataclass
class Misses:
    """Why candidates failed: reasons, and (excess [rad], joint, value [rad]) per limit miss."""

    reasons: list[Reason] = field(default_factory=list)
    violations: list[tuple[float, int, float]] = field(default_factory=list)


FixedSolver = Callable[[float, float, float, "float | None", Q, "Misses | None"], Found]


def miss(v: float, lo: float, hi: float, j: int, misses: Misses) -> None:
    """Record in ``misses`` that joint j's angle v [rad] cannot turn into [lo, hi]: its
    excess and its value at the turn nearest the range."""
    near = 0.5 * (lo + hi) + math.remainder(v - 0.5 * (lo + hi), _TWO_PI)
    misses.violations.append((max(lo - near, near - hi), j, near))


def fixed_solver(fam: PlanarFamily, lower: Q, upper: Q) -> FixedSolver:
    """solve(x, y, z, pitch, seed, misses): every solution at ``pitch`` [rad] (None: 2
    planar joints, the pitch follows) for the tool point (x, y, z) [m], unsorted."""
    base, three, dof = fam.base, len(fam.planar) == 3, len(lower)
    (j1, j2, j3), (s1, s2, s3) = (*fam.planar, 0)[:3], (*fam.sigma, 0.0)[:3]
    lo1, hi1, lo2, hi2, lo3, hi3 = lower[j1], upper[j1], lower[j2], upper[j2], lower[j3], upper[j3]
    lo0, hi0 = (lower[base], upper[base]) if base is not None else (0.0, 0.0)
    l1, l2, ang1, bend, phi0 = fam.l1, fam.l2, fam.ang1, fam.bend, fam.phi0
    k0, k1 = l1 * l1 + l2 * l2, 2.0 * l1 * l2
    (c1x, c1z), (v3x, v3z) = fam.c1, fam.links[2] if three else (0.0, 0.0)
    lat, az, bs, c0, s0 = fam.lateral, fam.azimuth_r, fam.base_sign, math.cos(phi0), math.sin(phi0)
    (ux, uy, uz), pi, tp = fam.u, math.pi, _TWO_PI
    cos, sin, acos, atan2, sqrt = math.cos, math.sin, math.acos, math.atan2, math.sqrt
    rem, floor, straight, ptol = math.remainder, math.floor, _STRAIGHT, PITCH_TOLERANCE
    yaw3 = base == 0 and fam.planar == (1, 2, 3)  # the common layout: joints in order
    pair = base is None and fam.planar == (0, 1) and dof == 2
    yaw2 = base == 0 and fam.planar == (1, 2) and dof == 3  # a spherical wrist's arm

    def solve(
        x: float, y: float, z: float, pitch: float | None, seed: Q, misses: Misses | None
    ) -> Found:
        found: Found = []
        rho = sqrt(x * x + y * y)
        branches: tuple[tuple[float, float], ...] | Reason
        plain = base is not None and not lat and rho >= 1e-12  # off the axis, no offset
        if plain:  # the common case, inline
            heading = bs * (atan2(y, x) - az)
            branches = ((rho, heading), (-rho, heading + bs * pi))
        elif base is None and abs(x * ux + y * uy + z * uz - lat) <= 1e-9:
            branches = ((ux * y - uy * x, 0.0),)
        else:  # on the base axis, a lateral offset: the vectorised reference's branches
            branches = _ways(fam, x, y, z, seed)
        if three and rho < 1e-12 and abs(pitch or 0.0) > pi / 2 + 1e-12:
            branches = "pitch"  # on the base axis the pitch is within -90..90 deg
        if isinstance(branches, str):
            if misses is not None:
                misses.reasons.append(branches)
            return found
        pv = pitch if three and pitch is not None else 0.0
        sp, cp = sin(pv), cos(pv)
        given = not three and pitch is not None  # 2 planar joints: check the pitch they give
        for r, q0 in branches:
            if base is not None and not lo0 <= q0 <= hi0:  # by whole turns into the limits
                w = q0 - tp * floor((q0 - lo0 + _SLACK) / tp)
                if w > hi0 + _SLACK:
                    if misses is not None:
                        miss(q0, lo0, hi0, base, misses)
                    continue
                q0 = lo0 if w < lo0 else (hi0 if w > hi0 else w)
            wx, wz, turn = r - c1x, z - c1z, 0.0
            if three:  # the wrist point, from the plane turn that gives the pitch
                if plain or not (lat or rho < 1e-12 or -1e-12 < r < 1e-12):  # ``turn_of``
                    ca = cp if r > 0.0 else -cp
                    c, s, turn = (
                        ca * c0 + sp * s0,
                        sp * c0 - ca * s0,
                        (pv if r > 0.0 else pi - pv) - phi0,
                    )
                else:  # a lateral offset, or on the base axis
                    c, s, turn = turn_of(fam, pv, r, rho, FLOATS)
                wx, wz = wx - (c * v3x - s * v3z), wz - (s * v3x + c * v3z)
            cg = (wx * wx + wz * wz - k0) / k1
            if not -1.0 - 1e-12 <= cg <= 1.0 + 1e-12:
                if misses is not None:
                    misses.reasons.append("too_far" if cg > 0 else "too_close")
                continue
            cg = 1.0 if cg > straight else (-1.0 if cg < -straight else cg)  # see _STRAIGHT
            g = acos(cg)
            t = atan2(l2 * sqrt(1.0 - cg * cg), l1 + l2 * cg)
            aim = atan2(wz, wx) - ang1
            for gg, tt in ((g, t), (-g, -t)) if g > 1e-12 else ((g, t),):
                a1, a2 = aim - tt, gg - bend
                if given:
                    got = pitch_of_phi(cos(phi0 + a1 + a2), sin(phi0 + a1 + a2), r, rho, FLOATS)
                    if abs(rem(got - pitch, tp)) > ptol:  # type: ignore[operator]
                        if misses is not None:
                            misses.reasons.append("pitch")
                        continue
                v1, v2 = s1 * a1, s2 * a2
                if not lo1 <= v1 <= hi1:  # as the base: inline, a call costs more than this
                    w = v1 - tp * floor((v1 - lo1 + _SLACK) / tp)
                    if w > hi1 + _SLACK:
                        if misses is not None:
                            miss(v1, lo1, hi1, j1, misses)
                        continue
                    v1 = lo1 if w < lo1 else (hi1 if w > hi1 else w)
                if not lo2 <= v2 <= hi2:
                    w = v2 - tp * floor((v2 - lo2 + _SLACK) / tp)
                    if w > hi2 + _SLACK:
                        if misses is not None:
                            miss(v2, lo2, hi2, j2, misses)
                        continue
                    v2 = lo2 if w < lo2 else (hi2 if w > hi2 else w)
                if three:
                    v3 = s3 * (turn - a1 - a2)
                    if not lo3 <= v3 <= hi3:
                        w = v3 - tp * floor((v3 - lo3 + _SLACK) / tp)
                        if w > hi3 + _SLACK:
                            if misses is not None:
                                miss(v3, lo3, hi3, j3, misses)
                            continue
                        v3 = lo3 if w < lo3 else (hi3 if w > hi3 else w)
                    if yaw3:
                        d0, d1, d2, d3 = q0 - seed[0], v1 - seed[1], v2 - seed[2], v3 - seed[3]
                        sol = (q0, v1, v2, v3, *seed[4:]) if dof > 4 else (q0, v1, v2, v3)
                        found.append((d0 * d0 + d1 * d1 + d2 * d2 + d3 * d3, sol))
                        continue
                elif pair:
                    d1, d2 = v1 - seed[0], v2 - seed[1]
                    found.append((d1 * d1 + d2 * d2, (v1, v2)))
                    continue
                elif yaw2:
                    d0, d1, d2 = q0 - seed[0], v1 - seed[1], v2 - seed[2]
                    found.append((d0 * d0 + d1 * d1 + d2 * d2, (q0, v1, v2)))
                    continue
                q = list(seed)
                q[j1], q[j2] = v1, v2
                if three:
                    q[j3] = v3
                if base is not None:
                    q[base] = q0
                found.append(
                    (sum((a - b) * (a - b) for a, b in zip(q, seed, strict=True)), tuple(q))
                )
        return found

    return solve


def _ways(
    fam: PlanarFamily, x: float, y: float, z: float, seed: Q
) -> tuple[tuple[float, float], ...] | Reason:
    """(plane radius r (signed) [m], base angle q0 [rad]) per base branch of the target
    (x, y, z) [m] (``_family.planes``), or why there is none."""
    rho, lat, bs = math.hypot(x, y), fam.lateral, fam.base_sign
    if fam.base is not None and rho >= 1e-12:  # ``planes`` off the base axis, in floats
        heading = math.atan2(y, x) - fam.azimuth_r
        if not lat:  # as ``solve``'s ``plain``
            return (rho, bs * heading), (-rho, bs * heading + bs * math.pi)
        r2 = rho * rho - lat * lat
        if r2 < -1e-18:
            return "too_close"
        r = math.sqrt(max(r2, 0.0))
        return (r, bs * (heading - math.atan2(-lat, r))), (
            -r,
            bs * (heading - math.atan2(-lat, -r)),
        )
    b = planes(fam, np.array([[x, y, z]]), np.array([seed]))
    if b.bad[0]:
        return "off_plane" if fam.base is None else "too_close"
    return tuple(zip(b.r.tolist(), b.q0.tolist(), strict=True))
