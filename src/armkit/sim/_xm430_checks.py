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

from ..devices import dxl_packet as pkt
from ..devices import xm430 as xm
from ..devices import xm430_notes
from ._xm430_memory import merged

_OWNER: dict[int, xm.Register] = {
    a: reg for reg in xm.XM430_W350.values() for a in range(reg.address, reg.address + reg.size)
}
_LOCKED = frozenset(xm.register(name) for name in xm430_notes.WATCHDOG_LOCKS)

Written = dict[xm.Register, int]  # register -> the value the write gives it


def _touched(start: int, size: int) -> list[xm.Register]:
    """The registers with at least one byte in ``start .. start + size``, in order."""
    found: list[xm.Register] = []
    for address in range(start, start + size):
        reg = _OWNER.get(address)
        if reg is not None and (not found or found[-1] is not reg):
            found.append(reg)
    return found


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
        regs = _touched(start, len(chunk))
        if not regs or any(not r.writable or (r.eeprom and eeprom_locked) for r in regs):
            return pkt.ACCESS_ERROR, {}
        if regs[0].address < start or regs[-1].address + regs[-1].size > start + len(chunk):
            return pkt.DATA_LENGTH_ERROR, {}
        for reg in regs:
            written[reg] = merged(memory, reg, start, chunk)
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
