"""What ``Arm`` is given, checked before anything moves: numbers in the user's units
(numbers, not text: ``"200"`` is refused as ``"open"`` is) and the timing options of a
move (InputError naming the argument otherwise)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._errors import InputError
from ._inputs import has_bool, shown
from .model import MAX_MOVE_S, check_duration, check_speed

F64 = NDArray[np.float64]
PITCH_LIMIT_DEG = 180.0  # a pitch [deg] is -180..180; beyond it is a slip, not another angle


@dataclass(frozen=True)
class Timing:
    """A move's timing options, checked: speed (fraction of max, None = 1), duration [s],
    whether to wait, and timeout [s] (None: none)."""

    speed: float | None
    duration: float | None
    wait: bool
    timeout: float | None


def numbers(values: object, what: str, *, finite: bool = True, one: bool = False) -> F64:
    """``values`` as a float array; InputError naming ``what`` if they are not numbers
    (True and False are not: ``numbers([True, 0, 100], ...)`` is refused, nor is text
    such as ``"200"``, which numpy would read as 200), or, with ``finite``, not finite
    (None and NaN included). ``one``: one value ("must be a number")."""
    kind = "a number" if one else "numbers"
    if has_text(values):
        raise InputError(f"{what} must be {kind}, not text, got {shown(values)}")
    try:
        a = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be {kind}, got {shown(values)}") from None
    if has_bool(values):
        raise InputError(f"{what} must be {kind}, not True or False, got {shown(values)}")
    if finite and not np.all(np.isfinite(a)):
        raise InputError(f"{what} must be finite numbers, got {shown(values)}")
    return a


def has_text(value: object) -> bool:
    """Whether ``value`` is or holds text (a str or bytes, a text array, or a tuple or
    list with one inside): numpy would read ``"200"`` as 200, armkit refuses it."""
    if isinstance(value, str | bytes):
        return True
    if isinstance(value, np.ndarray):
        if value.dtype.kind == "O":
            return any(has_text(v) for v in value.flat)
        return value.dtype.kind in "SU"
    if isinstance(value, tuple | list):
        return any(has_text(v) for v in value)
    return False


def timing_of(
    speed: float | None, duration: float | None, wait: bool, timeout: float | None
) -> Timing:
    """The timing options as floats, checked before any work is done (InputError naming
    the one that is not a number or out of its range: speed (0, 1], duration
    0..``MAX_MOVE_S`` s, timeout > 0 s)."""
    values = [
        None if v is None else number(v, name, finite=False)
        for v, name in ((speed, "speed"), (duration, "duration [s]"), (timeout, "timeout [s]"))
    ]
    if not isinstance(wait, bool | np.bool_):  # "no" would read as true
        raise InputError(f"wait must be True or False, got {shown(wait)}")
    if values[0] is not None:
        check_speed(values[0])
    if values[1] is not None:
        check_duration(values[1], MAX_MOVE_S)
    if values[2] is not None and not (math.isfinite(values[2]) and values[2] > 0):
        raise InputError(f"timeout must be a number of seconds > 0, got {shown(values[2])}")
    return Timing(values[0], values[1], bool(wait), values[2])


def number(value: object, what: str, *, finite: bool = True) -> float:
    """``value`` as one float (InputError naming ``what`` otherwise)."""
    a = numbers(value, what, finite=finite, one=True)
    if a.shape != ():
        raise InputError(f"{what} must be one number, got {shown(value)}")
    return float(a)


def pitch_radians(pitch: object) -> float | None:
    """A pitch given in degrees, checked, in radians (None stays None: no pitch). The pitch
    is the approach angle above the horizontal, -90 pointing straight down, so one beyond
    -180..180 (``PITCH_LIMIT_DEG``) is a slip (radians? an extra digit?), not another way
    to say an angle: InputError."""
    if pitch is None:
        return None
    deg = number(pitch, "pitch [deg]")
    if abs(deg) > PITCH_LIMIT_DEG:
        raise InputError(
            f"pitch [deg] must be -{PITCH_LIMIT_DEG:g}..{PITCH_LIMIT_DEG:g} (the approach angle "
            f"above the horizontal: 0 level, -90 pointing straight down), got {shown(deg)}"
        )
    return math.radians(deg)
