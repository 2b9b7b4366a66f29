"""What ``Arm`` is given, checked before anything moves: numbers in the user's units
and the timing options of a move (InputError naming the argument otherwise)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._errors import InputError
from ._inputs import has_bool, shown
from .model import MAX_MOVE_S, check_duration, check_speed

F64 = NDArray[np.float64]


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
    (True and False are not: ``numbers([True, 0, 100], ...)`` is refused), or, with
    ``finite``, not finite (None and NaN included). ``one``: one value ("must be a number")."""
    kind = "a number" if one else "numbers"
    try:
        a = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be {kind}, got {shown(values)}") from None
    if has_bool(values):
        raise InputError(f"{what} must be {kind}, not True or False, got {shown(values)}")
    if finite and not np.all(np.isfinite(a)):
        raise InputError(f"{what} must be finite numbers, got {shown(values)}")
    return a


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
    """A pitch given in degrees, checked, in radians (None stays None: no pitch)."""
    return None if pitch is None else math.radians(number(pitch, "pitch [deg]"))
