"""The one rule for joint limits, grip width and move timing.

``Arm``, every driver and the motion planner call these functions and no
others, so a move is accepted or refused the same way whichever layer is asked
(see ``armkit.drivers.Driver`` for the contract built on them).

Timing of a joint move from ``q0`` to ``q1`` [rad] along the straight line in
joint space, every joint arriving together:

- no ``duration``: as fast as the limits allow for the way the device moves. A
  device that ramps (a Dynamixel profile, ``ramps=True``, the default) takes the
  shortest rest-to-rest trapezoid in line: every joint runs the same normalised
  trapezoid scaled by its distance, no joint above ``speed`` x its maximum
  velocity or above its maximum acceleration. A device that goes straight to
  speed (an SSC-32 group move, a Maestro's speed limits: the servos' own motors
  do the accelerating, ``ramps=False``) takes the shortest constant-speed move
  within ``speed`` x every joint's maximum velocity;
- a ``duration`` [s]: exactly that long. It must let every joint keep within
  ``speed`` x its servo's own velocity limit (``Joint.peak_velocity``: the model's
  ``servo_speed_dps``, else its maximum) moving at constant speed (a stream of short
  segments is such a move); shorter raises InputError. Within that time the
  device may ramp where the servo's acceleration limit allows (``ramp_time``).

``Arm`` also bounds a single move to ``MAX_MOVE_S`` (``longest=``): a duration
or a speed that would make one move crawl for longer is refused, not obeyed.
Drivers take any length and send a long move in pieces where their device's
command has a shorter limit (an SSC-32 group move, a Dynamixel profile).
"""

from __future__ import annotations

import math
import weakref

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError, JointLimitError
from .._inputs import brief, is_number, shown
from ._check import MAX_MOVE_S as MAX_MOVE_S
from ._types import ArmModel

F64 = NDArray[np.float64]


class GripWidthError(JointLimitError, InputError):
    """A gripper opening outside the model's range (a limit, and a bad value)."""


SLACK = 1e-9  # [rad] or [m]: values this far outside a limit still count as inside


def check_joints(model: ArmModel, q: ArrayLike) -> F64:
    """``q`` [rad] as a float array of shape (dof,), every joint inside its limits.

    Raises:
        InputError: wrong shape or a value that is not finite (names the arm's joints).
        JointLimitError: the first joint outside its limits, with the value and the range [deg].
    """
    try:
        arr = np.asarray(q, dtype=np.float64)
    except (TypeError, ValueError):
        arr = np.full(0, np.nan)
    if arr.shape == (model.dof,):
        low, high = _bounds(model)
        if all(a <= v <= b for a, v, b in zip(low, arr.tolist(), high, strict=True)):
            return arr  # the common case, kept cheap: every driver command passes here
    if arr.shape != (model.dof,) or not np.isfinite(arr).all():
        names = ", ".join(model.joint_names)
        raise InputError(
            f"{model.name} needs {model.dof} finite joint angles [rad] ({names}), got {shown(q)}"
        )
    for joint, angle in zip(model.joints, arr, strict=True):
        if not joint.lower - SLACK <= angle <= joint.upper + SLACK:
            raise JointLimitError(
                f"{joint.name} {math.degrees(angle):.2f} deg is outside its limits "
                f"{math.degrees(joint.lower):.2f}..{math.degrees(joint.upper):.2f} deg; "
                "choose an angle inside them"
            )
    return arr


_BOUNDS: weakref.WeakKeyDictionary[ArmModel, tuple[list[float], list[float]]]
_BOUNDS = weakref.WeakKeyDictionary()


def _bounds(model: ArmModel) -> tuple[list[float], list[float]]:
    """The limits with their slack [rad], one per joint (kept per model: a model is frozen)."""
    found = _BOUNDS.get(model)
    if found is None:
        found = [j.lower - SLACK for j in model.joints], [j.upper + SLACK for j in model.joints]
        _BOUNDS[model] = found
    return found


def check_grip(model: ArmModel, width: float) -> float:
    """``width`` [m] if it is inside the gripper's range, else GripWidthError in mm."""
    g = model.gripper
    if not g.present:
        raise GripWidthError(
            f"{model.name} has no gripper: its model gives no [gripper] width_mm range"
        )
    if not (math.isfinite(width) and g.width_min - SLACK <= width <= g.width_max + SLACK):
        raise GripWidthError(
            f"grip width {brief(width * 1000)} mm is outside {model.name}'s range "
            f"{g.width_min * 1000:.1f}..{g.width_max * 1000:.1f} mm"
        )
    return float(width)


def check_speed(speed: float | None) -> float:
    """``speed`` as a fraction of every joint's maximum velocity, (0, 1]; None = 1
    (InputError otherwise)."""
    if speed is None:
        return 1.0
    if not (is_number(speed) and math.isfinite(speed) and 0.0 < speed <= 1.0):
        raise InputError(f"speed must be a fraction of the maximum in (0, 1], got {shown(speed)}")
    return float(speed)


def check_duration(duration: float, longest: float | None = None) -> float:
    """``duration`` [s] as a float: a time >= 0, at most ``longest`` [s] if given (InputError)."""
    if longest is not None:
        if not (is_number(duration) and 0.0 <= duration <= longest):
            raise InputError(
                f"duration must be 0..{longest:g} s, got {shown(duration)} s; "
                "split a longer motion into several moves"
            )
    elif not (is_number(duration) and math.isfinite(duration) and duration >= 0):
        raise InputError(f"duration must be a time >= 0 s, got {shown(duration)}")
    return float(duration)


def limits(model: ArmModel, speed: float = 1.0, *, peak: bool = False) -> tuple[F64, F64]:
    """(velocity limits x ``speed`` [rad/s], acceleration limits [rad/s^2]), shape (dof,)
    each: the planning limits, or with ``peak`` the servos' own (``Joint.peak_*``)."""
    if peak:
        vmax = speed * np.array([j.peak_velocity for j in model.joints])
        return vmax, np.array([j.peak_acceleration for j in model.joints])
    vmax = speed * np.array([j.max_velocity for j in model.joints])
    amax = np.array([j.max_acceleration for j in model.joints])
    return vmax, amax


def trapezoid_time(distance: ArrayLike, vmax: ArrayLike, amax: ArrayLike) -> F64:
    """Shortest rest-to-rest time [s] per joint for ``distance`` [rad] (any sign) with
    velocity ``vmax`` [rad/s] and acceleration ``amax`` [rad/s^2] (triangular when short)."""
    d, v, a = (np.abs(np.asarray(x, dtype=np.float64)) for x in (distance, vmax, amax))
    triangle = d < v * v / a
    return np.where(triangle, 2.0 * np.sqrt(d / a), d / v + v / a)


def line_units(model: ArmModel, q0: ArrayLike, q1: ArrayLike, speed: float) -> tuple[float, float]:
    """(velocity, acceleration) of the normalised move 0 -> 1 along the line q0 -> q1: the
    most any joint allows, per unit of the whole move [1/s, 1/s^2]; (inf, inf) if nothing moves."""
    dist = np.abs(np.asarray(q1, dtype=np.float64) - np.asarray(q0, dtype=np.float64))
    moving = dist > 0
    if not np.any(moving):
        return math.inf, math.inf
    vmax, amax = limits(model, speed)
    return float(np.min(vmax[moving] / dist[moving])), float(np.min(amax[moving] / dist[moving]))


def shortest_time(model: ArmModel, q0: ArrayLike, q1: ArrayLike, speed: float = 1.0) -> float:
    """The shortest rest-to-rest time [s] of the move q0 -> q1 [rad] along the line."""
    v_unit, a_unit = line_units(model, q0, q1, speed)
    if math.isinf(v_unit):
        return 0.0
    return float(trapezoid_time(1.0, v_unit, a_unit))


def constant_speed_time(
    model: ArmModel, q0: ArrayLike, q1: ArrayLike, speed: float = 1.0, *, peak: bool = False
) -> float:
    """The least time [s] of the move q0 -> q1 [rad] at constant speed within every
    joint's ``speed`` x maximum velocity (``peak``: its servo's own, the shortest legal
    ``duration``)."""
    dist = np.abs(np.asarray(q1, dtype=np.float64) - np.asarray(q0, dtype=np.float64))
    vmax, _ = limits(model, speed, peak=peak)
    return float(np.max(dist / vmax, initial=0.0))


def move_time(
    model: ArmModel,
    q0: ArrayLike,
    q1: ArrayLike,
    *,
    speed: float | None = None,
    duration: float | None = None,
    ramps: bool = True,
    longest: float | None = None,
) -> float:
    """How long [s] the move q0 -> q1 [rad] takes under the rule of the module doc
    (``ramps``: whether the device ramps its speed, for moves without a duration;
    ``longest``: the most one move may take [s], None: no bound).

    Raises:
        InputError: a bad ``speed`` or ``duration``, a duration too short for the
            velocity limits (the message says how long the move needs), or a move
            longer than ``longest``.
    """
    frac = check_speed(speed)
    if duration is None:
        seconds = (shortest_time if ramps else constant_speed_time)(model, q0, q1, frac)
        if longest is not None and seconds > longest:  # a tiny speed: refuse rather than crawl
            raise InputError(
                f"this move would take {seconds:.0f} s at {frac * 100.0:g} % of the joints' "
                f"top speed; a move may take at most {longest:g} s: raise the speed"
            )
        return seconds
    duration = check_duration(duration, longest)
    needed = constant_speed_time(model, q0, q1, frac, peak=True)
    if duration < needed - 1e-9:
        raise InputError(
            f"duration {duration:.4g} s is too short: the servos' speed limits need "
            f"{needed:.4g} s or more for this move"
        )
    return duration


def ramp_time(total: float, distance: ArrayLike, amax: ArrayLike) -> float:
    """The shortest ramp [s] of a ``total``-second trapezoid that keeps every joint under
    ``amax`` [rad/s^2] over ``distance`` [rad] (d = a * ramp * (total - ramp)); 0 (a
    constant-speed move) when no ramp can: the move is too short for the acceleration. A
    ``total`` that is the triangle's own (``shortest_time`` of a short move: need = total^2
    up to rounding) ramps half of it, not none."""
    need = 4.0 * float(np.max(np.abs(np.asarray(distance)) / np.asarray(amax), initial=0.0))
    if total <= 0 or need > total * total * (1.0 + 1e-9):
        return 0.0
    return (total - math.sqrt(max(0.0, total * total - need))) / 2.0
