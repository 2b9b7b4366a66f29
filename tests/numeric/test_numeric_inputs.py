"""Bad input: ValueError naming the argument and what is allowed."""

from __future__ import annotations

import numpy as np
import pytest

from armkit import InputError
from armkit.kinematics import Target, ik, ik_batch
from armkit.model import load_model

MODEL = load_model("openmanipulator_x")
P = np.array([0.2, 0.0, 0.1])


@pytest.mark.parametrize(
    ("args", "word"),
    [
        (("abc",), "position must be numbers"),
        ((np.array([np.nan, 0.0, 0.1]),), "position"),
        ((np.array([np.inf, 0.0, 0.1]),), "position"),
        ((np.array([0.2, 0.0]),), "position"),
        ((np.zeros((2, 3, 1)),), "position"),
        ((P, float("nan")), "pitch"),
        ((P, "up"), "pitch"),
        ((P, np.zeros(3)), "pitch"),
        ((np.zeros((2, 3)), np.zeros(3)), "pitch"),
        ((P, None, np.eye(3) * 2.0), "orientation"),
        ((P, None, np.diag([1.0, 1.0, -1.0])), "orientation"),
        ((P, None, np.eye(4)), "orientation"),
        ((P, None, np.full((3, 3), np.nan)), "orientation"),
        ((np.zeros((2, 3)), None, np.eye(3)), "orientation"),
        ((P, 0.1, np.eye(3)), "not both"),
    ],
)
def test_bad_target_is_refused_when_made_naming_the_field(
    args: tuple[object, ...], word: str
) -> None:
    with pytest.raises(InputError, match=word):
        Target(*args)  # type: ignore[arg-type]


def test_good_targets_are_kept_as_given() -> None:
    assert Target([0.2, 0.0, 0.1]).mask == "position"
    assert Target(np.zeros((2, 3)), 0.1).mask == "position+pitch"
    assert Target(np.zeros((2, 3)), np.zeros(2)).pitch.shape == (2,)
    assert Target(np.zeros((0, 3)), None, np.zeros((0, 3, 3))).mask == "pose"
    assert Target(P, None, np.eye(3)).orientation is not None


def test_unknown_method_lists_the_valid_ones() -> None:
    with pytest.raises(
        ValueError, match="method must be one of auto, analytic, lm, ccd, jacobian, random"
    ):
        ik(MODEL, Target(P), method="newton")  # type: ignore[arg-type]


@pytest.mark.parametrize("seed", [np.zeros(3), np.array([0.0, np.nan, 0.0, 0.0]), "home"])
def test_bad_seed_names_q_seed(seed: object) -> None:
    with pytest.raises(ValueError, match="q_seed"):
        ik(MODEL, Target(P), q_seed=seed, method="lm")  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("tol_pos", "tol_ang", "word"), [(0.0, 1e-4, "tol_m"), (1e-5, np.nan, "tol_rad")]
)
def test_bad_tolerance_names_it(tol_pos: float, tol_ang: float, word: str) -> None:
    with pytest.raises(ValueError, match=word):
        ik(MODEL, Target(P), method="lm", tol_m=tol_pos, tol_rad=tol_ang)


@pytest.mark.parametrize(
    ("kwargs", "word"),
    [
        ({"positions": np.zeros(3)}, "positions"),
        ({"positions": np.full((2, 3), np.inf)}, "positions"),
        ({"positions": np.zeros((2, 3)), "pitches": np.zeros(3)}, "pitches"),
        ({"positions": np.zeros((2, 3)), "orientations": np.zeros((2, 3, 3))}, "orientations"),
        ({"positions": np.zeros((2, 3)), "q_seed": np.zeros((3, 4))}, "q_seed"),
    ],
)
def test_bad_batch_input_names_the_argument(kwargs: dict[str, object], word: str) -> None:
    args: dict[str, object] = {
        "positions": None,
        "pitches": None,
        "orientations": None,
        "q_seed": MODEL.home,
    }
    args.update(kwargs)
    with pytest.raises(ValueError, match=word):
        ik_batch(
            MODEL,
            args["positions"],
            args["pitches"],
            args["q_seed"],
            orientations=args["orientations"],
            method="lm",
        )  # type: ignore[arg-type]
