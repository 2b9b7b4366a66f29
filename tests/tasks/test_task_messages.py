"""Task refusals say what to do: a cube under another (it said 'its jaws would hold
only the top -32.0 mm of red'), a place with neither TO nor --xyz (it said 'not both')."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main


def test_a_covered_cube_says_what_is_on_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    state = ["--scene", "board_001"]  # the simulated arm kept in the test's config folder
    assert main([*state, "pick", "blue", "--pitch", "0"]) == 0  # from the side: upright on red
    assert main([*state, "place", "blue", "red"]) == 0
    capsys.readouterr()
    for args, task in (
        (["pick", "red"], "pick red"),
        (["move-item", "red", "board[1,1]"], "move red"),
    ):
        assert main([*state, *args]) == 2
        err = capsys.readouterr().err
        assert err == f"armkit: error: {task}: cannot pick red: it is under blue; move blue first\n"
    assert main([*state, "move-item", "blue", "board[0,2]"]) == 0
    assert main([*state, "pick", "red"]) == 0


def test_place_without_a_target_or_with_two(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--scene", "board_001", "place", "red"]) == 2
    assert capsys.readouterr().err == (
        "armkit: error: 'place' needs TO <where> (a place, board[ROW,COL], cube or container) "
        "or --xyz X Y Z [mm]\n"
    )
    assert (
        main(["--scene", "board_001", "move-item", "red", "board[1,1]", "--xyz", "1", "2", "3"])
        == 2
    )
    err = capsys.readouterr().err
    assert err.endswith("takes TO board[1,1] or --xyz X Y Z [mm], not both; drop one\n")
