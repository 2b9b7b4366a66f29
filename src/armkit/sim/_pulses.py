"""Hobby-servo controller channels: a pulse [µs] moving linearly in time, and a move log."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True, slots=True)
class _Move:
    start_us: float = 0.0
    target_us: float = 0.0
    t0: float = 0.0
    duration_s: float = 0.0
    ramp_s: float = 0.0


class VirtualServo:
    """One channel's output pulse [µs], moving in time; 0 = never commanded (or off).

    Linear in time, or with ``ramp_s`` > 0 a trapezoid: the speed grows for ``ramp_s``
    [s], holds, and falls for the last ``ramp_s`` (``ramp_s`` <= half the duration).
    A move replaces the whole state at once, so a simulation step reading the pulse
    while the controller's thread starts a move sees the old move or the new one,
    never half of each.
    """

    def __init__(self) -> None:
        self._move = _Move()

    @property
    def start_us(self) -> float:
        """Where the move began [µs]."""
        return self._move.start_us

    @property
    def target_us(self) -> float:
        """Where it ends [µs]."""
        return self._move.target_us

    @property
    def t0(self) -> float:
        """When it began [s, device clock]."""
        return self._move.t0

    @property
    def duration_s(self) -> float:
        """How long it takes [s]."""
        return self._move.duration_s

    @property
    def ramp_s(self) -> float:
        """Its acceleration time at each end [s]."""
        return self._move.ramp_s

    def pulse(self, now: float) -> float:
        """The pulse being sent at time ``now`` [s, device clock]."""
        move = self._move
        if move.duration_s <= 0.0 or now >= move.t0 + move.duration_s:
            return move.target_us
        frac = _fraction(max(0.0, now - move.t0), move.duration_s, move.ramp_s)
        return move.start_us + (move.target_us - move.start_us) * frac

    def moving(self, now: float) -> bool:
        """True while the pulse is still changing."""
        move = self._move
        return move.duration_s > 0.0 and now < move.t0 + move.duration_s

    def go(self, target_us: float, duration_s: float, now: float, ramp_s: float = 0.0) -> None:
        """Start a move from here to ``target_us`` lasting ``duration_s`` with ``ramp_s`` [s]
        of acceleration at each end (a first move, or one from off, jumps)."""
        start = self.pulse(now)
        duration = duration_s if start > 0.0 else 0.0
        self._move = _Move(start, target_us, now, duration, min(ramp_s, duration / 2.0))

    def hold(self, now: float) -> None:
        """Stop where the servo is now."""
        self.go(self.pulse(now), 0.0, now)


def _fraction(t: float, total: float, ramp: float) -> float:
    """How far along (0..1) a move of ``total`` [s] with ``ramp`` [s] ramps is at ``t`` [s]."""
    if ramp <= 0.0:
        return t / total
    peak = 1.0 / (total - ramp)
    if t < ramp:
        return 0.5 * peak / ramp * t * t
    if t <= total - ramp:
        return peak * (t - 0.5 * ramp)
    return 1.0 - 0.5 * peak / ramp * (total - t) ** 2


def ramped_move(distance: float, speed: float, accel: float) -> tuple[float, float]:
    """(duration, ramp) [s] of a move of ``distance`` [µs] at most ``speed`` [µs/s] with
    ``accel`` [µs/s^2] (0 for either = unlimited)."""
    d = abs(distance)
    if d == 0.0 or (speed <= 0.0 and accel <= 0.0):
        return 0.0, 0.0
    if accel <= 0.0:
        return d / speed, 0.0
    if speed <= 0.0 or d < speed * speed / accel:
        ramp = (d / accel) ** 0.5
        return 2.0 * ramp, ramp
    return d / speed + speed / accel, speed / accel


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

    def go(
        self, channel: int, target_us: float, duration_s: float, now: float, ramp_s: float = 0.0
    ) -> VirtualServo:
        """Move ``channel`` to ``target_us`` [µs] over ``duration_s`` [s] from ``now`` (with
        ``ramp_s`` [s] of acceleration at each end)."""
        servo = self.servos[channel]
        servo.go(target_us, duration_s, now, ramp_s)
        self.busy_until = max(self.busy_until, servo.t0 + servo.duration_s)
        return servo

    def setpoint(self, channel: int, t: float) -> float | None:
        """The pulse [µs] on ``channel`` at ``t`` [s]; None while it sends no pulse."""
        pulse = self.servos[channel].pulse(t)
        return pulse if pulse > 0.0 else None

    def busy(self, t: float) -> bool:
        """True while a move may still be running."""
        return t < self.busy_until
