"""Units a script may write after a number, and the default for each kind of value.

Every quantity is converted to SI here (m, rad, s; fractions for percentages;
m/s for tool speeds), once, when the value is resolved.
"""

from __future__ import annotations

import math
from typing import Literal

Dim = Literal["length", "angle", "time", "percent", "speed", "count"]

# unit -> (dimension, factor to SI)
UNITS: dict[str, tuple[Dim, float]] = {
    "mm": ("length", 1e-3),
    "cm": ("length", 1e-2),
    "m": ("length", 1.0),
    "in": ("length", 0.0254),
    "deg": ("angle", math.pi / 180.0),
    "rad": ("angle", 1.0),
    "s": ("time", 1.0),
    "ms": ("time", 1e-3),
    "min": ("time", 60.0),
    "%": ("percent", 1e-2),
    "mm/s": ("speed", 1e-3),
    "cm/s": ("speed", 1e-2),
    "m/s": ("speed", 1.0),
}

# the unit a bare number has, for each dimension
DEFAULT_UNIT: dict[Dim, str] = {
    "length": "mm",
    "angle": "deg",
    "time": "s",
    "percent": "%",
    "speed": "mm/s",
    "count": "",
}

NOUN: dict[Dim, str] = {
    "length": "a length",
    "angle": "an angle",
    "time": "a time",
    "percent": "a percentage",
    "speed": "a speed",
    "count": "a whole number",
}


class UnitProblem(ValueError):
    """A number's unit is unknown or of the wrong kind (the message says which)."""


def units_of(dim: Dim) -> list[str]:
    """The units accepted for ``dim``."""
    return [u for u, (d, _) in UNITS.items() if d == dim]


def to_si(number: float, unit: str | None, dim: Dim) -> float:
    """``number`` written with ``unit`` (None: the default of ``dim``) in SI.

    Raises:
        UnitProblem: the unit is unknown or not one of ``dim``'s; a count not whole.
    """
    if dim == "count":
        if unit is not None:
            raise UnitProblem(f"a count takes no unit, got {number:g}{unit}")
        if number != int(number):
            raise UnitProblem(f"a count must be a whole number, got {number:g}")
        return number
    if unit is None:
        unit = DEFAULT_UNIT[dim]
    if unit not in UNITS:
        raise UnitProblem(f"unknown unit {unit!r}; {NOUN[dim]} takes {_listed(dim)}")
    have, factor = UNITS[unit]
    if have != dim:
        raise UnitProblem(
            f"{number:g}{unit} is {NOUN[have]}, but {NOUN[dim]} is needed ({_listed(dim)})"
        )
    return number * factor


def _listed(dim: Dim) -> str:
    return ", ".join(units_of(dim))
