"""A simulated arm's truth kept between processes, one file per model file.

``armkit move`` in one process and ``armkit where`` in the next must see the
same simulated arm, so a simulation opened with a state file starts where the
file says and writes its truth back when its device is closed: the joints, the gripper's
opening and the tool it holds (a pen, a mallet: the tool point a plan starts from),
in one file written at once. The file is
keyed by the model FILE, not the model's name: a shipped arm's file is
``sim_<name>.json``; a user's model file gets ``sim_<name>-<hash of its path>.json``,
so two files that both say ``name = "myarm"`` never share a pose. Files live in
the config directory (``$ARMKIT_CONFIG_DIR``, else ``$XDG_CONFIG_HOME/armkit``,
else ``~/.config/armkit``), are written atomically, and are held with
``armkit._lock.exclusive`` while a process uses them: a second process on the
same simulated arm is refused with a message naming the first.
"""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path

import numpy as np

from .._errors import DeviceError
from .._files import config_dir, write_atomic
from ..model import ArmModel
from ..scene import HeldTool
from ._arm import Truth

VERSION = 1


def state_key(model: ArmModel) -> str:
    """``<name>`` for a shipped model (or one made in code), ``<name>-<10 hex>`` for a file."""
    source = model.source
    if source is None or _shipped(source):
        return model.name
    digest = hashlib.sha256(str(Path(source).resolve()).encode()).hexdigest()[:10]
    return f"{model.name}-{digest}"


def kept_key(model: ArmModel, port: str | None) -> str:
    """The key of what is kept beside the simulated ``model`` (its scene's objects):
    ``state_key``, and with a state file of the user's (``--port FILE``) a digest of that
    file's path too, so the objects go with the arm they were left by."""
    if port is None:
        return state_key(model)
    return (
        f"{state_key(model)}@{hashlib.sha256(str(Path(port).resolve()).encode()).hexdigest()[:10]}"
    )


def _shipped(source: Path) -> bool:
    shipped = Path(__file__).resolve().parent.parent / "model" / "arms"
    return Path(source).resolve().parent == shipped


def state_file(model: ArmModel) -> Path:
    """Where the truth of the simulated ``model`` is kept between processes."""
    return config_dir() / f"sim_{state_key(model)}.json"


def load_truth(path: Path, model: ArmModel) -> Truth | None:
    """The truth saved for ``model`` at ``path``; None if there is no file.

    Raises:
        DeviceError: unreadable, or for another arm, or outside the joint limits
            (the message names the file and says to delete it).
    """
    if not path.exists():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        q = tuple(math.radians(float(a)) for a in data["q_deg"])
        truth = Truth(
            q, float(data["grip_mm"]) / 1000.0, float(data.get("motor_s", 0.0)),
            _tool(data.get("tool")),
        )  # fmt: skip
        arm, version = str(data["arm"]), data.get("version", VERSION)
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise DeviceError(f"{path}: unreadable simulator state ({exc}); delete the file") from None
    inside = len(q) == model.dof and bool(model.within_limits(np.array(q), 1e-6))
    if arm != model.name or version != VERSION or not inside:
        raise DeviceError(f"{path}: state is not for this {model.name} arm; delete the file")
    return truth


def save_truth(path: Path, model: ArmModel, truth: Truth) -> None:
    """Write ``truth`` for ``model`` at ``path`` (atomic replace)."""
    data = {
        "version": VERSION,
        "arm": model.name,
        "model_file": str(model.source) if model.source else None,
        "q_deg": [round(math.degrees(a), 6) for a in truth.q],
        "grip_mm": truth.grip * 1000.0,
        "motor_s": truth.motor_s,
        "tool": None if truth.tool is None else _tool_data(truth.tool),
    }
    write_atomic(path, json.dumps(data, indent=1) + "\n", durable=False)


def _tool_data(tool: HeldTool) -> dict[str, object]:
    """The held tool as the state file keeps it [mm]."""
    return {
        "name": tool.name,
        "tool_length_mm": tool.tool_length * 1000.0,
        "width_mm": tool.width * 1000.0,
    }


def _tool(data: object) -> HeldTool | None:
    """The held tool from the state file (None: nothing held); ValueError if malformed."""
    if data is None:
        return None
    if not isinstance(data, dict):
        raise ValueError(f"tool is {data!r}, not a table")
    length, width = float(data["tool_length_mm"]) / 1000.0, float(data["width_mm"]) / 1000.0
    if not (0.0 < length <= 10.0 and 0.0 <= width <= 1.0):
        raise ValueError(f"tool {data!r} out of range")
    return HeldTool(str(data["name"]), length, width)
