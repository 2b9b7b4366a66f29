"""Issue 10, item 5: one error contract. Every error a user can cause is an
ArmkitError, and a ValueError where it is a bad value."""

from __future__ import annotations

import ast
import builtins
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

import armkit
from armkit import Arm, ArmkitError, InputError
from armkit.model import load_model

SRC = Path(armkit.__file__).parent
OTHERS = ("kinematics", "sim")  # converted by their own engineers
BUILTIN_ERRORS = {
    name
    for name, value in vars(builtins).items()
    if isinstance(value, type) and issubclass(value, Exception)
} - {"EOFError"}  # end of input is not a mistake: the shell's reader keeps input()'s contract


def _raised_builtins(path: Path) -> list[str]:
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Raise) and node.exc is not None:
            call = node.exc.func if isinstance(node.exc, ast.Call) else node.exc
            if isinstance(call, ast.Name) and call.id in BUILTIN_ERRORS:
                found.append(f"{path.relative_to(SRC)}:{node.lineno} raises {call.id}")
    return found


def test_no_plain_builtin_errors_are_raised_outside_kinematics_and_sim() -> None:
    files = [p for p in SRC.rglob("*.py") if p.relative_to(SRC).parts[0] not in OTHERS]
    assert len(files) > 60
    assert [line for p in files for line in _raised_builtins(p)] == []


def test_every_error_class_is_an_armkit_error() -> None:
    from armkit import _errors

    classes = [
        v for v in vars(_errors).values() if isinstance(v, type) and issubclass(v, Exception)
    ]
    assert all(issubclass(c, ArmkitError) for c in classes)
    assert issubclass(InputError, ValueError) and issubclass(_errors.ReplyError, ValueError)


def _sim_arm() -> Arm:
    return Arm("openmanipulator_x", "sim")


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda arm: arm.move_joints(["a", 0, 0, 0]), "joint angles [deg] must be numbers"),
        (lambda arm: arm.move_joints([0, 0, 0]), "give 4 angles"),
        (lambda arm: arm.move_joints([float("nan")] * 4), "must be finite numbers of degrees, got nan"),
        (lambda arm: arm.grip(None), "grip width [mm] must be finite numbers, got None"),
        (lambda arm: arm.grip(500), "grip width 500.0 mm is outside"),
        (lambda arm: arm.move_to(200, None, 50), "x, y, z [mm] must be finite numbers"),
        (lambda arm: arm.follow([[1, 2], [3]]), "points_mm [mm] must be numbers"),
        (lambda arm: arm.turn_to("thumb", 3), "unknown joint 'thumb'"),
        (lambda arm: arm.move_joints([0, -60, 20, 40], speed=2), "speed must be a fraction"),
        (lambda arm: arm.move_joints([0, -60, 20, 40], timeout=-1), "timeout must be"),
    ],
)  # fmt: skip
def test_arm_refusals_are_input_errors(call: Callable[[Arm], object], words: str) -> None:
    with _sim_arm() as arm:
        before = arm.angles()
        with pytest.raises(InputError) as err:
            call(arm)
        assert words in str(err.value) and "np.float64" not in str(err.value)
        assert arm.angles() == before


def test_library_functions_refuse_with_input_errors() -> None:
    from armkit.connect import open_driver
    from armkit.motion import approach, line

    with pytest.raises(InputError, match="spacing must be > 0"):
        line(np.zeros(3), np.ones(3), 0.0)
    with pytest.raises(InputError, match="at most 1000000: use a larger spacing"):
        line(np.zeros(3), np.ones(3), 1e-9)
    with pytest.raises(InputError, match="at most 1000000"):
        line(np.zeros(3), [1e308, 1e308, 0], 0.002)
    with pytest.raises(InputError, match=r"start must be 3 numbers \[m\]"):
        line(["a", 0, 0], np.ones(3), 0.01)
    with pytest.raises(
        InputError, match=r"target must be 3 finite coordinates \[m\], got \(1, 2\)"
    ):
        approach([1, 2])
    with pytest.raises(InputError, match="unknown driver 'nope'"):
        open_driver(load_model("lynx6"), "nope")
