"""The CLI as a user runs it: good input, bad input (one line, non-zero, no traceback)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from armkit.cli import main


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    try:
        code = main(list(argv))
    except SystemExit as exc:  # argparse's own errors
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    return code, out, err


def test_arms_and_show(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "arms")
    assert code == 0 and "owi535" in out and "planar2" in out
    code, out, _ = run(capsys, "--arm", "lynx6", "show")
    assert code == 0 and "hand" in out and "standard" in out and "120.65" in out


def test_fk_json_shape(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "--arm", "owi535", "fk", "0", "30", "60", "0", "--json")
    data = json.loads(out)
    assert code == 0
    assert set(data) == {"arm", "joints_deg", "position_mm", "pitch_deg"}
    assert list(data["joints_deg"]) == ["base", "shoulder", "elbow", "wrist"]
    assert data["position_mm"][1] == 0.0


def test_ik_json_round_trips_through_fk(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "ik", "200", "0", "50", "--pitch", "-90", "--all", "--json")
    data = json.loads(out)
    assert code == 0 and data["target_mm"] == [200.0, 0.0, 50.0] and data["solutions"]
    for sol in data["solutions"]:
        angles = [str(v) for v in sol["joints_deg"].values()]
        _, fk_out, _ = run(capsys, "fk", *angles, "--json")
        pos = json.loads(fk_out)["position_mm"]
        assert all(abs(a - b) < 0.01 for a, b in zip(pos, [200, 0, 50], strict=True))


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["--arm", "nope", "fk", "0"], "unknown arm 'nope'"),
        (["fk", "0", "0", "0"], "needs 4 joint angles"),
        (["fk", "0", "x", "0", "0"], "argument DEG: must be a number of deg, got 'x'"),
        (["ik", "900", "0", "0"], "too far"),
        (["ik", "200", "0"], "the following arguments are required"),
        (["ik", "200", "0", "nan"], "argument Z: must be -100000..100000 mm, got nan"),
        (["--arm", "planar2", "ik", "500", "100", "500"], "outside the arm's plane"),
        (["ik", "200", "0", "50", "--method", "newton"], "invalid choice: 'newton'"),
        (["mvoe", "200", "0", "50"], "invalid choice: 'mvoe'; did you mean 'move'?"),
        (["draw", "circel"], "invalid choice: 'circel'; did you mean 'circle'?"),
        (["xyzzy"], "invalid choice: 'xyzzy' (choose from 'arms', 'show',"),
        (["--arm", "puma560", "ik", "400", "100", "300", "--method", "analytic"], "use a numeric"),
        (
            ["--arm", "al5d", "ik", "900", "0", "0", "--method", "lm"],
            "al5d cannot reach (900.0, 0.0, 0.0) mm: too far",
        ),
    ],
)
def test_bad_input_is_one_line(
    capsys: pytest.CaptureFixture[str], argv: list[str], needle: str
) -> None:
    code, out, err = run(capsys, *argv)
    assert code != 0 and out == ""
    assert needle in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err


@pytest.mark.parametrize("method", ["lm", "ccd", "jacobian"])
def test_ik_numeric_method_reaches_the_point(
    capsys: pytest.CaptureFixture[str], method: str
) -> None:
    code, out, _ = run(
        capsys, "--arm", "al5d", "ik", "200", "0", "100", "--method", method, "--json"
    )
    data = json.loads(out)
    assert code == 0 and data["method"] == method and data["iterations"] >= 1
    angles = [str(v) for v in data["solutions"][0]["joints_deg"].values()]
    _, fk_out, _ = run(capsys, "--arm", "al5d", "fk", *angles, "--json")
    pos = json.loads(fk_out)["position_mm"]
    assert all(abs(a - b) < 0.01 for a, b in zip(pos, [200, 0, 100], strict=True))


def test_plot_writes_png(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "pose.png"
    code, _, _ = run(capsys, "--arm", "owi535", "plot", "20", "30", "60", "0", "-o", str(target))
    assert code == 0 and target.stat().st_size > 5000 and target.read_bytes()[:4] == b"\x89PNG"


def test_demo_runs(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "demo", "-o", str(tmp_path / "d.png"))
    assert code == 0 and "stacks them" in out and (tmp_path / "d.png").exists()


def test_help_imports_no_heavy_modules() -> None:
    """``armkit --help`` must not import matplotlib, scipy or any device SDK."""
    code = (
        "import sys, contextlib, io\n"
        "from armkit.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    try:\n        main(['--help'])\n    except SystemExit:\n        pass\n"
        "bad = [m for m in ('matplotlib', 'scipy', 'usb', 'serial', 'dynamixel_sdk') if m in sys.modules]\n"
        "print(','.join(bad))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_console_script_exists() -> None:
    exe = Path(sys.executable).parent / "armkit"
    out = subprocess.run([str(exe), "--help"], capture_output=True, text=True, check=True)
    assert "millimetres" in out.stdout and "degrees" in out.stdout


def test_version(capsys: pytest.CaptureFixture[str]) -> None:
    import armkit

    code, out, _ = run(capsys, "--version")
    assert code == 0 and out.strip() == f"armkit {armkit.__version__}"
