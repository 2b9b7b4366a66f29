"""``armkit draw``: the plan is printed before anything moves, then the strokes drawn so
far on stderr (``armkit._progress``), the final count last."""

from __future__ import annotations

import io
import sys
from pathlib import Path

import pytest

import armkit._progress as progress
from armkit.cli import main

TWO_STROKES = (
    "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='70mm' viewBox='0 0 100 70'>"
    "<line x1='10' y1='10' x2='40' y2='10' stroke='black'/>"
    "<line x1='10' y1='40' x2='40' y2='60' stroke='black'/></svg>"
)


def test_the_plan_comes_first_then_the_strokes_drawn(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(progress, "SHOW_AFTER", 0.0)  # show every update, however quick
    monkeypatch.setattr(progress, "EVERY", 0.0)
    svg = tmp_path / "two.svg"
    svg.write_text(TWO_STROKES)
    both = io.StringIO()  # stdout and stderr in the order written
    monkeypatch.setattr(sys, "stdout", both)
    monkeypatch.setattr(sys, "stderr", both)
    assert main(["--scene", "drawing", "draw", "svg", str(svg)]) == 0
    lines = both.getvalue().splitlines()
    assert lines[0].startswith("draw two.svg on A5 with pen: 2 strokes")
    shown = [line for line in lines if line.startswith("drawing two.svg: ")]
    counts = [line.split(": ")[1].split(" strokes")[0] for line in shown]
    assert counts[0] == "0/2" and counts[-1] == "2/2" and "1/2" in counts
    assert lines.index(shown[-1]) < len(lines) - 1 and lines[-1].startswith("drawn: ")


def test_a_dry_run_prints_the_plan_and_no_progress(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(progress, "SHOW_AFTER", 0.0)
    svg = tmp_path / "two.svg"
    svg.write_text(TWO_STROKES)
    assert main(["--scene", "drawing", "draw", "svg", str(svg), "--dry-run"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("draw two.svg on A5 with pen: 2 strokes") and err == ""
