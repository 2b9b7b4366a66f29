"""Keyboard mode in a real terminal: under tmux (send-keys / capture-pane), and in a
pseudo-terminal (used instead when tmux is not installed)."""

from __future__ import annotations

import os
import pty
import re
import select
import shlex
import shutil
import subprocess
import sys
import time
from pathlib import Path

from armkit.drivers.timed import load_state, state_path

KEYS = "uuu" + "l" + "k"  # shoulder back x3, light on, base left


def command(config: Path) -> str:
    """A shell line: terminal settings, keyboard mode on the simulated OWI, settings again."""
    run = f"import sys; from armkit.cli import main; sys.exit(main({['--arm', 'owi535', '--driver', 'sim', 'keys']!r}))"
    return (
        f"export ARMKIT_CONFIG_DIR={shlex.quote(str(config))} PYTHONPATH={shlex.quote(os.pathsep.join(sys.path))}; "
        f"stty -g; {shlex.quote(sys.executable)} -c {shlex.quote(run)}; echo EXIT=$?; stty -g"
    )


def check_after(screen: str) -> None:
    settings = re.findall(r"^[0-9a-f:]{20,}$", screen, flags=re.M)
    assert len(settings) == 2 and settings[0] == settings[1], screen  # terminal restored
    assert "EXIT=0" in screen
    state = load_state(state_path("sim"))
    assert state.angles[1] < -0.2 and state.angles[0] < 0.0 and state.light


def wait_until(predicate: object, timeout: float = 15.0) -> None:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():  # type: ignore[operator]
            return
        time.sleep(0.05)
    raise AssertionError("timed out waiting for the terminal")


def run_in_tmux(config: Path, tmux: str) -> str:
    sock = ["-L", f"armkit-test-{os.getpid()}"]
    subprocess.run(
        [tmux, *sock, "new-session", "-d", "-s", "owi", "-x", "200", "-y", "30", "sh"], check=True
    )
    try:
        subprocess.run([tmux, *sock, "set-option", "-t", "owi", "remain-on-exit", "on"], check=True)

        def pane() -> str:
            return subprocess.run(
                [tmux, *sock, "capture-pane", "-p", "-t", "owi"], capture_output=True, text=True
            ).stdout

        wait_until(lambda: pane().strip() != "")  # the shell's prompt: type only after it
        subprocess.run(
            [tmux, *sock, "send-keys", "-t", "owi", command(config), "Enter"], check=True
        )
        wait_until(lambda: "| certain" in pane() or "UNCERTAIN" in pane())
        for key in KEYS:
            subprocess.run([tmux, *sock, "send-keys", "-t", "owi", "-l", key], check=True)
            time.sleep(0.1)
        wait_until(lambda: "light on" in pane())
        subprocess.run([tmux, *sock, "send-keys", "-t", "owi", "-l", "q"], check=True)
        wait_until(
            lambda: (
                "EXIT=" in pane() and len(re.findall(r"^[0-9a-f:]{20,}$", pane(), flags=re.M)) == 2
            )
        )
        return pane()
    finally:
        subprocess.run([tmux, *sock, "kill-server"], check=False)


def run_in_pty(config: Path) -> str:
    pid, fd = pty.fork()
    if pid == 0:  # the child: a shell on the pseudo-terminal
        os.execv("/bin/sh", ["sh", "-c", command(config)])
    out = b""

    def read_some() -> None:
        nonlocal out
        while select.select([fd], [], [], 0.05)[0]:
            try:
                chunk = os.read(fd, 4096)
            except OSError:
                return
            if not chunk:
                return
            out += chunk

    def seen(text: str) -> bool:
        read_some()
        return text.encode() in out

    wait_until(lambda: seen("| certain") or seen("UNCERTAIN"))
    for key in KEYS:
        os.write(fd, key.encode())
        time.sleep(0.05)
    wait_until(lambda: seen("light on"))
    os.write(fd, b"q")
    wait_until(lambda: seen("EXIT="))
    os.waitpid(pid, 0)
    read_some()
    return out.decode(errors="replace").replace("\r", "\n")


def test_keys_under_tmux_or_a_pty(tmp_path: Path) -> None:
    tmux = shutil.which("tmux")
    screen = run_in_tmux(tmp_path / "config", tmux) if tmux else run_in_pty(tmp_path / "config")
    assert "keys: w close / s open gripper" in screen
    assert re.search(r"sh\s+-\d+ .*light on", screen)  # the live status line
    check_after(screen)


def test_keys_in_a_pty(tmp_path: Path) -> None:
    screen = run_in_pty(tmp_path / "config")
    assert re.search(r"xyz\s+-?\d+\s+-?\d+\s+\d+ mm", screen)
    check_after(screen)
