"""The closed form at one pitch for one target, with the chain's constants bound once.

``fixed_solver`` returns a function of the target alone whose every constant
(link lengths, limits, signs) is a local of its closure: the same math as the
vectorised reference (``_closed``), in plain floats, a few microseconds a call.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from .._errors import Reason
from ._family import PlanarFamily
from ._planar import phi_for_pitch, pitch_for_phi, planes

Q = tuple[float, ...]
Found = list[tuple[float, Q]]  # (squared joint distance to the seed, solution)
_TWO_PI = 2.0 * math.pi
_SLACK = 1e-9


@dataclass
class Misses:
    """Why candidates failed: reasons, and (excess [rad], joint, value [rad]) per limit miss."""

    reasons: list[Reason] = field(default_factory=list)
    violations: list[tuple[float, int, float]] = field(default_factory=list)


FixedSolver = Callable[[float, float, float, "float | None", Q, "Misses | None"], Found]


def wrap_into(angle: float, lower: float, upper: float) -> float | None:
    """``angle`` plus a whole number of turns inside [lower, upper] [rad], or None."""
    if lower - _SLACK <= angle <= upper + _SLACK:
        return min(max(angle, lower), upper)
    wrapped = lower + (angle - lower) % _TWO_PI
    if wrapped <= upper + _SLACK:
        return min(wrapped, upper)
    if wrapped - _TWO_PI >= lower - _SLACK:
        return max(wrapped - _TWO_PI, lower)
    return None


def miss(misses: Misses | None, i: int, value: float, lo: float, hi: float) -> None:
    """Record joint i's miss: its angle [rad] at the turn nearest its range, and the excess."""
    if misses is not None:
        nearest = 0.5 * (lo + hi) + math.remainder(value - 0.5 * (lo + hi), _TWO_PI)
        misses.violations.append((max(lo - nearest, nearest - hi), i, nearest))


def fixed_solver(fam: PlanarFamily, lower: Q, upper: Q) -> FixedSolver:
    """solve(x, y, z, pitch, seed, misses): every solution at ``pitch`` [rad] (None:
    2 planar joints, the pitch follows) for the tool point (x, y, z) [m], unsorted."""
    base, three = fam.base, len(fam.planar) == 3
    (j1, j2, j3), (s1, s2, s3) = (*fam.planar, 0)[:3], (*fam.sigma, 0.0)[:3]
    lo1, hi1, lo2, hi2, lo3, hi3 = lower[j1], upper[j1], lower[j2], upper[j2], lower[j3], upper[j3]
    lo0, hi0 = (lower[base], upper[base]) if base is not None else (0.0, 0.0)
    l1, l2, ang1, bend, phi0 = fam.l1, fam.l2, fam.ang1, fam.bend, fam.phi0
    k0, k1 = l1 * l1 + l2 * l2, 2.0 * l1 * l2
    (c1x, c1z), (v3x, v3z) = fam.c1, fam.links[2] if three else (0.0, 0.0)
    cos, sin, acos, atan2 = math.cos, math.sin, math.acos, math.atan2

    lat, az, bs, c0, s0 = fam.lateral, fam.azimuth_r, fam.base_sign, math.cos(phi0), math.sin(phi0)
    ux, uy, uz = fam.u
    rem, tp, sqrt, pi = math.remainder, _TWO_PI, math.sqrt, math.pi
    simple, rest = base == 0 and fam.planar == (1, 2, 3), len(lower) > 4
    pair = base is None and fam.planar == (0, 1) and len(lower) == 2
    # ranges within (-pi, pi] + a turn: an angle inside them has no other turn inside
    narrow1, narrow2, narrow3 = (
        -pi <= lo and hi <= pi for lo, hi in ((lo1, hi1), (lo2, hi2), (lo3, hi3))
    )

    def wrap(v: float, lo: float, hi: float, j: int, misses: Misses | None) -> float | None:
        """v moved by whole turns into [lo, hi] (given it is outside), or None (recorded)."""
        w = lo + (v - lo) % tp
        if w > hi + _SLACK:
            w -= tp
            if w < lo - _SLACK:
                miss(misses, j, v, lo, hi)
                return None
        return lo if w < lo else (hi if w > hi else w)

    def generic(
        x: float, y: float, z: float, pitch: float | None, seed: Q
    ) -> list[tuple[float, float, float, float, float, float]] | str:
        """(r, rho, base angle, cos turn, sin turn, turn) per base branch, by ``planes``."""
        out = planes(fam, x, y, z, seed[base] if base is not None else 0.0)
        if isinstance(out, str):
            return out
        turns = []
        for r, rho, q0 in out:
            turn = phi_for_pitch(pitch or 0.0, r, rho) - phi0 if three else 0.0
            turns.append((r, rho, q0, cos(turn), sin(turn), turn))
        return turns

    def solve(
        x: float, y: float, z: float, pitch: float | None, seed: Q, misses: Misses | None
    ) -> Found:
        found: Found = []
        rho2 = x * x + y * y
        r2 = rho2 - lat * lat
        if base is None and not three and pitch is None:  # a planar pair in a fixed plane
            if abs(x * ux + y * uy + z * uz - lat) > 1e-9:
                if misses is not None:
                    misses.reasons.append("off_plane")
                return found
            branches: list[tuple[float, float, float, float, float, float]] | str = [
                (-uy * x + ux * y, sqrt(rho2), 0.0, 1.0, 0.0, 0.0)
            ]
        elif base is not None and three and r2 > 1e-24:  # facing the target, and over the shoulder
            rr, rho = sqrt(r2), sqrt(rho2)
            heading = atan2(y, x) - az
            sp, cp = sin(pitch or 0.0), cos(pitch or 0.0)
            if lat:
                sp = sp * rr / rho
                norm = sqrt(sp * sp + cp * cp)
                sp, cp = sp / norm, cp / norm
                qa, qb = bs * (heading - atan2(-lat, rr)), bs * (heading - atan2(-lat, -rr))
            else:
                qa, qb = bs * heading, bs * (heading + pi)
            ca, sa = cp * c0 + sp * s0, sp * c0 - cp * s0
            cb, sb = -cp * c0 + sp * s0, sp * c0 + cp * s0
            branches = [
                (rr, rho, qa, ca, sa, atan2(sa, ca)),
                (-rr, rho, qb, cb, sb, atan2(sb, cb)),
            ]
        else:
            branches = generic(x, y, z, pitch, seed)
        if isinstance(branches, str):
            if misses is not None:
                misses.reasons.append("off_plane" if branches == "off_plane" else "too_close")
            return found
        for r, rho, q0, c, s, turn in branches:
            if base is not None and not lo0 <= q0 <= hi0:
                w0 = wrap(q0, lo0, hi0, base, misses)
                if w0 is None:
                    continue
                q0 = w0
            wx, wz = r - c1x, z - c1z
            if three:
                if rho < 1e-12 and abs(pitch or 0.0) > math.pi / 2 + 1e-12:
                    if misses is not None:
                        misses.reasons.append("pitch")  # on the base axis: within +-90 deg
                    continue
                wx, wz = wx - (c * v3x - s * v3z), wz - (s * v3x + c * v3z)
            cg = (wx * wx + wz * wz - k0) / k1
            if not -1.0 - 1e-12 <= cg <= 1.0 + 1e-12:
                if misses is not None:
                    misses.reasons.append("too_far" if cg > 0 else "too_close")
                continue
            cg = 1.0 if cg > 1.0 else (-1.0 if cg < -1.0 else cg)
            g = acos(cg)
            t = atan2(l2 * sqrt(1.0 - cg * cg), l1 + l2 * cg)
            aim = atan2(wz, wx) - ang1
            for gg, tt in ((g, t), (-g, -t)) if g > 1e-12 else ((g, t),):
                a1, a2 = aim - tt, gg - bend
                if not three and pitch is not None:
                    got = pitch_for_phi(phi0 + a1 + a2, r, rho)
                    if abs(rem(got - pitch, tp)) > 1e-7:
                        if misses is not None:
                            misses.reasons.append("pitch")
                        continue
                v1 = s1 * a1
                if narrow1:
                    v1 = v1 - tp if v1 > pi else (v1 + tp if v1 < -pi else v1)
                if not lo1 <= v1 <= hi1:
                    w = wrap(v1, lo1, hi1, j1, misses)
                    if w is None:
                        continue
                    v1 = w
                v2 = s2 * a2
                if narrow2:
                    v2 = v2 - tp if v2 > pi else (v2 + tp if v2 < -pi else v2)
                if not lo2 <= v2 <= hi2:
                    w = wrap(v2, lo2, hi2, j2, misses)
                    if w is None:
                        continue
                    v2 = w
                if three:
                    v3 = s3 * (turn - a1 - a2)
                    if narrow3:
                        v3 = v3 - tp if v3 > pi else (v3 + tp if v3 < -pi else v3)
                    if not lo3 <= v3 <= hi3:
                        w = wrap(v3, lo3, hi3, j3, misses)
                        if w is None:
                            continue
                        v3 = w
                    if simple:  # base yaw + 3 planar joints first: the common layout
                        d0, d1, d2, d3 = q0 - seed[0], v1 - seed[1], v2 - seed[2], v3 - seed[3]
                        sol = (q0, v1, v2, v3, *seed[4:]) if rest else (q0, v1, v2, v3)
                        found.append((d0 * d0 + d1 * d1 + d2 * d2 + d3 * d3, sol))
                        continue
                elif pair:  # a planar pair alone: the 2-joint arm
                    d1, d2 = v1 - seed[0], v2 - seed[1]
                    found.append((d1 * d1 + d2 * d2, (v1, v2)))
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


NearestPitch = Callable[[float, float, float, float, float], "float | None"]


def nearest_pitch_solver(
    fam: PlanarFamily, reach: tuple[float, float], base_range: tuple[float, float]
) -> NearestPitch | None:
    """nearest(x, y, z, want, seed0): the pitch [rad] nearest ``want`` at which the wrist point
    is within ``reach`` = (d_min, d_max) [m] of the first planar joint (None: nowhere), for a
    base yaw + 3 planar joints with no lateral offset (else None: use the general path).

    There the pitch is the plane turn plus a constant (minus it, reaching back), and the wrist
    point's distance d from the shoulder follows d^2 = D^2 + L3^2 - 2 D L3 cos(turn - shift):
    the turns within reach are |turn - shift| in [u_in, u_out], so the nearest is a clamp.
    """
    if fam.base is None or len(fam.planar) != 3 or fam.lateral != 0.0:
        return None
    (c1x, c1z), (v3x, v3z) = fam.c1, fam.links[2]
    l3, ang3, phi0, az, bs = (
        math.hypot(v3x, v3z),
        math.atan2(v3z, v3x),
        fam.phi0,
        fam.azimuth_r,
        fam.base_sign,
    )
    lo2, hi2 = reach[0] ** 2, reach[1] ** 2
    lo0, hi0 = base_range
    pi, tp, cos, acos, atan2, rem = (
        math.pi,
        _TWO_PI,
        math.cos,
        math.acos,
        math.atan2,
        math.remainder,
    )

    full = hi0 - lo0 >= tp - 1e-9  # the base turns all the way: both branches always face
    c_k, s_k = math.cos(phi0 - ang3), math.sin(phi0 - ang3)

    def faces(q0: float) -> bool:
        return (
            full or lo0 - 1e-9 <= rem(q0 - 0.5 * (lo0 + hi0), tp) + 0.5 * (lo0 + hi0) <= hi0 + 1e-9
        )

    def nearest(x: float, y: float, z: float, want: float, seed0: float) -> float | None:
        r = math.hypot(x, y)
        if r < 1e-9:
            return want  # on the base axis: the solvers decide
        heading = atan2(y, x) - az
        cw, sw = cos(want), math.sin(want)
        # cos and sin of want's turn less the wrist link's angle, facing (+) and reaching back (-)
        ways = (
            (r, 1.0, bs * heading, cw * c_k + sw * s_k, sw * c_k - cw * s_k),
            (-r, -1.0, bs * (heading + pi), -(cw * c_k - sw * s_k), sw * c_k + cw * s_k),
        )
        todo = []
        for rr, sign, q0, ca, sa in ways:
            if not faces(q0):
                continue  # the base cannot face this way
            tx, tz = rr - c1x, z - c1z
            big2 = tx * tx + tz * tz
            big = math.sqrt(big2)
            k = 2.0 * big * l3
            if k < 1e-15:
                if lo2 - 1e-12 <= big2 + l3 * l3 <= hi2 + 1e-12:
                    return want
                continue
            c_lo, c_hi = (big2 + l3 * l3 - hi2) / k, (big2 + l3 * l3 - lo2) / k
            if c_lo > 1.0 + 1e-12 or c_hi < -1.0 - 1e-12:
                continue
            if c_lo <= (ca * tx + sa * tz) / big <= c_hi:  # the wrist within reach at want
                return want
            todo.append((sign, tx, tz, c_lo, c_hi))
        best, gap = None, math.inf
        for sign, tx, tz, c_lo, c_hi in todo:  # the nearest turn within reach: a clamp
            shift = atan2(tz, tx) - ang3
            u0 = rem((want if sign > 0 else pi - want) - phi0 - shift, tp)
            u_in, u_out = acos(min(1.0, c_hi)), acos(max(-1.0, c_lo))
            u = min(max(abs(u0), u_in), u_out)
            u = u if u0 >= 0.0 else -u
            if abs(u - u0) < gap:
                turn = u + shift + phi0
                best, gap = rem(turn if sign > 0 else pi - turn, tp), abs(u - u0)
        return best

    return nearest
