"""``import armkit`` loads only what its names need (issue 29 item 7): the public
names are loaded from their packages on first use (PEP 562), and each is the very
object its package exports (the lazy path pinned to the direct one)."""

from __future__ import annotations

import subprocess
import sys

import pytest

import armkit
from armkit import arm, kinematics, model

PACKAGES = {
    "Arm": arm, "Position": arm, "IKBatchResult": kinematics, "IKResult": kinematics,
    "Target": kinematics, "fk": kinematics, "fk_frames": kinematics, "ik": kinematics,
    "ik_batch": kinematics, "jacobian": kinematics, "pitch_of": kinematics,
    "ArmModel": model, "load_model": model,
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(PACKAGES))
def test_every_lazy_name_is_its_packages_object(name: str) -> None:
    assert getattr(armkit, name) is getattr(PACKAGES[name], name)
    assert name in dir(armkit)


def test_an_unknown_name_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        armkit.nothing  # type: ignore[attr-defined]  # noqa: B018
    with pytest.raises(armkit.ArmkitError):
        armkit.nothing  # type: ignore[attr-defined]  # noqa: B018
    assert not hasattr(armkit, "nothing")


def test_import_armkit_loads_no_numpy_and_no_arm() -> None:
    code = (
        "import sys, armkit; "
        "print(sorted(m for m in ('numpy', 'armkit.arm', 'armkit.kinematics', "
        "'armkit.model', 'armkit.sim', 'mujoco', 'armkit.physics') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
    code = "import armkit; from armkit import ik; print(ik.__module__)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip().startswith("armkit.kinematics")
