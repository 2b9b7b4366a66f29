from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture(autouse=True)
def _config_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
