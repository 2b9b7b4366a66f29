"""``armkit view --screenshot``: the browser's steps shown on stderr as they go
(``armkit._progress``), the picture written."""

from __future__ import annotations

from pathlib import Path

import pytest
from browser_page import chromium_or_skip

import armkit._progress as progress
from armkit.cli import main


def test_the_steps_of_a_screenshot_are_shown(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    chromium_or_skip()
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
    monkeypatch.setattr(progress, "SHOW_AFTER", 0.0)  # show every step, however quick
    monkeypatch.setattr(progress, "EVERY", 0.0)
    png = tmp_path / "view.png"
    assert main(["view", "--port", "0", "--size", "320", "240", "--screenshot", str(png)]) == 0
    out, err = capsys.readouterr()
    assert out.strip().endswith(f"armkit view: wrote {png}") and png.stat().st_size > 0
    steps = [line.split(", ")[0:2] for line in err.splitlines()]
    assert steps == [
        ["screenshot: 0/4 steps", "starting the browser"],
        ["screenshot: 1/4 steps", "opening the page"],
        ["screenshot: 2/4 steps", "waiting for the scene"],
        ["screenshot: 3/4 steps", "rendering"],
        ["screenshot: 4/4 steps", "done"],
    ]
