"""The ``[drivers.owi535]`` table of a model file: the OWI-535's defaults before a unit
is calibrated, checked completely (ModelError names the field) and read back as an
``OwiSection`` (its traverse times [s], gravity and load, re-homing and calibration
order, the tolerances of its tasks [mm, deg])."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .._errors import ModelError
from ._check import NUM, Checker

if TYPE_CHECKING:
    from ._types import ArmModel

OWI_JOINTS = ("base", "shoulder", "elbow", "wrist")
_OWI = {
    "traverse_s": dict, "gripper_s": NUM, "min_move_ms": NUM, "teleop_step_ms": NUM,
    "gravity_joints": list, "load_weights": dict, "down_up_ratio": dict, "overshoot_deg": dict,
    "battery_drain_per_hour": NUM, "base_reversed": bool, "watchdog_margin_s": NUM,
    "rehome_order": list, "rehome_to": dict, "calibration_order": list, "calibration_pose": dict,
    "task_waypoints": int, "task_tolerance_mm": NUM, "task_turn_tolerance_deg": NUM,
}  # fmt: skip


@dataclass(frozen=True)
class OwiSection:
    """``[drivers.owi535]``: the OWI-535's defaults before a unit is calibrated.

    Attributes:
        traverse_s: {joint: limit-to-limit time [s]}, every joint (000's baseline).
        gripper_s: gripper travel, one way [s].  min_move_ms: shortest reliable run [ms].
        teleop_step_ms: one key press in keyboard mode [ms].
        gravity_joints: joints whose rate depends on lowering or lifting the load.
        load_weights: relative masses at the elbow, the wrist and the grip point.
        down_up_ratio: {joint: lowering speed / lifting speed}.
        overshoot_deg: {joint: travel per move beyond the powered time [deg]}.
        battery_drain_per_hour: fraction of speed lost per hour of motor time.
        base_reversed: byte-1 values swapped.  watchdog_margin_s: overrun before the watchdog stops [s].
        rehome_order, rehome_to: joints re-homing drives, and the limit ("lower"/"upper") of each.
        calibration_order: joints in the order calibration times them.
        calibration_pose: {joint: poses, each {other joint: "lower" | "upper" | angle [deg]}}.
        task_waypoints: moves a task makes from its clearance height down to a grasp or
            release point (001: 3; fewer on an arm whose every run adds slip and coast).
        task_tolerance_mm, task_turn_tolerance_deg: how far [mm] and how much turned [deg]
            an object a task put down may end from where the plan puts it (open loop).
    """

    traverse_s: Mapping[str, float]
    gripper_s: float
    min_move_ms: float
    teleop_step_ms: float
    gravity_joints: tuple[str, ...]
    load_weights: tuple[float, float, float]
    down_up_ratio: Mapping[str, float]
    overshoot_deg: Mapping[str, float]
    battery_drain_per_hour: float
    base_reversed: bool
    watchdog_margin_s: float
    rehome_order: tuple[str, ...]
    rehome_to: Mapping[str, str]
    calibration_order: tuple[str, ...]
    calibration_pose: Mapping[str, tuple[Mapping[str, str | float], ...]]
    task_waypoints: int = 3
    task_tolerance_mm: float = 1.0
    task_turn_tolerance_deg: float = 1.0


def owi_section(model: ArmModel) -> OwiSection:
    """The model's ``[drivers.owi535]`` as a typed setup.

    Raises:
        ModelError: not an OWI-535 model, or a field is wrong (names file and field).
    """
    if model.joint_names != OWI_JOINTS or not isinstance(model.drivers.get("owi535"), dict):
        raise ModelError(
            f"model {model.name!r} is not an OWI-535 (needs joints {', '.join(OWI_JOINTS)} "
            "and a [drivers.owi535] table); use --arm owi535"
        )
    return check_owi(Checker(model.source), model.drivers["owi535"], model)


def _per_joint(
    check: Checker, data: Any, where: str, low: float, high: float, every: bool = False
) -> dict[str, float]:
    check.table(data, where, dict.fromkeys(OWI_JOINTS, NUM), OWI_JOINTS if every else ())
    return {j: check.within(v, f"{where}.{j}", low, high) for j, v in data.items()}


def _joint_list(check: Checker, data: Any, where: str) -> tuple[str, ...]:
    data = list(data) if isinstance(data, tuple) else data
    if not isinstance(data, list) or len(set(map(str, data))) != len(data):
        raise check.fail(where, f"must be a list of different joints, got {data!r}")
    for k, name in enumerate(data):
        check.choice(name, f"{where}[{k}]", OWI_JOINTS)
    return tuple(data)


def check_owi(check: Checker, data: Any, model: ArmModel) -> OwiSection:
    """``data``, the ``[drivers.owi535]`` table of ``model``, checked (ModelError names
    the field) and read as an ``OwiSection`` (the defaults filled in)."""
    w = "drivers.owi535"
    check.table(data, w, _OWI, ("traverse_s", "gripper_s", "min_move_ms"))
    if model.joint_names != OWI_JOINTS:
        raise check.fail(w, f"the OWI-535 driver needs joints {', '.join(OWI_JOINTS)}")
    get = data.get
    return OwiSection(
        traverse_s=_per_joint(check, data["traverse_s"], f"{w}.traverse_s", 0.5, 600.0, True),
        gripper_s=check.within(data["gripper_s"], f"{w}.gripper_s", 0.1, 60.0, "s"),
        min_move_ms=check.within(data["min_move_ms"], f"{w}.min_move_ms", 10.0, 5000.0, "ms"),
        teleop_step_ms=check.within(get("teleop_step_ms", 250), f"{w}.teleop_step_ms", 10, 5e3),
        gravity_joints=_joint_list(check, get("gravity_joints", []), f"{w}.gravity_joints"),
        load_weights=_owi_weights(check, get("load_weights", {}), f"{w}.load_weights"),
        down_up_ratio=_per_joint(check, get("down_up_ratio", {}), f"{w}.down_up_ratio", 0.1, 10),
        overshoot_deg=_per_joint(check, get("overshoot_deg", {}), f"{w}.overshoot_deg", 0, 45),
        battery_drain_per_hour=check.within(
            get("battery_drain_per_hour", 0.0), f"{w}.battery_drain_per_hour", 0.0, 10.0
        ),
        base_reversed=bool(get("base_reversed", False)),
        watchdog_margin_s=check.within(
            get("watchdog_margin_s", 1.0), f"{w}.watchdog_margin_s", 0.05, 60.0, "s"
        ),
        rehome_order=_joint_list(check, get("rehome_order", OWI_JOINTS[::-1]), f"{w}.rehome_order"),
        rehome_to=_rehome_to(check, get("rehome_to", {}), f"{w}.rehome_to"),
        calibration_order=_joint_list(
            check, get("calibration_order", OWI_JOINTS), f"{w}.calibration_order"
        ),
        calibration_pose=_poses(check, get("calibration_pose", {}), f"{w}.calibration_pose"),
        task_waypoints=check.integer(get("task_waypoints", 3), f"{w}.task_waypoints", 1, 10),
        task_tolerance_mm=check.within(
            get("task_tolerance_mm", 1.0), f"{w}.task_tolerance_mm", 0.1, 50.0, "mm"
        ),
        task_turn_tolerance_deg=check.within(
            get("task_turn_tolerance_deg", 1.0), f"{w}.task_turn_tolerance_deg", 0.1, 20.0, "deg"
        ),
    )


def _rehome_to(check: Checker, data: Any, where: str) -> dict[str, str]:
    check.table(data, where, dict.fromkeys(OWI_JOINTS, str), ())
    for j, limit in data.items():
        check.choice(limit, f"{where}.{j}", ("lower", "upper"))
    return {j: str(data.get(j, "lower")) for j in OWI_JOINTS}


def _owi_weights(check: Checker, data: Any, where: str) -> tuple[float, float, float]:
    keys = ("elbow", "wrist", "grip")
    check.table(data, where, dict.fromkeys(keys, NUM), ())
    w = [check.within(data.get(k, 1.0), f"{where}.{k}", 0.0, 100.0) for k in keys]
    if sum(w) <= 0:
        raise check.fail(where, "needs at least one weight > 0")
    return (w[0], w[1], w[2])


def _poses(
    check: Checker, data: Any, where: str
) -> dict[str, tuple[Mapping[str, str | float], ...]]:
    check.table(data, where, dict.fromkeys(OWI_JOINTS, list), ())
    out: dict[str, tuple[Mapping[str, str | float], ...]] = {}
    for joint in OWI_JOINTS:
        poses = data.get(joint, [{}])
        if not poses:
            raise check.fail(f"{where}.{joint}", "needs at least one pose ({} = as it is)")
        out[joint] = tuple(
            _pose(check, p, f"{where}.{joint}[{k}]", joint) for k, p in enumerate(poses)
        )
    return out


def _pose(check: Checker, data: Any, where: str, timed: str) -> dict[str, str | float]:
    check.table(data, where, dict.fromkeys(OWI_JOINTS, object), ())
    pose: dict[str, str | float] = {}
    for joint, rest in data.items():
        if joint == timed:
            raise check.fail(f"{where}.{joint}", "is the joint being timed; name the others")
        if isinstance(rest, str):
            pose[joint] = check.choice(rest, f"{where}.{joint}", ("lower", "upper"))
        else:
            pose[joint] = check.angle(rest, f"{where}.{joint}")
    return pose
