"""The XM430's control-table memory as bytes: which registers a write covers, and the
Indirect Address/Data areas (e-Manual XM430-W350, "Indirect Address, Indirect Data":
Indirect Data n reads and writes the byte Indirect Address n names)."""

from __future__ import annotations

from ..devices import xm430 as xm

_BY_ADDRESS = {r.address: r for r in xm.XM430_W350.values()}
# Indirect Data byte address -> address of the Indirect Address register that points it
_INDIRECT = {
    xm.register(f"Indirect Data {n}").address: xm.register(f"Indirect Address {n}").address
    for n in range(1, 2 * xm.INDIRECT_COUNT + 1)
}
_FIRST_INDIRECT = min(_INDIRECT)


def covered(address: int, size: int) -> list[xm.Register]:
    """The registers that start inside ``address .. address + size``."""
    return [_BY_ADDRESS[a] for a in range(address, address + size) if a in _BY_ADDRESS]


def _target(memory: bytearray, address: int) -> int:
    """Where the byte at ``address`` really is: itself, or what its Indirect Address names."""
    pointer = _INDIRECT.get(address)
    if pointer is None:
        return address
    return int.from_bytes(memory[pointer : pointer + 2], "little")


def read_through(memory: bytearray, address: int, size: int) -> bytes:
    """``size`` bytes from ``address``, Indirect Data read through its Indirect Address."""
    raw = bytearray(memory[address : address + size])
    if address + size > _FIRST_INDIRECT:
        for i in range(size):
            target = _target(memory, address + i)
            raw[i] = memory[target] if target < len(memory) else 0
    return bytes(raw)


def runs(memory: bytearray, address: int, data: bytes) -> list[tuple[int, bytes]]:
    """A write as runs of consecutive target bytes: an Indirect Data byte goes where its
    Indirect Address points."""
    if address + len(data) <= _FIRST_INDIRECT:  # no Indirect Data: one run, where it says
        return [(address, bytes(data))]
    found: list[tuple[int, bytearray]] = []
    for i, byte in enumerate(data):
        target = _target(memory, address + i)
        if found and found[-1][0] + len(found[-1][1]) == target:
            found[-1][1].append(byte)
        else:
            found.append((target, bytearray((byte,))))
    return [(start, bytes(chunk)) for start, chunk in found]
