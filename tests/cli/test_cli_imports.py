"""The CLI starts light (issue 29 item 7): building the parser and ``armkit --help``
load no numpy and none of armkit's heavy packages, ``armkit ik`` loads the model and
the kinematics but no simulator, driver, arm or scene. No time is asserted: what is
checked is what a command imports, in a fresh process."""

from __future__ import annotations

import subprocess
import sys

import pytest

HEAVY = (
    "numpy", "matplotlib", "scipy", "usb", "serial", "dynamixel_sdk", "armkit.arm",
    "armkit.kinematics", "armkit.model._types", "armkit.sim", "armkit.drivers",
    "armkit.devices", "armkit.scene._scene", "armkit.motion", "armkit.tasks",
    "armkit.drawing", "armkit.music", "armkit.script", "armkit.viz", "armkit.connect._simulate",
    "mujoco", "armkit.physics",
)  # fmt: skip
IK_NEEDS = ("numpy", "armkit.kinematics", "armkit.model._types")  # a model holds numpy arrays


def loaded_after(code: str) -> list[str]:
    """The modules of ``HEAVY`` (or their sub-modules) loaded after ``code`` ran."""
    script = (
        "import contextlib, io, sys\n"
        f"with contextlib.redirect_stdout(io.StringIO()):\n    {code}\n"
        f"heavy = {HEAVY!r}\n"
        "print(' '.join(sorted({h for h in heavy for m in sys.modules "
        "if m == h or m.startswith(h + '.')})))\n"
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out.stdout.split()


def test_building_the_parser_loads_nothing_heavy() -> None:
    assert loaded_after("from armkit.cli._app import build_parser; build_parser()") == []


@pytest.mark.parametrize("words", [["--help"], ["ik", "--help"], ["move", "--help"]])
def test_help_loads_nothing_heavy(words: list[str]) -> None:
    code = f"from armkit.cli import main; main({words!r})"
    assert loaded_after(code) == []


def test_ik_loads_the_model_and_kinematics_only(config_dir: object) -> None:
    loaded = loaded_after("from armkit.cli import main; main(['ik', '200', '0', '100'])")
    assert "armkit.kinematics" in loaded and "numpy" in loaded
    assert [name for name in loaded if name not in IK_NEEDS] == []
