"""Plane geometry of the closed-form family: the two-link law of cosines, the
chain's forward map in its plane, and pitch <-> plane-angle conversion.

Angles here are *plane* angles alpha_j = sigma_j * q_j [rad]; lengths [m].
"""

from __future__ import annotations

import math

from ._family import PlanarFamily

Vec2 = tuple[float, float]


def two_link(fam: PlanarFamily, wx: float, wz: float) -> tuple[list[tuple[float, float]], str]:
    """Plane angles (alpha_1, alpha_2) of the first two planar joints that put
    the end of the second link at (wx, wz) [m], both elbow branches.

    Returns:
        The solutions (0, 1 or 2), and '' or the reason there are none
        (``"too_far"`` / ``"too_close"``).
    """
    v1, v2 = fam.links[0], fam.links[1]
    cx, cz = fam.c1
    dx, dz = wx - cx, wz - cz
    l1, l2 = math.hypot(*v1), math.hypot(*v2)
    cos_g = (dx * dx + dz * dz - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)
    if cos_g > 1.0 + 1e-12:
        return [], "too_far"
    if cos_g < -1.0 - 1e-12:
        return [], "too_close"
    gamma = math.acos(min(1.0, max(-1.0, cos_g)))
    bend = math.atan2(v2[1], v2[0]) - math.atan2(v1[1], v1[0])
    aim = math.atan2(dz, dx) - math.atan2(v1[1], v1[0])
    out = []
    for g in (gamma, -gamma) if gamma > 1e-12 else (gamma,):
        kx, kz = l1 + l2 * math.cos(g), l2 * math.sin(g)
        out.append((aim - math.atan2(kz, kx), g - bend))
    return out, ""


def forward(fam: PlanarFamily, alphas: tuple[float, ...]) -> tuple[float, float, float]:
    """Tool point (r, z) [m] and plane approach angle phi [rad] for plane angles."""
    x, z = fam.c1
    turn = 0.0
    for alpha, (vx, vz) in zip(alphas, fam.links, strict=True):
        turn += alpha
        c, s = math.cos(turn), math.sin(turn)
        x, z = x + c * vx - s * vz, z + s * vx + c * vz
    return x, z, fam.phi0 + turn


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
