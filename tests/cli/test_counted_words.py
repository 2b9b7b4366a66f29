"""Counts and numbers as printed: '1 object', '2 objects', never '-0.00'."""

from __future__ import annotations

import re

import pytest

from armkit._terminal import count, fixed
from armkit.cli import main
from armkit.cli._table import table


def test_count_and_fixed() -> None:
    assert [count(n, "step") for n in (0, 1, 2)] == ["0 steps", "1 step", "2 steps"]
    assert count(1, "servo command") == "1 servo command"
    assert count(3, "bar and drum", "bars and drums") == "3 bars and drums"
    assert [fixed(v) for v in (-0.001, -0.0, 0.004, -0.005001, 1.0)] == [
        "0.00", "0.00", "0.00", "-0.01", "1.00",
    ]  # fmt: skip
    assert fixed(-0.04, 1) == "0.0" and fixed(float("nan")) == "nan"
    assert "-0.00" not in table(["a"], [[-0.0001]])


def test_cli_lines_say_one_thing_in_the_singular(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["scene", "list"]) == 0
    out = capsys.readouterr().out
    assert "reach_003    1 object: hand" in out and "board_001    4 objects:" in out
    assert main(["ik", "200", "-0.0001", "100"]) == 0  # the waist a hair below 0 deg
    out = capsys.readouterr().out
    assert "-0.00" not in out and "0.00" in out
    assert main(["--arm", "puma560", "ik", "400", "0", "300"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"\(lm: \d+ iterations?, \d+ restarts?,", out)
    assert not re.search(r"(?<!\d)1 (iterations|restarts)", out)
