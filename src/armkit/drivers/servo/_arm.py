"""The hobby-servo arm driver: joint angles -> pulses through each servo's table -> one group move.

Every command is checked completely (the shared rules of ``armkit.model._limits``,
then each servo's table and the controller's limits) before the first byte goes
out; a refused command sends nothing. A move is one group move lasting the time
of the shared timing rule (``move_time``), longer only if a servo's table is
locally steeper than its joint's speed allows; all servos arrive together. A
move longer than the controller's longest command goes as pieces along the line.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from ..._clock import Clock, WallClock
from ..._errors import DeviceError, InputError
from ...model import ArmModel, check_grip, check_joints, check_speed, move_time
from .._driver import Forecast, pieces
from ._bus import ServoBus
from ._forecast import ServoForecaster, group_ms
from ._table import PULSE_MAX_US, PULSE_MIN_US, ServoCalibration

WAIT_MARGIN_S = 1.0  # extra time allowed for a move to report done


class ServoArmDriver:
    """A servo arm on an SSC-32 or Maestro (implements ``armkit.drivers.Driver``).

    Hobby servos report nothing: ``read()`` gives the angles of the pulses being sent
    (as asked, where the controller reports the pulse sent: its read-back is coarser).
    After power-up the controller does not know where a servo is, so the first move
    of each servo jumps at full speed; move home first.

    Args:
        model: the arm; its joints' ``max_velocity`` [rad/s] limit every move.
        bus: the controller.  joints: one table per joint.  grip: the gripper's, or None.
        on_close: called once by ``close()``.  clock: time for waiting (real time by default).
        settle_s: how long a waiting move waits after the controller reports it done, for
            the servos to catch up with their pulses [s] (they report nothing).
    """

    moves = "hobby"  # see armkit.drivers.Forecaster

    def __init__(
        self,
        model: ArmModel,
        bus: ServoBus,
        joints: tuple[ServoCalibration, ...],
        grip: ServoCalibration | None,
        on_close: Callable[[], None] | None = None,
        clock: Clock | None = None,
        settle_s: float = 0.1,
    ) -> None:
        self.model, self.bus = model, bus
        self.settle_s = settle_s
        self.joints, self.grip_table = joints, grip
        self.clock = clock or WallClock()
        self._on_close = on_close
        self._closed = False
        self._busy_until = 0.0  # when the moves sent so far end [s, self.clock]
        # channel -> (start pulse, target pulse, start time, duration) of the last move sent
        self._last: dict[int, tuple[float, float, float, float]] = {}
        # channel -> last pulse sent [µs]; at start, what the controller is sending
        self._commanded = {ch: p for ch, p in bus.read(self._channels()).items() if p > 0}
        # channel -> (pulse [µs], value [rad or m]) of the last command this driver sent
        self._asked: dict[int, tuple[float, float]] = {}

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
        """Move every joint to ``q`` [rad], shape (dof,), all arriving together, in the
        time of the shared rule (see ``armkit.drivers.Driver``).

        Args:
            duration: exactly this long [s]; None = as fast as the limits allow.
            speed: fraction of each joint's maximum velocity, (0, 1]; None = 1.
            wait: block until the controller reports the move done.

        Raises:
            JointLimitError: an angle is outside its joint's limits (names joint and range).
            ValueError: wrong shape, speed or duration; a long move with ``wait=False``.
        """
        goal = check_joints(self.model, q)
        frac = check_speed(speed)
        self._alive()
        starts, pad = self._starts()
        origin = self._angles_of(starts)
        # the controller moves every pulse at constant speed: its servos do the ramping
        seconds = move_time(self.model, origin, goal, speed=frac, duration=duration, ramps=False)
        parts = pieces(origin, goal, seconds, self.bus.max_time_ms / 1000.0)
        if len(parts) > 1 and not wait:
            raise InputError(
                f"this move takes {seconds:.1f} s, longer than one {self.bus.name} command "
                f"({self.bus.max_time_ms / 1000:.1f} s): it goes in pieces, so it must wait"
            )
        parts[-1] = (goal, parts[-1][1])  # end on the goal itself, not the line's end
        for k, (target, piece_s) in enumerate(parts):
            values = {t.channel: float(a) for t, a in zip(self.joints, target, strict=True)}
            pulses = {t.channel: t.to_pulse(values[t.channel]) for t in self.joints}
            time_ms = self._move_time_ms(pulses, starts, pad, piece_s, duration is not None, frac)
            self._send(pulses, time_ms, wait or k < len(parts) - 1, values)
            starts, pad = dict(self._commanded), 0.0

    def _alive(self) -> None:
        if self._closed:
            raise DeviceError(
                f"the {self.model.name}'s {self.bus.name} is closed; open the driver again"
            )

    def _angles_of(self, pulses: dict[int, float]) -> NDArray[np.float64]:
        """Joint angles [rad] of ``pulses`` (a servo never commanded: its home angle)."""
        angles = [
            table.to_value(pulses[table.channel]) if pulses.get(table.channel) else joint.home
            for table, joint in zip(self.joints, self.model.joints, strict=True)
        ]
        return np.array(angles, dtype=np.float64)

    def _move_time_ms(
        self,
        pulses: dict[int, float],
        starts: dict[int, float],
        pad: float,
        seconds: float,
        exact: bool,
        speed: float,
    ) -> int:
        """Group time [ms] for ``seconds`` [s] of the shared rule (``group_ms``)."""
        timing = (seconds, pad, exact, speed)
        return group_ms(self.model, self.joints, pulses, starts, timing, self.bus.name)

    def forecast(
        self,
        q0: NDArray[np.float64],
        q1: NDArray[np.float64],
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """What ``move(q1)`` does from ``q0`` [rad] (``ServoForecaster``); nothing is sent."""
        return self.forecaster().forecast(q0, q1, duration=duration, speed=speed, motor_s=motor_s)

    def forecast_grip(self, before: float | None, width: float) -> float:
        """How long ``grip(width)`` [m] takes [s]: the settle time."""
        return self.forecaster().forecast_grip(before, width)

    def forecaster(self) -> ServoForecaster:
        """This arm's forecasts as a value (its tables, its controller, its settle time)."""
        longest = self.bus.max_time_ms / 1000.0
        return ServoForecaster(self.model, self.joints, longest, self.bus.name, self.settle_s)

    def _starts(self) -> tuple[dict[int, float], float]:
        """Where each servo starts from [µs], and how uncertain that is [µs]: the last
        pulses sent, or, while a move may still be running, the pulses read back, each
        refined to where the move sent should have it now if that agrees with the read."""
        now = self.clock.now()
        if now >= self._busy_until:
            return dict(self._commanded), 0.0
        read = {ch: p for ch, p in self.bus.read(self._channels()).items() if p > 0}
        resolution, pad = self.bus.readback.read_us, 0.0
        for ch, pulse in read.items():
            expected = self._expected(ch, now)
            if expected is not None and abs(expected - pulse) <= resolution:
                read[ch] = expected
            else:
                pad = resolution
        return read, pad

    def _expected(self, channel: int, now: float) -> float | None:
        """The pulse [µs] the last move sent should give on ``channel`` at ``now``."""
        if channel not in self._last:
            return None
        start, target, t0, seconds = self._last[channel]
        if seconds <= 0 or now >= t0 + seconds:
            return target
        return start + (target - start) * max(0.0, now - t0) / seconds

    def _send(
        self, pulses: dict[int, float], time_ms: int, wait: bool, values: dict[int, float]
    ) -> None:
        """One move of ``pulses`` [µs] (from ``values`` [rad, m]) in ``time_ms`` [ms]."""
        now = self.clock.now()
        for ch, target in pulses.items():
            start = self._expected(ch, now) or self._commanded.get(ch, target)
            self._last[ch] = (start, target, now, time_ms / 1000.0)
        self.bus.move(pulses, time_ms or None)
        self._commanded.update(pulses)
        self._asked.update({ch: (p, values[ch]) for ch, p in pulses.items()})
        self._busy_until = max(self._busy_until, now + time_ms / 1000.0)
        if wait:
            self.clock.sleep(self._busy_until - now)  # nothing to ask before it can be done
            self.bus.wait(WAIT_MARGIN_S)
            self.bus.check_reached(pulses)
            self.clock.sleep(self.settle_s)

    def move_servo(
        self, name: str, pulse_us: float, *, speed: float = 0.5, wait: bool = True
    ) -> None:
        """Send one servo a raw pulse [µs, 500..2500] at ``speed`` x its joint's maximum
        (calibration; the gripper moves at once). Other servos hold."""
        table = self._table(name)
        if not PULSE_MIN_US <= pulse_us <= PULSE_MAX_US:
            raise InputError(f"pulse {pulse_us} µs for {name} is outside 500..2500 µs")
        pulses = {table.channel: float(pulse_us)}
        starts, pad = self._starts()
        frac = check_speed(speed)
        time_ms = 0
        if table is not self.grip_table:
            time_ms = self._move_time_ms(pulses, starts, pad, 0.0, False, frac)
        self._send(pulses, time_ms, wait, {table.channel: table.to_value(pulse_us)})

    def _table(self, name: str) -> ServoCalibration:
        for table in self.tables:
            if table.name == name:
                return table
        raise InputError(f"no servo {name!r}; servos are {', '.join(t.name for t in self.tables)}")

    def read(self) -> NDArray[np.float64]:
        """Joint angles [rad], shape (dof,), from the pulses the controller reports.

        A servo whose last move from this driver has ended, and whose controller
        reports the pulse it was sent (``ReadBack.reports``: on the SSC-32 the reading's
        10 µs bin holds it), reads as the angle asked for. Any other (a move still
        running, a pulse someone else set, a servo this driver never moved) reads as
        the controller reports it; a servo with no pulse reads as its home angle.
        """
        now = self.clock.now()
        reported = self.bus.read([t.channel for t in self.joints])
        angles = [
            self._angle(table, reported[table.channel], now, joint.home)
            for table, joint in zip(self.joints, self.model.joints, strict=True)
        ]
        return np.array(angles, dtype=np.float64)

    def _angle(self, table: ServoCalibration, pulse: float, now: float, home: float) -> float:
        """The angle [rad] of ``pulse`` [µs] read on ``table``'s channel at ``now`` [s]:
        the one asked for if the controller reports the pulse sent for it once its move
        has ended; else the reading's (``home`` [rad] for no pulse)."""
        asked, last = self._asked.get(table.channel), self._last.get(table.channel)
        ended = last is None or now >= last[2] + last[3]
        if asked is not None and ended and self.bus.readback.reports(asked[0], pulse):
            return asked[1]
        return table.to_value(pulse) if pulse > 0 else home

    def grip(self, width: float) -> None:
        """Set the gripper opening ``width`` [m] through the gripper's table."""
        check_grip(self.model, width)
        self._alive()
        if self.grip_table is None:
            raise DeviceError(f"{self.model.name} has no gripper channel on the {self.bus.name}")
        channel = self.grip_table.channel
        self._send({channel: self.grip_table.to_pulse(width)}, 0, True, {channel: width})

    def relax(self) -> None:
        """Pulses off on every channel of the arm: the servos stop holding (002's end,
        where the uM-PWM1 disables every channel). Support the arm first. Until the next
        move, ``stop`` leaves them off and ``read`` reports home angles (no pulse)."""
        self._alive()
        self.bus.off(self._channels())
        self._commanded.clear()
        self._asked.clear()
        self._last.clear()
        self._busy_until = self.clock.now()

    def stop(self) -> None:
        """Hold every servo where it is now, by what was sent (no reply needed). Safe to
        call at any time, repeatedly."""
        if self._closed:
            return
        now = self.clock.now()
        at = {ch: self._expected(ch, now) or p for ch, p in self._commanded.items()}
        self.bus.stop(self._channels(), at)
        self._commanded.update(at)
        # a servo stopped short of its pulse holds where the board has it: no longer as asked
        self._asked = {ch: a for ch, a in self._asked.items() if at.get(ch) == a[0]}
        self._last = {ch: (p, p, now, 0.0) for ch, p in at.items()}
        self._busy_until = now

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
