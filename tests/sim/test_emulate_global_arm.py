"""``armkit --arm NAME emulate KIND``: the global --arm is the emulated arm, as --arm after
'emulate' is; two different arms are refused in one line; neither: a lone controller."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from armkit.cli import main
from armkit.cli._app import build_parser
from armkit.cli._emulate import _arm

ARMKIT = [sys.executable, "-c", "import sys; from armkit.cli import main; sys.exit(main())"]


@pytest.mark.parametrize(
    ("words", "arm"),
    [
        (["--arm", "lynx6", "emulate", "ssc32"], "lynx6"),
        (["--arm=lynx6", "emulate", "ssc32"], "lynx6"),
        (["emulate", "ssc32", "--arm", "lynx6"], "lynx6"),
        (["--arm", "lynx6", "emulate", "ssc32", "--arm", "lynx6"], "lynx6"),
        (["--arm", "openmanipulator_x", "emulate", "dynamixel"], "openmanipulator_x"),
        (["emulate", "ssc32"], None),
        (["--driver", "sim", "emulate", "maestro"], None),
    ],
)
def test_the_arm_comes_from_either_place(words: list[str], arm: str | None) -> None:
    assert _arm(build_parser().parse_args(words)) == arm


def test_two_different_arms_are_refused_in_one_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
    assert main(["--arm", "lynx6", "emulate", "ssc32", "--arm", "owi535"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err == (
        "armkit: error: two arms: --arm lynx6 before 'emulate' and --arm owi535 after it; "
        "give one\n"
    )


def test_the_global_arm_drives_the_emulated_controller(tmp_path: Path) -> None:
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path / "config")}
    proc = subprocess.Popen(
        [*ARMKIT, "--arm", "lynx6", "emulate", "ssc32"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
    )
    try:
        assert proc.stdout is not None and proc.stderr is not None
        assert proc.stdout.readline().startswith("/dev/")
        assert "an SSC-32U driving the lynx6 on /dev/" in proc.stderr.readline()
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=10) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
