"""Whether a simulated XM430 takes a WRITE, and the Protocol 2.0 error number if not.

ROBOTIS e-Manual, "DYNAMIXEL Protocol 2.0", Status Packet, Error, in the order the
servo finds them:

- 7, Access Error: a read-only or undefined address, or the EEPROM area while torque is
  on ("XM430-W350", Control Table, CAUTION) or through the Secondary ID ("Secondary
  ID (12)": the EEPROM area cannot be modified with it);
- 5, Data Length Error: a write that covers only part of a register (2 bytes of a
  4-byte item);
- 4, Data Range Error: a goal register while the Bus Watchdog has tripped ("Bus
  Watchdog (98)"), or a value outside the register's Range column;
- 6, Data Limit Error: beyond the limit another register sets.

The ranges are the registers' rules (``devices._xm430_rules``); nothing here knows a
register by name but the Bus Watchdog's list of locked goals (``_xm430_notes``).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

from ..devices import dxl_packet as pkt
from ..devices import xm430 as xm
from ..devices import xm430_notes

_OWNER: dict[int, xm.Register] = {
    a: reg for reg in xm.XM430_W350.values() for a in range(reg.address, reg.address + reg.size)
}
_LOCKED = frozenset(xm.register(name) for name in xm430_notes.WATCHDOG_LOCKS)

Written = dict[xm.Register, int]  # register -> the value the write gives it


@dataclass(frozen=True, slots=True)
class _Span:
    """What a write of some bytes at some address covers (from the table alone)."""

    regs: tuple[xm.Register, ...]  # the registers with a byte in it, in order
    open: bool  # every one writable
    eeprom: bool  # one of them in the EEPROM area
    whole: bool  # it starts and ends on register boundaries


@functools.cache
def _span(start: int, size: int) -> _Span:
    """The registers with at least one byte in ``start .. start + size`` (see ``_Span``)."""
    found: list[xm.Register] = []
    for address in range(start, start + size):
        reg = _OWNER.get(address)
        if reg is not None and (not found or found[-1] is not reg):
            found.append(reg)
    regs = tuple(found)
    whole = bool(regs) and regs[0].address >= start
    whole = whole and regs[-1].address + regs[-1].size <= start + size
    return _Span(regs, all(r.writable for r in regs), any(r.eeprom for r in regs), whole)


def check_write(
    memory: bytearray,
    pieces: list[tuple[int, bytes]],
    *,
    eeprom_locked: bool,
    watchdog_tripped: bool,
) -> tuple[int, Written]:
    """(error, written): the status error number of writing ``pieces`` ((address, bytes)
    runs, Indirect Data already resolved) into ``memory``, and the registers' new values
    (empty unless the error is 0). ``eeprom_locked``: torque on, or sent to the Secondary
    ID."""
    written: Written = {}
    for start, chunk in pieces:
        span = _span(start, len(chunk))
        if not span.regs or not span.open or (span.eeprom and eeprom_locked):
            return pkt.ACCESS_ERROR, {}
        if not span.whole:
            return pkt.DATA_LENGTH_ERROR, {}
        for reg in span.regs:  # each one whole: its value is its bytes of the chunk
            at = reg.address - start
            written[reg] = reg.decode(chunk[at : at + reg.size])
    if watchdog_tripped and any(reg in _LOCKED for reg in written):
        return pkt.DATA_RANGE_ERROR, {}

    def values(name: str) -> int:
        reg = xm.register(name)
        found = written.get(reg)
        return reg.decode(memory[reg.address : reg.address + reg.size]) if found is None else found

    for reg, value in written.items():
        error = 0 if reg.rule is None else reg.rule.error(value, values)
        if error:
            return error, {}
    return 0, written
