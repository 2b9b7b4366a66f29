"""Position-only closed form (3 planar joints): the pitch nearest the seed's that fits.

In the arm's plane the wrist point (the end of link 2) lies on a circle of
the last link's length around the target; as the pitch turns, it moves round
that circle. The arm fits where the wrist point is within the two links'
annulus around the first planar joint and every joint is inside its limits.
Each boundary of that set is where the wrist point's distance reaches one of
a few radii (the annulus and the elbow's limits), where the shoulder sits at
a limit (the elbow point is then fixed: the wrist lies at link 2's length
from it), or where the wrist joint sits at a limit (links 2 and 3 then form
one rigid link) - each the intersection of two circles, in closed form.
The nearest pitch that fits is the seed's own, or the nearest of those
boundaries that fits. First tried: the nearest pitch at which the wrist point
is inside the annulus (``nearest_reachable``), which fits on most targets.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ._chain import Chain
from ._closed import Branches, best, branches, solve
from ._family import PlanarFamily
from ._forward import sweep
from ._pose import pitch_of

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
_TWO_PI = 2.0 * np.pi


def free_batch(chain: Chain, fam: PlanarFamily, P: F64, seed: F64) -> tuple[F64, Bool]:
    """Best solution per target [rad] (N, dof) (NaN rows where none) and ok (N,)."""
    want = preferred(chain, seed)
    b = branches(fam, P, seed)
    pitch, has = nearest_reachable(chain, fam, b, P[:, 2], want)
    q, ok = best(solve(chain, fam, P, pitch, seed), seed)
    idx = np.flatnonzero(~ok & has)
    trials = candidates(chain, fam, P[idx], seed[idx], want[idx]) if idx.size else None
    still = np.ones(idx.size, dtype=bool)
    for k in range(0 if trials is None else trials.shape[1]):
        assert trials is not None
        live = np.isfinite(trials[:, k]) & still
        if not live.any():
            break
        sub = idx[live]
        qs, oks = best(solve(chain, fam, P[sub], trials[live, k], seed[sub]), seed[sub])
        q[sub[oks]], ok[sub[oks]] = qs[oks], True
        still[np.flatnonzero(live)[oks]] = False
    return q, ok


def preferred(chain: Chain, seed: F64) -> F64:
    """The pitch [rad] of the tool at each seed (N, dof), shape (N,)."""
    if (seed == chain.home_a).all():
        return np.full(len(seed), chain.home_pitch)
    return np.asarray(pitch_of(sweep(chain, seed).T), dtype=np.float64)


def _to_pitch(fam: PlanarFamily, turn: F64, r: F64, rho: F64) -> F64:
    """Pitch [rad] of plane turns (see ``_planar.pitch_for_phi``), broadcast."""
    phi = fam.phi0 + turn
    if fam.lateral == 0.0 and not (rho < 1e-12).any():  # pitch = phi, or pi - phi reaching back
        return np.asarray(np.remainder(np.where(r >= 0, phi, np.pi - phi) + np.pi, _TWO_PI) - np.pi)
    c = np.cos(phi)
    axis = (np.abs(r) < 1e-12) | (rho < 1e-12)
    along = np.where(axis, np.abs(c), c * r / np.where(axis, 1.0, rho))
    return np.asarray(np.arctan2(np.sin(phi), along))


def _base_ok(chain: Chain, fam: PlanarFamily, q0: F64) -> Bool:
    if fam.base is None:
        return np.ones(len(q0), dtype=bool)
    lo, hi = chain.lower[fam.base], chain.upper[fam.base]
    w = lo + np.remainder(q0 - lo, _TWO_PI)
    return np.asarray((w <= hi + 1e-9) | ((q0 >= lo - 1e-9) & (q0 <= hi + 1e-9)))


def nearest_reachable(
    chain: Chain, fam: PlanarFamily, b: Branches, z: F64, want: F64
) -> tuple[F64, Bool]:
    """Per target the pitch nearest ``want`` at which the wrist point is within reach of
    the first two links (and the base inside its limits), and whether there is one."""
    out, dist = want.copy(), np.full(len(z), np.inf)
    lo_d, hi_d = chain.wrist_reach
    (v3x, v3z), c1 = fam.links[2], fam.c1
    l3, ang3 = np.hypot(v3x, v3z), np.arctan2(v3z, v3x)
    for r, q0 in zip(b.r, b.q0, strict=True):
        tx, tz = r - c1[0], z - c1[1]
        big = np.hypot(tx, tz)
        k = np.maximum(2.0 * big * l3, 1e-300)
        c_lo = (big * big + l3 * l3 - hi_d * hi_d) / k
        c_hi = (big * big + l3 * l3 - lo_d * lo_d) / k
        empty = (c_lo > 1.0 + 1e-12) | (c_hi < -1.0 - 1e-12) | ~_base_ok(chain, fam, q0) | b.bad
        u_in, u_out = np.arccos(np.clip(c_hi, -1, 1)), np.arccos(np.clip(c_lo, -1, 1))
        shift = np.arctan2(tz, tx) - ang3
        for start, end in ((shift + u_in, shift + u_out), (shift - u_out, shift - u_in)):
            a, e = _to_pitch(fam, start, r, b.rho), _to_pitch(fam, end, r, b.rho)
            lo, hi = np.where(r >= 0, a, e), np.where(r >= 0, e, a)
            span = np.remainder(hi - lo, _TWO_PI)
            d = np.remainder(want - lo, _TWO_PI)
            to_hi, to_lo = d - span, _TWO_PI - d
            pick = np.where(d <= span, want, np.where(to_hi < to_lo, lo + span, lo))
            gap = np.where(d <= span, 0.0, np.minimum(to_hi, to_lo))
            better = ~empty & (gap < dist)
            out, dist = np.where(better, pick, out), np.where(better, gap, dist)
    return out, np.isfinite(dist)


def candidates(chain: Chain, fam: PlanarFamily, P: F64, seed: F64, want: F64) -> F64:
    """Pitches [rad] where the arm's fit can change, shape (N, K), nearest ``want`` first
    (NaN where none), for targets P (N, 3) [m] and seeds (N, dof) [rad]."""
    b = branches(fam, P, seed)
    (v1x, v1z), (v2x, v2z), (v3x, v3z) = fam.links
    l1, l2, l3, ang3 = fam.l1, fam.l2, np.hypot(v3x, v3z), np.arctan2(v3z, v3x)
    s1, s2, s3 = fam.sigma
    j1, j2, j3 = fam.planar
    elbow = [
        np.hypot(l1 + l2 * np.cos(s2 * a + fam.bend), l2 * np.sin(s2 * a + fam.bend))
        for a in (chain.lower[j2], chain.upper[j2])
    ]
    lo_d, hi_d = chain.wrist_reach  # the annulus; inside it the elbow's limits
    radii = sorted({lo_d, hi_d, *(d for d in elbow if lo_d < d < hi_d)})
    out = []
    for r, q0 in zip(b.r, b.q0, strict=True):
        tx, tz = r - fam.c1[0], P[:, 2] - fam.c1[1]
        turns = [_circles(tx, tz, l3, ang3, d) for d in radii]
        for a in (chain.lower[j1], chain.upper[j1]):  # shoulder at a limit: elbow point fixed
            ex = np.cos(s1 * a) * v1x - np.sin(s1 * a) * v1z
            ez = np.sin(s1 * a) * v1x + np.cos(s1 * a) * v1z
            turns.append(_circles(tx - ex, tz - ez, l3, ang3, l2))
        for a in (chain.lower[j3], chain.upper[j3]):  # wrist at a limit: links 2 + 3 rigid
            ux = v2x + np.cos(s3 * a) * v3x - np.sin(s3 * a) * v3z
            uz = v2z + np.sin(s3 * a) * v3x + np.cos(s3 * a) * v3z
            turns.append(_circles(tx, tz, np.hypot(ux, uz), np.arctan2(uz, ux), l1) + s3 * a)
        pitch = _to_pitch(fam, np.concatenate(turns, axis=1), r[:, None], b.rho[:, None])
        out.append(np.where(_base_ok(chain, fam, q0)[:, None], pitch, np.nan))
    pitches = np.concatenate(out, axis=1)
    gap = np.abs(np.remainder(pitches - want[:, None] + np.pi, _TWO_PI) - np.pi)
    order = np.argsort(np.where(np.isfinite(gap), gap, np.inf), axis=1, kind="stable")
    return np.take_along_axis(pitches, order, axis=1)


def _circles(tx: F64, tz: F64, length: float | F64, angle: float | F64, radius: float) -> F64:
    """Turns t (N, 2) with |T - R(t) v| = radius, T = (tx, tz), v of ``length`` at ``angle``
    (NaN where the circles do not meet)."""
    big = np.hypot(tx, tz)
    c = (big * big + length * length - radius * radius) / np.maximum(2.0 * big * length, 1e-300)
    u = np.arccos(np.where(np.abs(c) <= 1.0 + 1e-12, np.clip(c, -1.0, 1.0), np.nan))
    base = np.arctan2(tz, tx) - angle
    return np.stack([base + u, base - u], axis=1)
