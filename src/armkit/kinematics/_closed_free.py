"""Closed-form IK for one target without a pitch (base yaw + 3 planar joints): the pitch
nearest the seed's at which the wrist point is within reach, in plain floats.

The scalar fast path of ``_pitch_range.nearest_reachable`` and ``free_batch`` (the
pitch, then ``_closed_fast``'s solver at it); the tests pin it to them
(``test_pitch_range``: 10,000 targets).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ._closed_fast import FixedSolver, Found, Q
from ._family import PlanarFamily
from ._pose import pitch_scalar
from ._state import State

FreeSolver = Callable[[float, float, float, Q], "Found | None"]
AtHome = tuple[Q, float, State, tuple[float, float]]  # home [rad], its pitch [rad], FK, shift [m]
_TWO_PI = 2.0 * math.pi


def free_solver(
    fam: PlanarFamily, solve: FixedSolver, reach: tuple[float, float],
    base_range: tuple[float, float], at_home: AtHome,
) -> FreeSolver:  # fmt: skip
    """free(x, y, z, seed): position only (base yaw + 3 planar joints), every solution at the
    pitch nearest the seed's at which the wrist point is within the wrist ``reach`` =
    (d_min, d_max) [m] of the first planar joint, unsorted: [] where a joint limit refuses
    that pitch, None where no pitch is within reach. With u the turn of link 3 from the
    line shoulder-target, d^2 = D^2 + L3^2 - 2 D L3 cos u: within reach for cos u in
    [c_lo, c_hi], so the nearest pitch is the seed's or a clamp of cos u
    (``_pitch_range.nearest_reachable`` for one target), then ``solve`` at it."""
    home, home_pitch = at_home[0], at_home[1]
    if fam.base is None or len(fam.planar) != 3 or fam.lateral != 0.0:
        return lambda x, y, z, seed: solve(x, y, z, seed_pitch(seed, at_home), seed, None)
    (c1x, c1z), (v3x, v3z), phi0 = fam.c1, fam.links[2], fam.phi0
    l3, ang3, az, bs = math.hypot(v3x, v3z), math.atan2(v3z, v3x), fam.azimuth_r, fam.base_sign
    lo2, hi2, l3sq = reach[0] ** 2, reach[1] ** 2, l3 * l3
    (lo0, hi0), pi, tp, inf = base_range, math.pi, _TWO_PI, math.inf
    atan2, acos, rem, sqrt = math.atan2, math.acos, math.remainder, math.sqrt
    cos, sin = math.cos, math.sin
    mid, full = 0.5 * (lo0 + hi0), hi0 - lo0 >= _TWO_PI - 1e-9  # full: both ways always face
    c_k, s_k, l3_2 = math.cos(phi0 - ang3), math.sin(phi0 - ang3), 2.0 * l3

    def ways(cw: float, sw: float) -> tuple[tuple[float, float, float], ...]:
        """Per way, facing the target (+1) and turned back (-1), the cos and sin of link 3's
        direction at the pitch whose cos and sin are cw, sw."""
        return (1.0, cw * c_k + sw * s_k, sw * c_k - cw * s_k), (
            -1.0,
            sw * s_k - cw * c_k,
            sw * c_k + cw * s_k,
        )

    at_home_ways = ways(math.cos(home_pitch), math.sin(home_pitch))

    def free(x: float, y: float, z: float, seed: Q) -> Found | None:
        if seed is home or seed == home:
            want, each_way = home_pitch, at_home_ways
        else:
            want = seed_pitch(seed, at_home)
            each_way = ways(cos(want), sin(want))
        rho = sqrt(x * x + y * y)
        if rho < 1e-9:
            return solve(x, y, z, want, seed, None)  # on the base axis: at the seed's pitch
        tz = z - c1z
        tz2, out = tz * tz + l3sq, []
        heading = 0.0 if full else bs * (atan2(y, x) - az)
        # per way, link 3's direction at want: within reach where 2 L3 D cos u lies in
        # [D^2 + L3^2 - hi^2, D^2 + L3^2 - lo^2]
        for way, ca, sa in each_way:
            if not full:
                q0 = heading if way > 0.0 else heading + bs * pi
                if not lo0 - 1e-9 <= rem(q0 - mid, tp) + mid <= hi0 + 1e-9:
                    continue
            tx = way * rho - c1x
            a, d = tx * tx + tz2, l3_2 * (ca * tx + sa * tz)
            if a - hi2 <= d <= a - lo2:
                return solve(x, y, z, want, seed, None)  # within reach at want
            out.append((way, tx, a, d, ca, sa))
        best, pick = inf, (0.0, 0.0, 0.0)  # else the nearest turn within reach: a clamp
        for way, tx, a, d, ca, sa in out:
            big = sqrt(a - l3sq)
            k = l3_2 * big  # cos u = d / k, to be within [a - hi^2, a - lo^2] / k
            e = a - hi2 if d < a - hi2 else a - lo2
            if k < 1e-15 or not -k <= e <= k:
                continue  # no u within reach in this way
            cu, c = e / k, d / k
            gap = abs(acos(cu) - acos(c if -1.0 <= c <= 1.0 else (1.0 if c > 0 else -1.0)))
            if gap < best:
                su = sqrt(1.0 - cu * cu) if sa * tx - ca * tz >= 0.0 else -sqrt(1.0 - cu * cu)
                best, pick = gap, (way, cu * tx - su * tz, su * tx + cu * tz)
        if best == inf:
            return None
        way, dx, dz = pick  # link 3's direction there; the approach is phi0 - ang3 from it
        phi = atan2(dz, dx) - ang3 + phi0
        return solve(x, y, z, rem(phi if way > 0.0 else pi - phi, tp), seed, None)

    return free


def seed_pitch(seed: Q, at_home: AtHome) -> float:
    """The tool's pitch [rad] at joint angles ``seed`` [rad], measured from the base axis."""
    home, home_pitch, state, (bx, by) = at_home
    if seed is home or seed == home:
        return home_pitch
    st = state(list(seed))
    return pitch_scalar(st.R[0], (st.p[0] - bx, st.p[1] - by))
