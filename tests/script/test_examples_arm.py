"""Every example script passes ``armkit check``; those that need no job also run on
the simulator, and every job example's commands parse and check (warnings only)."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main
from armkit.script import check_file

SCRIPTS = sorted((Path(__file__).parents[2] / "examples" / "scripts").glob("*.arm"))


@pytest.mark.parametrize("path", SCRIPTS, ids=[p.name for p in SCRIPTS])
def test_example_checks(path: Path) -> None:
    result = check_file(path)
    assert result.ok, "\n".join(d.format(result.program.source) for d in result.diagnostics)


@pytest.mark.parametrize("path", SCRIPTS, ids=lambda p: p.name)
def test_every_example_runs_on_the_simulator(
    path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["run", str(path)]) == 0
    assert f"done: {path}" in capsys.readouterr().out


def test_there_is_an_example_per_feature_and_per_seed_job() -> None:
    names = {p.stem.split("_", 1)[1] for p in SCRIPTS}
    assert {"basic_motion", "poses", "repeat", "define", "owi_program"} <= names
    assert {"move_item_000", "board_001", "draw", "tune", "search_002"} <= names
