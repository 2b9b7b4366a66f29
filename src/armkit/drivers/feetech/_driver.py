"""Feetech arms (the SO-101, SO-100): joint angles <-> STS3215 steps on one bus.

Calibration from the model's ``[drivers.feetech]`` (``FeetechSection``): step =
``center_tick + direction * q * ticks_per_turn / 2pi``, clipped to 0..4095; the
gripper's opening maps to its jaw angle by the chord law. On connect every servo is
pinged (model 777), put in position mode (Operating Mode 0, kept in EEPROM through
Lock) and its torque turned on where it stands.

A move is one SYNC WRITE of Acceleration, Goal Position, Goal Time (0) and Goal
Velocity (41..47) per servo, timed so that all arrive together (``_forecast``), then
Moving polled until every servo stops and each checked within
``position_tolerance_ticks``. A failed move leaves every servo holding: one SYNC
WRITE (no reply needed) of the goals where the move has each joint now, then each
servo's Goal Position read back to say which hold. ``close()`` holds (torque stays
on: an SO-101 with torque off folds); ``relax()`` lets go on purpose.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from ..._clock import Clock, WallClock
from ..._errors import DeviceError
from ...devices import sts3215 as sts
from ...devices.feetech import FeetechBus
from ...model import FEETECH_SECTION, ArmModel, FeetechSection
from .._driver import Forecast
from .._hold import hold, hold_here, report
from .._sent import SentProfile
from ._forecast import POLL_S, FeetechForecaster, Goals
from ._lerobot import unit_config

F64 = NDArray[np.float64]
SETTLE_S = 0.3  # longest wait for a stopped servo's encoder to reach its goal step [s]
_GOAL_BLOCK = (41, 7)  # Acceleration .. Goal Velocity: (address, bytes)


def open_feetech(model: ArmModel, port: str | None) -> FeetechDriver:
    """Open the arm's servos on ``port`` (a device path), with the unit's calibration
    (``<config>/<arm>_feetech.json``, LeRobot's format) where there is one.

    Raises:
        ModelError: no or a wrong ``[drivers.feetech]`` table.
        DeviceError: no port, the port taken or missing, or the servos do not answer.
    """
    cfg = unit_config(model, FEETECH_SECTION.of(model))
    if not port:
        raise DeviceError("the feetech driver needs a port: /dev/ttyACM0 (say) or 'emu'")
    return FeetechDriver(model, FeetechBus(port, cfg.baudrate), config=cfg)


class FeetechDriver:
    """Driver (see ``drivers._driver``) for a Feetech arm described by ``model``."""

    moves = "smart"

    def __init__(
        self,
        model: ArmModel,
        bus: FeetechBus,
        *,
        config: FeetechSection | None = None,
        clock: Clock | None = None,
        on_close: Callable[[], None] | None = None,
    ) -> None:
        cfg = FEETECH_SECTION.of(model) if config is None else config
        self.model, self.bus, self._on_close = model, bus, on_close
        self.clock = clock or WallClock()
        self._forecaster = FeetechForecaster(model, cfg)
        self.ids = list(cfg.ids)
        self.gripper_id = cfg.gripper_id
        self.servos = [*self.ids] + ([cfg.gripper_id] if cfg.gripper_id is not None else [])
        self._tolerance = cfg.position_tolerance_ticks
        self._sent: SentProfile | None = None
        try:
            self._setup()
        except DeviceError:
            self.close()
            raise

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Names of the joints, in model order."""
        return self.model.joint_names

    def _setup(self) -> None:
        self.bus.check_models(self.servos)
        for sid in self.servos:
            self.bus.set_eeprom(sid, "Operating Mode", sts.MODE_POSITION)
        hold_here(self.bus, self.servos)

    def forecaster(self) -> FeetechForecaster:
        """This arm's forecasts as a value."""
        return self._forecaster

    def forecast(
        self,
        q0: F64,
        q1: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """What ``move(q1)`` does from ``q0`` [rad]; nothing is sent."""
        return self._forecaster.forecast(q0, q1, duration=duration, speed=speed, motor_s=motor_s)

    def forecast_grip(self, before: float | None, width: float) -> float:
        """How long ``grip(width)`` [m] takes from ``before`` [m] [s]."""
        return self._forecaster.forecast_grip(before, width)

    def _ticks(self) -> NDArray[np.int64]:
        present = self.bus.sync_read("Present Position", self.ids)
        return np.array([present[sid] for sid in self.ids], dtype=np.int64)

    def read(self) -> F64:
        """Present joint angles [rad], shape (dof,) (a servo on its goal's step reads as
        the goal asked for)."""
        ticks = self._ticks()
        angles = self._forecaster.angles(ticks)
        return angles if self._sent is None else self._sent.reading(ticks, angles)

    def move(
        self,
        q: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        """Move every joint to ``q`` [rad], all arriving together. Everything is checked
        before a byte is sent; a failed move leaves every servo holding (DeviceError)."""
        self._alive()
        start = self.read()
        goal, goals = self._forecaster.plan(start, q, duration, speed)
        try:
            self._send(start, goal, goals)
            if wait:
                self.clock.sleep(goals.seconds)
                self._wait_arrival(goals, goals.seconds * 0.5 + 1.0)
        except DeviceError as exc:
            raise DeviceError(f"{exc}; the move was abandoned: {report(self._hold)}") from exc

    def _send(self, start: F64, goal: F64, goals: Goals) -> None:
        block: dict[int, bytes] = {}
        for k, sid in enumerate(self.ids):
            block[sid] = (
                bytes((goals.accels[k],))
                + sts.register("Goal Position").encode(int(goals.ticks[k]))
                + bytes(2)
                + sts.register("Goal Velocity").encode(goals.speeds[k])
            )
        self.bus.write_block(*_GOAL_BLOCK, block)
        end = self._forecaster.angles(goals.ticks)
        self._sent = SentProfile(
            start, goal.copy(), end, goals.ticks, self.clock.now(), goals.seconds
        )

    def _wait_arrival(self, goals: Goals, timeout: float) -> None:
        if not self._stopped(self.ids, timeout):
            raise DeviceError(f"servos {self.ids}: still moving {timeout:.1f} s after the command")
        goal = dict(zip(self.ids, goals.ticks.tolist(), strict=True))
        deadline = self.clock.now() + SETTLE_S
        present = self.bus.sync_read("Present Position", self.ids)
        while present != goal and self.clock.now() < deadline:  # the encoders land on it
            self.clock.sleep(POLL_S)
            present = self.bus.sync_read("Present Position", self.ids)
        for sid, target in zip(self.ids, goals.ticks.tolist(), strict=True):
            if abs(present[sid] - target) > self._tolerance:
                raise DeviceError(
                    f"servo {sid}: stopped at step {present[sid]}, goal {target} (tolerance"
                    f" {self._tolerance}); is it blocked or did it miss the command?"
                )

    def _stopped(self, ids: list[int], timeout: float) -> bool:
        deadline = self.clock.now() + timeout
        while any(self.bus.sync_read("Moving", ids).values()):
            if self.clock.now() > deadline:
                return False
            self.clock.sleep(POLL_S)
        return True

    def grip(self, width: float) -> None:
        """Open the gripper to ``width`` [m] and wait; a stall on an object is a grasp."""
        tick = self._forecaster.grip_tick(width)
        self._alive()
        assert self.gripper_id is not None  # else the model has no gripper: grip_tick refused
        self.bus.write(self.gripper_id, "Goal Position", tick)
        self._stopped([self.gripper_id], 3.0)

    def _hold(self) -> tuple[list[int], list[int]]:
        """Hold every joint where the last move has it now (``_hold``): (confirmed,
        silent) IDs."""
        sent, self._sent, now = self._sent, None, self.clock.now()
        if sent is None:
            return [], []
        goals = dict(zip(self.ids, self._forecaster.ticks(sent.where(now)).tolist(), strict=True))
        return hold(
            self.bus, goals, not sent.done(now), lambda sid: self.bus.read(sid, "Goal Position")
        )

    def stop(self) -> None:
        """Hold every joint where it is now. Safe to repeat, a no-op once closed."""
        if not self.bus.is_open:
            return
        _, silent = self._hold()
        if silent:
            raise DeviceError(
                f"servos {silent} did not confirm that they hold; they may still move"
            )

    def relax(self) -> None:
        """Torque off on every servo: the arm goes limp (support it first)."""
        self._alive()
        self._sent = None
        self.bus.set_torque(self.servos, False)

    def stiffen(self) -> None:
        """Torque on where every servo is now: the arm holds that pose."""
        self._alive()
        self._sent = None
        hold_here(self.bus, self.servos)

    def _alive(self) -> None:
        if not self.bus.is_open:
            raise DeviceError(
                f"the {self.model.name}'s Feetech bus is closed; open the driver again"
            )

    def close(self) -> None:
        """Hold position (torque stays on), release the port. Safe twice."""
        try:
            with contextlib.suppress(DeviceError):
                if self.bus.is_open:
                    self._hold()
        finally:
            self.bus.close()
            on_close, self._on_close = self._on_close, None
            if on_close is not None:
                on_close()
