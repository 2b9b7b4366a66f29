"""A pyserial port whose other end is a simulated device (imported only where pyserial is).

``SimSerial`` is a ``serial.SerialBase`` subclass, built as pyserial's own
``loop://`` and ``socket://`` ports are: pyserial's ``read_until``, settings and
checks run on top of the simulated line (``_wire.Wire``).
"""

from __future__ import annotations

from typing import Any

import serial


class SimSerial(serial.SerialBase):  # type: ignore[misc]
    """A pyserial port on ``wire`` (a ``_wire.Wire``; opened at once, closing it closes
    the wire)."""

    def __init__(self, wire: Any) -> None:
        self._wire = wire
        super().__init__(port=None, baudrate=wire.baudrate, timeout=wire.timeout)
        self.port = wire.port
        self.is_open = True

    def open(self) -> None:
        self.is_open = True

    def close(self) -> None:
        self.is_open = False
        self._wire.close()

    def _reconfigure_port(self, *args: object) -> None:
        self._wire.baudrate, self._wire.timeout = self._baudrate, self._timeout

    @property
    def in_waiting(self) -> int:
        return int(self._wire.in_waiting)

    def read(self, size: int = 1) -> bytes:
        self._reconfigure_port()
        return bytes(self._wire.read(size))

    def write(self, data: bytes) -> int:
        self._reconfigure_port()
        return int(self._wire.write(data))

    def reset_input_buffer(self) -> None:
        self._wire.reset_input_buffer()

    def reset_output_buffer(self) -> None:
        self._wire.reset_output_buffer()

    def flush(self) -> None:
        self._wire.flush()

    def _update_break_state(self) -> None:
        pass

    def _update_rts_state(self) -> None:
        pass

    def _update_dtr_state(self) -> None:
        pass

    @property
    def cts(self) -> bool:
        return True

    @property
    def dsr(self) -> bool:
        return True

    @property
    def ri(self) -> bool:
        return False

    @property
    def cd(self) -> bool:
        return True
