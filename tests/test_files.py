"""``armkit._files.check_output_path``: the one check of every file armkit is asked to
write, proven by creating and removing a temporary file beside it (so /proc, read-only
mounts and permissions are refused up front, also when running as root), one line,
writing nothing that stays; and ``folder_problem`` for folders armkit creates."""

from __future__ import annotations

import errno
import os
import sys
from pathlib import Path

import pytest

from armkit import ArmkitError, InputError
from armkit._files import check_output_path, folder_problem, write_atomic


def _refusal(path: object, option: str = "", suffixes: tuple[str, ...] = ()) -> str:
    with pytest.raises(InputError) as caught:
        check_output_path(path, option, suffixes)  # type: ignore[arg-type]
    message = str(caught.value)
    assert "\n" not in message and isinstance(caught.value, ArmkitError | ValueError)
    return message


def test_a_writable_path_is_returned_and_nothing_stays(tmp_path: Path) -> None:
    (tmp_path / "old.png").write_bytes(b"keep")
    assert check_output_path(tmp_path / "new.png", "-o", (".png",)) == tmp_path / "new.png"
    assert check_output_path(str(tmp_path / "old.png"), "-o", (".PNG",)) == tmp_path / "old.png"
    assert check_output_path(tmp_path / "ANY.Wav", suffixes=(".wav",)).name == "ANY.Wav"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.png"]
    assert (tmp_path / "old.png").read_bytes() == b"keep"


def test_home_is_expanded(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("HOME", str(tmp_path))
    assert check_output_path("~/x.urdf") == tmp_path / "x.urdf"


def test_a_directory_is_refused_with_what_to_do(tmp_path: Path) -> None:
    message = _refusal(tmp_path, "-o/--output")
    assert message == f"-o/--output: cannot write {tmp_path}: it is a directory; give a file name inside it"  # fmt: skip
    assert list(tmp_path.iterdir()) == []  # no temporary file beside it either


def test_a_missing_or_non_folder_parent_is_refused(tmp_path: Path) -> None:
    assert "the folder" in (m := _refusal(tmp_path / "no" / "x.wav")) and "does not exist" in m
    (tmp_path / "file").write_text("")
    assert "is not a folder" in _refusal(tmp_path / "file" / "x.wav")


def test_proc_is_refused_by_the_probe() -> None:
    if not Path("/proc").is_dir():
        pytest.skip("no /proc here")
    message = _refusal("/proc/x.wav", "--wav", (".wav",))
    assert message.startswith("--wav: cannot write /proc/x.wav: the folder /proc does not take new files (")  # fmt: skip
    assert message.endswith("; choose a file in a folder you can write to")


def test_an_unwritable_folder_is_refused_even_as_root(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def denied(*args: object, **kwargs: object) -> tuple[int, str]:
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr("tempfile.mkstemp", denied)  # armkit._files imports it where used
    message = _refusal(tmp_path / "x.gif", "--gif", (".gif",))
    assert message == (
        f"--gif: cannot write {tmp_path / 'x.gif'}: the folder {tmp_path} does not take new "
        "files (Permission denied); choose a file in a folder you can write to"
    )
    assert folder_problem(tmp_path / "new" / "deeper") == (
        f"the folder {tmp_path} does not take new files (Permission denied)"
    )


def test_a_read_only_file_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "x.csv").write_text("old")
    monkeypatch.setattr("armkit._files.os.access", lambda path, mode: False)
    assert "the file is read-only" in _refusal(tmp_path / "x.csv", "--record")


@pytest.mark.skipif(sys.platform == "win32", reason="no FIFOs")
def test_a_pipe_or_device_is_refused(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "pipe.csv")
    assert "not a regular file" in _refusal(tmp_path / "pipe.csv")
    if Path("/dev/null").exists():
        assert "not a regular file" in _refusal("/dev/null")


@pytest.mark.parametrize(
    ("name", "suffixes", "says"),
    [
        ("x.mp3", (".wav",), "the file name must end in .wav; name it like out.wav"),
        ("x", (".wav",), "must end in .wav"),
        ("x.jpg", (".png", ".svg", ".pdf"), "must end in one of .png, .svg, .pdf"),
    ],
)
def test_a_wrong_suffix_is_refused_first(
    tmp_path: Path, name: str, suffixes: tuple[str, ...], says: str
) -> None:
    assert says in _refusal(tmp_path / "missing" / name, "", suffixes)


def test_an_empty_or_too_long_name_is_refused(tmp_path: Path) -> None:
    assert "no file name given" in _refusal("", "--plot")
    assert "too long" in _refusal(tmp_path / ("n" * 250 + ".png"))


def test_folders_armkit_would_create(tmp_path: Path) -> None:
    assert folder_problem(tmp_path / "a" / "b") is None
    assert folder_problem(tmp_path) is None and list(tmp_path.iterdir()) == []
    (tmp_path / "file").write_text("")
    assert folder_problem(tmp_path / "file" / "c") == f"{tmp_path / 'file'} is not a folder"
    if Path("/proc").is_dir():
        assert "the folder /proc does not take new files" in str(folder_problem(Path("/proc/a")))


def test_the_checked_path_is_what_the_atomic_writer_writes(tmp_path: Path) -> None:
    path = check_output_path(tmp_path / "robot.urdf", "-o")
    write_atomic(path, "<robot/>\n")
    assert path.read_text() == "<robot/>\n"
    assert [p.name for p in tmp_path.iterdir()] == ["robot.urdf"]
