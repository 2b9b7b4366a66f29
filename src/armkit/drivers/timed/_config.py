"""Timing models from the ``[drivers.owi535]`` table of a model file (``OwiSection``):
defaults for a unit not yet calibrated, and 000's constant-rate model for comparison."""

from __future__ import annotations

import math

from ...model import ArmModel, OwiSection, owi_section
from ._timing import JointTiming, TimingModel

JOINTS = ("base", "shoulder", "elbow", "wrist")


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
