"""Issue 10: when a command fails and stopping the device afterwards fails too (a port
that vanished), the user sees the first error; the second is a note on it. Every CLI
command that closes a driver itself (OWI commands, calibrate) goes through
``armkit._closing.closing``, as ``with Arm`` does."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from armkit._closing import closing
from armkit._errors import DeviceError


class _Device:
    def __init__(self, fails: bool) -> None:
        self.fails, self.closed = fails, 0

    def close(self) -> None:
        self.closed += 1
        if self.fails:
            raise DeviceError("stop: port /dev/ttyUSB0 is gone")


def test_the_blocks_error_stays_the_one_raised() -> None:
    device = _Device(fails=True)
    with pytest.raises(DeviceError, match="move: no reply") as caught, closing(device):
        raise DeviceError("move: no reply from servo 3")
    assert device.closed == 1
    assert any("port /dev/ttyUSB0 is gone" in note for note in caught.value.__notes__)


def test_a_clean_block_closes_and_a_failing_close_is_raised() -> None:
    quiet, loud = _Device(fails=False), _Device(fails=True)
    with closing(quiet):
        pass
    assert quiet.closed == 1
    with pytest.raises(DeviceError, match="gone"), closing(loud):
        pass


def test_no_cli_command_closes_a_driver_in_a_bare_finally() -> None:
    cli = Path(__file__).parents[2] / "src" / "armkit" / "cli"
    bare = []
    for path in cli.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Try) and node.finalbody:
                text = ast.unparse(node.finalbody)
                if "driver.close()" in text:
                    bare.append(f"{path.name}:{node.lineno}")
    assert bare == []
