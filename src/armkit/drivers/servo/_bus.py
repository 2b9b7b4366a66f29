"""The few things the servo arm driver asks of a servo controller, for SSC-32 and Maestro.

Pulses are µs (floats; each controller rounds to its own resolution), times ms.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Protocol

from ..._errors import DeviceError
from ...devices.maestro import Maestro
from ...devices.ssc32 import SSC32, TIME_MAX_MS


class ServoBus(Protocol):
    """A servo controller as the driver sees it.

    Attributes:
        name: driver name (``"ssc32"``).  read_resolution_us: step of read-back pulses [µs].
        max_time_ms: longest single move [ms].
    """

    name: str
    read_resolution_us: float
    max_time_ms: int

    def move(self, pulses: dict[int, float], time_ms: int | None) -> None:
        """One coordinated move: channel -> pulse [µs], all arriving together after ``time_ms``."""
        ...

    def wait(self, timeout_s: float) -> None:
        """Block until the move is done; DeviceError after ``timeout_s`` [s]."""
        ...

    def read(self, channels: list[int]) -> dict[int, float]:
        """Channel -> pulse being sent [µs]; 0 = never commanded."""
        ...

    def stop(self, channels: list[int], at: Mapping[int, float]) -> None:
        """Hold each servo where it is now (``at``: the host's estimate [µs], for a
        controller that cannot stop by itself: no reply is needed)."""
        ...

    def check_reached(self, pulses: Mapping[int, float]) -> None:
        """After a move has ended: DeviceError if a channel is not sending its pulse [µs]."""
        ...

    def off(self, channels: list[int]) -> None:
        """Stop sending pulses on ``channels``: the servos stop holding."""
        ...

    def close(self) -> None:
        """Release the port."""
        ...


class SSC32Bus:
    """``ServoBus`` over an ``SSC32``: one group-move line per move, one ``QP`` line per read."""

    name = "ssc32"
    read_resolution_us = 10.0
    max_time_ms = TIME_MAX_MS

    def __init__(self, device: SSC32) -> None:
        self.device = device

    def move(self, pulses: dict[int, float], time_ms: int | None) -> None:
        self.device.group_move({ch: round(p) for ch, p in pulses.items()}, time_ms)

    def wait(self, timeout_s: float) -> None:
        self.device.wait(timeout_s)

    def read(self, channels: list[int]) -> dict[int, float]:
        return {ch: float(p) for ch, p in self.device.query_pulses(channels).items()}

    def stop(self, channels: list[int], at: Mapping[int, float]) -> None:
        self.device.stop(channels)

    def check_reached(self, pulses: Mapping[int, float]) -> None:
        """Nothing to check: the SSC-32 sends every pulse of 500..2500 µs it is given."""

    def off(self, channels: list[int]) -> None:
        self.device.pulses_off(channels)

    def close(self) -> None:
        self.device.close()


class MaestroBus:
    """``ServoBus`` over a ``Maestro``: per-servo speed limits make a group move."""

    name = "maestro"
    read_resolution_us = 0.25
    max_time_ms = 10 * TIME_MAX_MS

    def __init__(self, device: Maestro) -> None:
        self.device = device

    def move(self, pulses: dict[int, float], time_ms: int | None) -> None:
        self.device.group_move(pulses, time_ms)

    def wait(self, timeout_s: float) -> None:
        self.device.wait(timeout_s)

    def read(self, channels: list[int]) -> dict[int, float]:
        return {ch: self.device.get_position(ch) for ch in channels}

    def stop(self, channels: list[int], at: Mapping[int, float]) -> None:
        self.device.stop(channels, at)

    def check_reached(self, pulses: Mapping[int, float]) -> None:
        """Read every channel back: a Maestro clamps a target to the channel's range
        (factory 992..2000 µs) without a word, so a short pulse means a narrow range."""
        for ch, want in pulses.items():
            got = self.device.get_position(ch)
            if got and abs(got - want) > self.read_resolution_us:
                raise DeviceError(
                    f"Maestro on {self.device.port}: channel {ch} sends {got:.2f} µs, not the "
                    f"{want:.2f} µs asked: its range in the Maestro clamps it (factory "
                    f"992..2000 µs); widen channel {ch}'s Min/Max in the Maestro Control "
                    "Center (Channel Settings) to cover the servo's table, then Apply Settings"
                )

    def off(self, channels: list[int]) -> None:
        self.device.pulses_off(channels)

    def close(self) -> None:
        self.device.close()
