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
    parser.add_argument("--driver", dest="driver_name", default="sim")  # as cli/_app's
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


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["servo", "3", "2600"], "argument pulse: must be 500..2500 µs, got 2600"),
        (["servo", "32", "1500"], "argument channel: must be 0..31, got 32"),
        (["servo", "0", "nan"], "argument pulse: must be 500..2500 µs, got nan"),
    ],
)
def test_servo_values_are_checked_by_the_parser(
    argv: list[str], words: str, capsys: pytest.CaptureFixture[str]
) -> None:
    from armkit.cli import main

    assert main(["--driver", "ssc32", "--port", "emu", *argv]) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1


def test_servo_table_prints_the_ideal_tables(capsys: pytest.CaptureFixture[str]) -> None:
    assert run(["--arm", "lynx6", "--driver", "ssc32", "servo-table"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "lynx6 on ssc32: tables from ideal (no unit file)"
    assert out[1].split()[:3] == ["base", "ch", "0"]
    assert "90.0->1500" in out[1]
    assert out[-1].split()[:3] == ["grip", "ch", "5"]
