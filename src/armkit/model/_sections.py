"""The ``[drivers.<name>]`` tables of a model file, checked completely when the
model loads and read back as typed setups by the drivers.

Model files keep the tables as written (``ArmModel.drivers``). Each table a model
file may have is one ``Section`` of ``SECTIONS``: its name and the function that
checks it and reads it as typed settings (``OwiSection``, ``DynamixelSection``).
``check_driver_sections`` runs every check at load, so a driver never meets a
missing key or a wrong type. The driver kinds (``armkit.connect.driver_kinds()``) name
their section from here: a model file is read below the drivers.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Generic, TypeVar

from .._errors import ModelError
from ._check import NUM, Checker
from ._feetech_section import FeetechSection, read_feetech
from ._owi_section import OwiSection, check_owi

if TYPE_CHECKING:
    from ._types import ArmModel

T = TypeVar("T")
BAUDRATES = (
    9600, 19200, 38400, 57600, 115200, 1_000_000, 2_000_000, 3_000_000, 4_000_000, 4_500_000,
)  # fmt: skip

_DXL = {
    "ids": list, "gripper_id": int, "baudrate": int, "ticks_per_turn": int, "center_tick": NUM,
    "gripper_ticks": list, "gripper_current": int, "position_tolerance_ticks": int,
    "operating_mode": str,
}  # fmt: skip
DXL_MODES = ("position", "extended")
_SERVO = {
    "channels": list, "baudrate": int, "center_deg": list, "direction": list,
    "grip_pulse_us": list, "settle_ms": NUM,
}  # fmt: skip


@dataclass(frozen=True)
class Section(Generic[T]):
    """One ``[drivers.NAME]`` table a model file may have.

    Attributes:
        name: the table's name (``"ssc32"`` for ``[drivers.ssc32]``).
        read: checks the table of a model being loaded and reads it as typed settings,
            ``read(check, table, model)`` (ModelError names the field).
    """

    name: str
    read: Callable[[Checker, Any, ArmModel], T]

    def of(self, model: ArmModel) -> T:
        """The model's table as typed settings (ModelError if it has none)."""
        if not isinstance(model.drivers.get(self.name), dict):
            raise ModelError(f"{model.name} has no [drivers.{self.name}] table")
        return self.read(Checker(model.source), model.drivers[self.name], model)


@dataclass(frozen=True)
class DynamixelSection:
    """``[drivers.dynamixel]``: servo IDs and tick calibration of a Dynamixel arm.

    Attributes:
        ids: one servo ID per joint, model order (0..252, all different).
        gripper_id: the gripper's servo ID.  baudrate: bus speed [bit/s].
        ticks_per_turn: ticks in one turn.  center_tick: tick at joint angle 0.
        gripper_ticks: (closed, open) ticks; default ROBOTIS's own (ROBOTIS-GIT/
            open_manipulator, open_manipulator_libs/src/OpenManipulator.cpp, ``addTool``:
            gripper -0.010 m closed .. +0.010 m open, -0.015 "meter to radian", Drive Mode
            normal): 2048 -+ 0.010 / 0.015 rad x 4096 / 2pi = 2483 closed, 1613 open.
        gripper_current: current limit [2.69 mA units].
        position_tolerance_ticks: how close a servo must come to count as arrived [ticks].
        operating_mode: the joints' mode, ``"position"`` (one turn, 0..4095) or
            ``"extended"`` (multi-turn: joints with more than one turn of range).
    """

    ids: tuple[int, ...]
    gripper_id: int | None
    baudrate: int = 1_000_000
    ticks_per_turn: int = 4096
    center_tick: float = 2048.0
    gripper_ticks: tuple[int, int] = (2483, 1613)  # ROBOTIS's gripper range, see below
    gripper_current: int = 300
    position_tolerance_ticks: int = 30
    operating_mode: str = "position"


@dataclass(frozen=True)
class ServoSection:
    """``[drivers.ssc32]`` / ``[drivers.maestro]``: a hobby-servo arm's channels and the
    ideal pulse tables (002's) the servo driver starts from.

    Attributes:
        channels: one per joint, model order, then the gripper's if it has one (0..31,
            all different).
        baudrate: serial speed [bit/s] (default 9600).
        center_deg: per joint, the joint angle [deg] at 1500 µs (default 90, as 002).
        direction: per joint, +1, or -1 for a servo mounted the other way round.
        grip_pulse_us: (closed, open) gripper pulses [µs] (default (500, 2500)).
        settle_ms: how long the servos take to catch up with their pulses after a move
            [ms], 0..2000 (default 100): the controller cannot tell, so a waiting move waits.
    """

    channels: tuple[int, ...]
    baudrate: int = 9600
    center_deg: tuple[float, ...] = ()
    direction: tuple[int, ...] = ()
    grip_pulse_us: tuple[float, float] = (500.0, 2500.0)
    settle_ms: float = 100.0


def servo_section(model: ArmModel, name: str) -> ServoSection:
    """The model's ``[drivers.NAME]`` table of a hobby-servo controller, typed (ModelError
    if it has none or it is wrong)."""
    if not isinstance(model.drivers.get(name), dict):
        raise ModelError(f"{model.name} has no [drivers.{name}] table")
    return _servo(Checker(model.source), model.drivers[name], model, f"drivers.{name}")


def check_driver_sections(check: Checker, data: Any, model: ArmModel) -> None:
    """Every ``[drivers.*]`` table of a model being loaded (ModelError names the field)."""
    by_name = {section.name: section for section in SECTIONS}
    check.table(data, "drivers", dict.fromkeys(by_name, dict), ())
    for name, table in data.items():
        by_name[name].read(check, table, model)


def dynamixel_section(model: ArmModel) -> DynamixelSection:
    """The model's ``[drivers.dynamixel]`` as a typed setup (ModelError if missing or wrong)."""
    if not isinstance(model.drivers.get("dynamixel"), dict):
        raise ModelError(f"{model.name} has no [drivers.dynamixel] table; not a Dynamixel arm")
    return _dynamixel(Checker(model.source), model.drivers["dynamixel"], model)


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


def _servo(check: Checker, data: Any, model: ArmModel, w: str) -> ServoSection:
    """``[drivers.ssc32]``/``[drivers.maestro]`` (the servo driver builds its tables from
    them, ``armkit.drivers.servo.load_setup``)."""
    check.table(data, w, _SERVO, ("channels",))
    dof, channels = model.dof, data["channels"]
    if len(channels) not in (dof, dof + 1):
        raise check.fail(
            f"{w}.channels", f"must list {dof} joint channels (+ 1 for the gripper), got {channels}"
        )
    numbers = [check.integer(c, f"{w}.channels[{k}]", 0, 31) for k, c in enumerate(channels)]
    if len(set(numbers)) != len(numbers):
        raise check.fail(f"{w}.channels", f"channels must all differ, got {numbers}")
    baudrate = check.choice_int(data.get("baudrate", 9600), f"{w}.baudrate", BAUDRATES)
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
    settle = check.within(data.get("settle_ms", 100.0), f"{w}.settle_ms", 0.0, 2000.0, "ms")
    return ServoSection(
        tuple(numbers), baudrate, tuple(float(c) for c in centers), tuple(directions),
        (float(pulses[0]), float(pulses[1])), float(settle),
    )  # fmt: skip


def _ssc32(check: Checker, data: Any, model: ArmModel) -> ServoSection:
    return _servo(check, data, model, "drivers.ssc32")


def _maestro(check: Checker, data: Any, model: ArmModel) -> ServoSection:
    return _servo(check, data, model, "drivers.maestro")


OWI535_SECTION: Section[OwiSection] = Section("owi535", check_owi)
SSC32_SECTION: Section[ServoSection] = Section("ssc32", _ssc32)
MAESTRO_SECTION: Section[ServoSection] = Section("maestro", _maestro)
DYNAMIXEL_SECTION: Section[DynamixelSection] = Section("dynamixel", _dynamixel)
FEETECH_SECTION: Section[FeetechSection] = Section("feetech", read_feetech)
SECTIONS: tuple[Section[Any], ...] = (
    OWI535_SECTION, SSC32_SECTION, MAESTRO_SECTION, DYNAMIXEL_SECTION, FEETECH_SECTION,
)  # fmt: skip
