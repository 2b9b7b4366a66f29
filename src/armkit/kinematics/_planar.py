"""Plane geometry of the closed-form family, shared by its scalar and batch solvers:
base branches, pitch <-> plane turn, and the wrist's reachable range.

Angles here are plane angles alpha_j = sigma_j * q_j [rad]; lengths [m].
"""

from __future__ import annotations

import math

from ._family import PlanarFamily

_TWO_PI = 2.0 * math.pi
Plane = tuple[float, float, float]  # (r signed, rho, base angle) of one base branch


def wrist_range(fam: PlanarFamily, lower: float, upper: float) -> tuple[float, float]:
    """Smallest and largest distance [m] from the first planar joint to the end of
    link 2 that the second planar joint's limits [rad] allow (both elbow branches)."""
    s = fam.sigma[1]
    ends = sorted((s * lower + fam.bend, s * upper + fam.bend))
    full = upper - lower >= _TWO_PI

    def contains(angle: float) -> bool:
        return full or (angle - ends[0]) % _TWO_PI <= ends[1] - ends[0]

    cos_ends = (math.cos(ends[0]), math.cos(ends[1]))
    c_max = 1.0 if contains(0.0) else max(cos_ends)
    c_min = -1.0 if contains(math.pi) else min(cos_ends)
    l1, l2 = fam.l1, fam.l2
    return (
        math.sqrt(max(l1 * l1 + l2 * l2 + 2 * l1 * l2 * c_min, 0.0)),
        math.sqrt(max(l1 * l1 + l2 * l2 + 2 * l1 * l2 * c_max, 0.0)),
    )


def planes(fam: PlanarFamily, x: float, y: float, z: float, seed0: float) -> list[Plane] | str:
    """Per base branch the plane radius r (signed; < 0 reaching over the shoulder), the
    horizontal distance rho and the base angle [rad]; or why there is none."""
    if fam.base is None:
        ux, uy, uz = fam.u
        if abs(x * ux + y * uy + z * uz - fam.lateral) > 1e-9:
            return "off_plane"
        return [(-uy * x + ux * y, math.hypot(x, y), 0.0)]
    rho2 = x * x + y * y
    r2 = rho2 - fam.lateral * fam.lateral
    if r2 < -1e-18:
        return "too_close"
    r, rho = math.sqrt(max(r2, 0.0)), math.sqrt(rho2)
    if rho < 1e-12:  # on the base axis the base angle is free: the seed's, or turned round
        return [(0.0, 0.0, seed0), (-0.0, 0.0, seed0 + math.pi)]
    heading = math.atan2(y, x) - fam.azimuth_r
    return [
        (rr, rho, fam.base_sign * (heading - math.atan2(-fam.lateral, rr)))
        for rr in ((r, -r) if r > 1e-12 else (r,))
    ]


def phi_for_pitch(pitch: float, r: float, rho: float) -> float:
    """Plane approach angle [rad] that gives ``pitch`` [rad] at plane radius r (signed)
    and horizontal distance rho from the base axis [m] (see ``pitch_of``)."""
    if abs(r) < 1e-12 or rho < 1e-12:
        return pitch
    return math.atan2(math.sin(pitch) * abs(r) / rho, math.cos(pitch) * math.copysign(1.0, r))


def pitch_for_phi(phi: float, r: float, rho: float) -> float:
    """Inverse of ``phi_for_pitch``: pitch [rad] of plane approach angle ``phi``."""
    c = math.cos(phi)
    if abs(r) < 1e-12 or rho < 1e-12:
        return math.atan2(math.sin(phi), abs(c))
    return math.atan2(math.sin(phi), c * r / rho)
