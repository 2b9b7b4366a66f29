"""The picture writers of the API prove their path writable before drawing anything:
a folder that takes no files (/proc), a directory or a wrong suffix is an InputError
naming the path, and nothing is written."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit import InputError, load_model
from armkit.viz import Snapshot, plot_pose, write_gif, write_picture

LYNX = load_model("lynx6")
STATE = Snapshot(0.0, LYNX.home, 0.02)


@pytest.mark.parametrize(
    ("write", "path", "why"),
    [
        (lambda p: plot_pose(LYNX, LYNX.home, p), "/proc/pose.png", "does not take new files"),
        (lambda p: write_picture(LYNX, STATE, p), "/proc/arm.png", "does not take new files"),
        (lambda p: write_gif(LYNX, [STATE, STATE], p), "/proc/arm.gif", "does not take new files"),
        (lambda p: write_gif(LYNX, [STATE, STATE], p), "/proc/arm.png", "must end in .gif"),
    ],
)
def test_picture_writers_refuse_before_drawing(write, path: str, why: str) -> None:  # type: ignore[no-untyped-def]
    if path.startswith("/proc") and not Path("/proc").is_dir():
        pytest.skip("no /proc here")
    with pytest.raises(InputError, match=why):
        write(path)
    assert not Path(path).exists()


def test_a_directory_is_refused(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="is a directory"):
        plot_pose(LYNX, LYNX.home, tmp_path)
