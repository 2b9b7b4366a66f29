"""Reading a distance sensor on an arm through the interface a real one uses: the
SSC-32's analog input (``VA``..``VD``) on an arm driven by an SSC-32 (the Lynx6),
else a serial ADC board (``AdcBoard``) -- in the simulator, its emulator on a pty."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

from .._errors import DeviceError
from ._adc import AdcBoard, AdcEmulator
from ._gp2d120 import distance


@dataclass(frozen=True)
class DistanceSensor:
    """A GP2D120 as read by the host.

    Attributes:
        read: the output now [V].  via: how it is read (``"SSC-32 VA"``, ``"ADC board
            on /dev/pts/3 input 0"``).
    """

    read: Callable[[], float]
    via: str

    def distance(self) -> float | None:
        """The distance now [m], or None outside 4..30 cm."""
        return distance(self.read())


@contextlib.contextmanager
def open_sensor(
    ssc32: Any,
    channel: int = 0,
    port: str | None = None,
    *,
    inputs: Any = None,
    lock: Any = None,
    arm: str = "arm",
) -> Iterator[DistanceSensor]:
    """The sensor on analog input ``channel``: the SSC-32's (``ssc32``: the arm's
    controller's analog inputs, ``Arm.analog_inputs()``, or None), else the ADC board at
    ``port`` (None on a simulated arm: an emulated board on a pty reading its analog
    ``inputs``, ``SimArm.analog``, under ``lock``); ``arm`` names the arm in errors.

    Raises:
        DeviceError: no SSC-32 and no port on real hardware, or the board is silent.
    """
    if ssc32 is not None:
        yield DistanceSensor(
            lambda: float(ssc32.read_analog(channel)), f"SSC-32 V{'ABCD'[channel]}"
        )
        return
    emulator = None
    if port is None:
        if inputs is None:
            raise DeviceError(
                f"the {arm} has no SSC-32: give the port of the ADC board "
                "the distance sensor is wired to"
            )
        emulator = AdcEmulator(inputs, lock)
        port = emulator.port
    board = AdcBoard(port)
    try:
        yield DistanceSensor(lambda: board.read(channel), f"ADC board on {port} input {channel}")
    finally:
        board.close()
        if emulator is not None:
            emulator.close()
