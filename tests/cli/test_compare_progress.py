"""``armkit compare-ik``: the heading before the work, then the calls made so far on
stderr (``armkit._progress``), the final count last; the table after."""

from __future__ import annotations

import io
import sys

import pytest

import armkit._progress as progress
from armkit.cli import main
from armkit.cli._compare_methods import compare_methods, reachable_targets
from armkit.model import load_model


def test_the_heading_comes_first_then_the_calls_made(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(progress, "SHOW_AFTER", 0.0)  # show every update, however quick
    monkeypatch.setattr(progress, "EVERY", 0.0)
    both = io.StringIO()  # stdout and stderr in the order written
    monkeypatch.setattr(sys, "stdout", both)
    monkeypatch.setattr(sys, "stderr", both)
    assert main(["--arm", "planar2", "compare-ik", "--n", "5", "--seed", "0"]) == 0
    lines = both.getvalue().splitlines()
    assert lines[0].startswith("planar2: 5 reachable targets, task position, seed 0")
    shown = [line for line in lines if line.startswith("compare-ik: ")]
    assert shown[0].startswith("compare-ik: 0/") and ", method analytic, " in shown[0]
    total = shown[0].split("/")[1].split()[0]
    assert shown[-1].startswith(f"compare-ik: {total}/{total} calls")
    assert lines.index(shown[-1]) < lines.index(next(x for x in lines if x.startswith("method")))


def test_progress_is_told_each_target_of_each_method() -> None:
    model = load_model("planar2")
    targets = reachable_targets(model, 4, 0, "position")
    told: list[tuple[str, int]] = []
    compare_methods(model, targets, ["lm", "lm-batch"], progress=lambda m, n: told.append((m, n)))
    assert told == [("lm", k) for k in (0, 1, 2, 3, 4, 4)] + [("lm-batch", 0), ("lm-batch", 4)]
