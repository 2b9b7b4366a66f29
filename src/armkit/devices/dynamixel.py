"""XM430 servos on one Protocol 2.0 bus, through the ROBOTIS dynamixel-sdk.

The SDK is imported when a bus is opened, never when armkit is. Values are in
the control table's units (``_xm430``); signed registers come back signed.

Retry policy (bounded by ``retries``):

* Reads (PING, READ, SYNC_READ) change nothing, so they are retried freely on a
  communication error (no reply, corrupt reply).
* A unicast WRITE is never re-sent blind: when its status is lost the register
  is read back first, and the write is re-sent only if it did not land. Every
  value armkit writes is absolute (a goal, a mode, a profile), never relative.
* SYNC_WRITE has no status packet, so there is nothing to retry on: it is sent
  exactly once per call. Sending the same absolute goal again would not move a
  servo twice (it re-plans toward the same point), but armkit does not do it.
* REBOOT is not re-sent: after a lost status the servo is pinged and its
  Hardware Error Status checked instead.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping, Sequence
from contextlib import AbstractContextManager
from typing import Any

from .._clock import Clock, WallClock
from .._errors import DeviceError
from .._lock import Lock, exclusive
from . import _xm430 as xm
from ._dxl_packet import ALERT_BIT, describe_error
from ._dxl_sdk import (
    COMM_SUCCESS,
    GuardedPort,
    Protocol,
    comm_fault,
    import_sdk,
    installed_protocol,
    sdk_protocol,
    sized,
)
from ._dxl_settings import ServoSettings
from ._dxl_sync import ServoState as ServoState
from ._dxl_sync import SyncInstructions


class DynamixelBus:
    """A serial port with XM430 servos on it (Protocol 2.0).

    The bus does the unicast instructions (PING, READ, WRITE, REBOOT) and the retry
    policy itself; its group instructions are a ``SyncInstructions`` and its servo
    settings a ``ServoSettings``, both made of the bus's port and functions.

    Args:
        port: device path (``/dev/ttyUSB0``, an emulator's pty path).
        baudrate: bits/s, one the SDK accepts (the OpenManipulator-X runs at 1,000,000).
        retries: extra attempts after a communication error (0 = try once); between
            attempts the bus waits ``settle_s`` [s] and drops whatever arrived late.
        clock: time for waiting (real time by default).

    Raises:
        DeviceError: the SDK is missing, the port cannot be opened, or the baud
            rate is not supported.
    """

    def __init__(
        self,
        port: str,
        baudrate: int = 1_000_000,
        *,
        retries: int = 3,
        clock: Clock | None = None,
    ) -> None:
        sdk = import_sdk()
        self._attach(sdk_protocol(), sdk.PortHandler(port), retries, clock)
        lock = exclusive(port, f"the Dynamixel bus on {port}")
        self._lock: Lock | None = lock
        try:
            self._open(port, baudrate)
        except BaseException:
            lock.release()
            raise

    @classmethod
    def on_port(
        cls,
        port_handler: Any,
        *,
        retries: int = 3,
        clock: Clock | None = None,
        protocol: Protocol | None = None,
    ) -> DynamixelBus:
        """A bus over an already-open port handler (a simulated line, a custom port):
        the SDK's client where it is installed, else armkit's own (``protocol`` chooses)."""
        bus = cls.__new__(cls)
        bus._attach(protocol or installed_protocol(), port_handler, retries, clock)
        return bus

    @classmethod
    def on_handlers(cls, port_handler: Any, packet_handler: Any, retries: int = 3) -> DynamixelBus:
        """A bus over already-open SDK handlers (benchmarks, custom ports)."""
        bus = cls.__new__(cls)
        bus._attach(sdk_protocol(), port_handler, retries, None, packet_handler)
        return bus

    def _attach(
        self,
        proto: Protocol,
        port: Any,
        retries: int,
        clock: Clock | None,
        packet_handler: Any = None,
    ) -> None:
        self.protocol, self._port = proto, GuardedPort(port)
        self._ph = proto.packet_handler() if packet_handler is None else packet_handler
        self.clock = clock or WallClock()
        self.retries = retries
        self.settle_s = 0.1  # after a failed exchange: wait for late replies, then drop them
        self._lock = None  # held while a port opened by path is open
        self._sync = SyncInstructions(proto, self._port, self._ph, self._attempts, self._check)
        self._settings = ServoSettings(self.read, self.write, self._sync.write_block)

    def _open(self, port: str, baudrate: int) -> None:
        try:
            opened = self._port.setBaudRate(baudrate)
        except Exception as exc:  # pyserial raises SerialException/OSError subclasses
            raise DeviceError(
                f"cannot open Dynamixel port {port!r}: {exc}; check the adapter is plugged in,"
                " the path exists and you may use it (dialout group)"
            ) from None
        if not opened:
            raise DeviceError(
                f"baud rate {baudrate} is not supported by the dynamixel-sdk; use one of"
                " 57600, 115200, 1000000, 2000000, 3000000, 4000000"
            )

    @property
    def is_open(self) -> bool:
        """True while the port is open."""
        return bool(getattr(self._port, "is_open", False))

    def close(self) -> None:
        """Close the port (and release its lock). Safe to call twice."""
        try:
            if self.is_open:
                self._port.closePort()
        finally:
            if self._lock is not None:
                self._lock.release()

    def __enter__(self) -> DynamixelBus:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _retry(self, servo_id: int, what: str, call: Any) -> tuple[Any, int]:
        """Run ``call() -> (value, result, error)`` until it communicates; (value, error)."""
        result = COMM_SUCCESS
        for _ in self._attempts():
            value, result, error = call()
            if result == COMM_SUCCESS:
                return value, error
        raise DeviceError(
            f"servo {servo_id}: {what} failed after {self.retries + 1} tries: {comm_fault(result)};"
            " check its power, cable, ID and the baud rate"
        )

    def _attempts(self) -> Iterator[int]:
        """Attempt numbers 0..retries, settling the line between attempts."""
        for attempt in range(self.retries + 1):
            if attempt:
                self._settle()
            yield attempt

    def _settle(self) -> None:
        self.clock.sleep(self.settle_s)
        self._port.clearPort()

    def _check(self, servo_id: int, what: str, error: int) -> None:
        """Raise for a status error byte: refused instruction or hardware alert."""
        if error & ~ALERT_BIT:
            raise DeviceError(f"servo {servo_id}: {what} refused: {describe_error(error)}")
        if error & ALERT_BIT:
            bits = self.hardware_error(servo_id)
            raise DeviceError(
                f"servo {servo_id}: hardware error: {xm.describe_hardware_error(bits)}"
                f" (Hardware Error Status 0x{bits:02x}) during {what}; its torque is off:"
                f" remove the cause, then reboot it"
            )

    def ping(self, servo_id: int) -> int:
        """The model number of ``servo_id`` (retried on communication errors)."""
        model, _ = self._retry(servo_id, "PING", lambda: self._ph.ping(self._port, servo_id))
        return int(model)

    def scan(self, ids: Iterable[int] = range(253)) -> dict[int, int]:
        """{ID: model number} of the servos that answer one PING each (no retries)."""
        found = {}
        for sid in ids:
            model, result, _ = self._ph.ping(self._port, sid)
            if result == COMM_SUCCESS:
                found[sid] = int(model)
        return found

    def check_models(self, ids: Iterable[int], model: int = xm.MODEL_NUMBER) -> None:
        """Ping every ID; DeviceError naming the first that is missing or another model."""
        for sid in ids:
            found = self.ping(sid)
            if found != model:
                raise DeviceError(
                    f"servo {sid} is model {found}, expected {model} (XM430-W350);"
                    " check the IDs in the arm's [drivers.dynamixel] table"
                )

    def read(self, servo_id: int, name: str, *, alert_ok: bool = False) -> int:
        """Register ``name`` of ``servo_id``, signed if the register is."""
        reg = xm.register(name)
        port, address, size = self._port, reg.address, reg.size
        data, error = self._retry(
            servo_id,
            f"READ {name}",
            lambda: sized(self._ph.readTxRx(port, servo_id, address, size), size),
        )
        if not alert_ok:
            self._check(servo_id, f"READ {name}", error)
        return reg.decode(bytes(data))

    def write(self, servo_id: int, name: str, value: int) -> None:
        """Write an absolute ``value``; a lost status is resolved by reading back (see top)."""
        reg = xm.register(name)
        data = list(reg.encode(value))
        for _ in self._attempts():
            result, error = self._ph.writeTxRx(self._port, servo_id, reg.address, reg.size, data)
            if result == COMM_SUCCESS:
                self._check(servo_id, f"WRITE {name}={value}", error)
                return
            self._settle()
            if self.read(servo_id, name, alert_ok=True) == value:
                return
        raise DeviceError(
            f"servo {servo_id}: WRITE {name}={value} failed after {self.retries + 1} tries:"
            f" {comm_fault(result)}"
        )

    def hardware_error(self, servo_id: int) -> int:
        """Hardware Error Status bits of ``servo_id`` (0 = healthy)."""
        return self.read(servo_id, "Hardware Error Status", alert_ok=True)

    def reboot(self, servo_id: int) -> None:
        """REBOOT ``servo_id`` (clears a hardware error; torque comes back off)."""
        result, _ = self._ph.reboot(self._port, servo_id)
        bits = self.hardware_error(servo_id)  # pings the servo back, retried
        if bits:
            raise DeviceError(
                f"servo {servo_id}: still in hardware error after REBOOT"
                f" ({xm.describe_hardware_error(bits)}; reboot status: {comm_fault(result)})"
            )

    # -- group instructions (``_dxl_sync``) --------------------------------
    def sync_write(self, name: str, values: Mapping[int, int]) -> None:
        """{ID: value} of one register in one SYNC_WRITE, sent exactly once."""
        self._sync.sync_write(name, values)

    def sync_read(self, name: str, ids: Sequence[int]) -> dict[int, int]:
        """{ID: value} of one register, signed if the register is (retried as a whole)."""
        return self._sync.sync_read(name, ids)

    def read_states(self, ids: Sequence[int]) -> dict[int, ServoState]:
        """Present current, velocity and position of ``ids`` in one SYNC_READ (126..135)."""
        return self._sync.read_states(ids)

    # -- servo settings (``_dxl_settings``) --------------------------------
    def set_torque(self, ids: Iterable[int], on: bool) -> None:
        """Torque Enable on every servo in ``ids``."""
        self._settings.set_torque(ids, on)

    def torque(self, ids: Sequence[int], on: bool) -> AbstractContextManager[None]:
        """Set torque for the block, then put every servo back as it was."""
        return self._settings.torque(ids, on)

    def set_operating_mode(self, servo_id: int, mode: int) -> None:
        """Operating Mode (3 position, 4 extended, 5 current-based position, ...)."""
        self._settings.set_operating_mode(servo_id, mode)

    def set_eeprom(self, servo_id: int, name: str, value: int) -> None:
        """Write an EEPROM register if it differs, torque off around it, then restored."""
        self._settings.set_eeprom(servo_id, name, value)

    def set_time_based(self, ids: Iterable[int], on: bool) -> None:
        """Drive Mode bit 2: profiles in ms (True) or in velocity/acceleration units."""
        self._settings.set_time_based(ids, on)

    def set_profiles(self, profiles: Mapping[int, tuple[int, int]]) -> None:
        """{ID: (acceleration, velocity)} in one SYNC_WRITE of Profile Acceleration..Velocity."""
        self._settings.set_profiles(profiles)
