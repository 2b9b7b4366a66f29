"""Hobby-servo controller channels: a pulse [µs] moving linearly in time, and a move log."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class VirtualServo:
    """One channel's output pulse [µs], moving linearly in time; 0 = never commanded."""

    start_us: float = 0.0
    target_us: float = 0.0
    t0: float = 0.0
    duration_s: float = 0.0

    def pulse(self, now: float) -> float:
        """The pulse being sent at time ``now`` [s, device clock]."""
        if self.duration_s <= 0.0 or now >= self.t0 + self.duration_s:
            return self.target_us
        frac = (now - self.t0) / self.duration_s
        return self.start_us + (self.target_us - self.start_us) * frac

    def moving(self, now: float) -> bool:
        """True while the pulse is still changing."""
        return self.duration_s > 0.0 and now < self.t0 + self.duration_s

    def go(self, target_us: float, duration_s: float, now: float) -> None:
        """Start a move from here to ``target_us`` lasting ``duration_s`` (a first move jumps)."""
        start = self.pulse(now)
        self.start_us, self.target_us, self.t0 = start, target_us, now
        self.duration_s = duration_s if start > 0.0 else 0.0

    def hold(self, now: float) -> None:
        """Stop where the servo is now."""
        self.go(self.pulse(now), 0.0, now)


@dataclass(frozen=True)
class MoveRecord:
    """One move as the controller executed it: start time [s, device clock], duration [s], and
    channel -> (start pulse, target pulse) [µs]."""

    t0: float
    duration_s: float
    servos: dict[int, tuple[float, float]] = field(default_factory=dict)


class PulseOutputs:
    """The channels of a hobby-servo controller as its servos see them (``_servo_body.Outputs``)."""

    servos: list[VirtualServo]
    busy_until: float = 0.0  # when the last move started ends [s, device clock]

    def go(self, channel: int, target_us: float, duration_s: float, now: float) -> VirtualServo:
        """Move ``channel`` to ``target_us`` [µs] over ``duration_s`` [s] from ``now``."""
        servo = self.servos[channel]
        servo.go(target_us, duration_s, now)
        self.busy_until = max(self.busy_until, servo.t0 + servo.duration_s)
        return servo

    def setpoint(self, channel: int, t: float) -> float | None:
        """The pulse [µs] on ``channel`` at ``t`` [s]; None while it sends no pulse."""
        pulse = self.servos[channel].pulse(t)
        return pulse if pulse > 0.0 else None

    def busy(self, t: float) -> bool:
        """True while a move may still be running."""
        return t < self.busy_until
