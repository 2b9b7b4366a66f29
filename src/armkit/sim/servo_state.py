"""The simulated servo arm's state file: joint angles and grip, kept between CLI runs."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .._errors import DeviceError
from .._files import write_atomic
from ..model import ArmModel

F64 = NDArray[np.float64]


def load_state(path: str | Path, model: ArmModel) -> tuple[F64, float] | None:
    """Joint angles [rad] and grip width [m] saved for ``model`` at ``path``; None if
    there is no file. A file for another arm or outside the limits raises DeviceError."""
    file = Path(path)
    if not file.exists():
        return None
    try:
        data = json.loads(file.read_text(encoding="utf-8"))
        q = np.radians(np.asarray(data["q_deg"], dtype=np.float64))
        grip = float(data["grip_mm"]) / 1000.0
        arm = str(data["arm"])
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise DeviceError(f"{file}: unreadable simulator state ({exc}); delete the file") from None
    if arm != model.name or q.shape != (model.dof,) or not model.within_limits(q, 1e-6):
        raise DeviceError(f"{file}: state is not for this {model.name} arm; delete the file")
    return q, grip


def save_state(path: str | Path, arm: str, q: F64, grip: float) -> None:
    """Write ``q`` [rad] and ``grip`` [m] for the arm called ``arm`` (atomic replace)."""
    data = {"arm": arm, "q_deg": [round(math.degrees(a), 6) for a in q], "grip_mm": grip * 1000}
    write_atomic(Path(path), json.dumps(data), durable=False)
