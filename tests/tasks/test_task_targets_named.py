"""A place that cannot take the cube says why in its own words: a socket or point where
another cube stands ('board[0, 1] is taken by green', was a reach or tipping error), a
cube onto itself, a board named without its socket (was 'has no place ... board; it has:
board, ...')."""

from __future__ import annotations

import pytest

from armkit import InputError, load_model, tasks
from armkit.scene import load_scene

MODEL = load_model("openmanipulator_x")
SCENE = load_scene("board_001")
START = tasks.Start(MODEL, MODEL.home)


def _picked() -> tasks.Plan:
    return tasks.pick(START, SCENE, "red")


@pytest.mark.parametrize(
    ("to", "message"),
    [
        (
            "board[0,1]",
            "place red: board[0, 1] is taken by green; choose a free one, or put red on green",
        ),
        ((220.0, 0.0, 3.0), "place red: (220.0, 0.0, 3.0) mm is taken by green"),
        ("red", "place red: red cannot go on itself; choose another place"),
    ],
)
def test_place_names_what_is_in_the_way(to: object, message: str) -> None:
    picked = _picked()
    with pytest.raises(tasks.TaskError) as info:
        tasks.place(tasks.Start(MODEL, picked.q_end), picked.rest, "red", to)  # type: ignore[arg-type]
    assert str(info.value).startswith(message)


def test_the_cube_s_own_socket_and_a_cube_to_stack_on_are_free() -> None:
    picked = _picked()
    start = tasks.Start(MODEL, picked.q_end)
    assert tasks.place(start, picked.rest, "red", "board[0,0]").held is None
    assert tasks.place(start, picked.rest, "red", "green").held is None


def test_move_item_too() -> None:
    with pytest.raises(tasks.TaskError, match=r"move red: board\[0, 1\] is taken by green"):
        tasks.move_item(START, SCENE, "red", "board[0,1]")
    with pytest.raises(tasks.TaskError, match="move red: red cannot go on itself"):
        tasks.move_item(START, SCENE, "red", "red")
    with pytest.raises(
        InputError,
        match=r"board is a board: say which socket, board\[ROW, COL\] \(rows 0..2, columns 0..2\)",
    ):
        tasks.move_item(START, SCENE, "red", "board")


def test_a_stack_is_named_by_its_top_cube() -> None:
    # with red on green, 'taken by green; ... put blue on green' named the covered cube
    picked = _picked()
    stacked = tasks.place(tasks.Start(MODEL, picked.q_end), picked.rest, "red", "green")
    blue = tasks.pick(tasks.Start(MODEL, stacked.q_end), stacked.rest, "blue")
    start = tasks.Start(MODEL, blue.q_end)
    with pytest.raises(
        tasks.TaskError, match=r"board\[0, 1\] is taken by green; .* put blue on red$"
    ):
        tasks.place(start, blue.rest, "blue", "board[0,1]")
    with pytest.raises(tasks.TaskError, match=r"place blue: green has red on it; put blue on red$"):
        tasks.place(start, blue.rest, "blue", "green")
