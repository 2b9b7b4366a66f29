"""The ``[drivers.owi535]`` table of a model file: defaults for a unit not yet
calibrated, and 000's constant-rate timing model for comparison."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from ...model import ArmModel, OwiSection, owi_section
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


def owi_config(model: ArmModel) -> OwiConfig:
    """Non-timing settings from the model file (ModelError: not an OWI model or a bad field)."""
    cfg = owi_section(model)
    return OwiConfig(
        teleop_step_s=cfg.teleop_step_ms / 1000.0,
        base_reversed=cfg.base_reversed,
        watchdog_margin_s=cfg.watchdog_margin_s,
        rehome_order=cfg.rehome_order,
        rehome_to=dict(cfg.rehome_to),
        calibration_order=cfg.calibration_order,
        calibration_pose={j: [_rests(p) for p in cfg.calibration_pose[j]] for j in JOINTS},
    )


def _rests(pose: Mapping[str, str | float]) -> dict[str, str | float]:
    """{joint: "lower" | "upper" | angle [rad]} from the file's degrees."""
    return {k: v if isinstance(v, str) else math.radians(v) for k, v in pose.items()}


def constant_rate(model: ArmModel, traverse_s: dict[str, float] | None = None) -> TimingModel:
    """000's model: one rate per joint, limit span / traverse time, nothing else.

    Args:
        traverse_s: {joint: limit-to-limit time [s]}; None = the model file's.
    """
    cfg = owi_section(model)
    times = traverse_s or dict(cfg.traverse_s)
    joints = tuple(
        JointTiming(rates=(r, r, r, r))
        for r in (model.upper - model.lower) / [times[j] for j in JOINTS]
    )
    return _assemble(model, cfg, joints, drain=0.0)


def default_timing(model: ArmModel) -> TimingModel:
    """armkit's model with the model file's typical gravity, overshoot and battery figures."""
    cfg = owi_section(model)
    base = constant_rate(model)
    joints = tuple(
        _default_joint(cfg, j, base.joints[i], j in cfg.gravity_joints)
        for i, j in enumerate(JOINTS)
    )
    return _assemble(model, cfg, joints, drain=cfg.battery_drain_per_hour / 3600.0)


def _default_joint(cfg: OwiSection, name: str, base: JointTiming, gravity: bool) -> JointTiming:
    over = math.radians(cfg.overshoot_deg.get(name, 0.0))
    r = base.rates[0]
    if gravity:
        ratio = cfg.down_up_ratio.get(name, 1.0)
        down, up = r * 2 * ratio / (1 + ratio), r * 2 / (1 + ratio)
        return JointTiming((down, up, down, up), True, (over, over))
    return JointTiming((r, r, r, r), False, (over, over))


def _assemble(
    model: ArmModel, cfg: OwiSection, joints: tuple[JointTiming, ...], drain: float
) -> TimingModel:
    return TimingModel(
        joints=joints,
        lower=tuple(float(x) for x in model.lower),
        upper=tuple(float(x) for x in model.upper),
        lengths=(model.dh[2].a, model.dh[3].a, model.tool_length),
        weights=cfg.load_weights,
        drain=drain,
        gripper_s=cfg.gripper_s,
        min_move_s=cfg.min_move_ms / 1000.0,
    )
