"""Checks of the values read from a model file: each failure is a ``ModelError``
naming the file, the field, what is allowed and what was found."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

from .._errors import ModelError

NUM = (int, float)
MAX_LENGTH_MM = 10_000.0  # no link, offset or tool of an arm armkit drives is 10 m long
MIN_LENGTH_MM = 0.01  # a length is 0 or at least this (1e-300 is a typo, not a link)
MAX_ANGLE_DEG = 360.0
MAX_MOVE_S = 30.0  # longest single move Arm accepts [s] (a Dynamixel profile allows 32.7 s)
_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]{0,63}")


class Checker:
    """Type, key and range checks that name the file and the field."""

    def __init__(self, path: Path | None) -> None:
        self.path = path

    def fail(self, where: str, message: str) -> ModelError:
        """The error for ``where`` (a dotted field name)."""
        source = f"{self.path}: " if self.path is not None else ""
        file = None if self.path is None else str(self.path)
        return ModelError(f"{source}field '{where}': {message}", file=file, field=where)

    def table(
        self, data: Any, where: str, schema: dict[str, Any], required: tuple[str, ...]
    ) -> None:
        """``data`` is a table with only ``schema``'s keys, the ``required`` ones there,
        each of its type (``NUM`` = a finite number)."""
        if not isinstance(data, dict):
            raise self.fail(where, f"must be a table, got {_kind(data)}")
        for key in data:
            if key not in schema:
                allowed = ", ".join(schema)
                raise self.fail(f"{where}.{key}".lstrip("."), f"unknown key; allowed: {allowed}")
        for key in required:
            if key not in data:
                raise self.fail(f"{where}.{key}".lstrip("."), "missing (required)")
        for key, value in data.items():
            self.type(value, f"{where}.{key}".lstrip("."), schema[key])

    def type(self, value: Any, where: str, kind: Any) -> None:
        """``value`` is of ``kind`` (a type, or ``NUM``: a finite int or float)."""
        if kind is object:
            return
        if kind is NUM and (isinstance(value, bool) or not isinstance(value, NUM)):
            raise self.fail(where, f"must be a number, got {_shown(value)}")
        if kind is NUM and not math.isfinite(value):
            raise self.fail(where, f"must be finite, got {value!r}")
        if kind is not NUM and not isinstance(value, kind):
            raise self.fail(where, f"must be a {kind.__name__}, got {_kind(value)}")

    def numbers(self, value: Any, where: str, count: int | None) -> list[float]:
        """A list of ``count`` (None: any number of) finite numbers."""
        if not isinstance(value, list) or (count is not None and len(value) != count):
            n = f"{count} numbers" if count is not None else "a list of numbers"
            raise self.fail(where, f"must be {n}, got {_shown(value)}")
        for k, item in enumerate(value):
            self.type(item, f"{where}[{k}]", NUM)
        return [float(v) for v in value]

    def within(
        self,
        value: Any,
        where: str,
        low: float,
        high: float,
        unit: str = "",
        *,
        open_low: bool = False,
    ) -> float:
        """A finite number in [low, high] (``(low, high]`` with ``open_low``)."""
        self.type(value, where, NUM)
        x = float(value)
        if x > high or x < low or (open_low and x == low):
            span = f"> {low:g} and <= {high:g}" if open_low else f"{low:g}..{high:g}"
            raise self.fail(where, f"must be {span} {unit}".rstrip() + f", got {x:g}")
        return x

    def length(self, value: Any, where: str, *, signed: bool = False) -> float:
        """A length [mm]: 0, or MIN..MAX_LENGTH_MM (either sign with ``signed``)."""
        low = -MAX_LENGTH_MM if signed else 0.0
        x = self.within(value, where, low, MAX_LENGTH_MM, "mm")
        if 0.0 < abs(x) < MIN_LENGTH_MM:
            raise self.fail(where, f"must be 0 or at least {MIN_LENGTH_MM:g} mm long, got {x:g}")
        return x

    def angle(self, value: Any, where: str, limit: float = MAX_ANGLE_DEG) -> float:
        """An angle [deg] in -limit..limit."""
        return self.within(value, where, -limit, limit, "deg")

    def integer(self, value: Any, where: str, low: int, high: int) -> int:
        """A whole number in [low, high]."""
        if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
            raise self.fail(where, f"must be a whole number {low}..{high}, got {_shown(value)}")
        return value

    def choice_int(self, value: Any, where: str, allowed: tuple[int, ...]) -> int:
        """One of the whole numbers ``allowed``."""
        if isinstance(value, bool) or not isinstance(value, int) or value not in allowed:
            shown = ", ".join(str(a) for a in allowed)
            raise self.fail(where, f"must be one of {shown}, got {_shown(value)}")
        return value

    def identifier(self, value: Any, where: str) -> str:
        """A name made of letters, digits and '_', not starting with a digit, at most 64
        characters (it names files and columns)."""
        if not isinstance(value, str) or not _IDENTIFIER.fullmatch(value):
            raise self.fail(
                where,
                "must be a name of letters, digits and '_' (not starting with a digit, "
                f"at most 64 characters), got {_shown(value)}",
            )
        return value

    def choice(self, value: Any, where: str, allowed: tuple[str, ...]) -> str:
        """One of ``allowed``."""
        if not isinstance(value, str) or value not in allowed:
            raise self.fail(where, f"must be one of {', '.join(allowed)}, got {_shown(value)}")
        return value


def _kind(value: Any) -> str:
    names = {dict: "a table", list: "a list", str: "text", bool: "true/false"}
    return names.get(type(value), type(value).__name__)


def _shown(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."
