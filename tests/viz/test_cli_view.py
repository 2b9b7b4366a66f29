"""``armkit view``: refusals before anything runs, and the GIF recorder."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--screenshot", "{tmp}/pic.jpg"], "must end in .png"),
        (["--screenshot", "{tmp}/missing/pic.png"], "does not exist"),
        (["--gif", "{tmp}/anim.png"], "must end in .gif"),
        (["--gif", "{tmp}/a.gif", "--screenshot", "{tmp}/b.png"], "not both"),
        (["--pose", "0", "0", "--gif", "{tmp}/a.gif"], "needs 4 angles"),
        (["--pose", "0", "120", "0", "0", "--gif", "{tmp}/a.gif"], "joint limits"),
        (["--pitch", "-90"], "--pitch needs --target"),
        (["--port", "70000"], "--port must be"),
        (["--rate", "0"], "--rate must be"),
        (["--size", "10", "10", "--screenshot", "{tmp}/p.png"], "--size must be"),
        (["--follow", "--pose", "0", "0", "0", "0"], "--follow only watches"),
        (["--follow", "--gif", "{tmp}/a.gif"], "--follow only watches"),
        (["--write", "{tmp}/taught.txt"], "must end in .arm"),
        (["--write", "{tmp}/missing/taught.arm"], "does not exist"),
        (["--follow", "--write", "{tmp}/taught.arm"], "drop --follow"),
    ],
)
def test_refusals_are_one_line_and_touch_nothing(
    args: list[str],
    words: str,
    tmp_path: Path,
    config_dir: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    code = main(["view", *(a.format(tmp=tmp_path) for a in args)])
    err = capsys.readouterr().err
    assert code == 2
    assert err.startswith("armkit: error: ") and words in err and err.count("\n") == 1
    assert not any(p.suffix in (".png", ".gif", ".arm") for p in tmp_path.rglob("*"))
    assert not config_dir.exists()  # no simulated arm was opened


def test_gif_of_a_joint_path(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "path.gif"
    code = main(
        [
            "--scene",
            "board_001",
            "view",
            "--gif",
            str(out),
            "--fps",
            "5",
            "--pose",
            "30",
            "0",
            "0",
            "0",
        ]
    )
    assert code == 0, capsys.readouterr().err
    data = out.read_bytes()
    assert data[:6] in (b"GIF87a", b"GIF89a")
    from PIL import Image

    with Image.open(out) as img:
        assert img.n_frames > 3
    assert "frames" in capsys.readouterr().out


def test_view_serves_the_page_on_loopback_until_ctrl_c(config_dir: Path) -> None:
    import os
    import signal
    import subprocess
    import sys
    import urllib.request

    cmd = [
        sys.executable,
        "-c",
        "from armkit.cli import main; raise SystemExit(main())",
        "view",
        "--port",
        "0",
        "--write",
        str(config_dir.parent / "page.arm"),
    ]
    env = dict(os.environ, ARMKIT_CONFIG_DIR=str(config_dir))
    proc = subprocess.Popen(
        cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env
    )
    try:
        assert proc.stdout is not None
        line = proc.stdout.readline()
        assert line.startswith("armkit view: http://127.0.0.1:") and "Ctrl-C" in line, line
        url = line.split()[2]
        with urllib.request.urlopen(url, timeout=10) as reply:
            assert b"<html" in reply.read(2000).lower()
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 0
    assert "stopped" in out
    assert f"wrote 0 poses to {config_dir.parent / 'page.arm'}" in out
    assert main(["check", str(config_dir.parent / "page.arm")]) == 0


def test_a_target_is_a_marker_and_the_kept_arm_stays(
    config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """'view --target' is documented as a marker, and it moved the kept simulated arm to the
    target (a later task then started with the gripper 16 mm above a cube)."""
    import os
    import signal
    import subprocess
    import sys

    assert main(["where"]) == 0
    before = capsys.readouterr().out
    cmd = [sys.executable, "-c", "from armkit.cli import main; raise SystemExit(main())"]
    cmd += ["--scene", "board_001", "view", "--port", "0", "--target", "220", "0", "16"]
    env = dict(os.environ, ARMKIT_CONFIG_DIR=str(config_dir))
    proc = subprocess.Popen(
        [*cmd, "--pitch", "-90"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
        env=env,
    )  # fmt: skip
    try:
        assert proc.stdout is not None
        said = [proc.stdout.readline() for _ in range(2)]
        assert "on green" in said[0] and said[1].startswith("armkit view: http://"), said
        proc.send_signal(signal.SIGINT)
        proc.communicate(timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert main(["where"]) == 0
    assert capsys.readouterr().out == before
