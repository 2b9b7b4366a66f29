"""Timed rotations (000's ArmCommunicator, done right): run one or several
motors together, each for its own time, then stop; the light keeps its state
across stops; any way out of a run sends stop, and a watchdog stops the arm
if the program hangs in the middle of one."""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

from ..._clock import Clock
from ...devices import owi_encode as encode
from ._safety import Watchdog


class Device(Protocol):
    """What the motors need from the USB device (see ``armkit.devices.owi535``)."""

    def send(self, data: bytes) -> None:
        """Send one 3-byte command."""
        ...

    def close(self) -> None:
        """Release the device."""
        ...


@dataclass
class Run:
    """One timed run: the plan and what actually happened.

    Attributes:
        plan: {motor: (direction +1/-1, seconds)}.
        elapsed: {motor: powered time [s]} measured on the clock (filled as motors stop).
        started: the command that starts the motors was sent.
        complete: every motor ran its planned time and was stopped.
        watchdog_fired: the watchdog had to stop the arm.
    """

    plan: dict[str, tuple[int, float]]
    elapsed: dict[str, float] = field(default_factory=dict)
    started: bool = False
    complete: bool = False
    watchdog_fired: bool = False


Pause = Callable[[float], None]


class Motors:
    """The arm's motors and light behind a device and a clock."""

    def __init__(
        self,
        device: Device,
        clock: Clock,
        *,
        base_reversed: bool = False,
        watchdog_margin_s: float = 1.0,
    ) -> None:
        self.device, self.clock = device, clock
        self.base_reversed = base_reversed
        self.watchdog_margin_s = watchdog_margin_s
        self.light = False
        self._lock = threading.Lock()  # the watchdog's stop and the mover's commands
        self._halted_at: float | None = None  # clock time the watchdog stopped the run

    def send(self, motion: dict[str, int]) -> None:
        """Run the motors in ``motion`` ({motor: +1/-1}) and stop all others, light unchanged."""
        self.device.send(encode(motion, self.light, self.base_reversed))

    def stop(self) -> None:
        """Stop every motor (the light stays as it is)."""
        self.send({})

    def set_light(self, on: bool) -> None:
        """Switch the light; motors stop."""
        self.light = on
        self.stop()

    def execute(self, run: Run, pause: Pause | None = None) -> None:
        """Start every motor of ``run.plan`` together and stop each after its time,
        waiting through ``pause(seconds)`` (default: the clock's sleep).

        Fills ``run`` as it goes, so a caller's ``finally`` can see how far it got
        when an exception (or Ctrl-C, or SIGTERM) cut it short; stop is sent then.
        Once the watchdog has stopped the arm no motor starts again, and every motor
        still running counts as stopped at the watchdog's stop.
        """
        longest = max((s for _, s in run.plan.values()), default=0.0)
        t0 = self.clock.now()
        self._halted_at = None
        with Watchdog(self._watchdog_stop, longest + self.watchdog_margin_s) as dog:
            try:
                self._staged(run, t0, pause or self.clock.sleep)
                run.complete = not dog.fired
            finally:
                run.watchdog_fired = dog.fired
                if not run.complete:
                    self._quiet_stop()
                    ran = self._stopped_at(dog) - t0
                    for motor in run.plan:
                        run.elapsed.setdefault(motor, ran)

    def run_until(
        self,
        run: Run,
        wait: Callable[[], object],
        timeout_s: float,
        hold: Callable[[Callable[[], object]], None] | None = None,
    ) -> None:
        """Start the motors of ``run.plan`` (their times are ignored) and stop them when
        ``wait()`` returns, or when the watchdog's ``timeout_s`` [s] runs out. ``hold``
        runs the wait (a SignalGate's ``wait``, so a signal may cut it short)."""
        t0 = self.clock.now()
        self._halted_at = None
        with Watchdog(self._watchdog_stop, timeout_s) as dog:
            try:
                run.started = self._send_unless_halted({m: d for m, (d, _) in run.plan.items()})
                if run.started:
                    (hold or (lambda block: block()))(wait)
                run.complete = run.started and not dog.fired
            finally:
                self._quiet_stop()
                run.watchdog_fired = dog.fired
                ran = self._stopped_at(dog) - t0 if run.started else 0.0
                run.elapsed = dict.fromkeys(run.plan, ran)

    def _staged(self, run: Run, t0: float, pause: Pause) -> None:
        active = {m: d for m, (d, _) in run.plan.items()}
        run.started = self._send_unless_halted(active)
        if not run.started:
            run.elapsed = dict.fromkeys(run.plan, 0.0)
            return
        for motor, (_, seconds) in sorted(run.plan.items(), key=lambda item: item[1][1]):
            pause(t0 + seconds - self.clock.now())
            del active[motor]
            if not self._send_unless_halted(active):
                return
            run.elapsed[motor] = self.clock.now() - t0

    def _send_unless_halted(self, motion: dict[str, int]) -> bool:
        """Send ``motion`` unless the watchdog has stopped this run (then False)."""
        with self._lock:
            if self._halted_at is not None:
                return False
            self.send(motion)
            return True

    def _watchdog_stop(self) -> None:
        """From the watchdog's thread: stop now, and let no motor start again this run."""
        got = self._lock.acquire(timeout=0.5)  # never wait long for a mover stuck in a send
        try:
            self._quiet_stop()
            self._halted_at = self.clock.now()
        finally:
            if got:
                self._lock.release()

    def _stopped_at(self, dog: Watchdog) -> float:
        """Clock time every motor still running stopped: the watchdog's stop, else now."""
        halted = self._halted_at
        return halted if dog.fired and halted is not None else self.clock.now()

    def _quiet_stop(self) -> None:
        with contextlib.suppress(Exception):
            self.stop()
