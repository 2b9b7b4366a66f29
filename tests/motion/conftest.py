"""Shared fixtures: the simulator's state file goes to a temporary directory."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.model import ArmModel, load_model


@pytest.fixture(autouse=True)
def _config_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
    return tmp_path / "config"


@pytest.fixture(scope="session")
def omx() -> ArmModel:
    return load_model("openmanipulator_x")


@pytest.fixture(scope="session")
def lynx6() -> ArmModel:
    return load_model("lynx6")
