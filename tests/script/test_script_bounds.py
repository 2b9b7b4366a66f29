"""A script may not ask for an absurd pause or loop: ``wait`` is at most an hour and a
``repeat`` (or ``--repeat``) at most 10 000 iterations, refused by the check in one line
each, nothing moved."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main
from armkit.script import MAX_REPEAT, MAX_WAIT_S, Source, check_source


def _errors(text: str) -> list[str]:
    result = check_source(Source("b.arm", text))
    return [d.message for d in result.diagnostics if d.severity == "error"]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("wait 1e9\n", "wait needs a time in 0..3600 s (1 hour, the longest pause"),
        ("wait 3601\n", "got 3601 s; repeat a shorter wait for more"),
        ("wait 61min\n", "got 61 min (3660 s)"),
        ("wait 1e9ms\n", "got 1e+09 ms (1e+06 s)"),  # as written, not 10 digits
        ("wait -1\n", "wait needs a time in 0..3600 s"),
        ("repeat 1000000000\n  home\nend\n", "a repeat count must be 0..10000"),
        ("repeat 10001\n  home\nend\n", "got 10001"),
        ("define pause(t)\n  wait t\nend\npause 120min\n", "got 7200 s"),
        ("repeat 20000\n  home\nend\n", "got 20000"),
    ],
)
def test_absurd_values_are_refused_with_the_bound(text: str, message: str) -> None:
    errors = _errors(text)
    assert len(errors) == 1 and message in errors[0] and "\n" not in errors[0]


def test_the_bounds_themselves_are_allowed() -> None:
    assert MAX_WAIT_S == 3600.0 and MAX_REPEAT == 10_000
    assert _errors("wait 3600\nwait 60min\nwait 3600000ms\n") == []
    result = check_source(Source("b.arm", "repeat 10000\n  wait 60min\nend\n"))
    assert result.ok and result.timetable.total == pytest.approx(10_000 * 3600.0)


def test_check_refuses_a_huge_wait_in_one_error_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "long.arm"
    path.write_text("home\nwait 1e9\nrepeat 1000000000\n  home\nend\n")
    assert main(["check", str(path)]) == 2
    captured = capsys.readouterr()
    assert "ok for" not in captured.out
    last = captured.err.splitlines()[-1]
    assert last.startswith(f"armkit: error: {path}:2:1: wait needs a time in 0..3600 s")
    assert last.endswith(f"(2 errors in {path}; nothing moved)")
    assert f"{path}:3:8: error: a repeat count must be 0..10000" in captured.err
    assert "Traceback" not in captured.err


def test_run_refuses_too_many_runs_before_opening_the_arm(
    tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "ok.arm"
    path.write_text("home\n")
    assert main(["run", str(path), "--repeat", "10001"]) == 2
    err = capsys.readouterr().err
    assert err.strip() == "armkit: error: --repeat must be 1..10000, got 10001"
    assert not config_dir.exists() or not any(config_dir.iterdir())
