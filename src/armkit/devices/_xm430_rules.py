"""What one XM430-W350 register accepts, as data: the control table's Range column.

ROBOTIS e-Manual XM430-W350, "Control Table of EEPROM Area" and "Control Table of
RAM Area" (the Range column) and the register descriptions (Goal Position (116):
a range per Operating Mode; Profile Acceleration (108) / Profile Velocity (112): a
range per profile kind, Drive Mode (10) bit 2). Each register carries at most one
rule (``Register.rule``); a rule answers with the Protocol 2.0 error number the
servo puts in its status packet ("DYNAMIXEL Protocol 2.0", Status Packet, Error):

- 4, Data Range Error: outside the register's own range;
- 6, Data Limit Error: beyond the limit another register sets (Goal Velocity and
  Velocity Limit (44), Goal Position and Min/Max Position Limit (52/48)).

A rule sees the control table through ``values(name)``: every register's value as
it will be once the write it checks is done (so a write of two registers at once is
checked against each other).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from ._dxl_packet import DATA_LIMIT_ERROR, DATA_RANGE_ERROR

Values = Callable[[str], int]  # register name -> its value (after the write being checked)


class Rule(Protocol):
    """A register's range: ``error`` is 0 when ``value`` may be written, else the status
    error number; ``text`` says the range as the manual does."""

    def error(self, value: int, values: Values) -> int:
        """0, or the Protocol 2.0 error number for writing ``value``."""
        ...

    def text(self) -> str:
        """The range in the manual's words (``"0 ~ 252"``)."""
        ...


@dataclass(frozen=True, slots=True)
class Span:
    """``low ~ high`` (inclusive): Data Range Error outside."""

    low: int
    high: int

    def error(self, value: int, values: Values) -> int:
        return 0 if self.low <= value <= self.high else DATA_RANGE_ERROR

    def text(self) -> str:
        return f"{self.low:,} ~ {self.high:,}"


@dataclass(frozen=True, slots=True)
class OneOf:
    """One of the listed values (Operating Mode: 0, 1, 3, 4, 5, 16): Data Range Error else."""

    allowed: tuple[int, ...]

    def error(self, value: int, values: Values) -> int:
        return 0 if value in self.allowed else DATA_RANGE_ERROR

    def text(self) -> str:
        return ", ".join(str(v) for v in self.allowed)


@dataclass(frozen=True, slots=True)
class Bits:
    """Only the bits of ``mask`` may be set (the others are "unused, always 0")."""

    mask: int

    def error(self, value: int, values: Values) -> int:
        return 0 if value >= 0 and not value & ~self.mask else DATA_RANGE_ERROR

    def text(self) -> str:
        return f"bits 0x{self.mask:02X}"


@dataclass(frozen=True, slots=True)
class WithinLimit:
    """``-limit ~ limit`` where ``limit`` is another register's value: Data Limit Error
    beyond (Goal PWM and PWM Limit (36), ...)."""

    limit: str

    def error(self, value: int, values: Values) -> int:
        return 0 if abs(value) <= values(self.limit) else DATA_LIMIT_ERROR

    def text(self) -> str:
        return f"-{self.limit} ~ {self.limit}"


@dataclass(frozen=True, slots=True)
class BetweenLimits:
    """``values(low) ~ values(high)``: Data Limit Error outside (Goal Position in Position
    Control Mode: Min Position Limit (52) ~ Max Position Limit (48))."""

    low: str
    high: str

    def error(self, value: int, values: Values) -> int:
        return 0 if values(self.low) <= value <= values(self.high) else DATA_LIMIT_ERROR

    def text(self) -> str:
        return f"{self.low} ~ {self.high}"


@dataclass(frozen=True, slots=True)
class LimitSpan:
    """``low ~ high`` as a limit: Data Limit Error outside (Goal Position in extended
    position mode: -1,048,575 ~ 1,048,575)."""

    low: int
    high: int

    def error(self, value: int, values: Values) -> int:
        return 0 if self.low <= value <= self.high else DATA_LIMIT_ERROR

    def text(self) -> str:
        return f"{self.low:,} ~ {self.high:,}"


@dataclass(frozen=True, slots=True)
class ByValue:
    """The rule of the present value of ``register`` (Goal Position: by Operating Mode);
    a value not listed takes ``other`` (None: anything goes)."""

    register: str
    cases: tuple[tuple[int, Rule], ...]
    other: Rule | None = None

    def error(self, value: int, values: Values) -> int:
        key = values(self.register)
        rule = next((rule for case, rule in self.cases if case == key), self.other)
        return 0 if rule is None else rule.error(value, values)

    def text(self) -> str:
        return "; ".join(f"{self.register} {key}: {rule.text()}" for key, rule in self.cases)


@dataclass(frozen=True, slots=True)
class ByBit:
    """``clear`` while bit ``bit`` of ``register`` is 0, ``set`` while it is 1 (the
    profile registers: Drive Mode (10) bit 2 picks velocity- or time-based units)."""

    register: str
    bit: int
    clear: Rule
    set: Rule

    def error(self, value: int, values: Values) -> int:
        rule = self.set if values(self.register) & self.bit else self.clear
        return rule.error(value, values)

    def text(self) -> str:
        return f"{self.clear.text()} (time-based: {self.set.text()})"
