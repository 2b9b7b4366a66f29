"""Position-only closed form (3 planar joints): the pitch nearest the seed's that fits.

In the arm's plane the wrist point W (the end of link 2) lies on the circle of
the last link's length around the target; as the pitch turns, W moves round
that circle. The arm fits where W is within the two links' annulus around the
first planar joint and every joint is inside its limits. The nearest fitting
pitch is the seed's own, or one where the fit changes: where the elbow sits at
a limit or straight or folded (W then at a known distance from the shoulder),
where the shoulder sits at a limit (W at link 2's length from a fixed elbow
point), or where the wrist sits at a limit (links 2 and 3 then one rigid link,
at its length from the target) - each the meeting of two circles, in closed
form. First taken, and enough for most targets: the nearest pitch at which W
is within the annulus (``nearest_reachable``, and the chain's scalar
``nearest``). Where a joint limit refuses it, every boundary point is checked
by dot products of the links (no angle computed) and the nearest that fits is
taken (``boundary_pitch``, ``limited_pitch``).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._chain import Chain
from ._closed import SLACK, TWO_PI, best, solve
from ._family import PlanarFamily, Planes, Range, planes, turn_of
from ._forward import CHUNK, chunks, poses
from ._lanes import LANES, Ops
from ._pose import pitch_of, pitch_of_phi

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
Lane = Any  # an array of floats: one value per lane


def free_batch(chain: Chain, fam: PlanarFamily, P: F64, seed: F64) -> tuple[F64, Bool]:
    """Best solution per target [rad] (N, dof) (NaN rows where none) and ok (N,)."""
    q, ok = np.full((len(P), chain.dof), np.nan), np.zeros(len(P), dtype=bool)
    want, has = preferred(chain, seed), np.zeros(len(P), dtype=bool)
    for rows in chunks(len(P)):
        b = planes(fam, P[rows], seed[rows])
        pitch, has[rows] = nearest_reachable(chain, fam, b, want[rows])
        q[rows], ok[rows] = best(solve(chain, fam, P[rows], pitch, seed[rows], b), seed[rows])
    hard = np.flatnonzero(~ok & has)
    for s in range(0, len(hard), 4 * CHUNK):  # large lanes: boundary_pitch loops per point
        i = hard[s : s + 4 * CHUNK]
        at, found = limited_pitch(chain, fam, P[i], seed[i], want[i])
        q[i], ok[i] = best(solve(chain, fam, P[i], at, seed[i]), seed[i])
        ok[i] &= found
    return q, ok


def limited_pitch(
    chain: Chain, fam: PlanarFamily, P: F64, seed: F64, want: F64
) -> tuple[F64, Bool]:
    """Per target (N, 3) [m] the boundary pitch [rad] nearest ``want`` (N,) at which the arm
    fits, over every base branch the base allows, and whether there is one (N,)."""
    b = planes(fam, P, seed)
    count = len(b.r) // len(P)
    with np.errstate(invalid="ignore", divide="ignore"):  # NaN: no boundary point there
        gap, at = boundary_pitch(chain, fam, b.r, b.z, b.rho, np.tile(want, count))
    gap = b.per_target(np.where(base_fits(chain, fam, b.q0) & ~np.tile(b.bad, count), gap, np.inf))
    k = np.argmin(gap, axis=0)
    cols = np.arange(len(P))
    return b.per_target(at)[k, cols], np.isfinite(gap[k, cols])


def preferred(chain: Chain, seed: F64) -> F64:
    """The pitch [rad] of the tool at each seed (N, dof), shape (N,), from the base axis."""
    if (seed == chain.home_a).all():
        return np.full(len(seed), chain.home_pitch)
    T = poses(chain, seed)
    if chain.shift is not None:  # measured from the base axis
        T[:, 0, 3] -= chain.shift[0]
        T[:, 1, 3] -= chain.shift[1]
    return np.asarray(pitch_of(T), dtype=np.float64)


def nearest_reachable(chain: Chain, fam: PlanarFamily, b: Planes, want: F64) -> tuple[F64, Bool]:
    """Per target the pitch [rad] nearest ``want`` at which the wrist point is within reach
    of the first two links (and the base inside its limits), and whether there is one.
    With u the turn from where the wrist point is nearest the shoulder, d^2 = D^2 + L3^2 -
    2 D L3 cos u: within reach for cos u in [c_lo, c_hi], so the nearest u is a clamp."""
    lo_d, hi_d = chain.wrist_reach
    (v3x, v3z), (c1x, c1z) = fam.links[2], fam.c1
    l3, ang3 = math.hypot(v3x, v3z), math.atan2(v3z, v3x)
    ck, sk, cp, sp = math.cos(ang3), math.sin(ang3), math.cos(fam.phi0), math.sin(fam.phi0)
    tx, tz = b.r - c1x, b.z - c1z
    big = np.sqrt(tx * tx + tz * tz)
    k = np.maximum(2.0 * big * l3, 1e-300)
    c_lo, c_hi = (big * big + l3 * l3 - hi_d * hi_d) / k, (big * big + l3 * l3 - lo_d * lo_d) / k
    empty = (c_lo > 1.0 + 1e-12) | (c_hi < -1.0 - 1e-12) | ~base_fits(chain, fam, b.q0)
    cs, ss = (tx * ck + tz * sk) / big, (tz * ck - tx * sk) / big  # where W is nearest
    wants = np.tile(want, len(b.r) // len(want))
    c, s, _ = turn_of(fam, wants, b.r, b.rho)
    cu, su = c * cs + s * ss, s * cs - c * ss  # u at want
    clamped = np.clip(cu, c_lo, c_hi)
    with np.errstate(invalid="ignore"):
        su = np.where(clamped == cu, su, np.copysign(np.sqrt(1.0 - clamped * clamped), su))
    ct, st = clamped * cs - su * ss, su * cs + clamped * ss  # the turn at u
    pitch = np.where(
        clamped == cu, wants, pitch_of_phi(ct * cp - st * sp, st * cp + ct * sp, b.r, b.rho)
    )
    gap = b.per_target(
        np.where(empty | np.tile(b.bad, len(b.r) // len(want)), np.inf, _gap(pitch, wants))
    )
    i, cols = np.argmin(gap, axis=0), np.arange(len(want))
    found = np.isfinite(gap[i, cols])
    return np.where(found, b.per_target(pitch)[i, cols], want), found


def boundary_pitch(
    chain: Chain, fam: PlanarFamily, r: Lane, z: Lane, rho: Lane, want: Lane, ops: Ops = LANES
) -> tuple[Lane, Lane]:
    """Per lane - one base branch of a target: plane radius r (signed), height z and
    horizontal distance rho [m] - the boundary point that fits nearest ``want`` [rad]: how
    far (a number that grows with the distance; inf where none fits) and its pitch [rad].
    Written over lanes (``_lanes``): arrays with ``LANES``, one branch in floats with
    ``FLOATS`` (the scalar solver's fallback, ``_closed_scalar.limited``)."""
    tx, tz = r - fam.c1[0], z - fam.c1[1]
    (v3x, v3z), l3 = fam.links[2], math.hypot(*fam.links[2])
    if l3 < 1e-12:  # no last link: no boundary circle (as ``_boundary_fast``)
        return math.inf + 0.0 * tx, 0.0 * tx
    k = fam.phi0 - math.atan2(v3z, v3x)  # the approach's angle in the plane less link 3's
    ck, sk, ranges = math.cos(k) / l3, math.sin(k) / l3, chain.ranges

    def pitch(x: Lane, z: Lane) -> Lane:  # the pitch [rad] with link 3 at (x, z) [m]
        return pitch_of_phi(x * ck - z * sk, x * sk + z * ck, r, rho, ops)

    axis = (rho < 1e-12) | (abs(r) < 1e-12)
    if fam.lateral or (axis.any() if isinstance(axis, np.ndarray) else axis):
        wx3 = wz3 = None  # the pitch's own distance from want
    else:  # pitch = +-(approach angle) + a constant: nearest where link 3 is nearest want's
        c, s = ops.where(r > 0, 1.0, -1.0) * ops.cos(want), ops.sin(want)  # the approach
        wx3, wz3 = c * math.cos(k) + s * math.sin(k), s * math.cos(k) - c * math.sin(k)
    gap, bx, bz = math.inf + 0.0 * tx, 0.0 * tx, 0.0 * tx
    for wx, wz, ex, ez in _boundaries(chain, fam, tx, tz, ops):
        l3x, l3z = tx - wx, tz - wz
        d = _gap(pitch(l3x, l3z), want, ops) if wx3 is None else -(l3x * wx3 + l3z * wz3)
        better = d < gap
        if better is False:  # one branch in floats, and no nearer: no need to check it
            continue
        better = better & _fits(ranges, (ex, ez), (wx - ex, wz - ez), (l3x, l3z))
        w = ops.where
        gap, bx, bz = w(better, d, gap), w(better, l3x, bx), w(better, l3z, bz)
    return gap, pitch(bx, bz)


def _gap(pitch: Lane, want: Lane, ops: Ops = LANES) -> Lane:
    """|pitch - want| [rad] round the circle, for pitches and ``want`` in [-pi, pi]."""
    d = abs(pitch - want)
    return ops.where(d > math.pi, TWO_PI - d, d)


def base_fits(chain: Chain, fam: PlanarFamily, q0: Lane, ops: Ops = LANES) -> Lane:
    """Where base angles q0 [rad] are inside the base's limits by whole turns (as ``wrap``)."""
    if fam.base is None:
        return q0 == q0  # everywhere, as a bool or an array of them (q0 is 0 there)
    lo, hi = chain.lower[fam.base], chain.upper[fam.base]  # a turn or more: always true
    return q0 - TWO_PI * ops.floor((q0 - lo + SLACK) / TWO_PI) <= hi + SLACK


def _boundaries(
    chain: Chain, fam: PlanarFamily, tx: Lane, tz: Lane, ops: Ops
) -> Iterator[tuple[Lane, Lane, Lane, Lane]]:
    """Where the fit can change along the wrist circle about T = (tx, tz) [m]: per boundary
    point the wrist point W and the elbow point E, x and z each [m] (NaN where none)."""
    (v1x, v1z), (v2x, v2z), (v3x, v3z) = fam.links
    l1, l2, l3 = fam.l1, fam.l2, math.hypot(v3x, v3z)
    (j1, j2, j3), (s1, s2, s3) = fam.planar, fam.sigma
    lo, hi = sorted((s2 * chain.lower[j2] + fam.bend, s2 * chain.upper[j2] + fam.bend))
    for b in {lo, hi} | {b for b in (0.0, math.pi) if (b - lo) % TWO_PI <= hi - lo}:
        x, y = l1 + l2 * math.cos(b), l2 * math.sin(b)  # elbow at a limit, straight or folded:
        d = math.hypot(x, y)  # W at distance d, E turned from W by a constant
        if d > 1e-12:
            for wx, wz in _meet(0.0, 0.0, d, tx, tz, l3, ops):
                yield wx, wz, (x * wx + y * wz) * (l1 / d / d), (x * wz - y * wx) * (l1 / d / d)
    for a in (chain.lower[j1], chain.upper[j1]):  # shoulder at a limit: E fixed
        ex, ez = (
            math.cos(s1 * a) * v1x - math.sin(s1 * a) * v1z,
            math.sin(s1 * a) * v1x + math.cos(s1 * a) * v1z,
        )
        for wx, wz in _meet(ex, ez, l2, tx, tz, l3, ops):
            yield wx, wz, ex + 0.0 * wx, ez + 0.0 * wz
    for a in (chain.lower[j3], chain.upper[j3]):  # wrist at a limit: links 2 and 3 make one
        c, s = math.cos(s3 * a), math.sin(s3 * a)  # rigid link U; R U = T - E, R turns link 2
        ux, uz = v2x + c * v3x - s * v3z, v2z + s * v3x + c * v3z
        u2 = ux * ux + uz * uz
        for ex, ez in _meet(0.0, 0.0, l1, tx, tz, math.sqrt(u2), ops):
            rc, rs = (ux * (tx - ex) + uz * (tz - ez)) / u2, (ux * (tz - ez) - uz * (tx - ex)) / u2
            yield ex + rc * v2x - rs * v2z, ez + rs * v2x + rc * v2z, ex, ez


def _meet(
    ax: float, az: float, ra: float, bx: Lane, bz: Lane, rb: float, ops: Ops
) -> tuple[tuple[Lane, Lane], tuple[Lane, Lane]]:
    """Both points where the circle about (ax, az) of radius ra meets the circle about
    (bx, bz) of radius rb [m] (NaN where they do not)."""
    dx, dz = bx - ax, bz - az
    d2 = dx * dx + dz * dz + 1e-300
    along = (d2 + ra * ra - rb * rb) / (2.0 * d2)  # along the centre line, per its length
    h2 = ra * ra / d2 - along * along
    h = ops.where(h2 >= -1e-12, ops.sqrt(abs(h2)), math.nan)
    mx, mz = ax + along * dx, az + along * dz
    return (mx - h * dz, mz + h * dx), (mx + h * dz, mz - h * dx)


def _fits(ranges: tuple[Range, ...], *links: tuple[Lane, Lane]) -> Lane:
    """Where every planar joint is inside its range, given links 1 (= E), 2 and 3 as vectors
    [m]: each link's dot product with the direction of its range's middle."""
    ok = links[2][0] == links[2][0]  # not NaN: the boundary point exists
    for k, cm, sm, least in ranges:
        (bx, bz), (px, pz) = links[k], (links[k - 1] if k else (1.0, 0.0))
        ok = ok & ((px * cm - pz * sm) * bx + (px * sm + pz * cm) * bz >= least)
    return ok
