"""Timed rotations (000's ArmCommunicator, done right): run one or several
motors together, each for its own time, then stop; the light keeps its state
across stops; any way out of a run sends stop, and a watchdog stops the arm
if the program hangs in the middle of one."""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

from ..._clock import Clock
from ...devices._owi_commands import encode
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
        complete: every motor ran its planned time and was stopped.
        watchdog_fired: the watchdog had to stop the arm.
    """

    plan: dict[str, tuple[int, float]]
    elapsed: dict[str, float] = field(default_factory=dict)
    complete: bool = False
    watchdog_fired: bool = False


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

    def execute(self, run: Run) -> None:
        """Start every motor of ``run.plan`` together and stop each after its time.

        Fills ``run`` as it goes, so a caller's ``finally`` can see how far it got
        when an exception (or Ctrl-C, or SIGTERM) cut it short; stop is sent then.
        """
        longest = max((s for _, s in run.plan.values()), default=0.0)
        t0 = self.clock.now()
        with Watchdog(self._quiet_stop, longest + self.watchdog_margin_s) as dog:
            try:
                self._staged(run, t0)
                run.complete = not dog.fired
            finally:
                run.watchdog_fired = dog.fired
                if not run.complete:
                    self._quiet_stop()
                    # motors still running ran until now, or until the watchdog stopped them
                    ran = dog.timeout_s if dog.fired else self.clock.now() - t0
                    for motor in run.plan:
                        run.elapsed.setdefault(motor, ran)

    def run_until(self, run: Run, wait: Callable[[], object], timeout_s: float) -> None:
        """Start the motors of ``run.plan`` (their times are ignored) and stop them when
        ``wait()`` returns, or when the watchdog's ``timeout_s`` [s] runs out."""
        t0 = self.clock.now()
        with Watchdog(self._quiet_stop, timeout_s) as dog:
            try:
                self.send({m: d for m, (d, _) in run.plan.items()})
                wait()
                run.complete = not dog.fired
            finally:
                self._quiet_stop()
                run.watchdog_fired = dog.fired
                ran = timeout_s if dog.fired else self.clock.now() - t0
                run.elapsed = dict.fromkeys(run.plan, ran)

    def _staged(self, run: Run, t0: float) -> None:
        active = {m: d for m, (d, _) in run.plan.items()}
        self.send(active)
        for motor, (_, seconds) in sorted(run.plan.items(), key=lambda item: item[1][1]):
            self.clock.sleep(t0 + seconds - self.clock.now())
            del active[motor]
            self.send(active)
            run.elapsed[motor] = self.clock.now() - t0

    def _quiet_stop(self) -> None:
        with contextlib.suppress(Exception):
            self.stop()
