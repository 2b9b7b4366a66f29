"""Closed-form IK for one target in plain floats: the scalar fast path of ``_closed``.

Base branches: the arm faces the target (r > 0) or reaches over its shoulder
(r < 0). Elbow branches: the law of cosines' two signs. Every candidate is
wrapped into the joint limits by whole turns and kept only if it fits.
Without a pitch (3 planar joints) the pitch is the one nearest the seed's at
which the arm fits: first the nearest at which the wrist point is within the
links' reach (``annulus_arcs``); if the limits refuse it, the nearest of the
pitches where a limit or the reach begins (``_pitch_range.candidates``) that fits.
Tests pin this path to the vectorised solver, which is the reference.
"""

from __future__ import annotations

import math

from .._errors import Reason, UnreachableError
from ._chain import Chain
from ._closed_fast import Found, Misses, Q, wrap_into
from ._family import PlanarFamily
from ._planar import pitch_for_phi, planes

_TWO_PI = 2.0 * math.pi


def refusal(
    chain: Chain, fam: PlanarFamily, p: Q, pitch: float | None, seed: Q
) -> UnreachableError:
    """Why no solution fits ``p`` [m] at ``pitch`` [rad] (None: at the seed's pitch):
    the joint and limit when only the limits are in the way, else the reason."""
    assert chain.fixed is not None
    if pitch is None and len(fam.planar) == 3:
        pitch = preferred(chain, seed)
    misses = Misses()
    chain.fixed(p[0], p[1], p[2], pitch, seed, misses)
    return unreachable(chain, p, pitch, misses)


def preferred(chain: Chain, seed: Q) -> float:
    """The pitch [rad] of the tool at joint angles ``seed``."""
    st = chain.state(list(seed))
    (ax, ay, az), (px, py, _) = st.R[0], st.p
    rho = math.hypot(px, py)
    h = (ax * px + ay * py) / rho if rho >= 1e-9 else math.hypot(ax, ay)
    return math.atan2(az, h)


def free(chain: Chain, fam: PlanarFamily, x: float, y: float, z: float, seed: Q) -> Found:
    """Position only (3 planar joints): every solution at the pitch nearest the seed's at
    which the arm fits, unsorted; [] if none."""
    want = chain.home_pitch if seed == chain.home else preferred(chain, seed)
    assert chain.fixed is not None
    at: float | None = want
    if chain.nearest is not None:  # the nearest pitch with the wrist point within reach
        at = chain.nearest(x, y, z, want, seed[0])
        if at is None:  # out of reach at every pitch
            return []
    return chain.fixed(x, y, z, at, seed, None) or _exact(chain, fam, x, y, z, seed, want)


def _exact(
    chain: Chain, fam: PlanarFamily, x: float, y: float, z: float, seed: Q, want: float
) -> Found:
    """The nearest fitting pitch among those where the fit can change: the scalar form of
    ``_pitch_range.candidates`` (see there), tried nearest ``want`` first."""
    assert chain.fixed is not None
    branches = planes(fam, x, y, z, seed[fam.base] if fam.base is not None else 0.0)
    if isinstance(branches, str):
        return []
    (v1x, v1z), (v2x, v2z), (v3x, v3z) = fam.links
    l1, l2, l3, ang3 = fam.l1, fam.l2, math.hypot(v3x, v3z), math.atan2(v3z, v3x)
    (s1, s2, s3), (j1, j2, j3) = fam.sigma, fam.planar
    lo_d, hi_d = chain.wrist_reach
    elbow = [
        math.hypot(l1 + l2 * math.cos(s2 * a + fam.bend), l2 * math.sin(s2 * a + fam.bend))
        for a in (chain.lower[j2], chain.upper[j2])
    ]
    radii = sorted({lo_d, hi_d, *(d for d in elbow if lo_d < d < hi_d)})
    pitches = []
    for r, rho, q0 in branches:
        if (
            fam.base is not None
            and wrap_into(q0, chain.lower[fam.base], chain.upper[fam.base]) is None
        ):
            continue
        tx, tz = r - fam.c1[0], z - fam.c1[1]
        turns = [t for d in radii for t in _circles(tx, tz, l3, ang3, d)]
        for a in (chain.lower[j1], chain.upper[j1]):  # shoulder at a limit
            c, s = math.cos(s1 * a), math.sin(s1 * a)
            turns += _circles(tx - (c * v1x - s * v1z), tz - (s * v1x + c * v1z), l3, ang3, l2)
        for a in (chain.lower[j3], chain.upper[j3]):  # wrist at a limit
            c, s = math.cos(s3 * a), math.sin(s3 * a)
            ux, uz = v2x + c * v3x - s * v3z, v2z + s * v3x + c * v3z
            turns += [
                t + s3 * a for t in _circles(tx, tz, math.hypot(ux, uz), math.atan2(uz, ux), l1)
            ]
        pitches += [pitch_for_phi(fam.phi0 + t, r, rho) for t in turns]
    pitches.sort(key=lambda p: abs(math.remainder(p - want, _TWO_PI)))
    for pitch in pitches:
        found = chain.fixed(x, y, z, pitch, seed, None)
        if found:
            return found
    return []


def _circles(tx: float, tz: float, length: float, angle: float, radius: float) -> list[float]:
    """Turns t [rad] with |T - R(t) v| = radius, T = (tx, tz), v of ``length`` at ``angle``."""
    big = math.hypot(tx, tz)
    c = (big * big + length * length - radius * radius) / max(2.0 * big * length, 1e-300)
    if abs(c) > 1.0 + 1e-12:
        return []
    u, base = math.acos(min(1.0, max(-1.0, c))), math.atan2(tz, tx) - angle
    return [base + u, base - u]


def _num(v: float) -> str:
    """A number for a message: one decimal, or 3 significant digits when huge."""
    return f"{v:.1f}" if abs(v) < 1e6 else f"{v:.3g}"


def where(p: Q, pitch: float | None) -> str:
    """The target in the user's units, briefly: '(x, y, z) mm at pitch P deg'."""
    mm = [v * 1000.0 for v in p]
    if all(math.isfinite(v) for v in mm):
        text = "(" + ", ".join(_num(v) for v in mm) + ") mm"
    else:  # too far for millimetres in a float: metres
        text = "(" + ", ".join(f"{v:.3g}" for v in p) + ") m"
    return text if pitch is None else text + f" at pitch {_num(math.degrees(pitch))} deg"


def too_far(chain: Chain, p: Q, pitch: float | None) -> UnreachableError:
    """The error for a target beyond every pose's reach."""
    return UnreachableError(
        f"{chain.name} cannot reach {where(p, pitch)}: {EXPLAIN['too_far']}", reason="too_far"
    )


def unreachable(chain: Chain, p: Q, pitch: float | None, misses: Misses) -> UnreachableError:
    """The error for a target no candidate reaches: the nearest limit miss, or the reason."""
    if misses.violations:
        _, i, value = min(misses.violations)
        lo, hi = math.degrees(chain.lower[i]), math.degrees(chain.upper[i])
        return UnreachableError(
            f"{chain.name} cannot reach {where(p, pitch)} inside its limits: "
            f"{chain.joint_names[i]} would be {math.degrees(value):.1f} deg, allowed "
            f"{lo:.1f}..{hi:.1f} deg; try another pitch or a point nearer the middle of the reach",
            reason="joint_limit",
        )
    reason: Reason = next((r for r in EXPLAIN if r in misses.reasons), "too_far")
    return UnreachableError(
        f"{chain.name} cannot reach {where(p, pitch)}: {EXPLAIN[reason]}", reason=reason
    )


EXPLAIN: dict[Reason, str] = {
    "too_far": "too far away for the arm's links; try a point nearer the base",
    "too_close": "too close to the base for the arm's links; try a point further out",
    "off_plane": "the point is outside the arm's plane of motion",
    "pitch": "the arm cannot have that pitch there (on the base axis it is within -90..90 deg;"
    " an arm with two planar joints cannot choose it: leave the pitch out)",
}
