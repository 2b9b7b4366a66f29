"""The position-only solver's boundary search for one base branch, compiled
(``_boundaryc.c``): where a joint limit refuses the pitch the scalar solver chose first
(``_closed_scalar.limited``), the boundary point nearest the wanted pitch at which the arm
fits. This module packs an arm's circles once (``pack_boundary``, kept as
``Chain.boundary``); ``_pitch_range.boundary_pitch`` (lanes) is the same search and its
reference, and runs in floats where the extension was not built.

Every boundary point is where the wrist circle about the target T (radius L3) meets
another circle: the elbow at a limit, straight or folded (about the shoulder), the
shoulder at a limit (about a fixed elbow point E), the wrist at a limit (links 2 and 3
one rigid link U: the elbow circle about the shoulder meets the circle of |U| about T).
Why compiled: in Python the ~14 circle meetings per branch cost ~7 us a branch, 5.5x the
normal path per call; compiled, well under a microsecond.
"""

from __future__ import annotations

import math
from array import array
from collections.abc import Callable

from ._family import PlanarFamily, Range

Q = tuple[float, ...]
Search = Callable[[bytes, float, float, float, float], tuple[float, float]]
_TWO_PI = 2.0 * math.pi
_PACKED = 48  # float64, the layout _boundaryc.c reads

try:
    from ._boundaryc import boundary as _boundary
except ImportError:  # not built (no C compiler): _closed_scalar runs the lanes in floats
    COMPILED: Search | None = None
else:
    COMPILED = _boundary


def pack_boundary(fam: PlanarFamily, lower: Q, upper: Q, ranges: tuple[Range, ...]) -> bytes | None:
    """The arm's boundary circles as ``_boundaryc.c`` reads them (see its header): from
    the family's links [m], the joints' limits [rad] and ``ranges`` (``joint_ranges``);
    None where the last link has no length (the tool point on the wrist axis: no circle)."""
    (c1x, c1z), ((v1x, v1z), (v2x, v2z), (v3x, v3z)) = fam.c1, fam.links
    l1, l2, l3 = fam.l1, fam.l2, math.hypot(v3x, v3z)
    if l3 < 1e-12:
        return None
    (j1, j2, j3), (s1, s2, s3) = fam.planar, fam.sigma
    k = fam.phi0 - math.atan2(v3z, v3x)
    out = array("d", [c1x, c1z, v2x, v2z, math.cos(k), math.sin(k)])
    out.extend([math.cos(k) / l3, math.sin(k) / l3, l1 * l1, l2 * l2, l3 * l3, fam.lateral])
    lo, hi = sorted((s2 * lower[j2] + fam.bend, s2 * upper[j2] + fam.bend))
    elbows = []  # (d^2, x l1 / d^2, y l1 / d^2): W at d from the shoulder, E turned from W
    for b in {lo, hi} | {b for b in (0.0, math.pi) if (b - lo) % _TWO_PI <= hi - lo}:
        x, y = l1 + l2 * math.cos(b), l2 * math.sin(b)
        if math.hypot(x, y) > 1e-12:
            elbows += [x * x + y * y, x * l1 / (x * x + y * y), y * l1 / (x * x + y * y)]
    out.extend([len(elbows) // 3, *elbows, *[0.0] * (12 - len(elbows))])
    for a in (lower[j1], upper[j1]):  # the elbow point with the shoulder at a limit
        c, s = math.cos(s1 * a), math.sin(s1 * a)
        out.extend([c * v1x - s * v1z, s * v1x + c * v1z])
    for a in (lower[j3], upper[j3]):  # U = link 2 + link 3 turned by the wrist's limit
        c, s = math.cos(s3 * a), math.sin(s3 * a)
        ux, uz = v2x + c * v3x - s * v3z, v2z + s * v3x + c * v3z
        out.extend([ux, uz, ux * ux + uz * uz])
    out.extend([len(ranges), *[float(v) for g in ranges for v in g]])
    out.extend([0.0] * (_PACKED - len(out)))
    return out.tobytes()
