"""The Feetech STS3215 control table (the SMS/STS series memory table) as data.

Sources: Feetech's SMS/STS memory table (the ``SMS_STS_*`` addresses of Feetech's
SCServo libraries, ``sms_sts.py`` of the ``scservo_sdk`` and ``SMS_STS.h``) and
LeRobot's ``STS_SMS_SERIES_CONTROL_TABLE`` (huggingface/lerobot,
``src/lerobot/motors/feetech/tables.py``), which agree on every address used here.

Each register is (address, size [bytes], access, factory default, range). Addresses
below 40 are EEPROM: a write there takes effect at once and is kept through a power
cycle only while Lock (55) is 0 (Feetech's examples: ``unLockEprom`` "open the EEPROM
save function", ``LockEprom`` "close" it). Values are little-endian (the SDK's
``PacketHandler(0)``); signed registers are *sign-magnitude*, their sign in one bit
(``sign_bit``: Homing Offset bit 11, the positions and velocities bit 15, Present Load
bit 10), as LeRobot's ``STS_SMS_SERIES_ENCODINGS_TABLE`` and the SDK's
``SCS_TOHOST``/``SCS_TOSCS`` say.

Units: position [step] (4096 per turn), velocity [step/s], acceleration
[100 step/s^2] (0 = no ramp), torque limit [0.1 %], voltage [0.1 V], temperature
[deg C], current [6.5 mA], return delay [2 us].
"""

from __future__ import annotations

from dataclasses import dataclass

from .._errors import InputError

MODEL_NUMBER = 777  # STS3215 (LeRobot's MODEL_NUMBER_TABLE "sts3215": 777)
FIRMWARE = (3, 10)  # (major, minor) a simulated servo reports
STEPS_PER_TURN = 4096
CENTER_STEP = 2048
MAX_SPEED_STEPS = 3073  # no-load speed at 7.4 V: 0.222 s / 60 deg (Feetech STS3215) [step/s]
ACCELERATION_UNIT = 100  # [step/s^2] per unit of Acceleration (41)
EEPROM_END = 40  # addresses below are EEPROM
TABLE_SIZE = 71  # bytes: Present Current (69/2) ends at 70

# Baud Rate (6) index -> bit/s (the SDK's SMS_STS_1M .. SMS_STS_38400)
BAUD_RATES: dict[int, int] = {
    0: 1_000_000, 1: 500_000, 2: 250_000, 3: 128_000, 4: 115_200, 5: 76_800, 6: 57_600,
    7: 38_400,
}  # fmt: skip

# Operating Mode (33): 0 position (servo), 1 constant speed (wheel), 2 PWM, 3 step
MODE_POSITION = 0

# Status (65) bits = the status packet's error byte (the SDK's ERRBIT_*)
STATUS_BITS: dict[int, str] = {
    0x01: "input voltage error",
    0x02: "angle sensor error",
    0x04: "overheating",
    0x08: "overcurrent",
    0x20: "overload",
}


@dataclass(frozen=True, slots=True)
class Register:
    """One memory-table entry.

    Attributes:
        name: the table's name (``"Goal Position"``).
        address: first byte.  size: 1 or 2 bytes, little-endian.
        writable: False for read-only registers.  default: factory value.
        low, high: the values a write may put there (as decoded); outside, the servo
            does not take it.  sign_bit: the sign bit of a sign-magnitude register
            (None: unsigned).
    """

    name: str
    address: int
    size: int
    writable: bool = True
    default: int = 0
    low: int = 0
    high: int | None = None  # None: anything the size holds
    sign_bit: int | None = None

    @property
    def eeprom(self) -> bool:
        """True for EEPROM registers (kept through a power cycle while Lock is 0)."""
        return self.address < EEPROM_END

    @property
    def largest(self) -> int:
        """The largest value the register's bits hold."""
        bits = 8 * self.size if self.sign_bit is None else self.sign_bit
        return (1 << bits) - 1

    def encode(self, value: int) -> bytes:
        """``value`` as wire bytes (sign-magnitude where signed); InputError if it does
        not fit."""
        magnitude = abs(int(value))
        if magnitude > self.largest or (value < 0 and self.sign_bit is None):
            raise InputError(
                f"{self.name}: {value} does not fit (at most {self.largest} in magnitude"
                f"{', unsigned' if self.sign_bit is None else ''})"
            )
        raw = magnitude | ((1 << self.sign_bit) if value < 0 and self.sign_bit else 0)
        return raw.to_bytes(self.size, "little")

    def decode(self, raw: bytes | bytearray) -> int:
        """Wire bytes (exactly ``size``) -> value."""
        return self.from_raw(int.from_bytes(raw, "little"))

    def from_raw(self, raw: int) -> int:
        """The value of the unsigned word ``raw`` (what the SDK's sync read returns)."""
        if self.sign_bit is None:
            return raw
        magnitude = raw & ((1 << self.sign_bit) - 1)
        return -magnitude if raw >> self.sign_bit & 1 else magnitude

    def accepts(self, value: int) -> bool:
        """Whether a write of ``value`` is taken (inside the register's range)."""
        high = self.largest if self.high is None else self.high
        low = -self.largest if self.sign_bit is not None and self.low == 0 else self.low
        return self.writable and low <= value <= high


def _ro(
    name: str, address: int, size: int, default: int = 0, sign_bit: int | None = None
) -> Register:
    return Register(name, address, size, False, default, sign_bit=sign_bit)


_REGISTERS: tuple[Register, ...] = (
    _ro("Firmware Major Version", 0, 1, FIRMWARE[0]),
    _ro("Firmware Minor Version", 1, 1, FIRMWARE[1]),
    _ro("Model Number", 3, 2, MODEL_NUMBER),
    Register("ID", 5, 1, default=1, high=253),
    Register("Baud Rate", 6, 1, default=0, high=7),
    Register("Return Delay Time", 7, 1, default=0, high=254),
    Register("Response Status Level", 8, 1, default=1, high=1),
    Register("Min Position Limit", 9, 2, default=0, high=4094),
    Register("Max Position Limit", 11, 2, default=4095, low=1, high=4095),
    Register("Max Temperature Limit", 13, 1, default=70, high=100),
    Register("Max Voltage Limit", 14, 1, default=80, high=254),
    Register("Min Voltage Limit", 15, 1, default=40, high=254),
    Register("Max Torque Limit", 16, 2, default=1000, high=1000),
    Register("Phase", 18, 1, default=12),
    Register("Unloading Condition", 19, 1, default=44),
    Register("LED Alarm Condition", 20, 1, default=47),
    Register("P Coefficient", 21, 1, default=32),
    Register("D Coefficient", 22, 1, default=32),
    Register("I Coefficient", 23, 1, default=0),
    Register("Minimum Startup Force", 24, 2, default=16, high=1000),
    Register("CW Dead Zone", 26, 1, default=1, high=32),
    Register("CCW Dead Zone", 27, 1, default=1, high=32),
    Register("Protection Current", 28, 2, default=500, high=511),
    Register("Angular Resolution", 30, 1, default=1, low=1, high=3),
    Register("Homing Offset", 31, 2, default=0, sign_bit=11),
    Register("Operating Mode", 33, 1, default=MODE_POSITION, high=3),
    Register("Protective Torque", 34, 1, default=20, high=100),
    Register("Protection Time", 35, 1, default=200, high=254),
    Register("Overload Torque", 36, 1, default=80, high=100),
    Register("Velocity closed loop P", 37, 1, default=10, high=100),
    Register("Over Current Protection Time", 38, 1, default=200, high=254),
    Register("Velocity closed loop I", 39, 1, default=200, high=254),
    Register("Torque Enable", 40, 1, default=0, high=1),
    Register("Acceleration", 41, 1, default=0, high=254),
    Register("Goal Position", 42, 2, default=0, sign_bit=15),
    Register("Goal Time", 44, 2, default=0),
    Register("Goal Velocity", 46, 2, default=0, sign_bit=15),
    Register("Torque Limit", 48, 2, default=1000, high=1000),
    Register("Lock", 55, 1, default=1, high=1),
    _ro("Present Position", 56, 2, sign_bit=15),
    _ro("Present Velocity", 58, 2, sign_bit=15),
    _ro("Present Load", 60, 2, sign_bit=10),
    _ro("Present Voltage", 62, 1, 74),
    _ro("Present Temperature", 63, 1, 25),
    _ro("Status", 65, 1),
    _ro("Moving", 66, 1),
    _ro("Present Current", 69, 2),
)

STS3215: dict[str, Register] = {reg.name: reg for reg in _REGISTERS}
BY_ADDRESS: dict[int, Register] = {reg.address: reg for reg in _REGISTERS}


def register(name: str) -> Register:
    """The register called ``name`` (InputError listing them if there is none)."""
    try:
        return STS3215[name]
    except KeyError:
        raise InputError(f"no STS3215 register {name!r}; registers: {', '.join(STS3215)}") from None


def baud_index(rate: int) -> int:
    """Baud Rate (6) value for ``rate`` [bit/s] (InputError if the servo has no such rate)."""
    for index, bps in BAUD_RATES.items():
        if bps == rate:
            return index
    rates = ", ".join(str(r) for r in BAUD_RATES.values())
    raise InputError(f"an STS3215 runs at {rate} bit/s never; its rates are {rates}")


def describe_status(bits: int) -> str:
    """Status (65) bits in words."""
    found = [text for bit, text in STATUS_BITS.items() if bits & bit]
    return ", ".join(found) if found else f"status 0x{bits:02x}"
