"""compare-ik: the same targets for every method, verified by FK; the CLI prints a table."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from armkit.cli import main
from armkit.cli._compare_methods import (
    applicable_methods,
    compare_methods,
    reachable_targets,
    verified,
)
from armkit.model import load_model


def test_targets_are_reproducible_and_reachable() -> None:
    model = load_model("al5d")
    a = reachable_targets(model, 20, 3, "position+pitch")
    b = reachable_targets(model, 20, 3, "position+pitch")
    np.testing.assert_array_equal(a.T, b.T)
    assert model.within_limits(a.q).all()
    assert verified(model, a, a.q).all()


def test_verified_rejects_wrong_answers_and_limit_violations() -> None:
    model = load_model("openmanipulator_x")
    t = reachable_targets(model, 5, 1, "position")
    q = t.q.copy()
    q[0, 0] += 0.1  # moves the tool by far more than 1 mm
    q[1] = np.nan  # no answer
    q[2, 1] = model.upper[1] + 0.01  # outside the limits
    assert verified(model, t, q).tolist() == [False, False, False, True, True]


def test_compare_scores_every_applicable_method() -> None:
    model = load_model("planar2")
    assert applicable_methods(model, "position")[0] == "analytic"
    puma = load_model("puma560")  # the spherical wrist's closed form takes a full pose only
    assert "analytic" in applicable_methods(puma, "pose")
    assert "analytic" not in applicable_methods(puma, "position")
    scores = compare_methods(model, reachable_targets(model, 10, 0, "position"))
    assert [s.method for s in scores] == list(applicable_methods(model, "position"))
    by = {s.method: s for s in scores}
    assert by["lm"].success == 1.0 and by["lm-batch"].success == 1.0
    assert all(0.0 <= s.success <= 1.0 and s.median_s > 0 for s in scores)


def test_cli_prints_the_table(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--arm", "planar2", "compare-ik", "--n", "5", "--seed", "2"]) == 0
    out = capsys.readouterr().out
    assert "planar2: 5 reachable targets, task position, seed 2" in out
    for method in ("analytic", "lm", "lm-batch", "ccd", "jacobian", "random"):
        assert f"\n{method} " in out


def test_cli_writes_a_chart(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "ik.png"
    assert main(["--arm", "planar2", "compare-ik", "--n", "3", "--plot", str(path)]) == 0
    assert path.stat().st_size > 1000


@pytest.mark.parametrize(
    ("argv", "word"),
    [
        (["compare-ik", "--n", "0"], "argument --n: must be 1..100000 targets, got 0"),
        (["compare-ik", "--repeats", "0"], "repeats"),
    ],
)
def test_cli_bad_input_is_one_line_and_non_zero(
    argv: list[str], word: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["--arm", "planar2", *argv]) == 2
    err = capsys.readouterr().err
    assert word in err and err.count("\n") == 1
