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

import numpy as np

from .._errors import Reason, UnreachableError
from ._chain import Chain
from ._closed_fast import Found, Misses, Q
from ._family import PlanarFamily
from ._pitch_range import candidates

_TWO_PI = 2.0 * math.pi


def solve(chain: Chain, fam: PlanarFamily, p: Q, pitch: float | None, seed: Q) -> Found:
    """Every solution for tool point ``p`` [m] and ``pitch`` [rad] (None: the nearest
    the seed's that fits, with 3 planar joints), unsorted.

    Raises:
        UnreachableError: none; ``reason`` says why, the message names the joint and
            limit when only the limits are in the way.
    """
    x, y, z = p
    fixed = chain.fixed
    assert fixed is not None
    if pitch is not None or len(fam.planar) == 2:
        found = fixed(x, y, z, pitch, seed, None)
    else:
        found = _free(chain, fam, x, y, z, seed)
    if not found:
        if pitch is None and len(fam.planar) == 3:
            pitch = preferred(chain, seed)
        misses = Misses()
        fixed(x, y, z, pitch, seed, misses)
        raise unreachable(chain, p, pitch, misses)
    return found


def preferred(chain: Chain, seed: Q) -> float:
    """The pitch [rad] of the tool at joint angles ``seed``."""
    st = chain.state(list(seed))
    (ax, ay, az), (px, py, _) = st.R[0], st.p
    rho = math.hypot(px, py)
    h = (ax * px + ay * py) / rho if rho >= 1e-9 else math.hypot(ax, ay)
    return math.atan2(az, h)


def _free(chain: Chain, fam: PlanarFamily, x: float, y: float, z: float, seed: Q) -> Found:
    """Position only: the solutions at the pitch nearest the seed's at which the arm fits."""
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
    """The nearest fitting pitch among those where the fit can change (see ``_pitch_range``)."""
    assert chain.fixed is not None
    pitches = candidates(chain, fam, np.array([[x, y, z]]), np.array([seed]), np.array([want]))[0]
    for pitch in pitches[np.isfinite(pitches)].tolist():
        found = chain.fixed(x, y, z, pitch, seed, None)
        if found:
            return found
    return []


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
