"""``dxl-scan`` against the emulator (the lead registers the module in cli/_app.py)."""

from __future__ import annotations

import argparse

import pytest

from armkit import DeviceError
from armkit.cli import _dynamixel


def run(argv: list[str]) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--port")
    _dynamixel.add_commands(parser.add_subparsers(dest="command"))
    args = parser.parse_args(argv)
    return int(args.func(args))


def test_scan_lists_the_openmanipulator_servos(capsys: pytest.CaptureFixture[str]) -> None:
    assert run(["--port", "emu", "dxl-scan", "--ids", "10-16"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in out[2:]] == ["11", "12", "13", "14", "15"]
    assert out[2].split()[1:5] == ["1020", "XM430-W350", "position", "off"]


def test_scan_reports_an_empty_bus(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(DeviceError, match="no servo answered"):
        run(["--port", "emu", "dxl-scan", "--ids", "1"])


@pytest.mark.parametrize("ids", ["300", "a-b", "5-2"])
def test_bad_id_ranges_are_refused(ids: str) -> None:
    with pytest.raises(ValueError, match="--ids"):
        _dynamixel.parse_ids(ids)


def test_scan_needs_a_port() -> None:
    with pytest.raises(ValueError, match="needs --port"):
        run(["dxl-scan"])
