"""Every output path of the CLI is proven writable before anything moves: a file in a
folder that takes no new files (/proc), a directory, a missing folder or a wrong suffix
is one line on stderr, exit 2, no traceback, and the simulated arm (its state file, its
scene's objects) is exactly where it was; nothing is written."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main

TUNE = Path(__file__).resolve().parents[2] / "examples" / "music" / "twinkle.rtttl"
LINES = Path(__file__).resolve().parents[2] / "examples" / "drawings" / "lines.svg"
PROC = Path("/proc")
CIRCLE = ["draw", "circle", "--center", "200", "0", "50", "--radius", "20"]
needs_proc = pytest.mark.skipif(not PROC.is_dir(), reason="no /proc here")


def _files(folder: Path) -> dict[str, bytes]:
    """Every file under ``folder`` (the simulated arms' and objects' state) and its bytes."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in folder.rglob("*") if p.is_file()}


def _where(argv: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    capsys.readouterr()
    assert main([*argv, "where"]) == 0
    return capsys.readouterr().out


def _refused(argv: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    """Run ``argv``; assert it is refused as a user mistake (exit 2, one line) and return it."""
    capsys.readouterr()
    code = main(argv)
    captured = capsys.readouterr()
    assert code == 2, captured
    assert captured.err.count("\n") == 1 and captured.err.startswith("armkit: error: ")
    assert "Traceback" not in captured.err and "Errno" not in captured.err
    return captured.err


@needs_proc
@pytest.mark.parametrize(
    ("arm", "words", "option"),
    [
        ([], ["move", "200", "0", "100", "--gif", "/proc/x.gif"], "--gif"),
        (["--scene", "xylophone"], ["play", str(TUNE), "--wav", "/proc/x.wav"], "--wav"),
        (["--scene", "xylophone"], ["play", str(TUNE), "--plot", "/proc/x.png"], "--plot"),
        (["--scene", "board_001"], ["rotate-cube", "red", "--gif", "/proc/rotate.gif"], "--gif"),
        (["--scene", "board_001"], ["pick", "red", "--gif", "/proc/pick.gif"], "--gif"),
        ([], [*CIRCLE, "--record", "/proc/c.csv"], "--record"),
        ([], ["draw", "line", "200", "0", "50", "220", "0", "50", "--gif", "/proc/l.gif"], "--gif"),
        (
            ["--scene", "drawing"],
            ["draw", "svg", str(LINES), "--preview", "/proc/p.png"],
            "--preview",
        ),
        (
            ["--scene", "drawing"],
            ["draw", "svg", str(LINES), "--result", "/proc/r.png"],
            "--result",
        ),
    ],
)
def test_a_motion_with_an_unwritable_output_moves_nothing(
    arm: list[str],
    words: list[str],
    option: str,
    config_dir: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main([*arm, "move", "210", "10", "90"]) == 0  # a pose (and state files) to keep
    where, before = _where(arm, capsys), _files(config_dir)
    err = _refused([*arm, *words], capsys)
    path = words[-1]
    assert f"{option}: cannot write {path}: the folder /proc does not take new files" in err
    assert err.rstrip().endswith("; choose a file in a folder you can write to")
    assert _files(config_dir) == before
    assert _where(arm, capsys) == where


@needs_proc
@pytest.mark.parametrize(
    "argv",
    [
        ["demo", "-o", "/proc/d.png"],
        ["--scene", "board_001", "view", "--gif", "/proc/tour.gif"],
        ["compare-ik", "--n", "10", "--plot", "/proc/c.png"],
        ["--scene", "board_001", "scene", "show", "-o", "/proc/b.png"],
        ["--arm", "lynx6", "plot", "90", "90", "90", "90", "90", "-o", "/proc/x.png"],
        ["urdf", "-o", "/proc/x.urdf"],
    ],
)
def test_other_commands_refuse_an_unwritable_output_before_working(
    argv: list[str], config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    err = _refused(argv, capsys)
    assert f"cannot write {argv[-1]}: the folder /proc does not take new files" in err
    assert not config_dir.exists() or _files(config_dir) == {}
    assert capsys.readouterr().out == ""


def test_urdf_into_a_directory_is_refused_and_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    err = _refused(["urdf", "-o", str(out)], capsys)
    assert err == f"armkit: error: -o/--output: cannot write {out}: it is a directory; give a file name inside it\n"  # fmt: skip
    assert list(out.iterdir()) == [] and sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert main(["urdf", "-o", str(out / "omx.urdf")]) == 0
    assert [p.name for p in out.iterdir()] == ["omx.urdf"]


def test_play_into_a_directory_or_missing_folder_plays_nothing(
    tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    scene = ["--scene", "xylophone"]
    assert main([*scene, "move", "210", "10", "90"]) == 0
    where, before = _where(scene, capsys), _files(config_dir)
    (tmp_path / "x.wav").mkdir()
    assert "it is a directory" in _refused([*scene, "play", str(TUNE), "--wav", str(tmp_path / "x.wav")], capsys)  # fmt: skip
    missing = tmp_path / "no" / "x.wav"
    assert "does not exist" in _refused([*scene, "play", str(TUNE), "--wav", str(missing)], capsys)
    assert _files(config_dir) == before and _where(scene, capsys) == where


@needs_proc
def test_a_config_folder_that_takes_no_files_is_refused_before_moving(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", "/proc/armkit")
    err = _refused(["move", "200", "0", "100"], capsys)
    assert "the folder /proc does not take new files" in err and "ARMKIT_CONFIG_DIR" in err
