"""Dynamixel arms (the OpenManipulator-X): joint angles <-> XM430 ticks on one bus.

Calibration, from the model's ``[drivers.dynamixel]`` table: joint servo
``ids``, ``gripper_id``, ``baudrate``, ``ticks_per_turn`` and ``center_tick``:
``tick = center_tick + q * ticks_per_turn / 2pi`` (ticks increase with the
model's positive angle), clipped to the position-mode range 0..4095 (at most
one tick at exactly +-180 deg).

Gripper (current-based position mode, so it squeezes with at most
``gripper_current`` x 2.69 mA instead of stalling at full torque): the opening
maps linearly from ``width_mm[0]`` at ``gripper_ticks[0]`` to ``width_mm[1]`` at
``gripper_ticks[1]``. The default ticks (1500 closed, 2600 open) are a starting
point; measure your unit and set ``gripper_ticks`` in its calibration file.

Moves use time-based profiles (Drive Mode bit 2): every joint gets the same
total and ramp time, so all arrive together. ``close()`` leaves torque ON and
the arm holding its pose, because an OpenManipulator-X with torque off folds
under gravity; call ``relax()`` first to release it on purpose.
"""

from __future__ import annotations

import contextlib
import math
import time
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import DeviceError, InputError, JointLimitError
from ..devices import _xm430 as xm
from ..devices.dynamixel import DynamixelBus
from ..model import ArmModel, dynamixel_section

_MAX_PROFILE_MS = 32737  # time-based Profile Velocity limit
_POLL_S = 0.01
_HOLD_PROFILE_MS = (50, 100)  # (ramp, total) of a stop: settle on the held tick in 0.1 s


def open_driver(model: ArmModel, port: str | None) -> DynamixelDriver:
    """Open the arm's servos on ``port`` (a device path, or ``"emu"`` for an emulator).

    Raises:
        ModelError: no or a wrong ``[drivers.dynamixel]`` table.
        DeviceError: no port, or the servos do not answer.
    """
    cfg = dynamixel_section(model)
    if not port:
        raise DeviceError("the dynamixel driver needs a port: /dev/ttyUSB0 (say) or 'emu'")
    emulator = None
    if port == "emu":
        from ..sim.dynamixel_emulator import DynamixelEmulator

        emulator = DynamixelEmulator([*cfg.ids, cfg.gripper_id])
        port = emulator.port
    try:
        bus = DynamixelBus(port, cfg.baudrate)
    except DeviceError:
        if emulator is not None:
            emulator.close()
        raise
    return DynamixelDriver(model, bus, emulator=emulator)


def profile_times(
    distance: NDArray[np.float64], v_max: NDArray[np.float64], a_max: NDArray[np.float64]
) -> tuple[float, float]:
    """(total, ramp) [s] of the shortest common trapezoid for every joint.

    ``distance`` [rad], ``v_max`` [rad/s], ``a_max`` [rad/s^2], shape (dof,).
    """
    d = np.abs(distance)
    triangular = d < v_max**2 / a_max
    each = np.where(triangular, 2.0 * np.sqrt(d / a_max), d / v_max + v_max / a_max)
    total = float(each.max(initial=0.0))
    return total, ramp_for(total, d, a_max)


def ramp_for(total: float, distance: NDArray[np.float64], a_max: NDArray[np.float64]) -> float:
    """Shortest ramp [s] of a ``total``-second trapezoid that keeps every joint under
    ``a_max``: d = a * ramp * (total - ramp), solved for the most demanding joint."""
    need = 4.0 * float(np.max(np.abs(distance) / a_max, initial=0.0))
    return min(total / 2.0, (total - math.sqrt(max(total * total - need, 0.0))) / 2.0)


def check_timing(duration: float | None, speed: float | None) -> None:
    """ValueError unless ``duration`` is 0..32.7 s and ``speed`` in (0, 1] (or None)."""
    if speed is not None and not 0.0 < speed <= 1.0:
        raise InputError(f"speed must be in (0, 1] (a fraction of max speed), got {speed}")
    if duration is not None and not 0.0 <= duration <= _MAX_PROFILE_MS / 1000:
        raise InputError(f"duration must be 0..{_MAX_PROFILE_MS / 1000} s, got {duration}")


class DynamixelDriver:
    """Driver (see ``drivers._driver``) for a Dynamixel arm described by ``model``."""

    def __init__(self, model: ArmModel, bus: DynamixelBus, *, emulator: Any = None) -> None:
        cfg = dynamixel_section(model)
        self.model, self.bus, self._emulator = model, bus, emulator
        self.ids = list(cfg.ids)
        self.gripper_id = cfg.gripper_id
        self._ticks_per_rad = cfg.ticks_per_turn / (2.0 * math.pi)
        self._center = cfg.center_tick
        self._grip_ticks = cfg.gripper_ticks
        self._tolerance = cfg.position_tolerance_ticks
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
        self.bus.check_models([*self.ids, self.gripper_id])
        for sid in self.ids:
            self.bus.set_operating_mode(sid, xm.MODE_POSITION)
        self.bus.set_time_based(self.ids, True)
        self.bus.set_operating_mode(self.gripper_id, xm.MODE_CURRENT_POSITION)
        self.bus.write(self.gripper_id, "Goal Current", gripper_current)
        self.bus.set_torque([*self.ids, self.gripper_id], True)

    def to_ticks(self, q: NDArray[np.float64]) -> NDArray[np.int64]:
        """Joint angles [rad], shape (dof,) -> goal ticks, shape (dof,)."""
        ticks = np.rint(self._center + np.asarray(q) * self._ticks_per_rad)
        return np.clip(ticks, 0, 4095).astype(np.int64)

    def to_angles(self, ticks: NDArray[np.int64]) -> NDArray[np.float64]:
        """Ticks, shape (dof,) -> joint angles [rad], shape (dof,)."""
        return (np.asarray(ticks, dtype=np.float64) - self._center) / self._ticks_per_rad

    def check_limits(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        """``q`` [rad] as a (dof,) array; JointLimitError names the first joint outside."""
        q = np.asarray(q, dtype=np.float64)
        if q.shape != (self.model.dof,):
            raise InputError(f"expected {self.model.dof} joint angles, got shape {q.shape}")
        for joint, value in zip(self.model.joints, q, strict=True):
            if not joint.lower - 1e-9 <= value <= joint.upper + 1e-9:
                raise JointLimitError(
                    f"{joint.name}: {math.degrees(value):.2f} deg is outside its range"
                    f" {math.degrees(joint.lower):.2f}..{math.degrees(joint.upper):.2f} deg;"
                    " choose a target inside it"
                )
        return q

    def timing(
        self,
        start: NDArray[np.float64],
        goal: NDArray[np.float64],
        duration: float | None = None,
        speed: float | None = None,
    ) -> int:
        """Profile total time [ms] for a move, from ``duration`` [s] and/or ``speed`` (0, 1]."""
        check_timing(duration, speed)
        v_max = np.array([j.max_velocity for j in self.model.joints]) * (speed or 1.0)
        a_max = np.array([j.max_acceleration for j in self.model.joints])
        fastest, _ = profile_times(goal - start, v_max, a_max)
        total_ms = max(1, math.ceil(1000.0 * max(fastest, duration or 0.0)))
        if total_ms > _MAX_PROFILE_MS:
            raise InputError(
                f"this move would take {total_ms / 1000:.1f} s at speed {speed}; a servo profile"
                f" lasts at most {_MAX_PROFILE_MS / 1000} s: raise the speed or split the move"
            )
        return total_ms

    def move(
        self,
        q: NDArray[np.float64],
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        """Move every joint to ``q`` [rad], shape (dof,), all arriving together.

        A duration shorter than the joints' speed and acceleration limits allow is
        stretched to the shortest one that respects them. Every argument is checked
        before a byte is sent. If the move fails part-way every servo that answers is
        commanded to hold its present position, then DeviceError is raised.
        """
        goal = self.check_limits(q)
        check_timing(duration, speed)
        ticks = self.to_ticks(goal)
        start = self.read()
        total_ms = self.timing(start, goal, duration=duration, speed=speed)
        a_max = np.array([j.max_acceleration for j in self.model.joints])
        ramp_ms = round(1000.0 * ramp_for(total_ms / 1000.0, goal - start, a_max))
        try:
            self.bus.set_profiles({sid: (ramp_ms, total_ms) for sid in self.ids})
            self.bus.sync_write("Goal Position", dict(zip(self.ids, ticks.tolist(), strict=True)))
            if wait:
                self._wait(total_ms / 1000.0 * 1.5 + 1.0, ticks)
        except DeviceError as exc:
            lost: list[int] = []
            with contextlib.suppress(DeviceError):
                lost = self._hold()
            silent = f" (servos {lost} did not answer)" if lost else ""
            raise DeviceError(
                f"{exc}; the move was abandoned and every servo that answers holds{silent}"
            ) from exc

    def _wait(self, timeout: float, goal: NDArray[np.int64]) -> None:
        """Wait for the joints to stop, then check they arrived at ``goal`` [tick]."""
        if not self._stopped(self.ids, timeout):
            raise DeviceError(f"servos {self.ids}: still moving {timeout:.1f} s after the command")
        self._check_arrival(self.ids, goal)

    def _stopped(self, ids: list[int], timeout: float) -> bool:
        """Poll Moving until every servo in ``ids`` stops (True) or ``timeout`` [s] (False)."""
        deadline = time.monotonic() + timeout
        while any(self.bus.sync_read("Moving", ids).values()):
            if time.monotonic() > deadline:
                return False
            time.sleep(_POLL_S)
        return True

    def _check_arrival(self, ids: list[int], goal: NDArray[np.int64]) -> None:
        present = self.bus.sync_read("Present Position", ids)
        for sid, target in zip(ids, goal.tolist(), strict=True):
            if abs(present[sid] - target) > self._tolerance:
                raise DeviceError(
                    f"servo {sid}: stopped at tick {present[sid]}, goal {target}"
                    f" (tolerance {self._tolerance}); is it blocked or did it miss the command?"
                )

    def read(self) -> NDArray[np.float64]:
        """Present joint angles [rad], shape (dof,), from one SYNC_READ."""
        states = self.bus.read_states(self.ids)
        return self.to_angles(np.array([states[sid].position for sid in self.ids]))

    def grip_ticks(self, width: float) -> int:
        """Gripper goal tick for an opening ``width`` [m] (ValueError outside the model's range)."""
        g = self.model.gripper
        if not g.width_min - 1e-12 <= width <= g.width_max + 1e-12:
            raise InputError(
                f"grip width {width * 1000:.1f} mm is outside {self.model.name}'s range"
                f" {g.width_min * 1000:.1f}..{g.width_max * 1000:.1f} mm"
            )
        closed, opened = self._grip_ticks
        return round(
            closed + (width - g.width_min) / (g.width_max - g.width_min) * (opened - closed)
        )

    def grip(self, width: float) -> None:
        """Open the gripper to ``width`` [m] and wait; a stall on an object is a grasp."""
        tick = self.grip_ticks(width)
        self.bus.write(self.gripper_id, "Goal Position", tick)
        self._stopped([self.gripper_id], 3.0)

    def _hold(self) -> list[int]:
        """Command every servo that answers to its present position; the IDs that did not.
        One try per servo, so that a missing one delays the others as little as possible."""
        held, lost = {}, []
        retries, self.bus.retries = self.bus.retries, 0
        try:
            for sid in [*self.ids, self.gripper_id]:
                try:
                    held[sid] = self.bus.read(sid, "Present Position", alert_ok=True)
                except DeviceError:
                    lost.append(sid)
        finally:
            self.bus.retries = retries
        if held:
            self.bus.set_profiles({sid: _HOLD_PROFILE_MS for sid in held if sid in self.ids})
            self.bus.sync_write("Goal Position", held)
        return lost

    def stop(self) -> None:
        """Hold every servo at its present position now. Safe to repeat, a no-op once closed."""
        if not self.bus.is_open:
            return
        lost = self._hold()
        if lost:
            raise DeviceError(f"servos {lost} did not answer, so they could not be stopped")

    def relax(self) -> None:
        """Torque off on every servo: the arm goes limp (support it first)."""
        self.bus.set_torque([*self.ids, self.gripper_id], False)

    def close(self) -> None:
        """Hold position (torque stays on, see the module notes), release the port. Safe twice."""
        try:
            with contextlib.suppress(DeviceError):
                if self.bus.is_open:
                    self._hold()
        finally:
            self.bus.close()
            if self._emulator is not None:
                self._emulator.close()
                self._emulator = None
