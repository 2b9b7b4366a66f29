"""Fixtures for the script tests: a private config directory and a counting arm."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from script_arms import CountingDriver, counting_arm

from armkit import Arm


@pytest.fixture(autouse=True)
def config_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    d = tmp_path / "config"
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(d))
    return d


@pytest.fixture
def arm() -> Iterator[tuple[Arm, CountingDriver]]:
    a, d = counting_arm()
    yield a, d
    a.close()
