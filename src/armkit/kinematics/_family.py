"""Recognise the closed-form family: a base yaw joint (optional) followed by a
planar chain of 2 or 3 joints with parallel horizontal axes, then any roll
joints whose axis is the approach line through the tool point.

The test is geometric, on the joint axes and the tool at q = 0, so it holds
for any chain (DH in either convention, offsets and flips, URDF frames) and
for a user's own arm of that shape. Links shorter than ``MIN_LINK`` or longer
than ``MAX_LINK`` are refused with the reason (the law of cosines divides by
their lengths); such an arm is solved numerically.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._lanes import FLOATS, LANES, Ops

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
Vec2 = tuple[float, float]
Vec3 = tuple[float, float, float]
Lane = Any  # a float, or an array: one value per lane
_EPS = 1e-9
MIN_LINK = 1e-6  # [m]
MAX_LINK = 1e4  # [m]
_CHECK = 0.5e-9  # [rad]: a boundary point fits within half the solvers' slack
# [rad]: on an arm with 2 planar joints the pitch follows from the position; a pitch
# given there is accepted this near the one the position implies (a position typed to
# a few digits implies a pitch a hair off the one meant)
PITCH_TOLERANCE = math.radians(0.01)
Vec = tuple[float, ...]


@dataclass(frozen=True)
class PlanarFamily:
    """The closed-form geometry of a family arm, in the arm's vertical plane.

    Plane coordinates (r, z): r along e_r = z_world x u, z up; u is the planar
    joints' axis at q = 0. Positive q_j turns the plane by sigma_j * q_j
    (counter-clockwise from e_r towards z).

    Attributes:
        base: index of the yaw joint, or None (planar arm in a fixed plane).
        base_sign: +1 if a positive base angle turns counter-clockwise seen from above.
        planar: indices of the planar joints, 2 or 3.
        sigma: +1/-1 per planar joint.
        trailing: indices of roll joints that move neither the tool point nor its pitch.
        c1: first planar joint in the plane [m].
        links: 2D link vectors at q = 0: joint to joint, the last one to the tool point [m].
        phi0: approach angle in the plane at q = 0 [rad].
        lateral: tool point's offset along u [m].
        azimuth_r: azimuth of e_r at q = 0 [rad].
        u: the planar axis at q = 0.
        l1, l2: lengths of the first two links [m]; ang1: angle of link 1 at q = 0,
            bend: angle of link 2 relative to link 1 at q = 0 [rad].
    """

    base: int | None
    base_sign: float
    planar: tuple[int, ...]
    sigma: tuple[float, ...]
    trailing: tuple[int, ...]
    c1: Vec2
    links: tuple[Vec2, ...]
    phi0: float
    lateral: float
    azimuth_r: float
    u: Vec3
    l1: float
    l2: float
    ang1: float
    bend: float


def base_shift(axis: Vec3, point: Vec3) -> tuple[float, float]:
    """Where a vertical first joint axis (signed unit ``axis`` through ``point`` [m]) meets
    the world's horizontal plane, (x, y) [m]; (0, 0) if it is not vertical or is at the
    origin. The family is recognised in the world frame moved there, so a fixed offset
    before the first joint (a URDF's root beside the base axis) keeps the closed form."""
    if abs(axis[2]) <= 1 - _EPS or math.hypot(point[0], point[1]) < 1e-12:
        return 0.0, 0.0
    return point[0], point[1]


def base_pitch(pitch: Lane, x: Lane, y: Lane, bx: float, by: float, ops: Ops = FLOATS) -> Lane:
    """A pitch [rad] as ``pitch_of`` measures it (the horizontal direction from the world
    origin to the target (x, y) [m]) measured instead from the base axis at (bx, by) [m].
    The approach's horizontal part lies along the target's direction from the base axis,
    so the two tangents differ by k, the cosine between the two directions."""
    dx, dy = x - bx, y - by
    d, rho = ops.hypot(dx, dy), ops.hypot(x, y)
    far = (d > 1e-12) & (rho > 1e-12)
    k = ops.where(far, (dx * x + dy * y) / ops.where(far, d * rho, 1.0), 1.0)
    return ops.atan2(abs(k) * ops.sin(pitch), ops.where(k < 0.0, -1.0, 1.0) * ops.cos(pitch))


def detect(axes: list[Vec3], points: list[Vec3], tool: F64) -> PlanarFamily | str:
    """The family geometry from each joint's signed axis and a point on it at q = 0 and
    the tool pose (4, 4) there; or one line saying why the arm is not of the family."""
    ax, pts = [np.array(a) for a in axes], [np.array(p) for p in points]
    dof, z = len(ax), np.array([0.0, 0.0, 1.0])
    has_base = abs(ax[0] @ z) > 1 - _EPS and math.hypot(pts[0][0], pts[0][1]) < _EPS
    start = 1 if has_base else 0
    why = "is not a base yaw + planar chain (2-3 parallel horizontal axes, then only roll joints about the approach line)"
    if start >= dof or abs(ax[start] @ z) > _EPS:
        return why
    u = ax[start] / np.linalg.norm(ax[start])
    planar = [start]
    while planar[-1] + 1 < dof and abs(ax[planar[-1] + 1] @ u) > 1 - _EPS:
        planar.append(planar[-1] + 1)
    tip, approach = tool[:3, 3], tool[:3, 0]
    trailing = list(range(planar[-1] + 1, dof))
    if not 2 <= len(planar) <= 3 or abs(approach @ u) > _EPS:
        return why
    if not all(_on_line(ax[j], pts[j], approach, tip) for j in trailing):
        return why
    return _geometry(has_base, ax, pts, tool, u, planar, trailing)


def _on_line(axis: F64, point: F64, direction: F64, tip: F64) -> bool:
    """True if the joint axis is the line through ``tip`` along ``direction``."""
    parallel = bool(abs(axis @ direction) > 1 - _EPS)
    return parallel and float(np.linalg.norm(np.cross(tip - point, direction))) < _EPS


def _geometry(
    has_base: bool, ax: list[F64], pts: list[F64], tool: F64, u: F64, planar: list[int],
    trailing: list[int],
) -> PlanarFamily | str:  # fmt: skip
    e_z = np.array([0.0, 0.0, 1.0])
    e_r = np.cross(e_z, u)

    def plane(p: F64) -> Vec2:
        return (float(p @ e_r), float(p @ e_z))

    centres = [plane(pts[j]) for j in planar] + [plane(tool[:3, 3])]
    links = tuple((b[0] - a[0], b[1] - a[1]) for a, b in itertools.pairwise(centres))
    (v1x, v1z), (v2x, v2z) = links[0], links[1]
    l1, l2 = math.hypot(v1x, v1z), math.hypot(v2x, v2z)
    for k, length in ((1, l1), (2, l2)):
        if not MIN_LINK <= length <= MAX_LINK:
            return (
                f"has a planar link {k} of {length * 1000:.3g} mm; the closed form needs "
                f"{MIN_LINK * 1000:g} mm to {MAX_LINK / 1000:g} km"
            )
    approach = plane(tool[:3, 0])
    ang1 = math.atan2(v1z, v1x)
    return PlanarFamily(
        base=0 if has_base else None,
        base_sign=float(np.sign(ax[0][2])) if has_base else 1.0,
        planar=tuple(planar),
        sigma=tuple(float(np.sign(ax[j] @ u)) for j in planar),
        trailing=tuple(trailing),
        c1=centres[0],
        links=links,
        phi0=math.atan2(approach[1], approach[0]),
        lateral=lateral if abs(lateral := float(tool[:3, 3] @ u)) > 1e-12 else 0.0,
        azimuth_r=math.atan2(e_r[1], e_r[0]),
        u=(float(u[0]), float(u[1]), float(u[2])),
        l1=l1,
        l2=l2,
        ang1=ang1,
        bend=math.atan2(v2z, v2x) - ang1,
    )


def wrist_range(fam: PlanarFamily, lower: float, upper: float) -> tuple[float, float]:
    """Smallest and largest distance [m] from the first planar joint to the end of
    link 2 that the second planar joint's limits [rad] allow (both elbow branches)."""
    ends = sorted((fam.sigma[1] * lower + fam.bend, fam.sigma[1] * upper + fam.bend))
    full = upper - lower >= 2.0 * math.pi

    def contains(angle: float) -> bool:
        return full or (angle - ends[0]) % (2.0 * math.pi) <= ends[1] - ends[0]

    cos_ends = (math.cos(ends[0]), math.cos(ends[1]))
    c_max = 1.0 if contains(0.0) else max(cos_ends)
    c_min = -1.0 if contains(math.pi) else min(cos_ends)
    l1, l2 = fam.l1, fam.l2
    return (
        math.sqrt(max(l1 * l1 + l2 * l2 + 2 * l1 * l2 * c_min, 0.0)),
        math.sqrt(max(l1 * l1 + l2 * l2 + 2 * l1 * l2 * c_max, 0.0)),
    )


@dataclass(frozen=True)
class Planes:
    """The base branches of N targets, B of them (facing the target, and over the shoulder;
    one without a base), stacked branch after branch: per branch and target (B * N,) the
    plane radius r (signed), the base angle q0 [rad], the horizontal distance rho and
    height z of the target [m]; and the targets with no branch at all (N,)."""

    r: F64
    q0: F64
    rho: F64
    z: F64
    bad: Bool

    def per_target(self, v: NDArray[Any]) -> NDArray[Any]:
        """Stacked values (B * N, ...) as (B, N, ...)."""
        return v.reshape(-1, len(self.bad), *v.shape[1:])


def planes(fam: PlanarFamily, P: F64, seed: F64) -> Planes:
    """The base branches of targets P (N, 3) [m] (seeds (N, dof) [rad] give the base angle
    on the base axis)."""
    x, y, z = P[:, 0], P[:, 1], P[:, 2]
    rho2 = x * x + y * y
    rho = np.sqrt(rho2)
    if fam.base is None:
        ux, uy, uz = fam.u
        bad = np.abs(x * ux + y * uy + z * uz - fam.lateral) > 1e-9
        return Planes(ux * y - uy * x, np.zeros(len(P)), rho, z, bad)
    r2 = rho2 - fam.lateral * fam.lateral
    r = np.sqrt(np.maximum(r2, 0.0))
    r = np.concatenate([r, np.where(rho < 1e-12, -0.0, -r)])
    axis = np.concatenate([rho, rho]) < 1e-12
    turn = np.repeat([0.0, np.pi], len(P))  # on the axis: the seed's base angle, or turned round
    lean = np.arctan2(-fam.lateral, r) if fam.lateral else -turn
    heading = np.tile(np.arctan2(y, x) - fam.azimuth_r, 2)
    q0 = np.where(axis, np.tile(seed[:, fam.base], 2) + turn, fam.base_sign * (heading - lean))
    return Planes(r, q0, np.tile(rho, 2), np.tile(z, 2), r2 < -1e-18)


def turn_of(fam: PlanarFamily, pitch: Lane, r: Lane, rho: Lane, ops: Ops = LANES) -> Any:
    """cos, sin and angle [rad] of the plane turn (from q = 0) that gives ``pitch`` [rad] in
    the base branch of plane radius r (signed) and horizontal distance rho [m] (see
    ``pitch_of``), over lanes; NaN on the base axis beyond +-90 deg, where no pitch is
    possible."""
    axis = (rho < 1e-12) | (abs(r) < 1e-12)
    pitch = ops.where((rho < 1e-12) & (abs(pitch) > math.pi / 2 + 1e-12), math.nan, pitch)
    sp, cp = ops.sin(pitch), ops.cos(pitch)
    cp = ops.where(axis | (r > 0), cp, -cp)  # reaching back the approach points the other way
    if fam.lateral:
        sp = sp * ops.where(axis, 1.0, abs(r) / ops.where(axis, 1.0, rho))
        norm = ops.sqrt(sp * sp + cp * cp)
        sp, cp = sp / norm, cp / norm
        phi = ops.atan2(sp, cp)
    else:  # the approach angle in the plane is the pitch, or pi - pitch reaching back
        phi = ops.where(axis | (r > 0), pitch, math.pi - pitch)
    c0, s0 = math.cos(fam.phi0), math.sin(fam.phi0)
    return cp * c0 + sp * s0, sp * c0 - cp * s0, phi - fam.phi0


Range = tuple[int, float, float, float]  # link k, its middle direction's cos, sin, least dot


def joint_ranges(fam: PlanarFamily, lower: Vec, upper: Vec) -> tuple[Range, ...]:
    """Per planar joint with a range under a turn: the direction its range's middle gives
    its link k (from the plane's r axis, or the previous link), and the least dot product of
    the link with it inside the range (lengths times the cosine of half the range) [m^2],
    for ``_pitch_range``'s boundary points; ``lower``, ``upper``: the joints' limits [rad]."""
    out = []
    angles = [math.atan2(vz, vx) for vx, vz in fam.links]
    for k, (j, s) in enumerate(zip(fam.planar, fam.sigma, strict=True)):
        lo, hi = sorted((s * lower[j], s * upper[j]))
        half = 0.5 * (hi - lo) + _CHECK
        if half < math.pi:
            mid = 0.5 * (lo + hi) + angles[k] - (angles[k - 1] if k else 0.0)
            lengths = math.hypot(*fam.links[k]) * (math.hypot(*fam.links[k - 1]) if k else 1.0)
            out.append((k, math.cos(mid), math.sin(mid), lengths * math.cos(half)))
    return tuple(out)
