"""Fixtures: emulators on pseudo-terminals, and a private config directory per test."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from armkit.model import ArmModel, load_model
from armkit.sim.emulators import MaestroEmulator, SSC32Emulator


@pytest.fixture
def ssc32_emu() -> Iterator[SSC32Emulator]:
    with SSC32Emulator(9600) as emu:
        yield emu


@pytest.fixture
def maestro_emu() -> Iterator[MaestroEmulator]:
    with MaestroEmulator() as emu:
        yield emu


@pytest.fixture(scope="session")
def lynx6() -> ArmModel:
    return load_model("lynx6")
