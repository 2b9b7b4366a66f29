"""The hobby-servo arm driver: joint angles -> pulses through each servo's table -> one group move.

Every command is checked completely (shape, each servo's range, speed, time)
before the first byte goes out; a refused command sends nothing. A move is one
group move: the time is set by the servo that needs longest at its maximum speed,
so all servos arrive together and none turns faster than its limit.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from ..._errors import DeviceError, InputError
from ...model import ArmModel
from ._bus import ServoBus
from ._table import PULSE_MAX_US, PULSE_MIN_US, ServoCalibration

WAIT_MARGIN_S = 1.0  # extra time allowed for a move to report done


class ServoArmDriver:
    """A servo arm on an SSC-32 or Maestro (implements ``armkit.drivers.Driver``).

    Hobby servos report nothing: ``read()`` gives the angles of the pulses being
    sent. After power-up the controller does not know where a servo is, so the
    first move of each servo jumps at full speed; move home first.

    Args:
        model: the arm; its joints' ``max_velocity`` [rad/s] limit every move.
        bus: the controller.  joints: one table per joint.  grip: the gripper's, or None.
        on_close: called once by ``close()`` (e.g. to stop an emulator).
    """

    def __init__(
        self,
        model: ArmModel,
        bus: ServoBus,
        joints: tuple[ServoCalibration, ...],
        grip: ServoCalibration | None,
        on_close: Callable[[], None] | None = None,
    ) -> None:
        self.model, self.bus = model, bus
        self.joints, self.grip_table = joints, grip
        self._on_close = on_close
        self._closed = False
        self._busy_until = 0.0  # when the moves sent so far end [s, monotonic clock]
        # channel -> last pulse sent [µs]; at start, what the controller is sending
        self._commanded = {ch: p for ch, p in bus.read(self._channels()).items() if p > 0}

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Names of the joints, model order."""
        return self.model.joint_names

    @property
    def tables(self) -> tuple[ServoCalibration, ...]:
        """Every servo's table: the joints', then the gripper's if there is one."""
        return (*self.joints, *([self.grip_table] if self.grip_table else []))

    def _channels(self) -> list[int]:
        return [t.channel for t in self.tables]

    def move(
        self,
        q: NDArray[np.float64],
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        """Move every joint to ``q`` [rad], shape (dof,), all arriving together.

        Args:
            duration: at least this long [s] (longer if a servo's speed limit needs it).
            speed: fraction of each joint's maximum velocity, (0, 1]; None = 1.
            wait: block until the controller reports the move done.

        Raises:
            JointLimitError: an angle is outside its servo's range (names servo and range).
            ValueError: wrong shape, speed or duration.
        """
        q = self._check_q(q)
        pulses = {t.channel: t.to_pulse(float(a)) for t, a in zip(self.joints, q, strict=True)}
        time_ms = self._move_time_ms(pulses, duration, _check_speed(speed))
        self._send(pulses, time_ms, wait)

    def _check_q(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        q = np.asarray(q, dtype=np.float64)
        if q.shape != (self.model.dof,):
            raise InputError(
                f"{self.model.name} needs {self.model.dof} joint angles "
                f"({', '.join(self.joint_names)}), got shape {q.shape}"
            )
        return q

    def _move_time_ms(self, pulses: dict[int, float], duration: float | None, speed: float) -> int:
        """Group time [ms]: the slowest servo's time at ``speed`` x its maximum, at least
        ``duration``; rounded up, so no servo exceeds its limit."""
        if duration is not None and not (math.isfinite(duration) and duration >= 0):
            raise InputError(f"duration must be a number of seconds >= 0, got {duration}")
        starts, pad = self._starts()
        needed = [duration or 0.0]
        for table, joint in zip(self.joints, self.model.joints, strict=True):
            start, target = starts.get(table.channel), pulses.get(table.channel)
            if start is not None and target is not None:
                travel = abs(target - start) + pad  # µs of pulse
                rate = table.max_rate(start, target)
                needed.append(travel * rate / (joint.max_velocity * speed))
        time_ms = math.ceil(max(needed) * 1000.0 - 1e-9)
        if time_ms > self.bus.max_time_ms:
            raise InputError(
                f"this move would take {time_ms / 1000:.1f} s; the {self.bus.name} allows at most "
                f"{self.bus.max_time_ms / 1000:.1f} s per move; move in smaller steps or faster"
            )
        return time_ms

    def _starts(self) -> tuple[dict[int, float], float]:
        """Where each servo starts from [µs], and how uncertain that is [µs]: the last
        pulses sent, or, while a move may still be running, the pulses read back."""
        if time.monotonic() >= self._busy_until:
            return self._commanded, 0.0
        read = self.bus.read(self._channels())
        return {ch: p for ch, p in read.items() if p > 0}, self.bus.read_resolution_us

    def _send(self, pulses: dict[int, float], time_ms: int, wait: bool) -> None:
        self.bus.move(pulses, time_ms or None)
        self._commanded.update(pulses)
        self._busy_until = max(self._busy_until, time.monotonic() + time_ms / 1000.0)
        if wait:
            self.bus.wait(self._busy_until - time.monotonic() + WAIT_MARGIN_S)

    def move_servo(
        self, name: str, pulse_us: float, *, speed: float = 0.5, wait: bool = True
    ) -> None:
        """Send one servo a raw pulse [µs, 500..2500] at ``speed`` x its joint's maximum
        (calibration; the gripper moves at once). Other servos hold."""
        table = self._table(name)
        if not PULSE_MIN_US <= pulse_us <= PULSE_MAX_US:
            raise InputError(f"pulse {pulse_us} µs for {name} is outside 500..2500 µs")
        pulses = {table.channel: float(pulse_us)}
        time_ms = 0 if table is self.grip_table else self._move_time_ms(pulses, None, speed)
        self._send(pulses, time_ms, wait)

    def _table(self, name: str) -> ServoCalibration:
        for table in self.tables:
            if table.name == name:
                return table
        raise InputError(f"no servo {name!r}; servos are {', '.join(t.name for t in self.tables)}")

    def read(self) -> NDArray[np.float64]:
        """Joint angles [rad], shape (dof,), from the pulses the controller reports.

        A pulse within the read-back resolution of the last one sent gives back the
        angle that was asked for; a servo never commanded reports its home angle.
        """
        reported = self.bus.read([t.channel for t in self.joints])
        angles = []
        for table, joint in zip(self.joints, self.model.joints, strict=True):
            pulse, sent = reported[table.channel], self._commanded.get(table.channel)
            if sent is not None and abs(pulse - sent) <= self.bus.read_resolution_us:
                pulse = sent
            angles.append(table.to_value(pulse) if pulse > 0 else joint.home)
        return np.array(angles, dtype=np.float64)

    def grip(self, width: float) -> None:
        """Set the gripper opening ``width`` [m] through the gripper's table."""
        if self.grip_table is None:
            raise DeviceError(f"{self.model.name} has no gripper channel on the {self.bus.name}")
        self._send({self.grip_table.channel: self.grip_table.to_pulse(width)}, 0, True)

    def stop(self) -> None:
        """Hold every servo where it is now. Safe to call at any time, repeatedly."""
        if not self._closed:
            self.bus.stop(self._channels())
            self._commanded = {ch: p for ch, p in self.bus.read(self._channels()).items() if p > 0}

    def close(self) -> None:
        """Stop, release the port (and the emulator, if one was started). Safe to call twice."""
        if self._closed:
            return
        try:
            self.stop()
        finally:
            self._closed = True
            self.bus.close()
            if self._on_close:
                self._on_close()


def _check_speed(speed: float | None) -> float:
    if speed is None:
        return 1.0
    if not (math.isfinite(speed) and 0.0 < speed <= 1.0):
        raise InputError(f"speed must be a fraction of the maximum in (0, 1], got {speed}")
    return float(speed)
