"""``armkit.cli.main`` builds its parser once per process and reuses it: one command's
options never carry over into the next, and the parser is the one ``build_parser`` makes."""

from __future__ import annotations

import pytest

from armkit.cli import main
from armkit.cli._app import build_parser, parser_of_process


def test_the_parser_is_built_once_and_reused() -> None:
    assert parser_of_process() is parser_of_process()
    fresh = build_parser()
    assert fresh is not parser_of_process()
    assert fresh.format_help() == parser_of_process().format_help()


def test_a_replaced_registry_of_kinds_builds_it_again(monkeypatch: pytest.MonkeyPatch) -> None:
    from armkit.connect import _kinds

    before = parser_of_process()
    monkeypatch.setattr(_kinds, "KINDS", _kinds.KINDS[:-1])  # as tests that add a kind do
    assert parser_of_process() is not before
    assert "dynamixel" not in parser_of_process().format_help().split("--driver")[1][:80]
    monkeypatch.undo()
    assert parser_of_process().format_help() == before.format_help()


def test_one_call_leaves_nothing_for_the_next(capsys: pytest.CaptureFixture[str]) -> None:
    parser = parser_of_process()
    first = parser.parse_args(["--arm", "lynx6", "ik", "200", "0", "50", "--pitch", "-45", "--all"])
    second = parser.parse_args(["ik", "200", "0", "50"])
    assert (first.arm, first.pitch, first.all) == ("lynx6", -45.0, True)
    assert (second.arm, second.pitch, second.all) == ("openmanipulator_x", None, False)
    assert "given" not in vars(second)
    assert main(["--arm", "lynx6", "ik", "200", "0", "50", "--pitch", "-45"]) == 0
    assert main(["ik", "200", "0", "50", "--pitch", "-90"]) == 0
    out = capsys.readouterr().out
    assert "base deg" in out and "waist deg" in out  # the second call is the default arm's


def test_a_mistake_does_not_spoil_the_parser(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["move", "1", "2"]) == 2
    assert main(["mvoe"]) == 2
    assert main(["fk", "0", "0", "0", "0"]) == 0
    assert "position: x 274.00" in capsys.readouterr().out
