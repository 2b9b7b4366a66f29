"""Dynamixel arms (the OpenManipulator-X): joint angles <-> XM430 ticks on one bus.

Calibration, from the model's ``[drivers.dynamixel]`` table: joint servo
``ids``, ``gripper_id``, ``baudrate``, ``ticks_per_turn`` and ``center_tick``:
``tick = center_tick + q * ticks_per_turn / 2pi`` (ticks increase with the
model's positive angle), clipped to the position-mode range 0..4095 (at most
one tick at exactly +-180 deg). ``operating_mode = "extended"`` puts the joints
in extended position mode instead (multi-turn, no clipping: joints with more
than one turn of range).

Gripper (current-based position mode, so it squeezes with at most
``gripper_current`` x 2.69 mA instead of stalling at full torque): the opening
maps linearly from ``width_mm[0]`` at ``gripper_ticks[0]`` to ``width_mm[1]`` at
``gripper_ticks[1]``. The default ticks are ROBOTIS's (2483 closed, 1613 open:
its stroke per tick, with ticks falling as the jaws open); measure your unit and
set ``gripper_ticks`` in its calibration file. Every servo's Drive Mode is
written on connect (normal direction; time-based profiles on the joints), so
the direction never depends on what a unit was last set to.

Moves use time-based profiles (Drive Mode bit 2): every joint gets the same
total and ramp time (the shared timing rule of ``armkit.model._limits``), so
all arrive together; a move longer than one profile (32.7 s) goes in pieces.
``close()`` leaves torque ON and the arm holding its pose, because an
OpenManipulator-X with torque off folds under gravity; call ``relax()`` first
to release it on purpose.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from .._clock import Clock, WallClock
from .._errors import DeviceError, InputError
from ..devices import xm430 as xm
from ..devices.dynamixel import DynamixelBus
from ..model import (
    ArmModel,
    DynamixelSection,
    check_grip,
    check_joints,
    check_speed,
    dynamixel_section,
    limits,
    move_time,
    ramp_time,
)
from ._driver import Forecast, pieces
from ._dxl_forecast import MAX_PROFILE_MS
from ._dxl_forecast import DynamixelForecaster as DynamixelForecaster
from ._dxl_points import dynamixel_points as dynamixel_points
from ._dxl_wait import stopped, wait_arrival
from ._hold import hold, hold_here, report
from ._sent import SentProfile

HOLD_PROFILE_MS = (50, 100)  # (ramp, total) of a stop: settle on the held tick in 0.1 s


def open_dynamixel(model: ArmModel, port: str | None) -> DynamixelDriver:
    """Open the arm's servos on ``port`` (a device path).

    Raises:
        ModelError: no or a wrong ``[drivers.dynamixel]`` table.
        DeviceError: no port, or the servos do not answer.
    """
    cfg = dynamixel_section(model)
    if not port:
        raise DeviceError("the dynamixel driver needs a port: /dev/ttyUSB0 (say) or 'emu'")
    bus = DynamixelBus(port, cfg.baudrate)
    return DynamixelDriver(model, bus)


class DynamixelDriver:
    """Driver (see ``drivers._driver``) for a Dynamixel arm described by ``model``.

    Args:
        config: the setup (default: the model's ``[drivers.dynamixel]``, ``dynamixel_section``).
        clock: time for waiting (real time by default).  on_close: run once by ``close()``.
    """

    moves = "smart"  # see armkit.drivers.Forecaster

    def __init__(
        self,
        model: ArmModel,
        bus: DynamixelBus,
        *,
        config: DynamixelSection | None = None,
        clock: Clock | None = None,
        on_close: Callable[[], None] | None = None,
    ) -> None:
        cfg = dynamixel_section(model) if config is None else config
        self.model, self.bus, self._on_close = model, bus, on_close
        self.clock = clock or WallClock()
        self._forecaster = DynamixelForecaster(model, cfg)
        self._extended = cfg.operating_mode == "extended"
        self.ids = list(cfg.ids)
        self.gripper_id = cfg.gripper_id
        self.servos = [*self.ids] if cfg.gripper_id is None else [*self.ids, cfg.gripper_id]
        self._ticks_per_rad = cfg.ticks_per_turn / (2.0 * math.pi)
        self._grip_ticks = cfg.gripper_ticks
        self._tolerance = cfg.position_tolerance_ticks
        self._sent: SentProfile | None = None  # the last profile sent, while it holds
        try:
            self._setup(cfg.gripper_current)
        except DeviceError:
            self.close()
            raise

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Names of the joints, in model order."""
        return self.model.joint_names

    def _setup(self, gripper_current: int) -> None:
        self.bus.check_models(self.servos)
        mode = xm.MODE_EXTENDED_POSITION if self._extended else xm.MODE_POSITION
        for sid in self.ids:
            self.bus.set_operating_mode(sid, mode)
            self.bus.set_eeprom(sid, "Drive Mode", xm.DRIVE_MODE_TIME_BASED)  # normal direction
        if self.gripper_id is not None:
            self.bus.set_eeprom(self.gripper_id, "Drive Mode", 0)
            self.bus.set_operating_mode(self.gripper_id, xm.MODE_CURRENT_POSITION)
            self.bus.write(self.gripper_id, "Goal Current", gripper_current)
        self.bus.set_torque(self.servos, True)

    def to_ticks(self, q: NDArray[np.float64]) -> NDArray[np.int64]:
        """Joint angles [rad], shape (dof,) -> goal ticks, shape (dof,)."""
        return self._forecaster.ticks(q)

    def to_angles(self, ticks: NDArray[np.int64]) -> NDArray[np.float64]:
        """Ticks, shape (dof,) -> joint angles [rad], shape (dof,)."""
        return self._forecaster.angles(ticks)

    def forecast(
        self,
        q0: NDArray[np.float64],
        q1: NDArray[np.float64],
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """What ``move(q1)`` does from ``q0`` [rad] (``DynamixelForecaster``); nothing is sent."""
        return self._forecaster.forecast(q0, q1, duration=duration, speed=speed, motor_s=motor_s)

    def forecast_grip(self, before: float | None, width: float) -> float:
        """How long ``grip(width)`` [m] takes from ``before`` [m] [s]."""
        return self._forecaster.forecast_grip(before, width)

    def forecaster(self) -> DynamixelForecaster:
        """This arm's forecasts as a value (its model and tick calibration)."""
        return self._forecaster

    def move(
        self,
        q: NDArray[np.float64],
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        """Move every joint to ``q`` [rad], shape (dof,), all arriving together, in the time
        of the shared rule (see ``armkit.drivers.Driver``). Every argument is checked
        before a byte is sent. If the move fails part-way every servo that answers is
        commanded to hold its present position, then DeviceError is raised.
        """
        goal = check_joints(self.model, q)
        frac = check_speed(speed)
        self._alive()
        asked, start = self._start()
        seconds = move_time(self.model, asked, goal, speed=frac, duration=duration)
        end = self.to_angles(self.to_ticks(goal))
        if duration is None:  # the profile is timed for what the servos do: to the goal's tick
            seconds = move_time(self.model, start, end, speed=frac)
        parts = pieces(start, goal, seconds, MAX_PROFILE_MS / 1000.0)
        if len(parts) > 1 and not wait:
            raise InputError(
                f"this move takes {seconds:.1f} s; a servo profile lasts at most "
                f"{MAX_PROFILE_MS / 1000} s, so it goes in pieces and must wait"
            )
        _, amax = limits(self.model, peak=duration is not None)  # timed: the servos' own
        ramp = ramp_time(seconds, end - start, amax) if len(parts) == 1 else 0.0
        try:
            origin = start
            for k, (target, piece_s) in enumerate(parts):
                last = k == len(parts) - 1
                origin = self._profile_move(origin, target, piece_s, ramp, wait or not last)
        except DeviceError as exc:
            raise DeviceError(f"{exc}; the move was abandoned: {report(self._hold)}") from exc

    def _profile_move(
        self,
        origin: NDArray[np.float64],
        target: NDArray[np.float64],
        seconds: float,
        ramp: float,
        wait: bool,
    ) -> NDArray[np.float64]:
        """One time-based profile from ``origin`` to ``target``'s ticks [rad] lasting
        ``seconds`` with ``ramp`` [s] of acceleration at each end (pieces of a long move:
        none). Returns where it ends [rad] (``target`` to the tick)."""
        total_ms = max(1, math.ceil(1000.0 * seconds - 1e-9))
        ramp_ms = min(round(1000.0 * ramp), total_ms // 2)
        ticks = self.to_ticks(target)
        end = self.to_angles(ticks)
        self.bus.set_profiles({sid: (ramp_ms, total_ms) for sid in self.ids})
        self.bus.sync_write("Goal Position", dict(zip(self.ids, ticks.tolist(), strict=True)))
        now, total = self.clock.now(), total_ms / 1000.0
        self._sent = SentProfile(origin, target.copy(), end, ticks, now, total)
        if wait:
            self.clock.sleep(total_ms / 1000.0)  # nothing to ask before it can be done
            timeout = total_ms / 1000.0 * 0.5 + 1.0
            wait_arrival(self.bus, self.clock, self.ids, ticks, timeout, self._tolerance)
        return end

    def _alive(self) -> None:
        if not self.bus.is_open:
            raise DeviceError(
                f"the {self.model.name}'s Dynamixel bus is closed; open the driver again"
            )

    def _start(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Where a new move starts [rad]: (as the timing rule sees it, as the servos go).
        The servos follow the last profile, their encoders a little behind, so a move
        starts where the profile has them now (once it has ended: the angles it was
        sent for, as ``read`` says, and their ticks), unless they are further from it
        than the arrival tolerance (blocked, pushed): then where they are."""
        ticks = self._ticks()
        present = self.to_angles(ticks)
        if self._sent is None:
            return present, present
        now = self.clock.now()
        commanded = self._sent.where(now)
        if np.max(np.abs(present - commanded)) * self._ticks_per_rad > self._tolerance:
            return self._sent.reading(ticks, present), present
        return (self._sent.goal if self._sent.done(now) else commanded), commanded

    def _ticks(self) -> NDArray[np.int64]:
        states = self.bus.read_states(self.ids)
        return np.array([states[sid].position for sid in self.ids], dtype=np.int64)

    def read(self) -> NDArray[np.float64]:
        """Present joint angles [rad], shape (dof,), from one SYNC_READ; a servo on the
        tick of the last goal reads as that goal's angle (the tick holds it to within
        half a tick either way)."""
        ticks = self._ticks()
        angles = self.to_angles(ticks)
        return angles if self._sent is None else self._sent.reading(ticks, angles)

    def grip_ticks(self, width: float) -> int:
        """Gripper goal tick for an opening ``width`` [m] (ValueError outside the model's range)."""
        g = self.model.gripper
        check_grip(self.model, width)
        closed, opened = self._grip_ticks
        return round(
            closed + (width - g.width_min) / (g.width_max - g.width_min) * (opened - closed)
        )

    def grip(self, width: float) -> None:
        """Open the gripper to ``width`` [m] and wait; a stall on an object is a grasp."""
        tick = self.grip_ticks(width)
        self._alive()
        assert self.gripper_id is not None  # else the model has no gripper: grip_ticks refused
        self.bus.write(self.gripper_id, "Goal Position", tick)
        stopped(self.bus, self.clock, [self.gripper_id], 3.0)

    def _hold(self) -> tuple[list[int], list[int]]:
        """Hold every joint where its last profile has it now (``_hold``), settling on
        the held tick in 0.1 s (``HOLD_PROFILE_MS``): (IDs that confirmed, IDs that did not)."""
        sent, self._sent, now = self._sent, None, self.clock.now()
        if sent is None:  # no move sent: every servo rests on the goal it had
            return [], []
        goals = dict(zip(self.ids, self.to_ticks(sent.where(now)).tolist(), strict=True))
        send = not sent.done(now)
        if send:
            self.bus.set_profiles({sid: HOLD_PROFILE_MS for sid in goals})
        return hold(
            self.bus, goals, send, lambda sid: self.bus.read(sid, "Goal Position", alert_ok=True)
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
        """Torque on where every servo is now (after ``relax``): the arm holds that pose."""
        self._alive()
        self._sent = None
        hold_here(self.bus, self.servos)

    def close(self) -> None:
        """Hold position (torque stays on, see the module notes), release the port. Safe twice."""
        try:
            with contextlib.suppress(DeviceError):
                if self.bus.is_open:
                    self._hold()
        finally:
            self.bus.close()
            on_close, self._on_close = self._on_close, None
            if on_close is not None:
                on_close()
