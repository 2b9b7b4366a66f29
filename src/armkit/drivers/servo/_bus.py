"""The few things the servo arm driver asks of a servo controller, for SSC-32 and Maestro.

Pulses are µs (floats; each controller rounds to its own resolution), times ms.
How finely each controller takes and reports pulses is data (``ReadBack``), and one
rule (``ReadBack.reports``) says whether a reading is the pulse that was sent.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol

from ..._errors import DeviceError
from ...devices.maestro import Maestro
from ...devices.ssc32 import SSC32, TIME_MAX_MS


@dataclass(frozen=True)
class ReadBack:
    """How finely a controller takes pulses and reports them back.

    Attributes:
        command_us: step of the pulses it is sent [µs] (a commanded pulse goes out
            rounded to the nearest step).
        read_us: step of the pulses it reports [µs], each reading the nearest step to
            the pulse it sends (the SSC-32's ``QP``: one byte = pulse / 10 µs, user
            guide; the simulated board rounds to the nearest byte).
    """

    command_us: float
    read_us: float

    def on_wire(self, pulse_us: float) -> float:
        """The pulse [µs] the controller sends for a command of ``pulse_us`` [µs]."""
        return round(pulse_us / self.command_us) * self.command_us

    def reports(self, sent_us: float, read_us: float) -> bool:
        """Whether a reading of ``read_us`` [µs] is what the controller reports while it
        sends the command ``sent_us`` [µs]: the pulse on the wire lies in the reading's
        bin, within half a read step either way (10 µs bin on the SSC-32)."""
        return abs(self.on_wire(sent_us) - read_us) <= self.read_us / 2.0


SSC32_READBACK = ReadBack(command_us=1.0, read_us=10.0)  # #<ch>P<µs>; QP: pulse / 10 µs
MAESTRO_READBACK = ReadBack(command_us=0.25, read_us=0.25)  # quarter-µs both ways


class ServoBus(Protocol):
    """A servo controller as the driver sees it.

    Attributes:
        name: driver name (``"ssc32"``).  readback: how finely it takes and reports pulses.
        max_time_ms: longest single move [ms].
    """

    name: str
    readback: ReadBack
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
    readback = SSC32_READBACK
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
    readback = MAESTRO_READBACK
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
            if got and not self.readback.reports(want, got):
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
