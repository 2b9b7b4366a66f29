"""Closed-form IK for N targets at once, vectorised over targets.

Same math as ``_analytic`` and ``_fast``: for each of the 2 base branches the
plane target is computed once on (N,) arrays, then both elbow branches share
its trigonometry (+-gamma). The 4 candidates per target land in an
(N, 4, dof) array and the valid one nearest the seed wins.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel
from ._family import PlanarFamily

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
_TWO_PI = 2.0 * np.pi
_SLACK = 1e-9


def solve_batch(
    model: ArmModel, fam: PlanarFamily, P: F64, pitch: F64 | None, seed: F64
) -> tuple[F64, Bool, NDArray[np.str_]]:
    """Best solution per target.

    Args:
        P: targets [m], shape (N, 3).
        pitch: pitch per target [rad], shape (N,), or None (2 planar joints only).
        seed: joint angles [rad], shape (N, dof).

    Returns:
        q (N, dof) with NaN rows where none fits, ok (N,), reason (N,).
    """
    n = len(P)
    cand = np.repeat(seed[:, None, :], 4, axis=1)
    valid = np.zeros((n, 4), dtype=bool)
    far = np.zeros(n, dtype=bool)
    branches, plane_bad = _planes(fam, P, seed)
    for k, (r, rho, q0) in enumerate(branches):
        far |= _branch(
            model,
            fam,
            P[:, 2],
            r,
            rho,
            q0,
            pitch,
            cand[:, 2 * k : 2 * k + 2],
            valid[:, 2 * k : 2 * k + 2],
        )
    valid &= ~plane_bad[:, None]
    diff = cand - seed[:, None, :]
    dist = np.where(valid, np.einsum("nkd,nkd->nk", diff, diff), np.inf)
    best = np.argmin(dist, axis=1)
    ok = valid[np.arange(n), best]
    q = np.where(ok[:, None], cand[np.arange(n), best], np.nan)
    return q, ok, _reasons(ok, plane_bad, valid, far, fam)


def _planes(fam: PlanarFamily, P: F64, seed: F64) -> tuple[list[tuple[F64, F64, F64]], Bool]:
    """Per base branch: plane radius r (signed), distance rho, base angle, each (N,)."""
    x, y = P[:, 0], P[:, 1]
    rho = np.hypot(x, y)
    if fam.base is None:
        ux, uy, _ = fam.u
        bad = np.abs(x * ux + y * uy - fam.lateral) > 1e-9
        return [(-uy * x + ux * y, rho, np.zeros(len(P)))], bad
    r2 = rho * rho - fam.lateral**2
    r = np.sqrt(np.maximum(r2, 0.0))
    heading = np.arctan2(y, x) - fam.azimuth_r
    on_axis = rho < 1e-12
    out = []
    for rr in (r, -r):
        psi = heading - np.arctan2(-fam.lateral, rr) if fam.lateral else heading + np.pi * (rr < 0)
        turn_round = (
            np.pi if rr is not r else 0.0
        )  # on the axis: seed's base angle, or turned round
        out.append(
            (rr, rho, np.where(on_axis, seed[:, fam.base] + turn_round, fam.base_sign * psi))
        )
    return out, r2 < -1e-18


def _branch(
    model: ArmModel,
    fam: PlanarFamily,
    z: F64,
    r: F64,
    rho: F64,
    q0: F64,
    pitch: F64 | None,
    out: F64,
    valid: Bool,
) -> Bool:
    """Fill both elbow candidates of one base branch; return the too-far mask (N,)."""
    c, s, turn = _wrist_turn(fam, r, rho, pitch)
    v3x, v3z = fam.links[2] if len(fam.planar) == 3 else (0.0, 0.0)
    wx = r - (c * v3x - s * v3z) - fam.c1[0]
    wz = z - (s * v3x + c * v3z) - fam.c1[1]
    l1, l2, ang1, bend = _link_constants(fam)
    cos_g = (wx * wx + wz * wz - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)
    reach = np.abs(cos_g) <= 1.0 + 1e-12
    cg = np.clip(cos_g, -1.0, 1.0)
    g = np.arccos(cg)
    t = np.arctan2(l2 * np.sqrt(1.0 - cg * cg), l1 + l2 * cg)
    aim = np.arctan2(wz, wx) - ang1
    for e, sign in enumerate((1.0, -1.0)):
        alphas = [aim - sign * t, sign * g - bend]
        if len(fam.planar) == 3:
            alphas.append(turn - alphas[0] - alphas[1])
        elif pitch is not None:
            reach = reach & _pitch_ok(fam, alphas[0] + alphas[1], r, rho, pitch)
        valid[:, e] = reach & _fill(model, fam, q0, alphas, out[:, e])
    return cos_g > 1.0 + 1e-12


def _wrist_turn(fam: PlanarFamily, r: F64, rho: F64, pitch: F64 | None) -> tuple[F64, F64, F64]:
    """cos, sin and angle of the total plane turn that gives ``pitch`` (3 planar joints)."""
    if len(fam.planar) == 2 or pitch is None:
        zero = np.zeros_like(r)
        return zero + 1.0, zero, zero
    on_axis = rho < 1e-12
    pitch = np.where(on_axis & (np.abs(pitch) > np.pi / 2 + 1e-12), np.nan, pitch)  # see pitch_of
    sp = np.sin(pitch) * np.where(on_axis, 1.0, np.abs(r) / np.where(on_axis, 1.0, rho))
    cp = np.cos(pitch) * np.where(r < 0, -1.0, 1.0)
    norm = np.hypot(sp, cp)
    sp, cp = sp / norm, cp / norm
    c0, s0 = np.cos(fam.phi0), np.sin(fam.phi0)
    c, s = cp * c0 + sp * s0, sp * c0 - cp * s0
    return c, s, np.arctan2(s, c)


def _link_constants(fam: PlanarFamily) -> tuple[float, float, float, float]:
    (v1x, v1z), (v2x, v2z) = fam.links[0], fam.links[1]
    ang1 = float(np.arctan2(v1z, v1x))
    return (
        float(np.hypot(v1x, v1z)),
        float(np.hypot(v2x, v2z)),
        ang1,
        float(np.arctan2(v2z, v2x)) - ang1,
    )


def _fill(model: ArmModel, fam: PlanarFamily, q0: F64, alphas: list[F64], out: F64) -> Bool:
    """Write base and planar angles into ``out`` (N, dof), wrapped into limits; the fit mask."""
    cols = ([fam.base] if fam.base is not None else []) + list(fam.planar)
    values = ([q0] if fam.base is not None else []) + [
        s * a for s, a in zip(fam.sigma, alphas, strict=True)
    ]
    ok = np.ones(len(q0), dtype=bool)
    for j, v in zip(cols, values, strict=True):
        lo, hi = model.joints[j].lower, model.joints[j].upper
        w = v - _TWO_PI * np.round(v / _TWO_PI)
        w = np.where(w < lo - _SLACK, w + _TWO_PI, np.where(w > hi + _SLACK, w - _TWO_PI, w))
        inside = (w >= lo - _SLACK) & (w <= hi + _SLACK)
        out[:, j] = np.clip(w, lo, hi)
        ok &= inside
    return ok


def _pitch_ok(fam: PlanarFamily, turn: F64, r: F64, rho: F64, pitch: F64) -> Bool:
    phi = fam.phi0 + turn
    along = np.where(
        np.abs(r) < 1e-12, np.abs(np.cos(phi)), np.cos(phi) * r / np.where(rho < 1e-12, 1, rho)
    )
    got = np.arctan2(np.sin(phi), along)
    return np.abs(np.remainder(got - pitch + np.pi, _TWO_PI) - np.pi) < 1e-7


def _reasons(
    ok: Bool, plane_bad: Bool, valid: Bool, far: Bool, fam: PlanarFamily
) -> NDArray[np.str_]:
    reason = np.full(len(ok), "joint_limit", dtype="<U11")
    reason[far & ~ok] = "too_far"
    reason[plane_bad] = "off_plane" if fam.base is None else "too_close"
    reason[ok] = ""
    return reason
