"""One OWI unit's state, kept in a file so it is never lost: limits, timing
model, estimated angles, gripper and light, motor-seconds used, whether the
angles are certain, and the move in progress (if any).

The file lives in ``$ARMKIT_CONFIG_DIR``, else ``$XDG_CONFIG_HOME/armkit``,
else ``~/.config/armkit``, as ``owi535/<unit>.json``, in degrees for people to
read. Every write is atomic (temporary file, fsync, ``os.replace``), so a
crash or ``kill -9`` leaves either the old or the new file, never a torn one.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from ..._errors import ArmkitError, InputError
from ..._files import config_dir, write_atomic
from ._timing import JointTiming, TimingModel

VERSION = 1


@dataclass(frozen=True)
class Pending:
    """A move that was started and not yet recorded as finished.

    Attributes:
        directions: {joint index: +1 | -1} of the motors started.
        seconds: planned motor time per joint [s].
        started_unix: wall-clock start (``time.time()``) [s].
    """

    directions: dict[int, int]
    seconds: dict[int, float]
    started_unix: float


@dataclass(frozen=True)
class UnitState:
    """Everything armkit knows about one unit. Angles [rad], times [s]."""

    unit: str
    timing: TimingModel
    angles: tuple[float, ...]
    uncertain: bool = True
    reason: str = "never homed"
    gripper: str = "unknown"  # "open", "closed" or "unknown"
    light: bool = False
    motor_s: float = 0.0
    calibrated: bool = False
    pending: Pending | None = None
    extra: dict[str, Any] = field(default_factory=dict)

    def with_(self, **changes: Any) -> UnitState:
        """A copy with ``changes`` applied."""
        return replace(self, **changes)


def state_path(unit: str) -> Path:
    """The state file of OWI unit ``unit``."""
    if not unit or any(c in unit for c in "/\\") or unit.startswith("."):
        raise InputError(f"OWI unit name {unit!r} must be a plain name like 'default' or 'desk'")
    return config_dir() / "owi535" / f"{unit}.json"


def save(state: UnitState, path: Path, durable: bool = True) -> None:
    """Write ``state`` to ``path`` atomically (temp file, fsync, rename). ``durable=False``
    skips the fsyncs (still atomic, not power-loss safe): for simulations."""
    write_atomic(path, json.dumps(to_dict(state), indent=2) + "\n", durable)


def load(path: Path) -> UnitState:
    """Read a state file.

    Raises:
        ArmkitError: unreadable or malformed (the message names the file and what to do).
    """
    try:
        return from_dict(json.loads(path.read_text()))
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ArmkitError(
            f"OWI state file {path} is unreadable ({exc}); "
            "delete it, then re-home the arm (rehome) or calibrate it"
        ) from None


def to_dict(state: UnitState) -> dict[str, Any]:
    """JSON-ready form, angles in degrees."""
    return {
        "version": VERSION,
        "unit": state.unit,
        "angles_deg": [math.degrees(a) for a in state.angles],
        "uncertain": state.uncertain,
        "reason": state.reason,
        "gripper": state.gripper,
        "light": state.light,
        "motor_s": state.motor_s,
        "calibrated": state.calibrated,
        "pending": _pending_to_dict(state.pending),
        "timing": timing_to_dict(state.timing),
        "extra": state.extra,
    }


def from_dict(d: dict[str, Any]) -> UnitState:
    """Inverse of :func:`to_dict`."""
    if d.get("version") != VERSION:
        raise InputError(f"version {d.get('version')!r}, expected {VERSION}")
    return UnitState(
        unit=str(d["unit"]),
        timing=timing_from_dict(d["timing"]),
        angles=tuple(math.radians(float(a)) for a in d["angles_deg"]),
        uncertain=bool(d["uncertain"]),
        reason=str(d["reason"]),
        gripper=str(d["gripper"]),
        light=bool(d["light"]),
        motor_s=float(d["motor_s"]),
        calibrated=bool(d["calibrated"]),
        pending=_pending_from_dict(d["pending"]),
        extra=dict(d.get("extra", {})),
    )


def _pending_to_dict(p: Pending | None) -> dict[str, Any] | None:
    if p is None:
        return None
    return {
        "directions": {str(k): v for k, v in p.directions.items()},
        "seconds": {str(k): v for k, v in p.seconds.items()},
        "started_unix": p.started_unix,
    }


def _pending_from_dict(d: dict[str, Any] | None) -> Pending | None:
    if d is None:
        return None
    return Pending(
        directions={int(k): int(v) for k, v in d["directions"].items()},
        seconds={int(k): float(v) for k, v in d["seconds"].items()},
        started_unix=float(d["started_unix"]),
    )


def timing_to_dict(tm: TimingModel) -> dict[str, Any]:
    """A timing model in degrees and seconds."""
    return {
        "joints": [
            {
                "rates_dps": [math.degrees(r) for r in jt.rates],
                "rates_are": "forwards lowering, forwards lifting, backwards lowering, lifting",
                "gravity": jt.gravity,
                "overshoot_deg": [math.degrees(o) for o in jt.overshoot],
            }
            for jt in tm.joints
        ],
        "limits_deg": [
            [math.degrees(lo), math.degrees(hi)] for lo, hi in zip(tm.lower, tm.upper, strict=True)
        ],
        "lengths_m": list(tm.lengths),
        "load_weights": list(tm.weights),
        "drain_per_s": tm.drain,
        "gripper_s": tm.gripper_s,
        "min_move_s": tm.min_move_s,
    }


def timing_from_dict(d: dict[str, Any]) -> TimingModel:
    """Inverse of :func:`timing_to_dict`."""
    joints = tuple(
        JointTiming(
            rates=_four(math.radians(r) for r in j["rates_dps"]),
            gravity=bool(j["gravity"]),
            overshoot=_pair(math.radians(o) for o in j["overshoot_deg"]),
        )
        for j in d["joints"]
    )
    lengths = tuple(float(x) for x in d["lengths_m"])
    if len(lengths) != 3 or any(r <= 0 for jt in joints for r in jt.rates):
        raise InputError("timing needs 3 lengths and positive rates")
    return TimingModel(
        joints=joints,
        lower=tuple(math.radians(float(lo)) for lo, _ in d["limits_deg"]),
        upper=tuple(math.radians(float(hi)) for _, hi in d["limits_deg"]),
        lengths=(lengths[0], lengths[1], lengths[2]),
        weights=_three(d.get("load_weights", (1.0, 1.0, 1.0))),
        drain=float(d["drain_per_s"]),
        gripper_s=float(d["gripper_s"]),
        min_move_s=float(d["min_move_s"]),
    )


def _three(values: Any) -> tuple[float, float, float]:
    a, b, c = (float(v) for v in values)
    return (a, b, c)


def _four(values: Any) -> tuple[float, float, float, float]:
    a, b, c, e = (float(v) for v in values)
    return (a, b, c, e)


def _pair(values: Any) -> tuple[float, float]:
    a, b = (float(v) for v in values)
    return (a, b)
