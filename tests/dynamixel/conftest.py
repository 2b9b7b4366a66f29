"""Fixtures: an XM430 emulator on a pty (the OpenManipulator-X's IDs 11..15) and a bus on it."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from armkit.devices.dynamixel import DynamixelBus
from armkit.sim.emulators import DynamixelEmulator


@pytest.fixture
def emu() -> Iterator[DynamixelEmulator]:
    with DynamixelEmulator() as emulator:
        yield emulator


@pytest.fixture
def bus(emu: DynamixelEmulator) -> Iterator[DynamixelBus]:
    with DynamixelBus(emu.port, 1_000_000, retries=3) as b:
        b.settle_s = 0.15  # longer than the emulator's late replies (0.08 s): they are flushed
        yield b
