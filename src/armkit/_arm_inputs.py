"""What ``Arm`` is given, checked before anything moves: numbers in the user's units
and the timing options of a move (InputError naming the argument otherwise)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._errors import InputError

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Timing:
    """A move's timing options, checked: speed (fraction of max, None = 1), duration [s],
    whether to wait, and timeout [s] (None: none)."""

    speed: float | None
    duration: float | None
    wait: bool
    timeout: float | None


def numbers(values: object, what: str, *, finite: bool = True) -> F64:
    """``values`` as a float array; InputError naming ``what`` if they are not numbers
    (or, with ``finite``, not finite: None and NaN included)."""
    try:
        a = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be numbers, got {values!r}") from None
    if finite and not np.all(np.isfinite(a)):
        raise InputError(f"{what} must be finite numbers, got {values!r}")
    return a


def timing_of(
    speed: float | None, duration: float | None, wait: bool, timeout: float | None
) -> Timing:
    """The timing options as floats (InputError naming the one that is not a number)."""
    values = [
        None if v is None else number(v, name, finite=False)
        for v, name in ((speed, "speed"), (duration, "duration [s]"), (timeout, "timeout [s]"))
    ]
    if not isinstance(wait, bool | np.bool_):  # "no" would read as true
        raise InputError(f"wait must be True or False, got {wait!r}")
    return Timing(values[0], values[1], bool(wait), values[2])


def number(value: object, what: str, *, finite: bool = True) -> float:
    """``value`` as one float (InputError naming ``what`` otherwise)."""
    a = numbers(value, what, finite=finite)
    if a.shape != ():
        raise InputError(f"{what} must be one number, got {value!r}")
    return float(a)


def pitch_radians(pitch: object) -> float | None:
    """A pitch given in degrees, checked, in radians (None stays None: no pitch)."""
    return None if pitch is None else math.radians(number(pitch, "pitch [deg]"))
