"""The XM430-W350 control table (ROBOTIS e-manual, Protocol 2.0 firmware) as data.

Each register is (address, size [bytes], signed, access, factory default).
Addresses below 64 are EEPROM: writable only while Torque Enable is 0.
Units: position [tick] (4096 per turn), velocity [0.229 rev/min], acceleration
[214.577 rev/min^2], current [2.69 mA], voltage [0.1 V], temperature [deg C];
in time-based profile mode (Drive Mode bit 2) both profile registers are [ms].
"""

from __future__ import annotations

from dataclasses import dataclass

from .._errors import InputError
from ._xm430_rules import (
    BetweenLimits,
    Bits,
    ByBit,
    ByValue,
    LimitSpan,
    OneOf,
    Rule,
    Span,
    WithinLimit,
)

MODEL_NUMBER = 1020  # XM430-W350
FIRMWARE_VERSION = 46  # what a simulated servo reports (e-Manual features by version below)
TICKS_PER_TURN = 4096
VELOCITY_UNIT_RPM = 0.229
ACCELERATION_UNIT_RPM2 = 214.577
CURRENT_UNIT_MA = 2.69

# Operating Mode values
MODE_CURRENT = 0
MODE_VELOCITY = 1
MODE_POSITION = 3
MODE_EXTENDED_POSITION = 4
MODE_CURRENT_POSITION = 5
MODE_PWM = 16

OPERATING_MODES = (
    MODE_CURRENT, MODE_VELOCITY, MODE_POSITION, MODE_EXTENDED_POSITION, MODE_CURRENT_POSITION,
    MODE_PWM,
)  # fmt: skip

# Drive Mode (10) bits (e-Manual, "Drive Mode (10)"); the others are unused, always 0
DRIVE_MODE_REVERSE = 0x01  # Normal/Reverse Mode
DRIVE_MODE_TIME_BASED = 0x04  # Profile Configuration: profiles in ms, not velocity units
DRIVE_MODE_TORQUE_ON_BY_GOAL = 0x08  # Torque On by Goal Update (firmware 45 and later)
DRIVE_MODE_BITS = DRIVE_MODE_REVERSE | DRIVE_MODE_TIME_BASED | DRIVE_MODE_TORQUE_ON_BY_GOAL

# Hardware Error Status bits
HARDWARE_ERRORS: dict[int, str] = {
    0x01: "input voltage error",
    0x04: "overheating",
    0x08: "motor encoder error",
    0x10: "electrical shock",
    0x20: "overload",
}


@dataclass(frozen=True, slots=True)
class Register:
    """One control-table entry.

    Attributes:
        name: the e-manual's name (``"Goal Position"``).
        address: first byte. size: 1, 2 or 4 bytes, little-endian.
        signed: two's complement. writable: False for read-only registers.
        default: factory value.  rule: the values a WRITE may put here (the manual's Range
            column, ``_xm430_rules``); None: any value the size holds.
    """

    name: str
    address: int
    size: int
    signed: bool = False
    writable: bool = True
    default: int = 0
    rule: Rule | None = None  # the Range column: what a WRITE may put here

    def __hash__(self) -> int:
        """Its address: registers key the values of every simulated write (the generated
        hash of every field, the rule's too, was a tenth of a simulated packet's cost)."""
        return hash(self.address)

    @property
    def eeprom(self) -> bool:
        """True for EEPROM registers (address < 64): locked while torque is on."""
        return self.address < 64

    def encode(self, value: int) -> bytes:
        """``value`` as wire bytes; ValueError when it does not fit the register."""
        try:
            return int(value).to_bytes(self.size, "little", signed=self.signed)
        except OverflowError:
            kind = "signed" if self.signed else "unsigned"
            raise InputError(
                f"{self.name}: {value} does not fit a {kind} {self.size}-byte register"
            ) from None

    def decode(self, raw: bytes | bytearray) -> int:
        """Wire bytes (exactly ``size``) -> value, signed if the register is."""
        return int.from_bytes(raw, "little", signed=self.signed)

    def from_unsigned(self, value: int) -> int:
        """Fix an SDK value that came back unsigned (sync reads are) to this register's sign."""
        return self.decode(int(value).to_bytes(self.size, "little", signed=False))


_GAIN = Span(0, 16_383)
_PROFILE = ByBit("Drive Mode", DRIVE_MODE_TIME_BASED, Span(0, 32_767), Span(0, 32_737))
EXTENDED_LIMIT = 1_048_575
_GOAL_POSITION = ByValue(
    "Operating Mode",
    (
        (MODE_POSITION, BetweenLimits("Min Position Limit", "Max Position Limit")),
        (MODE_EXTENDED_POSITION, LimitSpan(-EXTENDED_LIMIT, EXTENDED_LIMIT)),
        (MODE_CURRENT_POSITION, LimitSpan(-EXTENDED_LIMIT, EXTENDED_LIMIT)),
    ),
)

# (name, address, size, ...): the e-Manual's table; ``rule`` is its Range column
_REGISTERS: tuple[Register, ...] = (
    Register("Model Number", 0, 2, writable=False, default=MODEL_NUMBER),
    Register("Model Information", 2, 4, writable=False),
    Register("Firmware Version", 6, 1, writable=False, default=FIRMWARE_VERSION),
    Register("ID", 7, 1, default=1, rule=Span(0, 252)),
    Register("Baud Rate", 8, 1, default=1, rule=Span(0, 7)),
    Register("Return Delay Time", 9, 1, default=250, rule=Span(0, 254)),
    Register("Drive Mode", 10, 1, rule=Bits(DRIVE_MODE_BITS)),
    Register("Operating Mode", 11, 1, default=MODE_POSITION, rule=OneOf(OPERATING_MODES)),
    Register("Secondary ID", 12, 1, default=255, rule=Span(0, 255)),
    Register("Protocol Type", 13, 1, default=2, rule=Span(1, 2)),
    Register("Homing Offset", 20, 4, signed=True, rule=Span(-1_044_479, 1_044_479)),
    Register("Moving Threshold", 24, 4, default=10, rule=Span(0, 1_023)),
    Register("Temperature Limit", 31, 1, default=80, rule=Span(0, 100)),
    Register("Max Voltage Limit", 32, 2, default=160, rule=Span(95, 160)),
    Register("Min Voltage Limit", 34, 2, default=95, rule=Span(95, 160)),
    Register("PWM Limit", 36, 2, default=885, rule=Span(0, 885)),
    Register("Current Limit", 38, 2, default=1193, rule=Span(0, 1_193)),
    Register("Velocity Limit", 44, 4, default=200, rule=Span(0, 1_023)),
    Register("Max Position Limit", 48, 4, default=4095, rule=Span(0, 4_095)),
    Register("Min Position Limit", 52, 4, default=0, rule=Span(0, 4_095)),
    Register("Startup Configuration", 60, 1, rule=Bits(0x03)),
    Register("Shutdown", 63, 1, default=52),
    Register("Torque Enable", 64, 1, rule=Span(0, 1)),
    Register("LED", 65, 1, rule=Span(0, 1)),
    Register("Status Return Level", 68, 1, default=2, rule=Span(0, 2)),
    Register("Registered Instruction", 69, 1, writable=False),
    Register("Hardware Error Status", 70, 1, writable=False),
    Register("Velocity I Gain", 76, 2, default=1920, rule=_GAIN),
    Register("Velocity P Gain", 78, 2, default=100, rule=_GAIN),
    Register("Position D Gain", 80, 2, rule=_GAIN),
    Register("Position I Gain", 82, 2, rule=_GAIN),
    Register("Position P Gain", 84, 2, default=800, rule=_GAIN),
    Register("Feedforward 2nd Gain", 88, 2, rule=_GAIN),
    Register("Feedforward 1st Gain", 90, 2, rule=_GAIN),
    Register("Bus Watchdog", 98, 1, signed=True, rule=Span(0, 127)),  # -1: tripped
    Register("Goal PWM", 100, 2, signed=True, default=885, rule=WithinLimit("PWM Limit")),
    Register("Goal Current", 102, 2, signed=True, default=1193, rule=WithinLimit("Current Limit")),
    Register("Goal Velocity", 104, 4, signed=True, rule=WithinLimit("Velocity Limit")),
    Register("Profile Acceleration", 108, 4, rule=_PROFILE),
    Register("Profile Velocity", 112, 4, rule=_PROFILE),
    Register("Goal Position", 116, 4, signed=True, default=2048, rule=_GOAL_POSITION),
    Register("Realtime Tick", 120, 2, writable=False),
    Register("Moving", 122, 1, writable=False),
    Register("Moving Status", 123, 1, writable=False),
    Register("Present PWM", 124, 2, signed=True, writable=False),
    Register("Present Current", 126, 2, signed=True, writable=False),
    Register("Present Velocity", 128, 4, signed=True, writable=False),
    Register("Present Position", 132, 4, signed=True, writable=False, default=2048),
    Register("Velocity Trajectory", 136, 4, signed=True, writable=False),
    Register("Position Trajectory", 140, 4, signed=True, writable=False),
    Register("Present Input Voltage", 144, 2, writable=False, default=120),
    Register("Present Temperature", 146, 1, writable=False, default=30),
    Register("Backup Ready", 147, 1, writable=False),
)

# Indirect Address n (2 bytes) names the control-table byte that Indirect Data n
# (1 byte) reads and writes; factory default: the address of Indirect Data n itself.
# Two blocks of 28 (e-Manual XM430-W350, "Indirect Address, Indirect Data").
INDIRECT_BLOCKS = ((1, 168, 224), (29, 578, 634))  # (first n, first address, first data)
INDIRECT_COUNT = 28  # entries per block
CONTROL_TABLE_SIZE = 662  # bytes: Indirect Data 56 ends at address 661


def _indirect() -> tuple[Register, ...]:
    regs: list[Register] = []
    for first, address, data in INDIRECT_BLOCKS:
        for k in range(INDIRECT_COUNT):
            regs.append(
                Register(
                    f"Indirect Address {first + k}",
                    address + 2 * k,
                    2,
                    default=data + k,
                    rule=Span(64, CONTROL_TABLE_SIZE - 1),  # the RAM area only
                )
            )
            regs.append(Register(f"Indirect Data {first + k}", data + k, 1, rule=Span(0, 255)))
    return tuple(sorted(regs, key=lambda r: r.address))


XM430_W350: dict[str, Register] = {reg.name: reg for reg in (*_REGISTERS, *_indirect())}


# Baud Rate register value -> bit/s (e-Manual XM430-W350, "Baud Rate (8)").
BAUD_RATES: dict[int, int] = {
    0: 9_600,
    1: 57_600,
    2: 115_200,
    3: 1_000_000,
    4: 2_000_000,
    5: 3_000_000,
    6: 4_000_000,
    7: 4_500_000,
}

# Status Return Level (68): which instructions get a status packet.
STATUS_LEVEL_PING, STATUS_LEVEL_READ, STATUS_LEVEL_ALL = 0, 1, 2

# Moving Status (123) bits (e-Manual, "Moving Status (123)").
IN_POSITION = 0x01
PROFILE_ONGOING = 0x02
FOLLOWING_ERROR = 0x08
PROFILE_SHIFT = 4  # bits 5..4: 0 step, 1 rectangular, 2 triangular, 3 trapezoidal
PROFILE_STEP, PROFILE_RECTANGULAR, PROFILE_TRIANGULAR, PROFILE_TRAPEZOIDAL = 0, 1, 2, 3


def baud_value(rate: int) -> int:
    """The Baud Rate register value of ``rate`` [bit/s]; InputError for an unknown rate."""
    for value, bps in BAUD_RATES.items():
        if bps == rate:
            return value
    raise InputError(
        f"baud rate {rate} is not an XM430 rate; use one of {list(BAUD_RATES.values())}"
    )


def register(name: str) -> Register:
    """The register called ``name``; InputError lists the known names."""
    try:
        return XM430_W350[name]
    except KeyError:
        raise InputError(
            f"no XM430-W350 register {name!r}; known: {', '.join(XM430_W350)}"
        ) from None


def describe_hardware_error(bits: int) -> str:
    """Hardware Error Status bits -> ``"overload, overheating"``."""
    names = [text for bit, text in HARDWARE_ERRORS.items() if bits & bit]
    return ", ".join(names) if names else f"unknown hardware error 0x{bits:02x}"
