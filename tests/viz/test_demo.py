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
from armkit.cli._demo import FOLLOW, SCREENSHOT, TOUR, next_commands

ROOT = Path(__file__).parents[2]


@pytest.fixture(autouse=True)
def _in_tmp_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Run in the test's own folder (files written to the working directory land there)."""
    monkeypatch.chdir(tmp_path)


def test_the_demo_shows_every_arm_and_scene_and_leaves_nothing_behind(
    tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
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
    assert not config_dir.exists()  # nothing kept: every arm was in memory
    from PIL import Image

    with Image.open(tmp_path / "stack.png") as img:
        assert np.asarray(img.convert("RGB")).std() > 10  # a picture, not a blank page
    for command in [*next_commands(), FOLLOW]:
        assert command in out


def test_a_demo_refusal_comes_before_anything_runs(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["demo", "-o", "missing/stack.png"]) == 2
    assert main(["demo", "--gif", "anim.png"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err.count("armkit: error:") == 2


@pytest.mark.parametrize("command", [*next_commands(), TOUR, SCREENSHOT])
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


def test_the_suggested_follow_serves_until_ctrl_c(config_dir: Path) -> None:
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


def test_without_chromium_the_demo_suggests_a_picture_it_can_make(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """On a bare machine (no Chromium on PATH) the demo's hint 'view --screenshot' failed;
    it now suggests the animation of the same view, which needs only the plot extra."""
    monkeypatch.delenv("ARMKIT_CHROMIUM", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))  # nothing there: no chromium, no tmux
    hints = next_commands()
    assert SCREENSHOT not in hints and TOUR in hints
    assert main(shlex.split(TOUR)[1:]) == 0 and (tmp_path / "tour.gif").stat().st_size > 1000


def test_make_demo_installs_what_its_hints_need() -> None:
    """`make demo` installed only the plot extra, and the hints 'view --screenshot' and
    'view --follow' need the web extra: every extra a hint needs is in the demo's install."""
    makefile = (ROOT / "Makefile").read_text()
    stamp = makefile.split("$(STAMP):", 1)[1].split("\n\n", 1)[0]
    installed = set(stamp.split('-e ".[', 1)[1].split("]", 1)[0].split(","))
    needs = {"--gif": "plot", "view": "web"}
    for hint in (*next_commands(), SCREENSHOT, TOUR, FOLLOW):
        words = shlex.split(hint)
        for word, extra in needs.items():
            if word in words and not (word == "view" and "--gif" in words):
                assert extra in installed, (hint, extra, installed)
