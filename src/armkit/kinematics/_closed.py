"""Closed-form IK for N targets at once, vectorised over targets: the reference.

Base branches: the arm faces the target (plane radius r > 0) or reaches over
its shoulder (r < 0). Elbow branches: the law of cosines' two signs. For each
base branch the plane target is computed once on (N,) arrays and both elbows
share its trigonometry; every joint is moved by whole turns into its limits
where it can be, and the valid candidate nearest the seed wins.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ._family import PITCH_TOLERANCE, PlanarFamily, Planes, planes, turn_of
from ._pose import pitch_of_phi

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
TWO_PI = 2.0 * np.pi
SLACK = 1e-9  # [rad] a joint this far beyond a limit counts as at it
STRAIGHT = 1.0 - 1e-12  # cos of the elbow beyond it: straight or folded (1e-13 m)
# Why a branch fails, ranked as ``_closed_scalar.refusal`` ranks ``Misses``: the highest
# code among a target's branches names it; 0 (nothing recorded) reads as too far. A base
# outside its limits ranks last: that way round is closed, the other way says why.
BASE, PITCH, TOO_CLOSE, TOO_FAR, JOINT_LIMIT = 1, 2, 3, 4, 5
WHY = np.array(["too_far", "joint_limit", "pitch", "too_close", "too_far", "joint_limit"])


class Limits(Protocol):
    """What the solvers read of a chain: its joint count and limits [rad]."""

    @property
    def dof(self) -> int: ...
    @property
    def lower(self) -> tuple[float, ...]: ...
    @property
    def upper(self) -> tuple[float, ...]: ...


@dataclass(frozen=True)
class Checks:
    """What ``_branches`` found per base branch (B * N,), kept to say why not: the elbow's
    cosine (NaN: no pitch possible), where the base fits, and per elbow where the
    geometry (and a given pitch) fits, before the joint limits."""

    cos_g: F64
    base: Bool
    geometry: tuple[Bool, ...]


@dataclass(frozen=True)
class Candidates:
    """K candidates for each of N targets as lanes: joint angles (dof, K, N) [rad] and
    where each fits (K, N), with the checks that say why not; per target (N,): with no
    base branch (off the plane, or inside the lateral offset)."""

    lanes: F64
    fits: Bool
    checks: Checks
    bad: Bool

    @property
    def q(self) -> F64:
        """The candidates per target [rad], (N, K, dof)."""
        return self.lanes.transpose(2, 1, 0)

    @property
    def valid(self) -> Bool:
        """Where each candidate fits, (N, K)."""
        return self.fits.T


def solve(
    chain: Limits, fam: PlanarFamily, P: F64, pitch: F64 | None, seed: F64, b: Planes | None = None
) -> Candidates:
    """Every candidate for targets P (N, 3) [m] at ``pitch`` (N,) [rad] (None: 2 planar
    joints, the pitch follows), seeds (N, dof) [rad] (and their ``planes`` if known):
    K = 2 B, elbow by elbow, each of every base branch."""
    b = planes(fam, P, seed) if b is None else b
    count = len(b.r) // len(P)
    lanes = np.empty((chain.dof, 2, len(b.r)))
    lanes[:] = np.tile(seed.T, count)[:, None, :]
    fits, checks = _branches(chain, fam, b, pitch, lanes)
    fits = fits.reshape(2 * count, len(P)) & ~b.bad
    lanes = lanes.reshape(chain.dof, 2 * count, len(P))
    return Candidates(lanes, fits, checks, b.bad)


def best(c: Candidates, seed: F64) -> tuple[F64, Bool]:
    """The valid candidate nearest each seed (NaN rows where none), and ok (N,)."""
    dist = np.zeros(c.fits.shape)
    for j in range(len(c.lanes)):
        d = c.lanes[j] - seed[:, j]
        dist += d * d
    pick = np.argmin(np.where(c.fits, dist, np.inf), axis=0)
    cols = np.arange(len(seed))
    ok = c.fits[pick, cols]
    return np.where(ok[:, None], c.lanes[:, pick, cols].T, np.nan), ok


def reasons(fam: PlanarFamily, c: Candidates) -> NDArray[np.str_]:
    """Why each target of ``c`` has no valid candidate ('' where it has one), shape (N,):
    the highest ``WHY`` code among its branches, as ``_closed_scalar.refusal`` says it."""
    cos_g, base, geometry = c.checks.cos_g, c.checks.base, c.checks.geometry
    why = np.select([cos_g > 1.0 + 1e-12, cos_g < -1.0 - 1e-12], [TOO_FAR, TOO_CLOSE], 0)
    why[~(base | np.isnan(cos_g))] = BASE
    ok = (np.abs(cos_g) <= 1.0 + 1e-12) & base
    for geometry_ok, fits in zip(geometry, c.fits.reshape(len(geometry), -1), strict=True):
        why[ok & ~geometry_ok] = np.maximum(why[ok & ~geometry_ok], PITCH)
        why[geometry_ok & ~fits] = JOINT_LIMIT
    why[np.isnan(cos_g)] = PITCH  # on the base axis beyond +-90 deg: nothing else counts
    reason: NDArray[np.str_] = WHY[why.reshape(-1, len(c.bad)).max(axis=0)].astype("<U11")
    reason[c.bad] = "off_plane" if fam.base is None else "too_close"
    reason[c.valid.any(axis=1)] = ""
    return reason


def wrap(v: F64, lo: float, hi: float) -> tuple[F64, Bool]:
    """Angles v [rad] moved by whole turns into [lo, hi] (kept where already inside), clamped
    to it; and where that was possible (within ``SLACK``)."""
    w = v - TWO_PI * np.floor((v - (lo - SLACK)) / TWO_PI)  # in [lo - SLACK, lo - SLACK + 2 pi)
    if hi - lo > TWO_PI - 2 * SLACK:  # a turn or more: keep an angle that is already inside
        w = np.where((v >= lo - SLACK) & (v <= hi + SLACK), v, w)
    return np.clip(w, lo, hi), w <= hi + SLACK


def _branches(
    chain: Limits, fam: PlanarFamily, b: Planes, pitch: F64 | None, out: F64
) -> tuple[Bool, Checks]:
    """Fill both elbow candidates (dof, 2, B * N) of every base branch; return where each
    fits (2, B * N) and the checks that say why not."""
    three = len(fam.planar) == 3
    wx, wz = b.r - fam.c1[0], b.z - fam.c1[1]
    if three:
        assert pitch is not None
        c, s, turn = turn_of(fam, np.tile(pitch, len(b.r) // len(pitch)), b.r, b.rho)
        (v3x, v3z) = fam.links[2]
        wx, wz = wx - (c * v3x - s * v3z), wz - (s * v3x + c * v3z)
    l1, l2 = fam.l1, fam.l2
    cos_g = (wx * wx + wz * wz - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)
    cg = np.where(np.abs(cos_g) > STRAIGHT, np.sign(cos_g), cos_g)  # as ``_closed_fast``
    g = np.arccos(cg)
    t = np.arctan2(l2 * np.sqrt(1.0 - cg * cg), l1 + l2 * cg)
    aim = np.arctan2(wz, wx) - fam.ang1
    ok, base = np.abs(cos_g) <= 1.0 + 1e-12, np.ones(len(cos_g), dtype=bool)
    if fam.base is not None:
        out[fam.base], base = wrap(b.q0, chain.lower[fam.base], chain.upper[fam.base])
        ok &= base
    geometry = []
    valid = np.empty((2, len(ok)), dtype=bool)
    for e, sign in enumerate((1.0, -1.0)):
        a1, a2 = aim - sign * t, sign * g - fam.bend
        alphas = (a1, a2, turn - a1 - a2) if three else (a1, a2)
        fit = ok if three or pitch is None else ok & _pitch_ok(fam, a1 + a2, b, pitch)
        geometry.append(fit)
        for j, s_j, a in zip(fam.planar, fam.sigma, alphas, strict=True):
            out[j, e], inside = wrap(s_j * a, chain.lower[j], chain.upper[j])
            fit = fit & inside
        valid[e] = fit
    return valid, Checks(cos_g, base, tuple(geometry))


def _pitch_ok(fam: PlanarFamily, turn: F64, b: Planes, pitch: F64) -> Bool:
    """Where the plane turns [rad] of a 2-joint planar chain give ``pitch`` (N,) [rad]."""
    got = pitch_of_phi(np.cos(fam.phi0 + turn), np.sin(fam.phi0 + turn), b.r, b.rho)
    pitch = np.tile(pitch, len(b.r) // len(pitch))
    return np.asarray(np.abs(np.remainder(got - pitch + np.pi, TWO_PI) - np.pi) <= PITCH_TOLERANCE)
