"""``--driver sim`` needs only numpy: a clean virtual environment with numpy and armkit,
and none of pyserial, pyusb or the dynamixel-sdk, runs every shipped arm on the same
driver class with the same bytes on the wire as the full environment.

The environment is built once, offline: ``python -m venv --without-pip``, then a
``.pth`` file naming armkit's ``src`` (what ``pip install --no-deps -e .`` writes) and
a folder holding nothing but this interpreter's numpy. (``.ci/run`` also builds one
the long way, from the package index.)
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import sysconfig
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from armkit.kinematics import fk, pitch_of
from armkit.model import load_model, shipped_models

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = Path(__file__).with_name("sim_wire_script.py")


@pytest.fixture(scope="module")
def numpy_only(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    """The python of a fresh venv that has numpy and armkit and nothing else."""
    base = tmp_path_factory.mktemp("numpy-only")
    venv = base / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    only = base / "numpy-only"
    only.mkdir()
    numpy_dir = Path(np.__file__).resolve().parent
    for name in ("numpy", "numpy.libs"):
        if (numpy_dir.parent / name).exists():
            (only / name).symlink_to(numpy_dir.parent / name)
    python = venv / "bin" / "python"
    site = subprocess.run(
        [str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout.strip()
    assert site != sysconfig.get_paths()["purelib"]
    Path(site, "armkit-numpy-only.pth").write_text(f"{ROOT / 'src'}\n{only}\n")
    yield python


def _run(python: Path, args: list[str], config: Path) -> subprocess.CompletedProcess[str]:
    env = {"ARMKIT_CONFIG_DIR": str(config), "PATH": os.environ.get("PATH", "/usr/bin:/bin")}
    return subprocess.run(
        [str(python), *args], capture_output=True, text=True, env=env, timeout=600, check=False
    )


def test_the_venv_has_numpy_and_no_client_library(numpy_only: Path, tmp_path: Path) -> None:
    code = (
        "import importlib.util as u, numpy, armkit; "
        "print([m for m in ('serial', 'usb', 'dynamixel_sdk', 'matplotlib') if u.find_spec(m)])"
    )
    out = _run(numpy_only, ["-c", code], tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"


def _cli(python: Path, argv: list[str], config: Path) -> str:
    code = f"import sys; from armkit.cli import main; sys.exit(main({argv!r}))"
    out = _run(python, ["-c", code], config)
    assert out.returncode == 0, out.stderr
    return out.stdout


def _xyz(text: str) -> np.ndarray:
    words = text.split("gripper at ")[1].split()
    return np.array([float(words[i]) for i in (1, 3, 5)])


@pytest.mark.parametrize("arm", shipped_models())
def test_where_joints_and_move_on_every_arm(numpy_only: Path, tmp_path: Path, arm: str) -> None:
    model = load_model(arm)
    span = model.upper - model.lower
    q = np.clip(model.home + 0.05 * span, model.lower, model.upper)
    pose = fk(model, q)
    target, pitch = pose[:3, 3] * 1000.0, float(np.degrees(pitch_of(pose)))
    base = ["--arm", arm, "--driver", "sim"]
    assert "gripper at" in _cli(numpy_only, [*base, "where"], tmp_path)
    angles = [f"{a:.3f}" for a in np.degrees(q)]
    _cli(numpy_only, [*base, "joints", *angles], tmp_path)
    assert np.linalg.norm(_xyz(_cli(numpy_only, [*base, "where"], tmp_path)) - target) < 2.0
    _cli(numpy_only, [*base, "home"], tmp_path)
    where_to = [f"{v:.2f}" for v in target]
    if model.dof > 2:  # a two-link arm cannot choose its pitch
        where_to += ["--pitch", f"{pitch:.3f}"]
    moved = _cli(numpy_only, [*base, "move", *where_to], tmp_path)
    assert np.linalg.norm(_xyz(moved) - target) < 2.0


def test_same_driver_class_and_same_bytes_with_and_without_the_libraries(
    numpy_only: Path, tmp_path: Path
) -> None:
    bare = _run(numpy_only, [str(SCRIPT)], tmp_path / "bare")
    full = _run(Path(sys.executable), [str(SCRIPT)], tmp_path / "full")
    assert bare.returncode == 0, bare.stderr
    assert full.returncode == 0, full.stderr
    without, with_libs = json.loads(bare.stdout), json.loads(full.stdout)
    assert not any(without["libraries"].values())
    assert all(with_libs["libraries"].values())
    assert without["arms"] == with_libs["arms"]
    assert {name: arm["driver"] for name, arm in without["arms"].items()} == {
        "al5d": "ServoArmDriver",
        "lynx6": "ServoArmDriver",
        "openmanipulator_x": "DynamixelDriver",
        "owi535": "TimedDriver",
        "planar2": "DynamixelDriver",
        "puma560": "DynamixelDriver",
        "so100": "FeetechDriver",
        "so101": "FeetechDriver",
    }
