"""A serial port with bounded request/reply exchanges, shared by the SSC-32 and the Maestro.

pyserial opens a port given by path (``serial`` extra, imported only then). A
port may also be given already open: any object with pyserial's ``read``,
``read_until``, ``write``, ``reset_input_buffer``, ``close``, ``timeout`` and
``baudrate`` (a simulated line: ``armkit.sim``'s wire, itself a pyserial port
where pyserial is installed). The bytes are the same either way.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol, TypeVar

from .._clock import Clock, WallClock
from .._errors import DeviceError, ReplyError

CR = b"\r"
T = TypeVar("T")


class SerialPort(Protocol):
    """What armkit uses of a serial port (pyserial's names and meaning)."""

    timeout: float | None
    baudrate: int

    def write(self, data: bytes) -> int | None:
        """Send ``data``."""
        ...

    def read(self, size: int = 1) -> bytes:
        """Up to ``size`` bytes within ``timeout`` [s]."""
        ...

    def read_until(self, expected: bytes = b"\n", size: int | None = None) -> bytes:
        """Bytes up to ``expected`` within ``timeout`` [s]."""
        ...

    def reset_input_buffer(self) -> None:
        """Drop what has arrived."""
        ...

    def close(self) -> None:
        """Release the port."""
        ...


def _complete(reply: bytes, size: int | None) -> bytes:
    if not reply:
        raise ReplyError("no reply")
    if size is not None and len(reply) != size:
        raise ReplyError(f"reply {reply!r} has {len(reply)} bytes, expected {size}")
    return reply


def import_serial() -> Any:
    try:
        import serial
    except ModuleNotFoundError:
        raise DeviceError(
            "pyserial is not installed; install armkit's serial extra: pip install 'armkit[serial]'"
        ) from None
    return serial


class SerialLink:
    """A serial port with bounded request/reply exchanges (used by SSC-32 and Maestro).

    A reply that is missing, late or malformed is drained away and the request is
    sent again, at most ``retries`` more times; only queries are ever repeated.
    """

    def __init__(
        self,
        name: str,
        port: str | SerialPort,
        baudrate: int,
        timeout_s: float,
        retries: int,
        clock: Clock | None = None,
    ) -> None:
        self.name, self.baudrate = name, baudrate
        self.timeout_s, self.retries = timeout_s, retries
        self.clock = clock or WallClock()
        if isinstance(port, str):
            self.port = port
            self._serial = _open(name, port, baudrate, timeout_s)
        else:
            self.port = str(getattr(port, "port", None) or f"a {name} line")
            port.baudrate, port.timeout = baudrate, timeout_s
            self._serial = port

    def write(self, data: bytes) -> None:
        """Send ``data`` as it is."""
        try:
            self._serial.write(data)
        except Exception as exc:
            raise DeviceError(f"{self.name} on {self.port}: write failed: {exc}") from None

    def exchange(
        self, request: bytes, size: int | None, parse: Callable[[bytes], T], what: str
    ) -> T:
        """Send ``request``, read ``size`` bytes (None: up to CR), return ``parse(reply)``;
        DeviceError naming ``what`` was asked and the last fault after 1 + retries tries."""
        problem = ""
        for _ in range(1 + self.retries):
            self._serial.reset_input_buffer()
            self.write(request)
            try:
                return parse(_complete(self._read(size), size))
            except ValueError as exc:
                problem = str(exc)
                self._drain()
        raise DeviceError(
            f"{self.name} on {self.port}: {what}: {problem} after {1 + self.retries} "
            f"tries; check power, cable and baud rate ({self.baudrate})"
        )

    def _read(self, size: int | None) -> bytes:
        return bytes(self._serial.read_until(CR) if size is None else self._serial.read(size))

    def _drain(self) -> None:
        self.clock.sleep(self.timeout_s)
        self._serial.reset_input_buffer()

    def close(self) -> None:
        """Release the port. Safe to call twice."""
        self._serial.close()


def _open(name: str, port: str, baudrate: int, timeout_s: float) -> Any:
    serial = import_serial()
    try:
        return serial.Serial(port, baudrate, timeout=timeout_s, write_timeout=1.0)
    except (serial.SerialException, OSError) as exc:
        raise DeviceError(f"cannot open {name} on {port}: {exc}; check the port name") from None
