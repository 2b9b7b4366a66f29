"""The servo-specific CLI commands, through their own parser (other command modules
are built elsewhere)."""

from __future__ import annotations

import argparse

import pytest

from armkit._errors import DeviceError
from armkit.cli import _servo


def run(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="armkit")
    parser.add_argument("--arm", default="lynx6")
    parser.add_argument("--driver", default="sim")
    parser.add_argument("--port", default=None)
    _servo.add_commands(parser.add_subparsers(dest="command"))
    args = parser.parse_args(argv)
    return int(args.func(args))


@pytest.mark.parametrize("driver", ["ssc32", "maestro"])
def test_servo_sends_a_pulse_and_prints_the_read_back(
    driver: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert run(["--driver", driver, "--port", "emu", "servo", "3", "1700", "--time-ms", "20"]) == 0
    assert capsys.readouterr().out == "channel 3: sent 1700 µs, controller reports 1700 µs\n"


@pytest.mark.parametrize(
    ("argv", "error", "words"),
    [
        (["--driver", "ssc32", "--port", "emu", "servo", "3", "2600"], ValueError, "2600"),
        (["--driver", "ssc32", "--port", "emu", "servo", "32", "1500"], ValueError, "channel 32"),
        (["--driver", "maestro", "--port", "emu", "servo", "24", "1500"], ValueError, "channel 24"),
        (["--driver", "sim", "--port", "emu", "servo", "3", "1500"], ValueError, "--driver ssc32"),
        (["--driver", "ssc32", "servo", "3", "1500"], DeviceError, "--port"),
    ],
)
def test_servo_refuses_before_opening_anything(
    argv: list[str], error: type[Exception], words: str
) -> None:
    with pytest.raises(error, match=words):
        run(argv)


def test_servo_table_prints_the_ideal_tables(capsys: pytest.CaptureFixture[str]) -> None:
    assert run(["--arm", "lynx6", "--driver", "ssc32", "servo-table"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "lynx6 on ssc32: tables from ideal (no unit file)"
    assert out[1].split()[:3] == ["base", "ch", "0"]
    assert "90.0->1500" in out[1]
    assert out[-1].split()[:3] == ["grip", "ch", "5"]
