"""Simulated controllers on pseudo-terminals, for programs that open a serial port by path.

Each emulator is a simulated device (``ssc32.SimSSC32``, ``maestro.SimMaestro``,
``dynamixel.SimDynamixelBus``) in its own real-time world, served by the one
pty server (``_pty.PtyServer``); ``armkit emulate`` runs them from the command line::

    with SSC32Emulator() as emu:
        board = SSC32(emu.port, 9600)         # armkit's device class, pyserial, any program

``time_scale`` > 1 runs the device's time faster than real time (replies are not
delayed by it). Everything the device records (``received``, ``errors``,
``history``, ``servos``) is reachable here too; hold ``lock`` to read it while
the server runs.
"""

from __future__ import annotations

import threading
from collections.abc import Iterable
from typing import Any, Self

from ._outbox import ByteDevice
from ._pty import PtyServer
from ._pulses import MoveRecord, VirtualServo
from ._world import World
from .dynamixel import OPENMANIPULATOR_X_IDS, SimDynamixelBus
from .maestro import PROTOCOL_ERROR as PROTOCOL_ERROR
from .maestro import SimMaestro
from .ssc32 import SimSSC32
from .xm430 import XM430


class Emulator:
    """A simulated device in a real-time world (its own, or ``world``) on a pseudo-terminal
    (``port``)."""

    def __init__(
        self, device: ByteDevice, time_scale: float = 1.0, world: World | None = None
    ) -> None:
        self.world = world or World(realtime=True, pace=time_scale)
        self.device = device
        self.server = PtyServer(device, self.world)
        self.port = self.server.port

    @property
    def lock(self) -> threading.RLock:
        """Hold it to read the device's state while the server runs (the device's own
        lock: the world's thread never waits for it)."""
        return self.device.lock

    def reply_summary(self) -> str:
        """How fast it answered: the count, median and 99.9th percentile of the time from
        reading a request to writing its reply [ms] (the last ``_outbox.LOG_ROWS``)."""
        times = sorted(self.server.reply_s)
        if not times:
            return "answered no request"
        median, tail = times[len(times) // 2], times[min(len(times) - 1, int(0.999 * len(times)))]
        return (
            f"answered {len(times)} requests; from reading a request to writing its reply "
            f"{1e3 * median:.2f} ms median, {1e3 * tail:.2f} ms at the 99.9th percentile"
        )

    def now(self) -> float:
        """The device's time [s]."""
        return self.world.device_time()

    def close(self) -> None:
        """Stop serving. Safe to call twice."""
        self.server.close()
        self.world.close()

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class _PulseEmulator(Emulator):
    device: Any

    @property
    def received(self) -> list[bytes]:
        """Every complete command as received."""
        return list(self.device.received)

    @property
    def errors(self) -> list[str]:
        """What the device refused or could not hear."""
        misheard = ["bytes at the wrong baud rate"] if self.server.misheard else []
        return [*self.device.errors, *misheard]

    @property
    def history(self) -> list[MoveRecord]:
        """Every move executed."""
        return list(self.device.history)

    @property
    def servos(self) -> list[VirtualServo]:
        """The channels' pulse generators."""
        return list(self.device.servos)

    def pulse(self, channel: int) -> float:
        """The pulse ``channel`` sends now [µs] (0 = never commanded)."""
        with self.lock:
            return float(self.device.pulse(channel, self.world.device_time()))

    def inject(self, fault: str, count: int = 1, delay_s: float = 0.15) -> None:
        """Spoil the next ``count`` replies (``_outbox.FAULTS``)."""
        with self.lock:
            self.device.outbox.inject(fault, count, delay_s)


class SSC32Emulator(_PulseEmulator):
    """An SSC-32U at ``baudrate`` on a pseudo-terminal."""

    device: SimSSC32

    def __init__(
        self, baudrate: int = 9600, time_scale: float = 1.0, world: World | None = None
    ) -> None:
        super().__init__(SimSSC32(baudrate), time_scale, world)


class MaestroEmulator(_PulseEmulator):
    """A Mini Maestro 24 on a pseudo-terminal (any baud rate)."""

    device: SimMaestro

    def __init__(
        self, channels: int = 24, time_scale: float = 1.0, world: World | None = None
    ) -> None:
        super().__init__(SimMaestro(channels), time_scale, world)

    @property
    def speed(self) -> list[int]:
        """Speed limit per channel [25 µs/s units]."""
        return list(self.device.speed)

    @property
    def acceleration(self) -> list[int]:
        """Acceleration limit per channel (device units)."""
        return list(self.device.acceleration)


class DynamixelEmulator(Emulator):
    """XM430 servos (``ids``) on a Dynamixel bus on a pseudo-terminal."""

    device: SimDynamixelBus

    def __init__(self, ids: Iterable[int] = OPENMANIPULATOR_X_IDS, *, late_s: float = 0.08) -> None:
        world = World(realtime=True)
        device = SimDynamixelBus(ids, clock=world.device_time, late_s=late_s)
        self.world, self.device = world, device
        self.server = PtyServer(device, world)
        self.port = self.server.port

    @property
    def servos(self) -> dict[int, XM430]:
        """ID -> servo."""
        return self.device.servos

    @property
    def received(self) -> int:
        """Bytes the bus has read."""
        return self.device.received

    def inject(self, servo_id: int, fault: str, times: int = 1) -> None:
        """Make a servo misbehave (``dynamixel.FAULTS``)."""
        with self.lock:
            self.device.inject(servo_id, fault, times)

    def revive(self, servo_id: int) -> None:
        """Bring a vanished servo back."""
        with self.lock:
            self.device.revive(servo_id)
