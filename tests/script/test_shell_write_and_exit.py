"""``armkit shell`` end to end, with lines piped in: ``write`` gives a script that checks
and runs as the session did (its ``arm`` and ``scene`` lines), and the exit status says
whether a piped line failed."""

from __future__ import annotations

import io
import shutil
from importlib import resources
from pathlib import Path

import pytest

from armkit.cli import main


def _shell(monkeypatch: pytest.MonkeyPatch, lines: str, *options: str) -> int:
    monkeypatch.setattr("sys.stdin", io.StringIO(lines))
    return main([*options, "shell", "--no-history"])


def test_write_keeps_the_scene_the_shell_was_started_with(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """Was: 'armkit --scene board_001 shell', 'pick red', 'write sess.arm' wrote no scene
    line, and 'armkit check sess.arm' failed: 'red' must be an object of the scene, and no
    scene is chosen."""
    monkeypatch.chdir(tmp_path)
    assert _shell(monkeypatch, "pick red\nwrite sess.arm\n", "--scene", "board_001") == 0
    text = (tmp_path / "sess.arm").read_text()
    assert text.splitlines()[1:4] == [
        "arm openmanipulator_x",
        "scene board_001",
        "joints 0.000 -60.117 20.039 40.078   # where the session started",
    ]
    assert "driver" not in text  # armkit run's --driver (default sim) chooses: try it there
    capsys.readouterr()
    assert main(["check", "sess.arm"]) == 0, capsys.readouterr().err
    assert main(["scene", "reset", "board_001"]) == 0
    assert main(["--scene", "board_001", "run", "sess.arm"]) == 0, capsys.readouterr().err


def test_write_names_the_arm_and_scene_files_from_the_script_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """A model file and a scene file the shell read (one with a space in its name) are
    named by their paths from the folder the script is written to, so it checks from
    anywhere."""
    work = tmp_path / "work"
    (work / "out").mkdir(parents=True)
    arms, scenes = resources.files("armkit.model") / "arms", resources.files("armkit.scene")
    (work / "openmanipulator_x.toml").write_text((arms / "openmanipulator_x.toml").read_text())
    shutil.copy(str(scenes / "scenes" / "board_001.toml"), work / "my board.toml")
    monkeypatch.chdir(work)
    options = ("--arm", "openmanipulator_x.toml", "--scene", "my board.toml")
    assert _shell(monkeypatch, "pick red\nwrite out/s.arm\n", *options) == 0
    lines = (work / "out" / "s.arm").read_text().splitlines()
    assert lines[1:3] == ["arm ../openmanipulator_x.toml", 'scene "../my board.toml"']
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    assert main(["check", str(work / "out" / "s.arm")]) == 0, capsys.readouterr().err


@pytest.mark.parametrize(
    ("lines", "status"),
    [
        ("turn waist by 10\nwhere\n", 0),
        ("mvoe\nturn waist by 10\n", 1),  # a refused line; the next still ran
        ("turn waist by 500\n", 1),
        ("where extra\n", 1),
        ("jog\n", 1),
        ("write /nonexistent/x.arm\n", 1),
        ("repeat 2\n  turn waist by 1\n", 1),  # the input ended inside a block
        ("help nothing\nquit\nmvoe\n", 0),  # after quit nothing is read
    ],
)
def test_piped_lines_that_fail_give_exit_status_1(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], lines: str, status: int
) -> None:
    """Was: 0 whatever failed, so 'armkit shell < job.txt && next' went on."""
    assert _shell(monkeypatch, lines) == status
    assert ("error" in capsys.readouterr().out) == bool(status)


def test_the_shell_still_runs_the_lines_after_a_failed_one(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    assert _shell(monkeypatch, "mvoe\njoints 10 -60 20 40\nwhere\n") == 1
    assert "joints waist 10.00" in capsys.readouterr().out


def test_at_a_terminal_mistakes_leave_the_exit_status_0(tmp_path: Path) -> None:
    from script_arms import counting_arm

    from armkit.script._session import Session
    from armkit.script._shell import Shell

    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    a, _ = counting_arm()
    shell = Shell(Session(a, base_dir=tmp_path), stdin=Terminal("mvoe\n"), stdout=io.StringIO())
    assert shell.loop() == 0 and shell.failed
    a.close()


def test_the_docs_say_the_exit_status() -> None:
    readme = (Path(__file__).parents[2] / "docs" / "scripts.md").read_text()
    shell = readme[readme.index("**The shell** (`armkit shell`)") :]
    assert "exit status is 1 if any line failed" in " ".join(shell[:4000].split())
