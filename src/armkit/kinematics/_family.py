"""Recognise the closed-form family: a base yaw joint (optional) followed by a
planar chain of 2 or 3 joints with parallel horizontal axes, then any roll
joints whose axis is the approach line through the tool point.

The test is geometric, on the chain's frames at q = 0, so it holds for any DH
convention, offsets and flips, and for a user's own arm of that shape.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel
from ._fk import fk_frames

F64 = NDArray[np.float64]
Vec2 = tuple[float, float]
_EPS = 1e-9


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
        u: the planar axis at q = 0, shape (3,).
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
    u: tuple[float, float, float]


def family_of(model: ArmModel) -> PlanarFamily | None:
    """The model's closed-form geometry, or None if it is not of the family (cached)."""
    if "family" not in model._cache:
        model._cache["family"] = _detect(model)
    fam: PlanarFamily | None = model._cache["family"]
    return fam


def why_not_family(model: ArmModel) -> str:
    """One line saying why the closed form does not apply ('' if it does)."""
    if family_of(model) is not None:
        return ""
    return (
        f"{model.name} is not a base yaw + planar chain (2-3 parallel horizontal axes, "
        "then only roll joints about the approach line); use a numeric method such as 'lm'"
    )


def _axes(model: ArmModel) -> tuple[list[F64], list[F64], F64]:
    """Each joint's signed axis and a point on it at q = 0, and the tool pose."""
    frames = fk_frames(model, np.zeros(model.dof))
    shift = 1 if model.convention == "modified" else 0
    axes = [frames[i + shift][:3, 2] * model.dh[i].sign for i in range(model.dof)]
    points = [frames[i + shift][:3, 3] for i in range(model.dof)]
    return axes, points, frames[-1]


def _detect(model: ArmModel) -> PlanarFamily | None:
    axes, points, tool = _axes(model)
    z = np.array([0.0, 0.0, 1.0])
    has_base = abs(axes[0] @ z) > 1 - _EPS and math.hypot(points[0][0], points[0][1]) < _EPS
    start = 1 if has_base else 0
    if start >= model.dof:
        return None
    u = axes[start] / np.linalg.norm(axes[start])
    if abs(u @ z) > _EPS:
        return None
    planar = [start]
    while planar[-1] + 1 < model.dof and abs(axes[planar[-1] + 1] @ u) > 1 - _EPS:
        planar.append(planar[-1] + 1)
    tip, approach = tool[:3, 3], tool[:3, 0]
    trailing = list(range(planar[-1] + 1, model.dof))
    if not 2 <= len(planar) <= 3 or abs(approach @ u) > _EPS:
        return None
    if not all(_on_line(axes[j], points[j], approach, tip) for j in trailing):
        return None
    return _geometry(model, has_base, axes, points, tool, u, planar, trailing)


def _on_line(axis: F64, point: F64, direction: F64, tip: F64) -> bool:
    """True if the joint axis is the line through ``tip`` along ``direction``."""
    parallel = bool(abs(axis @ direction) > 1 - _EPS)
    return parallel and float(np.linalg.norm(np.cross(tip - point, direction))) < _EPS


def _geometry(
    model: ArmModel,
    has_base: bool,
    axes: list[F64],
    points: list[F64],
    tool: F64,
    u: F64,
    planar: list[int],
    trailing: list[int],
) -> PlanarFamily:
    e_z = np.array([0.0, 0.0, 1.0])
    e_r = np.cross(e_z, u)

    def plane(p: F64) -> Vec2:
        return (float(p @ e_r), float(p @ e_z))

    centres = [plane(points[j]) for j in planar] + [plane(tool[:3, 3])]
    links = tuple((b[0] - a[0], b[1] - a[1]) for a, b in itertools.pairwise(centres))
    approach = plane(tool[:3, 0])
    return PlanarFamily(
        base=0 if has_base else None,
        base_sign=float(np.sign(axes[0][2])) if has_base else 1.0,
        planar=tuple(planar),
        sigma=tuple(float(np.sign(axes[j] @ u)) for j in planar),
        trailing=tuple(trailing),
        c1=centres[0],
        links=links,
        phi0=math.atan2(approach[1], approach[0]),
        lateral=float(tool[:3, 3] @ u),
        azimuth_r=math.atan2(e_r[1], e_r[0]),
        u=(float(u[0]), float(u[1]), float(u[2])),
    )
