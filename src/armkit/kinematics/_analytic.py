"""Closed-form IK for the planar family, one target, in plain Python floats.

Base branches: the arm faces the target (r > 0) or reaches over its shoulder
(r < 0). Elbow branches: the law of cosines' two signs. Every candidate is
wrapped into the joint limits by whole turns and kept only if it fits.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from .._errors import UnreachableError
from ..model import ArmModel
from ._family import PlanarFamily
from ._planar import forward, phi_for_pitch, pitch_for_phi, two_link

__all__ = ["pitch_for_phi", "seed_pitch", "solve"]

Q = tuple[float, ...]
_TWO_PI = 2.0 * math.pi
_SLACK = 1e-9


@dataclass
class _Attempt:
    """Candidates that fit, and why the others did not."""

    good: list[Q] = field(default_factory=list)
    reasons: list[str] = field(default_factory=list)
    violations: list[tuple[float, int, float]] = field(default_factory=list)


def solve(model: ArmModel, fam: PlanarFamily, p: Q, pitch: float | None, seed: Q) -> list[Q]:
    """Every solution for tool point ``p`` [m] and ``pitch`` [rad] (None: the model's
    default pitch, else free), best (nearest ``seed``) first.

    Raises:
        UnreachableError: no solution; ``reason`` says why, the message names the
            joint and limit when only the limits are in the way.
    """
    if pitch is None:
        pitch = model.default_pitch
    if pitch is None and len(fam.planar) == 3:
        return _free_pitch(model, fam, p, seed)
    attempt = _solve_pitch(model, fam, p, pitch, seed)
    if not attempt.good:
        raise _unreachable(model, p, pitch, attempt)
    return _sorted(attempt.good, seed)


def _solve_pitch(
    model: ArmModel, fam: PlanarFamily, p: Q, pitch: float | None, seed: Q
) -> _Attempt:
    attempt = _Attempt()
    planes, why = _planes(fam, p, seed)
    if why:
        attempt.reasons.append(why)
    for r, z, rho, q0 in planes:
        for alphas in _plane_solutions(fam, r, z, rho, pitch, attempt):
            _keep(model, fam, _assemble(fam, q0, alphas, seed), attempt)
    return attempt


def _planes(
    fam: PlanarFamily, p: Q, seed: Q
) -> tuple[list[tuple[float, float, float, float]], str]:
    """Plane targets (r, z, rho, base angle) for each base branch, or why none."""
    x, y, z = p
    if fam.base is None:
        ux, uy, uz = fam.u
        if abs(x * ux + y * uy + z * uz - fam.lateral) > 1e-9:
            return [], "off_plane"
        er = (-uy, ux)  # e_r = z x u, horizontal
        return [(x * er[0] + y * er[1], z, math.hypot(x, y), 0.0)], ""
    rho2 = x * x + y * y
    r2 = rho2 - fam.lateral * fam.lateral
    if r2 < -1e-18:
        return [], "too_close"
    r = math.sqrt(max(r2, 0.0))
    rho = math.sqrt(rho2)
    if rho < 1e-12:  # on the base axis: the base angle is free; keep the seed's, or turn it round
        q0 = seed[fam.base]
        return [(0.0, z, 0.0, q0), (-0.0, z, 0.0, q0 + math.pi)], ""
    heading = math.atan2(y, x) - fam.azimuth_r
    out = []
    for rr in (r, -r) if r > 1e-12 else (r,):
        psi = heading - math.atan2(-fam.lateral, rr)
        out.append((rr, z, rho, fam.base_sign * psi))
    return out, ""


def _plane_solutions(
    fam: PlanarFamily, r: float, z: float, rho: float, pitch: float | None, attempt: _Attempt
) -> list[tuple[float, ...]]:
    """Plane angles of every planar joint reaching (r, z) with ``pitch``."""
    if len(fam.planar) == 2:
        sols, why = two_link(fam, r, z)
        if why:
            attempt.reasons.append(why)
        if pitch is not None:
            sols = [s for s in sols if _pitch_matches(fam, s, r, rho, pitch)]
            if not sols and not why:
                attempt.reasons.append("pitch")
        return [tuple(s) for s in sols]
    if rho < 1e-12 and abs(pitch or 0.0) > math.pi / 2 + 1e-12:
        attempt.reasons.append("pitch")  # on the base axis pitch is measured in [-90, 90] deg
        return []
    phi = phi_for_pitch(pitch or 0.0, r, rho)
    turn = phi - fam.phi0
    v3x, v3z = fam.links[2]
    c, s = math.cos(turn), math.sin(turn)
    sols, why = two_link(fam, r - (c * v3x - s * v3z), z - (s * v3x + c * v3z))
    if why:
        attempt.reasons.append(why)
    return [(a1, a2, turn - a1 - a2) for a1, a2 in sols]


def _pitch_matches(
    fam: PlanarFamily, alphas: tuple[float, float], r: float, rho: float, pitch: float
) -> bool:
    phi = fam.phi0 + alphas[0] + alphas[1]
    diff = pitch_for_phi(phi, r, rho) - pitch
    return abs(math.remainder(diff, _TWO_PI)) < 1e-7


def _assemble(fam: PlanarFamily, q0: float, alphas: tuple[float, ...], seed: Q) -> list[float]:
    q = list(seed)
    if fam.base is not None:
        q[fam.base] = q0
    for j, sigma, alpha in zip(fam.planar, fam.sigma, alphas, strict=True):
        q[j] = sigma * alpha
    return q


def _keep(model: ArmModel, fam: PlanarFamily, q: list[float], attempt: _Attempt) -> None:
    """Wrap each angle into its limits by whole turns; keep q if all fit."""
    worst: tuple[float, int, float] | None = None
    for i, joint in enumerate(model.joints):
        value = _wrap_into(q[i], joint.lower, joint.upper)
        if value is None:
            mid = 0.5 * (joint.lower + joint.upper)
            nearest = mid + math.remainder(q[i] - mid, _TWO_PI)  # the turn nearest the range
            excess = max(joint.lower - nearest, nearest - joint.upper)
            if worst is None or excess > worst[0]:
                worst = (excess, i, nearest)
        else:
            q[i] = value
    if worst is None:
        attempt.good.append(tuple(q))
    else:
        attempt.violations.append(worst)


def _wrap_into(angle: float, lower: float, upper: float) -> float | None:
    """``angle`` plus a whole number of turns inside [lower, upper], or None."""
    if lower - _SLACK <= angle <= upper + _SLACK:
        return min(max(angle, lower), upper)
    wrapped = lower + math.fmod(angle - lower, _TWO_PI) % _TWO_PI
    if wrapped <= upper + _SLACK:
        return min(wrapped, upper)
    if wrapped - _TWO_PI >= lower - _SLACK:
        return max(wrapped - _TWO_PI, lower)
    return None


def _sorted(good: list[Q], seed: Q) -> list[Q]:
    unique: list[Q] = []
    for q in sorted(good, key=lambda q: sum((a - b) ** 2 for a, b in zip(q, seed, strict=True))):
        if all(max(abs(a - b) for a, b in zip(q, u, strict=True)) > 1e-9 for u in unique):
            unique.append(q)
    return unique


def _free_pitch(model: ArmModel, fam: PlanarFamily, p: Q, seed: Q) -> list[Q]:
    """Position only on a 3-joint planar chain: the pitch nearest the seed's that fits.

    Pitches are tried outwards from the seed's in 3 deg steps both ways, then,
    for a point within the links' reach, in 0.1 deg steps; the first that fits
    is refined by bisection towards the seed's pitch, so the answer lies on
    the edge of what the limits allow.
    """
    preferred = seed_pitch(fam, seed)
    solve = _pitch_solver(model, fam, p, seed)
    sols = solve(preferred)
    if sols:
        return sols
    for step_deg in (3.0, 0.1) if _within_reach(fam, p) else (3.0,):
        step = math.radians(step_deg)
        for k in range(1, int(180 / step_deg) + 1):
            for sign in (1.0, -1.0):
                if solve(preferred + sign * k * step):
                    return _bisect(
                        solve, preferred + sign * (k - 1) * step, preferred + sign * k * step
                    )
    raise _unreachable(model, p, None, _solve_pitch(model, fam, p, preferred, seed))


def _within_reach(fam: PlanarFamily, p: Q) -> bool:
    """True if the point is no further from the first planar joint than all links stretched out."""
    reach = sum(math.hypot(*v) for v in fam.links)
    r = math.hypot(p[0], p[1]) if fam.base is not None else p[0] * -fam.u[1] + p[1] * fam.u[0]
    return (
        math.hypot(abs(r) - fam.c1[0], p[2] - fam.c1[1]) <= reach + 1e-9
        or math.hypot(r + fam.c1[0], p[2] - fam.c1[1]) <= reach + 1e-9
    )


def _pitch_solver(model: ArmModel, fam: PlanarFamily, p: Q, seed: Q) -> Callable[[float], list[Q]]:
    """pitch [rad] -> every solution at that pitch, best first (the fast path where it exists)."""
    from ._fast import fast_solver

    fast = fast_solver(model)

    def solve(pitch: float) -> list[Q]:
        if fast is not None:
            found = fast(p[0], p[1], p[2], pitch, seed)
            return [q for _, q in sorted(found[1], key=lambda pair: pair[0])] if found else []
        return _sorted(_solve_pitch(model, fam, p, pitch, seed).good, seed)

    return solve


def _bisect(solve: Callable[[float], list[Q]], miss: float, hit: float) -> list[Q]:
    """Narrow [miss, hit] to 1e-4 rad and return the solutions at the fitting end."""
    while abs(hit - miss) > 1e-4:
        mid = 0.5 * (miss + hit)
        if solve(mid):
            hit = mid
        else:
            miss = mid
    return solve(hit)


def seed_pitch(fam: PlanarFamily, seed: Q) -> float:
    """Pitch [rad] of the tool at joint angles ``seed``."""
    alphas = tuple(s * seed[j] for j, s in zip(fam.planar, fam.sigma, strict=True))
    r, _, phi = forward(fam, alphas)
    return pitch_for_phi(phi, r, math.hypot(r, fam.lateral))


def _unreachable(model: ArmModel, p: Q, pitch: float | None, attempt: _Attempt) -> UnreachableError:
    where = "({:.1f}, {:.1f}, {:.1f}) mm".format(*(v * 1000 for v in p))
    if pitch is not None:
        where += f" at pitch {math.degrees(pitch):.1f} deg"
    if attempt.violations:
        _, i, value = min(attempt.violations)
        j = model.joints[i]
        return UnreachableError(
            f"{model.name} cannot reach {where} inside its limits: {j.name} would be "
            f"{math.degrees(value):.1f} deg, allowed {math.degrees(j.lower):.1f}..{math.degrees(j.upper):.1f}",
            reason="joint_limit",
        )
    reason = _main_reason(attempt.reasons)
    return UnreachableError(f"{model.name} cannot reach {where}: {_EXPLAIN[reason]}", reason=reason)


def _main_reason(reasons: list[str]) -> str:
    for reason in ("too_far", "too_close", "off_plane", "pitch"):
        if reason in reasons:
            return reason
    return "too_far"


_EXPLAIN = {
    "too_far": "too far away for the arm's links; try a point nearer the base",
    "too_close": "too close to the base for the arm's links; try a point further out",
    "off_plane": "the point is outside the arm's plane of motion",
    "pitch": "the arm cannot have that pitch there (on the base axis it is within -90..90 deg;"
    " an arm with two planar joints cannot choose it: leave the pitch out)",
}
