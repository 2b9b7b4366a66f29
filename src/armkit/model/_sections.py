"""The ``[drivers.<name>]`` tables of a model file, checked completely when the
model loads and read back as typed setups by the drivers.

Model files keep the tables as written (``ArmModel.drivers``); ``owi_section``
and ``dynamixel_section`` turn them into frozen dataclasses, and
``check_driver_sections`` runs every check at load, so a driver never meets a
missing key or a wrong type.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from .._errors import ModelError
from ._check import NUM, Checker
from ._types import ArmModel

OWI_JOINTS = ("base", "shoulder", "elbow", "wrist")
DRIVER_SECTIONS = ("owi535", "ssc32", "maestro", "dynamixel")
BAUDRATES = (
    9600, 19200, 38400, 57600, 115200, 1_000_000, 2_000_000, 3_000_000, 4_000_000, 4_500_000,
)  # fmt: skip

_OWI = {
    "traverse_s": dict, "gripper_s": NUM, "min_move_ms": NUM, "teleop_step_ms": NUM,
    "gravity_joints": list, "load_weights": dict, "down_up_ratio": dict, "overshoot_deg": dict,
    "battery_drain_per_hour": NUM, "base_reversed": bool, "watchdog_margin_s": NUM,
    "rehome_order": list, "rehome_to": dict, "calibration_order": list, "calibration_pose": dict,
    "task_waypoints": int, "task_tolerance_mm": NUM, "task_turn_tolerance_deg": NUM,
}  # fmt: skip
_DXL = {
    "ids": list, "gripper_id": int, "baudrate": int, "ticks_per_turn": int, "center_tick": NUM,
    "gripper_ticks": list, "gripper_current": int, "position_tolerance_ticks": int,
    "operating_mode": str,
}  # fmt: skip
DXL_MODES = ("position", "extended")
_SERVO = {
    "channels": list, "baudrate": int, "center_deg": list, "direction": list,
    "grip_pulse_us": list,
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


@dataclass(frozen=True)
class DynamixelSection:
    """``[drivers.dynamixel]``: servo IDs and tick calibration of a Dynamixel arm.

    Attributes:
        ids: one servo ID per joint, model order (0..252, all different).
        gripper_id: the gripper's servo ID.  baudrate: bus speed [bit/s].
        ticks_per_turn: ticks in one turn.  center_tick: tick at joint angle 0.
        gripper_ticks: (closed, open) ticks; default ROBOTIS's own (open_manipulator_x
            libraries: gripper -0.010 m closed .. +0.010 m open at -0.015 m per rad, Drive
            Mode normal): 2048 -+ 0.010 / 0.015 rad x 4096 / 2pi = 2483 closed, 1613 open.
        gripper_current: current limit [2.69 mA units].
        position_tolerance_ticks: how close a servo must come to count as arrived [ticks].
        operating_mode: the joints' mode, ``"position"`` (one turn, 0..4095) or
            ``"extended"`` (multi-turn: joints with more than one turn of range).
    """

    ids: tuple[int, ...]
    gripper_id: int
    baudrate: int = 1_000_000
    ticks_per_turn: int = 4096
    center_tick: float = 2048.0
    gripper_ticks: tuple[int, int] = (2483, 1613)  # ROBOTIS's gripper range, see below
    gripper_current: int = 300
    position_tolerance_ticks: int = 30
    operating_mode: str = "position"


def check_driver_sections(check: Checker, data: Any, model: ArmModel) -> None:
    """Every ``[drivers.*]`` table of a model being loaded (ModelError names the field)."""
    check.table(data, "drivers", dict.fromkeys(DRIVER_SECTIONS, dict), ())
    for name, section in data.items():
        if name == "owi535":
            _owi(check, section, model)
        elif name == "dynamixel":
            _dynamixel(check, section, model)
        else:
            _servo(check, section, model, f"drivers.{name}")


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
    return _owi(Checker(model.source), model.drivers["owi535"], model)


def dynamixel_section(model: ArmModel) -> DynamixelSection:
    """The model's ``[drivers.dynamixel]`` as a typed setup (ModelError if missing or wrong)."""
    if not isinstance(model.drivers.get("dynamixel"), dict):
        raise ModelError(f"{model.name} has no [drivers.dynamixel] table; not a Dynamixel arm")
    return _dynamixel(Checker(model.source), model.drivers["dynamixel"], model)


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


def _owi(check: Checker, data: Any, model: ArmModel) -> OwiSection:
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


def _dynamixel(check: Checker, data: Any, model: ArmModel) -> DynamixelSection:
    w = "drivers.dynamixel"
    check.table(data, w, _DXL, ("ids", "gripper_id"))
    ids = data["ids"]
    if len(ids) != model.dof:
        raise check.fail(f"{w}.ids", f"must list {model.dof} servo IDs, one per joint, got {ids}")
    ids = [check.integer(i, f"{w}.ids[{k}]", 0, 252) for k, i in enumerate(ids)]
    grip = check.integer(data["gripper_id"], f"{w}.gripper_id", 0, 252)
    if len({*ids, grip}) != len(ids) + 1:
        raise check.fail(w, f"servo IDs must all differ, got ids {ids} and gripper_id {grip}")
    get = data.get
    ticks = check.integer(get("ticks_per_turn", 4096), f"{w}.ticks_per_turn", 360, 1_000_000)
    return DynamixelSection(
        ids=tuple(ids),
        gripper_id=grip,
        baudrate=check.choice_int(get("baudrate", 1_000_000), f"{w}.baudrate", BAUDRATES),
        ticks_per_turn=ticks,
        center_tick=check.within(get("center_tick", 2048), f"{w}.center_tick", 0, ticks),
        gripper_ticks=_gripper_ticks(
            check, get("gripper_ticks", list(DynamixelSection.gripper_ticks)), w
        ),
        gripper_current=check.integer(get("gripper_current", 300), f"{w}.gripper_current", 1, 2047),
        position_tolerance_ticks=check.integer(
            get("position_tolerance_ticks", 30), f"{w}.position_tolerance_ticks", 1, 1000
        ),
        operating_mode=check.choice(
            get("operating_mode", "position"), f"{w}.operating_mode", DXL_MODES
        ),
    )


def _gripper_ticks(check: Checker, data: Any, w: str) -> tuple[int, int]:
    where = f"{w}.gripper_ticks"
    if not isinstance(data, list) or len(data) != 2:
        raise check.fail(where, f"must be [closed, open] ticks, got {data!r}")
    closed = check.integer(data[0], f"{where}[0]", 0, 4095)
    opened = check.integer(data[1], f"{where}[1]", 0, 4095)
    if closed == opened:
        raise check.fail(where, f"closed and open must differ, got {data}")
    return (closed, opened)


def _servo(check: Checker, data: Any, model: ArmModel, w: str) -> None:
    """``[drivers.ssc32]``/``[drivers.maestro]`` (the servo driver reads them as tables)."""
    check.table(data, w, _SERVO, ("channels",))
    dof, channels = model.dof, data["channels"]
    if len(channels) not in (dof, dof + 1):
        raise check.fail(
            f"{w}.channels", f"must list {dof} joint channels (+ 1 for the gripper), got {channels}"
        )
    numbers = [check.integer(c, f"{w}.channels[{k}]", 0, 31) for k, c in enumerate(channels)]
    if len(set(numbers)) != len(numbers):
        raise check.fail(f"{w}.channels", f"channels must all differ, got {numbers}")
    check.choice_int(data.get("baudrate", 9600), f"{w}.baudrate", BAUDRATES)
    centers = check.numbers(data.get("center_deg", [90.0] * dof), f"{w}.center_deg", dof)
    for k, c in enumerate(centers):
        check.angle(c, f"{w}.center_deg[{k}]")
    directions = data.get("direction", [1] * dof)
    if len(directions) != dof or any(d not in (1, -1) or isinstance(d, bool) for d in directions):
        raise check.fail(
            f"{w}.direction", f"must list {dof} directions, each 1 or -1, got {directions}"
        )
    pulses = check.numbers(data.get("grip_pulse_us", [500.0, 2500.0]), f"{w}.grip_pulse_us", 2)
    for k, p in enumerate(pulses):
        check.within(p, f"{w}.grip_pulse_us[{k}]", 500.0, 2500.0, "µs")
