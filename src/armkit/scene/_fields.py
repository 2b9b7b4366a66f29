"""Reading one table of a scene file: every key checked, errors naming file and field."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._errors import SceneError

F64 = NDArray[np.float64]
MAX_MM = 10_000.0  # no coordinate or size in a scene is beyond 10 m
_MISSING: Any = object()


class Entry:
    """One TOML table of a scene file (``where`` names it, e.g. ``cubes[2]``)."""

    def __init__(self, path: Path, where: str, data: Any, allowed: tuple[str, ...]) -> None:
        self.path, self.where = path, where
        if not isinstance(data, dict):
            raise self.fail("", f"must be a table, got {type(data).__name__}")
        for key in data:
            if key not in allowed:
                raise self.fail(key, f"unknown key; allowed: {', '.join(allowed)}")
        self.data: dict[str, Any] = data

    def fail(self, key: str, message: str) -> SceneError:
        """A SceneError naming the file and ``where.key``."""
        field = f"{self.where}.{key}".strip(".")
        return SceneError(
            f"{self.path}: field '{field}': {message}", file=str(self.path), field=field
        )

    def has(self, key: str) -> bool:
        """True if the key is given."""
        return key in self.data

    def _get(self, key: str, default: Any) -> Any:
        if key in self.data:
            return self.data[key]
        if default is _MISSING:
            raise self.fail(key, "missing (required)")
        return default

    def number(
        self, key: str, default: Any = _MISSING, lo: float = -MAX_MM, hi: float = MAX_MM
    ) -> float:
        """A finite number in [lo, hi] (in the file's units)."""
        value = self._get(key, default)
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.fail(key, f"must be a number, got {value!r}")
        if not (math.isfinite(value) and lo <= value <= hi):
            raise self.fail(key, f"must be {lo:g}..{hi:g}, got {value!r}")
        return float(value)

    def positive_mm(self, key: str, default: Any = _MISSING) -> float:
        """A length > 0 [mm] in the file, returned in metres."""
        value = self.number(key, default)
        if value <= 0:
            raise self.fail(key, f"must be > 0 mm, got {value:g}")
        return value / 1000.0

    def mm(self, key: str, default: Any = _MISSING) -> float:
        """A coordinate [mm] in the file, returned in metres."""
        return self.number(key, default) / 1000.0

    def deg(self, key: str, default: Any = _MISSING) -> float:
        """An angle [deg] in the file (-360..360), returned in radians."""
        return math.radians(self.number(key, default, lo=-360.0, hi=360.0))

    def integer(self, key: str, default: Any = _MISSING, lo: int = 0, hi: int = 1000) -> int:
        """An integer in [lo, hi]."""
        value = self._get(key, default)
        if isinstance(value, bool) or not isinstance(value, int) or not lo <= value <= hi:
            raise self.fail(key, f"must be a whole number {lo}..{hi}, got {value!r}")
        return value

    def text(self, key: str, default: Any = _MISSING, choices: tuple[str, ...] = ()) -> str:
        """A string (one of ``choices`` if given)."""
        value = self._get(key, default)
        if not isinstance(value, str):
            raise self.fail(key, f"must be a string, got {value!r}")
        if choices and value not in choices:
            raise self.fail(key, f"must be one of {', '.join(choices)}, got {value!r}")
        return value

    def name(self) -> str:
        """The entry's ``name``: an identifier (letters, digits, _ and -)."""
        value = self.text("name")
        if not value or not all(c.isalnum() or c in "_-" for c in value) or len(value) > 64:
            raise self.fail("name", f"must be 1..64 letters, digits, '_' or '-', got {value!r}")
        return value

    def numbers(self, key: str, count: int, default: Any = _MISSING) -> list[float]:
        """A list of ``count`` finite numbers, each within +-10 m (in the file's units)."""
        value = self._get(key, default)
        if not isinstance(value, list) or len(value) != count:
            raise self.fail(key, f"must be a list of {count} numbers, got {value!r}")
        out = []
        for k, item in enumerate(value):
            if isinstance(item, bool) or not isinstance(item, int | float):
                raise self.fail(f"{key}[{k}]", f"must be a number, got {item!r}")
            if not (math.isfinite(item) and abs(item) <= MAX_MM):
                raise self.fail(f"{key}[{k}]", f"must be within +-{MAX_MM:g}, got {item!r}")
            out.append(float(item))
        return out

    def point_mm(self, key: str, default: Any = _MISSING) -> F64:
        """``[x, y, z]`` [mm] in the file, returned in metres, shape (3,)."""
        return np.array(self.numbers(key, 3, default)) / 1000.0

    def sizes_mm(self, key: str, count: int) -> tuple[float, ...]:
        """``count`` lengths > 0 [mm], returned in metres."""
        values = self.numbers(key, count)
        for k, v in enumerate(values):
            if v <= 0:
                raise self.fail(f"{key}[{k}]", f"must be > 0 mm, got {v:g}")
        return tuple(v / 1000.0 for v in values)

    def direction(self, key: str, default: Any = _MISSING) -> F64:
        """A direction ``[x, y, z]`` (any length > 0), returned as a unit vector (3,)."""
        v = np.array(self.numbers(key, 3, default))
        norm = float(np.linalg.norm(v))
        if norm < 1e-9:
            raise self.fail(key, f"must be a non-zero direction, got {v.tolist()}")
        unit: F64 = v / norm
        return unit


def entries(path: Path, data: dict[str, Any], key: str, allowed: tuple[str, ...]) -> list[Entry]:
    """The ``[[key]]`` array of tables of a scene file, each as an Entry."""
    items = data.get(key, [])
    if not isinstance(items, list):
        raise SceneError(f"{path}: field '{key}': must be an array of tables ([[{key}]])")
    return [Entry(path, f"{key}[{k}]", item, allowed) for k, item in enumerate(items)]
