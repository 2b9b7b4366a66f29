"""Following an arm another process moves (``armkit view --follow``), and ``--view``
and ``--gif`` on the commands that move the arm (``armkit.cli._watch``)."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import armkit
from armkit.cli import main
from armkit.connect import sim_state_file
from armkit.viz import LiveSource, ObjectPose, Snapshot
from armkit.viz._live import decode, encode, follow_path, live_path

OMX = armkit.load_model("openmanipulator_x")
ARMKIT = [sys.executable, "-c", "from armkit.cli import main; raise SystemExit(main())"]


def test_a_snapshot_survives_the_channel() -> None:
    T = np.eye(4)
    T[:3, 3] = (0.2, -0.05, 0.03)
    state = Snapshot(1.25, np.radians([10.0, 20.0, -30.0, 40.0]), 0.031, (ObjectPose("red", T),))
    back = decode(encode(state), OMX.dof)
    assert back.t == 1.25 and back.grip == 0.031
    np.testing.assert_array_equal(back.q, state.q)
    assert back.objects[0].name == "red"
    np.testing.assert_array_equal(back.objects[0].T, T)
    with pytest.raises(ValueError, match="5 joint angles"):
        decode(encode(state), 5)


def test_nobody_following_means_nothing_is_published(config_dir: Path) -> None:
    assert main(["joints", "30", "0", "0", "0"]) == 0
    assert not live_path(sim_state_file(OMX)).exists()


def test_the_follower_sees_another_process_move_the_arm_as_it_moves(config_dir: Path) -> None:
    source = LiveSource(OMX, sim_state_file(OMX))
    np.testing.assert_array_equal(source.state().q, OMX.home)  # nothing kept yet: home
    assert follow_path(sim_state_file(OMX)).exists()
    move = [*ARMKIT, "joints", "60", "0", "0", "0", "--duration", "1.0"]
    proc = subprocess.Popen(move, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seen = []
    while proc.poll() is None:
        seen.append(source.state().q.copy())
        time.sleep(0.01)
    assert proc.returncode == 0, proc.stderr.read() if proc.stderr else ""
    seen.append(source.state().q.copy())
    # the waist passed through many angles between home and 60 deg, in order
    waist = np.degrees([q[0] for q in seen])
    between = np.unique(np.round(waist[(waist > 1.0) & (waist < 59.0)], 3))
    assert len(between) >= 5, waist
    assert np.all(np.diff(waist) >= -1e-6)
    assert waist[-1] == pytest.approx(60.0, abs=0.1)
    source.close()
    assert not follow_path(sim_state_file(OMX)).exists()


def test_gif_on_a_task_records_the_cube_carried(tmp_path: Path, config_dir: Path) -> None:
    out = tmp_path / "pick.gif"
    code = main(["--scene", "board_001", "pick", "green", "--gif", str(out), "--fps", "5"])
    assert code == 0
    from PIL import Image

    with Image.open(out) as img:
        assert img.n_frames > 5
        first = np.asarray(img.convert("RGB"))
        img.seek(img.n_frames - 1)
        last = np.asarray(img.convert("RGB"))
    assert np.abs(first.astype(int) - last.astype(int)).sum() > 0


@pytest.mark.parametrize(
    ("words", "message"),
    [
        (["joints", "30", "0", "0", "0", "--gif", "{tmp}/a.png"], "must end in .gif"),
        (["joints", "30", "0", "0", "0", "--gif", "{tmp}/no/a.gif"], "does not exist"),
        (["joints", "30", "0", "0", "0", "--fps", "0", "--gif", "{tmp}/a.gif"], "--fps"),
        (["--driver", "ssc32", "home", "--view"], "simulated arm"),
        (["--scene", "board_001", "pick", "red", "--view", "--view-wait", "-1"], "--view-wait"),
        (["move", "200", "0", "50", "--view", "--view-port", "70000"], "--view-port"),
    ],
)
def test_watch_refusals_move_nothing_and_write_nothing(
    words: list[str],
    message: str,
    tmp_path: Path,
    config_dir: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    code = main([w.format(tmp=tmp_path) for w in words])
    err = capsys.readouterr().err
    assert code == 2 and message in err and err.count("\n") == 1
    assert not sim_state_file(OMX).exists()
    assert not list(tmp_path.rglob("*.gif"))


def test_view_serves_the_job_in_real_time(
    config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code = main(["joints", "20", "0", "0", "0", "--view", "--view-port", "0", "--view-wait", "0"])
    out = capsys.readouterr().out
    assert code == 0
    assert "live view at http://127.0.0.1:" in out and "waist 20.00" in out
