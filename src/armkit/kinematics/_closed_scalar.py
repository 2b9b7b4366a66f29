"""Closed-form IK for one target: position only, and the errors that say why not.

Without a pitch (3 planar joints) the pitch is the one nearest the seed's at
which the arm fits (see ``_pitch_range``): first the nearest at which the wrist
point is within the links' reach, by the chain's ``free``; where a joint limit
refuses that one, the boundary search (``limited``): compiled (``_boundary_fast``), or
``_pitch_range.boundary_pitch`` in floats where the extension was not built.
"""

from __future__ import annotations

import math

from .._errors import Reason, UnreachableError
from .._inputs import brief, mm
from ._boundary_fast import COMPILED
from ._chain import Chain
from ._closed_fast import Found, Misses, Q, _ways
from ._closed_free import seed_pitch
from ._family import PlanarFamily
from ._lanes import FLOATS
from ._pitch_range import base_fits, boundary_pitch
from ._result import IKResult


def limited(chain: Chain, x: float, y: float, z: float, seed: Q) -> Found:
    """Position only, where a joint limit refuses ``chain.free``'s pitch: every solution at
    the boundary pitch nearest the seed's at which the arm fits, unsorted; [] if none.
    The boundary search one base branch at a time (``boundary_search``)."""
    fam, solve = chain.family, chain.fixed
    assert fam is not None and solve is not None
    ways = _ways(fam, x, y, z, seed)
    if isinstance(ways, str):
        return []
    want, rho, gap, pitch = preferred(chain, seed), math.hypot(x, y), math.inf, 0.0
    if chain.boundary is None:  # no last link: no boundary circle to search
        return []
    for r, q0 in ways:
        if base_fits(chain, fam, q0, FLOATS):
            g, at = boundary_search(chain, r, z, rho, want)
            gap, pitch = (g, at) if g < gap else (gap, pitch)
    return solve(x, y, z, pitch, seed, None) if gap < math.inf else []


def family_ik(
    chain: Chain, p: tuple[float, float, float], pitch: float | None, seed: tuple[float, ...]
) -> IKResult:
    """The base yaw + planar closed form of ``chain`` (``chain.fixed`` set): tool point p
    [m] at ``pitch`` [rad] (None: the model's default, else free) from ``seed`` [rad]."""
    solve = chain.fixed
    assert solve is not None
    x, y, z = p
    if pitch is None:
        pitch = chain.default_pitch
    free, at = chain.free, pitch
    if chain.shift is not None:  # the family's frame; p and pitch stay the world's
        x, y, at = chain.based(x, y, pitch)
    if at is not None or free is None:
        found = solve(x, y, z, at, seed, None)
    elif not (found := free(x, y, z, seed)):  # type: ignore[assignment]
        found = [] if found is None else limited(chain, x, y, z, seed)
    if not found:
        if not p[0] * p[0] + p[1] * p[1] + z * z <= chain.reach2:
            raise too_far(chain, p, pitch)
        assert chain.family is not None
        raise refusal(chain, chain.family, p, pitch, seed)
    return IKResult.of(found, (p, pitch, None), chain)


def boundary_search(
    chain: Chain, r: float, z: float, rho: float, want: float
) -> tuple[float, float]:
    """On one base branch (plane radius r (signed), height z, horizontal distance rho [m])
    the boundary point nearest the pitch ``want`` [rad] at which the arm fits: (gap, its
    pitch [rad]), gap inf where none. Compiled where built, else the lanes in floats."""
    fam = chain.family
    assert fam is not None and chain.boundary is not None
    if COMPILED is not None:
        return COMPILED(chain.boundary, r, z, rho, want)
    g, at = boundary_pitch(chain, fam, r, z, rho, want, FLOATS)
    return float(g), float(at)


def preferred(chain: Chain, seed: Q) -> float:
    """The pitch [rad] of the tool at joint angles ``seed``."""
    return seed_pitch(seed, (chain.home, chain.home_pitch, chain.state, chain.shift or (0.0, 0.0)))


def refusal(
    chain: Chain, fam: PlanarFamily, p: Q, pitch: float | None, seed: Q
) -> UnreachableError:
    """Why no solution fits ``p`` [m] at ``pitch`` [rad] (None: at the seed's pitch):
    the joint and limit when only the limits are in the way, else the reason. A base
    outside its limits is named only when no way round gives another reason."""
    assert chain.fixed is not None
    x, y, at = chain.based(p[0], p[1], pitch)
    if at is None and len(fam.planar) == 3:
        pitch = at = preferred(chain, seed)  # (said as measured from the base axis)
    misses = Misses()
    chain.fixed(x, y, p[2], at, seed, misses)
    limits = [v for v in misses.violations if v[1] != fam.base]
    if limits or (misses.violations and not misses.reasons):
        _, i, value = min(limits or misses.violations)
        lo, hi = math.degrees(chain.lower[i]), math.degrees(chain.upper[i])
        return UnreachableError(
            f"{chain.name} cannot reach {where(p, pitch)} inside its limits: "
            f"{chain.joint_names[i]} would be {math.degrees(value):.1f} deg, allowed "
            f"{lo:.1f}..{hi:.1f} deg; try another pitch or a point nearer the middle of the reach",
            reason="joint_limit",
        )
    reason: Reason = next((r for r in EXPLAIN if r in misses.reasons), "too_far")
    why = EXPLAIN[reason] if reason != "pitch" or len(fam.planar) == 3 else TWO_PLANAR
    return UnreachableError(f"{chain.name} cannot reach {where(p, pitch)}: {why}", reason=reason)


def wrist_refusal(chain: Chain, p: Q, R9: Q, seed: Q) -> UnreachableError:
    """Why no solution of the spherical-wrist closed form fits ``p`` [m] with rotation R9:
    a limit of the first three joints by name, else the position's reason, else the wrist."""
    assert chain.wrist_solve is not None
    misses = Misses()
    chain.wrist_solve(p[0], p[1], p[2], R9, seed, misses)
    if misses.violations:
        _, i, value = min(misses.violations)
        lo, hi = math.degrees(chain.lower[i]), math.degrees(chain.upper[i])
        return UnreachableError(
            f"{chain.name} cannot reach {mm(p)} with that orientation inside its limits: "
            f"{chain.joint_names[i]} would be {math.degrees(value):.1f} deg, allowed "
            f"{lo:.1f}..{hi:.1f} deg; try a point nearer the middle of the reach",
            reason="joint_limit",
        )
    reason: Reason = next((r for r in EXPLAIN if r in misses.reasons), "joint_limit")
    why = EXPLAIN.get(reason, WRIST)
    return UnreachableError(
        f"{chain.name} cannot reach {mm(p)} with that orientation: {why}", reason=reason
    )


def too_far(chain: Chain, p: Q, pitch: float | None) -> UnreachableError:
    """The error for a target beyond every pose's reach."""
    return UnreachableError(
        f"{chain.name} cannot reach {where(p, pitch)}: {EXPLAIN['too_far']}", reason="too_far"
    )


def where(p: Q, pitch: float | None) -> str:
    """The target in the user's units, briefly: '(x, y, z) mm at pitch P deg'."""
    return mm(p) if pitch is None else f"{mm(p)} at pitch {brief(math.degrees(pitch))} deg"


EXPLAIN: dict[Reason, str] = {
    "too_far": "too far away for the arm's links; try a point nearer the base",
    "too_close": "too close to the base for the arm's links; try a point further out",
    "off_plane": "the point is outside the arm's plane of motion",
    "pitch": "on the base axis the gripper's pitch is within -90..90 deg; give one in that"
    " range, or move the point off the axis",
}
WRIST = "the wrist cannot turn to that orientation inside its limits; try another orientation"
TWO_PLANAR = (
    "the pitch follows from the position on an arm with two planar joints; leave the pitch out"
)
