"""Bad input: ValueError naming the argument and what is allowed."""

from __future__ import annotations

import numpy as np
import pytest

from armkit.kinematics import Target, ik, ik_batch
from armkit.model import load_model

MODEL = load_model("openmanipulator_x")
P = np.array([0.2, 0.0, 0.1])


@pytest.mark.parametrize(
    ("target", "word"),
    [
        (Target(np.array([np.nan, 0.0, 0.1])), "position"),
        (Target(np.array([np.inf, 0.0, 0.1])), "position"),
        (Target(np.array([0.2, 0.0])), "position"),
        (Target(P, pitch=float("nan")), "pitch"),
        (Target(P, orientation=np.eye(3) * 2.0), "orientation"),
        (Target(P, orientation=np.diag([1.0, 1.0, -1.0])), "orientation"),
        (Target(P, orientation=np.eye(4)), "orientation"),
        (Target(P, orientation=np.full((3, 3), np.nan)), "orientation"),
    ],
)
def test_bad_target_names_the_field(target: Target, word: str) -> None:
    with pytest.raises(ValueError, match=word):
        ik(MODEL, target, q_seed=MODEL.home, method="lm")


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
