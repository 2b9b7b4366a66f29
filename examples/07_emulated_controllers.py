"""Emulated controllers as other programs see them: the makers' own protocols.

``armkit emulate ssc32|maestro|dynamixel`` serves a simulated controller on a
pseudo-terminal; here the same emulators run in this process and plain
pyserial and the official dynamixel-sdk talk to them as to the hardware:
the SSC-32U's ``P0``/``PO``/inputs, the Maestro's Pololu protocol and its
factory 992..2000 µs range, and the XM430's indirect address area and
FAST_SYNC_READ (the way ROBOTIS's own software reads).

Needs: the serial and dynamixel extras (pip install 'armkit[serial,dynamixel]'; ``make test`` has them).
Run: .venv/bin/python examples/07_emulated_controllers.py
"""

from __future__ import annotations

import serial

from armkit.sim.emulators import DynamixelEmulator, MaestroEmulator, SSC32Emulator


def ssc32() -> None:
    with SSC32Emulator(9600) as emu, serial.Serial(emu.port, 9600, timeout=1.0) as line:
        line.write(b"#0P1500#1P3000\r")  # 3000 µs is clamped to 2500, the group still moves
        line.write(b"#0PO-20\rQP0QP1\r")  # an offset of -20 µs, then the pulses / 10 µs
        print(
            f"SSC-32U: channel 0 sends {line.read(1)[0] * 10} µs, channel 1 {line.read(1)[0] * 10} µs"
        )
        line.write(b"AB\r")
        print(f"SSC-32U: inputs A and B read {line.read(2).decode()} (pulled up)")


def maestro() -> None:
    with MaestroEmulator() as emu, serial.Serial(emu.port, 9600, timeout=1.0) as line:
        quarter = 900 * 4  # below the factory range: the Maestro clamps it to 992 µs
        line.write(bytes([0xAA, 12, 0x04, 0, quarter & 0x7F, quarter >> 7]))  # Pololu protocol
        line.write(bytes([0xAA, 12, 0x10, 0]))
        print(f"Maestro: asked 900 µs, sends {int.from_bytes(line.read(2), 'little') / 4} µs")


def dynamixel() -> None:
    try:
        import dynamixel_sdk as sdk
    except ModuleNotFoundError:
        print("XM430s: install the dynamixel extra to talk to them with the official SDK")
        return
    with DynamixelEmulator() as emu:
        port, ph = sdk.PortHandler(emu.port), sdk.PacketHandler(2.0)
        port.openPort()
        port.setBaudRate(1_000_000)
        for k in range(4):  # Indirect Data 1..4 read Present Position (132..135)
            ph.write2ByteTxRx(port, 11, 168 + 2 * k, 132 + k)
        position, _, _ = ph.read4ByteTxRx(port, 11, 224)
        group = sdk.GroupSyncRead(port, ph, 132, 4)
        for sid in (11, 12, 13):
            group.addParam(sid)
        group.fastSyncRead()
        ticks = [group.getData(sid, 132, 4) for sid in (11, 12, 13)]
        print(
            f"XM430s: servo 11 through its indirect area at tick {position}; FAST_SYNC_READ {ticks}"
        )
        port.closePort()


if __name__ == "__main__":
    ssc32()
    maestro()
    dynamixel()
