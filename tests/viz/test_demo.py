"""``armkit demo``: the showcase runs on simulated arms, leaves no state behind, and
every command it suggests next works as printed."""

from __future__ import annotations

import shlex
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from browser_page import chromium_or_skip

from armkit.cli import main
from armkit.cli._demo import FOLLOW, NEXT


@pytest.fixture(autouse=True)
def config(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
    monkeypatch.chdir(tmp_path)
    return tmp_path / "config"


def test_the_demo_shows_every_arm_and_scene_and_leaves_nothing_behind(
    tmp_path: Path, config: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["demo", "-o", "stack.png"]) == 0
    out = capsys.readouterr().out
    from armkit.model import shipped_models
    from armkit.scene import shipped_scenes

    for arm in shipped_models():
        assert f"\n{arm} " in out
    for scene in shipped_scenes():
        assert scene.split("_")[-1] in out
    assert "red 15.5, green 40.5, blue 65.5" in out  # stacked, each one cube higher
    assert "placed object on bin" in out
    assert not config.exists()  # nothing kept: every arm was in memory
    from PIL import Image

    with Image.open(tmp_path / "stack.png") as img:
        assert np.asarray(img.convert("RGB")).std() > 10  # a picture, not a blank page
    for command in [*NEXT, FOLLOW]:
        assert command in out


def test_a_demo_refusal_comes_before_anything_runs(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["demo", "-o", "missing/stack.png"]) == 2
    assert main(["demo", "--gif", "anim.png"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err.count("armkit: error:") == 2


@pytest.mark.parametrize("command", NEXT)
def test_every_suggested_command_works(
    command: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    words = shlex.split(command)[1:]
    if "--screenshot" in words:
        monkeypatch.setenv("ARMKIT_CHROMIUM", chromium_or_skip())
    assert main(words) == 0, command
    for word in words:
        if word.endswith((".gif", ".png")):
            assert (tmp_path / word).stat().st_size > 1000


def test_the_suggested_follow_serves_until_ctrl_c(config: Path) -> None:
    cmd = [sys.executable, "-c", "from armkit.cli import main; raise SystemExit(main())"]
    cmd += [*shlex.split(FOLLOW)[1:], "--port", "0"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        assert proc.stdout is not None
        line = proc.stdout.readline()
        assert line.startswith("armkit view: http://127.0.0.1:"), line
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 0 and "stopped" in out
