"""Closed-form IK for N targets at once, vectorised over targets: the reference.

For each base branch the plane target is computed once on (N,) arrays, then
both elbow branches share its trigonometry (+-gamma); the 4 candidates per
target land in an (N, 4, dof) array and the valid one nearest the seed wins.
Without a pitch (3 planar joints) the pitch nearest the seed's that fits is
found in closed form: the nearest at which the wrist point is within the
links' reach, else the nearest of the pitches where the reach or a joint
limit begins or ends (``candidates``) that fits, tried nearest first.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._chain import Chain
from ._family import PlanarFamily

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
_TWO_PI = 2.0 * np.pi
_SLACK = 1e-9


@dataclass(frozen=True)
class Branches:
    """Per base branch (1 or 2): plane radius r (signed), distance rho, base angle, each (N,)."""

    r: list[F64]
    rho: F64
    q0: list[F64]
    bad: Bool  # off the plane (no base) or inside the lateral offset (with a base)


@dataclass(frozen=True)
class Candidates:
    """q (N, K, dof) [rad], valid (N, K), and per target: beyond reach (too_far) (N,)."""

    q: F64
    valid: Bool
    far: Bool
    bad: Bool


def branches(fam: PlanarFamily, P: F64, seed: F64) -> Branches:
    """The base branches of targets P (N, 3) [m]: facing them, and over the shoulder."""
    x, y = P[:, 0], P[:, 1]
    rho = np.hypot(x, y)
    if fam.base is None:
        ux, uy, uz = fam.u
        bad = np.abs(x * ux + y * uy + P[:, 2] * uz - fam.lateral) > 1e-9
        return Branches([-uy * x + ux * y], rho, [np.zeros(len(P))], bad)
    r2 = rho * rho - fam.lateral**2
    r = np.sqrt(np.maximum(r2, 0.0))
    heading = np.arctan2(y, x) - fam.azimuth_r
    on_axis = rho < 1e-12
    q0 = []
    for rr, turn in ((r, 0.0), (-r, np.pi)):  # on the axis: the seed's base angle, or turned round
        psi = fam.base_sign * (heading - np.arctan2(-fam.lateral, rr))
        q0.append(np.where(on_axis, seed[:, fam.base] + turn, psi))
    return Branches([r, np.where(on_axis, -0.0, -r)], rho, q0, r2 < -1e-18)


def solve(chain: Chain, fam: PlanarFamily, P: F64, pitch: F64 | None, seed: F64) -> Candidates:
    """Every candidate for targets P (N, 3) [m] at ``pitch`` (N,) [rad] (None: 2 planar
    joints, the pitch follows), seeds (N, dof) [rad]."""
    n, b = len(P), branches(fam, P, seed)
    k = 2 * len(b.r)
    q = np.repeat(seed[:, None, :], k, axis=1)
    valid = np.zeros((n, k), dtype=bool)
    far = np.zeros(n, dtype=bool)
    for i, (r, q0) in enumerate(zip(b.r, b.q0, strict=True)):
        far |= _branch(
            chain,
            fam,
            P[:, 2],
            r,
            b.rho,
            q0,
            pitch,
            q[:, 2 * i : 2 * i + 2],
            valid[:, 2 * i : 2 * i + 2],
        )
    valid &= ~b.bad[:, None]
    return Candidates(q, valid, far, b.bad)


def best(c: Candidates, seed: F64) -> tuple[F64, Bool]:
    """The valid candidate nearest each seed (NaN rows where none), and ok (N,)."""
    diff = c.q - seed[:, None, :]
    dist = np.where(c.valid, np.einsum("nkd,nkd->nk", diff, diff), np.inf)
    pick = np.argmin(dist, axis=1)
    rows = np.arange(len(seed))
    ok = c.valid[rows, pick]
    return np.where(ok[:, None], c.q[rows, pick], np.nan), ok


def reasons(fam: PlanarFamily, c: Candidates) -> NDArray[np.str_]:
    """Why each target of ``c`` has no valid candidate ('' where it has one), shape (N,)."""
    reason = np.full(len(c.far), "joint_limit", dtype="<U11")
    reason[c.far] = "too_far"
    reason[c.bad] = "off_plane" if fam.base is None else "too_close"
    reason[c.valid.any(axis=1)] = ""
    return reason


def _branch(
    chain: Chain, fam: PlanarFamily, z: F64, r: F64, rho: F64, q0: F64, pitch: F64 | None,
    out: F64, valid: Bool,
) -> Bool:  # fmt: skip
    """Fill both elbow candidates of one base branch; return the too-far mask (N,)."""
    three = len(fam.planar) == 3
    wx, wz = r - fam.c1[0], z - fam.c1[1]
    turn = np.zeros_like(r)
    if three:
        assert pitch is not None
        c, s, turn = wrist_turn(fam, r, rho, pitch)
        (v3x, v3z) = fam.links[2]
        wx, wz = wx - (c * v3x - s * v3z), wz - (s * v3x + c * v3z)
    l1, l2 = fam.l1, fam.l2
    cos_g = (wx * wx + wz * wz - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)
    reach = np.abs(cos_g) <= 1.0 + 1e-12
    cg = np.clip(cos_g, -1.0, 1.0)
    g = np.arccos(cg)
    t = np.arctan2(l2 * np.sqrt(1.0 - cg * cg), l1 + l2 * cg)
    aim = np.arctan2(wz, wx) - fam.ang1
    for e, sign in enumerate((1.0, -1.0)):
        alphas = [aim - sign * t, sign * g - fam.bend]
        ok = reach.copy()
        if three:
            alphas.append(turn - alphas[0] - alphas[1])
        elif pitch is not None:
            ok &= _pitch_ok(fam, alphas[0] + alphas[1], r, rho, pitch)
        valid[:, e] = ok & _fill(chain, fam, q0, alphas, out[:, e])
    return np.asarray(cos_g > 1.0 + 1e-12)


def wrist_turn(fam: PlanarFamily, r: F64, rho: F64, pitch: F64) -> tuple[F64, F64, F64]:
    """cos, sin and angle of the total plane turn that gives ``pitch`` (3 planar joints)."""
    on_axis = (rho < 1e-12) | (np.abs(r) < 1e-12)
    pitch = np.where((rho < 1e-12) & (np.abs(pitch) > np.pi / 2 + 1e-12), np.nan, pitch)
    sp = np.sin(pitch) * np.where(on_axis, 1.0, np.abs(r) / np.where(on_axis, 1.0, rho))
    cp = np.cos(pitch) * np.where(on_axis | (r > 0), 1.0, -1.0)
    norm = np.hypot(sp, cp)
    sp, cp = sp / norm, cp / norm
    c0, s0 = np.cos(fam.phi0), np.sin(fam.phi0)
    c, s = cp * c0 + sp * s0, sp * c0 - cp * s0
    return c, s, np.arctan2(s, c)


def _fill(chain: Chain, fam: PlanarFamily, q0: F64, alphas: list[F64], out: F64) -> Bool:
    """Write base and planar angles into ``out`` (N, dof), wrapped into limits; the fit mask."""
    cols = ([fam.base] if fam.base is not None else []) + list(fam.planar)
    values = ([q0] if fam.base is not None else []) + [
        s * a for s, a in zip(fam.sigma, alphas, strict=True)
    ]
    ok = np.ones(len(q0), dtype=bool)
    for j, v in zip(cols, values, strict=True):
        lo, hi = chain.lower[j] - _SLACK, chain.upper[j] + _SLACK
        w = v - _TWO_PI * np.round(v / _TWO_PI)  # the turn in [-pi, pi], then one more if needed
        w += np.where(w < lo, _TWO_PI, np.where(w > hi, -_TWO_PI, 0.0))
        if lo < -np.pi or hi > np.pi:  # a range wider than that: keep an angle already inside
            w = np.where((v >= lo) & (v <= hi), v, w)
        inside = (w >= lo) & (w <= hi)
        out[:, j] = np.clip(w, chain.lower[j], chain.upper[j])
        ok &= inside
    return ok


def _pitch_ok(fam: PlanarFamily, turn: F64, r: F64, rho: F64, pitch: F64) -> Bool:
    phi = fam.phi0 + turn
    along = np.where(
        np.abs(r) < 1e-12, np.abs(np.cos(phi)), np.cos(phi) * r / np.where(rho < 1e-12, 1, rho)
    )
    got = np.arctan2(np.sin(phi), along)
    return np.asarray(np.abs(np.remainder(got - pitch + np.pi, _TWO_PI) - np.pi) < 1e-7)
