"""A unit's calibration offsets for tasks (001): every grasp and release point
is commanded ``height`` higher and ``perpendicular`` further from the base, so
that this unit's arm lands where the plan wants it.

File (TOML, millimetres): ``height_offset_mm = 2.0`` and
``perpendicular_offset_mm = -1.5``; by default ``<config dir>/<arm>_tasks.toml``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from .._errors import ModelError
from .._files import config_dir
from .._toml_files import read_toml

MAX_OFFSET_MM = 50.0


class CalibrationError(ModelError, ValueError):
    """A task calibration file is missing or wrong (names the file and field)."""


@dataclass(frozen=True)
class Calibration:
    """Offsets added to every commanded grasp and release point [mm]: ``height`` up,
    ``perpendicular`` away from the base axis."""

    height: float = 0.0
    perpendicular: float = 0.0

    @property
    def zero(self) -> bool:
        """True when both offsets are zero."""
        return self.height == 0.0 and self.perpendicular == 0.0


def default_calibration_file(arm: str) -> Path:
    """``<config dir>/<arm>_tasks.toml``."""
    return config_dir() / f"{arm}_tasks.toml"


def load_calibration(path: str | Path) -> Calibration:
    """Read a task calibration file (millimetres).

    Raises:
        CalibrationError: missing file, not TOML, unknown key, or an offset not a
            number within +-50 mm.
    """
    p = Path(path).expanduser()
    data, _text = read_toml(p, CalibrationError, "task calibration file")
    allowed = ("height_offset_mm", "perpendicular_offset_mm")
    values = []
    for key in data:
        if key not in allowed:
            raise CalibrationError(
                f"{p}: field '{key}': unknown key; allowed: {', '.join(allowed)}"
            )
    for key in allowed:
        v = data.get(key, 0.0)
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
            raise CalibrationError(f"{p}: field '{key}': must be a number [mm], got {v!r}")
        if abs(v) > MAX_OFFSET_MM:
            raise CalibrationError(
                f"{p}: field '{key}': must be within +-{MAX_OFFSET_MM:g} mm, got {v}"
            )
        values.append(float(v))
    return Calibration(values[0], values[1])


def calibration_for(arm: str, path: str | Path | None = None) -> Calibration:
    """The calibration in ``path``, else the arm's default file if it exists, else zero."""
    if path is not None:
        return load_calibration(path)
    default = default_calibration_file(arm)
    return load_calibration(default) if default.is_file() else Calibration()
