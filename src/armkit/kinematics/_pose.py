"""Reading a pose the way arm users do: position and the gripper's pitch."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._inputs import array
from ._lanes import LANES, Ops

F64 = NDArray[np.float64]
Vec3 = tuple[float, float, float]


def pitch_of(T: F64) -> F64:
    """The gripper's pitch: angle of the approach axis above the horizontal [rad].

    Measured in the vertical plane through the base axis and the tool point,
    positive upwards, 0 = pointing horizontally away from the base, -pi/2 =
    straight down. With the tool point on the base axis, the horizontal
    direction of the approach axis is used instead.

    Args:
        T: tool pose(s), shape (4, 4) or (N, 4, 4).

    Returns:
        Pitch [rad], shape () or (N,), in (-pi, pi].
    """
    if not (isinstance(T, np.ndarray) and T.dtype == np.float64 and T.shape[-2:] == (4, 4)):
        T = array(T, "T (a tool pose)", ((4, 4), (None, 4, 4)), "homogeneous transform")
    a, p = T[..., :3, 0], T[..., :3, 3]
    return np.asarray(pitch_lanes((a[..., 0], a[..., 1], a[..., 2]), (p[..., 0], p[..., 1])))


def pitch_lanes(a: tuple[F64, F64, F64], p: tuple[F64, F64]) -> F64:
    """``pitch_of`` for approach axes a and tool points' (x, y) p [m], given component by
    component as arrays of any one shape (floats count as constant arrays) [rad]."""
    (ax, ay, az), (px, py) = a, p
    rho = np.hypot(px, py)
    on_axis = rho < 1e-9
    along = (ax * px + ay * py) / np.where(on_axis, 1.0, rho)
    return np.asarray(np.arctan2(az, np.where(on_axis, np.hypot(ax, ay), along)))


def pitch_scalar(a: Vec3, p: tuple[float, ...]) -> float:
    """``pitch_of`` for approach axis a and tool point p [m] (x, y: z is not needed), in
    plain floats [rad]."""
    rho = math.hypot(p[0], p[1])
    h = (a[0] * p[0] + a[1] * p[1]) / rho if rho >= 1e-9 else math.hypot(a[0], a[1])
    return math.atan2(a[2], h)


def pitch_of_phi(c: Any, s: Any, r: Any, rho: Any, ops: Ops = LANES) -> Any:
    """The pitch [rad] in [-pi, pi] of plane approach angles given by their cosines c and
    sines s, at plane radii r (signed) and horizontal distances rho [m] (see ``pitch_of``),
    over lanes (``_lanes``)."""
    axis = (abs(r) < 1e-12) | (rho < 1e-12)
    return ops.atan2(s, ops.where(axis, abs(c), c * r / ops.where(axis, 1.0, rho)))
