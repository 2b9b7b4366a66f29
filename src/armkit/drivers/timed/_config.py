"""The ``[drivers.owi535]`` table of a model file: defaults for a unit not yet
calibrated, and 000's constant-rate timing model for comparison."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..._errors import ModelError
from ...model import ArmModel
from ._timing import JointTiming, TimingModel

JOINTS = ("base", "shoulder", "elbow", "wrist")


@dataclass(frozen=True)
class OwiConfig:
    """Driver settings that are not timings.

    Attributes:
        teleop_step_s: one key press in keyboard mode [s].
        base_reversed: byte-1 values swapped for this unit.
        watchdog_margin_s: overrun of a move's plan after which the watchdog stops it [s].
        rehome_order: joints in the order re-homing drives them.
        rehome_to: {joint: "lower" | "upper"} limit each joint is driven against.
        calibration_order: joints in the order calibration times them.
        calibration_pose: {joint: [{other joint: "lower" | "upper" | angle [rad]}]}
            poses in which that joint is timed (two with different load sides
            separate direction from gravity).
    """

    teleop_step_s: float
    base_reversed: bool
    watchdog_margin_s: float
    rehome_order: tuple[str, ...]
    rehome_to: dict[str, str]
    calibration_order: tuple[str, ...]
    calibration_pose: dict[str, list[dict[str, str | float]]]


def table(model: ArmModel) -> dict[str, Any]:
    """The model's ``[drivers.owi535]`` table; ModelError if the model has none."""
    if model.joint_names != JOINTS or "owi535" not in model.drivers:
        raise ModelError(
            f"model {model.name!r} is not an OWI-535 (needs joints {', '.join(JOINTS)} "
            "and a [drivers.owi535] table); use --arm owi535"
        )
    cfg: dict[str, Any] = model.drivers["owi535"]
    return cfg


def owi_config(model: ArmModel) -> OwiConfig:
    """Non-timing settings from the model file."""
    cfg = table(model)
    return OwiConfig(
        teleop_step_s=float(cfg.get("teleop_step_ms", 250)) / 1000.0,
        base_reversed=bool(cfg.get("base_reversed", False)),
        watchdog_margin_s=float(cfg.get("watchdog_margin_s", 1.0)),
        rehome_order=tuple(cfg.get("rehome_order", JOINTS[::-1])),
        rehome_to={j: str(cfg.get("rehome_to", {}).get(j, "lower")) for j in JOINTS},
        calibration_order=tuple(cfg.get("calibration_order", JOINTS)),
        calibration_pose={
            j: [_rests(p) for p in cfg.get("calibration_pose", {}).get(j, [{}])] for j in JOINTS
        },
    )


def _weights(table: dict[str, Any]) -> tuple[float, float, float]:
    w = [float(table.get(k, 1.0)) for k in ("elbow", "wrist", "grip")]
    if min(w) < 0 or sum(w) <= 0:
        raise ModelError(f"[drivers.owi535] load_weights must be >= 0, not all 0, got {table}")
    return (w[0], w[1], w[2])


def _rests(table: dict[str, Any]) -> dict[str, str | float]:
    return {k: v if isinstance(v, str) else math.radians(float(v)) for k, v in table.items()}


def constant_rate(model: ArmModel, traverse_s: dict[str, float] | None = None) -> TimingModel:
    """000's model: one rate per joint, limit span / traverse time, nothing else.

    Args:
        traverse_s: {joint: limit-to-limit time [s]}; None = the model file's.
    """
    cfg = table(model)
    times = traverse_s or {j: float(cfg["traverse_s"][j]) for j in JOINTS}
    joints = tuple(
        JointTiming(rates=(r, r, r, r))
        for r in (model.upper - model.lower) / [times[j] for j in JOINTS]
    )
    return _assemble(model, cfg, joints, drain=0.0)


def default_timing(model: ArmModel) -> TimingModel:
    """armkit's model with the model file's typical gravity, overshoot and battery figures."""
    cfg = table(model)
    base = constant_rate(model)
    gravity = set(cfg.get("gravity_joints", []))
    joints = tuple(
        _default_joint(cfg, j, base.joints[i], j in gravity) for i, j in enumerate(JOINTS)
    )
    return _assemble(
        model, cfg, joints, drain=float(cfg.get("battery_drain_per_hour", 0.0)) / 3600.0
    )


def _default_joint(cfg: dict[str, Any], name: str, base: JointTiming, gravity: bool) -> JointTiming:
    over = math.radians(float(cfg.get("overshoot_deg", {}).get(name, 0.0)))
    r = base.rates[0]
    if gravity:
        ratio = float(cfg.get("down_up_ratio", {}).get(name, 1.0))
        down, up = r * 2 * ratio / (1 + ratio), r * 2 / (1 + ratio)
        return JointTiming((down, up, down, up), True, (over, over))
    return JointTiming((r, r, r, r), False, (over, over))


def _assemble(
    model: ArmModel, cfg: dict[str, Any], joints: tuple[JointTiming, ...], drain: float
) -> TimingModel:
    return TimingModel(
        joints=joints,
        lower=tuple(float(x) for x in model.lower),
        upper=tuple(float(x) for x in model.upper),
        lengths=(model.dh[2].a, model.dh[3].a, model.tool_length),
        weights=_weights(cfg.get("load_weights", {})),
        drain=drain,
        gripper_s=float(cfg["gripper_s"]),
        min_move_s=float(cfg["min_move_ms"]) / 1000.0,
    )
