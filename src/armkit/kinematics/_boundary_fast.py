"""``_pitch_range.boundary_pitch`` for one base branch in plain floats, with the arm's
circles bound once: the scalar position-only solver's path where a joint limit refuses
the pitch it chose first (``_closed_scalar.limited``). Tests pin it to the lanes.

Every boundary point is where the wrist circle about the target T (radius L3) meets
another circle: the elbow at a limit, straight or folded (about the shoulder), the
shoulder at a limit (about a fixed elbow point E), the wrist at a limit (links 2 and 3
one rigid link U: the elbow circle about the shoulder meets the circle of |U| about T).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ._family import PlanarFamily, Range
from ._lanes import FLOATS
from ._pose import pitch_of_phi

Q = tuple[float, ...]
Boundary = Callable[[float, float, float, float], tuple[float, float]]
_TWO_PI = 2.0 * math.pi


def boundary_solver(
    fam: PlanarFamily, lower: Q, upper: Q, ranges: tuple[Range, ...]
) -> Boundary | None:
    """boundary(r, z, rho, want) -> (gap, pitch [rad]): ``boundary_pitch`` for one branch
    (plane radius r (signed), height z, horizontal distance rho [m]; want [rad]); None
    where the last link has no length (the tool point on the wrist axis: no circle)."""
    (c1x, c1z), ((v1x, v1z), (v2x, v2z), (v3x, v3z)) = fam.c1, fam.links
    l1, l2, l3 = fam.l1, fam.l2, math.hypot(v3x, v3z)
    if l3 < 1e-12:
        return None
    (j1, j2, j3), (s1, s2, s3) = fam.planar, fam.sigma
    k = fam.phi0 - math.atan2(v3z, v3x)
    cK, sK, ck, sk = math.cos(k), math.sin(k), math.cos(k) / l3, math.sin(k) / l3
    lo, hi = sorted((s2 * lower[j2] + fam.bend, s2 * upper[j2] + fam.bend))
    elbows = []  # (d^2, x l1 / d^2, y l1 / d^2): W at d from the shoulder, E turned from W
    for b in {lo, hi} | {b for b in (0.0, math.pi) if (b - lo) % _TWO_PI <= hi - lo}:
        x, y = l1 + l2 * math.cos(b), l2 * math.sin(b)
        if math.hypot(x, y) > 1e-12:
            elbows.append((x * x + y * y, x * l1 / (x * x + y * y), y * l1 / (x * x + y * y)))
    shoulders = [
        (
            math.cos(s1 * a) * v1x - math.sin(s1 * a) * v1z,
            math.sin(s1 * a) * v1x + math.cos(s1 * a) * v1z,
        )
        for a in (lower[j1], upper[j1])
    ]
    wrists = []  # U = link 2 + link 3 turned by the wrist's limit
    for a in (lower[j3], upper[j3]):
        c, s = math.cos(s3 * a), math.sin(s3 * a)
        ux, uz = v2x + c * v3x - s * v3z, v2z + s * v3x + c * v3z
        wrists.append((ux, uz, ux * ux + uz * uz))
    l1sq, l2sq, l3sq, lateral = l1 * l1, l2 * l2, l3 * l3, fam.lateral
    checks = tuple((k, cm, sm, least) for k, cm, sm, least in ranges)

    def boundary(r: float, z: float, rho: float, want: float) -> tuple[float, float]:
        tx, tz = r - c1x, z - c1z
        by_pitch = bool(lateral) or rho < 1e-12 or -1e-12 < r < 1e-12
        c = math.cos(want) if r > 0 else -math.cos(want)
        s = math.sin(want)
        wx3, wz3 = c * cK + s * sK, s * cK - c * sK  # link 3's direction at want
        found: list[tuple[float, float, float, float]] = []  # W, E per point
        for d2, ax, ay in elbows:
            for wx, wz in _meet(tx, tz, 0.0, 0.0, d2, l3sq):
                found.append((wx, wz, ax * wx + ay * wz, ax * wz - ay * wx))
        for ex, ez in shoulders:
            for wx, wz in _meet(tx, tz, ex, ez, l2sq, l3sq):
                found.append((wx, wz, ex, ez))
        for ux, uz, u2 in wrists:
            for ex, ez in _meet(tx, tz, 0.0, 0.0, l1sq, u2):
                rc, rs = (
                    (ux * (tx - ex) + uz * (tz - ez)) / u2,
                    (ux * (tz - ez) - uz * (tx - ex)) / u2,
                )
                found.append((ex + rc * v2x - rs * v2z, ez + rs * v2x + rc * v2z, ex, ez))
        ranked = []  # (gap, order, point): nearest first, ties in the reference's order
        for i, (wx, wz, ex, ez) in enumerate(found):
            lx, lz = tx - wx, tz - wz
            if by_pitch:
                d = abs(pitch_of_phi(lx * ck - lz * sk, lx * sk + lz * ck, r, rho, FLOATS) - want)
                d = _TWO_PI - d if d > math.pi else d
            else:
                d = -(lx * wx3 + lz * wz3)
            ranked.append((d, i, lx, lz, ex, ez, wx, wz))
        ranked.sort()
        for d, _, lx, lz, ex, ez, wx, wz in ranked:
            links = ((ex, ez), (wx - ex, wz - ez), (lx, lz))
            for kk, cm, sm, least in checks:
                (ax, az), (px, pz) = links[kk], (links[kk - 1] if kk else (1.0, 0.0))
                if not (px * cm - pz * sm) * ax + (px * sm + pz * cm) * az >= least:
                    break
            else:
                return d, pitch_of_phi(lx * ck - lz * sk, lx * sk + lz * ck, r, rho, FLOATS)
        return math.inf, pitch_of_phi(0.0, 0.0, r, rho, FLOATS)

    return boundary


def _meet(
    tx: float, tz: float, ax: float, az: float, ra2: float, rb2: float
) -> tuple[tuple[float, float], ...]:
    """Where the circle about (ax, az) of squared radius ra2 meets the circle about (tx, tz)
    of squared radius rb2 [m]: both points, or none (``_pitch_range._meet``)."""
    dx, dz = tx - ax, tz - az
    d2 = dx * dx + dz * dz + 1e-300
    along = (d2 + ra2 - rb2) / (2.0 * d2)
    h2 = ra2 / d2 - along * along
    if not h2 >= -1e-12:
        return ()
    h = math.sqrt(abs(h2))
    mx, mz = ax + along * dx, az + along * dz
    return (mx - h * dz, mz + h * dx), (mx + h * dz, mz - h * dx)
