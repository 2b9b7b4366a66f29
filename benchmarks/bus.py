"""Servo-bus control cycles: armkit's own software time against the wire time.

Run:  .venv/bin/python benchmarks/bus.py [--cycles 500] [--repeats 7]

OpenManipulator-X cycle = SYNC_WRITE of 4 goal positions + SYNC_READ of 4
present positions (IDs 11..14), the loop a streaming controller runs. The wire
time is what those bytes need at 1 Mbps (10 bits a byte: start + 8 + stop),
without the servos' return delay.

The rows separate who spends the time, so that the emulator's CPU is never
counted as armkit's:

* "replay port" rows run the SDK on a stand-in PortHandler that answers
  instantly with canned status bytes (built once, before timing): no pty, no
  emulator, no waiting. "SDK alone" is the raw GroupSyncWrite/GroupSyncRead
  code a user would write; "armkit bus" is DynamixelBus doing the same cycle
  (goals encoded, replies checked for errors and sign-converted).
  Their difference is armkit's own bus overhead.
* "driver conversion" is the rest of armkit's per-cycle work: limit check,
  angles -> ticks, ticks -> angles.
* "armkit codec" is armkit's own packet builder/parser (_dxl_packet, used by
  the emulator and tests) doing the same cycle's frames, for scale.
* "pty + emulator" rows are the whole cycle through the pseudo-terminal with
  the emulator thread answering, for armkit's bus and for the raw SDK:
  informational, they include the emulator's Python CPU time, the two threads
  sharing the GIL and the pty, and no baud-rate limit.

Times are the best of ``--repeats`` interleaved runs of ``--cycles`` cycles
(pty rows: cycles / 5), so that other load on the machine disturbs them least.
"""

from __future__ import annotations

import argparse
import os
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from armkit.devices import _dxl_packet as pkt
from armkit.devices.dynamixel import DynamixelBus
from armkit.drivers.dynamixel import DynamixelDriver
from armkit.model import check_joints, load_model
from armkit.sim.emulators import DynamixelEmulator

IDS = [11, 12, 13, 14]
GOALS = {11: 2048, 12: 1500, 13: 2300, 14: 2600}
BAUD = 1_000_000


def omx_frames() -> tuple[list[bytes], list[bytes]]:
    """(instruction frames, status frames) of one OpenManipulator-X cycle."""
    sent = [
        pkt.sync_write(116, 4, {sid: g.to_bytes(4, "little") for sid, g in GOALS.items()}),
        pkt.sync_read(132, 4, IDS),
    ]
    replies = [pkt.status(sid, 0, GOALS[sid].to_bytes(4, "little")) for sid in IDS]
    return sent, replies


def wire_us(frames: list[bytes], baud: int = BAUD) -> float:
    """Time the bytes of ``frames`` need on the wire [us], 10 bits a byte."""
    return sum(len(f) for f in frames) * 10 / baud * 1e6


class ReplayPort:
    """A PortHandler stand-in: a SYNC_READ is answered at once with ``replies``."""

    def __init__(self, replies: list[bytes]) -> None:
        self.replies = b"".join(replies)
        self.buffer = bytearray()
        self.is_using, self.is_open, self.baudrate = False, True, BAUD
        self.tx_time_per_byte = 10_000 / BAUD  # ms per byte, as the SDK keeps it

    def clearPort(self) -> None:
        self.buffer.clear()

    def writePort(self, packet: list[int]) -> int:
        if packet[7] == pkt.Inst.SYNC_READ:
            self.buffer += self.replies
        return len(packet)

    def readPort(self, length: int) -> bytes:
        chunk = bytes(self.buffer[:length])
        del self.buffer[:length]
        return chunk

    def setPacketTimeout(self, packet_length: int) -> None:
        pass

    def isPacketTimeout(self) -> bool:
        return True


def per_cycle_us(cycles: int, repeats: int, **named: Callable[[], object]) -> dict[str, float]:
    """{name: us per call} of each cycle function, best of ``repeats`` runs of ``cycles``
    calls. The runs of the functions are interleaved, so that a busy machine slows them
    alike, and the best run is the least disturbed one."""
    best = dict.fromkeys(named, float("inf"))
    for _ in range(repeats):
        for name, cycle in named.items():
            t0 = time.perf_counter()
            for _ in range(cycles):
                cycle()
            best[name] = min(best[name], (time.perf_counter() - t0) / cycles * 1e6)
    return best


def sdk_cycle(sdk: Any, port: Any) -> Callable[[], object]:
    """The raw-SDK cycle a user would write (no error checks beyond the result codes)."""
    ph = sdk.PacketHandler(2.0)
    write, read = sdk.GroupSyncWrite(port, ph, 116, 4), sdk.GroupSyncRead(port, ph, 132, 4)
    for sid in IDS:
        read.addParam(sid)

    def cycle() -> object:
        write.clearParam()
        for sid, goal in GOALS.items():
            write.addParam(sid, list(goal.to_bytes(4, "little")))
        write.txPacket()
        read.txRxPacket()
        return [read.getData(sid, 132, 4) for sid in IDS]

    return cycle


def bus_cycle(bus: DynamixelBus) -> Callable[[], object]:
    """armkit's bus doing the same cycle."""

    def cycle() -> object:
        bus.sync_write("Goal Position", GOALS)
        return bus.sync_read("Present Position", IDS)

    return cycle


def driver_conversion(driver: DynamixelDriver) -> Callable[[], object]:
    """armkit's per-cycle arithmetic above the bus: limits, angles -> ticks -> angles."""
    q = np.radians([10.0, -20.0, 30.0, 40.0])

    def cycle() -> object:
        ticks = driver.to_ticks(check_joints(driver.model, q))
        return driver.to_angles(ticks)

    return cycle


def codec_cycle() -> Callable[[], object]:
    """armkit's own codec building the cycle's frames and parsing its replies."""
    _, replies = omx_frames()
    goals = {sid: g.to_bytes(4, "little") for sid, g in GOALS.items()}

    def cycle() -> object:
        pkt.sync_write(116, 4, goals)
        pkt.sync_read(132, 4, IDS)
        return [pkt.decode(r).data for r in replies]

    return cycle


def omx_rows(cycles: int, repeats: int) -> list[tuple[str, float]]:
    """(row name, us per cycle) of the OpenManipulator-X cycle."""
    import dynamixel_sdk as sdk
    from dynamixel_sdk import PacketHandler

    _, replies = omx_frames()
    bus = DynamixelBus.on_handlers(ReplayPort(replies), PacketHandler(2.0))
    with DynamixelEmulator() as emu, DynamixelBus(emu.port, BAUD) as real:
        driver = DynamixelDriver(load_model("openmanipulator_x"), real)
        fast = per_cycle_us(
            cycles,
            repeats,
            **{
                "SDK alone, replay port": sdk_cycle(sdk, ReplayPort(replies)),
                "armkit bus (incl. SDK), replay port": bus_cycle(bus),
                "driver conversion": driver_conversion(driver),
                "armkit codec (_dxl_packet)": codec_cycle(),
            },
        )
        raw = sdk.PortHandler(emu.port)
        raw.openPort()
        slow = per_cycle_us(
            max(1, cycles // 5),
            repeats,
            **{
                "armkit bus, pty + emulator": bus_cycle(real),
                "SDK alone, pty + emulator": sdk_cycle(sdk, raw),
            },
        )
        raw.closePort()
        driver.close()
    return list(fast.items()) + list(slow.items())


# === SSC-32 section ========================================================
SSC32_PULSES = {0: 1500, 1: 1620, 2: 1410, 3: 1730, 4: 1500, 5: 1200}
SSC32_BAUD = 115_200  # the SSC-32's fastest rate


def ssc32_rows(cycles: int, repeats: int) -> tuple[list[tuple[str, float]], float] | None:
    """SSC-32 group-move rows (6-servo group move + QP read-back) and their wire time [us]."""
    from armkit.devices.ssc32 import SSC32, group_move_bytes, parse_pulses, query_pulse_bytes
    from armkit.sim.emulators import SSC32Emulator

    channels = list(SSC32_PULSES)
    move = group_move_bytes(SSC32_PULSES, 1000)
    query = query_pulse_bytes(channels)
    reply = bytes(p // 10 for p in SSC32_PULSES.values())
    wire = wire_us([move, query, reply], SSC32_BAUD)

    def pure() -> object:
        group_move_bytes(SSC32_PULSES, 1000)
        query_pulse_bytes(channels)
        return parse_pulses(reply, channels)

    with SSC32Emulator(SSC32_BAUD) as emu, SSC32(emu.port, SSC32_BAUD) as board:

        def full() -> object:
            board.group_move(SSC32_PULSES, 1000)
            return board.query_pulses(channels)

        fast = per_cycle_us(cycles, repeats, **{"armkit bytes + parse (pure)": pure})
        slow = per_cycle_us(max(1, cycles // 5), repeats, **{"armkit SSC32, pty + emulator": full})
    return list(fast.items()) + list(slow.items()), wire


# ===========================================================================


def print_table(
    title: str, wire: float, rows: list[tuple[str, float]], baud: str = "1 Mbps"
) -> None:
    print(f"\n{title}\n{'':-<72}")
    print(f"{'':38} {'us/cycle':>10} {'% of wire':>10}")
    print(f"{'wire time at ' + baud:38} {wire:10.1f} {100.0:9.1f}%")
    for name, us in rows:
        print(f"{name:38} {us:10.1f} {100 * us / wire:9.1f}%")


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cycles", type=int, default=500)
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    sent, replies = omx_frames()
    wire = wire_us(sent + replies)
    rows = omx_rows(args.cycles, args.repeats)
    n_bytes = sum(map(len, sent + replies))
    print_table(
        f"OpenManipulator-X cycle: {n_bytes} bytes (4 goals out, 4 positions back)", wire, rows
    )
    times = dict(rows)
    own = times["armkit bus (incl. SDK), replay port"] - times["SDK alone, replay port"]
    own += times["driver conversion"]
    print(
        f"\narmkit's own time per cycle (bus overhead over the SDK + driver conversion):"
        f" {own:.1f} us = {100 * own / wire:.1f} % of the wire time (target <= 10 %)"
    )
    ssc32 = ssc32_rows(args.cycles, args.repeats)
    if ssc32 is not None:
        print_table(
            "SSC-32 group move (6 servos) + QP read-back", ssc32[1], ssc32[0], "115200 baud"
        )


if __name__ == "__main__":
    main()
