"""Position-only closed form (3 planar joints): the pitch nearest the seed's that fits.

In the arm's plane the wrist point W (the end of link 2) lies on the circle of
the last link's length around the target; as the pitch turns, W moves round
that circle. The arm fits where W is within the two links' annulus around the
first planar joint and every joint is inside its limits. The nearest fitting
pitch is the seed's own, or one where the fit changes: where W's distance from
the shoulder reaches a radius of the annulus or of the elbow's limits, where
the shoulder sits at a limit (W is then at link 2's length from a fixed elbow
point), or where the wrist sits at a limit (links 2 and 3 then form one rigid
link, at its length from the target) - each the meeting of two circles, in
closed form. First taken, and enough for most targets: the nearest pitch at
which W is within the annulus (``nearest_reachable``). Where a joint limit
refuses it, every boundary point is checked at once by the signs of dot and
cross products of the links (no angle is computed), and the nearest that fits
is taken (``boundary_pitch``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ._chain import Chain
from ._closed import TWO_PI, Planes, best, pitch_of_phi, planes, solve, turn_of, wrap
from ._family import PlanarFamily
from ._forward import sweep
from ._pose import pitch_of

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
_CHECK = 0.5e-9  # [rad]: a boundary point fits within half the solver's slack


def free_batch(chain: Chain, fam: PlanarFamily, P: F64, seed: F64) -> tuple[F64, Bool]:
    """Best solution per target [rad] (N, dof) (NaN rows where none) and ok (N,)."""
    want, b = preferred(chain, seed), planes(fam, P, seed)
    pitch, has = nearest_reachable(chain, fam, b, want)
    q, ok = best(solve(chain, fam, P, pitch, seed, b), seed)
    hard = np.flatnonzero(~ok & has)
    if hard.size:
        b = b.take(hard)
        at, found = boundary_pitch(chain, fam, b, want[hard])
        qh, okh = best(solve(chain, fam, P[hard], at, seed[hard], b), seed[hard])
        q[hard], ok[hard] = qh, okh & found
    return q, ok


def preferred(chain: Chain, seed: F64) -> F64:
    """The pitch [rad] of the tool at each seed (N, dof), shape (N,)."""
    if (seed == chain.home_a).all():
        return np.full(len(seed), chain.home_pitch)
    return np.asarray(pitch_of(sweep(chain, seed).T), dtype=np.float64)


def _gap(pitch: F64, want: F64) -> F64:
    """|pitch - want| [rad] round the circle, for pitches and ``want`` in [-pi, pi]."""
    d = np.abs(pitch - want)
    return np.minimum(d, TWO_PI - d)


def nearest_reachable(chain: Chain, fam: PlanarFamily, b: Planes, want: F64) -> tuple[F64, Bool]:
    """Per target the pitch [rad] nearest ``want`` at which the wrist point is within reach
    of the first two links (and the base inside its limits), and whether there is one.

    With u the turn from the one at which the wrist point is nearest the shoulder, its
    distance d follows d^2 = D^2 + L3^2 - 2 D L3 cos u: within reach where cos u lies in
    [c_lo, c_hi], so the nearest u is a clamp of cos u (the sign of sin u kept).
    """
    lo_d, hi_d = chain.wrist_reach
    (v3x, v3z), (c1x, c1z) = fam.links[2], fam.c1
    l3, ang3 = math.hypot(v3x, v3z), math.atan2(v3z, v3x)
    ck, sk, cp, sp = math.cos(ang3), math.sin(ang3), math.cos(fam.phi0), math.sin(fam.phi0)
    tx, tz = b.r - c1x, b.z - c1z
    big = np.sqrt(tx * tx + tz * tz)
    k = np.maximum(2.0 * big * l3, 1e-300)
    c_lo, c_hi = (big * big + l3 * l3 - hi_d * hi_d) / k, (big * big + l3 * l3 - lo_d * lo_d) / k
    empty = (c_lo > 1.0 + 1e-12) | (c_hi < -1.0 - 1e-12) | ~_base_fits(chain, fam, b.q0)
    cs, ss = (tx * ck + tz * sk) / big, (tz * ck - tx * sk) / big  # where W is nearest
    wants = np.tile(want, len(b.r) // len(want))
    c, s, _ = turn_of(fam, want, b)
    cu, su = c * cs + s * ss, s * cs - c * ss  # u at want
    clamped = np.clip(cu, c_lo, c_hi)
    su = np.where(clamped == cu, su, np.copysign(np.sqrt(1.0 - clamped * clamped), su))
    ct, st = clamped * cs - su * ss, su * cs + clamped * ss  # the turn at u
    pitch = np.where(
        clamped == cu, wants, pitch_of_phi(ct * cp - st * sp, st * cp + ct * sp, b.r, b.rho)
    )
    return _nearest(b, pitch, np.where(empty, np.inf, _gap(pitch, wants)), want)


def boundary_pitch(chain: Chain, fam: PlanarFamily, b: Planes, want: F64) -> tuple[F64, Bool]:
    """Per target the pitch [rad] nearest ``want`` among the boundary points that fit, and
    whether one does."""
    (v3x, v3z), n = fam.links[2], len(want)
    tx, tz = b.r - fam.c1[0], b.z - fam.c1[1]
    with np.errstate(divide="ignore", invalid="ignore"):
        Wx, Wz, Ex, Ez = _boundaries(chain, fam, tx, tz)
        l3x, l3z = tx - Wx, tz - Wz  # (K, B * N)
        fits = _fits(chain, fam, l3x, l3z, Wx - Ex, Wz - Ez, Ex, Ez)
    fits &= _base_fits(chain, fam, b.q0) & ~np.tile(b.bad, len(b.r) // n)
    if fam.lateral or (b.rho < 1e-12).any():  # the distance of the pitch itself
        key = _gap(_pitch(fam, l3x, l3z, b.r, b.rho), np.tile(want, len(b.r) // n))
    else:  # pitch = +-(approach angle) + a constant: the nearest has link 3 nearest want's
        c, s, _ = turn_of(fam, want, b)
        key = -(l3x * (c * v3x - s * v3z) + l3z * (s * v3x + c * v3z))
    key = np.where(fits, key, np.inf).reshape(-1, n)  # (K * B, N)
    i, cols = np.argmin(key, axis=0), np.arange(n)
    found = np.isfinite(key[i, cols])
    lane = i % (len(b.r) // n) * n + cols  # the chosen one's base branch and target
    l3x, l3z = l3x.reshape(-1, n)[i, cols], l3z.reshape(-1, n)[i, cols]
    return np.where(found, _pitch(fam, l3x, l3z, b.r[lane], b.rho[lane]), want), found


def _pitch(fam: PlanarFamily, l3x: F64, l3z: F64, r: F64, rho: F64) -> F64:
    """The pitch [rad] at which link 3 is the vector (l3x, l3z) [m] in the plane."""
    (v3x, v3z), l3 = fam.links[2], math.hypot(*fam.links[2])
    k = fam.phi0 - math.atan2(v3z, v3x)  # link 3's direction + k = the approach's
    c = (l3x * math.cos(k) - l3z * math.sin(k)) / l3
    return pitch_of_phi(c, (l3x * math.sin(k) + l3z * math.cos(k)) / l3, r, rho)


def _nearest(b: Planes, pitch: F64, gap: F64, want: F64) -> tuple[F64, Bool]:
    """Per target the pitch of the smallest gap over the first axis of (M, N) or stacked
    (B * N,) pitches and gaps, else ``want``; and whether there was one."""
    pitch, gap = pitch.reshape(-1, len(want)), gap.reshape(-1, len(want))
    i, cols = np.argmin(gap, axis=0), np.arange(len(want))
    found = np.isfinite(gap[i, cols])
    return np.where(found, pitch[i, cols], want), found


def _base_fits(chain: Chain, fam: PlanarFamily, q0: F64) -> Bool:
    """Where the base angles q0 [rad] are inside the base's limits by whole turns."""
    if fam.base is None or chain.upper[fam.base] - chain.lower[fam.base] >= TWO_PI:
        return np.ones(len(q0), dtype=bool)
    return wrap(q0, chain.lower[fam.base], chain.upper[fam.base])[1]


def _boundaries(chain: Chain, fam: PlanarFamily, tx: F64, tz: F64) -> tuple[F64, F64, F64, F64]:
    """Where the fit can change along the wrist circle about T = (tx, tz) (N,) [m]: per
    boundary point the wrist point W and the elbow point E, x and z each (K, N) [m]
    (NaN where none)."""
    (v1x, v1z), (v2x, v2z), (v3x, v3z) = fam.links
    l1, l2, l3 = fam.l1, fam.l2, math.hypot(v3x, v3z)
    (j1, _, j3), (s1, _, s3) = fam.planar, fam.sigma
    d, c, s = _elbow_ends(chain, fam)  # W at distance d; E turned from W by a constant
    W = _meet(0.0, 0.0, d, tx, tz, l3)
    E = [((c * wx + s * wz) * (l1 / d), (c * wz - s * wx) * (l1 / d)) for wx, wz in W]
    a = np.array([chain.lower[j1], chain.upper[j1]])[:, None] * s1  # shoulder at a limit: E fixed
    ex, ez = np.cos(a) * v1x - np.sin(a) * v1z, np.sin(a) * v1x + np.cos(a) * v1z
    for wx, wz in _meet(ex, ez, l2, tx, tz, l3):
        W.append((wx, wz))
        E.append((ex + 0.0 * wx, ez + 0.0 * wz))
    a = np.array([chain.lower[j3], chain.upper[j3]])[:, None] * s3  # wrist at a limit: links 2
    ux, uz = v2x + np.cos(a) * v3x - np.sin(a) * v3z, v2z + np.sin(a) * v3x + np.cos(a) * v3z
    u2 = ux * ux + uz * uz  # and 3 make one rigid link U: R U = T - E, and R turns link 2
    for ex, ez in _meet(0.0, 0.0, l1, tx, tz, np.sqrt(u2)):
        rc, rs = (ux * (tx - ex) + uz * (tz - ez)) / u2, (ux * (tz - ez) - uz * (tx - ex)) / u2
        W.append((ex + rc * v2x - rs * v2z, ez + rs * v2x + rc * v2z))
        E.append((ex, ez))
    return (
        np.concatenate([w[0] for w in W]), np.concatenate([w[1] for w in W]),
        np.concatenate([e[0] for e in E]), np.concatenate([e[1] for e in E]),
    )  # fmt: skip


def _elbow_ends(chain: Chain, fam: PlanarFamily) -> tuple[F64, F64, F64]:
    """The elbow turns (link 2 from link 1) where the fit can change: at its limits, and
    straight or folded where its range holds them. Per turn, each (M, 1): the distance d [m]
    from the shoulder to the wrist point, and cos, sin of the angle from it to link 1."""
    j2, s2, l1, l2 = fam.planar[1], fam.sigma[1], fam.l1, fam.l2
    lo, hi = sorted((s2 * chain.lower[j2] + fam.bend, s2 * chain.upper[j2] + fam.bend))
    turns = {lo, hi} | {b for b in (0.0, math.pi) if (b - lo) % TWO_PI <= hi - lo}
    ends = [(l1 + l2 * math.cos(b), l2 * math.sin(b)) for b in sorted(turns)]
    d = np.array([[math.hypot(x, y)] for x, y in ends if math.hypot(x, y) > 1e-12])
    x, y = (np.array([[v[k]] for v in ends if math.hypot(*v) > 1e-12]) for k in (0, 1))
    return d, x / d, y / d


def _meet(
    ax: float | F64, az: float | F64, ra: float | F64, bx: F64, bz: F64, rb: float | F64
) -> list[tuple[F64, F64]]:
    """Both points where circles about (ax, az) of radius ra (each a number or (M, 1)) meet
    circles about (bx, bz) (N,) of radius rb [m], each (M, N) (NaN where they do not)."""
    dx, dz = bx - ax, bz - az
    d2 = dx * dx + dz * dz
    along = (d2 + ra * ra - rb * rb) / (2.0 * d2)  # along the centre line, per its length
    h2 = ra * ra / d2 - along * along
    h = np.sqrt(np.where(h2 >= -1e-12, np.maximum(h2, 0.0), np.nan))
    mx, mz = ax + along * dx, az + along * dz
    return [(mx - h * dz, mz + h * dx), (mx + h * dz, mz - h * dx)]


def _fits(
    chain: Chain, fam: PlanarFamily, l3x: F64, l3z: F64, l2x: F64, l2z: F64, ex: F64, ez: F64
) -> Bool:
    """Where the planar joints are inside their limits, given each link as a vector [m]:
    link 1 = E, link 2, link 3. Joint j's plane angle lies in its range when the link is
    within half the range of the direction the range's middle gives it (the previous
    link, or the plane's r axis, turned by the middle): a dot product against a cosine."""
    links = [(ex, ez), (l2x, l2z), (l3x, l3z)]
    angles = [math.atan2(vz, vx) for vx, vz in fam.links]
    ok = np.isfinite(l3x)
    for k, (j, s) in enumerate(zip(fam.planar, fam.sigma, strict=True)):
        lo, hi = sorted((s * chain.lower[j], s * chain.upper[j]))
        half = 0.5 * (hi - lo) + _CHECK
        if half < math.pi:
            mid = 0.5 * (lo + hi) + angles[k] - (angles[k - 1] if k else 0.0)
            (cm, sm), (bx, bz) = (math.cos(mid), math.sin(mid)), links[k]
            px, pz = links[k - 1] if k else (1.0, 0.0)  # the previous link, turned by the middle
            mx, mz = (px * cm - pz * sm, px * sm + pz * cm) if k else (cm, sm)
            lengths = math.hypot(*fam.links[k]) * (math.hypot(*fam.links[k - 1]) if k else 1.0)
            ok &= mx * bx + mz * bz >= lengths * math.cos(half)
    return ok
