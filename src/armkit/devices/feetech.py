"""STS3215 servos on one Feetech bus, through Feetech's official SDK (``scservo_sdk``).

The SDK (``pip install 'armkit[feetech]'``: feetech-servo-sdk) is imported when a bus
is opened, never when armkit is; its ``PacketHandler(0)`` speaks the STS series
(little-endian words). Values are in the memory table's units (``_sts3215``),
sign-magnitude registers decoded.

Retry policy (bounded by ``retries``), as the Dynamixel bus's:

* PING, READ and SYNC READ change nothing and are retried on a communication error;
* a unicast WRITE is never re-sent blind: after a lost status the register is read
  back and the write re-sent only if it did not land (every value written is absolute);
* SYNC WRITE, REG WRITE to the broadcast ID and ACTION have no status: sent once.

The STS status byte carries only the servo's Status bits (voltage, angle sensor,
overheating, overcurrent, overload: the SDK's ``ERRBIT_*``), no "range" or "access"
error: a value the servo does not take is simply not stored. So every setting armkit
writes is read back (``set``), and a value that did not land is a DeviceError.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Iterable, Iterator, Mapping, Sequence
from typing import Any

from .._clock import Clock, WallClock
from .._errors import DeviceError
from .._lock import Lock, exclusive
from . import _scs_packet as scs
from . import _sts3215 as sts
from ._dxl_sdk import GuardedPort

COMM_SUCCESS = 0
COMM_RX_CORRUPT = -7
_COMM_FAULTS = {
    -1: "port busy",
    -2: "transmit failed",
    -3: "receive failed",
    -6: "no reply (timeout)",
    -7: "corrupt reply (bad checksum or truncated)",
    -9: "not available",
}


def import_sdk() -> Any:
    """Feetech's ``scservo_sdk`` (DeviceError saying how to install it)."""
    try:
        import scservo_sdk
    except ModuleNotFoundError:
        raise DeviceError(
            "the Feetech bus needs feetech-servo-sdk: pip install 'armkit[feetech]'"
        ) from None
    return scservo_sdk


def installed_sdk() -> Any:
    """Feetech's ``scservo_sdk`` where it is installed, else armkit's own client with its
    interface (``_scs_protocol``: the same bytes)."""
    if importlib.util.find_spec("scservo_sdk") is not None:
        return import_sdk()
    from . import _scs_protocol

    return _scs_protocol


def comm_fault(result: int) -> str:
    """Text for an SDK communication result code."""
    return _COMM_FAULTS.get(result, f"communication result {result}")


class FeetechBus:
    """A serial port with STS3215 servos on it.

    Args:
        port: device path (``/dev/ttyACM0``, an emulator's pty path).
        baudrate: bits/s, one the servos run at (the SO-101 runs at 1,000,000).
        retries: extra attempts after a communication error (0 = try once).
        clock: time for waiting (real time by default).

    Raises:
        DeviceError: the SDK is missing, the port is taken by another process, cannot
            be opened, or the baud rate is not one the SDK accepts.
    """

    def __init__(
        self, port: str, baudrate: int = 1_000_000, *, retries: int = 3, clock: Clock | None = None
    ) -> None:
        sdk = import_sdk()
        lock = exclusive(port, f"the Feetech bus on {port}")
        try:
            self._attach(sdk.PortHandler(port), retries, clock, sdk)
            self._lock: Lock | None = lock
            self._open(port, baudrate)
        except BaseException:
            lock.release()
            raise

    @classmethod
    def on_port(
        cls, port_handler: Any, *, retries: int = 3, clock: Clock | None = None, sdk: Any = None
    ) -> FeetechBus:
        """A bus over an already-open SDK-style port handler (a simulated line), through
        ``sdk`` (default: ``installed_sdk()``)."""
        bus = cls.__new__(cls)
        bus._attach(port_handler, retries, clock, sdk or installed_sdk())
        return bus

    def _attach(self, port: Any, retries: int, clock: Clock | None, sdk: Any) -> None:
        self._sdk = sdk
        self._port = GuardedPort(port, "Feetech bus")
        self._ph = self._sdk.PacketHandler(0)  # 0: STS/SMS, little-endian words
        self.clock = clock or WallClock()
        self.retries, self.settle_s = retries, 0.1
        self._lock = None

    def _open(self, port: str, baudrate: int) -> None:
        try:
            opened = self._port.setBaudRate(baudrate)
        except Exception as exc:  # pyserial: SerialException/OSError subclasses
            raise DeviceError(
                f"cannot open Feetech port {port!r}: {exc.__cause__ or exc}; check the adapter is plugged in,"
                " the path exists and you may use it (dialout group)"
            ) from None
        if not opened:
            rates = ", ".join(str(r) for r in sts.BAUD_RATES.values())
            raise DeviceError(f"baud rate {baudrate} is not one of the STS3215's: {rates}")

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
                self._lock = None

    def __enter__(self) -> FeetechBus:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- the retry policy -----------------------------------------------------------
    def _attempts(self) -> Iterator[int]:
        for attempt in range(self.retries + 1):
            if attempt:
                self.clock.sleep(self.settle_s)
                self._port.clearPort()
            yield attempt

    def _retry(self, servo_id: int, what: str, call: Any) -> tuple[Any, int]:
        """Run ``call() -> (value, result, error)`` until it communicates: (value, error)."""
        result = COMM_SUCCESS
        for _ in self._attempts():
            value, result, error = call()
            if result == COMM_SUCCESS:
                return value, error
        raise DeviceError(
            f"servo {servo_id}: {what} failed after {self.retries + 1} tries: {comm_fault(result)};"
            " check its power, cable, ID and the baud rate"
        )

    @staticmethod
    def _check(servo_id: int, what: str, error: int) -> None:
        if error:
            raise DeviceError(
                f"servo {servo_id}: {sts.describe_status(error)} (status 0x{error:02x})"
                f" during {what}; let it cool or remove the load, then power it again"
            )

    # -- unicast instructions -----------------------------------------------------
    def ping(self, servo_id: int) -> int:
        """The model number of ``servo_id`` (PING, then READ of Model Number: the SDK's)."""
        model, _ = self._retry(servo_id, "PING", lambda: self._ph.ping(self._port, servo_id))
        return int(model)

    def scan(self, ids: Iterable[int] = range(254)) -> dict[int, int]:
        """{ID: model number} of the servos that answer one PING each (no retries)."""
        found = {}
        for sid in ids:
            model, result, _ = self._ph.ping(self._port, sid)
            if result == COMM_SUCCESS:
                found[sid] = int(model)
        return found

    def check_models(self, ids: Iterable[int], model: int = sts.MODEL_NUMBER) -> None:
        """Ping every ID; DeviceError naming the first that is missing or another model."""
        for sid in ids:
            found = self.ping(sid)
            if found != model:
                raise DeviceError(
                    f"servo {sid} is model {found}, expected {model} (STS3215);"
                    " check the IDs in the arm's [drivers.feetech] table"
                )

    def read(self, servo_id: int, name: str) -> int:
        """Register ``name`` of ``servo_id`` (READ, retried)."""
        reg = sts.register(name)

        def call() -> tuple[Any, int, int]:
            data, result, error = self._ph.readTxRx(self._port, servo_id, reg.address, reg.size)
            bad = result == COMM_SUCCESS and len(data) != reg.size
            return data, COMM_RX_CORRUPT if bad else result, error

        data, error = self._retry(servo_id, f"READ {name}", call)
        self._check(servo_id, f"READ {name}", error)
        return reg.decode(bytes(data))

    def write(self, servo_id: int, name: str, value: int) -> None:
        """WRITE an absolute ``value``; a lost status is resolved by reading back."""
        reg = sts.register(name)
        data = list(reg.encode(value))
        result = COMM_SUCCESS
        for _ in self._attempts():
            result, error = self._ph.writeTxRx(self._port, servo_id, reg.address, reg.size, data)
            if result == COMM_SUCCESS:
                self._check(servo_id, f"WRITE {name}={value}", error)
                return
            if self.read(servo_id, name) == value:
                return
        raise DeviceError(
            f"servo {servo_id}: WRITE {name}={value} failed after {self.retries + 1} tries:"
            f" {comm_fault(result)}"
        )

    def set(self, servo_id: int, name: str, value: int) -> None:
        """WRITE then READ back: DeviceError if the servo did not take ``value``."""
        self.write(servo_id, name, value)
        found = self.read(servo_id, name)
        if found != value:
            reg = sts.register(name)
            raise DeviceError(
                f"servo {servo_id}: {name} reads {found} after writing {value}; the servo does"
                f" not take it (its range is {reg.low}..{reg.high if reg.high is not None else reg.largest})"
            )

    def set_eeprom(self, servo_id: int, name: str, value: int) -> None:
        """An EEPROM register kept through power cycles: Lock 0, write, Lock 1 (if it differs)."""
        if self.read(servo_id, name) == value:
            return
        self.write(servo_id, "Lock", 0)
        try:
            self.set(servo_id, name, value)
        finally:
            self.write(servo_id, "Lock", 1)

    def reg_write(self, servo_id: int, name: str, value: int) -> None:
        """REG WRITE: ``value`` kept by the servo until ACTION (status checked)."""
        reg = sts.register(name)
        result, error = self._ph.regWriteTxRx(
            self._port, servo_id, reg.address, reg.size, list(reg.encode(value))
        )
        if result != COMM_SUCCESS:
            raise DeviceError(f"servo {servo_id}: REG WRITE {name} failed: {comm_fault(result)}")
        self._check(servo_id, f"REG WRITE {name}", error)

    def action(self, servo_id: int = scs.BROADCAST_ID) -> None:
        """ACTION: every servo (or ``servo_id``) does its registered write now."""
        result = self._ph.action(self._port, servo_id)
        if result != COMM_SUCCESS:
            raise DeviceError(f"ACTION to {servo_id} failed: {comm_fault(result)}")

    def reset(self, servo_id: int) -> None:
        """RESET (instruction 6): the memory table back to its factory values. The SDK has
        no function for it; the packet goes through its ``txRxPacket``."""
        packet = [0xFF, 0xFF, servo_id, 2, scs.Inst.RESET, 0]
        _, result, error = self._ph.txRxPacket(self._port, packet)
        if result != COMM_SUCCESS:
            raise DeviceError(f"servo {servo_id}: RESET failed: {comm_fault(result)}")
        self._check(servo_id, "RESET", error)

    # -- group instructions -------------------------------------------------------
    def sync_write(self, name: str, values: Mapping[int, int]) -> None:
        """{ID: value} of one register in one SYNC WRITE, sent exactly once."""
        reg = sts.register(name)
        self.write_block(reg.address, reg.size, {s: reg.encode(v) for s, v in values.items()})

    def write_block(self, address: int, size: int, data: Mapping[int, bytes]) -> None:
        """One SYNC WRITE of ``size`` bytes at ``address``: {ID: bytes}."""
        group = self._sdk.GroupSyncWrite(self._port, self._ph, address, size)
        for sid, raw in data.items():
            group.addParam(sid, list(raw))
        result = group.txPacket()
        if result != COMM_SUCCESS:
            raise DeviceError(f"SYNC WRITE to {list(data)} failed: {comm_fault(result)}")

    def sync_read(self, name: str, ids: Sequence[int]) -> dict[int, int]:
        """{ID: value} of one register from one SYNC READ (retried as a whole)."""
        reg = sts.register(name)
        raw = self.read_block(reg.address, reg.size, ids)
        return {sid: reg.decode(data) for sid, data in raw.items()}

    def read_block(self, address: int, size: int, ids: Sequence[int]) -> dict[int, bytes]:
        """{ID: ``size`` bytes at ``address``} from one SYNC READ (each reply read with the
        SDK's ``readRx``, which keeps the status byte the group drops)."""
        failed, result = -1, COMM_SUCCESS
        for _ in self._attempts():
            group = self._sdk.GroupSyncRead(self._port, self._ph, address, size)
            for sid in ids:
                group.addParam(sid)
            failed, result, replies = self._sync_replies(group, ids, size)
            if result == COMM_SUCCESS:
                for sid, (_, error) in replies.items():
                    self._check(sid, f"SYNC READ at {address}", error)
                return {sid: data for sid, (data, _) in replies.items()}
        raise DeviceError(
            f"servo {failed}: SYNC READ failed after {self.retries + 1} tries:"
            f" {comm_fault(result)}; check its power, cable, ID and the baud rate"
        )

    def _sync_replies(
        self, group: Any, ids: Sequence[int], size: int
    ) -> tuple[int, int, dict[int, tuple[bytes, int]]]:
        result = group.txPacket()
        replies: dict[int, tuple[bytes, int]] = {}
        for sid in ids:
            if result == COMM_SUCCESS:
                data, result, error = self._ph.readRx(self._port, sid, size)
                if result == COMM_SUCCESS and len(data) != size:
                    result = COMM_RX_CORRUPT
            if result != COMM_SUCCESS:
                self._port.is_using = False
                return sid, result, replies
            replies[sid] = (bytes(data), error)
        return -1, result, replies

    # -- settings -------------------------------------------------------------------
    def set_torque(self, ids: Iterable[int], on: bool) -> None:
        """Torque Enable on every servo in ``ids``."""
        for sid in ids:
            self.write(sid, "Torque Enable", int(on))
