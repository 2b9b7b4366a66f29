"""Fixtures: emulators on pseudo-terminals, and a private config directory per test."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from armkit.model import ArmModel, load_model
from armkit.sim.emulators import MaestroEmulator, SSC32Emulator


@pytest.fixture(autouse=True)
def config_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Calibration files go to a fresh directory, never the user's."""
    folder = tmp_path / "config"
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(folder))
    return folder


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
